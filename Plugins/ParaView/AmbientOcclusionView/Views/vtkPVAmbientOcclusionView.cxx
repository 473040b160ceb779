#include "vtkPVAmbientOcclusionView.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVAOParallelReducer.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderStepsPass.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVAmbientOcclusionView);

//------------------------------------------------------------------------------
vtkPVAmbientOcclusionView::vtkPVAmbientOcclusionView()
{
  // Like vtkRenderer with vtkHybridAmbientOcclusionPass in a VTK application: the pass renders
  // its delegate into the G-buffer (the IceT pass, when there is one, wraps all of it).
  this->HybridPass->SetDelegatePass(this->HybridDelegate);
  this->HybridPass->SetParallelReducer(this->Reducer);
  this->HybridPass->SetMaximumAccumulatedFrames(this->AmbientOcclusionAccumulatedFrames);
  this->UpdateAmbientOcclusionPass();
}

//------------------------------------------------------------------------------
vtkPVAmbientOcclusionView::~vtkPVAmbientOcclusionView() = default;

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::UpdateAmbientOcclusionPass()
{
  this->SynchronizedRenderers->SetRenderPass(
    this->AmbientOcclusionMethod == HAO ? this->HybridPass.GetPointer() : nullptr);
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::Render(bool interactive, bool skip_rendering)
{
  if (this->AmbientOcclusionMethod != NONE)
  {
    this->RenderEmptyImages = true; // read by vtkPVRenderView::Render for IceT
  }
  // A still renders the accumulation's frames; the count depends only on properties, which
  // every rank shares, so all ranks render and composite together.
  const int frames = !interactive && !skip_rendering && this->AmbientOcclusionMethod != NONE
    ? this->AmbientOcclusionAccumulatedFrames
    : 1;
  for (int frame = 0; frame < frames; ++frame)
  {
    this->Superclass::Render(interactive, skip_rendering);
  }

  vtkHybridAmbientOcclusionPass* pass = this->HybridPass;
  vtkPVAOParallelReducer* reducer = this->Reducer;
  const int* dims = pass->GetVoxelizer()->GetGridDimensions();
  const double statistics[16] = { static_cast<double>(pass->GetVoxelizationCount()),
    static_cast<double>(reducer->GetNumberOfGridReductions()),
    reducer->GetLastGridBytes(),
    reducer->GetLastDownloadTime(),
    reducer->GetLastSyncTime(),
    reducer->GetLastAllReduceTime(),
    reducer->GetLastUploadTime(),
    pass->GetVoxelizeTime(),
    pass->GetLastFrameHadOcclusion() ? 1.0 : 0.0,
    static_cast<double>(dims[0]),
    static_cast<double>(dims[1]),
    static_cast<double>(dims[2]),
    reducer->GetLastMessageBytes(),
    static_cast<double>(pass->GetAccumulatedFrames()),
    this->AmbientOcclusionMethod == HAO ? pass->GetRefinedFraction() : 0.0,
    static_cast<double>(pass->GetIncrementalVoxelizationCount()) };
  std::copy(statistics, statistics + 16, this->AmbientOcclusionStatistics);
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::SetAmbientOcclusionMethod(int method)
{
  if (method != NONE && method != HAO)
  {
    vtkWarningMacro(<< "Unknown ambient occlusion method " << method << "; using None.");
    method = NONE;
  }
  if (this->AmbientOcclusionMethod != method)
  {
    this->AmbientOcclusionMethod = method;
    this->UpdateAmbientOcclusionPass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::SetAmbientOcclusionRadius(double radius)
{
  this->HybridPass->SetRadius(radius);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionRays(int rays)
{
  this->HybridPass->SetNumberOfRays(rays);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionSteps(int steps)
{
  this->HybridPass->SetNumberOfSteps(steps);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionVoxelResolution(int resolution)
{
  this->HybridPass->SetVoxelResolution(resolution);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionRegionMode(int mode)
{
  this->HybridPass->SetRegionMode(mode);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionExplicitRegion(double xmin,
  double xmax,
  double ymin,
  double ymax,
  double zmin,
  double zmax)
{
  this->HybridPass->SetExplicitRegion(xmin, xmax, ymin, ymax, zmin, zmax);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionIntensity(double intensity)
{
  this->HybridPass->SetIntensity(intensity);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionFalloff(int falloff)
{
  this->HybridPass->SetFalloff(falloff);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionFilterSize(int size)
{
  this->HybridPass->SetFilterSize(size);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionOnly(bool only)
{
  this->HybridPass->SetAOOnly(only);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionScale(int scale)
{
  this->HybridPass->SetAOScale(scale);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionRefinement(bool on)
{
  this->HybridPass->SetRefinement(on);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionRefinementContrast(double contrast)
{
  this->HybridPass->SetRefinementContrast(contrast);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionIncrementalVoxelization(bool on)
{
  this->HybridPass->SetIncrementalVoxelization(on);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionCellsPerRadius(double cells)
{
  this->HybridPass->SetCellsPerRadius(cells);
}
void vtkPVAmbientOcclusionView::SetAmbientOcclusionVoxelizationAxes(int axes)
{
  this->HybridPass->SetVoxelizationAxes(axes);
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::SetAmbientOcclusionAccumulatedFrames(int frames)
{
  frames = std::max(1, std::min(frames, 1024));
  if (this->AmbientOcclusionAccumulatedFrames != frames)
  {
    this->AmbientOcclusionAccumulatedFrames = frames;
    this->HybridPass->SetMaximumAccumulatedFrames(frames);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::SetAmbientOcclusionParallelReduction(bool on)
{
  if (this->AmbientOcclusionParallelReduction != on)
  {
    this->AmbientOcclusionParallelReduction = on;
    this->HybridPass->SetParallelReducer(on ? this->Reducer.GetPointer() : nullptr);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkHybridAmbientOcclusionPass* vtkPVAmbientOcclusionView::GetHybridAmbientOcclusionPass()
{
  return this->HybridPass;
}

//------------------------------------------------------------------------------
vtkPVAOParallelReducer* vtkPVAmbientOcclusionView::GetParallelReducer()
{
  return this->Reducer;
}

//------------------------------------------------------------------------------
void vtkPVAmbientOcclusionView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AmbientOcclusionMethod: " << this->AmbientOcclusionMethod << "\n";
  os << indent << "AmbientOcclusionAccumulatedFrames: " << this->AmbientOcclusionAccumulatedFrames
     << "\n";
  os << indent << "AmbientOcclusionParallelReduction: " << this->AmbientOcclusionParallelReduction
     << "\n";
}
