#include "vtkAmbientOcclusionVolumesPass.h"

#include "vtkAOVolumeRasterizer.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkAmbientOcclusionVolumesPass);

//------------------------------------------------------------------------------
// The shared parameters' defaults are AOV's: AOScale 1 (every pixel evaluated: the map is exact
// and noise-free, so filtering only blurs it) and FilterSize 6.
vtkAmbientOcclusionVolumesPass::vtkAmbientOcclusionVolumesPass() = default;
vtkAmbientOcclusionVolumesPass::~vtkAmbientOcclusionVolumesPass() = default;

//------------------------------------------------------------------------------
const char* vtkAmbientOcclusionVolumesPass::GetCombinationAsString()
{
  return this->Combination == MULTIPLICATIVE ? "Multiplicative" : "Additive";
}

//------------------------------------------------------------------------------
vtkIdType vtkAmbientOcclusionVolumesPass::GetNumberOfOccludingTriangles()
{
  return this->Rasterizer->GetNumberOfTriangles();
}

//------------------------------------------------------------------------------
int vtkAmbientOcclusionVolumesPass::GetGeometryUpdateCount()
{
  return this->Rasterizer->GetUpdateCount();
}

//------------------------------------------------------------------------------
vtkAOVolumeRasterizer* vtkAmbientOcclusionVolumesPass::GetRasterizer()
{
  return this->Rasterizer;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::PrepareOcclusion(const Frame& frame)
{
  // Enough to clear depth-reconstruction error, no more (see the class documentation).
  const double* b = frame.Bounds;
  const double longest =
    std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] }) + 2.0 * this->EffectiveRadius;
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : longest / 2000.0;
  return this->Rasterizer->UpdateOccluders(frame.Window, frame.Occluders, frame.Bounds);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkAmbientOcclusionVolumesPass::RenderOcclusion(const Frame& frame)
{
  vtkAOVolumeRasterizer::Parameters parameters;
  parameters.Scale = this->AOScale;
  parameters.Radius = this->EffectiveRadius;
  parameters.Bias = this->EffectiveBias;
  parameters.BinaryFalloff = this->Falloff == BINARY;
  parameters.Multiplicative = this->Combination == MULTIPLICATIVE;
  parameters.Parallel = frame.Parallel;
  parameters.SampleOffset[0] = frame.SampleOffset[0];
  parameters.SampleOffset[1] = frame.SampleOffset[1];
  return this->Rasterizer->Render(
           frame.Window, this->GBuffer, frame.View, frame.Projection, parameters)
    ? this->Rasterizer->GetOutput()
    : nullptr;
}

//------------------------------------------------------------------------------
long long vtkAmbientOcclusionVolumesPass::GetOcclusionMemorySize()
{
  return this->Rasterizer->GetGraphicsMemorySize();
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::ReleaseOcclusionResources(vtkWindow* w)
{
  this->Rasterizer->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Combination: " << this->GetCombinationAsString() << "\n";
  os << indent << "NumberOfOccludingTriangles: " << this->GetNumberOfOccludingTriangles() << "\n";
  os << indent << "GeometryUpdateCount: " << this->GetGeometryUpdateCount() << "\n";
}
