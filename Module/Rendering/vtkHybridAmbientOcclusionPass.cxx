#include "vtkHybridAmbientOcclusionPass.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOParallelReducer.h"
#include "vtkAOVoxelTracer.h"
#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

vtkStandardNewMacro(vtkHybridAmbientOcclusionPass);

namespace
{
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
  // Tuned against the reference (see the class documentation): a map at a third of the
  // screen's resolution, and the paper's 16-pixel filter window.
  this->AOScale = 3;
  this->FilterSize = 16;
}

//------------------------------------------------------------------------------
vtkHybridAmbientOcclusionPass::~vtkHybridAmbientOcclusionPass() = default;

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::ApplyPreset(int preset)
{
  if (preset < INTERACTIVE || preset > QUALITY)
  {
    vtkErrorMacro(<< "Unknown preset " << preset << " (expected 0 INTERACTIVE, 1 BALANCED or "
                  << "2 QUALITY): nothing changed.");
    return;
  }
  const bool fast = preset == INTERACTIVE;
  this->SetVoxelResolution(fast ? 256 : 0);
  this->SetVoxelizationAxes(fast ? 1 : 3);
  this->SetRefinement(!fast);
  this->SetCellErosion(fast ? 0.0 : 0.25);
  this->SetAOScale(preset == QUALITY ? 2 : 3);
  this->SetNumberOfRays(preset == QUALITY ? 16 : 8);
  this->SetNumberOfSteps(4);
  this->SetFilterSize(16);
  this->SetNumberOfCascades(0);
  // QUALITY: cells of R / 192 (one grid up to 1024^3, then cascades of 1024^3) and the map's
  // contrast marked from 0.05 (quality.md "Quality preset").
  const bool quality = preset == QUALITY;
  this->SetCellsPerRadius(quality ? 192.0 : 64.0);
  this->SetCascadeResolution(quality ? 1024 : 512);
  this->SetRefinementContrast(quality ? 0.05 : 0.0);
}

