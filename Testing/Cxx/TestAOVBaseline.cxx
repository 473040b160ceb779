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
  auto win = MakeWindow(BaselineSize, BaselineSize, ren);
  // Coarser spheres than HAO's test: AOV's cost is triangles x their volumes' screen area.
  AddSphereBlock(ren, 16);
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  if (!aoOff)
  {
    aov->SetDelegatePass(basic);
    aov->SetRadius(2.0);
    // A quarter of the pixels evaluated, the rest filled by the bilateral filter: a third of
    // the time of every pixel on llvmpipe, about the same A (TestAOVContactOcclusion).
    aov->SetAOScale(2);
    ren->SetPass(aov); // no jitter: every frame is the same
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
  const bool rendered = aoOff ? MeanLuminance(win, top) > 0.3 : aov->GetLastFrameHadOcclusion();
  if (!aoOff)
  {
    Check(aov->GetLastFrameHadOcclusion(), "the pass applied occlusion");
    const double aoPocket = MeanAO(aov, pocket);
    const double aoTop = MeanAO(aov, top);
    std::printf("AOV A: pocket between four spheres %.3f, top of a sphere %.3f\n", aoPocket, aoTop);
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
