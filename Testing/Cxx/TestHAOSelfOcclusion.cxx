// A surface never occludes itself, whatever the bias and the radius, and contacts are darkest
// at the contact (issue 16, item 4). Closed forms:
// - a lone plane, closed cylinder or sphere (convex or flat) has A = 1 at every point: asserted for
//   tilted planes and cylinders at several orientations, with Bias = 0, a tiny bias and a
//   bias of a few cells, at R = 0.5 and at a huge R (1000);
// - a sphere of radius a resting on a plane occludes a plane point at distance D from its
//   centre by (a / D)^2 cos(beta) = a^3 / D^3 (binary falloff, R beyond the sphere): asserted
//   at distances from the contact down to 0.15 a, where the old start-run skip left a light
//   band.
#include "vtkAOTestUtilities.h"

#include "vtkCylinderSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cmath>

namespace
{
using namespace vtkAOTest;

// Covered pixels' A of the last frame, sorted.
std::vector<float> CoveredAO(vtkHybridAmbientOcclusionPass* hao)
{
  std::vector<float> values;
  vtkNew<vtkImageData> image;
  if (!hao->GetAmbientOcclusionImage(image))
  {
    return values;
  }
  auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (a->GetTypedComponent(i, 1) > 0.5f)
    {
      values.push_back(a->GetTypedComponent(i, 0));
    }
  }
  std::sort(values.begin(), values.end());
  return values;
}

// A lone surface turned by @p tilt about x then @p turn about y, seen from an oblique camera.
void LoneSurface(vtkRenderer* ren, int shape, double tilt, double turn)
{
  ren->RemoveAllViewProps();
  vtkNew<vtkTransform> transform;
  transform->RotateY(turn);
  transform->RotateX(tilt);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetTransform(transform);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, 0, -1);
  plane->SetPoint1(-1, 0, 1);
  plane->SetPoint2(1, 0, -1);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(0.4);
  cylinder->SetHeight(2);
  cylinder->SetResolution(40);
  cylinder->CappingOn(); // closed: its inside is not seen
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.7);
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  move->SetInputConnection(shape == 0 ? plane->GetOutputPort()
      : shape == 1                    ? cylinder->GetOutputPort()
                                      : sphere->GetOutputPort());
  AddActor(ren, move);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(2.5, 3.5, 4.0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();
}

// Mean A over a small box of pixels around the world point @p p.
double AOAt(vtkHybridAmbientOcclusionPass* hao, vtkRenderer* ren, const double p[3], int half)
{
  ren->SetWorldPoint(p[0], p[1], p[2], 1.0);
  ren->WorldToDisplay();
  const double* d = ren->GetDisplayPoint();
  const int x = static_cast<int>(d[0]), y = static_cast<int>(d[1]);
  return MeanAO(hao, x - half, y - half, x + half + 1, y + half + 1);
}
}

int TestHAOSelfOcclusion(int, char*[])
{
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(240, 240, ren);
  auto hao = InstallHAO(ren);
  hao->SetFalloffToBinary();

  // 1. Lone surfaces: A = 1.
  const char* names[3] = { "plane", "cylinder", "sphere" };
  const double orientations[5][2] = { { 0, 0 }, { 12, 25 }, { 37, 61 }, { 63, 14 }, { 81, 47 } };
  for (int shape = 0; shape < 3; ++shape)
  {
    for (const auto& o : orientations)
    {
      if (shape == 2 && o[0] != 0)
      {
        continue; // a sphere has one orientation
      }
      for (double radius : { 0.5, 1000.0 })
      {
        for (double bias : { 0.0, 1e-4, 0.05 })
        {
          LoneSurface(ren, shape, o[0], o[1]);
          hao->SetRadius(radius);
          hao->SetBias(bias);
          win->Render();
          const std::vector<float> a = CoveredAO(hao);
          if (a.empty())
          {
            Check(false, std::string("no covered pixels for the ") + names[shape]);
            continue;
          }
          double mean = 0;
          for (float v : a)
          {
            mean += v;
          }
          mean /= a.size();
          const double p1 = a[a.size() / 100];
          char what[256];
          std::snprintf(what,
            sizeof(what),
            "lone %s tilted %g, turned %g, R %g, bias %g: mean A %.4f >= 0.99, 1st percentile "
            "%.3f >= 0.9 (grid %d)",
            names[shape],
            o[0],
            o[1],
            radius,
            bias,
            mean,
            p1,
            hao->GetEffectiveVoxelResolution());
          std::printf("%s\n", what);
          Check(mean >= 0.99 && p1 >= 0.9, what);
        }
      }
    }
  }

  // 2. A sphere (a = 0.5) resting on a plane, R = 2 (beyond the whole sphere from every
  // point tested): A = 1 - a^3 / D^3 on the plane, D the distance to the sphere's centre.
  ren->RemoveAllViewProps();
  AddGround(ren, 3);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0.5, 0);
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  AddActor(ren, sphere);
  // Looking down from above the sphere's side.
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0.45, 0, 0);
  cam->SetPosition(0.45, 3.2, 0.0001);
  cam->SetViewUp(0, 0, -1);
  cam->SetViewAngle(40);
  ren->ResetCameraClippingRange();
  win->SetSize(400, 400);
  hao->SetRadius(2.0);
  hao->SetNumberOfRays(32);
  for (double bias : { 0.0, 1e-4 })
  {
    hao->SetBias(bias);
    win->Render();
    // Plane points at distance d beyond the sphere's silhouette (x = 0.5), on the x axis;
    // the camera looks down from above x = 0.45, so they are seen right beside the sphere.
    for (double d : { 0.03, 0.075, 0.15, 0.3, 0.6 })
    {
      const double p[3] = { 0.5 + d, 0, 0 };
      const double distance = std::sqrt(p[0] * p[0] + 0.25);
      const double exact = 1.0 - 0.125 / (distance * distance * distance);
      const double measured = AOAt(hao, ren, p, 2);
      char what[200];
      std::snprintf(what,
        sizeof(what),
        "bias %g: plane %.3f from the sphere's foot: A %.3f, exact %.3f (within 0.08)",
        bias,
        p[0],
        measured,
        exact);
      std::printf("%s\n", what);
      Check(measured >= 0 && std::abs(measured - exact) <= 0.08, what);
    }
  }
  ren->ReleaseGraphicsResources(win);
  return Result();
}