//------------------------------------------------------------------------------
const char* vtkHybridAmbientOcclusionPass::GetPresetAsString(int preset)
{
  switch (preset)
  {
    case INTERACTIVE:
      return "interactive";
    case BALANCED:
      return "balanced";
    case QUALITY:
      return "quality";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "CellErosion: " << this->CellErosion << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "VoxelResolution: " << this->VoxelResolution << "\n";
  os << indent << "CellsPerRadius: " << this->CellsPerRadius << "\n";
  os << indent << "MaximumAutomaticResolution: " << this->MaximumAutomaticResolution << "\n";
  os << indent << "NumberOfCascades: " << this->NumberOfCascades << " (resolution "
     << this->CascadeResolution << "; last used " << this->EffectiveNumberOfCascades << ")\n";
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "Refinement: " << this->Refinement << " (rays " << this->RefinementRays
     << ", filter radius " << this->RefinementFilterRadius << ", contrast "
     << this->RefinementContrast << ", " << (this->RefinementList ? "listed" : "in place") << ")\n";
  os << indent << "RegionMode: " << this->RegionMode << "\n";
  os << indent << "VoxelizationCount: " << this->VoxelizationCount << " (incremental "
     << this->IncrementalVoxelizationCount << ")\n";
  os << indent << "IncrementalVoxelization: " << this->IncrementalVoxelization << "\n";
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
    this->ResetVoxelizationState(); // the grid must be rebuilt with the new reducer
    this->Modified();
  }
}
vtkAOParallelReducer* vtkHybridAmbientOcclusionPass::GetParallelReducer()
{
  return this->ParallelReducer;
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::CollectOccluders(vtkRenderer* ren,
  std::vector<vtkProp*>& props,
  double bounds[6])
{
  const bool haveOccluders = this->Superclass::CollectOccluders(ren, props, bounds);
  if (!this->ParallelReducer)
  {
    return haveOccluders;
  }
  // Distributed rendering: the radius and the region come from all processes' occluders.
  this->ParallelReducer->ReduceBounds(bounds);
  return ValidBounds(bounds);
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
namespace
{
// A prop that changed counts as moving for this many frames: it is then voxelized on its own
// over the base of the others (IncrementalVoxelization), and joins the base when it stops.
constexpr long long MovingFrames = 16;

// Everything a prop's voxels depend on. The props' own MTimes are left out on purpose: they
// include their properties (colour, culling), which do not occlude.
std::vector<double> PropSignature(vtkProp* prop)
{
  std::vector<double> signature;
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
    signature.push_back(mapper ? static_cast<double>(mapper->GetMTime()) : 0.0);
    for (int port = 0; mapper && port < mapper->GetNumberOfInputPorts(); ++port)
    {
      for (int c = 0; c < mapper->GetNumberOfInputConnections(port); ++c)
      {
        vtkDataObject* input = mapper->GetInputDataObject(port, c);
        signature.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
      }
    }
  }
  return signature;
}

double PointerValue(vtkProp* prop)
{
  return static_cast<double>(reinterpret_cast<std::uintptr_t>(prop));
}
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::NeedsVoxelization(const std::vector<vtkProp*>& props,
  const double region[6],
  std::vector<vtkProp*>& moving,
  std::vector<vtkProp*>& still)
{
  // Everything the grids depend on but the props and the cascades' foci.
  std::vector<double> gridSignature(region, region + 6);
  gridSignature.push_back(this->EffectiveNumberOfCascades);
  gridSignature.push_back(this->EffectiveVoxelResolution);
  gridSignature.push_back(this->Voxelizer->GetRandomRotation());
  gridSignature.push_back(this->Voxelizer->GetRotationSeed());
  gridSignature.push_back(this->Voxelizer->GetNumberOfAxes());
  bool changed = gridSignature != this->GridSignature || props != this->LastOccluders;
  this->GridSignature.swap(gridSignature);

  // The props seen in the first frame form the scene; later ones arrive, and count as moving.
  const bool first = this->LastOccluders.empty();
  const long long frame = ++this->FrameNumber;
  std::map<vtkProp*, PropRecord> records;
  moving.clear();
  still.clear();
  for (vtkProp* prop : props)
  {
    PropRecord& record = records[prop];
    auto previous = this->PropRecords.find(prop);
    std::vector<double> signature = PropSignature(prop);
    if (previous == this->PropRecords.end())
    {
      record.LastChange = first ? frame - MovingFrames : frame;
      changed = true;
    }
    else
    {
      record.LastChange = previous->second.LastChange;
      if (signature != previous->second.Signature)
      {
        record.LastChange = frame;
        changed = true;
      }
    }
    record.Signature.swap(signature);
    (frame - record.LastChange < MovingFrames ? moving : still).push_back(prop);
  }
  this->PropRecords.swap(records);
  this->LastOccluders = props;
  return changed;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::ResetVoxelizationState()
{
  this->GridSignature.clear();
  this->PropRecords.clear();
  this->LastOccluders.clear();
  for (auto& key : this->BaseKeys)
  {
    key.clear();
  }
}

//------------------------------------------------------------------------------
namespace
{
// Automatic cascades start where one grid's cells would be this many times R / CellsPerRadius
// (R / 8 at the defaults, regions wider than 128 R). Below it one grid of up to 1024^3 is as
// good or better: on a city 80 R wide (cells R / 12.6) one grid has RMSE 0.026 (Wendland) and
// 0.049 (binary), 4 cascades of 512 0.025 and 0.064 for a fifth of the voxelization
// (Documentation/hao.md); the quality scenes (32 R or less) lose 0.001 to 0.025 in cascades.
constexpr double CascadeFactor = 8.0;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::ChooseGrids(vtkOpenGLRenderWindow* renWin,
  const double region[6])
{
  const double longest =
    std::max({ region[1] - region[0], region[3] - region[2], region[5] - region[4] });
  const double wanted = std::ceil(longest * this->CellsPerRadius / this->EffectiveRadius);
  int levels = this->NumberOfCascades;
  if (levels == 0)
  {
    // Automatic: cascades only where one grid of the largest automatic size would have cells
    // coarser than CascadeFactor x R / CellsPerRadius. Below that one grid is better: the
    // cascades give every pixel beyond the finest cube coarser cells, and an object seen
    // from outside its region lies mostly there (fins, R / 34 cells in one 1024^3 grid:
    // RMSE 0.053; cascades of 512: 0.078), as do the far pixels of a large scene.
    // Cascades of the capped grid's size or more are nowhere coarser than it (the last one
    // spans the region as it would), only finer near the camera: they start as soon as one
    // grid is capped (fins, 30 R wide: RMSE 0.033 in one 1024^3 grid, 0.027 in 3 cascades of
    // 1024, Wendland, the QUALITY preset; quality.md "Quality preset").
    const int cap =
      std::min(this->MaximumAutomaticResolution, this->Voxelizer->GetSupportedResolution(renWin));
    const double start = this->CascadeResolution >= cap ? cap : CascadeFactor * cap;
    levels = this->VoxelResolution > 0 || wanted <= start
      ? 1
      : static_cast<int>(std::ceil(std::log2(wanted / std::min(this->CascadeResolution, cap)))) + 1;
  }
  this->EffectiveNumberOfCascades = std::max(1, std::min(levels, vtkAOVoxelTracer::MaximumLevels));
  if (this->EffectiveNumberOfCascades > 1)
  {
    this->EffectiveVoxelResolution = this->VoxelResolution > 0
      ? this->VoxelResolution
      : std::min(this->CascadeResolution, this->Voxelizer->GetSupportedResolution(renWin));
  }
  else
  {
    this->EffectiveVoxelResolution = this->VoxelResolution > 0
      ? this->VoxelResolution
      : this->AutomaticVoxelResolution(renWin, region);
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkHybridAmbientOcclusionPass::CascadeFoci(vtkRenderer* ren,
  const double region[6])
{
  std::vector<double> foci;
  const int levels = this->EffectiveNumberOfCascades;
  if (levels <= 1)
  {
    return foci;
  }
  // Around the eye (the focal point for a parallel projection), as far inside the region as
  // the cube allows: where the region is thinner than the cube (a floor, a city) the cube is
  // centred on it, otherwise it is slid in until it touches the region's face.
  vtkCamera* cam = ren->GetActiveCamera();
  double eye[3];
  if (cam->GetParallelProjection())
  {
    cam->GetFocalPoint(eye);
  }
  else
  {
    cam->GetPosition(eye);
  }
  const double cell = this->EffectiveRadius / this->CellsPerRadius;
  for (int l = 0; l + 1 < levels; ++l)
  {
    const double half = 0.5 * this->EffectiveVoxelResolution * cell * std::ldexp(1.0, l);
    // Moved in steps of 1/16 of the cube, so that the grid stays put while the camera moves
    // within a step (each step is a new voxelization).
    const double step = half / 8.0;
    for (int i = 0; i < 3; ++i)
    {
      const double lo = region[2 * i] + half, hi = region[2 * i + 1] - half;
      const double inside = lo < hi ? std::min(std::max(eye[i], lo), hi) : 0.5 * (lo + hi);
      foci.push_back(step * std::round(inside / step));
    }
    foci.push_back(half);
  }
  foci.insert(foci.end(), { 0.0, 0.0, 0.0, 0.0 }); // the last covers the region
  return foci;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::UpdateFrameGrids()
{
  vtkAOVoxelTracer::Grids& grids = this->FrameGrids;
  grids.assign(1, this->Voxelizer);
  for (int l = 1; l < this->EffectiveNumberOfCascades; ++l)
  {
    vtkSmartPointer<vtkAOBitmaskVoxelizer>& cascade = this->Cascades[l - 1];
    if (!cascade)
    {
      cascade = vtkSmartPointer<vtkAOBitmaskVoxelizer>::New();
    }
    // The same voxel camera and axes as the finest grid.
    cascade->SetRandomRotation(this->Voxelizer->GetRandomRotation());
    cascade->SetRotationSeed(this->Voxelizer->GetRotationSeed());
    cascade->SetNumberOfAxes(this->Voxelizer->GetNumberOfAxes());
    grids.push_back(cascade);
  }
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::PrepareOcclusion(const Frame& frame)
{
  double region[6];
  if (!this->ComputeRegion(frame.Renderer, frame.Bounds, region))
  {
    return false;
  }
  this->ChooseGrids(frame.Window, region);
  const std::vector<double> foci = this->CascadeFoci(frame.Renderer, region);
  // Voxelize when something that occludes changed; a cascade also when it moved.
  const std::vector<vtkProp*>& occluders = frame.Occluders;
  std::vector<vtkProp*> moving, still;
  bool changed = this->NeedsVoxelization(occluders, region, moving, still);
  if (this->ParallelReducer)
  {
    changed = this->ParallelReducer->ReduceAny(changed); // all processes voxelize together
  }
  this->UpdateFrameGrids();
  const vtkAOVoxelTracer::Grids& grids = this->FrameGrids;
  for (int l = this->EffectiveNumberOfCascades; l < vtkAOVoxelTracer::MaximumLevels; ++l)
  {
    if (this->Cascades[l - 1] && this->Cascades[l - 1]->GetGridTexture())
    {
      this->Cascades[l - 1]->ReleaseGraphicsResources(frame.Window); // no longer used
    }
  }
  vtkRenderState voxelState(frame.Renderer), movingState(frame.Renderer),
    stillState(frame.Renderer);
  voxelState.SetPropArrayAndCount(
    const_cast<vtkProp**>(occluders.data()), static_cast<int>(occluders.size()));
  movingState.SetPropArrayAndCount(moving.data(), static_cast<int>(moving.size()));
  stillState.SetPropArrayAndCount(still.data(), static_cast<int>(still.size()));
  // Incremental: the props that move over a kept base of those that do not.
  const bool incremental = this->IncrementalVoxelization && !moving.empty() && !still.empty();
  bool voxelized = false;
  bool incremented = false;
  for (size_t l = 0; l < grids.size(); ++l)
  {
    vtkAOBitmaskVoxelizer* grid = grids[l];
    std::vector<double>& baseKey = this->BaseKeys[l];
    if (!incremental && !baseKey.empty())
    {
      grid->ReleaseBase(frame.Window); // nothing moves any more, or incremental is off
      baseKey.clear();
    }
    const double none[4] = { 0.0, 0.0, 0.0, 0.0 };
    const double* focus = foci.empty() ? none : &foci[4 * l];
    // The cascades follow the camera (the same on every process), each in its own steps.
    if (!changed && grid->GetGridTexture() && std::equal(focus, focus + 4, grid->GetFocus()))
    {
      continue;
    }
    if (!voxelized)
    {
      this->Timers[PREPARE]->Start();
      voxelized = true;
    }
    grid->SetResolution(this->EffectiveVoxelResolution);
    grid->SetRegion(region);
    grid->SetFocus(focus);
    bool useBase = false;
    if (incremental)
    {
      // What the base holds: the grid's frame and each still prop with its last change.
      std::vector<double> key = this->GridSignature;
      key.insert(key.end(), focus, focus + 4);
      for (vtkProp* prop : still)
      {
        key.push_back(PointerValue(prop));
        key.push_back(static_cast<double>(this->PropRecords[prop].LastChange));
      }
      if (key != baseKey || !grid->HasBase())
      {
        grid->RenderBase(&stillState);
        baseKey.swap(key);
      }
      useBase = grid->HasBase();
      if (!useBase)
      {
        baseKey.clear();
      }
    }
    grid->SetUseBase(useBase);
    grid->Render(useBase ? &movingState : &voxelState);
    incremented = incremented || useBase;
    if (l == 0)
    {
      this->NumberOfVoxelizedProps = grid->GetNumberOfRenderedProps();
    }
    if (this->ParallelReducer)
    {
      this->ParallelReducer->ReduceGrid(grid); // OR in the other processes' grids
    }
  }
  if (voxelized)
  {
    this->Timers[PREPARE]->Stop();
    ++this->VoxelizationCount;
    this->IncrementalVoxelizationCount += incremented ? 1 : 0;
  }
  for (vtkAOBitmaskVoxelizer* grid : grids)
  {
    if (grid->GetGridDimensions()[0] == 0)
    {
      return false;
    }
  }
  this->EffectiveBias = this->Bias; // any bias is safe: no automatic one is needed
  return true;
}

//------------------------------------------------------------------------------
vtkAOVoxelTracer::Input vtkHybridAmbientOcclusionPass::TracerInput(const Frame& frame)
{
  vtkAOVoxelTracer::Input input;
  input.Window = frame.Window;
  input.GBuffer = this->GBuffer;
  input.Cascades = this->FrameGrids;
  input.View = frame.View;
  input.Projection = frame.Projection;
  vtkAOVoxelTracer::Parameters& parameters = input.Settings;
  parameters.Scale = this->AOScale;
  parameters.Rays = this->NumberOfRays;
  parameters.Steps = this->NumberOfSteps;
  parameters.Radius = this->EffectiveRadius;
  parameters.Bias = this->EffectiveBias;
  parameters.Spread = this->Spread;
  parameters.Erosion = this->CellErosion;
  parameters.BinaryFalloff = this->Falloff == BINARY;
  parameters.Parallel = frame.Parallel;
  parameters.FollowGridVersions = true; // the grids change only through Render, UploadGrid
  parameters.FrameIndex = frame.AccumulationIndex;
  return input;
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::AppendAccumulationSignature(std::vector<double>& signature)
{
  signature.push_back(this->VoxelizationCount);
  signature.push_back(static_cast<double>(this->Voxelizer->GetMTime()));
  signature.push_back(this->EffectiveNumberOfCascades);
  signature.push_back(this->EffectiveVoxelResolution);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkHybridAmbientOcclusionPass::RenderOcclusion(const Frame& frame)
{
  if (!this->RefinesOcclusion())
  {
    this->Tracer->ReleaseRefinement(frame.Window); // left from frames that refined
  }
  return this->Tracer->Trace(this->TracerInput(frame)) ? this->Tracer->GetOutput() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkHybridAmbientOcclusionPass::RefineOcclusion(const Frame& frame,
  vtkTextureObject* upsampled,
  vtkTextureObject* marks)
{
  this->Tracer->SetListRefinement(this->RefinementList);
  return this->Tracer->Refine(this->TracerInput(frame),
    this->GetEffectiveRefinementRays(),
    this->RefinementFilterRadius,
    marks,
    upsampled);
}

//------------------------------------------------------------------------------
int vtkHybridAmbientOcclusionPass::GetEffectiveRefinementRays() const
{
  if (this->RefinementRays > 0)
  {
    return this->RefinementRays;
  }
  // A binary sample of 8 rays has a standard deviation up to 0.18, and the refined pixels are
  // averaged over a few neighbours of their own surface only: twice the rays took glyphs from
  // 0.053 to 0.048 and iso from 0.052 to 0.050 RMSE (quality.md "Refinement rays with the
  // binary falloff"). The Wendland-weighted samples are quieter (16 rays there: iso 0.045 ->
  // 0.042, the rest 0.001 or less, for twice the refinement's trace).
  return std::min(this->Falloff == BINARY ? 2 * this->NumberOfRays : this->NumberOfRays, 1024);
}

//------------------------------------------------------------------------------
double vtkHybridAmbientOcclusionPass::GetEffectiveRefinementContrast() const
{
  if (this->RefinementContrast > 0.0)
  {
    return this->RefinementContrast;
  }
  // 0.15 marks the creases and mouldings finer than a texel (Wendland, 17 scenes: mean RMSE
  // 0.0202 -> 0.0172, tardis 0.043 -> 0.034; quality.md "Refinement contrast"). The binary
  // falloff's samples are noisier (8 rays: a sample's standard deviation up to 0.18); there
  // 0.15 marked the noise (the built-in scene refined 0.6 -> 4.4 %) for a mean gain of 0.001.
  return this->Falloff == BINARY ? 0.3 : 0.15;
}

//------------------------------------------------------------------------------
double vtkHybridAmbientOcclusionPass::GetRefinedFraction()
{
  return this->RefinesOcclusion() ? this->Tracer->GetRefinedFraction() : 0.0;
}

//------------------------------------------------------------------------------
int vtkHybridAmbientOcclusionPass::AutomaticVoxelResolution(vtkOpenGLRenderWindow* renWin,
  const double region[6])
{
  // Cells of at most R / CellsPerRadius along the region's longest side, within [64, the
  // cap]; the implementation's own limit applies without a warning (it was not asked for).
  const double longest =
    std::max({ region[1] - region[0], region[3] - region[2], region[5] - region[4] });
  const double wanted = std::ceil(longest * this->CellsPerRadius / this->EffectiveRadius);
  const int cap =
    std::min(this->MaximumAutomaticResolution, this->Voxelizer->GetSupportedResolution(renWin));
  return static_cast<int>(std::max(64.0, std::min(static_cast<double>(cap), wanted)));
}

//------------------------------------------------------------------------------
void vtkHybridAmbientOcclusionPass::ReleaseOcclusionResources(vtkWindow* w)
{
  this->Voxelizer->ReleaseGraphicsResources(w);
  for (auto& cascade : this->Cascades)
  {
    if (cascade)
    {
      cascade->ReleaseGraphicsResources(w);
    }
  }
  this->Tracer->ReleaseGraphicsResources(w);
  this->ResetVoxelizationState();
}

//------------------------------------------------------------------------------
long long vtkHybridAmbientOcclusionPass::GetOcclusionMemorySize()
{
  long long bytes =
    this->Voxelizer->GetGraphicsMemorySize() + this->Tracer->GetGraphicsMemorySize();
  for (auto& cascade : this->Cascades)
  {
    bytes += cascade ? cascade->GetGraphicsMemorySize() : 0;
  }
  return bytes;
}
