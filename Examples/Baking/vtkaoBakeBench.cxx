// vtkaoBakeBench: throughput of the per-vertex bakers on one mesh (Documentation/baking.md).
//
//   vtkaoBakeBench [--input MESH.vtp] [--vertices N] [--directions K] [--resolution R]
//                  [--repeat P] [--hemicube N] [--hemisphere-vertices M] [--samples S]
//                  [--bias B] [--write-mesh FILE.vtp]
//
// Without --input the mesh is hills (a displaced grid) with a torus resting on them, about N
// vertices (default 100 000). Runs, on the same mesh, normals and bias:
// - vtkAOSattlerBaker with K directions (default 64) at R^2 (default 1024^2), once with the GPU
//   point test and once with the CPU test, P times alternately (default 1; the best time of
//   each is reported, which filters out other load on a shared machine): ms per direction,
//   vertex-directions per second, and how many visibility bits differ between the two;
// - vtkAOHemisphereBaker (N x N hemicube, default 64) on the first M vertices of the mesh
//   (default 200; every triangle still occludes): vertices per second (its cost grows as
//   vertices x triangles, so the whole mesh would take hours on llvmpipe);
// - vtkAOVertexBaker (when built with Embree) with S rays per vertex (default 64), binary
//   falloff, R = 1e4: rays per second.
// --hemisphere-vertices 0 or --samples 0 skip those runs.
#include "vtkAOHemisphereBaker.h"
#include "vtkAOSattlerBaker.h"
#ifdef VTKAO_HAS_REFERENCE
#include "vtkAOVertexBaker.h"
#endif

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSuperquadricSource.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
// Hills (a height field of Gaussian bumps, deterministic) and a torus lying on them.
vtkSmartPointer<vtkPolyData> MakeMesh(long long vertices)
{
  const int grid = std::max(8, static_cast<int>(std::sqrt(0.95 * vertices)) - 1);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-10, -10, 0);
  plane->SetPoint1(10, -10, 0);
  plane->SetPoint2(-10, 10, 0);
  plane->SetResolution(grid, grid);
  plane->Update();
  vtkNew<vtkPolyData> hills;
  hills->DeepCopy(plane->GetOutput());
  hills->GetPointData()->Initialize();
  vtkPoints* points = hills->GetPoints();
  const double bumps[6][4] = { { -4, -3, 3.0, 2.5 },
    { 5, 4, 2.0, 2.0 },
    { 2, -6, 1.5, 1.5 },
    { -6, 6, 2.5, 3.0 },
    { 7, -2, 1.0, 1.2 },
    { -1, 3, 1.2, 1.0 } }; // x, y, height, width
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (const auto& b : bumps)
    {
      const double r2 =
        ((p[0] - b[0]) * (p[0] - b[0]) + (p[1] - b[1]) * (p[1] - b[1])) / (b[3] * b[3]);
      p[2] += b[2] * std::exp(-r2);
    }
    points->SetPoint(i, p);
  }
  const int ring = std::max(8, static_cast<int>(std::sqrt(0.05 * vertices)));
  vtkNew<vtkSuperquadricSource> torus;
  torus->ToroidalOn();
  torus->SetCenter(0, -1, 1.2);
  torus->SetScale(1, 1, 1);
  torus->SetSize(2.0);
  torus->SetThickness(0.4);
  torus->SetThetaResolution(2 * ring);
  torus->SetPhiResolution(ring);
  torus->Update();
  vtkNew<vtkPolyData> ring3;
  ring3->DeepCopy(torus->GetOutput());
  ring3->GetPointData()->Initialize();
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(hills);
  append->AddInputData(ring3);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(append->GetOutputPort());
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->ComputeCellNormalsOff();
  normals->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(normals->GetOutput());
  return mesh;
}

// The same points and normals, only the polygons whose points are all among the first @p count.
vtkSmartPointer<vtkPolyData> FirstVertices(vtkPolyData* mesh, vtkIdType count)
{
  auto patch = vtkSmartPointer<vtkPolyData>::New();
  patch->SetPoints(mesh->GetPoints());
  patch->GetPointData()->SetNormals(mesh->GetPointData()->GetNormals());
  vtkNew<vtkCellArray> polys;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    it->GetCurrentCell(npts, pts);
    if (std::all_of(pts, pts + npts, [&](vtkIdType p) { return p < count; }))
    {
      polys->InsertNextCell(npts, pts);
    }
  }
  patch->SetPolys(polys);
  return patch;
}

long long Value(int argc, char* argv[], int& i)
{
  if (i + 1 >= argc)
  {
    std::cerr << "vtkaoBakeBench: " << argv[i] << ": missing value\n";
    std::exit(2);
  }
  return std::atoll(argv[++i]);
}
}

