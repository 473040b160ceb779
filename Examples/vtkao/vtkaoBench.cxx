// vtkao bench: in one process, render a warm-up frame then N timed frames per case and report
// the median and spread of the frame time, the AO overhead (method minus no AO, same scene,
// size and mode), HAO's per-stage GPU times (timer queries) and the GPU memory its textures
// take. Multisampling is off, as in `vtkao render`. Documentation/benchmark.md.
//
// Modes: "orbit" turns the camera 2 degrees per frame around a static scene (HAO does not
// re-voxelize); "moving" moves the sphere each frame (HAO re-voxelizes every frame: the
// sphere alone over a kept base of the rest, or, hao-full-voxelization, the whole scene).
// Series: "main" (the built-in scene and its 1M-triangle refinement, every method, both
// modes; AOV on the built-in scene only), "triangles" (the scene refined to 10k ... 2M
// triangles), "resolution" (1M triangles at 640x480, 1280x720, 1920x1080), "parameters" (HAO
// with one setting changed at a time), "grids" (the voxelization cost and GPU memory of one
// grid of 256 to 1024 cells and of 4 cascades of 256 to 512, re-voxelizing every frame) and
// "aov" (Ambient Occlusion Volumes against the triangle count, 10k ... 1M, at a small and a
// large radius, at a quarter of the size: AOV's cost is
// fill, triangles x the screen area of their volumes, and on llvmpipe a 1280x720 frame of 1M
// triangles takes minutes). AOV cases run at most 3 timed frames.

#include "vtkaoBench.h"
#include "vtkaoContext.h"
#include "vtkaoOptions.h"
#include "vtkaoProgram.h"
#include "vtkaoScene.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCamera.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Method
{
  std::string Name;
  std::string Kind; // none, ssao, hao, aov
  int Kernel = 32;  // ssao
  // hao settings, 0 = the pass's default (AOScale also aov's)
  int Rays = 0, Steps = 0, VoxelResolution = 0, AOScale = 0;
  int Cascades = 0, CascadeResolution = 0; // hao: 0 = the pass's default
  double Radius = 0;    // aov, 0 = the pass's default (a tenth of the scene's diagonal)
  int Combination = -1; // aov, -1 = the pass's default (--aov-combine)
  int Preset = -1;      // hao, -1 = the defaults; else applied before the settings above
  bool FullVoxelization = false; // hao: IncrementalVoxelization off (every prop, every time)
};

// HAO's presets (vtkHybridAmbientOcclusionPass::ApplyPreset): "quality" (AO scale 2, 16 rays)
// and "interactive" (a 256^3 grid, one voxelization axis, no refinement); "hao" is the
// defaults, the balanced preset. Documentation/benchmark.md and quality.md, "Presets".
Method Preset(const char* name, int preset)
{
  Method m{ name, "hao" };
  m.Preset = preset;
  return m;
}
Method QualityPreset()
{
  return Preset("hao-quality", vtkHybridAmbientOcclusionPass::QUALITY);
}
Method InteractivePreset()
{
  return Preset("hao-interactive", vtkHybridAmbientOcclusionPass::INTERACTIVE);
}

struct Case
{
  std::string Series;
  std::string Scene;
  long long Triangles = 0; // requested; 0 = the built-in scene as it is
  std::string Mode;
  Method How;
  int Width = 1280, Height = 720;
  std::string Setting; // parameters series: "rays 32" etc.; aov series: "radius 0.25"
  int Frames = 0;      // timed frames, 0 = the run's --frames
};

struct Result
{
  Case What;
  long long Triangles = 0; // rendered
  std::vector<double> Frames;
  // GPU stage times per frame, StageNames order; hao has the first five, aov gbuffer, filter,
  // composite and volumes (StageApplies).
  std::vector<std::vector<double>> Stages;
  int Voxelizations = 0;
  double Overhead = 0;
  long long GPUMemory = 0; // hao, aov: bytes the pass owns on the GPU
  long long Volumes = 0;   // aov: volumes drawn (triangles after merging coplanar patches)
};

const int NumberOfStages = 6;
const char* StageNames[NumberOfStages] = { "voxelize",
  "gbuffer",
  "trace",
  "filter",
  "composite",
  "volumes" };

bool StageApplies(const std::string& kind, int stage)
{
  return kind == "hao" ? stage < 5 : (kind == "aov" && stage != 0 && stage != 2);
}

double Quantile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0;
  }
  std::sort(v.begin(), v.end());
  const double x = q * (v.size() - 1);
  const size_t i = static_cast<size_t>(std::floor(x));
  const size_t j = std::min(v.size() - 1, i + 1);
  return v[i] + (x - i) * (v[j] - v[i]);
}

double Median(const std::vector<double>& v)
{
  return Quantile(v, 0.5);
}

std::string ReadCPUName()
{
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown";
}

// "OpenGL renderer string: X" -> X, from vtkRenderWindow::ReportCapabilities().
std::string CapabilityLine(const std::string& report, const std::string& key)
{
  const auto at = report.find(key);
  if (at == std::string::npos)
  {
    return "unknown";
  }
  const auto begin = at + key.size();
  const auto end = report.find('\n', begin);
  std::string value = report.substr(begin, end == std::string::npos ? end : end - begin);
  value.erase(0, value.find_first_not_of(" "));
  return value;
}

vtkActor* FindSphere(vtkRenderer* renderer)
{
  // The built-in scene's sphere is its second actor; move that one.
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  vtkActor* first = actors->GetNextActor();
  vtkActor* second = actors->GetNextActor();
  return second ? second : first;
}

