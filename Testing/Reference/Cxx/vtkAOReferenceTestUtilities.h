// Helpers for the reference tests: checks with the measured and expected values printed,
// and small surfaces for closed-form scenes.
#ifndef vtkAOReferenceTestUtilities_h
#define vtkAOReferenceTestUtilities_h

#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace vtkAOReferenceTest
{
inline int Failures = 0;

inline void Check(bool condition, const std::string& what)
{
  std::printf("%s: %s\n", condition ? "ok" : "FAILED", what.c_str());
  Failures += condition ? 0 : 1;
}

/// |value - expected| <= tolerance, reported with the numbers.
inline void CheckNear(double value, double expected, double tolerance, const std::string& what)
{
  const bool ok = std::isfinite(value) && std::fabs(value - expected) <= tolerance;
  std::printf("%s: %s: %.5f (expected %.5f +- %.4f)\n",
    ok ? "ok" : "FAILED",
    what.c_str(),
    value,
    expected,
    tolerance);
  Failures += ok ? 0 : 1;
}

inline int Result()
{
  std::printf("%d check(s) failed\n", Failures);
  return Failures ? 1 : 0;
}

/// The square [cx - half, cx + half] x [cz - half, cz + half] at height y, normal +y.
inline vtkSmartPointer<vtkPolyData> HorizontalSquare(double cx, double cz, double half, double y)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(cx - half, y, cz - half);
  plane->SetPoint1(cx - half, y, cz + half);
  plane->SetPoint2(cx + half, y, cz - half);
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
}

#endif
