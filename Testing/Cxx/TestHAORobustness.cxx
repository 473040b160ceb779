// The pass in a real application: empty renderers, a single point, NaN coordinates,
// translucent props, resizes, two viewports, release-and-render-again.
#include "vtkAOTestUtilities.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <limits>

int TestHAORobustness(int, char*[])
{
  using namespace vtkAOTest;
  auto win = MakeWindow(300, 300);

  // Empty renderer: a plain render, no occlusion, no error.
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  auto hao = InstallHAO(ren);
  win->Render();
  Check(!hao->GetLastFrameHadOcclusion(), "empty renderer: plain render");

  // A single point: degenerate bounds, plain render.
  vtkNew<vtkPolyData> point;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(1, 2, 3);
  point->SetPoints(pts);
  vtkNew<vtkCellArray> verts;
  vtkIdType id = 0;
  verts->InsertNextCell(1, &id);
  point->SetVerts(verts);
  vtkSmartPointer<vtkActor> pointActor = AddSurface(ren, point);
  win->Render();
  Check(!hao->GetLastFrameHadOcclusion(), "a single point: plain render");
  ren->RemoveActor(pointActor);

  // NaN coordinates: that prop is ignored with a warning, the rest still gets AO.
  vtkNew<vtkPolyData> nanMesh;
  vtkNew<vtkPoints> nanPts;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  nanPts->InsertNextPoint(nan, 0, 0);
  nanPts->InsertNextPoint(1, nan, 0);
  nanPts->InsertNextPoint(0, 1, 0);
  nanMesh->SetPoints(nanPts);
  vtkNew<vtkCellArray> tri;
  vtkIdType ids[3] = { 0, 1, 2 };
  tri->InsertNextCell(3, ids);
  nanMesh->SetPolys(tri);
  AddSurface(ren, nanMesh);
  AddSphereOnGround(ren);
  hao->SetRadius(2.0);
  win->Render();
  Check(hao->GetLastFrameHadOcclusion(), "NaN prop ignored, the rest has occlusion");
  // 300 px: 34.3 px per unit; ground beside the sphere at 1.15 units -> x = 150 + 40.
  const double ring = MeanAO(hao, 190, 146, 195, 154);
  const double open = MeanAO(hao, 10, 10, 30, 30);
  Check(ring >= 0 && ring < open - 0.08, "contact occlusion with a NaN prop present");

  // A translucent sphere neither occludes nor breaks the image.
  vtkSmartPointer<vtkActor> glass = AddSphere(ren, -3, -3);
  glass->GetProperty()->SetOpacity(0.3);
  win->Render();
  const double underGlass = MeanAO(hao, 41, 41, 46, 46); // ground beside (-3,-3)
  Check(hao->GetLastFrameHadOcclusion() && underGlass > 0.95,
    "translucent props do not occlude (A beside it " + std::to_string(underGlass) + ")");

  // Resize: the AO image follows the window.
  win->SetSize(200, 160);
  win->Render();
  vtkNew<vtkImageData> image;
  Check(hao->GetAmbientOcclusionImage(image) && image->GetDimensions()[0] == 200 &&
      image->GetDimensions()[1] == 160,
    "resize: the AO image is 200 x 160");

  // Release and render again.
  win->SetSize(300, 300);
  win->Render();
  const long long before = hao->GetGraphicsMemorySize();
  ren->ReleaseGraphicsResources(win);
  Check(before > 0 && hao->GetGraphicsMemorySize() == 0,
    "ReleaseGraphicsResources frees every texture the stages own (" + std::to_string(before) +
      " bytes before)");
  win->Render();
  Check(hao->GetGraphicsMemorySize() == before, "rendering again allocates the same textures");
  const double ringAgain = MeanAO(hao, 190, 146, 195, 154);
  Check(std::abs(ringAgain - ring) < 0.02, "release then render again gives the same occlusion");

  // Two viewports, each with its pass.
  ren->SetViewport(0, 0, 0.5, 1);
  vtkNew<vtkRenderer> ren2;
  ren2->SetViewport(0.5, 0, 1, 1);
  win->AddRenderer(ren2);
  AddSphereOnGround(ren2);
  auto hao2 = InstallHAO(ren2, 2.0);
  win->Render();
  Check(hao->GetLastFrameHadOcclusion() && hao2->GetLastFrameHadOcclusion(),
    "two viewports: both passes apply occlusion");
  vtkNew<vtkImageData> half;
  Check(hao2->GetAmbientOcclusionImage(half) && half->GetDimensions()[0] == 150,
    "the second viewport's AO image is its own size");

  ren->ReleaseGraphicsResources(win);
  ren2->ReleaseGraphicsResources(win);
  return Result();
}