// The passes a case can install; InstallCasePass sets up the one of its method.
struct CasePasses
{
  vtkNew<vtkRenderStepsPass> Basic;
  vtkNew<vtkHybridAmbientOcclusionPass> HAO;
  vtkNew<vtkSSAOPass> SSAO;
  vtkNew<vtkAmbientOcclusionVolumesPass> AOV;
};

void InstallCasePass(vtkRenderer* renderer, const Method& method, CasePasses& p)
{
  if (method.Kind == "aov")
  {
    p.AOV->SetDelegatePass(p.Basic);
    p.AOV->AccumulationOff();
    p.AOV->SetRadius(method.Radius);
    if (method.AOScale)
    {
      p.AOV->SetAOScale(method.AOScale);
    }
    if (method.Combination >= 0)
    {
      p.AOV->SetCombination(method.Combination);
    }
    renderer->SetPass(p.AOV);
  }
  else if (method.Kind == "hao")
  {
    p.HAO->SetDelegatePass(p.Basic);
    p.HAO->AccumulationOff(); // every timed frame does a frame's full work
    if (method.Preset >= 0)
    {
      p.HAO->ApplyPreset(method.Preset);
    }
    // The settings the case gives (0: the pass's default).
    using Setter = void (vtkHybridAmbientOcclusionPass::*)(int);
    const std::pair<int Method::*, Setter> settings[] = {
      { &Method::Rays, &vtkHybridAmbientOcclusionPass::SetNumberOfRays },
      { &Method::Steps, &vtkHybridAmbientOcclusionPass::SetNumberOfSteps },
      { &Method::VoxelResolution, &vtkHybridAmbientOcclusionPass::SetVoxelResolution },
      { &Method::AOScale, &vtkHybridAmbientOcclusionPass::SetAOScale },
      { &Method::Cascades, &vtkHybridAmbientOcclusionPass::SetNumberOfCascades },
      { &Method::CascadeResolution, &vtkHybridAmbientOcclusionPass::SetCascadeResolution },
    };
    for (const auto& setting : settings)
    {
      if (method.*(setting.first))
      {
        (p.HAO.Get()->*(setting.second))(method.*(setting.first));
      }
    }
    p.HAO->SetIncrementalVoxelization(!method.FullVoxelization);
    renderer->SetPass(p.HAO);
  }
  else if (method.Kind == "ssao")
  {
    // As `vtkao render --method ssao`: radius a tenth of the scene's diagonal, blurred.
    p.SSAO->SetDelegatePass(p.Basic);
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) +
      (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
    p.SSAO->SetRadius(0.1 * diagonal);
    p.SSAO->SetBias(0.001 * diagonal);
    p.SSAO->SetKernelSize(method.Kernel);
    p.SSAO->BlurOn();
    renderer->SetPass(p.SSAO);
  }
}

// Between frames: the camera orbits (mode orbit) or the sphere moves (@p start: where it was).
void AdvanceFrame(const Case& c,
  vtkRenderer* renderer,
  vtkActor* mover,
  const double start[3],
  int frame)
{
  if (c.Mode == "orbit")
  {
    renderer->GetActiveCamera()->Azimuth(2.0);
    renderer->ResetCameraClippingRange();
  }
  else if (mover)
  {
    mover->SetPosition(start[0] + 0.05 * frame, start[1], start[2]);
  }
}

// The GPU times of the pass's stages in the last frame (none for SSAO and plain rendering).
void RecordStages(const Method& method, CasePasses& p, Result& r)
{
  if (method.Kind == "hao")
  {
    r.Stages.push_back({ p.HAO->GetVoxelizeTime(),
      p.HAO->GetGBufferTime(),
      p.HAO->GetTraceTime(),
      p.HAO->GetFilterTime(),
      p.HAO->GetCompositeTime(),
      0.0 });
  }
  else if (method.Kind == "aov")
  {
    r.Stages.push_back({ 0.0,
      p.AOV->GetGBufferTime(),
      0.0,
      p.AOV->GetFilterTime(),
      p.AOV->GetCompositeTime(),
      p.AOV->GetVolumeTime() });
  }
}

