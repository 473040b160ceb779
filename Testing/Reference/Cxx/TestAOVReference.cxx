// Ambient Occlusion Volumes against the ray-traced reference, pixel by pixel, on a scene that
// exercises what the volumes must get right besides the form factor itself:
// - a unit sphere resting on an open ground plane (contact occlusion both ways);
// - a box built from six independently wound quads (inconsistent winding: the pass must orient
//   the closed component itself, or the faces turned inwards occlude nothing);
// - a mirrored actor (negative scale: the winding of its closed mesh flips in world space);
// - cube glyphs drawn by a vtkGlyph3DMapper (the volumes need the expanded glyphs);
// - a wall entirely outside the view, right beside the visible ground.
// The reference is traced with the pass's own radius and bias. The test fails when any of
// these is broken (each was checked by breaking it): the RMSE over covered pixels and the
// mean error beside each occluder are bounded (AOV - reference within 0.1 x the occlusion
// there + 0.005).
#include "vtkAOReferenceRenderer.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <vector>

namespace
{
using namespace vtkAOTest;

// An axis-aligned box of six quads with separate points, half of them wound the wrong way
// (as a careless exporter writes them).
vtkSmartPointer<vtkPolyData> CarelessBox(const double b[6])
{
  const double c[8][3] = { { b[0], b[2], b[4] },
    { b[1], b[2], b[4] },
    { b[1], b[3], b[4] },
    { b[0], b[3], b[4] },
    { b[0], b[2], b[5] },
    { b[1], b[2], b[5] },
    { b[1], b[3], b[5] },
    { b[0], b[3], b[5] } };
  // Three faces wound with their normals inwards (-z, +z, +x), three outwards.
  const int faces[6][4] = {
    { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 1, 5, 4 }, { 1, 5, 6, 2 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 }
  };
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  for (const auto& face : faces)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(c[face[k]]);
    }
    quads->InsertNextCell(4, ids);
  }
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->SetPoints(points);
  box->SetPolys(quads);
  return box;
}

// Mean of (aov - reference) and the reference's mean occlusion over a pixel box.
void BoxError(const AOImage& aov,
  const AOImage& ref,
  int x0,
  int y0,
  int x1,
  int y1,
  double& error,
  double& occlusion)
{
  error = occlusion = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const size_t i = static_cast<size_t>(y) * aov.W + x;
      if (ref.Coverage[i] > 0.5f && aov.Coverage[i] > 0.5f)
      {
        error += aov.A[i] - ref.A[i];
        occlusion += 1.0 - ref.A[i];
        ++n;
      }
    }
  }
  error = n ? error / n : 1.0;
  occlusion = n ? occlusion / n : 0.0;
}
}

