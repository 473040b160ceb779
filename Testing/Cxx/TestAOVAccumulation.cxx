// AOV's progressive stills at AO scale 3: the first frame after a change is the filtered
// frame without accumulation; each further render of the unchanged view evaluates the volumes
// at another pixel of every 3 x 3 block and writes those exact values in place, so the error
// against the AO-scale-1 image falls with every frame and after 9 frames A is the AO-scale-1
// image, pixel for pixel (fins 0.1 apart, finer than the map, show what the filter misses).
// Then the mean is kept, a change restarts it, and MaximumAccumulatedFrames caps it.
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"

#include <cmath>
#include <string>

namespace
{
/// Render once, check the accumulation count and return A.
std::vector<float> RenderFrame(vtkRenderWindow* win,
  vtkAmbientOcclusionVolumesPass* aov,
  int expectedFrames,
  const std::string& what)
{
  win->Render();
  vtkAOTest::Check(aov->GetAccumulatedFrames() == expectedFrames,
    what + ": " + std::to_string(aov->GetAccumulatedFrames()) + " accumulated frames, expected " +
      std::to_string(expectedFrames));
  return vtkAOTest::ReadAO(aov);
}
}

int TestAOVAccumulation(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(240, 200, ren);
  AddGround(ren, 5);
  AddSphere(ren, -1.2, 0);
  for (int i = 0; i < 8; ++i) // fins 0.05 thick, 0.15 apart: about 3 pixels
  {
    vtkNew<vtkCubeSource> fin;
    fin->SetCenter(0.8 + 0.15 * i, 0.5, 0);
    fin->SetXLength(0.05);
    fin->SetYLength(1.0);
    fin->SetZLength(2.5);
    AddActor(ren, fin);
  }
  TopView(ren, 0, 0, 9);
  ren->GetActiveCamera()->Elevation(-30);
  ren->ResetCameraClippingRange();
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  aov->SetDelegatePass(basic);
  aov->SetRadius(1.0);
  ren->SetPass(aov);

  // The exact image: AO scale 1, every pixel evaluated (one frame holds all there is).
  const std::vector<float> exact = RenderFrame(win, aov, 1, "AO scale 1");
  RenderFrame(win, aov, 1, "AO scale 1, again (nothing to add)");
  Check(!aov->IsAccumulating() && aov->GetAccumulationTarget() == 1,
    "AO scale 1 converges in one frame");

  // The filtered frame without accumulation.
  aov->SetAOScale(3);
  aov->AccumulationOff();
  const std::vector<float> filtered = RenderFrame(win, aov, 1, "AO scale 3, no accumulation");
  aov->AccumulationOn();
  Check(aov->GetAccumulationTarget() == 9, "AO scale 3: 9 frames to converge");

  std::vector<double> error;
  std::vector<float> still;
  for (int k = 1; k <= 9; ++k)
  {
    still = RenderFrame(win, aov, k, "AO scale 3, still view");
    if (k == 1)
    {
      Check(
        AODifference(still, filtered) < 1e-6, "the first frame is the frame without accumulation");
    }
    error.push_back(AODifference(still, exact));
    std::printf("frame %d: RMS difference from AO scale 1 %.5f (largest %.4f)\n",
      k,
      error.back(),
      AODifference(still, exact, true));
  }
  Check(error[0] > 2e-3, "the filtered frame differs from AO scale 1 (the fins)");
  for (int k = 1; k < 8; ++k)
  {
    Check(error[k] < error[k - 1], "frame " + std::to_string(k + 1) + " is closer to AO scale 1");
  }
  Check(AODifference(still, exact, true) < 1e-4, "after 9 frames A is the AO-scale-1 image");
  Check(!aov->IsAccumulating(), "after 9 frames nothing is left to add");
  const std::vector<float> kept = RenderFrame(win, aov, 9, "past the ninth frame");
  Check(AODifference(kept, still, true) == 0.0, "past the ninth frame the still is kept");

  // A change restarts: the camera moves and comes back.
  vtkCamera* cam = ren->GetActiveCamera();
  cam->Azimuth(5);
  RenderFrame(win, aov, 1, "camera moved");
  cam->Azimuth(-5);
  Check(AODifference(RenderFrame(win, aov, 1, "camera back"), filtered) < 1e-6,
    "after the camera returns A is the filtered frame again");
  RenderFrame(win, aov, 2, "still again");

  // MaximumAccumulatedFrames caps the stratification.
  aov->SetMaximumAccumulatedFrames(4);
  for (int k = 1; k <= 4; ++k)
  {
    RenderFrame(win, aov, k, "at most 4 frames");
  }
  Check(!aov->IsAccumulating() && aov->GetAccumulationTarget() == 4, "4 frames are the maximum");
  RenderFrame(win, aov, 4, "past the maximum");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