Result RunCase(const Case& c, vtkRenderWindow* window, int frames, std::string* glReport)
{
  // One window (one X connection, one context) for every case; a renderer per case.
  window->SetSize(c.Width, c.Height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkao::AddBuiltInScene(renderer, c.Triangles);
  window->AddRenderer(renderer);

  const Method& method = c.How;
  CasePasses passes;
  InstallCasePass(renderer, method, passes);
  Result r;
  r.What = c;
  r.Triangles = vtkao::CountTriangles(renderer);
  vtkActor* mover = FindSphere(renderer);
  double start[3] = { 0, 0, 0 };
  if (mover)
  {
    mover->GetPosition(start);
  }
  frames = c.Frames > 0 ? std::min(frames, c.Frames) : frames;
  for (int frame = 0; frame <= frames; ++frame) // frame 0: warm-up (shaders, first voxelization)
  {
    if (frame > 0)
    {
      AdvanceFrame(c, renderer, mover, start, frame);
    }
    const auto t0 = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const auto t1 = std::chrono::steady_clock::now();
    if (frame == 0 && glReport && glReport->empty())
    {
      *glReport = window->ReportCapabilities();
    }
    if (method.Kind == "hao")
    {
      passes.HAO->FinishTimings();
    }
    else if (method.Kind == "aov")
    {
      passes.AOV->FinishTimings();
    }
    if (frame == 0)
    {
      continue;
    }
    r.Frames.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    RecordStages(method, passes, r);
  }
  if (method.Kind == "hao")
  {
    r.Voxelizations = passes.HAO->GetVoxelizationCount() - 1;
    r.GPUMemory = passes.HAO->GetGraphicsMemorySize();
  }
  else if (method.Kind == "aov")
  {
    r.GPUMemory = passes.AOV->GetGraphicsMemorySize();
    r.Volumes = passes.AOV->GetNumberOfOccludingTriangles();
  }
  renderer->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  return r;
}

double StageMedian(const Result& r, int s)
{
  std::vector<double> v;
  for (const auto& f : r.Stages)
  {
    v.push_back(f[s]);
  }
  return Median(v);
}

// The command line of bench, apart from running it (the option fuzzer in Testing/Fuzz calls it).
struct BenchOptions
{
  bool Help = false;
  bool Quick = false;
  int Frames = 0;
  int Width = 1280, Height = 720;
  std::vector<std::string> Series = { "main",
    "triangles",
    "resolution",
    "parameters",
    "grids",
    "aov" };
  std::string Json, Md, Plots;
  int AOVCombination = -1;
};

BenchOptions ParseBenchOptions(int argc, char* argv[])
{
  BenchOptions o;
  bool sizeGiven = false;
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        throw std::invalid_argument(arg + ": missing value");
      }
      return argv[++i];
    };
    if (arg == "--quick")
    {
      o.Quick = true;
    }
    else if (arg == "--frames")
    {
      const std::string v = value();
      o.Frames = std::atoi(v.c_str());
      if (o.Frames < 1 || o.Frames > 10000)
      {
        throw std::invalid_argument("--frames: '" + v + "' is not in [1, 10000]");
      }
    }
    else if (arg == "--size")
    {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%dx%d", &o.Width, &o.Height) != 2 || o.Width < 1 ||
        o.Height < 1 || o.Width > 16384 || o.Height > 16384)
      {
        throw std::invalid_argument("--size: expected WxH, got '" + v + "'");
      }
      sizeGiven = true;
    }
    else if (arg == "--series")
    {
      const std::string v = value();
      o.Series.clear();
      std::stringstream list(v);
      std::string name;
      while (std::getline(list, name, ','))
      {
        if (name != "main" && name != "triangles" && name != "resolution" && name != "parameters" &&
          name != "grids" && name != "aov")
        {
          throw std::invalid_argument("--series: unknown series '" + name +
            "' (expected main, triangles, resolution, parameters, grids, aov)");
        }
        o.Series.push_back(name);
      }
      if (o.Series.empty())
      {
        throw std::invalid_argument("--series: empty list");
      }
    }
    else if (arg == "--output-json")
    {
      o.Json = value();
    }
    else if (arg == "--output-md")
    {
      o.Md = value();
    }
    else if (arg == "--aov-combine")
    {
      o.AOVCombination = vtkao::ParseAOVCombination(value());
    }
    else if (arg == "--plots")
    {
      o.Plots = value();
    }
    else if (arg == "--help" || arg == "-h")
    {
      o.Help = true;
      return o;
    }
    else
    {
      throw std::invalid_argument("bench: unknown argument '" + arg + "'");
    }
  }
  if (o.Quick && !sizeGiven) // --quick's small cases, at the size asked for if one is given
  {
    o.Width = std::min(o.Width, 160);
    o.Height = std::min(o.Height, 90);
  }
  if (o.Frames == 0)
  {
    o.Frames = o.Quick ? 2 : 7;
  }
  return o;
}

bool Has(const std::vector<std::string>& list, const std::string& item)
{
  return std::find(list.begin(), list.end(), item) != list.end();
}

// Every case of the requested series, in the order they run.
// The methods the series compare.
const Method PlainMethod{ "none", "none" };
const Method SSAO32{ "ssao32", "ssao", 32 };
const Method SSAO128{ "ssao128", "ssao", 128 };
const Method HAODefaults{ "hao", "hao" };
// The defaults, every voxelization of every prop (what "moving" cost before incremental
// voxelization, and what a scene whose props all change costs).
Method FullVoxelization()
{
  Method m{ "hao-full-voxelization", "hao" };
  m.FullVoxelization = true;
  return m;
}

// AOV with --aov-combine.
Method AOVMethod(const BenchOptions& o)
{
  Method aov{ "aov", "aov" };
  aov.Combination = o.AOVCombination;
  return aov;
}

void Add(std::vector<Case>& cases,
  const std::string& series,
  const std::string& scene,
  long long triangles,
  const std::string& mode,
  const Method& how,
  int w,
  int h,
  const std::string& setting = std::string())
{
  cases.push_back({ series, scene, triangles, mode, how, w, h, setting });
}

// The cases of the series main: the built-in scene (and one of 1M triangles), orbiting and
// moving, every method.
void PlanMain(const BenchOptions& o, std::vector<Case>& cases)
{
  std::vector<std::pair<std::string, long long>> scenes = { { "builtin", 0 } };
  if (!o.Quick)
  {
    scenes.push_back({ "builtin-1m", 1000000 });
  }
  for (const auto& scene : scenes)
  {
    for (const char* mode : { "orbit", "moving" })
    {
      for (const Method& m :
        { PlainMethod, SSAO32, SSAO128, HAODefaults, QualityPreset(), InteractivePreset() })
      {
        Add(cases, "main", scene.first, scene.second, mode, m, o.Width, o.Height);
      }
      if (std::string(mode) == "moving")
      {
        Add(cases, "main", scene.first, scene.second, mode, FullVoxelization(), o.Width, o.Height);
      }
      if (scene.second == 0)
      {
        Add(cases, "main", scene.first, scene.second, mode, AOVMethod(o), o.Width, o.Height);
        cases.back().Frames = 3;
      }
    }
  }
}

