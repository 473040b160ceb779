// Surfaces for the ambient-occlusion tests (closed-form scenes and the shared agreement scene)
// and what the per-vertex tests measure on a point-data array. No rendering: the baker tests,
// which have no pass, use these too.
#ifndef vtkAOTestSurfaces_h
#define vtkAOTestSurfaces_h

#include "vtkAlgorithm.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTessellatedBoxSource.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vtkAOTest
{
/// The square [cx - half, cx + half] x [cz - half, cz + half] at height y, normal +y, in
/// resolution x resolution quads.
inline vtkSmartPointer<vtkPolyData> HorizontalSquare(double cx,
  double cz,
  double half,
  double y,
  int resolution = 1)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(cx - half, y, cz - half);
  plane->SetPoint1(cx - half, y, cz + half);
  plane->SetPoint2(cx + half, y, cz - half);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  return plane->GetOutput();
}

inline vtkSmartPointer<vtkPolyData> Box(const double bounds[6])
{
  vtkNew<vtkCubeSource> box;
  box->SetBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  box->Update();
  return box->GetOutput();
}

/// A sphere of 2 resolution x resolution (theta x phi) facets.
inline vtkSmartPointer<vtkPolyData> Sphere(const double center[3], double radius, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center[0], center[1], center[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(2 * resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return sphere->GetOutput();
}

/// A sphere centred at (x, y, z): Sphere(center, radius, resolution).
inline vtkSmartPointer<vtkPolyData> Sphere(double x,
  double y,
  double z,
  double radius,
  int resolution)
{
  const double center[3] = { x, y, z };
  return Sphere(center, radius, resolution);
}

/// The inside of a room: a closed box [-1, 1] x [-0.5, 0.5] x [-1.5, 1.5] (tessellated quads,
/// shared points) with its point normals flipped inwards. Shared points matter: at a corner the
/// averaged normal points into the room, so the test point p + bias n lies inside and on no
/// wall. Every vertex sees nothing: A = 0.
inline vtkSmartPointer<vtkPolyData> Room()
{
  vtkNew<vtkTessellatedBoxSource> box;
  box->SetBounds(-1, 1, -0.5, 0.5, -1.5, 1.5);
  box->SetLevel(3);
  box->QuadsOn();
  box->DuplicateSharedPointsOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(box->GetOutputPort());
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOn(); // outwards ...
  normals->FlipNormalsOn();       // ... then inwards
  normals->ComputeCellNormalsOff();
  normals->Update();
  auto room = vtkSmartPointer<vtkPolyData>::New();
  room->DeepCopy(normals->GetOutput());
  return room;
}

/// The float point-data array @p name of @p algorithm's output (a baker's), or nullptr.
inline vtkFloatArray* PointArray(vtkAlgorithm* algorithm, const char* name = "AmbientOcclusion")
{
  vtkPolyData* output = vtkPolyData::SafeDownCast(algorithm->GetOutputDataObject(0));
  return output ? vtkFloatArray::SafeDownCast(output->GetPointData()->GetArray(name)) : nullptr;
}

/// The ray-cast reference the GPU bakers are compared with: @p rays (a vtkAOVertexBaker) bakes
/// @p mesh with binary falloff, @p radius, @p bias and @p samples rays per point. Returns A.
template<class RayCaster>
vtkFloatArray* BakeBinaryReference(RayCaster* rays,
  vtkPolyData* mesh,
  double radius,
  double bias,
  int samples)
{
  rays->SetInputData(mesh);
  rays->SetFalloffToBinary();
  rays->SetRadius(radius);
  rays->SetBias(bias);
  rays->SetSamples(samples);
  rays->Update();
  return PointArray(rays);
}

/// The smallest, largest and mean value of an array (1e30, -1e30, 0 when it is empty or null).
struct Range
{
  double Minimum = 1e30;
  double Maximum = -1e30;
  double Mean = 0.0;
};

inline Range RangeOf(vtkDataArray* a)
{
  Range range;
  const vtkIdType n = a ? a->GetNumberOfValues() : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int components = a->GetNumberOfComponents();
    const double value = a->GetComponent(i / components, i % components);
    range.Minimum = std::min(range.Minimum, value);
    range.Maximum = std::max(range.Maximum, value);
    range.Mean += value / n;
  }
  return range;
}

/// How far @p a lies from scale x @p b over every value (tuple and component): the RMS, the
/// largest and the 99th-percentile absolute difference. All 1e30 when the arrays are missing,
/// empty or of different shapes.
struct Difference
{
  double RMS = 1e30;
  double Maximum = 1e30;
  double P99 = 1e30;
};

inline Difference Compare(vtkDataArray* a, vtkDataArray* b, double scale = 1.0)
{
  Difference difference;
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents() || a->GetNumberOfValues() == 0)
  {
    return difference;
  }
  std::vector<double> errors;
  double sum = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      const double d = a->GetComponent(i, c) - scale * b->GetComponent(i, c);
      sum += d * d;
      errors.push_back(std::fabs(d));
    }
  }
  std::sort(errors.begin(), errors.end());
  difference.RMS = std::sqrt(sum / errors.size());
  difference.Maximum = errors.back();
  difference.P99 = errors[static_cast<size_t>(0.99 * (errors.size() - 1))];
  return difference;
}

/// The point of @p surface nearest to @p target.
inline vtkIdType Nearest(vtkPolyData* surface, const double target[3])
{
  vtkIdType best = -1;
  double bestDistance = std::numeric_limits<double>::max();
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    const double d = vtkMath::Distance2BetweenPoints(p, target);
    if (d < bestDistance)
    {
      bestDistance = d;
      best = i;
    }
  }
  return best;
}
}

#endif
