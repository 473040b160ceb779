// A moving actor moves its occlusion (the grid is rebuilt), and a static scene under a moving
// camera is not voxelized again.
#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOTestUtilities.h"

int TestHAODynamicScene(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddGround(ren, 5);
  vtkSmartPointer<vtkActor> sphere = AddSphere(ren, -2, 0);
  TopView(ren, 0, 0, 12);
  ren->GetActiveCamera()->SetClippingRange(0.1, 20);
  auto hao = InstallHAO(ren, 2.0);

  // Ground just beside each sphere position (x = -2 and x = +2, 45.8 px per unit).
  const int leftRing[4] = { 162, 195, 170, 205 };  // x ~ -0.75 from centre -2 -> +1.2
  const int rightRing[4] = { 230, 195, 238, 205 }; // x ~ +0.8, inner side of +2
  win->Render();
  const int first = hao->GetVoxelizationCount();
  const double a0 = MeanAO(hao, leftRing[0], leftRing[1], leftRing[2], leftRing[3]);
  const double b0 = MeanAO(hao, rightRing[0], rightRing[1], rightRing[2], rightRing[3]);
  std::printf("sphere at -2: A beside it %.3f, at the other place %.3f\n", a0, b0);
  Check(first == 1, "the first frame voxelizes once");
  Check(a0 >= 0.0 && a0 < b0 - 0.08, "occlusion where the sphere is");

  sphere->SetPosition(4, 0, 0); // now at x = +2
  win->Render();
  const double a1 = MeanAO(hao, leftRing[0], leftRing[1], leftRing[2], leftRing[3]);
  const double b1 = MeanAO(hao, rightRing[0], rightRing[1], rightRing[2], rightRing[3]);
  std::printf("sphere at +2: A at the old place %.3f, beside it %.3f\n", a1, b1);
  Check(hao->GetVoxelizationCount() == first + 1, "moving an actor re-voxelizes");
  Check(a1 > 0.95, "the old place is open again");
  Check(b1 >= 0.0 && b1 < a1 - 0.08, "the occlusion moved with the sphere");

  // Camera only: no voxelization, occlusion still there.
  const int beforeOrbit = hao->GetVoxelizationCount();
  for (int i = 0; i < 3; ++i)
  {
    ren->GetActiveCamera()->Azimuth(10);
    ren->GetActiveCamera()->Elevation(-5);
    ren->ResetCameraClippingRange();
    win->Render();
  }
  Check(hao->GetVoxelizationCount() == beforeOrbit,
    "a moving camera over a static scene does not re-voxelize");
  Check(hao->GetVoxelizeTime() == 0.0, "and the voxelization stage costs nothing");

  // Changing the data re-voxelizes.
  vtkSphereSource* source = vtkSphereSource::SafeDownCast(sphere->GetMapper()->GetInputAlgorithm());
  source->SetRadius(0.5);
  win->Render();
  Check(
    hao->GetVoxelizationCount() == beforeOrbit + 1, "modifying the mapper's input re-voxelizes");

  // The View region follows the camera.
  hao->SetRegionModeToView();
  win->Render();
  const int viewCount = hao->GetVoxelizationCount();
  ren->GetActiveCamera()->SetFocalPoint(3, 0, 3);
  ren->GetActiveCamera()->SetPosition(3, 12, 3);
  ren->GetActiveCamera()->SetClippingRange(0.1, 13);
  win->Render();
  const double* vr = hao->GetVoxelizer()->GetRegion();
  std::printf("view region x [%g, %g] z [%g, %g]\n", vr[0], vr[1], vr[4], vr[5]);
  Check(hao->GetVoxelizationCount() == viewCount + 1,
    "View region mode re-voxelizes when the camera moves");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
