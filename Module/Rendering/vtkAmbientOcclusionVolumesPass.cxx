#include "vtkAmbientOcclusionVolumesPass.h"

#include "vtkAOCompositor.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVolumeFS.h"
#include "vtkAOVolumeGS.h"
#include "vtkAOVolumeVS.h"
#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkCompositeDataGeometryFilter.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkFeatureEdges.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

vtkStandardNewMacro(vtkAmbientOcclusionVolumesPass);

namespace
{
enum Stage
{
  GBUFFER = 0,
  VOLUMES,
  COMPOSITE
};

bool ValidBounds(const double b[6])
{
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(b[i]))
    {
      return false;
    }
  }
  return b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
}

// The triangles of a mapper's input (any data set or composite), points merged so that a
// closed surface is recognized as one.
vtkSmartPointer<vtkPolyData> Triangulate(vtkDataObject* input)
{
  vtkSmartPointer<vtkPolyData> surface = vtkPolyData::SafeDownCast(input);
  if (vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkNew<vtkCompositeDataGeometryFilter> geometry;
    geometry->SetInputData(input);
    geometry->Update();
    surface = geometry->GetOutput();
  }
  else if (!surface && vtkDataSet::SafeDownCast(input))
  {
    vtkNew<vtkDataSetSurfaceFilter> geometry;
    geometry->SetInputData(input);
    geometry->Update();
    surface = geometry->GetOutput();
  }
  if (!surface || surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
  {
    return nullptr;
  }
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(surface);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  return triangles->GetOutput();
}

// Closed: every edge shared by exactly two triangles.
bool IsClosed(vtkPolyData* triangles)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(triangles);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->ColoringOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells() == 0;
}
}

//------------------------------------------------------------------------------
vtkAmbientOcclusionVolumesPass::vtkAmbientOcclusionVolumesPass()
{
  for (auto& timer : this->Timers)
  {
    timer = new vtkOpenGLRenderTimer;
  }
}

