// The reference image of a renderer's view: the camera is honoured (perspective and parallel,
// rows bottom-up as vtkHybridAmbientOcclusionPass::GetAmbientOcclusionImage), background
// pixels are A = 1 with coverage 0, every kind of prop occludes (actor matrix, composite
// input, glyphs), translucent props do not unless asked, results are deterministic per seed,
// and progress reaches 1. No render window: the reference needs no OpenGL.
#include "vtkAOReferenceRenderer.h"
#include "vtkAOTestSurfaces.h"
#include "vtkAOTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCompositePolyDataMapper.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <vector>

namespace
{
using namespace vtkAOTest;

// Camera at height 0.4 above the floor (y = 0), looking straight down, screen up = -z.
void CameraBetweenFloorAndCeiling(vtkRenderer* ren, bool parallel)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0, 0.4, 0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, -1);
  cam->SetViewAngle(60);
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(0.5);
  cam->SetClippingRange(0.01, 10);
}

struct Stats
{
  double MeanA = 0;
  double Coverage = 0;
};

Stats Measure(vtkImageData* image, int x0, int y0, int x1, int y1)
{
  auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  const int w = image->GetDimensions()[0];
  Stats s;
  int covered = 0, n = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(y) * w + x;
      ++n;
      if (a->GetTypedComponent(i, 1) > 0.5f)
      {
        s.MeanA += a->GetTypedComponent(i, 0);
        ++covered;
      }
    }
  }
  s.MeanA = covered ? s.MeanA / covered : -1;
  s.Coverage = n ? static_cast<double>(covered) / n : 0;
  return s;
}

// A square of side 2 centred at (cx, 0, cz), seen straight down from height 10 with a view
// angle that makes the view 8 units across at y = 0 (5 pixels per unit in a 40 x 40 image;
// screen right = +x, screen up = -z).
void SquareFromAbove(vtkRenderer* ren, double cx, double cz)
{
  AddSurface(ren, HorizontalSquare(cx, cz, 1, 0));
  const double angle = 2 * std::atan(0.4) * 180 / 3.141592653589793;
  LookAt(ren, { 0, 10, 0 }, { 0, 0, 0 }, { 0, 0, -1 }, angle, 1, 20);
}

// Mean A over the whole image for a floor under a ceiling prop built by @p addCeiling.
template<class F>
double CeilingScene(F addCeiling, bool parallel = false, bool translucent = false)
{
  vtkNew<vtkRenderer> ren;
  // The floor's normal points down (away from the camera): it must be flipped.
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-5, 0, -5);
  floor->SetPoint1(5, 0, -5);
  floor->SetPoint2(-5, 0, 5);
  floor->Update();
  AddSurface(ren, floor->GetOutput());
  addCeiling(ren.GetPointer());
  CameraBetweenFloorAndCeiling(ren, parallel);
  vtkNew<vtkAOReferenceRenderer> reference;
  reference->SetWidth(16);
  reference->SetHeight(12);
  reference->SetSamples(1024);
  reference->SetRadius(1.0);
  reference->SetBias(1e-5);
  reference->SetFalloffToBinary();
  reference->SetIncludeTranslucent(translucent);
  vtkNew<vtkImageData> image;
  if (!reference->Render(ren, image))
  {
    return -1;
  }
  const Stats s = Measure(image, 0, 0, 16, 12);
  return s.Coverage == 1.0 ? s.MeanA : -1;
}
}

