// Helpers for the ambient-occlusion tests that render: windows, small scenes of actors,
// installing a pass and reading A in screen regions. With the checks (vtkAOTestChecks.h,
// included) and the surfaces and array measures (vtkAOTestSurfaces.h, included where a test
// uses them), the one helper set of every test.
#ifndef vtkAOTestUtilities_h
#define vtkAOTestUtilities_h

#include "vtkAOTestChecks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace vtkAOTest
{
/// An offscreen window of w x h pixels without multisampling, holding @p ren (if given).
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int w, int h, vtkRenderer* ren = nullptr)
{
  auto win = vtkSmartPointer<vtkRenderWindow>::New();
  // Every window lives until the test exits. Xvfb started without -noreset resets itself when
  // its last client disconnects, and a window opened during that reset aborts ("bad X server
  // connection"). scripts/run-tests.sh passes -noreset; this keeps a bare `xvfb-run ctest` safe.
  // Only X windows: a headless (EGL, OSMesa) one must go before exit, as OSMesa's context is
  // gone by the time static objects are destroyed (making it current then crashes).
  static std::vector<vtkSmartPointer<vtkRenderWindow>> keepAlive;
  if (std::string(win->GetClassName()) == "vtkXOpenGLRenderWindow")
  {
    keepAlive.push_back(win);
  }
  win->SetOffScreenRendering(1);
  win->SetMultiSamples(0);
  win->SetSize(w, h);
  if (ren)
  {
    win->AddRenderer(ren);
  }
  return win;
}

inline vtkSmartPointer<vtkActor> AddActor(vtkRenderer* ren, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  ren->AddActor(actor);
  return actor;
}

/// An actor drawing @p surface.
inline vtkSmartPointer<vtkActor> AddSurface(vtkRenderer* ren, vtkPolyData* surface)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  ren->AddActor(actor);
  return actor;
}

/// A ground plane (y = 0, normal up) of half-size @p half.
inline vtkSmartPointer<vtkActor> AddGround(vtkRenderer* ren, double half)
{
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-half, 0, -half);
  ground->SetPoint1(-half, 0, half);
  ground->SetPoint2(half, 0, -half);
  return AddActor(ren, ground);
}

/// A sphere of radius @p r (default 1) resting on the ground at (x, r, z).
inline vtkSmartPointer<vtkActor> AddSphere(vtkRenderer* ren, double x, double z, double r = 1)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, r, z);
  sphere->SetRadius(r);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  return AddActor(ren, sphere);
}

/// Looking straight down at the ground from height h above (cx, 0, cz), with a view angle of
/// @p angle degrees (default 40).
inline void TopView(vtkRenderer* ren, double cx, double cz, double h, double angle = 40)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(cx, 0, cz);
  cam->SetPosition(cx, h, cz);
  cam->SetViewUp(0, 0, -1);
  cam->SetViewAngle(angle);
  ren->ResetCameraClippingRange();
}

/// Looking from @p position at @p focal with @p up up, a view angle of @p angle degrees and
/// the clipping range [nearClip, farClip] (fixed, where the test needs it so).
inline void LookAt(vtkRenderer* ren,
  const std::array<double, 3>& position,
  const std::array<double, 3>& focal,
  const std::array<double, 3>& up,
  double angle,
  double nearClip,
  double farClip)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(focal.data());
  cam->SetPosition(position.data());
  cam->SetViewUp(up.data());
  cam->SetViewAngle(angle);
  cam->SetClippingRange(nearClip, farClip);
}

