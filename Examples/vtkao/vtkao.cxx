// vtkao: the project's command-line program (shared/design/architecture.md).
//   vtkao render [INPUT ...] [options]   render one image off screen
//   vtkao bake INPUT --output OUT.vtp    bake A per vertex (with Embree)
// Bad input prints one line on stderr, exits non-zero and leaves no output file.

#include "vtkaoBench.h"
#include "vtkaoCompare.h"
#include "vtkaoContext.h"
#include "vtkaoImageIO.h"
#include "vtkaoOptions.h"
#include "vtkaoScene.h"
#include "vtkaoView.h"
#ifdef VTKAO_HAS_REFERENCE
#include "vtkaoBakeHemisphere.h"
#include "vtkaoQuality.h"
#include "vtkaoReference.h"
#endif

#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using vtkao::ParseChoice;
using vtkao::ParseInt;
using vtkao::ParseNumber;
using vtkao::UsageError;

const char* Usage =
  "usage: vtkao render [INPUT ...] [options]\n"
  "  INPUT: .vtp .vtu .vtk .stl .ply .obj .glb .gltf (several allowed); none = the built-in scene\n"
  "  --method none|ssao|hao|aov|reference|baked   (default hao; reference and baked need\n"
  "                               Embree; reference always writes A)\n"
  "  --ao-only                    write A itself (hao, aov, baked, reference)\n"
  "  --size WxH                   (default 1280x720)\n"
  "  --camera-position X,Y,Z  --camera-focal-point X,Y,Z  --camera-view-up X,Y,Z\n"
  "  --camera-view-angle DEG\n"
  "  --radius R  --falloff wendland|none  --bias B  --spread S\n"
  "  --preset interactive|balanced|quality   hao's measured speed/fidelity sets (default\n"
  "                               balanced = the pass's defaults; later options override it)\n"
  "  --ao-scale K  --filter-size M  (hao: default 3 and 16; aov: default 1 = every pixel, and 6)\n"
  "  --rays N  --steps N  --voxel-resolution N  --voxel-axes 1|3  --no-filter\n"
  "  --no-refine  --refine-rays N (0: automatic)  --refine-filter N (pixels, default 2, 0 off)\n"
  "  --cascades 0-4 (0: automatic, cascades past --dense-limit N cells, default 1024)\n"
  "  --cascade-resolution N (cells per cascade, default 512)\n"
  "  --cells-per-radius C        the automatic grid's cells per radius (default 64; quality 192)\n"
  "  --cell-erosion E             cells the grid's exposed faces are moved in, 0 to 0.25\n"
  "                               (default 0.25: thin walls; 0 off)\n"
  "  --refine-contrast C          A contrast within a map texel that is refined, 0 to 1\n"
  "                               (default 0: 0.15 Wendland, 0.3 binary falloff)\n"
  "  --refine-in-place            shade the refined pixels in a full-screen pass, not as a\n"
  "                               list (the same image; for comparing their cost)\n"
  "  --intensity I  --region scene|view  --ssao-kernel N  --aov-combine add|multiply\n"
  "  --scene-triangles N          refine the built-in scene to about N triangles\n"
  "  --frames N  --orbit DEG      render N frames, orbiting the camera DEG per frame\n"
  "  --accumulate N               then render the last view until N frames are accumulated\n"
  "                               and write that converged still (default: off); hao averages\n"
  "                               jittered frames, aov at --ao-scale s evaluates another pixel\n"
  "                               of each s x s block per frame (exact after s^2)\n"
  "  --timings FILE.json          per-frame and per-stage times (ms)\n"
  "  --samples N                  rays per pixel (reference) or per vertex (baked); default 256\n"
  "  --output FILE                .png or .exr\n"
  "  --compare M1,M2,...          the methods (none ssao hao aov reference) side by side in one\n"
  "                               labelled .png, same camera and options (instead of --method)\n"
  "usage: vtkao view [INPUT ...] [options]   interactive window (vtkao view --help)\n"
  "usage: vtkao gl-info    the OpenGL window class, vendor, renderer and version it gets\n"
  "usage: vtkao bake INPUT --output OUT.vtp [--samples N] [--radius R] [--bias B] [--spread S]\n"
  "                  [--falloff wendland|none] [--method raycast|sattler|hemisphere]\n"
  "                  [--resolution N]\n"
  "  --method sattler: GPU visibility from --samples directions (R = infinity, binary falloff;\n"
  "                    --radius, --falloff and --spread do not apply)\n"
  "  --method hemisphere: GPU hemicube per vertex, N x N front face (--resolution, default 64);\n"
  "                    binary falloff, --radius R (default infinity), --spread; --samples and\n"
  "                    --falloff do not apply\n"
  "  `vtkao render OUT.vtp --method baked` shows a baked file's AmbientOcclusion array\n"
  "usage: vtkao quality [--quick] [--output-dir DIR] [options]  (vtkao quality --help)\n";

