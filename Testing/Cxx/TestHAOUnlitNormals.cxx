// Normals the G-buffer completes from the depths (vtkAOGBufferPass::GetNormalsCompleted), and
// when: a ground and a sphere with lighting off, whose shaders have neither a normal nor a view
// position, are completed; a lit scene, and a ground drawn by a vtkImageActor (whose mapper draws
// through an internal, lit actor that carries the prop's property keys, as vtkLODActor's device
// does in ParaView), are not. Seen obliquely (a normal facing the viewer would tilt the rays'
// hemisphere by about 60 degrees), the ground beside the sphere is as dark as in the lit scene
// (within 0.03) and open ground keeps A > 0.95. Without the completion the unlit case fails
// (open ground 0.77, beside the sphere 0.65 against 0.91).
#include "vtkAOTestUtilities.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"

namespace
{
constexpr int Width = 400;
constexpr int Height = 300;

struct Measure
{
  double Beside; // ground 1.25 units left of the sphere's centre
  double Open;   // ground far from the sphere
  bool Completed;
};

// Mean A over a 7 x 7 pixel box around the ground point (x, 0, z).
double GroundAO(vtkRenderer* ren, vtkHybridAmbientOcclusionPass* hao, double x, double z)
{
  ren->SetWorldPoint(x, 0, z, 1);
  ren->WorldToDisplay();
  const double* d = ren->GetDisplayPoint();
  const int px = static_cast<int>(d[0]);
  const int py = static_cast<int>(d[1]);
  return vtkAOTest::MeanAO(hao, px - 3, py - 3, px + 4, py + 4);
}

Measure Run(vtkRenderer* ren, const char* what)
{
  using namespace vtkAOTest;
  auto win = MakeWindow(Width, Height, ren);
  ObliqueView(ren); // the direction to the eye is far from the ground's normal
  auto hao = InstallHAO(ren, 2.0);
  win->Render();
  Measure m;
  m.Beside = GroundAO(ren, hao, -1.25, 0);
  m.Open = GroundAO(ren, hao, 3.5, 3.0);
  m.Completed = hao->GetLastFrameCompletedNormals();
  std::printf("%s: A beside the sphere %.3f, open ground %.3f, normals completed %d\n",
    what,
    m.Beside,
    m.Open,
    m.Completed ? 1 : 0);
  Check(hao->GetLastFrameHadOcclusion(), std::string(what) + ": the pass applied occlusion");
  ren->ReleaseGraphicsResources(win);
  return m;
}

void CheckAgainstLit(const Measure& m, const Measure& lit, const std::string& what, bool completed)
{
  using vtkAOTest::Check;
  Check(m.Completed == completed,
    what +
      (completed ? ": the G-buffer completed the normals"
                 : ": every normal came from the mappers (no completion pass)"));
  vtkAOTest::CheckContact(m.Beside, m.Open, lit.Beside, what, "the sphere", "lit scene's");
}
}

int TestHAOUnlitNormals(int, char*[])
{
  using namespace vtkAOTest;

  Measure lit;
  {
    vtkNew<vtkRenderer> ren;
    AddGround(ren, 5);
    AddSphere(ren, 0, 0);
    lit = Run(ren, "lit");
    Check(!lit.Completed, "lit: every normal came from the mappers (no completion pass)");
    Check(lit.Open > 0.95 && lit.Beside < lit.Open - 0.08, "lit: contact occlusion");
  }

  // 1. Lighting off on both.
  {
    vtkNew<vtkRenderer> ren;
    AddGround(ren, 5)->GetProperty()->LightingOff();
    AddSphere(ren, 0, 0)->GetProperty()->LightingOff();
    CheckAgainstLit(Run(ren, "unlit"), lit, "unlit", true);
  }

  // 2. The ground as an image slice (101 x 101 samples, turned from z = 0 into y = 0), the
  // sphere lit.
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(101, 101, 1);
    image->SetOrigin(-5, -5, 0);
    image->SetSpacing(0.1, 0.1, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    std::fill_n(static_cast<unsigned char*>(image->GetScalarPointer()), 101 * 101, 200);
    vtkNew<vtkImageActor> slice;
    slice->GetMapper()->SetInputData(image);
    slice->RotateX(90);
    vtkNew<vtkRenderer> ren;
    ren->AddActor(slice);
    AddSphere(ren, 0, 0);
    CheckAgainstLit(Run(ren, "image slice"), lit, "image slice", false);
  }
  return Result();
}
