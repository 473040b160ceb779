// vtkao bench: in one process, for the built-in scene (and finer tessellations of it), render a
// warm-up frame then N timed frames per method and camera mode, and report the median and
// spread of the frame time, the AO overhead (method minus no AO, same scene and mode) and
// HAO's per-stage GPU times (timer queries). Multisampling is off, as in `vtkao render`.
//
// Modes: "orbit" turns the camera 2 degrees per frame around a static scene (HAO does not
// re-voxelize); "moving" moves the sphere each frame (HAO re-voxelizes every frame).

#include "vtkaoBench.h"
#include "vtkaoScene.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
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
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Method
{
  std::string Name;
  std::string Kind; // none, ssao, hao
  int Kernel = 32;  // ssao
  bool Quality = false;
};

struct Result
{
  std::string Scene;
  long long Triangles = 0;
  std::string Mode;
  std::string Method;
  std::vector<double> Frames;
  std::vector<std::vector<double>> Stages; // hao: voxelize, gbuffer, trace, filter, composite
  int Voxelizations = 0;
  double Overhead = 0;
};

const char* StageNames[5] = { "voxelize", "gbuffer", "trace", "filter", "composite" };

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

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      out += ' ';
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
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

Result RunCase(const std::string& sceneName,
  long long requestedTriangles,
  const std::string& mode,
  const Method& method,
  vtkRenderWindow* window,
  int frames,
  std::string* glReport)
{
  // One window (one X connection, one context) for every case; a renderer per case.
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkao::AddBuiltInScene(renderer, requestedTriangles);
  window->AddRenderer(renderer);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkHybridAmbientOcclusionPass> hao;
  vtkNew<vtkSSAOPass> ssao;
  if (method.Kind == "hao")
  {
    hao->SetDelegatePass(basic);
    if (method.Quality)
    {
      hao->SetNumberOfRays(64);
      hao->SetNumberOfSteps(16);
      hao->SetVoxelResolution(384);
    }
    renderer->SetPass(hao);
  }
  else if (method.Kind == "ssao")
  {
    // As `vtkao render --method ssao`: radius a tenth of the scene's diagonal, blurred.
    ssao->SetDelegatePass(basic);
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    const double diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) +
      (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
    ssao->SetRadius(0.1 * diagonal);
    ssao->SetBias(0.001 * diagonal);
    ssao->SetKernelSize(method.Kernel);
    ssao->BlurOn();
    renderer->SetPass(ssao);
  }

  Result r;
  r.Scene = sceneName;
  r.Triangles = vtkao::CountTriangles(renderer);
  r.Mode = mode;
  r.Method = method.Name;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkActor* mover = FindSphere(renderer);
  double start[3] = { 0, 0, 0 };
  if (mover)
  {
    mover->GetPosition(start);
  }
  for (int frame = 0; frame <= frames; ++frame) // frame 0: warm-up (shaders, first voxelization)
  {
    if (frame > 0)
    {
      if (mode == "orbit")
      {
        camera->Azimuth(2.0);
        renderer->ResetCameraClippingRange();
      }
      else if (mover)
      {
        mover->SetPosition(start[0] + 0.05 * frame, start[1], start[2]);
      }
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
      hao->FinishTimings();
    }
    if (frame == 0)
    {
      continue;
    }
    r.Frames.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    if (method.Kind == "hao")
    {
      r.Stages.push_back({ hao->GetVoxelizeTime(),
        hao->GetGBufferTime(),
        hao->GetTraceTime(),
        hao->GetFilterTime(),
        hao->GetCompositeTime() });
    }
  }
  r.Voxelizations = method.Kind == "hao" ? hao->GetVoxelizationCount() - 1 : 0;
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
}

