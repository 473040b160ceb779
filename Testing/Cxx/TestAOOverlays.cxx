// 2-D props over occluded surfaces, with both passes (vtkAOPropGeometry::IsOverlay): a solid
// vtkActor2D rectangle (vtkPolyDataMapper2D), a white vtkTextActor, a rectangle drawn by a
// prop that is neither a vtkActor2D nor a vtkProp3D (as VTK's widget representations, the text
// and scalar bar widgets' vtkBorderRepresentation, draw their 2-D actors) and one drawn in a
// vtkProp3D's overlay step (as vtkAxesActor draws its captions) over the ground beside the
// sphere. They are drawn after the composite, as they are: exact green, blue and red, white
// text pixels, while the ground in front of the sphere is darkened; and the AO image is
// the same to the bit as without them (each frame on its own: no accumulation). Drawn into the
// G-buffer, as before, their shaders left the normals under them undefined: llvmpipe leaves
// zeros, read as "no surface" (the AO image gets holes of A = 1 in their shapes: largest
// change 0.20), and where the G-buffer completed the normals from the depths (the holder's
// keys are never seen drawing) the blue rectangle was darkened to 0.87. With the delegate's
// overlay step left in the G-buffer, the vtkProp3D's rectangle leaves a hole (change 0.15).
#include "vtkAOTestUtilities.h"
#include "vtkActor2D.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCellArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

