#include "vtkAOAccumulator.h"

#include "vtkAOAccumulatorFS.h"
#include "vtkAOGL.h"
#include "vtkAOShaderUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkAOAccumulator);

//------------------------------------------------------------------------------
vtkAOAccumulator::vtkAOAccumulator() = default;
vtkAOAccumulator::~vtkAOAccumulator() = default;

//------------------------------------------------------------------------------
bool vtkAOAccumulator::Accumulate(vtkOpenGLRenderWindow* renWin, vtkTextureObject* frame, int count)
{
  if (!frame || count < 1)
  {
    return false;
  }
  const int w = static_cast<int>(frame->GetWidth()), h = static_cast<int>(frame->GetHeight());
  const int components = frame->GetComponents() == 2 ? 2 : 4;
  if (count == 1 && this->Output && this->Output->GetComponents() != components)
  {
    vtkAOShaderUtilities::ReleaseTexture(this->Output, renWin); // another stage's layout
  }
  if (count > 1 &&
    (!this->Output || static_cast<int>(this->Output->GetWidth()) != w ||
      static_cast<int>(this->Output->GetHeight()) != h))
  {
    return false; // nothing to add to: the caller restarts
  }
  vtkAOShaderUtilities::EnsureFloatTexture(this->Output, renWin, w, h, components);
  const int none[2] = { 0, 0 };
  return this->Draw(
    renWin, frame, count == 1 ? COPY : BLEND, static_cast<float>(1.0 / count), 1, none);
}

//------------------------------------------------------------------------------
bool vtkAOAccumulator::Scatter(vtkOpenGLRenderWindow* renWin,
  vtkTextureObject* map,
  int scale,
  const int offset[2])
{
  if (!map || !this->Output || scale < 1 || offset[0] < 0 || offset[0] >= scale || offset[1] < 0 ||
    offset[1] >= scale)
  {
    return false;
  }
  return this->Draw(renWin, map, SCATTER, 1.0f, scale, offset);
}

//------------------------------------------------------------------------------
bool vtkAOAccumulator::Draw(vtkOpenGLRenderWindow* renWin,
  vtkTextureObject* frame,
  Mode mode,
  float weight,
  int scale,
  const int offset[2])
{
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->Quad, renWin, vtkAOAccumulatorFS, this, "accumulation"))
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  const auto capabilitiesSaver = vtkAOShaderUtilities::SaveCapabilities(ostate, { GL_BLEND });
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkShaderProgram* program = this->Quad->Program;
  frame->Activate();
  program->SetUniformi("aoFrame", frame->GetTextureUnit());
  program->SetUniformi("aoCopy", mode == BLEND ? 0 : 1);
  program->SetUniformf("aoWeight", weight);
  program->SetUniformi("aoScatterScale", mode == SCATTER ? scale : 0);
  program->SetUniform2i("aoScatterOffset", offset);
  if (mode == BLEND)
  {
    // mean_k = mean_{k-1} + (a_k - mean_{k-1}) / k, on A only.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    ostate->vtkglColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  vtkAOShaderUtilities::DrawQuad(renWin, this->FrameBufferObject, this->Quad.get(), this->Output);
  frame->Deactivate();
  return true;
}
