// vtkAOHemisphereBaker, closed forms and bookkeeping:
// - a convex object (sphere, box) sees its whole hemisphere: A = 1 everywhere;
// - the inside of a closed box (normals inwards) sees nothing: A = 0 everywhere;
// - a floor under a square ceiling (an occluder on port 1): A at the centre = 1 - the
//   point-to-square form factor;
// - the radius: under a ceiling at height h, only directions with h / cos(theta) <= R are
//   blocked: A = (h / R)^2 (R > h, ceiling wide enough), A = 1 for R < h; with a cone of
//   half-angle alpha > acos(h / R): A = 1 - (1 - (h / R)^2) / sin^2(alpha), and A = 0 when the
//   cone lies inside the blocked one;
// - under a ball of radius r whose centre is at distance d above: A = 1 - (r / d)^2;
// - the batching does not change the result (one vertex per atlas = 1024 per atlas); progress
//   events per batch from 0 to 1; a user-supplied window gives the same result and keeps its
//   size; the array name is settable.
#include "vtkAOHemisphereBaker.h"
#include "vtkAOTestChecks.h"
#include "vtkAOTestOpenGLBakers.h"
#include "vtkAOTestSurfaces.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
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
#include <cstdio>
#include <string>

namespace
{
using namespace vtkAOTest;

// The value at the point nearest to (0, 0, 0).
double AtCentre(vtkAOHemisphereBaker* baker)
{
  const double origin[3] = { 0, 0, 0 };
  return PointArray(baker)->GetValue(Nearest(baker->GetOutput(), origin));
}
}

