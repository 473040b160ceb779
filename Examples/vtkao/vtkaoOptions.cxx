#include "vtkaoOptions.h"

#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkNew.h"

#include <iostream>

namespace vtkao
{
void ApplyPreset(PassSettings& s, const std::string& name)
{
  // The library's preset is the one source of its values: read them off a pass.
  const std::string choice =
    ParseChoice("--preset", "preset", name, { "interactive", "balanced", "quality" });
  vtkNew<vtkHybridAmbientOcclusionPass> hao;
  for (int p = vtkHybridAmbientOcclusionPass::INTERACTIVE;
       p <= vtkHybridAmbientOcclusionPass::QUALITY;
       ++p)
  {
    if (choice == vtkHybridAmbientOcclusionPass::GetPresetAsString(p))
    {
      hao->ApplyPreset(p);
    }
  }
  s.VoxelResolution = hao->GetVoxelResolution();
  s.VoxelAxes = hao->GetVoxelizationAxes();
  s.Refine = hao->GetRefinement();
  s.AOScale = hao->GetAOScale(); // HAO's: AOScaleGiven stays as it is, for AOV
  s.Rays = hao->GetNumberOfRays();
  s.Steps = hao->GetNumberOfSteps();
  s.FilterSize = hao->GetFilterSize();
  s.Cascades = hao->GetNumberOfCascades();
  s.CellErosion = hao->GetCellErosion();
  s.CellsPerRadius = hao->GetCellsPerRadius();
  s.CascadeResolution = hao->GetCascadeResolution();
  s.RefineContrast = hao->GetRefinementContrast();
}

void AddPassOptionParsers(OptionParsers& parsers, PassSettings& s)
{
  // --ao-scale and --filter-size: AOV has defaults of its own where they are not given.
  auto given = [](const char* option, int lo, int hi, int& value, bool& flag)
  {
    return [=, &value, &flag](const std::string& text)
    {
      value = ParseInt(option, text, lo, hi);
      flag = true;
    };
  };
  const OptionParsers shared = {
    { "--bias", [&s](const std::string& v) { s.Bias = ParseNumber("--bias", v, 0, 1e30); } },
    { "--falloff",
      [&s](const std::string& v) {
        s.BinaryFalloff = ParseChoice("--falloff", "falloff", v, { "wendland", "none" }) == "none";
      } },
    { "--ao-scale", given("--ao-scale", 1, 16, s.AOScale, s.AOScaleGiven) },
    { "--filter-size", given("--filter-size", 2, 64, s.FilterSize, s.FilterSizeGiven) },
    { "--region",
      [&s](const std::string& v) {
        s.Region = ParseChoice("--region", "region mode", v, { "scene", "view" });
      } },
    { "--aov-combine", [&s](const std::string& v) { s.AOVCombination = ParseAOVCombination(v); } },
    { "--preset", [&s](const std::string& v) { ApplyPreset(s, v); } },
    { "--cell-erosion",
      [&s](const std::string& v) { s.CellErosion = ParseNumber("--cell-erosion", v, 0, 0.25); } },
    { "--cells-per-radius",
      [&s](const std::string& v)
      { s.CellsPerRadius = ParseNumber("--cells-per-radius", v, 1, 1024); } },
    { "--refine-contrast",
      [&s](const std::string& v)
      { s.RefineContrast = ParseNumber("--refine-contrast", v, 0, 1); } },
  };
  parsers.insert(shared.begin(), shared.end());
  // The integer settings: the option, the field it sets, its range.
  struct IntegerOption
  {
    const char* Option;
    int PassSettings::*Value;
    int Low, High;
  };
  static const IntegerOption integers[] = {
    { "--rays", &PassSettings::Rays, 1, 1024 },
    { "--steps", &PassSettings::Steps, 1, 256 },
    { "--voxel-resolution", &PassSettings::VoxelResolution, 0, 4096 },
    { "--voxel-axes", &PassSettings::VoxelAxes, 1, 3 },
    { "--cascades", &PassSettings::Cascades, 0, 4 },
    { "--cascade-resolution", &PassSettings::CascadeResolution, 64, 1024 },
    { "--dense-limit", &PassSettings::DenseLimit, 64, 4096 },
    { "--refine-filter", &PassSettings::RefineFilter, 0, 8 },
    { "--refine-rays", &PassSettings::RefineRays, 0, 1024 },
  };
  for (const IntegerOption& option : integers)
  {
    int& value = s.*option.Value;
    parsers.emplace(option.Option,
      [&option, &value](const std::string& v)
      { value = ParseInt(option.Option, v, option.Low, option.High); });
  }
}

bool ParsePassFlag(const std::string& arg, PassSettings& s)
{
  bool* flag = arg == "--no-filter" ? &s.Filter
    : arg == "--no-refine"          ? &s.Refine
    : arg == "--refine-in-place"    ? &s.RefineList
                                    : nullptr;
  if (flag)
  {
    *flag = false;
  }
  return flag != nullptr;
}

void ApplySettings(const PassSettings& s, vtkHybridAmbientOcclusionPass* hao)
{
  if (s.Radius > 0)
  {
    hao->SetRadius(s.Radius);
  }
  hao->SetBias(s.Bias);
  hao->SetSpread(s.Spread);
  hao->SetIntensity(s.Intensity);
  hao->SetFalloff(s.BinaryFalloff ? vtkHybridAmbientOcclusionPass::BINARY
                                  : vtkHybridAmbientOcclusionPass::WENDLAND);
  hao->SetNumberOfRays(s.Rays);
  hao->SetNumberOfSteps(s.Steps);
  hao->SetVoxelResolution(s.VoxelResolution);
  hao->SetVoxelizationAxes(s.VoxelAxes);
  hao->SetNumberOfCascades(s.Cascades);
  if (s.CascadeResolution > 0)
  {
    hao->SetCascadeResolution(s.CascadeResolution);
  }
  hao->SetCellsPerRadius(s.CellsPerRadius);
  if (s.DenseLimit > 0)
  {
    hao->SetMaximumAutomaticResolution(s.DenseLimit);
  }
  hao->SetAOScale(s.AOScale);
  hao->SetFilterSize(s.FilterSize);
  hao->SetFilter(s.Filter);
  hao->SetRefinement(s.Refine);
  hao->SetRefinementRays(s.RefineRays);
  hao->SetRefinementList(s.RefineList);
  hao->SetRefinementFilterRadius(s.RefineFilter);
  hao->SetRefinementContrast(s.RefineContrast);
  hao->SetCellErosion(s.CellErosion);
  hao->SetAOOnly(s.AOOnly);
  hao->SetRegionMode(s.Region == "view" ? vtkHybridAmbientOcclusionPass::VIEW
                                        : vtkHybridAmbientOcclusionPass::SCENE);
}

void ApplySettings(const PassSettings& s, vtkAmbientOcclusionVolumesPass* aov)
{
  aov->SetRadius(s.Radius);
  aov->SetBias(s.Bias);
  aov->SetIntensity(s.Intensity);
  aov->SetFalloff(s.BinaryFalloff ? vtkAmbientOcclusionVolumesPass::BINARY
                                  : vtkAmbientOcclusionVolumesPass::WENDLAND);
  aov->SetAOOnly(s.AOOnly);
  // AOV's own defaults (AO scale 1, filter 6) unless the options give them.
  if (s.AOScaleGiven)
  {
    aov->SetAOScale(s.AOScale);
  }
  if (s.FilterSizeGiven)
  {
    aov->SetFilterSize(s.FilterSize);
  }
  if (s.AOVCombination >= 0)
  {
    aov->SetCombination(s.AOVCombination);
  }
}
}