//------------------------------------------------------------------------------
vtkAmbientOcclusionVolumesPass::~vtkAmbientOcclusionVolumesPass()
{
  for (auto& timer : this->Timers)
  {
    delete timer;
  }
  // The GL objects free themselves through their context's resource callbacks.
  if (this->Triangles)
  {
    this->Triangles->Delete();
  }
  if (this->VAO)
  {
    this->VAO->Delete();
  }
  if (this->Accumulation)
  {
    this->Accumulation->Delete();
  }
  if (this->Occlusion)
  {
    this->Occlusion->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "Falloff: " << (this->Falloff == WENDLAND ? "Wendland" : "Binary") << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "AOOnly: " << this->AOOnly << "\n";
  os << indent << "NumberOfOccludingTriangles: " << this->NumberOfOccludingTriangles << "\n";
  os << indent << "GeometryUpdateCount: " << this->GeometryUpdateCount << "\n";
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::CollectOccluders(vtkRenderer* ren,
  std::vector<vtkProp*>& props,
  double bounds[6])
{
  // All visible props, not the frustum-culled list of the render state: the volumes of
  // off-screen triangles still cover visible pixels.
  bounds[0] = bounds[2] = bounds[4] = VTK_DOUBLE_MAX;
  bounds[1] = bounds[3] = bounds[5] = VTK_DOUBLE_MIN;
  vtkPropCollection* viewProps = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  viewProps->InitTraversal(it);
  while (vtkProp* prop = viewProps->GetNextProp(it))
  {
    if (!prop->GetVisibility() ||
      (!vtkActor::SafeDownCast(prop) && !vtkAssembly::SafeDownCast(prop)))
    {
      continue;
    }
    // Bounds first: they bring the mapper's input up to date.
    const double* b = prop->GetBounds();
    if (!prop->HasOpaqueGeometry())
    {
      continue;
    }
    if (!b || !ValidBounds(b))
    {
      if (b && (!std::isfinite(b[0]) || !std::isfinite(b[1])) && !this->Warned)
      {
        vtkWarningMacro(<< "A prop has non-finite bounds; it does not occlude.");
        this->Warned = true;
      }
      continue;
    }
    props.push_back(prop);
    for (int i = 0; i < 3; ++i)
    {
      bounds[2 * i] = std::min(bounds[2 * i], b[2 * i]);
      bounds[2 * i + 1] = std::max(bounds[2 * i + 1], b[2 * i + 1]);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::UpdateOccluderGeometry(vtkOpenGLRenderWindow* renWin,
  const std::vector<vtkProp*>& props)
{
  // The actors to draw with their world matrices: an assembly's parts through its paths.
  std::vector<std::pair<vtkActor*, vtkMatrix4x4*>> parts;
  for (vtkProp* prop : props)
  {
    if (vtkAssembly* assembly = vtkAssembly::SafeDownCast(prop))
    {
      assembly->InitPathTraversal();
      while (vtkAssemblyPath* path = assembly->GetNextPath())
      {
        vtkAssemblyNode* node = path->GetLastNode();
        vtkActor* actor = vtkActor::SafeDownCast(node->GetViewProp());
        if (actor && actor->GetMapper() && actor->GetVisibility() && actor->HasOpaqueGeometry())
        {
          parts.emplace_back(actor, node->GetMatrix() ? node->GetMatrix() : actor->GetMatrix());
        }
      }
    }
    else if (vtkActor* actor = vtkActor::SafeDownCast(prop))
    {
      if (actor->GetMapper())
      {
        parts.emplace_back(actor, actor->GetMatrix());
      }
    }
  }

  // Everything the triangles depend on; properties (colour, culling) are left out.
  std::vector<double> signature;
  for (const auto& part : parts)
  {
    signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(part.first)));
    const double* m = &part.second->Element[0][0];
    signature.insert(signature.end(), m, m + 16);
    vtkMapper* mapper = part.first->GetMapper();
    signature.push_back(static_cast<double>(mapper->GetMTime()));
    vtkDataObject* input =
      mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0
      ? mapper->GetInputDataObject(0, 0)
      : nullptr;
    signature.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
  }
  if (this->Triangles && this->TrianglesWindow != renWin)
  {
    // Another context: its buffer is not ours to reuse.
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  if (signature == this->GeometrySignature && this->Triangles)
  {
    return this->NumberOfOccludingTriangles > 0;
  }
  this->GeometrySignature.swap(signature);

  // World positions relative to the scene's centre (float precision where it matters), w = 1
  // for triangles of open surfaces (two-sided occluders), 0 for closed ones.
  std::vector<float> data;
  for (int i = 0; i < 3; ++i)
  {
    this->SceneOrigin[i] = 0.5 * (this->SceneBounds[2 * i] + this->SceneBounds[2 * i + 1]);
  }
  for (const auto& part : parts)
  {
    vtkMapper* mapper = part.first->GetMapper();
    if (mapper->GetNumberOfInputPorts() == 0 || mapper->GetNumberOfInputConnections(0) == 0)
    {
      continue;
    }
    vtkSmartPointer<vtkPolyData> triangles = Triangulate(mapper->GetInputDataObject(0, 0));
    if (!triangles)
    {
      continue;
    }
    const bool closed = IsClosed(triangles);
    const float twoSided = closed ? 0.0f : 1.0f;
    vtkPoints* points = triangles->GetPoints();
    vtkCellArray* polys = triangles->GetPolys();
    vtkIdType npts;
    const vtkIdType* ids;
    // A closed surface occludes from its front side only: make its front side the outside
    // (positive enclosed volume), whatever the source's winding.
    bool flip = false;
    if (closed)
    {
      double volume = 0.0;
      for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
      {
        double a[3], b[3], c[3], bc[3];
        points->GetPoint(ids[0], a);
        points->GetPoint(ids[1], b);
        points->GetPoint(ids[2], c);
        vtkMath::Cross(b, c, bc);
        volume += vtkMath::Dot(a, bc);
      }
      flip = volume < 0.0;
    }
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
    {
      if (npts != 3)
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        double p[4] = { 0, 0, 0, 1 };
        points->GetPoint(ids[flip ? 2 - k : k], p);
        part.second->MultiplyPoint(p, p);
        for (int c = 0; c < 3; ++c)
        {
          data.push_back(static_cast<float>(p[c] / p[3] - this->SceneOrigin[c]));
        }
        data.push_back(twoSided);
      }
    }
  }
  this->NumberOfOccludingTriangles = static_cast<vtkIdType>(data.size() / 12);
  ++this->GeometryUpdateCount;
  if (!this->Triangles)
  {
    this->Triangles = vtkOpenGLBufferObject::New();
    this->Triangles->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->TrianglesWindow = renWin;
  }
  if (!data.empty() && !this->Triangles->Upload(data, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload the occluding triangles.");
    this->NumberOfOccludingTriangles = 0;
    this->GeometrySignature.clear();
  }
  if (this->VAO)
  {
    // The buffer may have been re-created: bind the attribute again.
    this->VAO->ShaderProgramChanged();
  }
  return this->NumberOfOccludingTriangles > 0;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin,
  int w,
  int h)
{
  vtkAOShaderUtilities::EnsureFloatTexture(this->Occlusion, renWin, w, h, 2);
  if (!this->Accumulation)
  {
    this->Accumulation = vtkOpenGLFramebufferObject::New();
  }
  this->Accumulation->SetContext(renWin);
  if (!this->VAO)
  {
    this->VAO = vtkOpenGLVertexArrayObject::New();
  }
  const std::string fs = vtkAOShaderUtilities::ComposeFragmentShader(vtkAOVolumeFS);
  vtkShaderProgram* program =
    renWin->GetShaderCache()->ReadyShaderProgram(vtkAOVolumeVS, fs.c_str(), vtkAOVolumeGS);
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the ambient occlusion volume shader program.");
    this->Program = nullptr;
    return false;
  }
  if (program != this->Program)
  {
    this->Program = program;
    this->VAO->ShaderProgramChanged();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::RenderVolumes(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren)
{
  const int w = this->GBuffer->GetWidth(), h = this->GBuffer->GetHeight();
  if (!this->InitializeGraphicsResources(renWin, w, h))
  {
    return false;
  }
  vtkShaderProgram* program = this->Program;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);

  this->Accumulation->SaveCurrentBindingsAndBuffers();
  this->Accumulation->Bind();
  this->Accumulation->AddColorAttachment(0, this->Occlusion);
  ostate->vtkglDrawBuffer(GL_NONE); // see vtkAOGBufferPass: reset the draw-buffer cache
  this->Accumulation->ActivateDrawBuffers(1);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglClearColor(1.0f, 0.0f, 0.0f, 0.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);

  // Each fragment subtracts the occlusion of its triangle: 1 - sum, unclamped in a float target.
  // Depth is tested in the shader against the G-buffer (which is sampled, so it cannot also be
  // attached); no face culling, the geometry shader emits the faces turned to the eye.
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  ostate->vtkglBlendEquation(GL_FUNC_REVERSE_SUBTRACT);

  vtkCamera* cam = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> modelView;
  modelView->DeepCopy(cam->GetViewTransformMatrix());
  vtkNew<vtkMatrix4x4> shift;
  for (int i = 0; i < 3; ++i)
  {
    shift->SetElement(i, 3, this->SceneOrigin[i]);
  }
  vtkMatrix4x4::Multiply4x4(modelView, shift, modelView);
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(cam->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
  vtkNew<vtkMatrix4x4> inverseProjection;
  inverseProjection->DeepCopy(projection);
  inverseProjection->Invert();

  vtkTextureObject* depth = this->GBuffer->GetDepthTexture();
  vtkTextureObject* normal = this->GBuffer->GetNormalTexture();
  depth->Activate();
  normal->Activate();
  program->SetUniformi("aoDepth", depth->GetTextureUnit());
  program->SetUniformi("aoNormal", normal->GetTextureUnit());
  vtkAOShaderUtilities::SetMatrix(program, "aoModelView", modelView);
  vtkAOShaderUtilities::SetMatrix(program, "aoProjection", projection);
  vtkAOShaderUtilities::SetMatrix(program, "aoInvProjection", inverseProjection);
  const int fullSize[2] = { w, h };
  program->SetUniform2i("aoFullSize", fullSize);
  program->SetUniformi("aoParallel", cam->GetParallelProjection() ? 1 : 0);
  program->SetUniformf("aoRadius", static_cast<float>(this->EffectiveRadius));
  program->SetUniformf("aoBias", static_cast<float>(this->EffectiveBias));
  program->SetUniformi("aoBinary", this->Falloff == BINARY ? 1 : 0);

  this->VAO->Bind();
  this->VAO->RemoveAttributeArray("vertexMC");
  bool ok = this->VAO->AddAttributeArray(
    program, this->Triangles, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
  if (!ok)
  {
    vtkErrorMacro(<< "Couldn't bind the occluding triangles to the volume shader.");
  }
  else
  {
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->NumberOfOccludingTriangles));
  }
  this->VAO->Release();

  normal->Deactivate();
  depth->Deactivate();
  ostate->vtkglBlendEquation(GL_FUNC_ADD);
  this->Accumulation->UnBind();
  this->Accumulation->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after rendering the ambient occlusion volumes");
  return ok;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::CollectTimings(bool wait)
{
  if (!this->TimingsPending)
  {
    return;
  }
  for (int i = 0; i < 3; ++i)
  {
    vtkOpenGLRenderTimer* timer = this->Timers[i];
    this->StageTimes[i] =
      timer->Stopped() && (wait || timer->Ready()) ? timer->GetElapsedMilliseconds() : 0.0;
    timer->Reset();
  }
  this->TimingsPending = false;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::FinishTimings()
{
  this->CollectTimings(true);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->LastFrameHadOcclusion = false;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass in vtkAmbientOcclusionVolumesPass: nothing is drawn.");
    return;
  }
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (ren->GetSelector())
  {
    // Picking renders ids, not colours: render as vtkOpenGLRenderer::DeviceRender does
    // without a pass, so the selector assigns each prop its id (as HAO does).
    this->ClearLights(ren);
    this->UpdateCamera(ren);
    this->UpdateLightGeometry(ren);
    this->UpdateLights(ren);
    this->NumberOfRenderedProps =
      ren->GetSelector()->Render(ren, s->GetPropArray(), s->GetPropArrayCount());
    return;
  }
  if (!renWin)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  this->CollectTimings(false);

  std::vector<vtkProp*> occluders;
  this->CollectOccluders(ren, occluders, this->SceneBounds);
  if (!occluders.empty())
  {
    const double* b = this->SceneBounds;
    const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) +
      (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
    this->EffectiveRadius = this->Radius > 0.0 ? this->Radius : 0.1 * diagonal;
    // The reference's automatic bias: two cells of a 256 grid over the padded bounds.
    const double longest =
      std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] }) + 2.0 * this->EffectiveRadius;
    this->EffectiveBias = this->Bias > 0.0 ? this->Bias : 2.0 * longest / 256.0;
  }
  if (occluders.empty() || !(this->EffectiveRadius > 0.0) ||
    !std::isfinite(this->EffectiveRadius) || !this->UpdateOccluderGeometry(renWin, occluders))
  {
    // Nothing that occludes (empty renderer, a single point, no polygons): plain render.
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }

  this->TimingsPending = true;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);

  // 1. G-buffer (shared with HAO).
  this->GBuffer->SetDelegatePass(this->DelegatePass);
  this->Timers[GBUFFER]->Start();
  this->GBuffer->Render(s);
  this->Timers[GBUFFER]->Stop();
  this->NumberOfRenderedProps = this->GBuffer->GetNumberOfRenderedProps();

  // 2. The volumes.
  this->Timers[VOLUMES]->Start();
  bool ok = this->RenderVolumes(renWin, ren);
  this->Timers[VOLUMES]->Stop();

  // 3. Composite into the framebuffer the renderer draws into (shared with HAO).
  int viewport[4] = { 0, 0, this->GBuffer->GetWidth(), this->GBuffer->GetHeight() };
  if (!s->GetFrameBuffer())
  {
    int w, h;
    ren->GetTiledSizeAndOrigin(&w, &h, &viewport[0], &viewport[1]);
  }
  const bool keepBackground = ren->Transparent() || !ren->GetErase();
  this->Timers[COMPOSITE]->Start();
  // Without occlusion the plain image still has to reach the screen: composite with A = 1.
  if (!ok)
  {
    this->Accumulation->SaveCurrentBindingsAndBuffers();
    this->Accumulation->Bind();
    this->Accumulation->AddColorAttachment(0, this->Occlusion);
    this->Accumulation->ActivateDrawBuffers(1);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    ostate->vtkglClearColor(1.0f, 0.0f, 0.0f, 0.0f);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->Accumulation->UnBind();
    this->Accumulation->RestorePreviousBindingsAndBuffers();
  }
  const bool composited = this->Compositor->Composite(renWin,
    this->GBuffer,
    this->Occlusion,
    1,
    ok ? this->Intensity : 0.0,
    this->AOOnly && ok,
    keepBackground,
    viewport);
  this->Timers[COMPOSITE]->Stop();
  this->LastFrameHadOcclusion = ok && composited;
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::GetAmbientOcclusionImage(vtkImageData* image)
{
  if (!this->LastFrameHadOcclusion || !image)
  {
    return false;
  }
  return vtkAOCompositor::ReadOcclusion(this->GBuffer, this->Occlusion, 1, image);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->GBuffer->ReleaseGraphicsResources(w);
  this->Compositor->ReleaseGraphicsResources(w);
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Occlusion, renWin);
  if (this->Accumulation)
  {
    this->Accumulation->ReleaseGraphicsResources(w);
    this->Accumulation->Delete();
    this->Accumulation = nullptr;
  }
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
    this->VAO->Delete();
    this->VAO = nullptr;
  }
  if (this->Triangles)
  {
    this->Triangles->ReleaseGraphicsResources();
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  this->TrianglesWindow = nullptr;
  this->Program = nullptr; // released with the window's shader cache
  for (auto& timer : this->Timers)
  {
    timer->ReleaseGraphicsResources();
  }
  std::fill(this->StageTimes, this->StageTimes + 3, 0.0);
  this->TimingsPending = false;
  this->GeometrySignature.clear();
}
