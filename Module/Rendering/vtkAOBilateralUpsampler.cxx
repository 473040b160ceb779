#include "vtkAOBilateralUpsampler.h"

#include "vtkAOBilateralUpsamplerFS.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
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
  vtkAOShaderUtilities::DeleteObjects({ this->Intermediate });
}

//------------------------------------------------------------------------------
void vtkAOBilateralUpsampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
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
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->Quad, renWin, vtkAOBilateralUpsamplerFS, this, "bilateral upsampling"))
  {
    return false;
  }
  vtkShaderProgram* program = this->Quad->Program;
  gbuffer->BindViewGeometry(program, projection, parallel);
  program->SetUniformi("aoScale", scale);
  program->SetUniformf("aoWindow", static_cast<float>(window));
  program->SetUniformf("aoRadius", static_cast<float>(radius));
  // Input samples within half the window on each side of the centre.
  program->SetUniformi("aoTaps", std::max(1, (window / 2 + scale - 1) / scale));

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
    vtkAOShaderUtilities::DrawQuad(renWin, this->FrameBufferObject, this->Quad.get(), pass.Out);
    pass.In->Deactivate();
  }

  gbuffer->UnbindViewGeometry();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBilateralUpsampler::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkAOShaderUtilities::ReleaseTexture(this->Intermediate, vtkOpenGLRenderWindow::SafeDownCast(w));
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
long long vtkAOBilateralUpsampler::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->Intermediate) +
    this->Superclass::GetGraphicsMemorySize();
}
