#include "vtkAOVertexBaker.h"

#include "vtkAOEmbreeScene.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkAOVertexBaker);

//------------------------------------------------------------------------------
vtkAOVertexBaker::vtkAOVertexBaker()
{
  this->SetNumberOfInputPorts(2);
}

vtkAOVertexBaker::~vtkAOVertexBaker() = default;

//------------------------------------------------------------------------------
void vtkAOVertexBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "Falloff: " << (this->Falloff == BINARY ? "binary" : "Wendland") << "\n";
  os << indent << "Sampling: " << (this->Sampling == UNIFORM ? "uniform" : "cosine") << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "TraceTime: " << this->TraceTime << "\n";
}

//------------------------------------------------------------------------------
void vtkAOVertexBaker::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

void vtkAOVertexBaker::AddOccluderData(vtkPolyData* occluder)
{
  this->AddInputData(1, occluder);
}

void vtkAOVertexBaker::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

void vtkAOVertexBaker::SetArrayName(const std::string& name)
{
  if (name != this->ArrayName)
  {
    this->ArrayName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkAOVertexBaker::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkAOVertexBaker::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  this->NumberOfRays = 0;
  this->TraceTime = 0.0;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> values;
  values->SetName(this->ArrayName.c_str());
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  values->FillValue(1.0f);
  output->GetPointData()->AddArray(values);
  if (n == 0)
  {
    return 1;
  }

  // The occluders: the input itself and every polydata on port 1.
  vtkAOEmbreeScene scene;
  scene.AddPolyData(input);
  const int occluders = inputVector[1]->GetNumberOfInformationObjects();
  for (int i = 0; i < occluders; ++i)
  {
    scene.AddPolyData(vtkPolyData::GetData(inputVector[1], i));
  }
  if (!scene.Commit())
  {
    vtkErrorMacro(<< "Couldn't build the ray-tracing scene: " << scene.GetError());
    return 0;
  }
  double bounds[6];
  scene.GetBounds(bounds);
  this->EffectiveRadius =
    this->Radius > 0.0 ? this->Radius : vtkAOEmbreeScene::AutomaticRadius(bounds);
  this->EffectiveBias =
    this->Bias > 0.0 ? this->Bias : vtkAOEmbreeScene::AutomaticBias(bounds);

  // The cells that define the surface: polygons and strips whose points are all finite and
  // that span an area. Only their points lie on a surface and only they shape the normals
  // (one NaN point must not spoil its neighbours' normals).
  std::vector<char> onSurface(static_cast<size_t>(n), 0);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkCellArray> strips;
  vtkPoints* points = input->GetPoints();
  for (int kind = 0; kind < 2; ++kind)
  {
    vtkCellArray* cells = kind == 0 ? input->GetPolys() : input->GetStrips();
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(npts, pts);
      bool valid = npts >= 3;
      for (vtkIdType k = 0; valid && k < npts; ++k)
      {
        double x[3];
        valid = pts[k] >= 0 && pts[k] < n;
        if (valid)
        {
          points->GetPoint(pts[k], x);
          valid = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
        }
      }
      if (valid && npts == 3)
      {
        double a[3], b[3], c[3], e1[3], e2[3], cross[3];
        points->GetPoint(pts[0], a);
        points->GetPoint(pts[1], b);
        points->GetPoint(pts[2], c);
        vtkMath::Subtract(b, a, e1);
        vtkMath::Subtract(c, a, e2);
        vtkMath::Cross(e1, e2, cross);
        valid = vtkMath::Norm(cross) > 0.0;
      }
      if (!valid)
      {
        continue;
      }
      (kind == 0 ? polys : strips)->InsertNextCell(npts, pts);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        onSurface[pts[k]] = 1;
      }
    }
  }

  // Point normals: the input's, or computed without splitting (so point ids are kept).
  vtkSmartPointer<vtkDataArray> normals = input->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n)
  {
    vtkNew<vtkPolyDataNormals> compute;
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    surface->SetPolys(polys);
    surface->SetStrips(strips);
    compute->SetInputData(surface);
    compute->SplittingOff();
    compute->ConsistencyOn();
    compute->AutoOrientNormalsOff();
    compute->ComputePointNormalsOn();
    compute->ComputeCellNormalsOff();
    compute->Update();
    normals = compute->GetOutput()->GetPointData()->GetNormals();
    if (!normals || normals->GetNumberOfTuples() != n)
    {
      vtkErrorMacro(<< "Couldn't compute point normals for the input.");
      return 0;
    }
  }

  vtkAOIntegralParameters parameters;
  parameters.Radius = this->EffectiveRadius;
  parameters.Bias = this->EffectiveBias;
  parameters.Spread = this->Spread;
  parameters.BinaryFalloff = this->Falloff == BINARY;
  parameters.CosineSampling = this->Sampling == COSINE;
  parameters.Samples = this->Samples;
  parameters.Seed = this->Seed;

  float* out = values->GetPointer(0);
  vtkDataArray* normalArray = normals;
  std::atomic<std::int64_t> rayCount(0);
  auto bake = [&](vtkIdType first, vtkIdType last)
  {
    std::int64_t rays = 0;
    for (vtkIdType i = first; i < last; ++i)
    {
      double p[3], nrm[3];
      points->GetPoint(i, p);
      normalArray->GetTuple(i, nrm);
      if (!onSurface[i] || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) ||
        !std::isfinite(nrm[0]) || !std::isfinite(nrm[1]) || !std::isfinite(nrm[2]) ||
        vtkMath::Normalize(nrm) == 0.0)
      {
        continue; // stays 1: not on a surface, or no direction to look in
      }
      out[i] = static_cast<float>(
        scene.ComputeAccessibility(p, nrm, parameters, static_cast<std::uint64_t>(i), rays));
    }
    rayCount += rays;
  };

  const auto start = std::chrono::steady_clock::now();
  // Blocks of points in parallel; progress between blocks, from this thread.
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
