// Contact occlusion with Ambient Occlusion Volumes: the ground right beside a sphere resting on
// it is darker than open ground by a stated margin, open ground and the sphere's top stay
// unoccluded, and an occluder entirely outside the view still darkens the visible ground (its
// triangles' volumes cover visible pixels).
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCamera.h"

#include <cmath>
#include <string>

int TestAOVContactOcclusion(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(100, 100, ren);
  AddGround(ren, 5);
  // A coarse sphere: the cost of the method is triangles x their volumes' screen area.
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0, 1, 0);
  ball->SetRadius(1.0); // resting on the ground
  ball->SetThetaResolution(16);
  ball->SetPhiResolution(8);
  auto sphere = AddActor(ren, ball);
  TopView(ren, 0, 0, 12);
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  aov->SetDelegatePass(basic);
  ren->SetPass(aov);
  aov->SetRadius(2.0);
  win->Render();

  Check(aov->GetLastFrameHadOcclusion(), "the pass applied occlusion");
  // 11.4 pixels per unit on the ground; the sphere's silhouette ends ~12 px from the centre.
  const double ring = vtkAOTest::MeanAO(aov, 63, 47, 66, 53);
  const double open = vtkAOTest::MeanAO(aov, 3, 3, 11, 11);
  const double top = vtkAOTest::MeanAO(aov, 48, 48, 52, 52);
  std::printf(
    "A: ring beside the contact %.3f, open ground %.3f, sphere top %.3f\n", ring, open, top);
  Check(open > 0.98, "open ground keeps A > 0.98");
  Check(top > 0.98, "the top of the sphere keeps A > 0.98");
  // (The value itself is checked against the ray-traced reference in TestAOVReference.)
  Check(ring >= 0.0 && ring < open - 0.05, "ground beside the contact is darker by more than 0.05");

  // Intensity does not change A, only the composite; the shaded image darkens.
  const double litRing = MeanLuminance(win, 63, 47, 66, 53);
  aov->SetIntensity(0.0);
  win->Render();
  Check(
    std::abs(vtkAOTest::MeanAO(aov, 63, 47, 66, 53) - ring) < 1e-6, "intensity leaves A unchanged");
  const double unlitRing = MeanLuminance(win, 63, 47, 66, 53);
  std::printf(
    "luminance beside the contact: %.3f with AO, %.3f with intensity 0\n", litRing, unlitRing);
  Check(litRing < unlitRing - 0.03, "the composite darkens the contact ring");
  aov->SetIntensity(1.0);

  // The volumes are drawn by their far faces: a far plane through them (VTK's automatic range
  // ends just beyond the props' bounds, and so does the one set here) must not lose occlusion.
  {
    vtkCamera* camera = ren->GetActiveCamera();
    double range[2];
    camera->GetClippingRange(range);
    camera->SetClippingRange(9.0, 100.0);
    win->Render();
    const double distantFar = vtkAOTest::MeanAO(aov, 63, 47, 66, 53);
    camera->SetClippingRange(9.0, 12.3); // the ground is 12 away
    win->Render();
    const double closeFar = vtkAOTest::MeanAO(aov, 63, 47, 66, 53);
    std::printf("ring with the far plane at 100: %.3f, at 12.3: %.3f\n", distantFar, closeFar);
    Check(std::abs(closeFar - distantFar) < 0.02 && std::abs(ring - distantFar) < 0.02,
      "a far plane through the volumes leaves the contact ring within 0.02");
    camera->SetClippingRange(range);
  }

  // Screen-space subsampling: a quarter (AOScale 2) or a sixteenth (4) of the pixels
  // evaluated, the rest filled by the bilateral filter: A close to the full evaluation.
  for (int scale : { 2, 4 })
  {
    aov->SetAOScale(scale);
    win->Render();
    const double subRing = vtkAOTest::MeanAO(aov, 63, 47, 66, 53);
    const double subOpen = vtkAOTest::MeanAO(aov, 3, 3, 11, 11);
    std::printf("AOScale %d: ring %.3f, open ground %.3f\n", scale, subRing, subOpen);
    Check(std::abs(subRing - ring) < 0.02 && subOpen > 0.98,
      "AOScale " + std::to_string(scale) + " keeps the ring within 0.02 and open ground open");
  }
  aov->SetAOScale(1);

  // Off-screen occluder: move the camera so the sphere is just outside the left edge; the
  // ground at the left edge, right beside it, must still be darker than the far side.
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(3.3, 0, 0);
  cam->SetPosition(3.3, 6, 0);
  ren->ResetCameraClippingRange();
  win->Render();
  // 22.9 px per unit; the view spans x in [1.12, 5.48]: the sphere (x <= 1) is off screen.
  const double edge = vtkAOTest::MeanAO(aov, 0, 47, 2, 53);
  const double far = vtkAOTest::MeanAO(aov, 75, 47, 85, 53);
  std::printf("off-screen sphere: A at the near edge %.3f, far side %.3f\n", edge, far);
  Check(edge >= 0.0 && edge < far - 0.03, "an off-screen occluder darkens the visible ground");
  sphere->VisibilityOff();
  win->Render();
  const double edgeWithout = vtkAOTest::MeanAO(aov, 0, 47, 2, 53);
  Check(edgeWithout > 0.98, "without the occluder the edge is open (A > 0.98)");

  // GPU memory: textures and the triangle buffer, all freed by ReleaseGraphicsResources.
  const long long before = aov->GetGraphicsMemorySize();
  ren->ReleaseGraphicsResources(win);
  Check(before > 0 && aov->GetGraphicsMemorySize() == 0,
    "ReleaseGraphicsResources frees the pass's GPU memory (" + std::to_string(before) +
      " bytes before, " + std::to_string(aov->GetGraphicsMemorySize()) + " after)");
  win->Render();
  Check(aov->GetLastFrameHadOcclusion() && aov->GetGraphicsMemorySize() == before,
    "rendering again after the release works and allocates the same (" +
      std::to_string(aov->GetGraphicsMemorySize()) + " bytes)");
  ren->ReleaseGraphicsResources(win);
  return Result();
}