namespace vtkao
{
int Bench(int argc, char* argv[])
{
  bool quick = false;
  int frames = 0;
  int width = 1280, height = 720;
  std::string json, md;
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
      quick = true;
    }
    else if (arg == "--frames")
    {
      const std::string v = value();
      frames = std::atoi(v.c_str());
      if (frames < 1 || frames > 10000)
      {
        throw std::invalid_argument("--frames: '" + v + "' is not in [1, 10000]");
      }
    }
    else if (arg == "--size")
    {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1 ||
        width > 16384 || height > 16384)
      {
        throw std::invalid_argument("--size: expected WxH, got '" + v + "'");
      }
    }
    else if (arg == "--output-json")
    {
      json = value();
    }
    else if (arg == "--output-md")
    {
      md = value();
    }
    else if (arg == "--help" || arg == "-h")
    {
      std::cout << "usage: vtkao bench [--quick] [--frames N] [--size WxH] [--output-json F]"
                   " [--output-md F]\n";
      return 0;
    }
    else
    {
      throw std::invalid_argument("bench: unknown argument '" + arg + "'");
    }
  }
  if (quick)
  {
    width = std::min(width, 160);
    height = std::min(height, 90);
  }
  if (frames == 0)
  {
    frames = quick ? 2 : 7;
  }

  const std::vector<Method> methods = { { "none", "none" },
    { "ssao32", "ssao", 32 },
    { "ssao128", "ssao", 128 },
    { "hao", "hao" },
    { "hao-quality", "hao", 32, true } };
  struct Scene
  {
    std::string Name;
    long long Triangles;
  };
  std::vector<Scene> scenes = { { "builtin", 0 } };
  if (!quick)
  {
    scenes.push_back({ "builtin-200k", 200000 });
    scenes.push_back({ "builtin-1m", 1000000 });
  }
  const std::vector<std::string> modes = { "orbit", "moving" };

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);

  std::string glReport;
  std::vector<Result> results;
  for (const auto& scene : scenes)
  {
    for (const auto& mode : modes)
    {
      double none = 0;
      for (const auto& method : methods)
      {
        Result r = RunCase(scene.Name, scene.Triangles, mode, method, window, frames, &glReport);
        if (method.Kind == "none")
        {
          none = Median(r.Frames);
        }
        r.Overhead = Median(r.Frames) - none;
        std::cout << scene.Name << " (" << r.Triangles << " triangles) " << mode << " "
                  << method.Name << ": median " << Median(r.Frames) << " ms, overhead "
                  << r.Overhead << " ms";
        if (method.Kind == "hao")
        {
          std::cout << "; stages";
          for (int s = 0; s < 5; ++s)
          {
            std::cout << " " << StageNames[s] << " " << StageMedian(r, s);
          }
        }
        std::cout << std::endl;
        results.push_back(r);
      }
    }
  }

  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof(date), "%Y-%m-%d", std::localtime(&now));
  const std::string cpu = ReadCPUName();
  const std::string renderer = CapabilityLine(glReport, "OpenGL renderer string:");
  const std::string version = CapabilityLine(glReport, "OpenGL version string:");

  if (!json.empty())
  {
    std::ofstream out(json);
    out << std::setprecision(6);
    out << "{\n  \"date\": " << JsonString(date) << ",\n  \"cpu\": " << JsonString(cpu)
        << ",\n  \"gl_renderer\": " << JsonString(renderer)
        << ",\n  \"gl_version\": " << JsonString(version) << ",\n  \"width\": " << width
        << ",\n  \"height\": " << height << ",\n  \"multisamples\": 0,\n  \"warmup_frames\": 1"
        << ",\n  \"frames\": " << frames << ",\n  \"cases\": [\n";
    for (size_t i = 0; i < results.size(); ++i)
    {
      const Result& r = results[i];
      out << "    {\"scene\": " << JsonString(r.Scene) << ", \"triangles\": " << r.Triangles
          << ", \"mode\": " << JsonString(r.Mode) << ", \"method\": " << JsonString(r.Method)
          << ",\n     \"median_ms\": " << Median(r.Frames)
          << ", \"p25_ms\": " << Quantile(r.Frames, 0.25)
          << ", \"p75_ms\": " << Quantile(r.Frames, 0.75)
          << ", \"min_ms\": " << Quantile(r.Frames, 0) << ", \"max_ms\": " << Quantile(r.Frames, 1)
          << ", \"overhead_ms\": " << r.Overhead << ",\n     \"frames_ms\": [";
      for (size_t f = 0; f < r.Frames.size(); ++f)
      {
        out << (f ? ", " : "") << r.Frames[f];
      }
      out << "],\n     \"voxelizations\": " << r.Voxelizations << ", \"stages_ms\": ";
      if (r.Stages.empty())
      {
        out << "null";
      }
      else
      {
        out << "{";
        for (int s = 0; s < 5; ++s)
        {
          out << (s ? ", " : "") << "\"" << StageNames[s] << "\": " << StageMedian(r, s);
        }
        out << "}";
      }
      out << "}" << (i + 1 < results.size() ? "," : "") << "\n";
    }
    out << "  ]\n}\n";
    if (!out.good())
    {
      throw std::runtime_error("cannot write '" + json + "'");
    }
  }
  if (!md.empty())
  {
    std::ofstream out(md);
    out << std::fixed << std::setprecision(1);
    out << "Date " << date << "; CPU " << cpu << "; GL " << renderer << " (" << version << "); "
        << width << "x" << height << ", no multisampling; " << frames
        << " frames after 1 warm-up; times in ms (median, [p25, p75]).\n\n";
    out << "| scene | triangles | mode | method | frame | spread | AO overhead | voxelize "
           "| gbuffer | trace | filter | composite | voxelizations |\n";
    out << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : results)
    {
      out << "| " << r.Scene << " | " << r.Triangles << " | " << r.Mode << " | " << r.Method
          << " | " << Median(r.Frames) << " | [" << Quantile(r.Frames, 0.25) << ", "
          << Quantile(r.Frames, 0.75) << "] | " << r.Overhead;
      for (int s = 0; s < 5; ++s)
      {
        if (r.Stages.empty())
        {
          out << " | -";
        }
        else
        {
          out << " | " << StageMedian(r, s);
        }
      }
      out << " | " << r.Voxelizations << " |\n";
    }
    if (!out.good())
    {
      throw std::runtime_error("cannot write '" + md + "'");
    }
  }
  return 0;
}
}