int TestAOVReference(int, char*[])
{
  const int w = 160, h = 120;
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> win;
  win->SetOffScreenRendering(1);
  win->SetMultiSamples(0);
  win->SetSize(w, h);
  win->AddRenderer(ren);

  AddSurface(ren, HorizontalSquare(0, 0, 8, 0)); // the ground, open: two-sided
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(-1.5, 1, 0);
  ball->SetRadius(1);
  ball->SetThetaResolution(48);
  ball->SetPhiResolution(24);
  ball->Update();
  AddSurface(ren, ball->GetOutput());
  const double boxBounds[6] = { 0.8, 2.2, 0, 0.7, -1.6, -0.2 };
  AddSurface(ren, CarelessBox(boxBounds));
  // The mirrored actor: a box mirrored in x by its matrix (scale -1), standing at x = 1.5.
  const double mirrorBounds[6] = { -2.2, -0.8, 0, 0.9, 0.6, 2.0 };
  vtkActor* mirrored = AddSurface(ren, Box(mirrorBounds));
  mirrored->SetScale(-1, 1, 1);
  // Cube glyphs (0.5 wide) on four points.
  vtkNew<vtkPoints> centres;
  for (double x : { -0.4, 0.4 })
  {
    for (double z : { 2.4, 3.2 })
    {
      centres->InsertNextPoint(x - 3.0, 0.25, z - 0.3);
    }
  }
  vtkNew<vtkPolyData> glyphPoints;
  glyphPoints->SetPoints(centres);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(0.5);
  cube->SetYLength(0.5);
  cube->SetZLength(0.5);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputData(glyphPoints);
  glyphs->SetSourceConnection(cube->GetOutputPort());
  glyphs->ScalingOff();
  glyphs->OrientOff();
  vtkNew<vtkActor> glyphActor;
  glyphActor->SetMapper(glyphs);
  ren->AddActor(glyphActor);
  // A wall beyond the top edge of the view (z < -3.1 is off screen), on the ground.
  const double wallBounds[6] = { -4, 4, 0, 1.5, -4.0, -3.6 };
  AddSurface(ren, Box(wallBounds));

  LookAt(ren, { 0, 9, 0.01 }, { 0, 0, 0 }, { 0, 0, -1 }, 38, 1, 20);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkAmbientOcclusionVolumesPass> aov;
  aov->SetDelegatePass(basic);
  aov->SetRadius(2.0);
  aov->AOOnlyOn();
  // The checks are of the geometry (orientation, mirrors, glyphs, off-screen walls), with the
  // combination that is exact for closed occluders that do not overlap: the sum. With the
  // multiplicative default the ground between the cube glyphs is 0.046 lighter than the
  // reference (several faces seen at once multiply their open fractions).
  aov->SetCombinationToAdditive();
  ren->SetPass(aov);
  win->Render();
  vtkNew<vtkImageData> aovImage;
  Check(aov->GetAmbientOcclusionImage(aovImage), "AOV produced an occlusion image");
  const AOImage a(aovImage);

  vtkNew<vtkAOReferenceRenderer> reference;
  reference->SetRadius(aov->GetEffectiveRadius());
  reference->SetBias(aov->GetEffectiveBias());
  reference->SetSamples(256);
  reference->SetWidth(w);
  reference->SetHeight(h);
  vtkNew<vtkImageData> refImage;
  Check(reference->Render(ren, refImage), "the reference traced the view");
  const AOImage r(refImage);
  if (a.A.size() != r.A.size() || a.A.empty())
  {
    Check(false, "images of the same size");
    return Result();
  }

  double sum = 0;
  int n = 0;
  for (size_t i = 0; i < a.A.size(); ++i)
  {
    if (r.Coverage[i] > 0.5f)
    {
      sum += (a.A[i] - r.A[i]) * (a.A[i] - r.A[i]);
      ++n;
    }
  }
  const double rmse = std::sqrt(sum / std::max(n, 1));
  std::printf("RMSE over %d covered pixels: %.4f (R %.3f, bias %.5f)\n",
    n,
    rmse,
    aov->GetEffectiveRadius(),
    aov->GetEffectiveBias());
  Check(rmse < 0.02, "AOV within RMSE 0.02 of the reference");

  // Beside each occluder: the mean error is small against the occlusion there. Pixel boxes
  // (x right, y up; 19.36 px per world unit on the ground): pixel x = 80 + 19.36 x,
  // pixel y = 60 - 19.36 z.
  struct Region
  {
    const char* name;
    int x0, y0, x1, y1;
  };
  const Region regions[] = {
    { "ground beside the sphere", 47, 83, 55, 85 },
    { "ground beside the careless box (+x)", 128, 74, 133, 81 },
    { "ground beside the careless box (-z)", 103, 95, 115, 99 },
    { "ground beside the mirrored box", 129, 31, 134, 38 },
    { "ground between the glyphs", 20, 10, 24, 13 },
    { "ground below the off-screen wall", 61, 115, 90, 120 },
  };
  for (const Region& g : regions)
  {
    double error = 0, occlusion = 0;
    BoxError(a, r, g.x0, g.y0, g.x1, g.y1, error, occlusion);
    std::printf("%s: reference occlusion %.3f, AOV - reference %+.4f\n", g.name, occlusion, error);
    Check(occlusion > 0.03, std::string(g.name) + ": the reference sees occlusion there");
    Check(std::fabs(error) < 0.1 * occlusion + 0.005,
      std::string(g.name) + ": AOV within a tenth of it (+0.005)");
  }
  ren->ReleaseGraphicsResources(win);
  return Result();
}
