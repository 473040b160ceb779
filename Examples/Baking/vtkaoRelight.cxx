// vtkaoRelight: precomputed visibility (Sattler et al. 2004) and relighting.
//
//   vtkaoRelight [INPUT] [--directions K] [--resolution N] [--hdr FILE] [--output-prefix P]
//                [--size WxH]
//
// Bakes the per-vertex visibility matrix of INPUT (.vtp .vtk .stl .ply .obj; none = a built-in
// floor with a ball and a box) once with vtkAOSattlerBaker, then relights it under several
// environments without new visibility, only c = M I:
//   constant  I_j = 1 (ambient occlusion itself),
//   sky       a sky gradient (blue zenith, white horizon, brown ground), up = +y,
//   lights    two coloured directional lights (narrow lobes) over a dim sky,
//   hdr       a lat-long (equirectangular) HDR/EXR image read with OpenImageIO (--hdr).
// Each environment is drawn off screen with the vertex colours c (unlit, clamped to [0, 1])
// into P<environment>.png (default P = "relight-"); the times of the bake and of each
// relighting are printed.
#include "vtkAOSattlerBaker.h"
#include "vtkaoBakingScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataReader.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include "vtkaoImageFile.h"
#include "vtkaoOptions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
const double Pi = 3.14159265358979323846;

bool EndsWith(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

// A reader of @p name.
template<class Reader>
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& name)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(name.c_str());
  return reader;
}

vtkSmartPointer<vtkPolyData> Read(const std::string& name)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (EndsWith(name, ".vtp"))
  {
    reader = MakeReader<vtkXMLPolyDataReader>(name);
  }
  else if (EndsWith(name, ".vtk"))
  {
    reader = MakeReader<vtkPolyDataReader>(name);
  }
  else if (EndsWith(name, ".stl"))
  {
    reader = MakeReader<vtkSTLReader>(name);
  }
  else if (EndsWith(name, ".ply"))
  {
    reader = MakeReader<vtkPLYReader>(name);
  }
  else if (EndsWith(name, ".obj"))
  {
    reader = MakeReader<vtkOBJReader>(name);
  }
  else
  {
    throw std::runtime_error("unsupported input '" + name + "'");
  }
  reader->Update();
  vtkPolyData* data = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data || data->GetNumberOfPolys() + data->GetNumberOfStrips() == 0)
  {
    throw std::runtime_error("'" + name + "' contains no polygons");
  }
  return data;
}

// RGB per direction.
using Environment = std::vector<double>;

Environment Constant(const std::vector<double>& dirs)
{
  return Environment(dirs.size(), 1.0);
}

Environment Sky(const std::vector<double>& dirs)
{
  const double zenith[3] = { 0.25, 0.45, 1.0 }, horizon[3] = { 1.0, 1.0, 1.0 },
               ground[3] = { 0.35, 0.25, 0.15 };
  Environment e(dirs.size());
  for (size_t j = 0; j < dirs.size() / 3; ++j)
  {
    const double up = dirs[3 * j + 1];
    for (int c = 0; c < 3; ++c)
    {
      e[3 * j + c] = up >= 0 ? horizon[c] + (zenith[c] - horizon[c]) * up : ground[c];
    }
  }
  return e;
}

// Directional lights as narrow lobes (cone of about 15 degrees), each normalized so that the
// lobe's cosine-weighted contribution to an open, facing vertex is its colour; plus a dim sky.
Environment Lights(const std::vector<double>& dirs)
{
  struct Light
  {
    double Direction[3];
    double Color[3];
  };
  const Light lights[2] = { { { 0.5, 0.8, 0.3 }, { 1.0, 0.8, 0.5 } },
    { { -0.7, 0.5, -0.5 }, { 0.3, 0.4, 1.0 } } };
  Environment e = Sky(dirs);
  for (double& v : e)
  {
    v *= 0.15;
  }
  const size_t k = dirs.size() / 3;
  for (const Light& light : lights)
  {
    double d[3] = { light.Direction[0], light.Direction[1], light.Direction[2] };
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    std::vector<double> weight(k, 0.0);
    double total = 0.0;
    for (size_t j = 0; j < k; ++j)
    {
      const double c =
        (dirs[3 * j] * d[0] + dirs[3 * j + 1] * d[1] + dirs[3 * j + 2] * d[2]) / norm;
      weight[j] = c > std::cos(15.0 * Pi / 180.0) ? c : 0.0;
      total += weight[j];
    }
    // The relit value divides by sum_j cos over the hemisphere (about k/4): scale the lobe so
    // that it adds its colour at normal incidence.
    const double scale = total > 0 ? (k / 4.0) / total : 0.0;
    for (size_t j = 0; j < k; ++j)
    {
      for (int c = 0; c < 3; ++c)
      {
        e[3 * j + c] += scale * weight[j] * light.Color[c];
      }
    }
  }
  return e;
}

