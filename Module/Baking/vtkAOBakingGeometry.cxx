#include "vtkAOBakingGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vtkAOBaking
{
//------------------------------------------------------------------------------
Geometry::Geometry()
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

Geometry::~Geometry() = default;

//------------------------------------------------------------------------------
bool Finite3(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

void Basis(const double l[3], double u[3], double v[3])
{
  const double helper[3] = {
    std::fabs(l[0]) < 0.9 ? 1.0 : 0.0, std::fabs(l[0]) < 0.9 ? 0.0 : 1.0, 0.0
  };
  vtkMath::Cross(helper, l, u);
  vtkMath::Normalize(u);
  vtkMath::Cross(l, u, v);
}

//------------------------------------------------------------------------------
bool GatherGeometry(vtkPolyData* input, vtkInformationVector* occluders, Geometry& geometry)
{
  const vtkIdType n = input->GetNumberOfPoints();
  geometry.OnSurface.assign(static_cast<size_t>(n), 0);
  double* bounds = geometry.Bounds;
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
      geometry.Triangles.push_back(static_cast<std::uint32_t>(offset + ids[c]));
      for (int d = 0; d < 3; ++d)
      {
        bounds[2 * d] = std::min(bounds[2 * d], corners[c][d]);
        bounds[2 * d + 1] = std::max(bounds[2 * d + 1], corners[c][d]);
      }
    }
    return true;
  };

  const int count = occluders ? occluders->GetNumberOfInformationObjects() : 0;
  for (int source = -1; source < count; ++source)
  {
    vtkPolyData* data = source < 0 ? input : vtkPolyData::GetData(occluders, source);
    if (!data || !data->GetPoints())
    {
      continue;
    }
    vtkPoints* points = data->GetPoints();
    const vtkIdType size = data->GetNumberOfPoints();
    const vtkIdType offset = static_cast<vtkIdType>(geometry.Points.size() / 3);
    if (static_cast<double>(offset) + size >
      static_cast<double>(std::numeric_limits<std::uint32_t>::max()))
    {
      return false;
    }
    geometry.Points.resize(geometry.Points.size() + 3 * static_cast<size_t>(size));
    double* xyz = geometry.Points.data() + 3 * static_cast<size_t>(offset);
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
          (kind == 0 ? geometry.Polys : geometry.Strips)->InsertNextCell(npts, pts);
          for (vtkIdType c = 0; c < npts; ++c)
          {
            geometry.OnSurface[pts[c]] = 1;
          }
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> PointNormals(vtkPolyData* input, const Geometry& geometry)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkSmartPointer<vtkDataArray> normals = input->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n)
  {
    return normals;
  }
  vtkNew<vtkPolyDataNormals> compute;
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(geometry.Polys);
  surface->SetStrips(geometry.Strips);
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
    return nullptr;
  }
  return normals;
}

//------------------------------------------------------------------------------
double AutomaticBias(const double bounds[6])
{
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  return 2.0 * (longest + 0.2 * diagonal) / 256.0;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* MakeContext(vtkRenderWindow* window,
  vtkSmartPointer<vtkRenderWindow>& own,
  const char*& error)
{
  if (!window)
  {
    if (!own)
    {
      own = vtkSmartPointer<vtkRenderWindow>::New();
      own->SetOffScreenRendering(1);
      own->SetMultiSamples(0);
      own->SetSize(16, 16);
      vtkNew<vtkRenderer> empty;
      own->AddRenderer(empty);
      own->Render(); // creates the context
      own->RemoveRenderer(empty);
    }
    window = own;
  }
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context)
  {
    error = "The render window is not a vtkOpenGLRenderWindow.";
    return nullptr;
  }
  context->Initialize();
  context->MakeCurrent();
  return context;
}
}
