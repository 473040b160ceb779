// 2-D props (vtkActor2D: annotations, text) over occluded surfaces, with both passes. They are
// drawn after the composite, as they are: a solid rectangle (vtkPolyDataMapper2D) over the
// ground beside the sphere keeps its exact colour and a white text actor keeps white pixels,
// while the ground in front of the sphere is darkened, and the AO image under the rectangle is
// the ground's own (about 0.92 at R = 2). Drawn into the G-buffer with the surfaces, as before,
// their shaders wrote only a colour and left the normals under them undefined: llvmpipe leaves
// zeros, read as "no surface", so the AO image had a hole of A = 1 in the rectangle's shape
// (this test's first check fails); another driver may leave anything there.
#include "vtkAOTestUtilities.h"
#include "vtkActor2D.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

namespace
{
constexpr int Width = 400;
constexpr int Height = 300;

// The display box { x0, y0, x1, y1 } of the ground rectangle [x0, x1] x [z0, z1] (y = 0).
std::array<int, 4> GroundBox(vtkRenderer* ren, double x0, double z0, double x1, double z1)
{
  std::array<int, 4> box{ Width, Height, 0, 0 };
  for (double x : { x0, x1 })
  {
    for (double z : { z0, z1 })
    {
      ren->SetWorldPoint(x, 0, z, 1);
      ren->WorldToDisplay();
      const double* d = ren->GetDisplayPoint();
      box[0] = std::min(box[0], static_cast<int>(d[0]));
      box[1] = std::min(box[1], static_cast<int>(d[1]));
      box[2] = std::max(box[2], static_cast<int>(d[0]) + 1);
      box[3] = std::max(box[3], static_cast<int>(d[1]) + 1);
    }
  }
  return box;
}

// A filled rectangle in display coordinates, drawn in pure green.
vtkSmartPointer<vtkActor2D> AddRectangle(vtkRenderer* ren, const std::array<int, 4>& box)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(box[0], box[1], 0);
  points->InsertNextPoint(box[2], box[1], 0);
  points->InsertNextPoint(box[2], box[3], 0);
  points->InsertNextPoint(box[0], box[3], 0);
  vtkNew<vtkCellArray> quads;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  quads->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> rectangle;
  rectangle->SetPoints(points);
  rectangle->SetPolys(quads);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(rectangle);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0, 1, 0);
  ren->AddActor2D(actor);
  return actor;
}

template<typename Pass>
void Run(const char* what)
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.2, 0.2, 0.2);
  AddGround(ren, 5);
  AddSphere(ren, 0, 0);
  // From 31 degrees above the ground, as in TestHAOUnlitNormals: the ground beside the sphere
  // is seen and occluded.
  LookAt(ren, { 0, 6, 10 }, { 0, 0, 0 }, { 0, 1, 0 }, 40, 1, 40);
  auto win = MakeWindow(Width, Height, ren);
  win->Render(); // the camera's matrices for the boxes below

  // The contact ring, right of the sphere (under the rectangle), left (under the text) and
  // in front (plain); open ground far away.
  const auto right = GroundBox(ren, 1.1, -0.2, 1.5, 0.2);
  const auto left = GroundBox(ren, -1.6, -0.3, -1.1, 0.3);
  const auto front = GroundBox(ren, -0.2, 1.1, 0.2, 1.4);
  const auto open = GroundBox(ren, 3.2, 2.8, 3.6, 3.2);
  // Rectangle pixels one in from its edges (rasterization of the border).
  const std::array<int, 4> inner{ right[0] + 1, right[1] + 1, right[2] - 1, right[3] - 1 };
  AddRectangle(ren, right);
  vtkNew<vtkTextActor> text;
  text->SetInput("M");
  text->GetTextProperty()->SetFontSize(48);
  text->GetTextProperty()->SetColor(1, 1, 1);
  text->GetTextProperty()->BoldOn();
  text->SetDisplayPosition(left[0], left[1]);
  ren->AddActor2D(text);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<Pass> pass;
  pass->SetDelegatePass(basic);
  pass->SetRadius(2.0);
  pass->SetIntensity(4.0); // A of about 0.92 under the overlays darkens the image by 0.3
  ren->SetPass(pass);
  win->Render();
  Check(pass->GetLastFrameHadOcclusion(), std::string(what) + ": the pass applied occlusion");

  const double underRectangle = MeanAO(pass, inner.data());
  const double underText = MeanAO(pass, left.data());
  const double openAO = MeanAO(pass, open.data());
  int w = 0;
  const auto rgb = GrabRGB(win, w);
  double mean[3] = { 0, 0, 0 };
  int n = 0;
  for (int y = inner[1]; y < inner[3]; ++y)
  {
    for (int x = inner[0]; x < inner[2]; ++x, ++n)
    {
      for (int c = 0; c < 3; ++c)
      {
        mean[c] += rgb->GetTypedComponent(static_cast<vtkIdType>(y) * w + x, c) / 255.0;
      }
    }
  }
  for (double& m : mean)
  {
    m /= std::max(n, 1);
  }
  int brightest = 0;
  for (int y = left[1]; y < left[3]; ++y)
  {
    for (int x = left[0]; x < left[2]; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(y) * w + x;
      const int darkest = std::min({ rgb->GetTypedComponent(i, 0),
        rgb->GetTypedComponent(i, 1),
        rgb->GetTypedComponent(i, 2) });
      brightest = std::max(brightest, darkest);
    }
  }
  const double frontLuminance = MeanLuminance(win, front.data());
  const double openLuminance = MeanLuminance(win, open.data());
  std::printf("%s: A under the rectangle %.3f, under the text %.3f, open %.3f; rectangle RGB "
              "%.3f %.3f %.3f (%d pixels), brightest text pixel %d; luminance in front %.3f, "
              "open %.3f\n",
    what,
    underRectangle,
    underText,
    openAO,
    mean[0],
    mean[1],
    mean[2],
    n,
    brightest,
    frontLuminance,
    openLuminance);

  // The overlays sit over real occlusion, and the surfaces around them are occluded.
  Check(underRectangle < openAO - 0.05 && underText < openAO - 0.05,
    std::string(what) + ": the ground under the overlays is occluded");
  Check(frontLuminance < 0.85 * openLuminance,
    std::string(what) + ": the ground in front of the sphere is darkened in the image");
  // The overlays themselves are not.
  Check(n > 20 && mean[0] < 0.01 && mean[2] < 0.01 && mean[1] > 0.99,
    std::string(what) + ": the rectangle keeps its exact green");
  Check(brightest >= 250, std::string(what) + ": the text keeps white pixels");
  ren->ReleaseGraphicsResources(win);
}
}

int TestAOOverlays(int, char*[])
{
  Run<vtkHybridAmbientOcclusionPass>("HAO");
  Run<vtkAmbientOcclusionVolumesPass>("AOV");
  return vtkAOTest::Result();
}
