// The vertex baker computes the same A as the reference at a vertex where both are defined,
// with cosine and uniform sampling alike; extra occluders on port 1 occlude; open surfaces
// stay at A = 1; closed-form values hold per vertex; unused points, NaN points and
// degenerate triangles give A = 1 without harming their neighbours.
#include "vtkAOReferenceRenderer.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOTestUtilities.h"
#include "vtkAOVertexBaker.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataCollection.h"

#include <algorithm>
#include <limits>

using namespace vtkAOTest;

namespace
{
// Bakes @p input under @p occluder: binary falloff, R = 1, bias 1e-5, @p samples rays.
vtkFloatArray* BakeBinary(vtkAOVertexBaker* baker,
  vtkPolyData* input,
  vtkPolyData* occluder,
  int samples)
{
  baker->SetInputData(input);
  baker->AddOccluderData(occluder);
  baker->SetRadius(1);
  baker->SetBias(1e-5);
  baker->SetFalloffToBinary();
  baker->SetSamples(samples);
  baker->Update();
  return PointArray(baker);
}
}

int TestVertexBaker(int, char*[])
{
  // A floor (20 x 20 cells over 8 x 8) with a unit sphere resting on it as an extra occluder.
  vtkSmartPointer<vtkPolyData> floor = HorizontalSquare(0, 0, 4, 0, 20);
  vtkSmartPointer<vtkPolyData> sphere = Sphere(0, 1, 0, 1, 32);

  vtkNew<vtkAOVertexBaker> baker;
  baker->SetInputData(floor);
  baker->AddOccluderData(sphere);
  baker->SetRadius(2.0);
  baker->SetBias(1e-4);
  baker->SetSamples(1024);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&progressEvents);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* client, void*) { ++*static_cast<int*>(client); });
  baker->AddObserver(vtkCommand::ProgressEvent, progress);
  baker->Update();
  vtkFloatArray* ao = PointArray(baker);
  Check(ao && ao->GetNumberOfTuples() == floor->GetNumberOfPoints(), "one A per point");
  if (!ao)
  {
    return Result();
  }
  Check(progressEvents >= 2, "progress events were sent");
  Check(baker->GetNumberOfRays() == 1024 * floor->GetNumberOfPoints(), "ray count");
  const float lo =
    *std::min_element(ao->GetPointer(0), ao->GetPointer(0) + ao->GetNumberOfValues());
  const float hi =
    *std::max_element(ao->GetPointer(0), ao->GetPointer(0) + ao->GetNumberOfValues());
  Check(lo >= 0.0f && hi <= 1.0f, "A in [0, 1]");

  // The vertex at (0.8, 0, 0) beside the sphere: baker and reference agree.
  const double beside[3] = { 0.8, 0, 0 };
  const vtkIdType vertex = Nearest(floor, beside);
  double p[3];
  floor->GetPoint(vertex, p);
  vtkNew<vtkAOReferenceRenderer> reference;
  reference->SetRadius(2.0);
  reference->SetBias(1e-4);
  reference->SetSamples(4096);
  vtkNew<vtkPolyDataCollection> scene;
  scene->AddItem(floor);
  scene->AddItem(sphere);
  reference->BuildScene(scene);
  const double up[3] = { 0, 1, 0 };
  const double expected = reference->ComputeAO(p, up);
  Check(
    expected < 0.8, "the vertex beside the sphere is occluded (" + std::to_string(expected) + ")");
  CheckNear(ao->GetValue(vertex), expected, 0.02, "baker = reference beside the sphere");
  const double corner[3] = { -4, 0, -4 };
  CheckNear(ao->GetValue(Nearest(floor, corner)), 1.0, 1e-6, "far corner open");

  // Uniform sampling weighted by the cosine estimates the same integral.
  baker->SetSamplingToUniform();
  baker->SetSamples(4096);
  baker->Update();
  CheckNear(PointArray(baker)->GetValue(vertex), expected, 0.02, "uniform sampling = reference");
  baker->SetSamplingToCosine();

  // Without the occluder the floor alone is open everywhere.
  baker->RemoveAllOccluders();
  baker->SetSamples(64);
  baker->SetArrayName("Open");
  baker->Update();
  vtkFloatArray* open = PointArray(baker, "Open");
  Check(open &&
      *std::min_element(open->GetPointer(0), open->GetPointer(0) + open->GetNumberOfValues()) ==
        1.0f,
    "a lone plane is open at every vertex (array renamed)");

  // Closed form per vertex: the floor under a ceiling at H = 0.5 (binary, R = 1) -> 0.25.
  {
    vtkNew<vtkAOVertexBaker> ceiling;
    vtkFloatArray* a =
      BakeBinary(ceiling, HorizontalSquare(0, 0, 0.2, 0), HorizontalSquare(0, 0, 3, 0.5), 2048);
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    {
      CheckNear(a->GetValue(i), 0.25, 0.01, "ceiling, vertex " + std::to_string(i));
    }
  }

  // Robustness: an unused point, a NaN point, a degenerate triangle and duplicated vertices
  // (each quad with its own four points, no normals: they are computed).
  {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> polys;
    for (int q = 0; q < 2; ++q)
    {
      const double x = q; // two unit quads side by side, at y = 0
      const vtkIdType b = points->GetNumberOfPoints();
      points->InsertNextPoint(x, 0, 0);
      points->InsertNextPoint(x, 0, 1);
      points->InsertNextPoint(x + 1, 0, 1);
      points->InsertNextPoint(x + 1, 0, 0);
      const vtkIdType quad[4] = { b, b + 1, b + 2, b + 3 };
      polys->InsertNextCell(4, quad);
    }
    const vtkIdType unused = points->InsertNextPoint(5, 5, 5);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const vtkIdType bad = points->InsertNextPoint(nan, 0, 0);
    const vtkIdType nanTriangle[3] = { 0, 1, bad };
    polys->InsertNextCell(3, nanTriangle);
    const vtkIdType degenerate[3] = { 0, 0, 1 };
    polys->InsertNextCell(3, degenerate);
    vtkNew<vtkPolyData> messy;
    messy->SetPoints(points);
    messy->SetPolys(polys);
    vtkNew<vtkAOVertexBaker> robust;
    vtkFloatArray* a = BakeBinary(robust, messy, HorizontalSquare(1, 0.5, 3, 0.5), 1024);
    Check(a && a->GetNumberOfTuples() == messy->GetNumberOfPoints(), "messy input baked");
    if (a)
    {
      CheckNear(a->GetValue(unused), 1.0, 0, "unused point: A = 1");
      CheckNear(a->GetValue(bad), 1.0, 0, "NaN point: A = 1");
      for (vtkIdType i = 0; i < 8; ++i)
      {
        CheckNear(a->GetValue(i), 0.25, 0.02, "duplicated-vertex quad point " + std::to_string(i));
      }
    }
  }
  return Result();
}