// The cases of the series triangles: the cost against the scene size.
void PlanTriangles(const BenchOptions& o, std::vector<Case>& cases)
{
  std::vector<std::pair<std::string, long long>> scenes = { { "builtin-10k", 10000 } };
  if (!o.Quick)
  {
    scenes.push_back({ "builtin-100k", 100000 });
    scenes.push_back({ "builtin-1m", 1000000 });
    scenes.push_back({ "builtin-2m", 2000000 });
  }
  for (const auto& scene : scenes)
  {
    for (const Method& m : { PlainMethod, SSAO32, HAODefaults })
    {
      Add(cases, "triangles", scene.first, scene.second, "orbit", m, o.Width, o.Height);
    }
    // Re-voxelization of the whole scene every frame, against one plain render of it.
    for (const Method& m : { PlainMethod, FullVoxelization() })
    {
      Add(cases, "triangles", scene.first, scene.second, "moving", m, o.Width, o.Height);
    }
  }
}

// The cases of the series resolution: the cost against the image size.
void PlanResolution(const BenchOptions& o, std::vector<Case>& cases)
{
  std::vector<std::pair<int, int>> sizes = { { 640, 480 }, { 1280, 720 }, { 1920, 1080 } };
  std::pair<std::string, long long> scene = { "builtin-1m", 1000000 };
  if (o.Quick)
  {
    sizes = { { 160, 90 }, { 320, 180 } };
    scene = { "builtin", 0 };
  }
  for (const auto& size : sizes)
  {
    for (const Method& m : { PlainMethod, SSAO32, HAODefaults })
    {
      Add(cases, "resolution", scene.first, scene.second, "orbit", m, size.first, size.second);
    }
  }
}

// The cases of the series parameters: HAO's settings one at a time.
void PlanParameters(const BenchOptions& o, std::vector<Case>& cases)
{
  Add(cases, "parameters", "builtin", 0, "orbit", PlainMethod, o.Width, o.Height, "none");
  struct Sweep
  {
    const char* Name;
    std::vector<int> Values;
    int Method::*Field;
  };
  const std::vector<Sweep> sweeps = {
    { "rays",
      o.Quick ? std::vector<int>{ 8, 16 } : std::vector<int>{ 8, 16, 32, 64 },
      &Method::Rays },
    { "steps", o.Quick ? std::vector<int>{ 4 } : std::vector<int>{ 4, 8, 16 }, &Method::Steps },
    { "voxel-resolution",
      o.Quick ? std::vector<int>{ 64 } : std::vector<int>{ 64, 128, 256, 512 },
      &Method::VoxelResolution },
    { "ao-scale", o.Quick ? std::vector<int>{ 1 } : std::vector<int>{ 1, 2, 4 }, &Method::AOScale },
  };
  for (const Sweep& sweep : sweeps)
  {
    for (int v : sweep.Values)
    {
      Method m = HAODefaults;
      m.*(sweep.Field) = v;
      Add(cases,
        "parameters",
        "builtin",
        0,
        "orbit",
        m,
        o.Width,
        o.Height,
        std::string(sweep.Name) + " " + std::to_string(v));
    }
  }
}

// The cases of the series grids: the voxelization cost and GPU memory of each grid size, one
// grid of 256 to 1024 cells and 4 cascades of 256 to 512, the whole scene re-voxelized every
// frame (the moving sphere, incremental voxelization off).
void PlanGrids(const BenchOptions& o, std::vector<Case>& cases)
{
  auto add = [&](const Method& m, const std::string& setting)
  { Add(cases, "grids", "builtin", 0, "moving", m, o.Width, o.Height, setting); };
  add(PlainMethod, std::string());
  for (int n : o.Quick ? std::vector<int>{ 256 } : std::vector<int>{ 256, 512, 1024 })
  {
    Method m = FullVoxelization();
    m.VoxelResolution = n;
    m.Cascades = 1;
    add(m, "1 grid " + std::to_string(n));
  }
  for (int n : o.Quick ? std::vector<int>{ 256 } : std::vector<int>{ 256, 384, 512 })
  {
    Method m = FullVoxelization();
    m.Cascades = 4;
    m.CascadeResolution = n;
    add(m, "4 cascades " + std::to_string(n));
  }
}

// The cases of the series aov: Ambient Occlusion Volumes against the scene size and its radius.
void PlanAOV(const BenchOptions& o, std::vector<Case>& cases)
{
  std::vector<std::pair<std::string, long long>> scenes = { { "builtin-10k", 10000 } };
  if (!o.Quick)
  {
    scenes.push_back({ "builtin-100k", 100000 });
    scenes.push_back({ "builtin-1m", 1000000 });
  }
  const int w = std::max(1, o.Width / 4), h = std::max(1, o.Height / 4);
  for (const auto& scene : scenes)
  {
    Add(cases, "aov", scene.first, scene.second, "orbit", PlainMethod, w, h);
    cases.back().Frames = 3;
    for (double radius : { 0.25, 1.0 })
    {
      Method m = AOVMethod(o);
      m.Radius = radius;
      std::ostringstream setting;
      setting << "radius " << radius;
      Add(cases, "aov", scene.first, scene.second, "orbit", m, w, h, setting.str());
      cases.back().Frames = 3;
    }
  }
}

