#include "vtkAOVertexBaker.h"

#include "vtkAOEmbreeScene.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>

vtkStandardNewMacro(vtkAOVertexBaker);

//------------------------------------------------------------------------------
vtkAOVertexBaker::vtkAOVertexBaker()
{
  // Embree builds its own scene from the polydata (ear-cut polygons).
  this->GatherTriangles = false;
}

vtkAOVertexBaker::~vtkAOVertexBaker() = default;

//------------------------------------------------------------------------------
void vtkAOVertexBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "Falloff: " << (this->Falloff == BINARY ? "binary" : "Wendland") << "\n";
  os << indent << "Sampling: " << (this->Sampling == UNIFORM ? "uniform" : "cosine") << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "TraceTime: " << this->TraceTime << "\n";
}

//------------------------------------------------------------------------------
void vtkAOVertexBaker::InitializeResults(vtkIdType vtkNotUsed(numberOfPoints))
{
  this->NumberOfRays = 0;
  this->TraceTime = 0.0;
}

//------------------------------------------------------------------------------
int vtkAOVertexBaker::BakePoints(Surface& surface, float* values)
{
  // The occluders: the input itself and every polydata on port 1.
  vtkAOEmbreeScene scene;
  scene.AddPolyData(surface.Input);
  const int occluders = surface.Occluders->GetNumberOfInformationObjects();
  for (int i = 0; i < occluders; ++i)
  {
    scene.AddPolyData(vtkPolyData::GetData(surface.Occluders, i));
  }
  if (!scene.Commit())
  {
    vtkErrorMacro(<< "Couldn't build the ray-tracing scene: " << scene.GetError());
    return 0;
  }
  scene.GetEffectiveRadiusAndBias(
    this->Radius, this->Bias, this->EffectiveRadius, this->EffectiveBias);

  vtkAOIntegralParameters parameters;
  parameters.Radius = this->EffectiveRadius;
  parameters.Bias = this->EffectiveBias;
  parameters.Spread = this->Spread;
  parameters.BinaryFalloff = this->Falloff == BINARY;
  parameters.CosineSampling = this->Sampling == COSINE;
  parameters.Samples = this->Samples;
  parameters.Seed = this->Seed;

  vtkPoints* points = surface.Input->GetPoints();
  const std::vector<vtkIdType>& baked = surface.Baked;
  std::atomic<std::int64_t> rayCount(0);
  auto bake = [&](vtkIdType first, vtkIdType last)
  {
    std::int64_t rays = 0;
    for (vtkIdType b = first; b < last; ++b)
    {
      const vtkIdType i = baked[b];
      double p[3];
      points->GetPoint(i, p);
      values[i] = static_cast<float>(scene.ComputeAccessibility(
        p, &surface.Normals[3 * i], parameters, static_cast<std::uint64_t>(i), rays));
    }
    rayCount += rays;
  };

  const auto start = std::chrono::steady_clock::now();
  // Blocks of points in parallel; progress between blocks, from this thread.
  const vtkIdType n = static_cast<vtkIdType>(baked.size());
  const vtkIdType block = std::max<vtkIdType>(1, n / 100);
  this->UpdateProgress(0.0);
  for (vtkIdType first = 0; first < n && !this->GetAbortExecute(); first += block)
  {
    const vtkIdType last = std::min(n, first + block);
    vtkSMPTools::For(first, last, std::max<vtkIdType>(1, block / 64), bake);
    this->UpdateProgress(static_cast<double>(last) / n);
  }
  this->TraceTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfRays = rayCount;
  return 1;
}