namespace
{
// A prop that is neither a vtkActor2D nor a vtkProp3D and draws a 2-D actor of its own, as
// VTK's widget representations do (vtkBorderRepresentation: the text and scalar bar widgets).
class OverlayHolder : public vtkProp
{
public:
  static OverlayHolder* New();
  vtkTypeMacro(OverlayHolder, vtkProp);
  vtkSmartPointer<vtkActor2D> Actor;
  int RenderOpaqueGeometry(vtkViewport* v) override { return this->Actor->RenderOpaqueGeometry(v); }
  int RenderOverlay(vtkViewport* v) override { return this->Actor->RenderOverlay(v); }
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
  void ReleaseGraphicsResources(vtkWindow* w) override { this->Actor->ReleaseGraphicsResources(w); }
};
vtkStandardNewMacro(OverlayHolder);

// A vtkProp3D that draws a 2-D actor in its overlay step, as vtkAxesActor draws its captions.
class Prop3DWithOverlay : public vtkProp3D
{
public:
  static Prop3DWithOverlay* New();
  vtkTypeMacro(Prop3DWithOverlay, vtkProp3D);
  vtkSmartPointer<vtkActor2D> Actor;
  double Extent[6] = { -0.1, 0.1, 0.9, 1.1, -0.1, 0.1 }; // inside the sphere
  double* GetBounds() override { return this->Extent; }
  int RenderOverlay(vtkViewport* v) override { return this->Actor->RenderOverlay(v); }
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
  void ReleaseGraphicsResources(vtkWindow* w) override { this->Actor->ReleaseGraphicsResources(w); }
};
vtkStandardNewMacro(Prop3DWithOverlay);

constexpr int Width = 400;
constexpr int Height = 300;

// A filled rectangle in display coordinates, drawn in pure @p colour.
vtkSmartPointer<vtkActor2D> MakeRectangle(const std::array<int, 4>& box, const double colour[3])
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
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

// Mean RGB (0-1) of @p rgb (width @p w) over the box's pixels one in from its edges (the
// rasterization of the border); the pixel count in @p n.
std::array<double, 3> MeanRGB(vtkUnsignedCharArray* rgb,
  int w,
  const std::array<int, 4>& box,
  int& n)
{
  std::array<double, 3> mean{ 0, 0, 0 };
  n = 0;
  for (int y = box[1] + 1; y < box[3] - 1; ++y)
  {
    for (int x = box[0] + 1; x < box[2] - 1; ++x, ++n)
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
  return mean;
}

template<typename Pass>
void Run(const char* what)
{
  using namespace vtkAOTest;
  const std::string name(what);
  vtkNew<vtkRenderer> ren;
  auto win = MakeObliqueSphereOnGround(ren, Width, Height);
  win->Render(); // the camera's matrices for the boxes below

  // The ground beside the sphere: right (under a vtkActor2D rectangle), left (under a text
  // actor), front right (under a rectangle drawn by a representation-like prop) and in front
  // (nothing over it); open ground far away.
  const auto right = GroundBox(ren, 1.1, -0.2, 1.5, 0.2);
  const auto left = GroundBox(ren, -1.6, -0.3, -1.1, 0.3);
  const auto frontRight = GroundBox(ren, 0.8, 0.8, 1.1, 1.1);
  const auto frontLeft = GroundBox(ren, -1.1, 0.8, -0.8, 1.1);
  const auto front = GroundBox(ren, -0.2, 1.1, 0.2, 1.4);
  const auto open = GroundBox(ren, 3.2, 2.8, 3.6, 3.2);
  const double green[3] = { 0, 1, 0 }, blue[3] = { 0, 0, 1 }, red[3] = { 1, 0, 0 };
  auto rectangle = MakeRectangle(right, green);
  ren->AddActor2D(rectangle);
  vtkNew<OverlayHolder> holder;
  holder->Actor = MakeRectangle(frontRight, blue);
  ren->AddViewProp(holder);
  vtkNew<Prop3DWithOverlay> prop3D;
  prop3D->Actor = MakeRectangle(frontLeft, red);
  ren->AddViewProp(prop3D);
  vtkNew<vtkTextActor> text;
  text->SetInput("M");
  text->GetTextProperty()->SetFontSize(48);
  text->GetTextProperty()->SetColor(1, 1, 1);
  text->GetTextProperty()->BoldOn();
  text->SetDisplayPosition(left[0], left[1]);
  ren->AddActor2D(text);
  vtkProp* overlays[] = { rectangle, holder, prop3D, text };

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<Pass> pass;
  pass->SetDelegatePass(basic);
  pass->SetRadius(2.0);
  pass->SetIntensity(4.0);      // A of about 0.92 under the overlays darkens the image by 0.3
  pass->SetAccumulation(false); // every render the same A, to compare without and with overlays
  ren->SetPass(pass);

  // The AO image without the overlays, then with them: the same.
  for (vtkProp* overlay : overlays)
  {
    overlay->VisibilityOff();
  }
  win->Render();
  const AOImage bare = PassAOImage(pass.Get());
  for (vtkProp* overlay : overlays)
  {
    overlay->VisibilityOn();
  }
  win->Render();
  Check(pass->GetLastFrameHadOcclusion(), name + ": the pass applied occlusion");
  const AOImage covered = PassAOImage(pass.Get());
  const double difference = MaxAbsDifference(bare, covered);

  const double underRectangle = MeanAO(pass, right.data());
  const double underHolder = MeanAO(pass, frontRight.data());
  const double underProp3D = MeanAO(pass, frontLeft.data());
  const double underText = MeanAO(pass, left.data());
  const double openAO = MeanAO(pass, open.data());
  int w = 0, n = 0, nHolder = 0, nProp3D = 0;
  const auto rgb = GrabRGB(win, w);
  const auto rgbRectangle = MeanRGB(rgb, w, right, n);
  const auto rgbHolder = MeanRGB(rgb, w, frontRight, nHolder);
  const auto rgbProp3D = MeanRGB(rgb, w, frontLeft, nProp3D);
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
  std::printf("%s: A under the rectangle %.3f, the holder's %.3f, the vtkProp3D's %.3f, the text "
              "%.3f, open %.3f; largest change of A from the overlays %.4f\n",
    what,
    underRectangle,
    underHolder,
    underProp3D,
    underText,
    openAO,
    difference);
  std::printf("%s: RGB of the rectangle %.3f %.3f %.3f (%d pixels), the holder's %.3f %.3f %.3f "
              "(%d), the vtkProp3D's %.3f %.3f %.3f (%d); brightest text pixel %d; luminance "
              "in front %.3f, open %.3f\n",
    what,
    rgbRectangle[0],
    rgbRectangle[1],
    rgbRectangle[2],
    n,
    rgbHolder[0],
    rgbHolder[1],
    rgbHolder[2],
    nHolder,
    rgbProp3D[0],
    rgbProp3D[1],
    rgbProp3D[2],
    nProp3D,
    brightest,
    frontLuminance,
    openLuminance);

  // The overlays sit over real occlusion, which they leave as it is, and the image around
  // them is darkened.
  Check(underRectangle < openAO - 0.05 && underHolder < openAO - 0.05 &&
      underProp3D < openAO - 0.05 && underText < openAO - 0.05,
    name + ": the ground under the overlays is occluded");
  Check(difference < 0.01, name + ": the overlays leave the AO image as it is without them");
  Check(frontLuminance < 0.85 * openLuminance,
    name + ": the ground in front of the sphere is darkened in the image");
  // The overlays themselves are not.
  Check(n > 20 && rgbRectangle[0] < 0.01 && rgbRectangle[2] < 0.01 && rgbRectangle[1] > 0.99,
    name + ": the vtkActor2D rectangle keeps its exact green");
  Check(nHolder > 10 && rgbHolder[0] < 0.01 && rgbHolder[1] < 0.01 && rgbHolder[2] > 0.99,
    name + ": the representation-like prop's rectangle keeps its exact blue");
  Check(nProp3D > 10 && rgbProp3D[0] > 0.99 && rgbProp3D[1] < 0.01 && rgbProp3D[2] < 0.01,
    name + ": the vtkProp3D's overlay rectangle keeps its exact red");
  Check(brightest >= 250, name + ": the text keeps white pixels");
  ren->ReleaseGraphicsResources(win);
}
}

int TestAOOverlays(int, char*[])
{
  Run<vtkHybridAmbientOcclusionPass>("HAO");
  Run<vtkAmbientOcclusionVolumesPass>("AOV");
  return vtkAOTest::Result();
}
