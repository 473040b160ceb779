// Contact occlusion: the ground right beside a sphere resting on it is darker than open ground
// and within 0.03 of the exact integral there, and open ground stays unoccluded (A > 0.95).
#include "vtkAOTestUtilities.h"

#include <cmath>

int TestHAOContactOcclusion(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddSphereOnGround(ren);
  auto hao = InstallHAO(ren, 2.0);
  win->Render();

  Check(hao->GetLastFrameHadOcclusion(), "the pass applied occlusion");
  // 45.8 pixels per unit on the ground; the sphere's silhouette ends ~50 px from the centre.
  const double ring = MeanAO(hao, 254, 195, 262, 205);
  const double open = MeanAO(hao, 15, 15, 45, 45);
  const double top = MeanAO(hao, 195, 195, 205, 205);
  std::printf(
    "A: ring beside the contact %.3f, open ground %.3f, sphere top %.3f\n", ring, open, top);
  Check(open > 0.95, "open ground keeps A > 0.95");
  Check(top > 0.95, "the top of the sphere keeps A > 0.95");
  // The exact A over that box (the sphere-on-plane integral with Wendland falloff, R = 2,
  // integrated by Monte Carlo over the box's pixels) is 0.910.
  Check(ring >= 0.0 && ring < open - 0.06 && std::abs(ring - 0.910) < 0.03,
    "ground beside the contact is darker than open ground, within 0.03 of the exact 0.910");

  // Filtering off shows the raw map: same occlusion, just noisier.
  hao->FilterOff();
  win->Render();
  const double rawRing = MeanAO(hao, 254, 195, 262, 205);
  Check(rawRing >= 0.0 && rawRing < open - 0.08, "the raw (unfiltered) map shows it too");

  // Intensity does not change A, only the composite.
  hao->FilterOn();
  hao->SetIntensity(0.0);
  win->Render();
  const double ringNoIntensity = MeanAO(hao, 254, 195, 262, 205);
  Check(std::abs(ringNoIntensity - ring) < 1e-6, "intensity leaves A unchanged");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
