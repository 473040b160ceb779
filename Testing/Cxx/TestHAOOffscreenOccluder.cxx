// An occluder outside the view frustum darkens visible ground next to it. vtkSSAOPass, in the
// same scene, demonstrably does not: its darkening there equals that of open ground.
#include "vtkAOTestUtilities.h"

int TestHAOOffscreenOccluder(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddGround(ren, 6);
  // A slab just right of the view (the view ends at x = 4.37 on the ground, 2.9 at height 4).
  vtkNew<vtkCubeSource> slab;
  slab->SetBounds(4.6, 5.2, 0, 4, -4, 4);
  AddActor(ren, slab);
  TopView(ren, 0, 0, 12);
  ren->GetActiveCamera()->SetClippingRange(0.1, 20); // keep the view as it is

  // Where the slab would be seen (nowhere in the image) and where its occlusion falls.
  const int right[4] = { 370, 180, 398, 220 }; // ground x in [3.7, 4.3]
  const int left[4] = { 2, 180, 30, 220 };     // mirror image, open ground

  auto hao = InstallHAO(ren, 2.0);
  win->Render();
  const double aoRight = MeanAO(hao, right);
  const double aoLeft = MeanAO(hao, left);
  std::printf("HAO A: next to the off-screen slab %.3f, open side %.3f\n", aoRight, aoLeft);
  Check(aoLeft > 0.95, "open ground keeps A > 0.95");
  Check(aoRight >= 0.0 && aoRight < aoLeft - 0.05,
    "HAO: the off-screen slab darkens the ground by > 0.05");

  // The same with vtkSSAOPass: compare each side with the plain render.
  vtkNew<vtkRenderStepsPass> basic;
  ren->SetPass(basic);
  win->Render();
  const double plainRight = MeanLuminance(win, right);
  const double plainLeft = MeanLuminance(win, left);
  InstallSSAO(ren, basic, 2.0, 128);
  win->Render();
  const double ssaoRight = MeanLuminance(win, right) / plainRight;
  const double ssaoLeft = MeanLuminance(win, left) / plainLeft;
  std::printf("SSAO/plain luminance: next to the slab %.3f, open side %.3f\n", ssaoRight, ssaoLeft);
  Check(std::abs(ssaoRight - ssaoLeft) < 0.02, "SSAO cannot see the off-screen slab");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