struct Options
{
  std::vector<std::string> Inputs;
  std::string Method = "hao";
  int Width = 1280, Height = 720;
  bool HasPosition = false, HasFocal = false, HasUp = false, HasAngle = false;
  double Position[3], Focal[3], Up[3], Angle = 30;
  vtkao::PassSettings Pass; // HAO's and AOV's (and the reference's radius, bias, spread, falloff)
  long long SceneTriangles = 0;
  int SSAOKernel = 32;
  int Samples = 256;
  int Frames = 1;
  int Accumulate = 0; // --accumulate; 0: the pass's accumulation off
  double Orbit = 0;
  std::string Timings;
  std::string Output;
};

void ParseVector(const std::string& option, const std::string& text, double v[3])
{
  std::stringstream in(text);
  std::string item;
  int n = 0;
  while (std::getline(in, item, ','))
  {
    if (n == 3)
    {
      throw UsageError(option + ": expected X,Y,Z, got '" + text + "'");
    }
    v[n++] = ParseNumber(option, item, -1e30, 1e30);
  }
  if (n != 3)
  {
    throw UsageError(option + ": expected X,Y,Z, got '" + text + "'");
  }
}

// The options of `vtkao render` that take a value: one parser each, writing into @p o.
vtkao::OptionParsers RenderOptionParsers(Options& o)
{
  // --camera-position and the like: X,Y,Z into @p v, and @p given set.
  auto vector = [](const char* option, double* v, bool& given)
  {
    return [option, v, &given](const std::string& text)
    {
      ParseVector(option, text, v);
      given = true;
    };
  };
  vtkao::OptionParsers parsers = {
    { "--method",
      [&](const std::string& v)
      {
        o.Method = ParseChoice("--method",
          "method",
          v,
#ifdef VTKAO_HAS_REFERENCE
          { "none", "ssao", "hao", "aov", "reference", "baked" });
#else
          { "none", "ssao", "hao", "aov" });
#endif
      } },
    { "--size", [&](const std::string& v) { vtkao::ParseSize(v, 1, 16384, o.Width, o.Height); } },
    { "--camera-position", vector("--camera-position", o.Position, o.HasPosition) },
    { "--camera-focal-point", vector("--camera-focal-point", o.Focal, o.HasFocal) },
    { "--camera-view-up", vector("--camera-view-up", o.Up, o.HasUp) },
    { "--camera-view-angle",
      [&](const std::string& v)
      {
        o.Angle = ParseNumber("--camera-view-angle", v, 0.01, 179);
        o.HasAngle = true;
      } },
    { "--radius",
      [&](const std::string& v) { o.Pass.Radius = ParseNumber("--radius", v, 1e-30, 1e30); } },
    { "--spread",
      [&](const std::string& v) { o.Pass.Spread = ParseNumber("--spread", v, 0.01, 1); } },
    { "--intensity",
      [&](const std::string& v) { o.Pass.Intensity = ParseNumber("--intensity", v, 0, 10); } },
    { "--samples",
      [&](const std::string& v) { o.Samples = ParseInt("--samples", v, 1, 1048576); } },
    { "--scene-triangles",
      [&](const std::string& v)
      { o.SceneTriangles = ParseInt("--scene-triangles", v, 0, 100000000); } },
    { "--ssao-kernel",
      [&](const std::string& v) { o.SSAOKernel = ParseInt("--ssao-kernel", v, 1, 1024); } },
    { "--frames", [&](const std::string& v) { o.Frames = ParseInt("--frames", v, 1, 1000000); } },
    { "--orbit", [&](const std::string& v) { o.Orbit = ParseNumber("--orbit", v, -360, 360); } },
    { "--accumulate",
      [&](const std::string& v) { o.Accumulate = ParseInt("--accumulate", v, 1, 4096); } },
    { "--timings", [&](const std::string& v) { o.Timings = v; } },
    { "--output", [&](const std::string& v) { o.Output = v; } },
  };
  vtkao::AddPassOptionParsers(parsers, o.Pass);
  return parsers;
}