// A lat-long image: u = atan2(x, -z) / (2 pi) + 0.5, v = acos(y) / pi (y up, top row = zenith).
// Each direction takes the mean of the pixels within its share of the sphere (a cap of solid
// angle 4 pi / k), so that bright small sources are not missed between the directions.
Environment LatLong(const std::vector<double>& dirs, const std::string& file)
{
  int w = 0, h = 0, channels = 0;
  std::vector<float> pixels;
  char error[512] = "";
  if (!vtkao::ReadImageFile(file.c_str(), &w, &h, &channels, &pixels, error, sizeof(error)))
  {
    throw std::runtime_error("cannot read '" + file + "': " + error);
  }
  const size_t k = dirs.size() / 3;
  const double capCos = 1.0 - 2.0 / k; // cap of solid angle 4 pi / k
  Environment e(3 * k, 0.0);
  std::vector<double> weights(k, 0.0);
  // Every pixel (weighted by its solid angle) goes to the directions whose cap contains it.
  for (int y = 0; y < h; ++y)
  {
    const double theta = Pi * (y + 0.5) / h;
    const double solid = std::sin(theta);
    for (int x = 0; x < w; ++x)
    {
      const double phi = 2.0 * Pi * ((x + 0.5) / w - 0.5);
      const double d[3] = {
        std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)
      };
      const float* p = &pixels[(static_cast<size_t>(y) * w + x) * channels];
      for (size_t j = 0; j < k; ++j)
      {
        if (dirs[3 * j] * d[0] + dirs[3 * j + 1] * d[1] + dirs[3 * j + 2] * d[2] >= capCos)
        {
          for (int c = 0; c < 3; ++c)
          {
            e[3 * j + c] += solid * p[std::min(c, channels - 1)];
          }
          weights[j] += solid;
        }
      }
    }
  }
  for (size_t j = 0; j < k; ++j)
  {
    for (int c = 0; c < 3; ++c)
    {
      e[3 * j + c] = weights[j] > 0 ? e[3 * j + c] / weights[j] : 0.0;
    }
  }
  return e;
}

void Draw(vtkPolyData* mesh,
  vtkFloatArray* radiance,
  int width,
  int height,
  const std::string& file)
{
  // Clamp to [0, 1] and store as 8-bit colours (the mapper's direct scalars).
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(radiance->GetNumberOfTuples());
  for (vtkIdType i = 0; i < radiance->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v =
        radiance->GetComponent(i, std::min(c, radiance->GetNumberOfComponents() - 1));
      colors->SetComponent(i, c, std::round(255.0 * std::min(1.0, std::max(0.0, v))));
    }
  }
  vtkNew<vtkPolyData> colored;
  colored->ShallowCopy(mesh);
  colored->GetPointData()->SetScalars(colors);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(colored);
  mapper->SetColorModeToDirectScalars();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  renderer->GetActiveCamera()->Elevation(30);
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(file.c_str());
  writer->Write();
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}
struct Options
{
  std::string Input, HDR, Prefix = "relight-";
  int Directions = 256, Resolution = 1024, Width = 640, Height = 480;
};

const char* Usage = "usage: vtkaoRelight [INPUT] [--directions K] [--resolution N] [--hdr FILE]"
                    " [--output-prefix P] [--size WxH]\n";

