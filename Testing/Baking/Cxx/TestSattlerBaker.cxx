// vtkAOSattlerBaker, closed forms and bookkeeping:
// - a convex object (sphere, box) sees every direction of its hemisphere: A = 1 everywhere;
// - the inside of a closed box (normals inwards) sees none: A = 0 everywhere;
// - a floor under a ceiling (an occluder on port 1): A at the centre = 1 - the ceiling's
//   point-to-square form factor;
// - relighting is linear: I = 1 gives A, 2 I gives 2 c, c(I1 + I2) = c(I1) + c(I2); the
//   on-the-fly radiance equals Relight() from the stored bits;
// - the stored matrix holds n x ceil(k / 32) words; StoreVisibility off stores nothing and gives
//   the same A; progress events run from 0 to 1; a user-supplied window gives the same result.
#include "vtkAOSattlerBaker.h"
#include "vtkAOTestChecks.h"
#include "vtkAOTestOpenGLBakers.h"
#include "vtkAOTestSurfaces.h"

#include "vtkAppendPolyData.h"
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
#include <vector>

namespace
{
using namespace vtkAOTest;

// A unit sphere of 48 x 24 facets at the origin.
vtkSmartPointer<vtkPolyData> UnitSphere()
{
  return Sphere(0, 0, 0, 1.0, 24);
}
}