// The command line (see the top of the file).
struct BenchOptions
{
  std::string Input, WriteMesh;
  long long Vertices = 100000, HemisphereVertices = 200;
  int Directions = 64, Resolution = 1024, Hemicube = 64, Samples = 64, Repeat = 1;
  double Bias = 0.02;
};

// False (after printing the usage) on an unknown option.
bool ParseArguments(int argc, char* argv[], BenchOptions& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--input" && i + 1 < argc)
    {
      o.Input = argv[++i];
    }
    else if (arg == "--write-mesh" && i + 1 < argc)
    {
      o.WriteMesh = argv[++i];
    }
    else if (arg == "--vertices")
    {
      o.Vertices = std::max(100LL, Value(argc, argv, i));
    }
    else if (arg == "--directions")
    {
      o.Directions = static_cast<int>(std::max(1LL, Value(argc, argv, i)));
    }
    else if (arg == "--resolution")
    {
      o.Resolution = static_cast<int>(std::max(16LL, Value(argc, argv, i)));
    }
    else if (arg == "--repeat")
    {
      o.Repeat = static_cast<int>(std::max(1LL, Value(argc, argv, i)));
    }
    else if (arg == "--hemicube")
    {
      o.Hemicube = static_cast<int>(std::max(8LL, Value(argc, argv, i)));
    }
    else if (arg == "--hemisphere-vertices")
    {
      o.HemisphereVertices = std::max(0LL, Value(argc, argv, i));
    }
    else if (arg == "--samples")
    {
      o.Samples = static_cast<int>(std::max(0LL, Value(argc, argv, i)));
    }
    else if (arg == "--bias" && i + 1 < argc)
    {
      o.Bias = std::atof(argv[++i]);
    }
    else
    {
      std::cerr
        << "usage: vtkaoBakeBench [--input MESH.vtp] [--vertices N] [--directions K] "
           "[--resolution R] [--repeat P] [--hemicube N] [--hemisphere-vertices M] [--samples S] "
           "[--bias B] [--write-mesh FILE.vtp]\n";
      return false;
    }
  }
  return true;
}

// The mesh of --input, else the hills and torus; written to --write-mesh if asked. nullptr
// (after a message) when the input cannot be read.
vtkSmartPointer<vtkPolyData> LoadMesh(const BenchOptions& o)
{
  vtkSmartPointer<vtkPolyData> mesh;
  if (!o.Input.empty())
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(o.Input.c_str());
    reader->Update();
    mesh = reader->GetOutput();
    if (!mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "vtkaoBakeBench: cannot read '" << o.Input << "'\n";
      return nullptr;
    }
  }
  else
  {
    mesh = MakeMesh(o.Vertices);
  }
  if (!o.WriteMesh.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(o.WriteMesh.c_str());
    writer->Write();
  }
  return mesh;
}

// Context and shaders made on a small mesh, so that the timings are the bakes themselves.
void WarmUp(vtkRenderWindow* window)
{
  vtkSmartPointer<vtkPolyData> small = MakeMesh(500);
  for (int gpu = 0; gpu < 2; ++gpu)
  {
    vtkNew<vtkAOSattlerBaker> warm;
    warm->SetInputData(small);
    warm->SetNumberOfDirections(2);
    warm->SetPointTest(
      gpu ? vtkAOSattlerBaker::POINT_TEST_AUTOMATIC : vtkAOSattlerBaker::POINT_TEST_CPU);
    warm->SetRenderWindow(window);
    warm->Update();
  }
  vtkNew<vtkAOHemisphereBaker> warm;
  warm->SetInputData(FirstVertices(small, 20));
  warm->SetRenderWindow(window);
  warm->Update();
}

