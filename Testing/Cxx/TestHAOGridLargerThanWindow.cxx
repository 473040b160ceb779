// The voxel grid's helper textures may be larger than the window: at voxel resolution 384 the
// coarse occupancy level the tracer skips empty space with is 192 x 384 texels, taller than a
// 64 x 64 window whose scissor box the renderer leaves set. The occlusion must not depend on
// that: a small window sees the same A as a large one (same camera, same aspect).
#include "vtkAOTestUtilities.h"

namespace
{
// Mean occlusion 1 - A over the covered pixels of a window of n x n pixels.
double MeanOcclusion(int n)
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(n, n, ren);
  // From above, close: the sphere and the contact ring around it fill the view.
  AddSphereOnGround(ren, 4.5);
  auto hao = InstallHAO(ren, 2.0);
  hao->SetVoxelResolution(384);
  win->Render();
  const double a = MeanAO(hao, 0, 0, n, n);
  ren->ReleaseGraphicsResources(win);
  return a < 0.0 ? -1.0 : 1.0 - a;
}
}

int TestHAOGridLargerThanWindow(int, char*[])
{
  using namespace vtkAOTest;
  const double large = MeanOcclusion(400);
  const double small = MeanOcclusion(64);
  std::printf("mean occlusion 1 - A: 400 x 400 window %.4f, 64 x 64 window %.4f\n", large, small);
  Check(large > 0.006, "the large window shows the contact occlusion");
  Check(small >= 0.0 && std::abs(small - large) < 0.25 * large,
    "the small window shows the same occlusion (within 25 %)");
  return Result();
}