std::vector<Case> PlanCases(const BenchOptions& o)
{
  using Planner = void (*)(const BenchOptions&, std::vector<Case>&);
  const std::pair<const char*, Planner> series[] = { { "main", &PlanMain },
    { "triangles", &PlanTriangles },
    { "resolution", &PlanResolution },
    { "parameters", &PlanParameters },
    { "grids", &PlanGrids },
    { "aov", &PlanAOV } };
  std::vector<Case> cases;
  for (const auto& planner : series)
  {
    if (Has(o.Series, planner.first))
    {
      planner.second(o, cases);
    }
  }
  return cases;
}

const Result* Find(const std::vector<Result>& results,
  const std::string& series,
  const std::string& scene,
  const std::string& mode,
  const std::string& method,
  int w = 0,
  int h = 0)
{
  for (const Result& r : results)
  {
    if (r.What.Series == series && r.What.Scene == scene && r.What.Mode == mode &&
      r.What.How.Name == method && (w == 0 || (r.What.Width == w && r.What.Height == h)))
    {
      return &r;
    }
  }
  return nullptr;
}

// The no-AO case a result's overhead is measured against: same series, scene, mode and size.
const Result* Baseline(const std::vector<Result>& results, const Result& r)
{
  return Find(
    results, r.What.Series, r.What.Scene, r.What.Mode, "none", r.What.Width, r.What.Height);
}

std::string Fixed(double v, int digits = 1)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

double MiB(long long bytes)
{
  return bytes / (1024.0 * 1024.0);
}

// The targets, read off the results of this run (ratios within one run).
void WriteTargets(std::ostream& out, const std::vector<Result>& results, int w, int h)
{
  out << "\n| target | measured | met |\n|---|---|---|\n";
  for (const char* scene : { "builtin", "builtin-1m" })
  {
    const Result* hao = Find(results, "main", scene, "orbit", "hao");
    const Result* ssao = Find(results, "main", scene, "orbit", "ssao32");
    const Result* quality = Find(results, "main", scene, "orbit", "hao-quality");
    const Result* ssao128 = Find(results, "main", scene, "orbit", "ssao128");
    const Result* fast = Find(results, "main", scene, "orbit", "hao-interactive");
    for (const Result* r : { hao, fast })
    {
      if (r && ssao)
      {
        out << "| HAO " << (r == hao ? "(defaults)" : "interactive preset")
            << " overhead <= vtkSSAOPass (kernel 32) overhead, " << scene << ", " << w << "x" << h
            << " | " << Fixed(r->Overhead) << " vs " << Fixed(ssao->Overhead) << " ms ("
            << Fixed(r->Overhead / std::max(1e-9, ssao->Overhead), 2) << "x) | "
            << (r->Overhead <= ssao->Overhead ? "yes" : "no") << " |\n";
      }
    }
    if (quality && ssao128)
    {
      out << "| HAO quality preset overhead <= vtkSSAOPass (kernel 128), " << scene << " | "
          << Fixed(quality->Overhead) << " vs " << Fixed(ssao128->Overhead) << " ms ("
          << Fixed(quality->Overhead / std::max(1e-9, ssao128->Overhead), 2) << "x) | "
          << (quality->Overhead <= ssao128->Overhead ? "yes" : "no") << " |\n";
    }
  }
  const Result* small = Find(results, "triangles", "builtin-10k", "orbit", "hao");
  const Result* large = Find(results, "triangles", "builtin-2m", "orbit", "hao");
  if (small && large)
  {
    const double a = StageMedian(*small, 2) + StageMedian(*small, 3);
    const double b = StageMedian(*large, 2) + StageMedian(*large, 3);
    out << "| trace + filter flat in triangles: 2M / 10k <= 1.15 (orbit) | " << Fixed(b) << " / "
        << Fixed(a) << " ms = " << Fixed(b / std::max(1e-9, a), 2) << " | "
        << (b <= 1.15 * a ? "yes" : "no") << " |\n";
  }
  const Result* moving =
    Find(results, "triangles", "builtin-1m", "moving", "hao-full-voxelization");
  const Result* plain = Find(results, "triangles", "builtin-1m", "moving", "none");
  if (moving && plain)
  {
    const double v = StageMedian(*moving, 0);
    const double p = Median(plain->Frames);
    out << "| re-voxelization of 1M triangles <= one plain render | " << Fixed(v) << " vs "
        << Fixed(p) << " ms | " << (v <= p ? "yes" : "no") << " |\n";
  }
  // AOV is fill bound (McGuire: "largely independent of the triangle count for a fixed covered
  // area"); what the triangle count does to it here is measured, not a target.
  for (const char* radius : { "radius 0.25", "radius 1" })
  {
    const Result* a = nullptr;
    const Result* b = nullptr;
    for (const Result& r : results)
    {
      if (r.What.Series == "aov" && r.What.Setting == radius)
      {
        a = r.What.Scene == "builtin-10k" ? &r : a;
        b = r.What.Scene == "builtin-1m" ? &r : b;
      }
    }
    if (a && b)
    {
      const double va = StageMedian(*a, 5), vb = StageMedian(*b, 5);
      out << "| AOV volume stage, 1M / 10k triangles, " << radius << ", " << a->What.Width << "x"
          << a->What.Height << " (measured, no bound) | " << Fixed(vb) << " / " << Fixed(va)
          << " ms = " << Fixed(vb / std::max(1e-9, va), 1) << "x for "
          << Fixed(static_cast<double>(b->Triangles) / std::max<long long>(1, a->Triangles), 0)
          << "x the triangles | - |\n";
    }
  }
  int orbitVoxelizations = 0, orbitCases = 0;
  for (const Result& r : results)
  {
    if (r.What.How.Kind == "hao" && r.What.Mode == "orbit")
    {
      orbitVoxelizations += r.Voxelizations;
      ++orbitCases;
    }
  }
  if (orbitCases)
  {
    out << "| no re-voxelization when only the camera moves | " << orbitVoxelizations
        << " voxelizations in " << orbitCases << " HAO orbit cases | "
        << (orbitVoxelizations == 0 ? "yes" : "no") << " |\n";
  }
}

