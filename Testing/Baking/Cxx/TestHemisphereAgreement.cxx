// vtkAOHemisphereBaker against the ray-cast baker (vtkAOVertexBaker, Embree) on the scene of
// TestSattlerAgreement (a floor, a resting ball, a sunk box; 1 435 vertices): binary falloff,
// the same bias, 2048 cosine-weighted rays per vertex, at R = 1e4 (every surface) and R = 1,
// hemicube resolution 32. Measured with llvmpipe: RMSE 0.0025 and 0.0012, 99th-percentile
// error 0.010 and 0.005. Bounds: RMSE <= 0.006, p99 <= 0.025 (about 2.5x the measurement; the
// reference's own noise is sqrt(A (1 - A) / 2048) <= 0.011 per vertex, the hemicube's
// discretisation at resolution 32 about 0.003 in the closed-form cases of TestHemisphereBaker).
// Missing occluders, a missing face or wrong pixel weights give errors of 0.03 and more.
// Prints the error and the throughput (vertices per second, rays per second).
#include "vtkAOHemisphereBaker.h"
#include "vtkAOTestChecks.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOVertexBaker.h"
#include "vtkaoBakingScene.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace vtkAOTest;

int TestHemisphereAgreement(int, char*[])
{
  // The scene of TestSattlerAgreement: a floor of 31 x 31 points, a ball of radius 0.5 half a
  // unit above it and a box sunk into it (1 435 points).
  vtkSmartPointer<vtkPolyData> mesh = vtkao::FloorBallAndSunkBox(30, 0.5, 16);
  const double bias = 0.01;

  std::printf(
    "%8s %10s %8s %8s %8s %12s\n", "R", "resolution", "RMSE", "p99", "seconds", "vertices/s");
  double rmse32[2] = { 1, 1 }, p99At32[2] = { 1, 1 };
  const double radii[2] = { 1e4, 1.0 };
  for (int r = 0; r < 2; ++r)
  {
    vtkNew<vtkAOVertexBaker> rays;
    vtkDataArray* reference = BakeBinaryReference(rays.Get(), mesh, radii[r], bias, 2048);
    std::printf("ray-cast baker, R = %g: %lld rays in %.3f s = %.3g rays/s\n",
      radii[r],
      static_cast<long long>(rays->GetNumberOfRays()),
      rays->GetTraceTime(),
      rays->GetNumberOfRays() / std::max(1e-9, rays->GetTraceTime()));
    {
      const int resolution = 32;
      vtkNew<vtkAOHemisphereBaker> baker;
      baker->SetInputData(mesh);
      baker->SetResolution(resolution);
      baker->SetBias(bias);
      baker->SetRadius(radii[r] < 1e3 ? radii[r] : 0.0);
      baker->Update();
      const Difference error = Compare(PointArray(baker), reference);
      const double rmse = error.RMS;
      const double p99 = error.P99;
      std::printf("%8g %10d %8.4f %8.4f %8.3f %12.4g\n",
        radii[r],
        resolution,
        rmse,
        p99,
        baker->GetTotalTime(),
        baker->GetVerticesPerSecond());
      rmse32[r] = rmse;
      p99At32[r] = p99;
    }
  }
  Check(rmse32[0] <= 0.006 && p99At32[0] <= 0.025,
    "R = infinity, resolution 32: RMSE " + std::to_string(rmse32[0]) + " <= 0.006, p99 " +
      std::to_string(p99At32[0]) + " <= 0.025");
  Check(rmse32[1] <= 0.006 && p99At32[1] <= 0.025,
    "R = 1, resolution 32: RMSE " + std::to_string(rmse32[1]) + " <= 0.006, p99 " +
      std::to_string(p99At32[1]) + " <= 0.025");
  return Result();
}
