// Full-resolution refinement (issue 16, item 2): on fins finer than a texel of the reduced AO
// map (AO scale 3), the refined image is close to the full-resolution map's (AO scale 1),
// where without refinement the map aliases into bands; only a minority of the pixels is
// traced again, and almost none where the map represents the surface (a lone plane: its
// outline against the background only). The refined pixels' filter (RefinementFilterRadius)
// brings them closer still, as the full-resolution map is filtered too.
#include "vtkAOTestUtilities.h"

#include <cmath>

int TestHAORefinement(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(320, 240, ren);
  AddGround(ren, 3);
  // A heat sink: a base and 24 fins 0.02 thick, 0.1 apart (about 4 pixels here).
  for (int i = 0; i < 24; ++i)
  {
    vtkNew<vtkCubeSource> fin;
    const double x = -1.2 + 0.1 * i;
    fin->SetBounds(x, x + 0.02, 0.0, 0.5, -0.8, 0.8);
    AddActor(ren, fin);
  }
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0, 0.2, 0);
  cam->SetPosition(1.5, 2.8, 4.0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(35);
  ren->ResetCameraClippingRange();
  auto hao = InstallHAO(ren, 0.3);
  hao->SetNumberOfRays(16);

  hao->SetAOScale(1);
  win->Render();
  const AOImage full = PassAOImage(hao.Get());
  hao->SetAOScale(3);
  hao->RefinementOff();
  win->Render();
  const AOImage reduced = PassAOImage(hao.Get());
  hao->RefinementOn();
  win->Render();
  const AOImage refined = PassAOImage(hao.Get());
  const double fraction = hao->GetRefinedFraction();
  Check(hao->GetRefinementFilterRadius() == 2, "the refinement filter is on by default");
  hao->SetRefinementFilterRadius(0);
  win->Render();
  const AOImage unfiltered = PassAOImage(hao.Get());
  hao->SetRefinementFilterRadius(2);

  // The refined pixels are listed (compacted) by default; shading them in place instead must
  // give the same image, with and without the refinement filter (the list only changes which
  // invocations do the work, a broken list or scatter leaves the reduced map there).
  Check(hao->GetRefinementList(), "the refined pixels are listed by default");
  hao->RefinementListOff();
  win->Render();
  const AOImage inPlace = PassAOImage(hao.Get());
  const double inPlaceFraction = hao->GetRefinedFraction();
  hao->SetRefinementFilterRadius(0);
  win->Render();
  const AOImage inPlaceUnfiltered = PassAOImage(hao.Get());
  hao->SetRefinementFilterRadius(2);
  hao->RefinementListOn();
  const double listVsInPlace = MaxAbsDifference(refined, inPlace);
  const double listVsInPlaceUnfiltered = MaxAbsDifference(unfiltered, inPlaceUnfiltered);
  std::printf("listed against in place: max |dA| %.2g (filtered), %.2g (unfiltered); "
              "list against the reduced map %.2g\n",
    listVsInPlace,
    listVsInPlaceUnfiltered,
    MaxAbsDifference(refined, reduced));
  Check(inPlaceFraction == fraction, "listed and in-place refinement mark the same pixels");
  Check(listVsInPlace <= 2e-3 && listVsInPlaceUnfiltered <= 2e-3,
    "listed and in-place refinement give the same AO image");

  const double before = CoveredRMSE(reduced, full), after = CoveredRMSE(refined, full);
  const double afterUnfiltered = CoveredRMSE(unfiltered, full);
  std::printf("RMS difference to AO scale 1: reduced map %.4f, refined %.4f (without the "
              "refinement filter %.4f); refined pixels %.1f%%\n",
    before,
    after,
    afterUnfiltered,
    100 * fraction);
  Check(full.A.size() == refined.A.size() && !full.A.empty(), "AO images of the window's size");
  Check(after < 0.85 * before,
    "refinement brings the reduced map at least 15% closer to the "
    "full-resolution one on fins finer than a texel");
  Check(after < 0.95 * afterUnfiltered,
    "the refinement filter brings the refined pixels at least 5% closer to the filtered "
    "full-resolution map");
  Check(fraction > 0.01 && fraction < 0.5, "a minority of the pixels is refined");

  // A lone plane: the map represents it everywhere, nothing is refined.
  ren->RemoveAllViewProps();
  AddGround(ren, 3);
  win->Render();
  std::printf("lone plane: refined %.3f%%\n", 100 * hao->GetRefinedFraction());
  Check(hao->GetRefinedFraction() < 0.01, "a lone plane needs almost no refinement (its outline)");
  const long long refiningBytes = hao->GetGraphicsMemorySize();
  // The listed refinement reads and scatters into the tracer's target; only the in-place one
  // keeps a full-screen copy of the map for its filter (RG32F).
  hao->RefinementListOff();
  win->Render();
  const long long inPlaceBytes = hao->GetGraphicsMemorySize();
  std::printf(
    "GPU memory refining listed %lld bytes, in place %lld\n", refiningBytes, inPlaceBytes);
  Check(inPlaceBytes - refiningBytes >= 320LL * 240 * 8,
    "only the in-place refinement holds a copy of the map");
  hao->RefinementListOn();
  win->Render();
  Check(hao->GetGraphicsMemorySize() == refiningBytes, "back to the list, the copy is freed");
  hao->RefinementOff();
  win->Render();
  Check(hao->GetRefinedFraction() == 0.0, "refinement off reports 0");
  // The marks (depth) and the pixel list are freed when it is off.
  std::printf("GPU memory refining %lld bytes, not refining %lld\n",
    refiningBytes,
    hao->GetGraphicsMemorySize());
  Check(refiningBytes - hao->GetGraphicsMemorySize() >= 320LL * 240 * 4,
    "turning refinement off frees the marks and the pixel list");
  hao->RefinementOn();
  hao->SetAOScale(1);
  win->Render();
  Check(hao->GetRefinedFraction() == 0.0, "AO scale 1 refines nothing and reports 0");

  // The contrast the marks use (the mouldings it is for: TestHAORefinementReference).
  Check(hao->GetRefinementContrast() == 0.0 && hao->GetEffectiveRefinementContrast() == 0.15,
    "automatic contrast 0.15 with the Wendland falloff");
  Check(hao->GetRefinementRays() == 0 && hao->GetEffectiveRefinementRays() == 16,
    "automatic refinement rays: NumberOfRays with the Wendland falloff");
  hao->SetFalloffToBinary();
  Check(hao->GetEffectiveRefinementContrast() == 0.3, "automatic contrast 0.3 (binary)");
  Check(hao->GetEffectiveRefinementRays() == 32, "automatic refinement rays: twice (binary)");
  hao->SetRefinementRays(12);
  Check(hao->GetEffectiveRefinementRays() == 12, "explicit refinement rays are kept");
  hao->SetRefinementRays(0);
  hao->SetFalloffToWendland();
  hao->SetRefinementContrast(0.2);
  Check(hao->GetEffectiveRefinementContrast() == 0.2, "an explicit contrast is kept");
  hao->SetRefinementContrast(0.0);

  ren->ReleaseGraphicsResources(win);
  return Result();
}
