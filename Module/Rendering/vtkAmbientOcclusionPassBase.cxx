#include "vtkAmbientOcclusionPassBase.h"

#include "vtkAOAccumulator.h"
#include "vtkAOBilateralUpsampler.h"
#include "vtkAOCompositor.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOPropGeometry.h"
#include "vtkCamera.h"
#include "vtkHardwareSelector.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOverlayPass.h"
#include "vtkProp3D.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVolume.h"
#include "vtkVolumetricPass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

//------------------------------------------------------------------------------
vtkAmbientOcclusionPassBase::vtkAmbientOcclusionPassBase()
{
  // The steps of vtkRenderStepsPass that 2-D props draw in, without its camera pass (which
  // may clear the framebuffer).
  vtkNew<vtkRenderPassCollection> steps;
  vtkNew<vtkOpaquePass> opaque;
  vtkNew<vtkTranslucentPass> translucent;
  vtkNew<vtkOverlayPass> overlay;
  steps->AddItem(opaque);
  steps->AddItem(translucent);
  steps->AddItem(overlay);
  this->Props2DPass->SetPasses(steps);
  for (auto& timer : this->Timers)
  {
    timer = new vtkOpenGLRenderTimer;
  }
}

//------------------------------------------------------------------------------
vtkAmbientOcclusionPassBase::~vtkAmbientOcclusionPassBase()
{
  for (auto& timer : this->Timers)
  {
    delete timer;
  }
  // The GL object frees itself through its context's resource callbacks.
  if (this->NoOcclusion)
  {
    this->NoOcclusion->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "Falloff: " << (this->Falloff == WENDLAND ? "Wendland" : "Binary") << "\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "AOOnly: " << this->AOOnly << "\n";
  os << indent << "AOScale: " << this->AOScale << "\n";
  os << indent << "FilterSize: " << this->FilterSize << "\n";
  os << indent << "Accumulation: " << this->Accumulation << " (at most "
     << this->MaximumAccumulatedFrames << " frames; last " << this->AccumulatedFrames << ")\n";
  os << indent << "LastFrameHadOcclusion: " << this->LastFrameHadOcclusion << "\n";
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::ValidBounds(const double b[6])
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

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::CollectOccluders(vtkRenderer* ren,
  std::vector<vtkProp*>& props,
  double bounds[6])
{
  // All visible props, not the frustum-culled list of the render state: occluders off
  // screen and behind the camera are the point of the object-space methods.
  if (vtkAOPropGeometry::CollectOccluders(ren, false, props, bounds) && !this->Warned)
  {
    vtkWarningMacro(<< "A prop has non-finite bounds; it does not occlude.");
    this->Warned = true;
  }
  return !props.empty();
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::UpdateEffectiveRadius(const double b[6])
{
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  this->EffectiveRadius = this->Radius > 0.0 ? this->Radius : 0.1 * diagonal;
  return this->EffectiveRadius > 0.0 && std::isfinite(this->EffectiveRadius);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::CollectTimings(bool wait)
{
  if (!this->TimingsPending)
  {
    return;
  }
  // One frame's queries at a time: a stage that did not run (HAO's voxelization of a static
  // scene) reports 0, and every timer is free for the next frame afterwards.
  for (int i = 0; i < NUMBER_OF_STAGES; ++i)
  {
    vtkOpenGLRenderTimer* timer = this->Timers[i];
    this->StageTimes[i] =
      timer->Stopped() && (wait || timer->Ready()) ? timer->GetElapsedMilliseconds() : 0.0;
    timer->Reset();
  }
  this->TimingsPending = false;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::FinishTimings()
{
  this->CollectTimings(true);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::RenderForSelection(const vtkRenderState* s)
{
  // Picking renders ids, not colours: no AO. The props must go through the selector, which
  // assigns each its id (vtkRenderer::UpdateGeometry does this without a pass); a delegate
  // such as vtkRenderStepsPass would draw them all with id 0 and nothing would be picked.
  // So render as vtkOpenGLRenderer::DeviceRender does without a pass.
  vtkRenderer* ren = s->GetRenderer();
  this->ClearLights(ren);
  this->UpdateCamera(ren);
  this->UpdateLightGeometry(ren);
  this->UpdateLights(ren);
  this->NumberOfRenderedProps =
    ren->GetSelector()->Render(ren, s->GetPropArray(), s->GetPropArrayCount());
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::RenderWithoutOcclusion(const vtkRenderState* s)
{
  this->AccumulatedFrames = 0;
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->LastFrameHadOcclusion = false;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass in " << this->GetClassName() << ": nothing is drawn.");
    return;
  }
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (ren->GetSelector())
  {
    this->RenderForSelection(s);
    return;
  }
  if (!renWin)
  {
    this->RenderWithoutOcclusion(s);
    return;
  }

  // The previous frame's queries have normally finished by now: read them without waiting.
  this->CollectTimings(false);

  Frame frame;
  frame.Window = renWin;
  frame.Renderer = ren;
  if (!this->CollectFrame(frame))
  {
    // Nothing that occludes (empty renderer, single point, degenerate bounds): plain render.
    this->RenderWithoutOcclusion(s);
    return;
  }
  this->RenderOccludedFrame(s, frame);
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::CollectFrame(Frame& frame)
{
  return this->CollectOccluders(frame.Renderer, frame.Occluders, frame.Bounds) &&
    this->UpdateEffectiveRadius(frame.Bounds);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::UpdateFrameCamera(Frame& frame)
{
  vtkRenderer* ren = frame.Renderer;
  vtkCamera* cam = ren->GetActiveCamera();
  frame.View->DeepCopy(cam->GetViewTransformMatrix());
  frame.Projection->DeepCopy(cam->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
  frame.Parallel = cam->GetParallelProjection() != 0;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::RenderOccludedFrame(const vtkRenderState* s, Frame& frame)
{
  this->TimingsPending = true;
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  // The stages bind their textures to other units: leave the active unit as it was.
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);

  // 1. The subclass's per-scene work (voxelization, triangle buffer).
  if (!this->PrepareOcclusion(frame))
  {
    this->RenderWithoutOcclusion(s);
    return;
  }

  // 2. G-buffer of the surfaces.
  FrameProps props;
  this->RenderGBuffer(s, props);
  this->UpdateFrameCamera(frame); // as the delegate left it

  // A still view whose mean holds every frame it can use needs no new occlusion.
  const bool converged = this->UpdateAccumulation(s, frame);
  bool ok = true;
  if (converged)
  {
    this->Result = this->Accumulator->GetOutput();
    this->ResultScale = this->AccumulatedScale;
  }
  else if (this->StratifiedFrame(frame))
  {
    // 3-5. The map at this frame's pixel of each block, written at those pixels of the mean.
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ok = this->RenderStratifiedOcclusion(frame);
  }
  else
  {
    // 3. The occlusion stage: the AO map.
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    this->Timers[OCCLUSION]->Start();
    vtkTextureObject* occlusion = this->RenderOcclusion(frame);
    this->Timers[OCCLUSION]->Stop();
    this->FirstMap = occlusion; // the stratified path's second frame scatters it

    // 4. Upsample and filter (and refine); 5. add to the running mean.
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ok = occlusion && this->FilterOcclusion(frame, occlusion) && this->AccumulateOcclusion(frame);
  }
  // 6. Composite.
  ok = this->Composite(s, frame.Window, ok) && ok;
  this->LastFrameHadOcclusion = ok;
  if (!ok)
  {
    this->AccumulatedFrames = 0;
    this->LastAccumulationSignature.clear();
    this->LastAccumulationCamera.clear();
  }

  // 7. Volumes, over the composite (not in the AO-only image, which shows A itself).
  if (ok && this->AOOnly)
  {
    return;
  }
  if (!props.Volumes.empty())
  {
    this->RenderOverComposite(s, frame.Window, this->VolumetricPass, props.Volumes);
  }

  // 8. The overlay step of the surfaces (their own 2-D content), and the 2-D props, last.
  if (props.SurfaceOverlayStep && !props.Surfaces.empty())
  {
    this->RenderOverComposite(s, frame.Window, props.SurfaceOverlayStep, props.Surfaces);
  }
  if (!props.Overlays.empty())
  {
    this->RenderOverComposite(s, frame.Window, this->Props2DPass, props.Overlays);
  }
}

//------------------------------------------------------------------------------
int vtkAmbientOcclusionPassBase::AccumulationTarget()
{
  if (this->JittersOcclusion())
  {
    return this->MaximumAccumulatedFrames;
  }
  if (this->StratifiesSubsampledMap() && this->UsesFilter())
  {
    return std::min(this->MaximumAccumulatedFrames, this->AOScale * this->AOScale);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::StratifiedFrame(const Frame& frame)
{
  return this->Accumulation && frame.AccumulationIndex > 0 && this->FirstMap &&
    this->StratifiesSubsampledMap() && this->UsesFilter();
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::GetSampleOffset(int k, int offset[2])
{
  // The pixels of an s x s block in an order that covers it evenly at every step: the centre
  // (where a frame without accumulation evaluates), then each time the pixel farthest from
  // those taken (distances wrap around, as the blocks tile the screen; ties in row order).
  const int s = this->AOScale;
  if (this->StratifiedOrderScale != s)
  {
    const int n = s * s;
    std::vector<int> nearest(n, n * n), order;
    auto take = [&](int p)
    {
      order.push_back(p);
      for (int q = 0; q < n; ++q)
      {
        const int dx = std::abs(q % s - p % s), dy = std::abs(q / s - p / s);
        const int wx = std::min(dx, s - dx), wy = std::min(dy, s - dy);
        nearest[q] = std::min(nearest[q], wx * wx + wy * wy);
      }
    };
    take((s / 2) * s + s / 2);
    while (static_cast<int>(order.size()) < n)
    {
      take(static_cast<int>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin()));
    }
    this->StratifiedOrder.swap(order);
    this->StratifiedOrderScale = s;
  }
  const int p = this->StratifiedOrder[std::max(0, std::min(k, s * s - 1))];
  offset[0] = p % s;
  offset[1] = p / s;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::RenderStratifiedOcclusion(Frame& frame)
{
  const int k = frame.AccumulationIndex;
  // The first frame's map is still the stage's output: its pixels first, as raw values.
  int first[2];
  this->GetSampleOffset(0, first);
  if (k == 1 && !this->Accumulator->Scatter(frame.Window, this->FirstMap, this->AOScale, first))
  {
    return false;
  }
  this->Timers[OCCLUSION]->Start();
  vtkTextureObject* occlusion = this->RenderOcclusion(frame);
  this->Timers[OCCLUSION]->Stop();
  this->Timers[FILTER]->Start();
  const bool ok = occlusion &&
    this->Accumulator->Scatter(frame.Window, occlusion, this->AOScale, frame.SampleOffset);
  this->Timers[FILTER]->Stop();
  if (!ok)
  {
    return false;
  }
  this->AccumulatedFrames = k + 1;
  this->AccumulatedScale = 1;
  this->Result = this->Accumulator->GetOutput();
  this->ResultScale = 1;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::IsAccumulating()
{
  return this->Accumulation && this->LastFrameHadOcclusion &&
    this->AccumulatedFrames < this->AccumulationTarget();
}

//------------------------------------------------------------------------------
std::vector<double> vtkAmbientOcclusionPassBase::AccumulationSignature(const vtkRenderState* s,
  const Frame& frame)
{
  // The pass's parameters (every setter modifies it), the size, the camera, and each prop
  // that is drawn or occludes: its address, visibility, modification time (transform,
  // property) and its surfaces' signature (mapper, inputs, world matrix).
  std::vector<double> signature{ static_cast<double>(this->GetMTime()),
    static_cast<double>(this->GBuffer->GetWidth()),
    static_cast<double>(this->GBuffer->GetHeight()),
    frame.Parallel ? 1.0 : 0.0,
    this->EffectiveRadius,
    this->EffectiveBias };
  int viewport[4];
  this->GetTargetViewport(s, viewport);
  signature.insert(signature.end(), viewport, viewport + 4);
  auto appendProp = [&signature](vtkProp* prop)
  {
    signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(prop)));
    signature.push_back(prop->GetVisibility());
    signature.push_back(static_cast<double>(prop->GetMTime()));
    vtkAOPropGeometry::AppendSignature(prop, signature);
  };
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    // 2-D props (text, scalar bars) do not reach the G-buffer's depth or normals: a frame
    // counter in the same renderer must not restart the mean every frame.
    if (vtkProp3D::SafeDownCast(s->GetPropArray()[i]))
    {
      appendProp(s->GetPropArray()[i]);
    }
  }
  for (vtkProp* prop : frame.Occluders)
  {
    appendProp(prop);
  }
  this->AppendAccumulationSignature(signature);
  return signature;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::UpdateAccumulation(const vtkRenderState* s, Frame& frame)
{
  std::vector<double> signature = this->AccumulationSignature(s, frame);
  // The camera's matrices are compared with a tolerance: a capture by vtkWindowToImageFilter
  // renders through a copy of the camera whose view angle went through a float (a relative
  // change of about 1e-7), and must add to the mean, not restart it (screenshots of a still).
  std::vector<double> camera;
  for (vtkMatrix4x4* m : { frame.View.GetPointer(), frame.Projection.GetPointer() })
  {
    camera.insert(camera.end(), &m->Element[0][0], &m->Element[0][0] + 16);
  }
  bool sameCamera = camera.size() == this->LastAccumulationCamera.size();
  for (size_t i = 0; sameCamera && i < camera.size(); ++i)
  {
    const double a = camera[i], b = this->LastAccumulationCamera[i];
    sameCamera = std::abs(a - b) <= 1e-6 * std::max({ 1.0, std::abs(a), std::abs(b) });
  }
  const bool unchanged = this->Accumulation && this->AccumulatedFrames > 0 &&
    this->Accumulator->GetOutput() && sameCamera && signature == this->LastAccumulationSignature;
  if (!unchanged)
  {
    this->AccumulatedFrames = 0;               // restart
    this->LastAccumulationCamera.swap(camera); // a drift within the tolerance does not add up
  }
  this->LastAccumulationSignature.swap(signature);
  frame.AccumulationIndex = this->AccumulatedFrames;
  this->GetSampleOffset(
    this->StratifiedFrame(frame) ? frame.AccumulationIndex : 0, frame.SampleOffset);
  return unchanged && this->AccumulatedFrames >= this->AccumulationTarget();
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::AccumulateOcclusion(const Frame& frame)
{
  if (!this->Accumulation)
  {
    this->AccumulatedFrames = 1;
    return true;
  }
  const int count = this->AccumulatedFrames + 1;
  if (!this->Accumulator->Accumulate(frame.Window, this->Result, count))
  {
    this->AccumulatedFrames = 0;
    return false;
  }
  this->AccumulatedFrames = count;
  this->AccumulatedScale = this->ResultScale;
  this->Result = this->Accumulator->GetOutput();
  return true;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::GetLastFrameCompletedNormals()
{
  return this->GBuffer->GetNormalsCompleted();
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::RenderGBuffer(const vtkRenderState* s, FrameProps& props)
{
  // Volumes are not surfaces: they are drawn after the composite, over the occluded surfaces
  // and against the depth the compositor restores. 2-D props and widget representations
  // (IsOverlay) are drawn after that: the shaders of 2-D actors write only a colour, which would
  // leave the G-buffer's normals under them undefined, and the composite would darken them by
  // the occlusion of what lies behind.
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (vtkVolume::SafeDownCast(prop))
    {
      props.Volumes.push_back(prop);
    }
    else if (vtkAOPropGeometry::IsOverlay(prop))
    {
      props.Overlays.push_back(prop);
    }
    else
    {
      props.Surfaces.push_back(prop);
    }
  }
  // For the same reason the overlay step of a vtkRenderStepsPass delegate (the surfaces' own
  // 2-D content: vtkAxesActor's captions) is taken out of the G-buffer and run after the
  // composite.
  vtkRenderStepsPass* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  if (steps && steps->GetOverlayPass())
  {
    props.SurfaceOverlayStep = steps->GetOverlayPass();
    steps->SetOverlayPass(nullptr);
  }
  vtkRenderState surfaceState(s->GetRenderer());
  surfaceState.SetPropArrayAndCount(props.Surfaces.data(), static_cast<int>(props.Surfaces.size()));
  surfaceState.SetFrameBuffer(s->GetFrameBuffer());
  surfaceState.SetRequiredKeys(s->GetRequiredKeys());
  this->GBuffer->SetDelegatePass(this->DelegatePass);
  this->Timers[GBUFFER]->Start();
  this->GBuffer->Render(&surfaceState);
  this->Timers[GBUFFER]->Stop();
  this->NumberOfRenderedProps = this->GBuffer->GetNumberOfRenderedProps();
  if (props.SurfaceOverlayStep)
  {
    steps->SetOverlayPass(props.SurfaceOverlayStep);
  }
}

//------------------------------------------------------------------------------
double vtkAmbientOcclusionPassBase::RefinementMarkingContrast()
{
  return vtkAOBilateralUpsampler::Marking().Contrast;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::FilterOcclusion(const Frame& frame, vtkTextureObject* occlusion)
{
  this->Result = occlusion;
  this->ResultScale = this->AOScale;
  if (!this->UsesFilter())
  {
    // Targets left from frames that filtered are freed.
    if (this->Upsampler->GetGraphicsMemorySize() > 0)
    {
      this->Upsampler->ReleaseGraphicsResources(frame.Window);
    }
    return true;
  }
  this->Timers[FILTER]->Start();
  vtkAOBilateralUpsampler::Marking marking;
  marking.Enabled = this->RefinesOcclusion();
  marking.Contrast = this->RefinementMarkingContrast();
  const bool ok = this->Upsampler->Upsample(frame.Window,
    this->GBuffer,
    occlusion,
    frame.Projection,
    frame.Parallel,
    this->AOScale,
    this->FilterSize,
    this->EffectiveRadius,
    marking);
  // The filter stage's time includes the refinement.
  const bool refined = ok &&
    (!marking.Enabled ||
      this->RefineOcclusion(frame, this->Upsampler->GetOutput(), this->Upsampler->GetMarks()));
  this->Timers[FILTER]->Stop();
  if (ok)
  {
    this->Result = this->Upsampler->GetOutput();
    this->ResultScale = 1;
  }
  return ok && refined;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::GetTargetViewport(const vtkRenderState* s, int viewport[4])
{
  viewport[0] = viewport[1] = 0;
  viewport[2] = this->GBuffer->GetWidth();
  viewport[3] = this->GBuffer->GetHeight();
  if (!s->GetFrameBuffer())
  {
    int w, h;
    s->GetRenderer()->GetTiledSizeAndOrigin(&w, &h, &viewport[0], &viewport[1]);
  }
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::Composite(const vtkRenderState* s,
  vtkOpenGLRenderWindow* renWin,
  bool ok)
{
  vtkTextureObject* occlusion = this->Result;
  int scale = this->ResultScale;
  if (!ok)
  {
    // The plain image still has to reach the screen: composite with A = 1.
    if (!this->NoOcclusion)
    {
      this->NoOcclusion = vtkTextureObject::New();
    }
    if (this->NoOcclusion->GetContext() != renWin || !this->NoOcclusion->GetHandle())
    {
      float open[4] = { 1.0f, 0.0f, 0.0f, 0.0f };
      this->NoOcclusion->SetContext(renWin);
      this->NoOcclusion->Create2DFromRaw(1, 1, 4, VTK_FLOAT, open);
    }
    occlusion = this->NoOcclusion;
    scale = 1;
  }
  vtkAOCompositor::Parameters parameters;
  parameters.OcclusionScale = scale;
  parameters.Intensity = ok ? this->Intensity : 0.0;
  parameters.AOOnly = ok && this->AOOnly;
  vtkRenderer* ren = s->GetRenderer();
  parameters.KeepBackground = ren->Transparent() || !ren->GetErase();
  this->GetTargetViewport(s, parameters.Viewport);
  this->Timers[COMPOSITE]->Start();
  const bool composited = this->Compositor->Composite(renWin, this->GBuffer, occlusion, parameters);
  this->Timers[COMPOSITE]->Stop();
  return composited;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::RenderOverComposite(const vtkRenderState* s,
  vtkOpenGLRenderWindow* renWin,
  vtkRenderPass* pass,
  const std::vector<vtkProp*>& props)
{
  int viewport[4];
  this->GetTargetViewport(s, viewport);
  vtkRenderState state(s->GetRenderer());
  state.SetPropArrayAndCount(const_cast<vtkProp**>(props.data()), static_cast<int>(props.size()));
  state.SetFrameBuffer(s->GetFrameBuffer());
  state.SetRequiredKeys(s->GetRequiredKeys());
  // The state the renderer draws them in without a pass: blended over the image, depth-tested
  // against the depth the compositor restored.
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  ostate->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  pass->Render(&state);
  this->NumberOfRenderedProps += pass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionPassBase::GetAmbientOcclusionImage(vtkImageData* image)
{
  if (!this->LastFrameHadOcclusion || !image || !this->Result)
  {
    return false;
  }
  return vtkAOCompositor::ReadOcclusion(this->GBuffer, this->Result, this->ResultScale, image);
}

//------------------------------------------------------------------------------
long long vtkAmbientOcclusionPassBase::GetGraphicsMemorySize()
{
  return this->GBuffer->GetGraphicsMemorySize() + this->GetOcclusionMemorySize() +
    this->Upsampler->GetGraphicsMemorySize() + this->Accumulator->GetGraphicsMemorySize();
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionPassBase::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->GBuffer->ReleaseGraphicsResources(w);
  this->ReleaseOcclusionResources(w);
  this->Upsampler->ReleaseGraphicsResources(w);
  this->Accumulator->ReleaseGraphicsResources(w);
  this->AccumulatedFrames = 0;
  this->LastAccumulationSignature.clear();
  this->LastAccumulationCamera.clear();
  this->Compositor->ReleaseGraphicsResources(w);
  this->VolumetricPass->ReleaseGraphicsResources(w);
  this->Props2DPass->ReleaseGraphicsResources(w);
  if (this->NoOcclusion)
  {
    this->NoOcclusion->ReleaseGraphicsResources(w);
  }
  for (auto& timer : this->Timers)
  {
    timer->ReleaseGraphicsResources();
  }
  std::fill(this->StageTimes, this->StageTimes + NUMBER_OF_STAGES, 0.0);
  this->TimingsPending = false;
  this->Result = nullptr;
  this->FirstMap = nullptr;
}
