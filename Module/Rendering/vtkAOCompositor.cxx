#include "vtkAOCompositor.h"

#include "vtkAOCompositorFS.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkAOCompositor);

//------------------------------------------------------------------------------
vtkAOCompositor::vtkAOCompositor() = default;

//------------------------------------------------------------------------------
vtkAOCompositor::~vtkAOCompositor() = default;

//------------------------------------------------------------------------------
void vtkAOCompositor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
bool vtkAOCompositor::Composite(vtkOpenGLRenderWindow* renWin,
  vtkAOGBufferPass* gbuffer,
  vtkTextureObject* occlusion,
  int occlusionScale,
  double intensity,
  bool aoOnly,
  bool keepBackground,
  const int viewport[4])
{
  if (!vtkAOShaderUtilities::ReadyQuad(this->Quad,
        renWin,
        vtkAOShaderUtilities::ComposeFragmentShader(vtkAOCompositorFS),
        this,
        "AO composite"))
  {
    return false;
  }
  vtkShaderProgram* program = this->Quad->Program;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);

  gbuffer->GetColorTexture()->Activate();
  gbuffer->GetDepthTexture()->Activate();
  occlusion->Activate();
  program->SetUniformi("aoColor", gbuffer->GetColorTexture()->GetTextureUnit());
  program->SetUniformi("aoDepth", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniformi("aoOcclusion", occlusion->GetTextureUnit());
  const int fullSize[2] = { gbuffer->GetWidth(), gbuffer->GetHeight() };
  program->SetUniform2i("aoFullSize", fullSize);
  program->SetUniformi("aoOcclusionScale", occlusionScale);
  program->SetUniformi("aoOnly", aoOnly ? 1 : 0);
  program->SetUniformi("aoKeepBackground", keepBackground ? 1 : 0);
  program->SetUniformf("aoIntensity", static_cast<float>(intensity));

  ostate->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  this->Quad->Render();

  occlusion->Deactivate();
  gbuffer->GetDepthTexture()->Deactivate();
  gbuffer->GetColorTexture()->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOCompositor::ReleaseGraphicsResources(vtkWindow*)
{
  this->Quad.reset();
}