int TestSattlerBaker(int, char*[])
{
  Range range;
  // 1. Convex objects: A = 1 at every vertex.
  {
    vtkNew<vtkAOSattlerBaker> baker;
    baker->SetInputData(UnitSphere());
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Minimum, 1.0, 0.01, "sphere: minimum A");
    CheckNear(range.Mean, 1.0, 0.001, "sphere: mean A");
    vtkNew<vtkCubeSource> cube;
    cube->Update();
    baker->SetInputData(cube->GetOutput());
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Minimum, 1.0, 0.01, "box (outside): minimum A");
  }

  // 2. The inside of a closed box: A = 0 at every vertex.
  {
    vtkNew<vtkAOSattlerBaker> baker;
    baker->SetInputData(Room());
    baker->Update();
    range = RangeOf(PointArray(baker));
    CheckNear(range.Maximum, 0.0, 0.01, "closed room (inside): maximum A");
    Check(PointArray(baker)->GetNumberOfValues() > 24,
      "room: one value per point (" + std::to_string(PointArray(baker)->GetNumberOfValues()) + ")");
    // The normals really point inwards (else A = 0 would be trivial failure of another kind).
    double n0[3], p0[3];
    baker->GetOutput()->GetPoint(0, p0);
    baker->GetOutput()->GetPointData()->GetNormals()->GetTuple(0, n0);
    Check(vtkMath::Dot(n0, p0) < 0, "room: normals point inwards");
  }

  // 3. A floor under a parallel square ceiling at height h (an occluder on port 1), both of
  //    half-width a: at the floor's centre A = 1 - F, F the point-to-square form factor.
  {
    const double a = 1.0, h = 0.5;
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(-a, 0, -a);
    floor->SetPoint1(-a, 0, a);
    floor->SetPoint2(a, 0, -a);
    floor->SetResolution(10, 10);
    vtkNew<vtkPlaneSource> ceiling;
    ceiling->SetOrigin(-a, h, -a);
    ceiling->SetPoint1(a, h, -a);
    ceiling->SetPoint2(-a, h, a);
    vtkNew<vtkAOSattlerBaker> baker;
    baker->SetInputConnection(floor->GetOutputPort());
    baker->AddOccluderConnection(ceiling->GetOutputPort());
    baker->SetNumberOfDirections(1024);
    baker->SetResolution(512);
    baker->SetBias(1e-4);
    baker->Update();
    // Point-to-rectangle form factor (rectangle parallel to the surface, corner above the
    // point): F = 1/(2 pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))]
    // with X = a/h, Y = a/h; the centred square is four such rectangles.
    const double x = a / h;
    const double f = 4.0 / (2.0 * vtkMath::Pi()) * 2.0 * (x / std::sqrt(1 + x * x)) *
      std::atan(x / std::sqrt(1 + x * x));
    const vtkIdType centre = 60; // the middle of an 11 x 11 grid of points
    double p[3];
    baker->GetOutput()->GetPoint(centre, p);
    Check(std::fabs(p[0]) < 1e-9 && std::fabs(p[2]) < 1e-9, "floor: point 60 is the centre");
    CheckNear(PointArray(baker)->GetValue(centre),
      1.0 - f,
      0.02,
      "floor under a ceiling: A at the centre = 1 - F(square)");
  }

  // 4. Relighting is linear and matches the on-the-fly radiance; bookkeeping.
  {
    // A floor [-4, 4]^2 of 16 x 16 quads with a unit ball resting on it.
    vtkSmartPointer<vtkPolyData> floor = HorizontalSquare(0, 0, 4, 0, 16);
    vtkSmartPointer<vtkPolyData> ball = Sphere(0, 1, 0, 1, 12);
    vtkNew<vtkAppendPolyData> scene;
    scene->AddInputData(floor);
    scene->AddInputData(ball);
    scene->Update();
    vtkPolyData* input = scene->GetOutput();
    const vtkIdType n = input->GetNumberOfPoints();
    const int k = 100; // not a multiple of 32

    // Two environments: a sky gradient (RGB) and a "sun" lobe.
    const std::vector<double> dirs = vtkAOSattlerBaker::MakeDirections(k, 7);
    std::vector<double> sky(3 * k), sun(3 * k), both(3 * k), twice(3 * k), ones(k, 1.0);
    for (int j = 0; j < k; ++j)
    {
      const double up = dirs[3 * j + 1];
      const double sunCos = 0.6 * dirs[3 * j] + 0.8 * dirs[3 * j + 1];
      for (int c = 0; c < 3; ++c)
      {
        sky[3 * j + c] = up > 0 ? 0.2 + 0.3 * c * up : 0.05;
        sun[3 * j + c] = sunCos > 0.9 ? 5.0 : 0.0;
        both[3 * j + c] = sky[3 * j + c] + sun[3 * j + c];
        twice[3 * j + c] = 2.0 * sky[3 * j + c];
      }
    }

    vtkNew<vtkAOSattlerBaker> baker;
    baker->SetInputData(input);
    baker->SetNumberOfDirections(k);
    baker->SetSeed(7);
    baker->SetIntensities(sky, 3);
    ProgressLog progress;
    progress.Watch(baker);
    baker->Update();
    Check(progress.RanFromZeroToOne(k), "progress: " + progress.Describe());
    Check(baker->GetWordsPerPoint() == 4, "k = 100: 4 words per point");
    Check(baker->GetVisibilityMemory() == static_cast<size_t>(n) * 4 * 4,
      "stored matrix: n x 4 words = " + std::to_string(baker->GetVisibilityMemory()) + " bytes");

    vtkFloatArray* ao = PointArray(baker);
    vtkNew<vtkFloatArray> cOnes, cSky, cSun, cBoth, cTwice;
    Check(baker->Relight(ones, 1, cOnes), "Relight(I = 1)");
    CheckNear(Compare(cOnes, ao).Maximum, 0.0, 1e-5, "I = 1 gives A: max |c - A|");
    baker->Relight(sky, 3, cSky);
    baker->Relight(sun, 3, cSun);
    baker->Relight(both, 3, cBoth);
    baker->Relight(twice, 3, cTwice);
    CheckNear(
      Compare(cTwice, cSky, 2.0).Maximum, 0.0, 1e-5, "doubling I doubles c: max |c(2I) - 2c(I)|");
    double worst = 0;
    for (vtkIdType v = 0; v < cBoth->GetNumberOfValues(); ++v)
    {
      worst = std::max<double>(
        worst, std::fabs(cBoth->GetValue(v) - cSky->GetValue(v) - cSun->GetValue(v)));
    }
    CheckNear(worst, 0.0, 1e-5, "additivity: max |c(I1 + I2) - c(I1) - c(I2)|");
    double sunMax = 0;
    for (vtkIdType v = 0; v < cSun->GetNumberOfValues(); ++v)
    {
      sunMax = std::max<double>(sunMax, cSun->GetValue(v));
    }
    Check(sunMax > 0.1, "the sun lights something: max c = " + std::to_string(sunMax));
    CheckNear(Compare(PointArray(baker, "Radiance"), cSky).Maximum,
      0.0,
      1e-5,
      "on-the-fly radiance = Relight() of the same I");
    Check(!baker->Relight(std::vector<double>(k + 1, 1.0), 1, cOnes), "Relight: wrong size fails");

    // The shadow of the ball on the floor: the floor point under the ball is darker than a
    // far corner, and the ball's top sees the whole hemisphere.
    double p[3];
    vtkIdType under = -1, corner = -1;
    for (vtkIdType v = 0; v < floor->GetNumberOfPoints(); ++v) // floor points first
    {
      input->GetPoint(v, p);
      if (std::fabs(p[0]) < 1e-6 && std::fabs(p[1]) < 1e-6 && std::fabs(p[2]) < 1e-6)
      {
        under = v;
      }
      if (std::fabs(p[0] + 4) < 1e-6 && std::fabs(p[2] + 4) < 1e-6)
      {
        corner = v;
      }
    }
    Check(under >= 0 && corner >= 0, "found the floor centre and corner");
    if (under >= 0 && corner >= 0)
    {
      Check(ao->GetValue(under) < 0.1,
        "floor under the ball: A = " + std::to_string(ao->GetValue(under)));
      CheckNear(ao->GetValue(corner), 1.0, 0.02, "floor corner far from the ball: A");
    }

    // On the fly: same A, nothing stored.
    vtkNew<vtkAOSattlerBaker> fly;
    fly->SetInputData(input);
    fly->SetNumberOfDirections(k);
    fly->SetSeed(7);
    fly->StoreVisibilityOff();
    fly->SetIntensities(sky, 3);
    fly->Update();
    Check(fly->GetVisibilityMemory() == 0, "on the fly: nothing stored");
    CheckNear(Compare(PointArray(fly), ao).Maximum, 0.0, 1e-6, "on the fly: same A");
    CheckNear(Compare(PointArray(fly, "Radiance"), cSky).Maximum, 0.0, 1e-5, "on the fly: same c");
    Check(!fly->Relight(ones, 1, cOnes), "on the fly: Relight() refuses");

    // A user-supplied window: same result, window size untouched.
    vtkNew<vtkAOSattlerBaker> shared;
    shared->SetInputData(input);
    shared->SetNumberOfDirections(k);
    shared->SetSeed(7);
    CheckUserWindow(shared.Get(), ao);
    std::printf("timing: %lld points x %d directions in %.3f s (draw+read %.3f s, test %.3f s)\n",
      static_cast<long long>(n),
      k,
      baker->GetTotalTime(),
      baker->GetRenderTime(),
      baker->GetTestTime());
  }

  return Result();
}
