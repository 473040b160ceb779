// Exactness against closed forms: the centre of the ground under a square quad at height h.
// - Binary falloff, R beyond the quad's corners: the form factor of a parallel square seen
//   from below its centre, 4 x the corner-rectangle formula (differential area to a parallel
//   rectangle).
// - Binary falloff, quad much larger than R: only the disc of the ball's cut occludes,
//   1 - (h/R)^2.
// - Wendland falloff, quad much larger than R: 2 * Integral from h/R to 1 of W(h/u) u du.
// The quad is above the camera (out of view), so its volume holds the eye: this also checks
// the full-screen fallback.
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"

#include <cmath>

namespace
{

// Form factor from a point under the centre of a parallel square of half-size a at height h.
double SquareFormFactor(double a, double h)
{
  const double x = a / h, y = a / h;
  const double corner = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
    (2.0 * vtkMath::Pi());
  return 4.0 * corner;
}

double WendlandPlane(double h, double r)
{
  // 2 * Integral_{h/R}^{1} W(h/u) u du, midpoint rule with many steps.
  const int steps = 200000;
  const double lo = h / r;
  double sum = 0;
  for (int i = 0; i < steps; ++i)
  {
    const double u = lo + (i + 0.5) * (1.0 - lo) / steps;
    const double x = h / u / r;
    const double w = std::pow(1 - x, 4) * (4 * x + 1);
    sum += w * u;
  }
  return 2.0 * sum * (1.0 - lo) / steps;
}
}

int TestAOVAnalytic(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(120, 120, ren);
  AddGround(ren, 50);
  const double h = 1.0;
  vtkNew<vtkPlaneSource> quad;
  quad->SetCenter(0, h, 0);
  quad->SetNormal(0, -1, 0);
  AddActor(ren, quad);
  TopView(ren, 0, 0, 0.5 * h, 30);
  ren->GetActiveCamera()->SetClippingRange(0.05, 10);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  aov->SetDelegatePass(basic);
  ren->SetPass(aov);
  const double bias = 1e-3;
  aov->SetBias(bias);
  // The closed forms are form factors of whole polygons; a quad is drawn as 2 triangles, whose
  // occlusions add up to the quad's (the multiplicative default multiplies their open
  // fractions instead: TestAOVOverlappingOccluders).
  aov->SetCombinationToAdditive();
  const double he = h - bias; // occlusion is evaluated from p + Bias n

  struct Case
  {
    const char* name;
    double half; // half-size of the quad
    double radius;
    bool binary;
    double expected;
    double tolerance;
  };
  const double a = 1.5;
  const Case cases[] = {
    { "binary, whole square in reach", a, 10.0, true, SquareFormFactor(a, he), 0.002 },
    { "binary, infinite plane cut by the ball",
      40.0,
      3.0,
      true,
      1.0 - (he / 3.0) * (he / 3.0),
      0.01 },
    { "Wendland, infinite plane", 40.0, 3.0, false, WendlandPlane(he, 3.0), 0.005 },
    { "Wendland, plane beyond reach", 40.0, 0.9, false, 0.0, 1e-6 },
  };
  for (const Case& c : cases)
  {
    quad->SetOrigin(-c.half, h, -c.half);
    quad->SetPoint1(c.half, h, -c.half);
    quad->SetPoint2(-c.half, h, c.half);
    aov->SetRadius(c.radius);
    aov->SetFalloff(
      c.binary ? vtkAmbientOcclusionVolumesPass::BINARY : vtkAmbientOcclusionVolumesPass::WENDLAND);
    win->Render();
    const double occlusion = 1.0 - vtkAOTest::MeanAO(aov, 58, 58, 62, 62);
    std::printf("%s: occlusion %.5f, closed form %.5f\n", c.name, occlusion, c.expected);
    Check(aov->GetLastFrameHadOcclusion(), std::string(c.name) + ": the pass applied occlusion");
    Check(std::abs(occlusion - c.expected) <= c.tolerance,
      std::string(c.name) + ": within the tolerance of the closed form");
  }

  // The same infinite plane tessellated into 800 triangles: its coplanar patch is merged into
  // the fan over its outline (2 triangles; the ground's 2 more), with the same occlusion.
  quad->SetOrigin(-40.0, h, -40.0);
  quad->SetPoint1(40.0, h, -40.0);
  quad->SetPoint2(-40.0, h, 40.0);
  quad->SetResolution(20, 20);
  aov->SetRadius(3.0);
  aov->SetFalloff(vtkAmbientOcclusionVolumesPass::WENDLAND);
  win->Render();
  const double tessellated = 1.0 - vtkAOTest::MeanAO(aov, 58, 58, 62, 62);
  std::printf("Wendland, tessellated infinite plane: occlusion %.5f, %lld volumes\n",
    tessellated,
    static_cast<long long>(aov->GetNumberOfOccludingTriangles()));
  Check(std::abs(tessellated - WendlandPlane(he, 3.0)) <= 0.005,
    "tessellated plane: within the tolerance of the closed form");
  Check(aov->GetNumberOfOccludingTriangles() == 4,
    "a tessellated plane is drawn as the 2 triangles of its outline");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
