// Cascaded grids (a clipmap around the camera) on a ground far larger than R: one grid of the
// largest automatic size would have cells of R / 5 there, too coarse for a contact. With the
// cascades, the ground beside a sphere resting on it is within 0.03 of the exact integral (as
// in TestHAOContactOcclusion, whose local geometry this repeats), both under the camera's first
// position and after the camera moved over a second sphere 60 units away (the cascades follow
// it). Turning the camera on the spot keeps them, and open ground stays unoccluded.
#include "vtkAOTestUtilities.h"

#include <cmath>

namespace
{
struct Figures
{
  double Ring, Open;
};

Figures Measure(vtkHybridAmbientOcclusionPass* hao)
{
  // 45.8 pixels per unit on the ground; the sphere's silhouette ends ~50 px from the centre.
  Figures f;
  f.Ring = vtkAOTest::MeanAO(hao, 254, 195, 262, 205);
  f.Open = vtkAOTest::MeanAO(hao, 15, 15, 45, 45);
  return f;
}
}

int TestHAOCascades(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddGround(ren, 200); // 400 x 400, R = 2: 12,800 cells of R / 64 across
  AddSphere(ren, 0, 0);
  AddSphere(ren, 60, 0);
  TopView(ren, 0, 0, 12);
  auto hao = InstallHAO(ren, 2.0);
  win->Render();

  Check(hao->GetLastFrameHadOcclusion(), "the pass applied occlusion");
  const int cascades = hao->GetEffectiveNumberOfCascades();
  const double mib = hao->GetGraphicsMemorySize() / (1024.0 * 1024.0);
  std::printf("cascades %d of %d cells, GPU memory %.1f MiB\n",
    cascades,
    hao->GetEffectiveVoxelResolution(),
    mib);
  Check(cascades >= 2, "a region 200 R wide is voxelized in cascades");

  const Figures first = Measure(hao);
  std::printf("first sphere: ring %.3f, open ground %.3f\n", first.Ring, first.Open);
  Check(first.Open > 0.95, "open ground keeps A > 0.95");
  // The exact A over that box (sphere on a plane, Wendland falloff, R = 2) is 0.910.
  Check(std::abs(first.Ring - 0.910) < 0.03, "ring within 0.03 of the exact 0.910");

  // Turning the camera on the spot moves no cascade: the grids are kept.
  int voxelizations = hao->GetVoxelizationCount();
  ren->GetActiveCamera()->Yaw(10);
  win->Render();
  Check(hao->GetVoxelizationCount() == voxelizations, "turning the camera keeps the cascades");

  TopView(ren, 60, 0, 12);
  win->Render();
  const Figures second = Measure(hao);
  std::printf("second sphere: ring %.3f, open ground %.3f\n", second.Ring, second.Open);
  Check(hao->GetVoxelizationCount() > voxelizations, "the cascades moved with the camera");
  Check(second.Open > 0.95, "open ground keeps A > 0.95 after the move");
  Check(std::abs(second.Ring - 0.910) < 0.03, "ring within 0.03 of 0.910 after the move");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