void WriteMarkdown(const std::string& path,
  const std::vector<Result>& results,
  const std::string& header,
  int w,
  int h)
{
  std::ofstream out(path);
  out << std::fixed << std::setprecision(1);
  out << header << "\n";
  const char* series[6] = { "main", "triangles", "resolution", "parameters", "grids", "aov" };
  for (const char* name : series)
  {
    bool any = false;
    for (const Result& r : results)
    {
      any = any || r.What.Series == name;
    }
    if (!any)
    {
      continue;
    }
    out << "\n### Series: " << name << "\n\n";
    out << "| scene | triangles | size | mode | method | setting | frame | spread | AO overhead "
           "| voxelize | gbuffer | trace | filter | composite | volumes | voxelizations | GPU MiB "
           "| volumes drawn |\n";
    out << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Result& r : results)
    {
      if (r.What.Series != name)
      {
        continue;
      }
      out << "| " << r.What.Scene << " | " << r.Triangles << " | " << r.What.Width << "x"
          << r.What.Height << " | " << r.What.Mode << " | " << r.What.How.Name << " | "
          << (r.What.Setting.empty() ? "-" : r.What.Setting) << " | " << Median(r.Frames) << " | ["
          << Quantile(r.Frames, 0.25) << ", " << Quantile(r.Frames, 0.75) << "] | " << r.Overhead;
      for (int s = 0; s < NumberOfStages; ++s)
      {
        out << " | ";
        if (r.Stages.empty() || !StageApplies(r.What.How.Kind, s))
        {
          out << "-";
        }
        else
        {
          out << StageMedian(r, s);
        }
      }
      out << " | " << r.Voxelizations << " | ";
      if (r.What.How.Kind == "hao" || r.What.How.Kind == "aov")
      {
        out << MiB(r.GPUMemory);
      }
      else
      {
        out << "-";
      }
      out << " | ";
      if (r.What.How.Kind == "aov")
      {
        out << r.Volumes;
      }
      else
      {
        out << "-";
      }
      out << " |\n";
    }
  }
  out << "\n### Against the targets (ratios from this run)\n";
  WriteTargets(out, results, w, h);
  if (!out.good())
  {
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

void WriteJson(const std::string& path,
  const std::vector<Result>& results,
  const std::string& prefix)
{
  std::ofstream out(path);
  out << std::setprecision(6);
  out << prefix << ",\n  \"cases\": [\n";
  for (size_t i = 0; i < results.size(); ++i)
  {
    const Result& r = results[i];
    out << "    {\"series\": " << vtkao::JsonString(r.What.Series)
        << ", \"scene\": " << vtkao::JsonString(r.What.Scene) << ", \"triangles\": " << r.Triangles
        << ", \"width\": " << r.What.Width << ", \"height\": " << r.What.Height
        << ", \"mode\": " << vtkao::JsonString(r.What.Mode)
        << ", \"method\": " << vtkao::JsonString(r.What.How.Name)
        << ", \"setting\": " << vtkao::JsonString(r.What.Setting)
        << ",\n     \"median_ms\": " << Median(r.Frames)
        << ", \"p25_ms\": " << Quantile(r.Frames, 0.25)
        << ", \"p75_ms\": " << Quantile(r.Frames, 0.75) << ", \"min_ms\": " << Quantile(r.Frames, 0)
        << ", \"max_ms\": " << Quantile(r.Frames, 1) << ", \"overhead_ms\": " << r.Overhead
        << ",\n     \"frames_ms\": [";
    for (size_t f = 0; f < r.Frames.size(); ++f)
    {
      out << (f ? ", " : "") << r.Frames[f];
    }
    out << "],\n     \"voxelizations\": " << r.Voxelizations
        << ", \"gpu_memory_bytes\": " << r.GPUMemory << ", \"volumes\": " << r.Volumes
        << ", \"stages_ms\": ";
    if (r.Stages.empty())
    {
      out << "null";
    }
    else
    {
      out << "{";
      const char* separator = "";
      for (int s = 0; s < NumberOfStages; ++s)
      {
        if (StageApplies(r.What.How.Kind, s))
        {
          out << separator << "\"" << StageNames[s] << "\": " << StageMedian(r, s);
          separator = ", ";
        }
      }
      out << "}";
    }
    out << "}" << (i + 1 < results.size() ? "," : "") << "\n";
  }
  out << "  ]\n}\n";
  if (!out.good())
  {
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

// The data files of the plots in one directory, and how many rows each got: a series that was
// not run plots nothing.
class PlotFiles
{
public:
  explicit PlotFiles(const std::string& dir)
    : Dir(dir)
  {
  }

  std::ofstream Open(const std::string& name)
  {
    this->Rows[name] = 0;
    std::ofstream f(this->Dir + "/" + name);
    if (!f)
    {
      throw std::runtime_error("cannot write '" + this->Dir + "/" + name + "'");
    }
    return f;
  }

  void AddRow(const std::string& name) { ++this->Rows[name]; }

  // A panel's plot command, or an empty panel when its series was not run (gnuplot fails on
  // an empty data file).
  std::string Plot(const std::string& dat, const std::string& command)
  {
    return this->Rows[dat] > 0 ? command
                               : "set label 1 'series not run' at graph 0.4, 0.5\n"
                                 "set xrange [0:1]\nset yrange [0:1]\nplot -1 notitle\n"
                                 "unset label 1\nset autoscale\n";
  }

private:
  std::string Dir;
  std::map<std::string, int> Rows;
};

// triangles.dat: the frame time against the scene size (orbit).
void WriteTrianglesData(PlotFiles& files, const std::vector<Result>& results)
{
  std::ofstream f = files.Open("triangles.dat");
  f << "# triangles none ssao32 hao hao_trace_plus_filter (ms, orbit)\n";
  for (const Result& r : results)
  {
    if (r.What.Series == "triangles" && r.What.Mode == "orbit" && r.What.How.Name == "hao")
    {
      const Result* n = Find(results, "triangles", r.What.Scene, "orbit", "none");
      const Result* s = Find(results, "triangles", r.What.Scene, "orbit", "ssao32");
      files.AddRow("triangles.dat");
      f << r.Triangles << " " << (n ? Median(n->Frames) : 0) << " " << (s ? Median(s->Frames) : 0)
        << " " << Median(r.Frames) << " " << StageMedian(r, 2) + StageMedian(r, 3) << "\n";
    }
  }
}

// resolution.dat: the AO overhead against the image size.
void WriteResolutionData(PlotFiles& files, const std::vector<Result>& results)
{
  std::ofstream f = files.Open("resolution.dat");
  f << "# megapixels none_overhead ssao32_overhead hao_overhead hao_gpu_mib\n";
  for (const Result& r : results)
  {
    if (r.What.Series == "resolution" && r.What.How.Name == "hao")
    {
      const Result* s =
        Find(results, "resolution", r.What.Scene, "orbit", "ssao32", r.What.Width, r.What.Height);
      files.AddRow("resolution.dat");
      f << r.What.Width * r.What.Height / 1e6 << " 0 " << (s ? s->Overhead : 0) << " " << r.Overhead
        << " " << MiB(r.GPUMemory) << "\n";
    }
  }
}

// parameters-<setting>.dat: HAO's stages against each setting of the parameters series.
void WriteParametersData(PlotFiles& files, const std::vector<Result>& results)
{
  for (const char* sweep : { "rays", "steps", "voxel-resolution", "ao-scale" })
  {
    std::ofstream f = files.Open(std::string("parameters-") + sweep + ".dat");
    f << "# value voxelize gbuffer trace filter composite overhead gpu_mib\n";
    for (const Result& r : results)
    {
      if (r.What.Series == "parameters" && r.What.Setting.rfind(sweep, 0) == 0)
      {
        files.AddRow(std::string("parameters-") + sweep + ".dat");
        f << r.What.Setting.substr(std::strlen(sweep) + 1);
        for (int s = 0; s < 5; ++s)
        {
          f << " " << StageMedian(r, s);
        }
        f << " " << r.Overhead << " " << MiB(r.GPUMemory) << "\n";
      }
    }
  }
}

// aov.dat: AOV's volume stage against the scene size, for two radii.
void WriteAOVData(PlotFiles& files, const std::vector<Result>& results)
{
  std::ofstream f = files.Open("aov.dat");
  f << "# triangles volumes_radius_0.25 volumes_radius_1 (ms, AOV volume stage) volumes_drawn\n";
  for (const Result& r : results)
  {
    if (r.What.Series == "aov" && r.What.Setting == "radius 0.25")
    {
      const Result* large = nullptr;
      for (const Result& q : results)
      {
        large =
          q.What.Series == "aov" && q.What.Scene == r.What.Scene && q.What.Setting == "radius 1"
          ? &q
          : large;
      }
      files.AddRow("aov.dat");
      f << r.Triangles << " " << StageMedian(r, 5) << " " << (large ? StageMedian(*large, 5) : 0)
        << " " << r.Volumes << "\n";
    }
  }
}

// bench.gp: the panels of bench.png.
void WriteGnuplotScript(PlotFiles& files, const std::string& title)
{
  std::ofstream f = files.Open("bench.gp");
  f << "set terminal pngcairo size 1500,1300 font ',10'\nset output 'bench.png'\n"
    << "set multiplot layout 3,3 title \"" << title << "\"\nset key top left\nset grid\n"
    << "set title 'Frame time vs triangles (orbit)'\nset logscale x\n"
    << "set xlabel 'triangles'\nset ylabel 'ms'\n"
    << files.Plot("triangles.dat",
         "plot 'triangles.dat' u 1:2 w lp t 'none', '' u 1:3 w lp t 'vtkSSAOPass 32', "
         "'' u 1:4 w lp t 'HAO', '' u 1:5 w lp t 'HAO trace + filter'\n")
    << "unset logscale x\nset title 'AO overhead vs resolution (1M triangles)'\n"
    << "set xlabel 'megapixels'\n"
    << files.Plot("resolution.dat",
         "plot 'resolution.dat' u 1:3 w lp t 'vtkSSAOPass 32', '' u 1:4 w lp t 'HAO'\n");
  const char* sweeps[4][2] = { { "rays", "rays per texel" },
    { "steps", "steps per ray" },
    { "voxel-resolution", "voxel resolution" },
    { "ao-scale", "AO scale" } };
  for (const auto& sw : sweeps)
  {
    f << "set title 'HAO stages vs " << sw[1] << " (built-in scene)'\nset xlabel '" << sw[1]
      << "'\nset style data histograms\nset style histogram rowstacked\n"
      << "set style fill solid 0.8 border -1\nset boxwidth 0.6\n"
      << files.Plot(std::string("parameters-") + sw[0] + ".dat",
           std::string("plot 'parameters-") + sw[0] +
             ".dat' u 3:xtic(1) t 'gbuffer', '' u 4 t 'trace', '' u 5 t 'filter', "
             "'' u 6 t 'composite', '' u 2 t 'voxelize'\n")
      << "set style data linespoints\n";
  }
  f << "set style data linespoints\nset title 'AOV volume stage vs triangles'\n"
    << "set logscale xy\nset xlabel 'triangles'\nset ylabel 'ms'\n"
    << files.Plot("aov.dat", "plot 'aov.dat' u 1:2 w lp t 'R = 0.25', '' u 1:3 w lp t 'R = 1'\n")
    << "unset logscale xy\nunset multiplot\n";
}

// Data files and a gnuplot script in @p dir; the PNG (bench.png) if gnuplot is installed.
void WritePlots(const std::string& dir,
  const std::vector<Result>& results,
  const std::string& title)
{
  PlotFiles files(dir);
  WriteTrianglesData(files, results);
  WriteResolutionData(files, results);
  WriteParametersData(files, results);
  WriteAOVData(files, results);
  WriteGnuplotScript(files, title);
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0)
  {
    const std::string command = "cd '" + dir + "' && gnuplot bench.gp";
    if (std::system(command.c_str()) != 0)
    {
      throw std::runtime_error("gnuplot failed on '" + dir + "/bench.gp'");
    }
  }
  else
  {
    std::cout << "gnuplot not found: wrote the data and " << dir
              << "/bench.gp, no PNG (apt-get install gnuplot-nox)" << std::endl;
  }
}
}

namespace vtkao
{
int Bench(int argc, char* argv[])
{
  const BenchOptions options = ParseBenchOptions(argc, argv);
  if (options.Help)
  {
    std::cout << "usage: vtkao bench [--quick] [--frames N] [--size WxH]\n"
                 "                   [--series main,triangles,resolution,parameters,grids,aov]\n"
                 "                   [--output-json F] [--output-md F] [--plots DIR]\n"
                 "                   [--aov-combine add|multiply]\n";
    return 0;
  }
  if (!options.Plots.empty())
  {
    // Fail before hours of rendering, not after.
    std::ofstream probe(options.Plots + "/.vtkao-bench-probe");
    if (!probe)
    {
      throw std::runtime_error("--plots: cannot write into '" + options.Plots + "'");
    }
    probe.close();
    std::remove((options.Plots + "/.vtkao-bench-probe").c_str());
  }
  const std::vector<Case> cases = PlanCases(options);

  vtkao::RequireRenderingContext();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);

  std::string glReport;
  std::vector<Result> results;
  for (const Case& c : cases)
  {
    Result r = RunCase(c, window, options.Frames, &glReport);
    const Result* base = Baseline(results, r);
    r.Overhead = base ? Median(r.Frames) - Median(base->Frames) : 0.0;
    std::cout << c.Series << ": " << c.Scene << " (" << r.Triangles << " triangles) " << c.Width
              << "x" << c.Height << " " << c.Mode << " " << c.How.Name
              << (c.Setting.empty() ? "" : " [" + c.Setting + "]") << ": median "
              << Median(r.Frames) << " ms, overhead " << r.Overhead << " ms";
    if (c.How.Kind == "hao" || c.How.Kind == "aov")
    {
      std::cout << "; stages";
      for (int s = 0; s < NumberOfStages; ++s)
      {
        if (StageApplies(c.How.Kind, s))
        {
          std::cout << " " << StageNames[s] << " " << StageMedian(r, s);
        }
      }
      std::cout << "; GPU " << MiB(r.GPUMemory) << " MiB";
      if (c.How.Kind == "aov")
      {
        std::cout << "; " << r.Volumes << " volumes";
      }
    }
    std::cout << std::endl;
    results.push_back(r);
  }

  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof(date), "%Y-%m-%d", std::localtime(&now));
  const std::string cpu = ReadCPUName();
  const std::string renderer = CapabilityLine(glReport, "OpenGL renderer string:");
  const std::string version = CapabilityLine(glReport, "OpenGL version string:");
  const std::string vendor = CapabilityLine(glReport, "OpenGL vendor string:");
  const int frames = options.Frames;
  const int width = options.Width, height = options.Height;

  if (!options.Json.empty())
  {
    std::ostringstream prefix;
    prefix << "{\n  \"date\": " << vtkao::JsonString(date)
           << ",\n  \"cpu\": " << vtkao::JsonString(cpu)
           << ",\n  \"gl_vendor\": " << vtkao::JsonString(vendor)
           << ",\n  \"gl_renderer\": " << vtkao::JsonString(renderer)
           << ",\n  \"gl_version\": " << vtkao::JsonString(version) << ",\n  \"width\": " << width
           << ",\n  \"height\": " << height << ",\n  \"multisamples\": 0,\n  \"warmup_frames\": 1"
           << ",\n  \"frames\": " << frames;
    WriteJson(options.Json, results, prefix.str());
  }
  std::ostringstream header;
  header << "Date " << date << "; CPU " << cpu << "; GL " << renderer << " (" << version
         << "); no multisampling; " << frames
         << " frames after 1 warm-up (AOV cases: at most 3); times in ms (median, [p25, p75]); "
            "GPU MiB: what the pass owns on the GPU (HAO: its stages' textures; AOV: its "
            "textures and triangle buffer).";
  if (!options.Md.empty())
  {
    WriteMarkdown(options.Md, results, header.str(), width, height);
  }
  if (!options.Plots.empty())
  {
    WritePlots(
      options.Plots, results, std::string("vtkao bench, ") + date + ", " + cpu + ", " + renderer);
  }
  return 0;
}
}
