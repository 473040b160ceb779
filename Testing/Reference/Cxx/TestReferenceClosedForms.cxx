// The reference estimates the AO integral of ao-definition.md: checked against scenes whose
// accessibility has a closed form (binary falloff, cosine weighting), and against a numerical
// integration of the Wendland kernel. 4096 stratified samples: the Monte Carlo error is far
// below the tolerances, which mostly cover the tessellation of curved surfaces.
#include "vtkAOReferenceRenderer.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOTestUtilities.h"

#include "vtkPolyDataCollection.h"

#include <initializer_list>

namespace
{
using namespace vtkAOTest;

double AO(vtkAOReferenceRenderer* reference,
  std::initializer_list<vtkPolyData*> surfaces,
  const double p[3],
  const double n[3])
{
  vtkNew<vtkPolyDataCollection> collection;
  for (vtkPolyData* surface : surfaces)
  {
    collection->AddItem(surface);
  }
  if (!reference->BuildScene(collection))
  {
    return -1.0;
  }
  return reference->ComputeAO(p, n);
}

// 1 - integral over s = sin^2(theta) in [0, 1] of W(H / cos(theta)): a floor point under an
// infinite ceiling at height H, Wendland kernel, by the midpoint rule.
double WendlandCeiling(double H, double R)
{
  const int steps = 200000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double s = (i + 0.5) / steps;
    const double t = H / std::sqrt(1.0 - s);
    if (t <= R)
    {
      const double q = t / R;
      sum += std::pow(1.0 - q, 4) * (4.0 * q + 1.0);
    }
  }
  return 1.0 - sum / steps;
}
}

int TestReferenceClosedForms(int, char*[])
{
  vtkNew<vtkAOReferenceRenderer> reference;
  reference->SetSamples(4096);
  reference->SetBias(1e-5);
  reference->SetFalloffToBinary();
  const double up[3] = { 0, 1, 0 };
  const double origin[3] = { 0, 0, 0 };

  // A point on a convex object alone sees nothing: A = 1.
  const double cube[6] = { -1, 1, -1, 1, -1, 1 };
  reference->SetRadius(10);
  const double top[3] = { 0.3, 1, -0.2 };
  CheckNear(AO(reference, { Box(cube) }, top, up), 1.0, 1e-6, "convex box alone, binary");
  const double pole[3] = { 0, 1, 0 };
  CheckNear(
    AO(reference, { Sphere(origin, 1, 64) }, pole, up), 1.0, 1e-6, "convex sphere alone, binary");
  reference->SetFalloffToWendland();
  CheckNear(AO(reference, { Box(cube) }, top, up), 1.0, 1e-6, "convex box alone, Wendland");
  reference->SetFalloffToBinary();

  // Inside a closed box smaller than R every direction is blocked: A = 0.
  const double side[3] = { 1, 0, 0 };
  CheckNear(AO(reference, { Box(cube) }, origin, up), 0.0, 1e-6, "inside a closed box");
  const double nearWall[3] = { 0.9, 0.2, 0.1 };
  CheckNear(AO(reference, { Box(cube) }, nearWall, side),
    0.0,
    1e-6,
    "inside a closed box, facing the near wall");

  // Floor point under a large parallel ceiling at height H < R: A = (H/R)^2.
  for (const double H : { 0.3, 0.5, 0.8 })
  {
    reference->SetRadius(1.0);
    CheckNear(
      AO(reference, { HorizontalSquare(0, 0, 2.0, H), HorizontalSquare(0, 0, 2.0, 0) }, origin, up),
      H * H,
      0.005,
      "ceiling at H = " + std::to_string(H) + ", R = 1");
  }

  // Floor point under a sphere of radius r centred on the normal at distance d, R >= d + r:
  // A = 1 - (r/d)^2.
  for (const double d : { 2.0, 3.0 })
  {
    const double center[3] = { 0, d, 0 };
    reference->SetRadius(d + 1.5);
    CheckNear(AO(reference, { Sphere(center, 1.0, 128) }, origin, up),
      1.0 - 1.0 / (d * d),
      0.005,
      "sphere r = 1 at d = " + std::to_string(d));
  }

  // Floor point at the foot of a perpendicular wall (x = 0), R large: A = 1/2.
  {
    vtkNew<vtkPlaneSource> wall;
    wall->SetOrigin(0, 0, -100);
    wall->SetPoint1(0, 100, -100);
    wall->SetPoint2(0, 0, 100);
    wall->Update();
    reference->SetRadius(50);
    const double foot[3] = { 1e-3, 0, 0 };
    CheckNear(AO(reference, { wall->GetOutput(), HorizontalSquare(0, 0, 100, 0) }, foot, up),
      0.5,
      0.005,
      "foot of a wall");
  }

  // Spread: a cone of half-angle 45 degrees under a ceiling at H = 0.8 R sees it when
  // sin^2(theta) <= 1 - 0.64, out of sin^2 <= 0.5: A = 1 - 0.36 / 0.5 = 0.28.
  reference->SetRadius(1.0);
  reference->SetSpread(0.5);
  CheckNear(AO(reference, { HorizontalSquare(0, 0, 2.0, 0.8) }, origin, up),
    0.28,
    0.005,
    "ceiling at 0.8 R, spread 0.5");
  reference->SetSpread(1.0);

  // Wendland falloff against the numerical integral of the same kernel.
  reference->SetFalloffToWendland();
  for (const double H : { 0.2, 0.5 })
  {
    CheckNear(AO(reference, { HorizontalSquare(0, 0, 2.0, H) }, origin, up),
      WendlandCeiling(H, 1.0),
      0.005,
      "Wendland ceiling at H = " + std::to_string(H));
  }

  // The automatic radius is a tenth of the scene diagonal, as the HAO pass's.
  reference->SetRadius(0);
  AO(reference, { Box(cube) }, top, up);
  CheckNear(reference->GetEffectiveRadius(), 0.1 * std::sqrt(12.0), 1e-9, "automatic radius");
  Check(reference->GetNumberOfTriangles() == 12, "a cube is 12 triangles");
  return Result();
}
