#include "vtkAOBilateralUpsampler.h"

#include "vtkAOBilateralUpsamplerFS.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkStandardNewMacro(vtkAOBilateralUpsampler);

//------------------------------------------------------------------------------
vtkAOBilateralUpsampler::vtkAOBilateralUpsampler() = default;

//------------------------------------------------------------------------------
vtkAOBilateralUpsampler::~vtkAOBilateralUpsampler()
{
  for (vtkObject* o : { static_cast<vtkObject*>(this->Intermediate),
         static_cast<vtkObject*>(this->Output),
         static_cast<vtkObject*>(this->FrameBufferObject) })
  {
    if (o)
    {
      o->Delete();
    }
  }
}

//------------------------------------------------------------------------------
void vtkAOBilateralUpsampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Output: " << this->Output << "\n";
}

//------------------------------------------------------------------------------
bool vtkAOBilateralUpsampler::Upsample(vtkOpenGLRenderWindow* renWin,
  vtkAOGBufferPass* gbuffer,
  vtkTextureObject* input,
  vtkMatrix4x4* projection,
  bool parallel,
  int scale,
  int window,
  double radius)
{
  const int w = gbuffer->GetWidth(), h = gbuffer->GetHeight();
  const int lh = static_cast<int>(input->GetHeight());
  // A, coverage, depth and packed normal of the pixel each texel stands for (as the input).
  vtkAOShaderUtilities::EnsureFloatTexture(this->Intermediate, renWin, w, lh, 4);
  vtkAOShaderUtilities::EnsureFloatTexture(this->Output, renWin, w, h, 2);
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(renWin);
  }
  if (!vtkAOShaderUtilities::ReadyQuad(this->Quad,
        renWin,
        vtkAOShaderUtilities::ComposeFragmentShader(vtkAOBilateralUpsamplerFS),
        this,
        "bilateral upsampling"))
  {
    return false;
  }
  vtkShaderProgram* program = this->Quad->Program;
  vtkNew<vtkMatrix4x4> invProjection;
  vtkMatrix4x4::Invert(projection, invProjection);

  gbuffer->GetDepthTexture()->Activate();
  gbuffer->GetNormalTexture()->Activate();
  program->SetUniformi("aoDepth", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniformi("aoNormal", gbuffer->GetNormalTexture()->GetTextureUnit());
  vtkAOShaderUtilities::SetMatrix(program, "aoInvProjection", invProjection);
  const int fullSize[2] = { w, h };
  program->SetUniform2i("aoFullSize", fullSize);
  program->SetUniformi("aoParallel", parallel ? 1 : 0);
  program->SetUniformi("aoScale", scale);
  program->SetUniformf("aoWindow", static_cast<float>(window));
  program->SetUniformf("aoRadius", static_cast<float>(radius));
  // Input samples within half the window on each side of the centre.
  program->SetUniformi("aoTaps", std::max(1, (window / 2 + scale - 1) / scale));

  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  renWin->GetState()->vtkglDrawBuffer(GL_NONE);
  struct
  {
    vtkTextureObject* In;
    vtkTextureObject* Out;
    int Horizontal;
  } passes[2] = { { input, this->Intermediate, 1 }, { this->Intermediate, this->Output, 0 } };
  for (const auto& pass : passes)
  {
    pass.In->Activate();
    program->SetUniformi("aoInput", pass.In->GetTextureUnit());
    program->SetUniformi("aoHorizontal", pass.Horizontal);
    this->FrameBufferObject->AddColorAttachment(0, pass.Out);
    this->FrameBufferObject->ActivateDrawBuffers(1);
    const int ow = static_cast<int>(pass.Out->GetWidth());
    const int oh = static_cast<int>(pass.Out->GetHeight());
    this->FrameBufferObject->StartNonOrtho(ow, oh);
    renWin->GetState()->vtkglViewport(0, 0, ow, oh);
    this->Quad->Render();
    pass.In->Deactivate();
  }
  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();

  gbuffer->GetNormalTexture()->Deactivate();
  gbuffer->GetDepthTexture()->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBilateralUpsampler::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  this->Quad.reset();
  vtkAOShaderUtilities::ReleaseTexture(this->Intermediate, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Output, renWin);
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->ReleaseGraphicsResources(w);
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
}

//------------------------------------------------------------------------------
long long vtkAOBilateralUpsampler::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->Intermediate) +
    vtkAOShaderUtilities::TextureBytes(this->Output);
}
