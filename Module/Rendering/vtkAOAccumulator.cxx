#include "vtkAOAccumulator.h"

#include "vtkAOAccumulatorFS.h"
#include "vtkAOGL.h"
#include "vtkAOShaderUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkAOAccumulator);

//------------------------------------------------------------------------------
vtkAOAccumulator::vtkAOAccumulator() = default;

//------------------------------------------------------------------------------
vtkAOAccumulator::~vtkAOAccumulator()
{
  // The GL objects free themselves through their context's resource callbacks.
  if (this->Output)
  {
    this->Output->Delete();
  }
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkAOAccumulator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Output: " << this->Output << "\n";
}

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
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(renWin);
  }
  if (!vtkAOShaderUtilities::ReadyQuad(this->Quad,
        renWin,
        vtkAOShaderUtilities::ComposeFragmentShader(vtkAOAccumulatorFS),
        this,
        "accumulation"))
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkShaderProgram* program = this->Quad->Program;
  frame->Activate();
  program->SetUniformi("aoFrame", frame->GetTextureUnit());
  program->SetUniformi("aoCopy", count == 1 ? 1 : 0);
  program->SetUniformf("aoWeight", static_cast<float>(1.0 / count));
  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  this->FrameBufferObject->AddColorAttachment(0, this->Output);
  ostate->vtkglDrawBuffer(GL_NONE);
  this->FrameBufferObject->ActivateDrawBuffers(1);
  this->FrameBufferObject->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);
  if (count == 1)
  {
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  else
  {
    // mean_k = mean_{k-1} + (a_k - mean_{k-1}) / k, on A only.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    ostate->vtkglColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
  }
  this->Quad->Render();
  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();
  frame->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOAccumulator::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  this->Quad.reset();
  vtkAOShaderUtilities::ReleaseTexture(this->Output, renWin);
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->ReleaseGraphicsResources(w);
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
}

//------------------------------------------------------------------------------
long long vtkAOAccumulator::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->Output);
}
