// HAO's presets (ApplyPreset): each sets its measured parameters and leaves the others alone;
// each renders the contact shadow of a sphere on the ground (darker beside the contact than
// on open ground; BALANCED and QUALITY within 0.03 of the exact value); INTERACTIVE voxelizes a
// 256^3 grid along one axis and refines nothing, BALANCED is the defaults; an unknown preset
// changes nothing.
#include "vtkAOTestUtilities.h"

#include "vtkCommand.h"

#include <cmath>

namespace
{
/// Counts the error events of the object it observes (the unknown preset's error).
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};
}

int TestHAOPresets(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddSphereOnGround(ren);
  auto hao = InstallHAO(ren);
  hao->SetRadius(2.0);
  hao->SetIntensity(2.0);
  hao->AccumulationOff();

  // The defaults are the balanced preset.
  vtkNew<vtkHybridAmbientOcclusionPass> defaults;
  defaults->ApplyPreset(vtkHybridAmbientOcclusionPass::BALANCED);
  vtkNew<vtkHybridAmbientOcclusionPass> fresh;
  Check(defaults->GetVoxelResolution() == fresh->GetVoxelResolution() &&
      defaults->GetVoxelizationAxes() == fresh->GetVoxelizationAxes() &&
      defaults->GetRefinement() == fresh->GetRefinement() &&
      defaults->GetAOScale() == fresh->GetAOScale() &&
      defaults->GetNumberOfRays() == fresh->GetNumberOfRays() &&
      defaults->GetNumberOfSteps() == fresh->GetNumberOfSteps() &&
      defaults->GetFilterSize() == fresh->GetFilterSize() &&
      defaults->GetCellsPerRadius() == fresh->GetCellsPerRadius() &&
      defaults->GetCascadeResolution() == fresh->GetCascadeResolution() &&
      defaults->GetRefinementContrast() == fresh->GetRefinementContrast(),
    "BALANCED is the defaults");

  struct Expected
  {
    int Preset, Resolution, Axes;
    bool Refinement;
    int AOScale, Rays;
    double CellsPerRadius;
    int CascadeResolution;
    double Contrast;
  };
  for (const Expected& e :
    { Expected{ vtkHybridAmbientOcclusionPass::INTERACTIVE, 256, 1, false, 3, 8, 64, 512, 0 },
      Expected{ vtkHybridAmbientOcclusionPass::BALANCED, 0, 3, true, 3, 8, 64, 512, 0 },
      Expected{ vtkHybridAmbientOcclusionPass::QUALITY, 0, 3, true, 2, 16, 192, 1024, 0.05 } })
  {
    const std::string name = vtkHybridAmbientOcclusionPass::GetPresetAsString(e.Preset);
    hao->ApplyPreset(e.Preset);
    Check(hao->GetVoxelResolution() == e.Resolution && hao->GetVoxelizationAxes() == e.Axes &&
        hao->GetRefinement() == e.Refinement && hao->GetAOScale() == e.AOScale &&
        hao->GetNumberOfRays() == e.Rays && hao->GetCellsPerRadius() == e.CellsPerRadius &&
        hao->GetCascadeResolution() == e.CascadeResolution &&
        hao->GetRefinementContrast() == e.Contrast,
      name + ": its parameters");
    Check(hao->GetRadius() == 2.0 && hao->GetIntensity() == 2.0 && !hao->GetAccumulation(),
      name + ": the other parameters are kept");
    win->Render();
    // 45.8 pixels per unit on the ground at 400 pixels (TestHAOContactOcclusion): the ring
    // just beside the contact, and open ground in a corner.
    const double ring = MeanAO(hao, 254, 195, 262, 205);
    const double open = MeanAO(hao, 10, 10, 40, 40);
    std::printf("%s: grid %d x %d, refined %.2f %%, ring %.3f, open %.3f\n",
      name.c_str(),
      hao->GetEffectiveVoxelResolution(),
      hao->GetEffectiveNumberOfCascades(),
      100 * hao->GetRefinedFraction(),
      ring,
      open);
    // The exact A over the ring's box is 0.910 (TestHAOContactOcclusion); one voxelization
    // axis leaves gaps beside the sphere (about 0.04 lighter).
    Check(ring >= 0.0 && ring < open - 0.04 && open > 0.95,
      name + ": the contact is shadowed, open ground open");
    if (e.Preset != vtkHybridAmbientOcclusionPass::INTERACTIVE)
    {
      Check(std::abs(ring - 0.910) < 0.03, name + ": the ring within 0.03 of the exact 0.910");
    }
    if (e.Preset == vtkHybridAmbientOcclusionPass::INTERACTIVE)
    {
      Check(hao->GetEffectiveVoxelResolution() == 256 && hao->GetRefinedFraction() == 0.0,
        "interactive: a 256^3 grid, nothing refined");
    }
  }

  // An unknown preset: an error, nothing changed.
  vtkNew<ErrorCounter> errors;
  hao->AddObserver(vtkCommand::ErrorEvent, errors);
  hao->ApplyPreset(7);
  Check(errors->Count == 1 && hao->GetAOScale() == 2 && hao->GetNumberOfRays() == 16,
    "an unknown preset is an error and changes nothing");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