// What the options ask for must make sense together.
void CheckRenderOptions(const Options& o)
{
  if (o.Output.empty())
  {
    throw UsageError("--output FILE is required");
  }
  if (!vtkao::IsSupportedImagePath(o.Output))
  {
    throw UsageError("--output: unsupported format for '" + o.Output + "' (expected .png or .exr)");
  }
  if (o.Pass.AOOnly && o.Method != "hao" && o.Method != "aov" && o.Method != "baked" &&
    o.Method != "reference")
  {
    throw UsageError("--ao-only needs --method hao, aov, baked or reference");
  }
  if (o.Method == "aov" && o.Pass.AOScale > 8)
  {
    throw UsageError("--ao-scale: AOV takes 1 to 8, got " + std::to_string(o.Pass.AOScale));
  }
}

Options ParseRenderOptions(int argc, char* argv[])
{
  Options o;
  vtkao::ParseArguments(argc,
    argv,
    Usage,
    RenderOptionParsers(o),
    [&](const std::string& arg)
    {
      if (arg == "--ao-only")
      {
        o.Pass.AOOnly = true;
      }
      else if (arg.rfind("--", 0) != 0)
      {
        o.Inputs.push_back(arg);
      }
      else if (!vtkao::ParsePassFlag(arg, o.Pass))
      {
        throw UsageError("unknown option '" + arg + "'");
      }
    });
  CheckRenderOptions(o);
  return o;
}

#ifdef VTKAO_HAS_REFERENCE
// vtkao bake INPUT --output OUT.vtp [options]
int Bake(int argc, char* argv[])
{
  std::string input, output;
  vtkao::RayTracingOptions options;
  int resolution = 0; // --resolution (hemisphere only)
  const vtkao::OptionParsers valued = {
    { "--output", [&](const std::string& v) { output = v; } },
    { "--samples",
      [&](const std::string& v) { options.Samples = ParseInt("--samples", v, 1, 1048576); } },
    { "--radius",
      [&](const std::string& v) { options.Radius = ParseNumber("--radius", v, 1e-30, 1e30); } },
    { "--bias", [&](const std::string& v) { options.Bias = ParseNumber("--bias", v, 0, 1e30); } },
    { "--spread",
      [&](const std::string& v) { options.Spread = ParseNumber("--spread", v, 0.01, 1); } },
    { "--falloff",
      [&](const std::string& v)
      {
        options.BinaryFalloff =
          ParseChoice("--falloff", "falloff", v, { "wendland", "none" }) == "none";
      } },
    { "--method",
      [&](const std::string& v)
      {
        options.BakeMethod =
          ParseChoice("--method", "bake method", v, { "raycast", "sattler", "hemisphere" });
      } },
    { "--resolution",
      [&](const std::string& v) { resolution = ParseInt("--resolution", v, 8, 256); } },
  };
  vtkao::ParseArguments(argc,
    argv,
    Usage,
    valued,
    [&](const std::string& arg)
    {
      if (arg.rfind("--", 0) == 0)
      {
        throw UsageError("unknown option '" + arg + "'");
      }
      if (!input.empty())
      {
        throw UsageError("bake takes one INPUT, got '" + input + "' and '" + arg + "'");
      }
      input = arg;
    });
  if (input.empty())
  {
    throw UsageError("bake: missing INPUT");
  }
  if (output.empty())
  {
    throw UsageError("--output FILE.vtp is required");
  }
  if (output.size() < 4 || output.compare(output.size() - 4, 4, ".vtp") != 0)
  {
    throw UsageError("--output: unsupported format for '" + output + "' (expected .vtp)");
  }
  if (options.BakeMethod != "raycast")
  {
    vtkao::RequireRenderingContext(); // sattler and hemisphere render with OpenGL
  }
  if (options.BakeMethod == "hemisphere")
  {
    vtkao::HemisphereBakeOptions hemisphere;
    hemisphere.Radius = options.Radius;
    hemisphere.Bias = options.Bias;
    hemisphere.Spread = options.Spread;
    hemisphere.Resolution = resolution > 0 ? resolution : hemisphere.Resolution;
    vtkao::BakeHemisphereFile(input, output, hemisphere, std::cout);
    return 0;
  }
  if (resolution > 0)
  {
    throw UsageError("--resolution applies to --method hemisphere only");
  }
  vtkao::BakeFile(input, output, options, std::cout);
  return 0;
}
#endif

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0;
  }
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

