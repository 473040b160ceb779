#include "vtkHybridAmbientOcclusionPass.h"

#include "vtkAOBilateralUpsampler.h"
#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOCompositor.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOParallelReducer.h"
#include "vtkAOPropGeometry.h"
#include "vtkAOVoxelTracer.h"
#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumetricPass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkHybridAmbientOcclusionPass);

namespace
{
enum Stage
{
  VOXELIZE = 0,
  GBUFFER,
  TRACE,
  FILTER,
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

void Union(double into[6], const double b[6])
{
  for (int i = 0; i < 3; ++i)
  {
    into[2 * i] = std::min(into[2 * i], b[2 * i]);
    into[2 * i + 1] = std::max(into[2 * i + 1], b[2 * i + 1]);
  }
}
}

//------------------------------------------------------------------------------
vtkHybridAmbientOcclusionPass::vtkHybridAmbientOcclusionPass()
{
  for (auto& timer : this->Timers)
  {
    timer = new vtkOpenGLRenderTimer;
  }
}

//------------------------------------------------------------------------------
vtkHybridAmbientOcclusionPass::~vtkHybridAmbientOcclusionPass()
{
  for (auto& timer : this->Timers)
  {
    delete timer;
  }
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "VoxelResolution: " << this->VoxelResolution << "\n";
  os << indent << "AOScale: " << this->AOScale << "\n";
  os << indent << "FilterSize: " << this->FilterSize << "\n";
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "Refinement: " << this->Refinement << " (rays " << this->RefinementRays << ")\n";
  os << indent << "CellsPerRadius: " << this->CellsPerRadius << "\n";
  os << indent << "MaximumAutomaticResolution: " << this->MaximumAutomaticResolution << "\n";
  os << indent << "Falloff: " << (this->Falloff == WENDLAND ? "Wendland" : "Binary") << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "AOOnly: " << this->AOOnly << "\n";
  os << indent << "RegionMode: " << this->RegionMode << "\n";
  os << indent << "VoxelizationCount: " << this->VoxelizationCount << "\n";
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::SetRandomRotation(bool on)
{
  this->Voxelizer->SetRandomRotation(on);
}
bool vtkHybridAmbientOcclusionPass::GetRandomRotation()
{
  return this->Voxelizer->GetRandomRotation();
}
void vtkHybridAmbientOcclusionPass::SetRotationSeed(unsigned int seed)
{
  this->Voxelizer->SetRotationSeed(seed);
}
unsigned int vtkHybridAmbientOcclusionPass::GetRotationSeed()
{
  return this->Voxelizer->GetRotationSeed();
}
void vtkHybridAmbientOcclusionPass::SetVoxelizationAxes(int axes)
{
  if (axes != this->Voxelizer->GetNumberOfAxes())
  {
    this->Voxelizer->SetNumberOfAxes(axes);
    this->Modified();
  }
}
int vtkHybridAmbientOcclusionPass::GetVoxelizationAxes()
{
  return this->Voxelizer->GetNumberOfAxes();
}
vtkAOBitmaskVoxelizer* vtkHybridAmbientOcclusionPass::GetVoxelizer()
{
  return this->Voxelizer;
}
void vtkHybridAmbientOcclusionPass::SetParallelReducer(vtkAOParallelReducer* reducer)
{
  if (this->ParallelReducer != reducer)
  {
    this->ParallelReducer = reducer;
    this->VoxelizationSignature.clear(); // the grid must be rebuilt with the new reducer
    this->Modified();
  }
}
vtkAOParallelReducer* vtkHybridAmbientOcclusionPass::GetParallelReducer()
{
  return this->ParallelReducer;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::CollectOccluders(vtkRenderer* ren,
  std::vector<vtkProp*>& props,
  double bounds[6])
{
  // All visible props, not the frustum-culled list of the render state: occluders off
  // screen and behind the camera are the point of the method.
  if (vtkAOPropGeometry::CollectOccluders(ren, false, props, bounds) && !this->Warned)
  {
    vtkWarningMacro(<< "A prop has non-finite bounds; it does not occlude.");
    this->Warned = true;
  }
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::ComputeRegion(vtkRenderer* ren,
  const double scene[6],
  double region[6])
{
  const double r = this->EffectiveRadius;
  // Outside the occluders' bounds there is nothing to hit, so the grid covers those bounds
  // with a small margin (1% of their longest side, so geometry on the bounds is not clipped),
  // not padded by R: a large R would otherwise spend the grid's cells on empty space.
  const double margin =
    0.01 * std::max({ scene[1] - scene[0], scene[3] - scene[2], scene[5] - scene[4] });
  double padded[6];
  for (int i = 0; i < 3; ++i)
  {
    padded[2 * i] = scene[2 * i] - margin;
    padded[2 * i + 1] = scene[2 * i + 1] + margin;
  }
  if (this->RegionMode == EXPLICIT)
  {
    std::copy(this->ExplicitRegion, this->ExplicitRegion + 6, region);
    return ValidBounds(region);
  }
  std::copy(padded, padded + 6, region);
  if (this->RegionMode == VIEW)
  {
    // The frustum's bounding box (corners of the NDC cube through the inverse projection),
    // clipped to the scene and dilated by the radius: what can occlude a visible point.
    vtkCamera* cam = ren->GetActiveCamera();
    vtkNew<vtkMatrix4x4> inverse;
    inverse->DeepCopy(
      cam->GetCompositeProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
    inverse->Invert();
    double frustum[6] = {
      VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN
    };
    for (int c = 0; c < 8; ++c)
    {
      const double ndc[4] = { c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0, 1.0 };
      double w[4];
      inverse->MultiplyPoint(ndc, w);
      if (w[3] != 0.0)
      {
        const double p[6] = {
          w[0] / w[3], w[0] / w[3], w[1] / w[3], w[1] / w[3], w[2] / w[3], w[2] / w[3]
        };
        Union(frustum, p);
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      region[2 * i] = std::max(scene[2 * i], frustum[2 * i]) - r;
      region[2 * i + 1] = std::min(scene[2 * i + 1], frustum[2 * i + 1]) + r;
      region[2 * i] = std::max(region[2 * i], padded[2 * i]);
      region[2 * i + 1] = std::min(region[2 * i + 1], padded[2 * i + 1]);
    }
  }
  return ValidBounds(region) &&
    (region[1] > region[0] || region[3] > region[2] || region[5] > region[4]);
}

//------------------------------------------------------------------------------
double vtkHybridAmbientOcclusionPass::GetRefinedFraction()
{
  return this->Refinement ? this->Tracer->GetRefinedFraction() : 0.0;
}

//------------------------------------------------------------------------------
int vtkHybridAmbientOcclusionPass::AutomaticVoxelResolution(
  vtkOpenGLRenderWindow* renWin, const double region[6])
{
  // Cells of at most R / CellsPerRadius along the region's longest side, within [64, the
  // cap]; the implementation's own limit applies without a warning (it was not asked for).
  const double longest =
    std::max({ region[1] - region[0], region[3] - region[2], region[5] - region[4] });
  const double wanted = std::ceil(longest * this->CellsPerRadius / this->EffectiveRadius);
  const int cap = std::min(
    this->MaximumAutomaticResolution, this->Voxelizer->GetSupportedResolution(renWin));
  return static_cast<int>(std::max(64.0, std::min(static_cast<double>(cap), wanted)));
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::NeedsVoxelization(const std::vector<vtkProp*>& props,
  const double region[6])
{
  // Everything the grid depends on. The props' own MTimes are left out on purpose: they
  // include their properties (colour, culling), which do not occlude.
  std::vector<double> signature(region, region + 6);
  signature.push_back(this->EffectiveVoxelResolution);
  signature.push_back(this->Voxelizer->GetRandomRotation());
  signature.push_back(this->Voxelizer->GetRotationSeed());
  signature.push_back(this->Voxelizer->GetNumberOfAxes());
  for (vtkProp* prop : props)
  {
    signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(prop)));
    if (vtkProp3D* prop3D = vtkProp3D::SafeDownCast(prop))
    {
      const double* m = &prop3D->GetMatrix()->Element[0][0];
      signature.insert(signature.end(), m, m + 16);
    }
    if (vtkAssembly* assembly = vtkAssembly::SafeDownCast(prop))
    {
      signature.push_back(static_cast<double>(assembly->GetMTime()));
    }
    if (vtkActor* actor = vtkActor::SafeDownCast(prop))
    {
      vtkMapper* mapper = actor->GetMapper();
      signature.push_back(static_cast<double>(mapper->GetMTime()));
      for (int port = 0; port < mapper->GetNumberOfInputPorts(); ++port)
      {
        for (int c = 0; c < mapper->GetNumberOfInputConnections(port); ++c)
        {
          vtkDataObject* input = mapper->GetInputDataObject(port, c);
          signature.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
        }
      }
    }
  }
  if (signature == this->VoxelizationSignature && this->Voxelizer->GetGridTexture())
  {
    return false;
  }
  this->VoxelizationSignature.swap(signature);
  return true;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::CollectTimings(bool wait)
{
  if (!this->TimingsPending)
  {
    return;
  }
  // One frame's queries at a time: a stage that did not run (voxelization of a static scene)
  // reports 0, and every timer is free for the next frame afterwards.
  for (int i = 0; i < 5; ++i)
  {
    vtkOpenGLRenderTimer* timer = this->Timers[i];
    this->StageTimes[i] =
      timer->Stopped() && (wait || timer->Ready()) ? timer->GetElapsedMilliseconds() : 0.0;
    timer->Reset();
  }
  this->TimingsPending = false;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::FinishTimings()
{
  this->CollectTimings(true);
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->LastFrameHadOcclusion = false;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass in vtkHybridAmbientOcclusionPass: nothing is drawn.");
    return;
  }
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (ren->GetSelector())
  {
    // Picking renders ids, not colours: no AO. The props must go through the selector, which
    // assigns each its id (vtkRenderer::UpdateGeometry does this without a pass); a delegate
    // such as vtkRenderStepsPass would draw them all with id 0 and nothing would be picked.
    // So render as vtkOpenGLRenderer::DeviceRender does without a pass.
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

  // The previous frame's queries have normally finished by now: read them without waiting.
  this->CollectTimings(false);

  std::vector<vtkProp*> occluders;
  double scene[6];
  this->CollectOccluders(ren, occluders, scene);
  bool haveOccluders = !occluders.empty();
  if (this->ParallelReducer)
  {
    // Distributed rendering: the radius and the region come from all processes' occluders.
    this->ParallelReducer->ReduceBounds(scene);
    haveOccluders = ValidBounds(scene);
  }
  if (haveOccluders)
  {
    const double diagonal = std::sqrt((scene[1] - scene[0]) * (scene[1] - scene[0]) +
      (scene[3] - scene[2]) * (scene[3] - scene[2]) +
      (scene[5] - scene[4]) * (scene[5] - scene[4]));
    this->EffectiveRadius = this->Radius > 0.0 ? this->Radius : 0.1 * diagonal;
  }
  double region[6];
  if (!haveOccluders || !(this->EffectiveRadius > 0.0) || !std::isfinite(this->EffectiveRadius) ||
    !this->ComputeRegion(ren, scene, region))
  {
    // Nothing that occludes (empty renderer, single point, degenerate bounds): plain render.
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
  // The stages bind their textures to other units: leave the active unit as it was.
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);

  // 1. Voxelize, only when something that occludes changed.
  this->EffectiveVoxelResolution = this->VoxelResolution > 0
    ? this->VoxelResolution
    : this->AutomaticVoxelResolution(renWin, region);
  bool revoxelize = this->NeedsVoxelization(occluders, region);
  if (this->ParallelReducer)
  {
    revoxelize = this->ParallelReducer->ReduceAny(revoxelize); // all processes voxelize together
  }
  if (revoxelize)
  {
    vtkRenderState voxelState(ren);
    voxelState.SetPropArrayAndCount(occluders.data(), static_cast<int>(occluders.size()));
    this->Voxelizer->SetResolution(this->EffectiveVoxelResolution);
    this->Voxelizer->SetRegion(region);
    this->Timers[VOXELIZE]->Start();
    this->Voxelizer->Render(&voxelState);
    if (this->ParallelReducer)
    {
      this->ParallelReducer->ReduceGrid(this->Voxelizer); // OR in the other processes' grids
    }
    this->Timers[VOXELIZE]->Stop();
    ++this->VoxelizationCount;
  }
  if (this->Voxelizer->GetGridDimensions()[0] == 0)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  this->EffectiveBias = this->Bias;

  // 2. G-buffer. Volumes are not surfaces: they are drawn after the composite, over the
  // occluded surfaces and against the depth the compositor restores.
  std::vector<vtkProp*> surfaces, volumes;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    (vtkVolume::SafeDownCast(prop) ? volumes : surfaces).push_back(prop);
  }
  vtkRenderState surfaceState(ren);
  surfaceState.SetPropArrayAndCount(surfaces.data(), static_cast<int>(surfaces.size()));
  surfaceState.SetFrameBuffer(s->GetFrameBuffer());
  surfaceState.SetRequiredKeys(s->GetRequiredKeys());
  this->GBuffer->SetDelegatePass(this->DelegatePass);
  this->Timers[GBUFFER]->Start();
  this->GBuffer->Render(&surfaceState);
  this->Timers[GBUFFER]->Stop();
  this->NumberOfRenderedProps = this->GBuffer->GetNumberOfRenderedProps();

  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  vtkCamera* cam = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> view;
  view->DeepCopy(cam->GetViewTransformMatrix());
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(cam->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));

  // 3. Trace the reduced-resolution AO map.
  vtkAOVoxelTracer::Parameters parameters;
  parameters.Scale = this->AOScale;
  parameters.Rays = this->NumberOfRays;
  parameters.Steps = this->NumberOfSteps;
  parameters.Radius = this->EffectiveRadius;
  parameters.Bias = this->EffectiveBias;
  parameters.Spread = this->Spread;
  parameters.BinaryFalloff = this->Falloff == BINARY;
  parameters.Parallel = cam->GetParallelProjection() != 0;
  parameters.GridVersion = this->VoxelizationCount; // the tracer's coarse level follows it
  this->Timers[TRACE]->Start();
  bool ok =
    this->Tracer->Trace(renWin, this->GBuffer, this->Voxelizer, view, projection, parameters);
  this->Timers[TRACE]->Stop();

  // 4. Upsample and filter.
  vtkTextureObject* occlusion = this->Tracer->GetOutput();
  int occlusionScale = this->AOScale;
  if (ok && this->Filter)
  {
    this->Timers[FILTER]->Start();
    ok = this->Upsampler->Upsample(renWin,
      this->GBuffer,
      occlusion,
      projection,
      parameters.Parallel,
      this->AOScale,
      this->FilterSize,
      this->EffectiveRadius);
    occlusion = this->Upsampler->GetOutput();
    occlusionScale = 1;
    // The filter stage's time includes the refinement.
    if (ok && this->Refinement)
    {
      vtkAOVoxelTracer::RefineParameters refine;
      refine.Rays = this->RefinementRays;
      ok = this->Tracer->Refine(
        renWin, this->GBuffer, this->Voxelizer, view, projection, parameters, refine, occlusion);
    }
    this->Timers[FILTER]->Stop();
  }

  // 5. Composite into the framebuffer the renderer draws into.
  int viewport[4] = { 0, 0, this->GBuffer->GetWidth(), this->GBuffer->GetHeight() };
  if (!s->GetFrameBuffer())
  {
    int w, h;
    ren->GetTiledSizeAndOrigin(&w, &h, &viewport[0], &viewport[1]);
  }
  const bool keepBackground = ren->Transparent() || !ren->GetErase();
  this->Timers[COMPOSITE]->Start();
  if (ok)
  {
    ok = this->Compositor->Composite(renWin,
      this->GBuffer,
      occlusion,
      occlusionScale,
      this->Intensity,
      this->AOOnly,
      keepBackground,
      viewport);
  }
  this->Timers[COMPOSITE]->Stop();
  this->LastFrameHadOcclusion = ok;

  // 6. Volumes, over the composite (not in the AO-only image, which shows A itself).
  if (!volumes.empty() && !(ok && this->AOOnly))
  {
    vtkRenderState volumeState(ren);
    volumeState.SetPropArrayAndCount(volumes.data(), static_cast<int>(volumes.size()));
    volumeState.SetFrameBuffer(s->GetFrameBuffer());
    ostate->vtkglViewport(
      viewport[0], viewport[1], this->GBuffer->GetWidth(), this->GBuffer->GetHeight());
    ostate->vtkglScissor(
      viewport[0], viewport[1], this->GBuffer->GetWidth(), this->GBuffer->GetHeight());
    ostate->vtkglEnable(GL_DEPTH_TEST);
    this->VolumetricPass->Render(&volumeState);
    this->NumberOfRenderedProps += this->VolumetricPass->GetNumberOfRenderedProps();
  }
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::GetAmbientOcclusionImage(vtkImageData* image)
{
  if (!this->LastFrameHadOcclusion || !image)
  {
    return false;
  }
  vtkTextureObject* ao = this->Filter ? this->Upsampler->GetOutput() : this->Tracer->GetOutput();
  return vtkAOCompositor::ReadOcclusion(this->GBuffer, ao, this->Filter ? 1 : this->AOScale, image);
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Voxelizer->ReleaseGraphicsResources(w);
  this->GBuffer->ReleaseGraphicsResources(w);
  this->Tracer->ReleaseGraphicsResources(w);
  this->Upsampler->ReleaseGraphicsResources(w);
  this->Compositor->ReleaseGraphicsResources(w);
  this->VolumetricPass->ReleaseGraphicsResources(w);
  for (auto& timer : this->Timers)
  {
    timer->ReleaseGraphicsResources();
  }
  std::fill(this->StageTimes, this->StageTimes + 5, 0.0);
  this->TimingsPending = false;
  this->VoxelizationSignature.clear();
}

//------------------------------------------------------------------------------
long long vtkHybridAmbientOcclusionPass::GetGraphicsMemorySize()
{
  return this->GBuffer->GetGraphicsMemorySize() + this->Voxelizer->GetGraphicsMemorySize() +
    this->Tracer->GetGraphicsMemorySize() + this->Upsampler->GetGraphicsMemorySize();
}
