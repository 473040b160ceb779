// Occluders that overlap as seen from a point: A of vtkAmbientOcclusionVolumesPass against
// closed forms, binary falloff, at the centre of the ground (the point is the origin, normal +y).
// - Two crossing walls, x = d and z = d, reaching far beyond R's shadow: each blocks half of
//   the cosine-weighted hemisphere (every direction with w_x > 0, resp. w_z > 0) and together
//   three quarters, so A = 1/4, and the quarter both block is exactly the product of their
//   halves: the multiplicative combination is exact here (A = (1 - 1/2)^2), the additive one
//   counts that quarter twice (A = 1 - 1/2 - 1/2 = 0). Also at AOScale 2 (the subsampled map
//   and the bilateral upsampler).
// - Two parallel squares stacked over the point, the far one hidden behind the near one (same
//   angular size): the true A is 1 - F (F, the near square's form factor). Neither combination
//   is exact: additive gives 1 - 2F; multiplicative, the product over the 4 triangles (each
//   square is 2 triangles, each half its form factor by symmetry), (1 - F/2)^4, closer to the
//   truth. The product depends on how a surface is cut into triangles ((1 - F/2)^2 is not
//   1 - F): this check also pins down that the factors are per triangle.
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"

#include <cmath>

namespace
{

// Form factor from a point under the centre of a parallel square of half-size a at height h.
double SquareFormFactor(double a, double h)
{
  const double x = a / h;
  const double s = std::sqrt(1 + x * x);
  return 4.0 * 2.0 * (x / s * std::atan(x / s)) / (2.0 * vtkMath::Pi());
}

vtkSmartPointer<vtkActor> AddQuad(vtkRenderer* ren,
  const double o[3],
  const double p1[3],
  const double p2[3])
{
  vtkNew<vtkPlaneSource> quad;
  quad->SetOrigin(o[0], o[1], o[2]);
  quad->SetPoint1(p1[0], p1[1], p1[2]);
  quad->SetPoint2(p2[0], p2[1], p2[2]);
  return vtkAOTest::AddActor(ren, quad);
}

double MeasureA(vtkRenderWindow* win,
  vtkAmbientOcclusionVolumesPass* aov,
  int combination,
  int scale)
{
  aov->SetCombination(combination);
  aov->SetAOScale(scale);
  win->Render();
  vtkAOTest::Check(aov->GetLastFrameHadOcclusion(), "the pass applied occlusion");
  return vtkAOTest::MeanAO(aov, 58, 58, 62, 62);
}
}

int TestAOVOverlappingOccluders(int, char*[])
{
  using namespace vtkAOTest;
  using AOV = vtkAmbientOcclusionVolumesPass;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(120, 120, ren);
  AddGround(ren, 50);
  LookAt(ren, { 0, 0.5, 0 }, { 0, 0, 0 }, { 0, 0, -1 }, 30, 0.05, 10);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<AOV> aov;
  Check(aov->GetCombination() == AOV::MULTIPLICATIVE, "the default combination is multiplicative");
  aov->SetDelegatePass(basic);
  ren->SetPass(aov);
  const double bias = 1e-3;
  aov->SetBias(bias);
  aov->SetFalloff(AOV::BINARY);

  // Walls at distance d, L along each side: the directions that miss them (too steep or too
  // grazing) weigh about d / L in the cosine-weighted measure.
  const double d = 0.5, L = 200.0;
  const double w1[3][3] = { { d, -1, -L }, { d, -1, L }, { d, L, -L } };
  const double w2[3][3] = { { -L, -1, d }, { L, -1, d }, { -L, L, d } };
  auto wall1 = AddQuad(ren, w1[0], w1[1], w1[2]);
  auto wall2 = AddQuad(ren, w2[0], w2[1], w2[2]);
  aov->SetRadius(4 * L);
  for (int scale : { 1, 2 })
  {
    const double product = MeasureA(win, aov, AOV::MULTIPLICATIVE, scale);
    const double sum = MeasureA(win, aov, AOV::ADDITIVE, scale);
    std::printf("crossing walls, AOScale %d: A multiplicative %.4f, additive %.4f, exact 0.25\n",
      scale,
      product,
      sum);
    Check(std::abs(product - 0.25) <= 0.01, "crossing walls: multiplicative A is 1/4");
    Check(sum <= 0.02, "crossing walls: additive A counts the shared quarter twice (A = 0)");
  }
  wall1->SetVisibility(false);
  wall2->SetVisibility(false);

  // Stacked squares: the far one (twice as large, twice as high) hidden behind the near one.
  const double a = 0.5, h = 1.0, he = h - bias; // occlusion is evaluated from p + Bias n
  const double s1[3][3] = { { -a, h, -a }, { a, h, -a }, { -a, h, a } };
  const double s2[3][3] = {
    { -2 * a, 2 * h, -2 * a }, { 2 * a, 2 * h, -2 * a }, { -2 * a, 2 * h, 2 * a }
  };
  AddQuad(ren, s1[0], s1[1], s1[2]);
  AddQuad(ren, s2[0], s2[1], s2[2]);
  aov->SetRadius(10.0);
  const double f1 = SquareFormFactor(a, he), f2 = SquareFormFactor(2 * a, 2 * h - bias);
  const double perTriangle = std::pow((1 - 0.5 * f1) * (1 - 0.5 * f2), 2);
  const double product = MeasureA(win, aov, AOV::MULTIPLICATIVE, 1);
  const double sum = MeasureA(win, aov, AOV::ADDITIVE, 1);
  std::printf("stacked squares: A multiplicative %.4f (closed form %.4f), additive %.4f (%.4f), "
              "true %.4f\n",
    product,
    perTriangle,
    sum,
    1 - f1 - f2,
    1 - f1);
  Check(std::abs(product - perTriangle) <= 0.005,
    "stacked squares: multiplicative A is the product of the triangles' open fractions");
  Check(std::abs(sum - (1 - f1 - f2)) <= 0.005,
    "stacked squares: additive A is 1 minus the sum of their form factors");
  Check(std::abs(product - (1 - f1)) < std::abs(sum - (1 - f1)) - 0.03,
    "stacked squares: multiplicative over-darkens less than additive");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