/// The display box { x0, y0, x1, y1 } of the ground rectangle [x0, x1] x [z0, z1] (y = 0), as
/// @p ren's current camera shows it.
inline std::array<int, 4> GroundBox(vtkRenderer* ren, double x0, double z0, double x1, double z1)
{
  const int* size = ren->GetSize();
  std::array<int, 4> box{ size[0], size[1], 0, 0 };
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

/// The contact scene: a unit sphere resting on a ground of half-size 5 at the origin, looked at
/// straight down from height @p h (TopView).
inline void AddSphereOnGround(vtkRenderer* ren, double h = 12)
{
  AddGround(ren, 5);
  AddSphere(ren, 0, 0);
  TopView(ren, 0, 0, h);
}

/// The contact scene seen obliquely, from 31 degrees above the ground (the camera at (0, 6, 10),
/// looking at the origin): the occluded ground beside the sphere is seen, and the direction to
/// the eye is far from the ground's normal.
inline void ObliqueView(vtkRenderer* ren)
{
  LookAt(ren, { 0, 6, 10 }, { 0, 0, 0 }, { 0, 1, 0 }, 40, 1, 40);
}

/// The scene of ObliqueView in a new window of @p w x @p h: a unit sphere resting on a ground of
/// half-size 5 at the origin (AddSphereOnGround's), on a dark grey background.
inline vtkSmartPointer<vtkRenderWindow> MakeObliqueSphereOnGround(vtkRenderer* ren, int w, int h)
{
  ren->SetBackground(0.2, 0.2, 0.2);
  AddGround(ren, 5);
  AddSphere(ren, 0, 0);
  ObliqueView(ren);
  return MakeWindow(w, h, ren);
}

/// HAO around a vtkRenderStepsPass, installed on @p ren, with radius @p radius (0: automatic).
inline vtkSmartPointer<vtkHybridAmbientOcclusionPass> InstallHAO(vtkRenderer* ren,
  double radius = 0)
{
  vtkNew<vtkRenderStepsPass> basic;
  auto hao = vtkSmartPointer<vtkHybridAmbientOcclusionPass>::New();
  hao->SetDelegatePass(basic);
  hao->SetRadius(radius);
  ren->SetPass(hao);
  return hao;
}

/// VTK's vtkSSAOPass around @p basic, installed on @p ren: radius @p radius, @p kernel samples.
inline vtkSmartPointer<vtkSSAOPass> InstallSSAO(vtkRenderer* ren,
  vtkRenderPass* basic,
  double radius,
  int kernel)
{
  auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
  ssao->SetDelegatePass(basic);
  ssao->SetRadius(radius);
  ssao->SetKernelSize(kernel);
  ren->SetPass(ssao);
  return ssao;
}

/// Mean A of the pass's last frame over the pixel box [x0, x1) x [y0, y1) (covered pixels).
/// Any pass with GetAmbientOcclusionImage (HAO, AOV).
template<class Pass>
double MeanAO(Pass* pass, int x0, int y0, int x1, int y1)
{
  vtkNew<vtkImageData> image;
  if (!pass->GetAmbientOcclusionImage(image))
  {
    return -1.0;
  }
  vtkFloatArray* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  const int w = image->GetDimensions()[0];
  double sum = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(y) * w + x;
      if (a->GetTypedComponent(i, 1) > 0.5f)
      {
        sum += a->GetTypedComponent(i, 0);
        ++n;
      }
    }
  }
  return n ? sum / n : -1.0;
}

template<class Pass>
double MeanAO(const vtkSmartPointer<Pass>& pass, int x0, int y0, int x1, int y1)
{
  return MeanAO(pass.Get(), x0, y0, x1, y1);
}

/// Per-pixel A and coverage of a two-component (A, coverage) image: a pass's
/// GetAmbientOcclusionImage or the reference's (vtkAOReferenceRenderer).
struct AOImage
{
  std::vector<float> A, Coverage;
  int W = 0, H = 0;
  AOImage() = default;
  explicit AOImage(vtkImageData* image)
  {
    W = image->GetDimensions()[0];
    H = image->GetDimensions()[1];
    auto* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    {
      A.push_back(a->GetTypedComponent(i, 0));
      Coverage.push_back(a->GetTypedComponent(i, 1));
    }
  }
};

/// The pass's last frame as an AOImage (empty if it has none).
template<class Pass>
AOImage PassAOImage(Pass* pass)
{
  vtkNew<vtkImageData> image;
  return pass->GetAmbientOcclusionImage(image) ? AOImage(image) : AOImage();
}

/// RMS difference of A between @p a and @p b over the pixels covered in both (1 if none).
inline double CoveredRMSE(const AOImage& a, const AOImage& b)
{
  double s = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.A.size() && i < b.A.size(); ++i)
  {
    if (a.Coverage[i] > 0.5f && b.Coverage[i] > 0.5f)
    {
      s += (a.A[i] - b.A[i]) * (a.A[i] - b.A[i]);
      ++n;
    }
  }
  return n ? std::sqrt(s / n) : 1.0;
}

