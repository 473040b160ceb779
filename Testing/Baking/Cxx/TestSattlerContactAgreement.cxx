// vtkAOSattlerBaker agrees with the ray-cast baker where the occluders lie close to the vertices:
// contact creases (a ball and boxes sunk into a floor, a box sunk into another) and a narrow
// slot between two boxes. Binary falloff, R much larger than the scene, the same bias, 4096
// cosine-weighted rays per vertex; k = 1024 directions, 512^2 depth maps (a pixel is 1.7 times
// the bias). The per-vertex RMSE must be <= 0.01 and the 99th-percentile error <= 0.02, with no
// bias towards open (mean signed difference within 0.001).
//
// The depth test used to allow 1.5 pixels plus a slope term of up to 4 pixels on top of the
// bias, which let the occluders nearest to a vertex through: RMSE 0.0202, p99 0.049, mean
// +0.0020 on this scene (the creases too bright; all three checks fail). Now only the
// pixel-centre snapping of the vertex's own tangent plane is allowed for: RMSE 0.0044, p99
// 0.0092, mean -0.0002.
#include "vtkAOSattlerBaker.h"
#include "vtkAOTestChecks.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOVertexBaker.h"

#include "vtkAppendPolyData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace vtkAOTest;

namespace
{
// A floor (6 x 6, 0.1 spacing) with a ball sunk 0.1 into it, two boxes sunk into it 0.06 apart
// (the slot), and a flat box sunk 0.05 into the top of a third. No vertex lies on another
// surface: the box walls fall between the floor's grid lines.
vtkSmartPointer<vtkPolyData> ContactScene()
{
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputData(HorizontalSquare(0.0, 0.0, 3.0, 0.0, 60));
  const double ball[3] = { -1.0, 0.4, 0.0 };
  scene->AddInputData(Sphere(ball, 0.5, 16));
  const double boxes[4][6] = {
    { 0.53, 1.27, -0.2, 0.8, -1.17, 1.13 }, // the slot: 0.06 wide, 0.8 deep
    { 1.33, 1.87, -0.2, 0.6, -0.57, 0.73 },
    { -2.47, -1.53, -0.2, 0.4, 1.03, 2.27 }, // the lower box ...
    { -2.27, -1.73, 0.35, 0.55, 1.23, 2.07 } // ... and the flat box sunk into its top
  };
  for (const auto& bounds : boxes)
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(Box(bounds));
    triangles->Update();
    scene->AddInputData(triangles->GetOutput());
  }
  scene->Update();
  return scene->GetOutput();
}
}

int TestSattlerContactAgreement(int, char*[])
{
  vtkSmartPointer<vtkPolyData> mesh = ContactScene();
  const double bias = 0.01;

  vtkNew<vtkAOVertexBaker> rays;
  vtkDataArray* reference = BakeBinaryReference(rays.Get(), mesh, 1e4, bias, 4096);

  vtkNew<vtkAOSattlerBaker> baker;
  baker->SetInputData(mesh);
  baker->SetNumberOfDirections(1024);
  baker->SetResolution(512);
  baker->SetBias(bias);
  baker->SetSeed(1);
  baker->StoreVisibilityOff();
  baker->Update();
  vtkDataArray* baked = PointArray(baker);
  const Difference error = Compare(baked, reference);
  double mean = 0.0;
  const vtkIdType n = mesh->GetNumberOfPoints();
  for (vtkIdType i = 0; baked && reference && i < n; ++i)
  {
    mean += (baked->GetTuple1(i) - reference->GetTuple1(i)) / n;
  }
  std::printf("%lld points, k = 1024, 512^2: RMSE %.4f, p99 %.4f, max %.4f, mean %+.4f (%.2f s)\n",
    static_cast<long long>(n),
    error.RMS,
    error.P99,
    error.Maximum,
    mean,
    baker->GetTotalTime());
  Check(error.RMS <= 0.01, "RMSE " + std::to_string(error.RMS) + " <= 0.01");
  Check(error.P99 <= 0.02, "p99 " + std::to_string(error.P99) + " <= 0.02");
  Check(std::fabs(mean) <= 0.001, "mean difference " + std::to_string(mean) + " within 0.001");
  return Result();
}
