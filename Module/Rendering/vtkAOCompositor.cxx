#include "vtkAOCompositor.h"

#include "vtkAOCompositorFS.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <vector>

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
  const Parameters& parameters)
{
  if (!vtkAOShaderUtilities::ReadyQuad(this->Quad, renWin, vtkAOCompositorFS, this, "AO composite"))
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
  const auto capabilitiesSaver =
    vtkAOShaderUtilities::SaveCapabilities(ostate, { GL_BLEND, GL_DEPTH_TEST });

  gbuffer->GetColorTexture()->Activate();
  gbuffer->GetDepthTexture()->Activate();
  occlusion->Activate();
  program->SetUniformi("aoColor", gbuffer->GetColorTexture()->GetTextureUnit());
  program->SetUniformi("aoDepth", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniformi("aoOcclusion", occlusion->GetTextureUnit());
  const int fullSize[2] = { gbuffer->GetWidth(), gbuffer->GetHeight() };
  program->SetUniform2i("aoFullSize", fullSize);
  program->SetUniformi("aoOcclusionScale", parameters.OcclusionScale);
  program->SetUniformi("aoOnly", parameters.AOOnly ? 1 : 0);
  program->SetUniformi("aoKeepBackground", parameters.KeepBackground ? 1 : 0);
  program->SetUniformf("aoIntensity", static_cast<float>(parameters.Intensity));

  const int* viewport = parameters.Viewport;
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
bool vtkAOCompositor::ReadOcclusion(vtkAOGBufferPass* gbuffer,
  vtkTextureObject* occlusion,
  int occlusionScale,
  vtkImageData* image)
{
#ifndef GL_ES_VERSION_3_0
  if (!gbuffer || !occlusion || !image || !gbuffer->GetDepthTexture())
  {
    return false;
  }
  vtkTextureObject* depthTexture = gbuffer->GetDepthTexture();
  const int w = gbuffer->GetWidth(), h = gbuffer->GetHeight();
  const int aw = static_cast<int>(occlusion->GetWidth());
  const int ah = static_cast<int>(occlusion->GetHeight());
  const int scale = std::max(1, occlusionScale);
  std::vector<float> aoData(static_cast<size_t>(aw) * ah * 2);
  std::vector<float> depth(static_cast<size_t>(w) * h);
  vtkAOShaderUtilities::ClearErrors(); // earlier errors are not this read-back's
  vtkOpenGLState* ostate = occlusion->GetContext()->GetState();
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  occlusion->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, aoData.data());
  occlusion->Deactivate();
  depthTexture->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  depthTexture->Deactivate();

  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> values;
  InitializeOcclusionArray(values, static_cast<vtkIdType>(w) * h);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t i = static_cast<size_t>(y) * w + x;
      const bool covered = depth[i] < 1.0f;
      const size_t j =
        static_cast<size_t>(std::min(y / scale, ah - 1)) * aw + std::min(x / scale, aw - 1);
      values->SetTypedComponent(static_cast<vtkIdType>(i),
        0,
        covered ? std::min(1.0f, std::max(0.0f, aoData[2 * j])) : 1.0f);
      values->SetTypedComponent(static_cast<vtkIdType>(i), 1, covered ? 1.0f : 0.0f);
    }
  }
  image->GetPointData()->SetScalars(values);
  return glGetError() == GL_NO_ERROR;
#else
  (void)gbuffer;
  (void)occlusion;
  (void)occlusionScale;
  (void)image;
  return false;
#endif
}

//------------------------------------------------------------------------------
void vtkAOCompositor::InitializeOcclusionArray(vtkFloatArray* values, vtkIdType numberOfPixels)
{
  values->SetName("AmbientOcclusion");
  values->SetNumberOfComponents(2);
  values->SetComponentName(0, "A");
  values->SetComponentName(1, "Coverage");
  values->SetNumberOfTuples(numberOfPixels);
}

//------------------------------------------------------------------------------
void vtkAOCompositor::ReleaseGraphicsResources(vtkWindow*)
{
  this->Quad.reset();
}
