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

int main(int argc, char* argv[])
{
  std::string input, writeMesh;
  long long vertices = 100000, hemisphereVertices = 200;
  int directions = 64, resolution = 1024, hemicube = 64, samples = 64, repeat = 1;
  double bias = 0.02;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--input" && i + 1 < argc)
    {
      input = argv[++i];
    }
    else if (arg == "--write-mesh" && i + 1 < argc)
    {
      writeMesh = argv[++i];
    }
    else if (arg == "--vertices")
    {
      vertices = std::max(100LL, Value(argc, argv, i));
    }
    else if (arg == "--directions")
    {
      directions = static_cast<int>(std::max(1LL, Value(argc, argv, i)));
    }
    else if (arg == "--resolution")
    {
      resolution = static_cast<int>(std::max(16LL, Value(argc, argv, i)));
    }
    else if (arg == "--repeat")
    {
      repeat = static_cast<int>(std::max(1LL, Value(argc, argv, i)));
    }
    else if (arg == "--hemicube")
    {
      hemicube = static_cast<int>(std::max(8LL, Value(argc, argv, i)));
    }
    else if (arg == "--hemisphere-vertices")
    {
      hemisphereVertices = std::max(0LL, Value(argc, argv, i));
    }
    else if (arg == "--samples")
    {
      samples = static_cast<int>(std::max(0LL, Value(argc, argv, i)));
    }
    else if (arg == "--bias" && i + 1 < argc)
    {
      bias = std::atof(argv[++i]);
    }
    else
    {
      std::cerr
        << "usage: vtkaoBakeBench [--input MESH.vtp] [--vertices N] [--directions K] "
           "[--resolution R] [--repeat P] [--hemicube N] [--hemisphere-vertices M] [--samples S] "
           "[--bias B] [--write-mesh FILE.vtp]\n";
      return 2;
    }
  }

  vtkSmartPointer<vtkPolyData> mesh;
  if (!input.empty())
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(input.c_str());
    reader->Update();
    mesh = reader->GetOutput();
    if (!mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "vtkaoBakeBench: cannot read '" << input << "'\n";
      return 1;
    }
  }
  else
  {
    mesh = MakeMesh(vertices);
  }
  if (!writeMesh.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(writeMesh.c_str());
    writer->Write();
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::printf("mesh: %lld vertices, %lld polygons; bias %g\n",
    static_cast<long long>(n),
    static_cast<long long>(mesh->GetNumberOfPolys()),
    bias);

  // One off-screen window for every baker, warmed up (context, shaders) on a small mesh so that
  // the timings below are the bakes themselves.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(16, 16);
  vtkNew<vtkRenderer> empty;
  window->AddRenderer(empty);
  window->Render();
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

  // Sattler, GPU then CPU point test, repeated; the best of each.
  std::vector<std::uint32_t> bits[2];
  double best[2][3] = { { 1e30, 0, 0 }, { 1e30, 0, 0 } }; // total, draw, test
  vtkIdType triangles = 0;
  int used[2] = { 0, 0 };
  for (int run = 0; run < 2 * repeat; ++run)
  {
    const int gpu = 1 - run % 2;
    vtkNew<vtkAOSattlerBaker> sattler;
    sattler->SetRenderWindow(window);
    sattler->SetInputData(mesh);
    sattler->SetNumberOfDirections(directions);
    sattler->SetResolution(resolution);
    sattler->SetBias(bias);
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
      directions,
      resolution,
      static_cast<long long>(triangles),
      seconds,
      1000.0 * seconds / directions,
      best[gpu][1],
      best[gpu][2],
      static_cast<double>(n) * directions / std::max(1e-9, seconds));
  }
  long long differing = 0;
  for (size_t w = 0; w < std::min(bits[0].size(), bits[1].size()); ++w)
  {
    differing += __builtin_popcount(bits[0][w] ^ bits[1][w]);
  }
  std::printf("sattler: %lld of %lld visibility bits differ between the GPU and the CPU test\n",
    differing,
    static_cast<long long>(n) * directions);

  // The hemicube on the first vertices.
  if (hemisphereVertices > 0)
  {
    vtkNew<vtkAOHemisphereBaker> hemisphere;
    hemisphere->SetRenderWindow(window);
    hemisphere->SetInputData(FirstVertices(mesh, std::min<vtkIdType>(n, hemisphereVertices)));
    hemisphere->AddOccluderData(mesh);
    hemisphere->SetResolution(hemicube);
    hemisphere->SetBias(bias);
    hemisphere->Update();
    std::printf("hemisphere: %lld vertices (%d^2 hemicube), %lld triangles: %.2f s (render %.2f "
                "s) = %.3g vertices/s\n",
      static_cast<long long>(hemisphere->GetNumberOfRenderedPoints()),
      hemicube,
      static_cast<long long>(hemisphere->GetNumberOfTriangles()),
      hemisphere->GetTotalTime(),
      hemisphere->GetRenderTime(),
      hemisphere->GetVerticesPerSecond());
  }

#ifdef VTKAO_HAS_REFERENCE
  if (samples > 0)
  {
    vtkNew<vtkAOVertexBaker> rays;
    rays->SetInputData(mesh);
    rays->SetFalloffToBinary();
    rays->SetRadius(1e4);
    rays->SetBias(bias);
    rays->SetSamples(samples);
    rays->Update();
    std::printf("raycast: %d rays/vertex, %lld rays in %.2f s = %.3g rays/s\n",
      samples,
      static_cast<long long>(rays->GetNumberOfRays()),
      rays->GetTraceTime(),
      rays->GetNumberOfRays() / std::max(1e-9, rays->GetTraceTime()));
  }
#endif
  return 0;
}