Options ParseOptions(int argc, char* argv[])
{
  Options o;
  const vtkao::OptionParsers parsers = {
    { "--directions",
      [&o](const std::string& v) { o.Directions = vtkao::ParseInt("--directions", v, 1, 65536); } },
    { "--resolution",
      [&o](const std::string& v) { o.Resolution = vtkao::ParseInt("--resolution", v, 16, 8192); } },
    { "--hdr", [&o](const std::string& v) { o.HDR = v; } },
    { "--output-prefix", [&o](const std::string& v) { o.Prefix = v; } },
    { "--size", [&o](const std::string& v) { vtkao::ParseSize(v, 1, 16384, o.Width, o.Height); } },
  };
  vtkao::ParseArguments(argc - 1,
    argv + 1,
    Usage,
    parsers,
    [&o](const std::string& arg)
    {
      if (arg.rfind("--", 0) == 0 || !o.Input.empty())
      {
        throw vtkao::UsageError("unexpected argument '" + arg + "'");
      }
      o.Input = arg;
    });
  return o;
}

// The visibility matrix of @p mesh, once; its size and speed on stdout.
void BakeVisibility(vtkAOSattlerBaker* baker, vtkPolyData* mesh, const Options& o)
{
  baker->SetInputData(mesh);
  baker->SetNumberOfDirections(o.Directions);
  baker->SetResolution(o.Resolution);
  baker->Update();
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::cout << "visibility: " << n << " points x " << baker->GetNumberOfDirections()
            << " directions in " << baker->GetTotalTime() << " s ("
            << 1000.0 * baker->GetTotalTime() / baker->GetNumberOfDirections() << " ms/direction, "
            << n * static_cast<double>(baker->GetNumberOfDirections()) / baker->GetTotalTime()
            << " vertex-directions/s); matrix " << baker->GetVisibilityMemory() << " bytes ("
            << baker->GetWordsPerPoint() * 4 << " bytes/point)\n";
}

// The environments to relight under, by name, sampled in the baker's directions.
std::vector<std::pair<std::string, Environment>> Environments(const std::vector<double>& dirs,
  const std::string& hdr)
{
  std::vector<std::pair<std::string, Environment>> environments = {
    { "constant", Constant(dirs) }, { "sky", Sky(dirs) }, { "lights", Lights(dirs) }
  };
  if (!hdr.empty())
  {
    environments.emplace_back("hdr", LatLong(dirs, hdr));
  }
  return environments;
}

// c = M I under one environment, drawn into <prefix><name>.png; the time and mean on stdout.
void Relight(vtkAOSattlerBaker* baker,
  const std::pair<std::string, Environment>& environment,
  const Options& o)
{
  vtkPolyData* output = baker->GetOutput();
  const vtkIdType n = output->GetNumberOfPoints();
  vtkNew<vtkFloatArray> radiance;
  const auto start = std::chrono::steady_clock::now();
  if (!baker->Relight(environment.second, 3, radiance))
  {
    throw std::runtime_error("relighting failed");
  }
  const double seconds = Seconds(start);
  double mean[3] = { 0, 0, 0 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      mean[c] += radiance->GetComponent(i, c) / n;
    }
  }
  const std::string file = o.Prefix + environment.first + ".png";
  Draw(output, radiance, o.Width, o.Height, file);
  std::cout << environment.first << ": relit in " << 1000.0 * seconds << " ms, mean c = ("
            << mean[0] << ", " << mean[1] << ", " << mean[2] << "), wrote " << file << "\n";
}
}

int main(int argc, char* argv[])
{
  try
  {
    const Options o = ParseOptions(argc, argv); // --help: the usage, and exit
    vtkSmartPointer<vtkPolyData> mesh =
      o.Input.empty() ? vtkao::FloorBallAndSunkBox(60, 1.0, 32) : Read(o.Input);
    vtkNew<vtkAOSattlerBaker> baker;
    BakeVisibility(baker, mesh, o);
    for (const auto& environment : Environments(baker->GetDirections(), o.HDR))
    {
      Relight(baker, environment, o);
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vtkaoRelight: " << e.what() << "\n";
    return 1;
  }
}
