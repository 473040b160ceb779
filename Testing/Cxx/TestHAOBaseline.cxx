// A regression image through VTK's testing framework (VTK >= 9.4, SSIM): HAO on a 4 x 4 block
// of touching spheres, one frame (no accumulation), against Testing/Data/Baseline/
// TestHAOBaseline.png. Its ctest variant AOOff-TestHAOBaseline renders the same scene without
// the pass and must fail the comparison (vtkAOTestBaseline.h says why the scene and the
// threshold). A itself is asserted here as everywhere else.
#include "vtkAOTestBaseline.h"

int TestHAOBaseline(int argc, char* argv[])
{
  using namespace vtkAOTest;
  const bool aoOff = AOOffRequested(argc, argv);
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(BaselineSize, BaselineSize, ren);
  AddSphereBlock(ren, 24);
  // Deterministic: one frame (no accumulation, so the frame vtkTesting renders again is the
  // same), the default voxel-grid rotation seed.
  vtkSmartPointer<vtkHybridAmbientOcclusionPass> hao;
  if (!aoOff)
  {
    hao = InstallHAO(ren, 2.0);
    hao->SetAccumulation(false);
  }
  win->Render();

  // The pocket of ground between the four central spheres, the top of a sphere.
  int px, py, tx, ty;
  ToDisplay(ren, 0, 0, 0, px, py);
  ToDisplay(ren, 1, 2, 1, tx, ty);
  const int pocket[4] = { px - 2, py - 2, px + 3, py + 3 };
  const int top[4] = { tx - 3, ty - 3, tx + 4, ty + 4 };
  // Without AO, a lit sphere top; with AO, occlusion applied (grabbing the window re-renders
  // it, which restarts the pass's mean: one full frame more, Documentation/reliability.md).
  const bool rendered = aoOff ? MeanLuminance(win, top) > 0.3 : hao->GetLastFrameHadOcclusion();
  if (!aoOff)
  {
    Check(hao->GetLastFrameHadOcclusion(), "the pass applied occlusion");
    const double aoPocket = MeanAO(hao, pocket);
    const double aoTop = MeanAO(hao, top);
    std::printf("HAO A: pocket between four spheres %.3f, top of a sphere %.3f\n", aoPocket, aoTop);
    Check(aoTop > 0.95, "the top of a sphere keeps A > 0.95");
    Check(aoPocket >= 0.0 && aoPocket < 0.9, "the pocket between four spheres has A < 0.9");
  }
  else
  {
    std::printf("AO off: the scene without the pass (the variant must fail the comparison)\n");
  }
  const int code = CompareWithBaseline(argc, argv, win, aoOff, rendered);
  ren->ReleaseGraphicsResources(win);
  return code;
}
