// An occluder behind the camera darkens the visible floor in front of it. A perspective camera
// looks horizontally along a floor from just above it; a wall stands just behind the camera,
// wholly on the far side of the camera's view plane, so it is never drawn. HAO (scene region
// mode) darkens the nearest visible floor (the bottom rows of the image) relative to a control
// region of far floor; vtkSSAOPass, in the same scene, cannot: its near/far luminance ratio is
// the same with and without the wall.
#include "vtkAOTestUtilities.h"

namespace
{
constexpr int Size = 300;
// The nearest visible floor (bottom rows: z in [1.40, 1.49], 0.56 to 0.65 from the wall) and
// far floor (rows 110-130: z in [-0.6, -0.2], farther than R + 0.2 from the wall).
const int Left[4] = { 30, 4, 270, 30 };
const int Right[4] = { 30, 110, 270, 130 };

double Ratio(vtkRenderWindow* win)
{
  using namespace vtkAOTest;
  return MeanLuminance(win, Left) / MeanLuminance(win, Right);
}
}

int TestHAOBehindCamera(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(Size, Size, ren);

  // The floor, y = 0, x in [-6, 6], z in [-10, 3].
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-6, 0, -10);
  floor->SetPoint1(-6, 0, 3);
  floor->SetPoint2(6, 0, -10);
  vtkSmartPointer<vtkActor> floorActor = AddActor(ren, floor);
  // The headlight grazes the floor: let ambient light show it.
  floorActor->GetProperty()->SetAmbient(0.6);
  floorActor->GetProperty()->SetDiffuse(0.4);
  // The wall: x in [-6, 6], y in [0, 3], z in [2.05, 2.35].
  vtkNew<vtkCubeSource> wallSource;
  wallSource->SetBounds(-6, 6, 0, 3, 2.05, 2.35);
  vtkSmartPointer<vtkActor> wall = AddActor(ren, wallSource);

  // Camera at (0, 0.5, 2) looking along -z, 90 degree view angle: the image's bottom edge
  // meets the floor at z = 1.5, 0.55 in front of the wall; the horizon is the middle row.
  // The whole wall lies at z > 2, behind the camera's view plane z = 2.
  LookAt(ren, { 0, 0.5, 2 }, { 0, 0.5, -5 }, { 0, 1, 0 }, 90, 0.1, 20);

  // Plain renders with and without the wall: it is really invisible.
  vtkNew<vtkRenderStepsPass> basic;
  ren->SetPass(basic);
  win->Render();
  const double plainWall = Ratio(win);
  const double plainLeftWall = MeanLuminance(win, Left);
  wall->VisibilityOff();
  win->Render();
  const double plainOpen = Ratio(win);
  const double plainLeftOpen = MeanLuminance(win, Left);
  std::printf("plain: near/far luminance %.4f with the wall, %.4f without\n", plainWall, plainOpen);
  Check(plainLeftWall == plainLeftOpen, "the wall is not drawn: the plain image is unchanged");

  // HAO, scene region mode.
  auto hao = InstallHAO(ren, 2.0);
  hao->SetRegionModeToScene();
  win->Render();
  const double haoOpen = Ratio(win);
  const double aoLeftOpen = MeanAO(hao, Left);
  const double aoRightOpen = MeanAO(hao, Right);
  wall->VisibilityOn();
  win->Render();
  const double haoWall = Ratio(win);
  const double aoLeft = MeanAO(hao, Left);
  const double aoRight = MeanAO(hao, Right);
  std::printf("HAO A: without the wall near %.3f far %.3f; with it near %.3f far %.3f\n",
    aoLeftOpen,
    aoRightOpen,
    aoLeft,
    aoRight);
  std::printf("HAO near/far luminance: %.4f with the wall, %.4f without\n", haoWall, haoOpen);
  Check(aoLeftOpen > 0.95 && aoRightOpen > 0.95, "HAO: open floor keeps A > 0.95");
  Check(aoRight > 0.95, "HAO: the far floor keeps A > 0.95 with the wall");
  // Analytic A at 0.55-0.65 from the wall (R = 2, Wendland): 0.94-0.95.
  Check(aoLeft >= 0.0 && aoLeft < aoRight - 0.03,
    "HAO: the wall behind the camera darkens the floor in front of it by > 0.03 in A");
  Check(haoWall < haoOpen - 0.03,
    "HAO: the near/far luminance ratio drops by > 0.03 with the wall behind the camera");

  // vtkSSAOPass: the same comparison.
  InstallSSAO(ren, basic, 2.0, 128);
  win->Render();
  const double ssaoWall = Ratio(win);
  wall->VisibilityOff();
  win->Render();
  const double ssaoOpen = Ratio(win);
  std::printf("SSAO near/far luminance: %.4f with the wall, %.4f without\n", ssaoWall, ssaoOpen);
  Check(std::abs(ssaoWall - ssaoOpen) < 0.01, "SSAO cannot see the wall behind the camera");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