/// Largest |A difference| between @p a and @p b over the pixels covered in both (1 if the
/// images differ in size or either is empty).
inline double MaxAbsDifference(const AOImage& a, const AOImage& b)
{
  if (a.A.empty() || a.A.size() != b.A.size())
  {
    return 1.0;
  }
  double m = 0;
  for (size_t i = 0; i < a.A.size(); ++i)
  {
    if (a.Coverage[i] > 0.5f && b.Coverage[i] > 0.5f)
    {
      m = std::max(m, static_cast<double>(std::fabs(a.A[i] - b.A[i])));
    }
  }
  return m;
}

template<class Pass>
double MeanAO(const vtkNew<Pass>& pass, int x0, int y0, int x1, int y1)
{
  return MeanAO(pass.Get(), x0, y0, x1, y1);
}

/// Mean A over the pixel box { x0, y0, x1, y1 }.
template<class Pass>
double MeanAO(const Pass& pass, const int box[4])
{
  return MeanAO(pass, box[0], box[1], box[2], box[3]);
}

/// A of the pass's last frame per pixel (covered pixels get A, the others -1; empty if the
/// frame had no occlusion).
template<class Pass>
std::vector<float> ReadAO(Pass* pass)
{
  vtkNew<vtkImageData> image;
  std::vector<float> out;
  if (!pass->GetAmbientOcclusionImage(image))
  {
    return out;
  }
  vtkFloatArray* a = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    out.push_back(a->GetTypedComponent(i, 1) > 0.5f ? a->GetTypedComponent(i, 0) : -1.0f);
  }
  return out;
}

/// RMS (or, with @p maximum, the largest) difference of A of two ReadAO images over the
/// pixels covered in both; infinity if the sizes differ or nothing is covered.
inline double AODifference(const std::vector<float>& a,
  const std::vector<float>& b,
  bool maximum = false)
{
  if (a.size() != b.size() || a.empty())
  {
    return HUGE_VAL;
  }
  double sum = 0, largest = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (a[i] >= 0.0f && b[i] >= 0.0f)
    {
      const double d = static_cast<double>(a[i]) - b[i];
      sum += d * d;
      largest = std::max(largest, std::abs(d));
      ++n;
    }
  }
  return n == 0 ? HUGE_VAL : maximum ? largest : std::sqrt(sum / n);
}

/// The contact checks of a ground beside an occluder (A @p beside) against the same scene drawn
/// another way (@p reference): open ground (A @p open) keeps A > 0.95, the ground beside
/// @p occluder is darker than open ground by > 0.08 and within 0.03 of @p reference.
inline void CheckContact(double beside,
  double open,
  double reference,
  const std::string& what,
  const std::string& occluder,
  const std::string& referenceName)
{
  Check(open > 0.95, what + ": open ground keeps A > 0.95");
  Check(beside >= 0.0 && beside < open - 0.08,
    what + ": ground beside " + occluder + " is darker than open ground by > 0.08");
  Check(std::abs(beside - reference) < 0.03,
    what + ": occlusion beside " + occluder + " within 0.03 of the " + referenceName);
}

/// The window's back buffer (RGB), and its width in pixels in @p width.
inline vtkSmartPointer<vtkUnsignedCharArray> GrabRGB(vtkRenderWindow* win, int& width)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(win);
  grab->ReadFrontBufferOff();
  grab->Update();
  width = grab->GetOutput()->GetDimensions()[0];
  return vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
}

/// Mean luminance (0-1) of the window's current image over a pixel box.
inline double MeanLuminance(vtkRenderWindow* win, int x0, int y0, int x1, int y1)
{
  int w = 0;
  const vtkSmartPointer<vtkUnsignedCharArray> rgb = GrabRGB(win, w);
  double sum = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(y) * w + x;
      sum += (rgb->GetTypedComponent(i, 0) + rgb->GetTypedComponent(i, 1) +
               rgb->GetTypedComponent(i, 2)) /
        (3.0 * 255.0);
      ++n;
    }
  }
  return n ? sum / n : -1.0;
}

/// Mean luminance over the pixel box { x0, y0, x1, y1 }.
inline double MeanLuminance(vtkRenderWindow* win, const int box[4])
{
  return MeanLuminance(win, box[0], box[1], box[2], box[3]);
}
}

#endif
