// A regression image through VTK's testing framework (VTK >= 9.4, SSIM): Ambient Occlusion
// Volumes on a 4 x 4 block of touching spheres against Testing/Data/Baseline/
// TestAOVBaseline.png. Its ctest variant AOOff-TestAOVBaseline renders the same scene without
// the pass and must fail the comparison (vtkAOTestBaseline.h says why the scene and the
// threshold). A itself is asserted here as everywhere else.
#include "vtkAOTestBaseline.h"
#include "vtkAmbientOcclusionVolumesPass.h"

int TestAOVBaseline(int argc, char* argv[])
{
  using namespace vtkAOTest;
  const bool aoOff = AOOffRequested(argc, argv);
  vtkNew<vtkRenderer> ren;
  // Coarser spheres than HAO's test: AOV's cost is triangles x their volumes' screen area.
  auto win = MakeSphereBlockWindow(ren, 16);
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  if (!aoOff)
  {
    aov->SetDelegatePass(basic);
    aov->SetRadius(2.0);
    // A quarter of the pixels evaluated, the rest filled by the bilateral filter: a third of
    // the time of every pixel on llvmpipe, about the same A (TestAOVContactOcclusion).
    aov->SetAOScale(2);
    // vtkTesting reads this render (-NoRerender): the first frame, the filtered map (a still's
    // later frames would refine it: Documentation/aov.md).
    ren->SetPass(aov);
  }
  win->Render();

  // Without AO (the variant), a lit sphere top; with AO, occlusion and A.
  return CheckSphereBlock(argc, argv, "AOV", ren, win, aoOff ? nullptr : aov.Get());
}
