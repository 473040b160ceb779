// A concave crease is darkest at the crease, and beside it A follows the closed form (issue
// 16, item 4). Closed form: with binary falloff, a point of a plane at distance x from an
// unbounded wall standing on it is occluded along the directions whose horizontal part points
// at the wall with a component above x / R. Cosine-weighted directions project uniformly onto
// the unit disk, so that share is the disk's segment beyond a = x / R:
// A(x) = 1 - (acos(a) - a sqrt(1 - a^2)) / pi, 0.5 at the crease.
// Asserted, at the defaults (cells of R/64 here): 2 to 6 cells from the wall the mean of A is
// within 0.02 of the closed form's (measured 0.006), and within 1.5 cells it is darker than
// there. Within a cell of the wall HAO is too dark (measured 0.20-0.37 against 0.50-0.51: the
// wall's cells, a cell thick, stand over the point, and rays going up run inside them); a rule
// that counted the wall's lowest cells (in the plane's own band) as hits made the quality
// scenes' creases better and this strip darker still (quality.md, "Thin walls").
#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOTestUtilities.h"

#include <algorithm>
#include <cmath>

namespace
{
constexpr double Pi = 3.14159265358979323846;

double WallClosedForm(double x, double radius)
{
  const double a = std::min(x / radius, 1.0);
  return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / Pi;
}
}

int TestHAOCrease(int, char*[])
{
  using namespace vtkAOTest;
  constexpr double R = 1.0;
  constexpr int Size = 300;
  constexpr double Half = 1.0; // the view: x, z in [-1, 1], seen straight down
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(Size, Size, ren);
  AddGround(ren, 4);
  // The wall: x in [0, 0.5], 2 high, 8 deep; its face x = 0 faces the plane's x < 0 half.
  vtkNew<vtkCubeSource> wall;
  wall->SetBounds(0, 0.5, 0, 2, -4, 4);
  AddActor(ren, wall);
  auto hao = InstallHAO(ren, R);
  hao->SetFalloffToBinary();
  // Straight down at the plane beside the wall, parallel projection; the wall's top is seen
  // on the right and is not sampled.
  LookAt(ren, { -0.5, 6, 0 }, { -0.5, 0, 0 }, { 0, 0, -1 }, 40, 0.1, 20);
  ren->GetActiveCamera()->ParallelProjectionOn();
  ren->GetActiveCamera()->SetParallelScale(Half);
  win->Render();
  const double cell = hao->GetVoxelizer()->GetCellSize();

  // Pixel column i sees x = -0.5 - Half + (i + 0.5) * 2 Half / Size.
  auto meanOver = [&](double x0, double x1, double& exact)
  {
    int first = Size, last = -1;
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < Size; ++i)
    {
      const double x = -0.5 - Half + (i + 0.5) * 2 * Half / Size;
      if (x >= -x1 && x <= -x0)
      {
        first = std::min(first, i);
        last = std::max(last, i);
        sum += WallClosedForm(-x, R);
        ++n;
      }
    }
    exact = n > 0 ? sum / n : 0.0;
    return n > 0 ? MeanAO(hao, first, Size / 4, last + 1, 3 * Size / 4) : -1.0;
  };
  double nearExact = 0.0, farExact = 0.0;
  const double nearA = meanOver(0.0, 1.5 * cell, nearExact);
  const double farA = meanOver(2 * cell, 6 * cell, farExact);
  std::printf("cell %.4f; within 1.5 cells of the wall: A %.3f, closed form %.3f; 2-6 cells: A "
              "%.3f, closed form %.3f\n",
    cell,
    nearA,
    nearExact,
    farA,
    farExact);
  Check(std::abs(farA - farExact) < 0.02, "beside the crease, A is the closed form's");
  Check(nearA >= 0.0 && nearA < farA, "the crease is darker than beside it");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