// Sattler, GPU then CPU point test, repeated; the best time of each, and the bits that differ.
void BenchSattler(vtkPolyData* mesh, vtkRenderWindow* window, const BenchOptions& o)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<std::uint32_t> bits[2];
  double best[2][3] = { { 1e30, 0, 0 }, { 1e30, 0, 0 } }; // total, draw, test
  vtkIdType triangles = 0;
  int used[2] = { 0, 0 };
  for (int run = 0; run < 2 * o.Repeat; ++run)
  {
    const int gpu = 1 - run % 2;
    vtkNew<vtkAOSattlerBaker> sattler;
    sattler->SetRenderWindow(window);
    sattler->SetInputData(mesh);
    sattler->SetNumberOfDirections(o.Directions);
    sattler->SetResolution(o.Resolution);
    sattler->SetBias(o.Bias);
    sattler->SetPointTest(
      gpu ? vtkAOSattlerBaker::POINT_TEST_AUTOMATIC : vtkAOSattlerBaker::POINT_TEST_CPU);
    sattler->Update();
    bits[gpu] = sattler->GetVisibility();
    triangles = sattler->GetNumberOfTriangles();
    used[gpu] = sattler->GetPointTestUsed();
    std::printf(
      "  run %d, %s test: %.2f s\n", run / 2 + 1, gpu ? "GPU" : "CPU", sattler->GetTotalTime());
    if (sattler->GetTotalTime() < best[gpu][0])
    {
      best[gpu][0] = sattler->GetTotalTime();
      best[gpu][1] = sattler->GetRenderTime();
      best[gpu][2] = sattler->GetTestTime();
    }
  }
  for (int gpu = 1; gpu >= 0; --gpu)
  {
    const double seconds = best[gpu][0];
    std::printf("sattler (%s test, used %s): %d directions at %d^2, %lld triangles: %.2f s = %.1f "
                "ms/direction (draw %.2f s, test %.2f s) = %.3g vertex-directions/s\n",
      gpu ? "GPU" : "CPU",
      vtkAOSattlerBaker::GetPointTestAsString(used[gpu]),
      o.Directions,
      o.Resolution,
      static_cast<long long>(triangles),
      seconds,
      1000.0 * seconds / o.Directions,
      best[gpu][1],
      best[gpu][2],
      static_cast<double>(n) * o.Directions / std::max(1e-9, seconds));
  }
  long long differing = 0;
  for (size_t w = 0; w < std::min(bits[0].size(), bits[1].size()); ++w)
  {
    differing += __builtin_popcount(bits[0][w] ^ bits[1][w]);
  }
  std::printf("sattler: %lld of %lld visibility bits differ between the GPU and the CPU test\n",
    differing,
    static_cast<long long>(n) * o.Directions);
}

// The hemicube on the first vertices (every triangle of the mesh occludes).
void BenchHemisphere(vtkPolyData* mesh, vtkRenderWindow* window, const BenchOptions& o)
{
  vtkNew<vtkAOHemisphereBaker> hemisphere;
  hemisphere->SetRenderWindow(window);
  hemisphere->SetInputData(
    FirstVertices(mesh, std::min<vtkIdType>(mesh->GetNumberOfPoints(), o.HemisphereVertices)));
  hemisphere->AddOccluderData(mesh);
  hemisphere->SetResolution(o.Hemicube);
  hemisphere->SetBias(o.Bias);
  hemisphere->Update();
  std::printf("hemisphere: %lld vertices (%d^2 hemicube), %lld triangles: %.2f s (render %.2f "
              "s) = %.3g vertices/s\n",
    static_cast<long long>(hemisphere->GetNumberOfRenderedPoints()),
    o.Hemicube,
    static_cast<long long>(hemisphere->GetNumberOfTriangles()),
    hemisphere->GetTotalTime(),
    hemisphere->GetRenderTime(),
    hemisphere->GetVerticesPerSecond());
}

#ifdef VTKAO_HAS_REFERENCE
// The ray caster, binary falloff, R = 1e4.
void BenchRaycast(vtkPolyData* mesh, const BenchOptions& o)
{
  vtkNew<vtkAOVertexBaker> rays;
  rays->SetInputData(mesh);
  rays->SetFalloffToBinary();
  rays->SetRadius(1e4);
  rays->SetBias(o.Bias);
  rays->SetSamples(o.Samples);
  rays->Update();
  std::printf("raycast: %d rays/vertex, %lld rays in %.2f s = %.3g rays/s\n",
    o.Samples,
    static_cast<long long>(rays->GetNumberOfRays()),
    rays->GetTraceTime(),
    rays->GetNumberOfRays() / std::max(1e-9, rays->GetTraceTime()));
}
#endif

int main(int argc, char* argv[])
{
  BenchOptions o;
  if (!ParseArguments(argc, argv, o))
  {
    return 2;
  }
  vtkSmartPointer<vtkPolyData> mesh = LoadMesh(o);
  if (!mesh)
  {
    return 1;
  }
  std::printf("mesh: %lld vertices, %lld polygons; bias %g\n",
    static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()),
    o.Bias);

  // One off-screen window for every baker.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(16, 16);
  vtkNew<vtkRenderer> empty;
  window->AddRenderer(empty);
  window->Render();
  WarmUp(window);
  BenchSattler(mesh, window, o);
  if (o.HemisphereVertices > 0)
  {
    BenchHemisphere(mesh, window, o);
  }
#ifdef VTKAO_HAS_REFERENCE
  if (o.Samples > 0)
  {
    BenchRaycast(mesh, o);
  }
#endif
  return 0;
}
