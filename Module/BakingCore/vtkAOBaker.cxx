#include "vtkAOBaker.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace
{
bool Finite3(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

double Diagonal(const double bounds[6])
{
  return std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
}
}

//------------------------------------------------------------------------------
vtkAOBaker::Surface::Surface()
  : Bounds{ VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX }
  , Polys(vtkSmartPointer<vtkCellArray>::New())
  , Strips(vtkSmartPointer<vtkCellArray>::New())
{
}

vtkAOBaker::Surface::~Surface() = default;

//------------------------------------------------------------------------------
vtkAOBaker::vtkAOBaker()
{
  this->SetNumberOfInputPorts(2);
}

vtkAOBaker::~vtkAOBaker() = default;

//------------------------------------------------------------------------------
void vtkAOBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "TotalTime: " << this->TotalTime << "\n";
}

//------------------------------------------------------------------------------
void vtkAOBaker::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

void vtkAOBaker::AddOccluderData(vtkPolyData* occluder)
{
  this->AddInputData(1, occluder);
}

void vtkAOBaker::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

void vtkAOBaker::SetArrayName(const std::string& name)
{
  if (name != this->ArrayName)
  {
    this->ArrayName = name;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkAOBaker::FillInputPortInformation(int port, vtkInformation* info)
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
double vtkAOBaker::AutomaticBias(const double bounds[6])
{
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  return 2.0 * (longest + 0.2 * Diagonal(bounds)) / 256.0;
}

void vtkAOBaker::Center(const double bounds[6], double center[3])
{
  for (int d = 0; d < 3; ++d)
  {
    center[d] = 0.5 * (bounds[2 * d] + bounds[2 * d + 1]);
  }
}

//------------------------------------------------------------------------------
int vtkAOBaker::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  this->TotalTime = 0.0;
  this->InitializeResults(input->GetNumberOfPoints());
  const int result = this->Bake(input, inputVector[1], output);
  this->TotalTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

//------------------------------------------------------------------------------
int vtkAOBaker::Bake(vtkPolyData* input, vtkInformationVector* occluders, vtkPolyData* output)
{
  output->ShallowCopy(input);
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> values;
  values->SetName(this->ArrayName.c_str());
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  values->FillValue(1.0f);
  output->GetPointData()->AddArray(values);

  Surface surface;
  surface.Input = input;
  surface.Output = output;
  surface.Occluders = occluders;
  if (!this->GatherSurface(surface))
  {
    vtkErrorMacro(<< "Too many points for 32-bit indices.");
    return 0;
  }
  if (n == 0 || surface.Polys->GetNumberOfCells() + surface.Strips->GetNumberOfCells() == 0)
  {
    return 1; // nothing to bake: every point keeps A = 1
  }
  if (!this->GatherNormals(surface))
  {
    vtkErrorMacro(<< "Couldn't compute point normals for the input.");
    return 0;
  }
  if (surface.Baked.empty())
  {
    return 1;
  }
  return this->BakePoints(surface, values->GetPointer(0));
}

//------------------------------------------------------------------------------
bool vtkAOBaker::GatherSurface(Surface& surface)
{
  vtkPolyData* input = surface.Input;
  const vtkIdType n = input->GetNumberOfPoints();
  surface.OnSurface.assign(static_cast<size_t>(n), 0);
  double* bounds = surface.Bounds;
  const bool keep = this->GatherTriangles;
  // A triangle occludes (and lets its cell define the surface) when it spans an area.
  auto addTriangle = [&](vtkIdType offset, const vtkIdType ids[3], const double* corners[3])
  {
    double e1[3], e2[3], cross[3];
    vtkMath::Subtract(corners[1], corners[0], e1);
    vtkMath::Subtract(corners[2], corners[0], e2);
    vtkMath::Cross(e1, e2, cross);
    if (!(vtkMath::Norm(cross) > 0.0))
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      if (keep)
      {
        surface.Triangles.push_back(static_cast<std::uint32_t>(offset + ids[c]));
      }
      for (int d = 0; d < 3; ++d)
      {
        bounds[2 * d] = std::min(bounds[2 * d], corners[c][d]);
        bounds[2 * d + 1] = std::max(bounds[2 * d + 1], corners[c][d]);
      }
    }
    return true;
  };

  vtkInformationVector* occluders = surface.Occluders;
  const int count = occluders ? occluders->GetNumberOfInformationObjects() : 0;
  std::vector<double> coordinates;
  vtkIdType offset = 0;
  for (int source = -1; source < count; ++source)
  {
    vtkPolyData* data = source < 0 ? input : vtkPolyData::GetData(occluders, source);
    if (!data || !data->GetPoints())
    {
      continue;
    }
    vtkPoints* points = data->GetPoints();
    const vtkIdType size = data->GetNumberOfPoints();
    if (keep &&
      static_cast<double>(offset) + size >
        static_cast<double>(std::numeric_limits<std::uint32_t>::max()))
    {
      return false;
    }
    std::vector<double>& xyzs = keep ? surface.Points : coordinates;
    if (!keep)
    {
      coordinates.clear();
    }
    const size_t first = xyzs.size();
    xyzs.resize(first + 3 * static_cast<size_t>(size));
    double* xyz = xyzs.data() + first;
    for (vtkIdType p = 0; p < size; ++p)
    {
      points->GetPoint(p, xyz + 3 * p);
    }
    for (int kind = 0; kind < 2; ++kind)
    {
      vtkCellArray* cells = kind == 0 ? data->GetPolys() : data->GetStrips();
      vtkIdType npts = 0;
      const vtkIdType* pts = nullptr;
      auto it = vtk::TakeSmartPointer(cells->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        it->GetCurrentCell(npts, pts);
        bool valid = npts >= 3;
        for (vtkIdType c = 0; valid && c < npts; ++c)
        {
          valid = pts[c] >= 0 && pts[c] < size && Finite3(xyz + 3 * pts[c]);
        }
        if (!valid)
        {
          continue;
        }
        // Polygons as fans, strips with alternating orientation (orientation does not matter:
        // both faces occlude).
        bool any = false;
        for (vtkIdType c = 2; c < npts; ++c)
        {
          const vtkIdType ids[3] = { kind == 0 ? pts[0] : pts[c - 2], pts[c - 1], pts[c] };
          const double* corners[3] = { xyz + 3 * ids[0], xyz + 3 * ids[1], xyz + 3 * ids[2] };
          any = addTriangle(offset, ids, corners) || any;
        }
        if (source < 0 && any)
        {
          (kind == 0 ? surface.Polys : surface.Strips)->InsertNextCell(npts, pts);
          for (vtkIdType c = 0; c < npts; ++c)
          {
            surface.OnSurface[pts[c]] = 1;
          }
        }
      }
    }
    offset += size;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBaker::GatherNormals(Surface& surface)
{
  vtkPolyData* input = surface.Input;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkSmartPointer<vtkDataArray> normals = input->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n)
  {
    vtkNew<vtkPolyDataNormals> compute;
    vtkNew<vtkPolyData> kept;
    kept->SetPoints(input->GetPoints());
    kept->SetPolys(surface.Polys);
    kept->SetStrips(surface.Strips);
    compute->SetInputData(kept);
    compute->SplittingOff();
    compute->ConsistencyOn();
    compute->AutoOrientNormalsOff();
    compute->ComputePointNormalsOn();
    compute->ComputeCellNormalsOff();
    compute->Update();
    normals = compute->GetOutput()->GetPointData()->GetNormals();
    if (!normals || normals->GetNumberOfTuples() != n)
    {
      return false;
    }
  }

  // The points to bake: on the surface, finite, with a normal to look along.
  surface.Normals.assign(3 * static_cast<size_t>(n), 0.0);
  surface.Baked.clear();
  vtkPoints* points = input->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], nrm[3];
    points->GetPoint(i, p);
    normals->GetTuple(i, nrm);
    if (!surface.OnSurface[i] || !Finite3(p) || !Finite3(nrm) || vtkMath::Normalize(nrm) == 0.0)
    {
      continue;
    }
    surface.Baked.push_back(i);
    std::copy(nrm, nrm + 3, surface.Normals.begin() + 3 * i);
  }
  return true;
}