int TestHemisphereBaker(int, char*[])
{
  Range range;
  // 1. Convex objects: A = 1 at every vertex.
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(16);
    vtkNew<vtkAOHemisphereBaker> baker;
    baker->SetInputConnection(sphere->GetOutputPort());
    baker->SetResolution(32);
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Minimum, 1.0, 1e-3, "sphere: minimum A");
    std::printf("sphere: %lld vertices x %lld triangles in %.3f s = %.4g vertices/s\n",
      static_cast<long long>(baker->GetNumberOfRenderedPoints()),
      static_cast<long long>(baker->GetNumberOfTriangles()),
      baker->GetTotalTime(),
      baker->GetVerticesPerSecond());
    vtkNew<vtkCubeSource> cube;
    baker->SetInputConnection(cube->GetOutputPort());
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Minimum, 1.0, 1e-3, "box (outside): minimum A");
  }

  // 2. The inside of a closed box: A = 0 at every vertex.
  {
    vtkNew<vtkAOHemisphereBaker> baker;
    baker->SetInputData(Room());
    baker->SetResolution(16);
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Maximum, 0.0, 1e-3, "closed room (inside): maximum A");
    Check(PointArray(baker)->GetNumberOfValues() > 24 &&
        baker->GetNumberOfRenderedPoints() == PointArray(baker)->GetNumberOfValues(),
      "room: every point rendered (" + std::to_string(baker->GetNumberOfRenderedPoints()) + ")");
  }

  // 3. A floor under a parallel square ceiling at height h (an occluder on port 1), both of
  //    half-width a: at the floor's centre A = 1 - F, F the point-to-square form factor.
  const double h = 0.5;
  {
    const double a = 1.0;
    vtkNew<vtkAOHemisphereBaker> baker;
    baker->SetInputData(HorizontalSquare(0, 0, a, 0.0, 10));
    baker->AddOccluderData(HorizontalSquare(0, 0, a, h, 1));
    baker->SetBias(1e-4);
    baker->Update();
    const double x = a / h;
    const double f = 4.0 / (2.0 * vtkMath::Pi()) * 2.0 * (x / std::sqrt(1 + x * x)) *
      std::atan(x / std::sqrt(1 + x * x));
    CheckNear(AtCentre(baker), 1.0 - f, 0.005, "floor under a ceiling: A at the centre = 1 - F");
    range = RangeOf(PointArray(baker));
    Check(range.Minimum >= 0.0 && range.Maximum <= 1.0, "floor: A in [0, 1]");
  }

  // 4. The radius and the cone, under a ceiling of half-width 3 at height h = 0.5.
  {
    vtkNew<vtkAOHemisphereBaker> baker;
    baker->SetInputData(HorizontalSquare(0, 0, 0.5, 0.0, 2));
    baker->AddOccluderData(HorizontalSquare(0, 0, 3.0, h, 1));
    baker->SetBias(1e-4);
    baker->SetRadius(1.0);
    baker->Update();
    CheckNear(AtCentre(baker), (h / 1.0) * (h / 1.0), 0.01, "R = 1: A = (h/R)^2");
    baker->SetRadius(0.45);
    baker->Update();
    CheckNear(AtCentre(baker), 1.0, 1e-3, "R = 0.45 < h: A = 1");
    baker->SetRadius(1.0);
    baker->SetSpread(0.8);
    baker->Update();
    const double sinAlpha = std::sin(0.8 * vtkMath::Pi() / 2.0);
    CheckNear(AtCentre(baker),
      1.0 - (1.0 - h * h) / (sinAlpha * sinAlpha),
      0.015,
      "R = 1, spread 0.8: A = 1 - (1 - (h/R)^2) / sin^2(alpha)");
    baker->SetSpread(0.5);
    baker->Update();
    CheckNear(AtCentre(baker), 0.0, 1e-3, "R = 1, spread 0.5 (cone inside the blocked one): A");
  }

  // 5. Batching, progress, user window, array name.
  {
    // A floor [-2, 2]^2 of 12 x 12 quads under a ball of radius 0.5 centred 0.8 above it.
    vtkSmartPointer<vtkPolyData> floor = HorizontalSquare(0, 0, 2, 0, 12);
    vtkSmartPointer<vtkPolyData> ball = Sphere(0, 0.8, 0, 0.5, 16);
    vtkNew<vtkAOHemisphereBaker> big;
    big->SetInputData(floor);
    big->AddOccluderData(ball);
    big->SetResolution(32);
    big->SetBias(0.01);
    big->Update();
    const vtkIdType n = big->GetOutput()->GetNumberOfPoints();
    Check(big->GetNumberOfBatches() == 1 && big->GetEffectiveBatchSize() == n,
      "all " + std::to_string(n) + " vertices in one atlas (" +
        std::to_string(big->GetNumberOfBatches()) + " batch(es))");
    // Under a ball of radius r at distance d: F = (r / d)^2 (a sphere seen from a point that
    // faces it); d = 0.8 - bias.
    CheckNear(
      AtCentre(big), 1.0 - 0.25 / (0.79 * 0.79), 0.01, "floor under a ball: A = 1 - (r/d)^2");

    vtkNew<vtkAOHemisphereBaker> small;
    small->SetInputData(floor);
    small->AddOccluderData(ball);
    small->SetResolution(32);
    small->SetBias(0.01);
    small->SetBatchSize(7); // not a divisor of n: a partial last batch
    small->SetArrayName("Accessibility");
    ProgressLog progress;
    progress.Watch(small);
    small->Update();
    const int batches = static_cast<int>((n + 6) / 7);
    Check(small->GetNumberOfBatches() == batches, std::to_string(batches) + " batches of 7");
    Check(progress.RanFromZeroToOne(batches), "progress: " + progress.Describe());
    Check(PointArray(small, "Accessibility") && !PointArray(small), "array name: Accessibility");
    CheckNear(Compare(PointArray(small, "Accessibility"), PointArray(big)).Maximum,
      0.0,
      1e-6,
      "batches of 7 = one batch: max |difference|");

    vtkNew<vtkAOHemisphereBaker> shared;
    shared->SetInputData(floor);
    shared->AddOccluderData(ball);
    shared->SetResolution(32);
    shared->SetBias(0.01);
    CheckUserWindow(shared.Get(), PointArray(big));
  }

  return Result();
}