#ifdef VTKAO_HAS_REFERENCE
// The ray tracer's parameters (--method reference and baked) from the render options.
vtkao::RayTracingOptions RayTracing(const Options& o)
{
  vtkao::RayTracingOptions rayTracing;
  rayTracing.Radius = o.Pass.Radius;
  rayTracing.Bias = o.Pass.Bias;
  rayTracing.Spread = o.Pass.Spread;
  rayTracing.BinaryFalloff = o.Pass.BinaryFalloff;
  rayTracing.Samples = o.Samples;
  return rayTracing;
}
#endif

// The scene (the files given or the built-in one) and the camera the options ask for.
void BuildScene(vtkRenderer* renderer, const Options& o)
{
  renderer->SetBackground(1.0, 1.0, 1.0);
  if (o.Inputs.empty())
  {
    vtkao::AddBuiltInScene(renderer, o.SceneTriangles);
  }
  else
  {
    for (const auto& input : o.Inputs)
    {
      vtkao::AddFile(renderer, input);
    }
    renderer->ResetCamera();
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  if (o.HasPosition)
  {
    camera->SetPosition(o.Position);
  }
  if (o.HasFocal)
  {
    camera->SetFocalPoint(o.Focal);
  }
  if (o.HasUp)
  {
    camera->SetViewUp(o.Up);
  }
  if (o.HasAngle)
  {
    camera->SetViewAngle(o.Angle);
  }
  camera->OrthogonalizeViewUp();
  // A moved camera keeps the clipping range of the old position: refit it to the scene.
  renderer->ResetCameraClippingRange();
}

// The passes `vtkao render` can install; the one of --method is set up by InstallPass.
struct Passes
{
  vtkNew<vtkRenderStepsPass> Basic;
  vtkNew<vtkHybridAmbientOcclusionPass> HAO;
  vtkNew<vtkSSAOPass> SSAO;
  vtkNew<vtkAmbientOcclusionVolumesPass> AOV;
};

// The pass's accumulation: off without --accumulate, so that --frames times every frame's
// full work; with it, a still of at most --accumulate frames.
void SetStill(vtkAmbientOcclusionPassBase* pass, const Options& o)
{
  pass->SetAccumulation(o.Accumulate > 0);
  pass->SetMaximumAccumulatedFrames(std::max(1, o.Accumulate));
}

void InstallAOV(vtkRenderer* renderer, Passes& passes, const Options& o)
{
  vtkAmbientOcclusionVolumesPass* aov = passes.AOV;
  aov->SetDelegatePass(passes.Basic);
  vtkao::ApplySettings(o.Pass, aov);
  // AOV's own defaults where --ao-scale and --filter-size are not given.
  aov->SetAOScale(o.Pass.AOScaleGiven ? o.Pass.AOScale : 1);
  aov->SetFilterSize(o.Pass.FilterSizeGiven ? o.Pass.FilterSize : 6);
  SetStill(aov, o); // a subsampled map (--ao-scale s) converges in s^2 frames
  renderer->SetPass(aov);
}

void InstallHAO(vtkRenderer* renderer, Passes& passes, const Options& o)
{
  vtkHybridAmbientOcclusionPass* hao = passes.HAO;
  hao->SetDelegatePass(passes.Basic);
  vtkao::ApplySettings(o.Pass, hao);
  SetStill(hao, o);
  renderer->SetPass(hao);
}

void InstallSSAO(vtkRenderer* renderer, Passes& passes, const Options& o)
{
  vtkSSAOPass* ssao = passes.SSAO;
  ssao->SetDelegatePass(passes.Basic);
  double b[6];
  renderer->ComputeVisiblePropBounds(b);
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  ssao->SetRadius(o.Pass.Radius > 0 ? o.Pass.Radius : 0.1 * diagonal);
  ssao->SetBias(0.001 * diagonal);
  ssao->SetKernelSize(o.SSAOKernel);
  ssao->BlurOn();
  renderer->SetPass(ssao);
}

// The pass of --method (none: VTK's own rendering; reference and baked: no pass).
void InstallPass(vtkRenderer* renderer, Passes& passes, const Options& o)
{
  if (o.Method == "aov")
  {
    InstallAOV(renderer, passes, o);
  }
  else if (o.Method == "hao")
  {
    InstallHAO(renderer, passes, o);
  }
  else if (o.Method == "ssao")
  {
    InstallSSAO(renderer, passes, o);
  }
}

// Per frame: the wall-clock time and the GPU time of each stage of the pass (ms).
struct FrameTimes
{
  std::vector<double> Total;
  std::vector<std::vector<double>> Stages;
  std::vector<std::string> StageNames;
};

// Renders --frames frames, orbiting the camera between them; the reference is traced into
// @p traced instead (the last frame's image).
FrameTimes RenderFrames(vtkRenderWindow* window,
  vtkRenderer* renderer,
  Passes& passes,
  const Options& o,
  vtkao::FloatImage& traced)
{
  FrameTimes times;
  times.StageNames = o.Method == "aov"
    ? std::vector<std::string>{ "gbuffer", "volumes", "filter", "composite" }
    : std::vector<std::string>{ "voxelize", "gbuffer", "trace", "filter", "composite" };
#ifdef VTKAO_HAS_REFERENCE
  const vtkao::RayTracingOptions rayTracing = RayTracing(o);
#else
  (void)traced;
#endif
  // --accumulate N: N - 1 more frames of the last view, each adding to the mean.
  const int total = o.Frames + std::max(0, o.Accumulate - 1);
  for (int frame = 0; frame < total; ++frame)
  {
    if (frame > 0 && frame < o.Frames && o.Orbit != 0)
    {
      renderer->GetActiveCamera()->Azimuth(o.Orbit);
      renderer->ResetCameraClippingRange();
    }
    const auto start = std::chrono::steady_clock::now();
#ifdef VTKAO_HAS_REFERENCE
    if (o.Method == "reference")
    {
      traced = vtkao::RenderReference(renderer, o.Width, o.Height, rayTracing, std::cout);
    }
    else
#endif
    {
      window->Render();
      window->WaitForCompletion();
    }
    const auto stop = std::chrono::steady_clock::now();
    times.Total.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    if (o.Method == "hao")
    {
      vtkHybridAmbientOcclusionPass* hao = passes.HAO;
      hao->FinishTimings();
      times.Stages.push_back({ hao->GetVoxelizeTime(),
        hao->GetGBufferTime(),
        hao->GetTraceTime(),
        hao->GetFilterTime(),
        hao->GetCompositeTime() });
    }
    else if (o.Method == "aov")
    {
      vtkAmbientOcclusionVolumesPass* aov = passes.AOV;
      aov->FinishTimings();
      times.Stages.push_back({ aov->GetGBufferTime(),
        aov->GetVolumeTime(),
        aov->GetFilterTime(),
        aov->GetCompositeTime() });
    }
  }
  return times;
}

// The image to write: the traced reference, the baked AO, the pass's AO term (--ao-only) or
// the window's colours.
vtkao::FloatImage CaptureImage(vtkRenderWindow* window,
  Passes& passes,
  const Options& o,
  const vtkao::FloatImage& traced)
{
  vtkao::FloatImage image;
  image.Width = o.Width;
  image.Height = o.Height;
#ifdef VTKAO_HAS_REFERENCE
  if (o.Method == "reference")
  {
    return traced;
  }
  if (o.Method == "baked" && o.Pass.AOOnly)
  {
    return vtkao::ReadBakedAO(window, o.Width, o.Height);
  }
#else
  (void)traced;
#endif
  if (o.Pass.AOOnly)
  {
    vtkNew<vtkImageData> ao;
    const bool read = o.Method == "aov" ? passes.AOV->GetAmbientOcclusionImage(ao)
                                        : passes.HAO->GetAmbientOcclusionImage(ao);
    if (!read)
    {
      throw std::runtime_error("the scene produced no ambient occlusion (no opaque polygons?)");
    }
    vtkFloatArray* a = vtkFloatArray::SafeDownCast(ao->GetPointData()->GetScalars());
    image.Channels = 2;
    image.Pixels.assign(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues());
    return image;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGBA();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgba =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  image.Channels = 4;
  image.Pixels.resize(static_cast<size_t>(rgba->GetNumberOfValues()));
  for (vtkIdType i = 0; i < rgba->GetNumberOfValues(); ++i)
  {
    image.Pixels[i] = rgba->GetValue(i) / 255.0f;
  }
  return image;
}

// One paragraph on stdout: the scene, the median frame and stage times, the pass's figures.
void Report(vtkRenderer* renderer, Passes& passes, const Options& o, const FrameTimes& times)
{
  std::cout << "scene: " << vtkao::CountTriangles(renderer) << " triangles\n";
  std::cout << "method " << o.Method << ", " << o.Width << "x" << o.Height << ", " << o.Frames
            << " frame(s): median frame " << Median(times.Total) << " ms";
  if (!times.Stages.empty())
  {
    std::cout << "; GPU stages (median ms):";
    for (size_t s = 0; s < times.StageNames.size(); ++s)
    {
      std::vector<double> v;
      for (const auto& f : times.Stages)
      {
        v.push_back(f[s]);
      }
      std::cout << " " << times.StageNames[s] << " " << Median(v);
    }
  }
  if (o.Method == "hao")
  {
    std::cout << "; voxelizations " << passes.HAO->GetVoxelizationCount() << "; refined "
              << 100.0 * passes.HAO->GetRefinedFraction() << " % of the pixels; radius "
              << passes.HAO->GetEffectiveRadius() << ", bias " << passes.HAO->GetEffectiveBias();
  }
  else if (o.Method == "aov")
  {
    std::cout << "; " << passes.AOV->GetNumberOfOccludingTriangles() << " volumes; radius "
              << passes.AOV->GetEffectiveRadius() << ", bias " << passes.AOV->GetEffectiveBias();
  }
  std::cout << "\nwrote " << o.Output << "\n";
}

// --timings FILE.json: every frame's times, written to a temporary file renamed at the end
// (no partial file is left behind).
void WriteTimings(const Options& o, const FrameTimes& times)
{
  const std::string temporary = o.Timings + ".partial";
  {
    std::ofstream json(temporary);
    json << "{\n  \"method\": \"" << o.Method << "\",\n  \"width\": " << o.Width
         << ",\n  \"height\": " << o.Height << ",\n  \"frames\": [\n";
    for (size_t f = 0; f < times.Total.size(); ++f)
    {
      json << "    {\"frame\": " << f << ", \"total_ms\": " << times.Total[f];
      if (f < times.Stages.size())
      {
        for (size_t s = 0; s < times.StageNames.size(); ++s)
        {
          json << ", \"" << times.StageNames[s] << "_ms\": " << times.Stages[f][s];
        }
      }
      json << "}" << (f + 1 < times.Total.size() ? "," : "") << "\n";
    }
    json << "  ],\n  \"median_total_ms\": " << Median(times.Total) << "\n}\n";
    if (!json.good())
    {
      throw std::runtime_error("cannot write timings file '" + o.Timings + "'");
    }
  }
  if (std::rename(temporary.c_str(), o.Timings.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write timings file '" + o.Timings + "'");
  }
}

int Render(int argc, char* argv[])
{
  const Options o = ParseRenderOptions(argc, argv);
  vtkNew<vtkRenderer> renderer;
  BuildScene(renderer, o);
  vtkao::RequireRenderingContext();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0); // MSAA would make plain rendering slower than an FBO pass
  window->SetSize(o.Width, o.Height);
  window->AddRenderer(renderer);
  Passes passes;
  InstallPass(renderer, passes, o);
#ifdef VTKAO_HAS_REFERENCE
  if (o.Method == "baked")
  {
    vtkao::BakeRenderer(renderer, RayTracing(o), o.Pass.AOOnly, std::cout);
  }
#endif
  vtkao::FloatImage traced;
  const FrameTimes times = RenderFrames(window, renderer, passes, o, traced);
  vtkao::WriteImage(CaptureImage(window, passes, o, traced), o.Output);
  Report(renderer, passes, o, times);
  if (!o.Timings.empty())
  {
    WriteTimings(o, times);
  }
  renderer->ReleaseGraphicsResources(window);
  return 0;
}
}

// vtkao gl-info: the OpenGL context this program gets (window class, vendor, renderer, version),
// one "key: value" line each, from one tiny off-screen frame.
int GLInfo()
{
  vtkao::RequireRenderingContext();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(16, 16);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  std::cout << "window: " << window->GetClassName() << "\n";
  std::istringstream report(window->ReportCapabilities());
  for (std::string line; std::getline(report, line);)
  {
    for (const char* key :
      { "OpenGL vendor string:", "OpenGL renderer string:", "OpenGL version string:" })
    {
      if (line.rfind(key, 0) == 0)
      {
        const size_t start = line.find_first_not_of(' ', std::string(key).size());
        const std::string name = std::string(key).substr(7, std::string(key).size() - 15);
        std::cout << "gl_" << name << ": " << (start == std::string::npos ? "" : line.substr(start))
                  << "\n";
      }
    }
  }
  renderer->ReleaseGraphicsResources(window);
  return 0;
}

int main(int argc, char* argv[])
{
  try
  {
    if (argc < 2)
    {
      throw UsageError("missing subcommand (expected: render or bake)");
    }
    const std::string command = argv[1];
    // render --compare (vtkaoCompare.cxx) and view (vtkaoView.cxx); their usage errors are
    // std::invalid_argument.
    try
    {
      if (command == "render" && vtkao::HasCompare(argc - 2, argv + 2))
      {
        return vtkao::RenderComparison(
          argc - 2, argv + 2, { "none", "ssao", "hao", "aov", "reference" }, &Render);
      }
      if (command == "bench")
      {
        return vtkao::Bench(argc - 2, argv + 2);
      }
      if (command == "view")
      {
        return vtkao::View(argc - 2, argv + 2);
      }
    }
    catch (const std::invalid_argument& e)
    {
      throw UsageError(e.what());
    }
    if (command == "render")
    {
      return Render(argc - 2, argv + 2);
    }
    if (command == "gl-info")
    {
      return GLInfo();
    }
#ifdef VTKAO_HAS_REFERENCE
    if (command == "bake")
    {
      return Bake(argc - 2, argv + 2);
    }
    if (command == "quality")
    {
      return vtkao::Quality(argc - 2, argv + 2);
    }
#endif
    if (command == "--help" || command == "-h")
    {
      std::cout << Usage;
      return 0;
    }
    throw UsageError("unknown subcommand '" + command + "' (expected: render or bake)");
  }
  catch (const UsageError& e)
  {
    std::cerr << "vtkao: " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vtkao: " << e.what() << "\n";
    return 1;
  }
}
