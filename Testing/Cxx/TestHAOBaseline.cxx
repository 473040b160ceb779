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
  auto win = MakeSphereBlockWindow(ren, 24);
  // Deterministic: one frame (no accumulation, so the frame vtkTesting renders again is the
  // same), the default voxel-grid rotation seed.
  vtkSmartPointer<vtkHybridAmbientOcclusionPass> hao;
  if (!aoOff)
  {
    hao = InstallHAO(ren, 2.0);
    hao->SetAccumulation(false);
  }
  win->Render();

  // Without AO (the variant), a lit sphere top; with AO, occlusion and A.
  return CheckSphereBlock(argc, argv, "HAO", ren, win, aoOff ? nullptr : hao.Get());
}
