// Progressive stills: renders of an unchanged view re-jitter HAO's rays and average A, so the
// mean converges (the change between the mean of k frames and of 2k frames falls as k grows,
// and the contact shadow stays on the exact integral); its first frame is the frame without
// accumulation; any change (camera, prop transform, prop data, a parameter, the window size)
// restarts it (GetAccumulatedFrames() back to 1 and A the single frame of the new state, not
// the old mean), a 2-D prop's does not; once MaximumAccumulatedFrames are in the mean, further
// renders keep it.
#include "vtkAOTestUtilities.h"

#include "vtkAlgorithm.h"
#include "vtkMapper.h"
#include "vtkTextActor.h"

#include <cmath>

namespace
{
/// Render once and check the accumulation count.
std::vector<float> RenderFrame(vtkRenderWindow* win,
  vtkHybridAmbientOcclusionPass* hao,
  int expectedFrames,
  const std::string& what)
{
  win->Render();
  vtkAOTest::Check(hao->GetAccumulatedFrames() == expectedFrames,
    what + ": " + std::to_string(hao->GetAccumulatedFrames()) + " accumulated frames, expected " +
      std::to_string(expectedFrames));
  return vtkAOTest::ReadAO(hao);
}
}

int TestHAOAccumulation(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(300, 300, ren);
  AddGround(ren, 5);
  vtkSmartPointer<vtkActor> sphere = AddSphere(ren, 0, 0);
  TopView(ren, 0, 0, 12);
  auto hao = InstallHAO(ren);
  hao->SetRadius(2.0);
  hao->SetNumberOfRays(2); // noisy frames, so that averaging has something to remove
  Check(hao->GetAccumulation() && hao->GetMaximumAccumulatedFrames() == 16,
    "accumulation is on by default, at most 16 frames");

  // The means of 1, 2, 4, 8 and 16 frames.
  std::vector<std::vector<float>> means;
  for (int k = 1; k <= 16; ++k)
  {
    std::vector<float> a = RenderFrame(win, hao, k, "still view");
    if ((k & (k - 1)) == 0)
    {
      means.push_back(a);
    }
  }
  const std::vector<float> single = means[0], converged = means[4];
  double change[4];
  for (int i = 0; i < 4; ++i)
  {
    change[i] = vtkAOTest::AODifference(means[i], means[i + 1]);
  }
  std::printf("RMS change of the mean from k to 2k frames: k=1 %.5f, 2 %.5f, 4 %.5f, 8 %.5f\n",
    change[0],
    change[1],
    change[2],
    change[3]);
  Check(change[0] > 1e-3, "the second frame is jittered differently from the first");
  Check(change[1] < 0.8 * change[0] && change[2] < 0.8 * change[1] && change[3] < 0.8 * change[2],
    "the mean changes less and less as frames are added (it converges)");
  Check(change[3] < 0.4 * change[0], "16 frames change the mean of 8 far less than 2 change 1");
  // 45.8 pixels per unit on the ground at 400 pixels; here 300: the ring beside the contact.
  win->Render(); // past the maximum: the mean is kept
  Check(hao->GetAccumulatedFrames() == 16 && !hao->IsAccumulating(),
    "past the maximum the mean holds 16 frames and is no longer refined");
  Check(vtkAOTest::AODifference(vtkAOTest::ReadAO(hao.Get()), converged) == 0.0,
    "past the maximum A is the same mean");

  // The first frame is the frame without accumulation.
  hao->AccumulationOff();
  std::vector<float> plain = RenderFrame(win, hao, 1, "accumulation off");
  Check(vtkAOTest::AODifference(plain, single) < 1e-6,
    "the first frame is the frame without accumulation");
  plain = RenderFrame(win, hao, 1, "accumulation off, again");
  Check(vtkAOTest::AODifference(plain, single) < 1e-6,
    "without accumulation every frame is that frame");
  hao->AccumulationOn();
  RenderFrame(win, hao, 1, "accumulation on again");
  RenderFrame(win, hao, 2, "the second frame of the still");

  // Each change restarts: the count is 1 and A is the new state's single frame. Changing
  // back shows the original view's first frame again, not the old mean.
  vtkCamera* cam = ren->GetActiveCamera();
  cam->Azimuth(10);
  RenderFrame(win, hao, 1, "camera moved");
  cam->Azimuth(-10);
  Check(vtkAOTest::AODifference(RenderFrame(win, hao, 1, "camera back"), single) < 1e-6,
    "after the camera returns A is the single frame, not the old mean");
  RenderFrame(win, hao, 2, "still again");

  sphere->SetPosition(0.5, 0, 0);
  RenderFrame(win, hao, 1, "sphere moved");
  sphere->SetPosition(0, 0, 0);
  Check(vtkAOTest::AODifference(RenderFrame(win, hao, 1, "sphere back"), single) < 1e-6,
    "after the sphere returns A is the single frame");
  RenderFrame(win, hao, 2, "still again");

  sphere->GetMapper()->GetInputAlgorithm()->Modified(); // the data is regenerated
  RenderFrame(win, hao, 1, "the sphere's data modified");
  RenderFrame(win, hao, 2, "still again");

  hao->SetNumberOfSteps(5);
  RenderFrame(win, hao, 1, "a parameter changed");
  hao->SetNumberOfSteps(4);
  Check(vtkAOTest::AODifference(RenderFrame(win, hao, 1, "parameter back"), single) < 1e-6,
    "after the parameter returns A is the single frame");

  // A 2-D prop (a frame counter) does not change A: its changes do not restart.
  vtkNew<vtkTextActor> counter;
  counter->SetInput("frame 1");
  ren->AddViewProp(counter);
  RenderFrame(win, hao, 2, "a text actor added");
  counter->SetInput("frame 2");
  RenderFrame(win, hao, 3, "the text changed");
  ren->RemoveViewProp(counter);
  RenderFrame(win, hao, 4, "the text actor removed");

  // A screenshot renders through vtkWindowToImageFilter, which swaps in a copy of the camera
  // whose view angle went through a float: it adds a frame to the still, as a render does.
  vtkNew<vtkWindowToImageFilter> screenshot;
  screenshot->SetInput(win);
  screenshot->Update();
  Check(hao->GetAccumulatedFrames() == 5,
    "a screenshot adds a frame (" + std::to_string(hao->GetAccumulatedFrames()) + ", expected 5)");
  RenderFrame(win, hao, 6, "a render after the screenshot");

  win->SetSize(320, 300);
  RenderFrame(win, hao, 1, "window resized");
  RenderFrame(win, hao, 2, "still again");

  // The converged still is right: the contact ring against the exact integral (0.910, see
  // TestHAOContactOcclusion) and open ground open. Back to the first size and 16 frames.
  win->SetSize(300, 300);
  hao->SetNumberOfRays(8);
  for (int k = 1; k <= 16; ++k)
  {
    RenderFrame(win, hao, k, "the default rays");
  }
  const double s = 300.0 / 400.0;
  const double ring = MeanAO(hao,
    static_cast<int>(254 * s),
    static_cast<int>(195 * s),
    static_cast<int>(262 * s),
    static_cast<int>(205 * s));
  const double open = MeanAO(hao, 10, 10, 35, 35);
  std::printf("converged: ring beside the contact %.3f, open ground %.3f\n", ring, open);
  Check(std::abs(ring - 0.910) < 0.03, "the converged contact ring is within 0.03 of 0.910");
  Check(open > 0.95, "open ground stays open");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