int TestReferenceImage(int, char*[])
{
  // Orientation: a square at x in [1, 3], z in [-3, -1] seen from above (screen right = +x,
  // screen up = -z) fills the upper-right quadrant of a bottom-up image, nothing else.
  {
    vtkNew<vtkRenderer> ren;
    SquareFromAbove(ren, 2, -2);
    vtkNew<vtkAOReferenceRenderer> reference;
    reference->SetWidth(40);
    reference->SetHeight(40);
    reference->SetSamples(16);
    int progressEvents = 0;
    double lastProgress = -1;
    vtkNew<vtkCallbackCommand> progress;
    struct Progress
    {
      int* Count;
      double* Last;
    } data{ &progressEvents, &lastProgress };
    progress->SetClientData(&data);
    progress->SetCallback(
      [](vtkObject*, unsigned long, void* client, void* call)
      {
        auto* d = static_cast<Progress*>(client);
        ++*d->Count;
        *d->Last = *static_cast<double*>(call);
      });
    reference->AddObserver(vtkCommand::ProgressEvent, progress);
    vtkNew<vtkImageData> image;
    Check(reference->Render(ren, image), "render without a render window");
    Check(image->GetDimensions()[0] == 40 && image->GetDimensions()[1] == 40, "40 x 40 image");
    Check(image->GetPointData()->GetScalars()->GetNumberOfComponents() == 2, "A and coverage");
    // 5 pixels per unit: the square covers x in [25, 35), y in [25, 35).
    CheckNear(Measure(image, 26, 26, 34, 34).Coverage, 1.0, 0, "upper-right square covered");
    CheckNear(Measure(image, 0, 0, 40, 24).Coverage, 0.0, 0, "lower half empty");
    CheckNear(Measure(image, 0, 0, 24, 40).Coverage, 0.0, 0, "left half empty");
    CheckNear(Measure(image, 0, 0, 20, 20).MeanA, -1, 0, "background has no A");
    auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
    CheckNear(a->GetTypedComponent(0, 0), 1.0, 0, "background A = 1");
    CheckNear(Measure(image, 25, 25, 35, 35).Coverage, 1.0, 0, "square is 10 x 10 pixels");
    CheckNear(Measure(image, 24, 24, 36, 36).Coverage, 100.0 / 144.0, 0, "and no more");
    CheckNear(Measure(image, 25, 25, 35, 35).MeanA, 1.0, 1e-6, "a lone square is open");
    Check(progressEvents >= 2, "progress events were sent");
    CheckNear(lastProgress, 1.0, 0, "progress ends at 1");
    Check(reference->GetNumberOfRays() == 40 * 40 + 100 * 16, "ray count: primary + AO rays");
  }

  // PixelOffset moves every primary ray off its pixel's centre, in pixels. The same view as
  // above, the square moved by 0.15 (three quarters of a pixel) right and up in the image: its
  // edges lie a quarter of a pixel past the centres of columns 25 and 35 and rows 25 and 35, so it
  // covers [26, 36) x [26, 36); rays shifted by 0.45 pixel (or 0.9, clamped to 0.5) see it at [25,
  // 35) x [25, 35); a shift of 0.2 changes nothing.
  {
    vtkNew<vtkRenderer> ren;
    SquareFromAbove(ren, 2.15, -2.15);
    vtkNew<vtkAOReferenceRenderer> reference;
    reference->SetWidth(40);
    reference->SetHeight(40);
    reference->SetSamples(4);
    Check(reference->GetPixelOffset()[0] == 0 && reference->GetPixelOffset()[1] == 0,
      "PixelOffset defaults to the pixel centres");
    vtkNew<vtkImageData> image;
    for (double offset : { 0.0, 0.2, 0.45, 0.9 })
    {
      reference->SetPixelOffset(offset, offset);
      Check(reference->Render(ren, image), "render with a pixel offset");
      const int c = offset < 0.25 ? 26 : 25; // the first covered column and row
      char what[120];
      std::snprintf(what, sizeof(what), "pixel offset %g: square at [%d, %d)", offset, c, c + 10);
      CheckNear(Measure(image, c, c, c + 10, c + 10).Coverage, 1.0, 0, what);
      CheckNear(Measure(image, c - 1, c - 1, c + 11, c + 11).Coverage, 100.0 / 144.0, 0, what);
    }
  }

  // A floor under a ceiling at H = 0.5 R, seen by a camera between them: A = (H/R)^2 = 0.25
  // at every pixel, whatever makes the ceiling.
  auto plainCeiling = [](vtkRenderer* ren) { AddSurface(ren, HorizontalSquare(0, 0, 5, 0.5)); };
  CheckNear(CeilingScene(plainCeiling), 0.25, 0.01, "ceiling, perspective");
  CheckNear(CeilingScene(plainCeiling, true), 0.25, 0.01, "ceiling, parallel projection");
  CheckNear(CeilingScene([](vtkRenderer* ren)
              { AddSurface(ren, HorizontalSquare(0, 0, 5, 0))->SetPosition(0, 0.5, 0); }),
    0.25,
    0.01,
    "ceiling moved by the actor matrix");
  auto translucentCeiling = [](vtkRenderer* ren)
  { AddSurface(ren, HorizontalSquare(0, 0, 5, 0.5))->GetProperty()->SetOpacity(0.5); };
  CheckNear(CeilingScene(translucentCeiling), 1.0, 1e-6, "a translucent ceiling does not occlude");
  CheckNear(
    CeilingScene(translucentCeiling, false, true), 0.25, 0.01, "unless IncludeTranslucent is on");
  CheckNear(CeilingScene(
              [](vtkRenderer* ren)
              {
                vtkNew<vtkMultiBlockDataSet> blocks;
                blocks->SetBlock(0, HorizontalSquare(0, 0, 5, 0.5));
                vtkNew<vtkCompositePolyDataMapper> mapper;
                mapper->SetInputDataObject(blocks);
                vtkNew<vtkActor> actor;
                actor->SetMapper(mapper);
                ren->AddActor(actor);
              }),
    0.25,
    0.01,
    "ceiling in a composite dataset");
  CheckNear(CeilingScene(
              [](vtkRenderer* ren)
              {
                // One glyph: a square at y = 0.25, scaled by 2 and placed at y = 0 -> y = 0.5.
                vtkNew<vtkPolyData> points;
                vtkNew<vtkPoints> p;
                p->InsertNextPoint(0, 0, 0);
                points->SetPoints(p);
                vtkNew<vtkGlyph3DMapper> mapper;
                mapper->SetInputData(points);
                mapper->SetSourceData(HorizontalSquare(0, 0, 3, 0.25));
                mapper->SetScaleFactor(2.0);
                vtkNew<vtkActor> actor;
                actor->SetMapper(mapper);
                ren->AddActor(actor);
              }),
    0.25,
    0.01,
    "ceiling made by a glyph mapper");

  // Deterministic for a seed, different for another seed.
  {
    vtkNew<vtkRenderer> ren;
    AddSurface(ren, HorizontalSquare(0, 0, 5, 0));
    const double center[3] = { 0, 1, 0 };
    AddSurface(ren, Sphere(center, 1, 16));
    ren->GetActiveCamera()->SetPosition(0, 6, 6);
    ren->ResetCamera();
    vtkNew<vtkAOReferenceRenderer> reference;
    reference->SetWidth(24);
    reference->SetHeight(16);
    reference->SetSamples(8);
    std::vector<float> runs[3];
    for (int run = 0; run < 3; ++run)
    {
      reference->SetSeed(run == 2 ? 7 : 0);
      vtkNew<vtkImageData> image;
      reference->Render(ren, image);
      auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
      runs[run].assign(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues());
    }
    Check(runs[0] == runs[1], "the same seed gives the same image");
    Check(runs[0] != runs[2], "another seed gives another image");
    Check(reference->GetEffectiveRadius() > 0, "automatic radius");
  }
  return Result();
}
