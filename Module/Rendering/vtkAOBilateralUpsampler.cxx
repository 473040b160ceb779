#include "vtkAOBilateralUpsampler.h"

#include "vtkAOBilateralUpsamplerFS.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
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
  vtkAOShaderUtilities::DeleteObjects({ this->Intermediate, this->Marks });
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
  double radius,
  const Marking& marking)
{
  const int w = gbuffer->GetWidth(), h = gbuffer->GetHeight();
  const int lh = static_cast<int>(input->GetHeight());
  // A, coverage, depth and packed normal of the pixel each texel stands for (as the input).
  vtkAOShaderUtilities::EnsureFloatTexture(this->Intermediate, renWin, w, lh, 4);
  vtkAOShaderUtilities::EnsureFloatTexture(this->Output, renWin, w, h, 2);
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  if (marking.Enabled)
  {
    vtkAOShaderUtilities::EnsureDepthTexture(this->Marks, renWin, w, h);
  }
  else
  {
    vtkAOShaderUtilities::ReleaseTexture(this->Marks, renWin);
  }
  // Two programs: the filter, and its variant that also writes the marks (compiled with
  // AO_MARK, so that the plain filter never writes depth), for the second pass when marking.
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->Quad, renWin, vtkAOBilateralUpsamplerFS, this, "bilateral upsampling") ||
    (marking.Enabled &&
      !vtkAOShaderUtilities::ReadyQuad(this->MarkQuad,
        renWin,
        vtkAOBilateralUpsamplerFS,
        this,
        "bilateral upsampling with refinement marks",
        "#define AO_MARK")))
  {
    return false;
  }

  // The marks: every pixel of the second pass writes its depth (GL_ALWAYS).
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  // Every texel of the targets is written, whatever scissor box the caller left.
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  if (marking.Enabled)
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }

  struct
  {
    vtkOpenGLQuadHelper* Quad;
    vtkTextureObject* In;
    vtkTextureObject* Out;
    vtkTextureObject* Depth;
    int Horizontal;
  } passes[2] = { { this->Quad.get(), input, this->Intermediate, nullptr, 1 },
    { marking.Enabled ? this->MarkQuad.get() : this->Quad.get(),
      this->Intermediate,
      this->Output,
      this->Marks,
      0 } };
  input->Activate(); // also aoMap: the marks read the reduced map in the second pass
  for (const auto& pass : passes)
  {
    vtkShaderProgram* program = pass.Quad->Program;
    renWin->GetShaderCache()->ReadyShaderProgram(program);
    gbuffer->BindViewGeometry(program, projection, parallel);
    program->SetUniformi("aoScale", scale);
    program->SetUniformf("aoWindow", static_cast<float>(window));
    program->SetUniformf("aoRadius", static_cast<float>(radius));
    // Input samples within half the window on each side of the centre.
    program->SetUniformi("aoTaps", std::max(1, (window / 2 + scale - 1) / scale));
    if (pass.Quad == this->MarkQuad.get())
    {
      program->SetUniformi("aoMap", input->GetTextureUnit());
      program->SetUniformf("aoNormalCos", static_cast<float>(marking.NormalCosine));
      program->SetUniformf("aoPlaneTolerance", static_cast<float>(marking.PlaneTolerance));
      program->SetUniformf("aoContrast", static_cast<float>(marking.Contrast));
    }
    pass.In->Activate();
    program->SetUniformi("aoInput", pass.In->GetTextureUnit());
    program->SetUniformi("aoHorizontal", pass.Horizontal);
    vtkAOShaderUtilities::DrawQuad(
      renWin, this->FrameBufferObject, pass.Quad, pass.Out, pass.Depth);
    if (pass.In != input)
    {
      pass.In->Deactivate();
    }
  }
  input->Deactivate();

  gbuffer->UnbindViewGeometry();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBilateralUpsampler::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Intermediate, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Marks, renWin);
  this->MarkQuad.reset();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
long long vtkAOBilateralUpsampler::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->Intermediate) +
    vtkAOShaderUtilities::TextureBytes(this->Marks) + this->Superclass::GetGraphicsMemorySize();
}
