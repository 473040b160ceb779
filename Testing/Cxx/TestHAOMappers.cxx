// Occluders drawn through other polydata mappers than vtkPolyDataMapper must be voxelized
// too: a sphere in a block of a vtkMultiBlockDataSet drawn by vtkCompositePolyDataMapper2, and
// sphere glyphs drawn by vtkGlyph3DMapper. The ground beside each of them must be darker
// than open ground by a stated margin, about as dark as beside a plain vtkPolyDataMapper
// sphere, and open ground keeps A > 0.95.
#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOCompat.h" // vtkAOCompositePolyDataMapper
#include "vtkAOTestUtilities.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

namespace
{
// 300 x 300 pixels, looking down from height 12 with a 40 degree view angle:
// 34.4 pixels per unit on the ground, the origin at pixel (150, 150), +x to the right and
// +z downwards in the image (view up is -z).
constexpr int Size = 300;
constexpr double PixelsPerUnit = Size / (2.0 * 12.0 * 0.36397023426620234);

int Px(double x)
{
  return static_cast<int>(Size / 2 + x * PixelsPerUnit);
}
int Py(double z)
{
  return static_cast<int>(Size / 2 - z * PixelsPerUnit);
}

/// Mean A over a small box of ground centred on (x, z) (world units).
double GroundAO(vtkHybridAmbientOcclusionPass* hao, double x, double z)
{
  return vtkAOTest::MeanAO(hao, Px(x) - 3, Py(z) - 3, Px(x) + 4, Py(z) + 4);
}

vtkSmartPointer<vtkPolyData> Sphere(double x, double y, double z)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(x, y, z);
  source->SetRadius(1);
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkPolyData> Ground(double half)
{
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-half, 0, -half);
  ground->SetPoint1(-half, 0, half);
  ground->SetPoint2(half, 0, -half);
  ground->Update();
  return ground->GetOutput();
}

struct Measure
{
  double Beside; // ground 1.25 units from the sphere's centre, left of it
  double Open;   // ground far from everything
};

// Where: the sphere (or glyph) stands at (cx, 1, cz); the ring sample is at (cx - 1.25, cz),
// the open sample at (3.5, 3.5), away from every occluder of the scenes below (the nearest
// glyph, at (3, 1, -3), is 6.5 units away: more than R + 1).
Measure Run(vtkRenderer* ren, double cx, double cz, const char* what)
{
  using namespace vtkAOTest;
  auto win = MakeWindow(Size, Size, ren);
  TopView(ren, 0, 0, 12);
  auto hao = InstallHAO(ren, 2.0);
  win->Render();
  Measure m;
  m.Beside = GroundAO(hao, cx - 1.25, cz);
  m.Open = GroundAO(hao, 3.5, 3.5);
  std::printf("%s: A beside the sphere %.3f, open ground %.3f, voxelized props %d, occlusion %d\n",
    what,
    m.Beside,
    m.Open,
    hao->GetVoxelizer()->GetNumberOfRenderedProps(),
    hao->GetLastFrameHadOcclusion() ? 1 : 0);
  Check(hao->GetLastFrameHadOcclusion(), std::string(what) + ": the pass applied occlusion");
  ren->ReleaseGraphicsResources(win);
  return m;
}

// A mapper's scene (named @p what in the messages) has the reference's contact occlusion beside
// @p occluder, and open ground stays unoccluded.
void CheckAgainstReference(const Measure& m,
  const Measure& reference,
  const std::string& what,
  const char* occluder)
{
  vtkAOTest::CheckContact(
    m.Beside, m.Open, reference.Beside, what, occluder, "vtkPolyDataMapper reference");
}
}

int TestHAOMappers(int, char*[])
{
  using namespace vtkAOTest;

  // Reference: the same ground and sphere through plain vtkPolyDataMapper.
  Measure reference;
  {
    vtkNew<vtkRenderer> ren;
    AddGround(ren, 5);
    AddSphere(ren, 0, 0);
    reference = Run(ren, 0, 0, "vtkPolyDataMapper (reference)");
  }

  // 1. vtkCompositePolyDataMapper2: block 0 the ground, block 1 the sphere.
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, Ground(5));
    blocks->SetBlock(1, Sphere(0, 1, 0));
    vtkNew<vtkAOCompositePolyDataMapper> mapper;
    mapper->SetInputDataObject(blocks);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> ren;
    ren->AddActor(actor);
    const Measure m = Run(ren, 0, 0, "vtkCompositePolyDataMapper2");
    CheckAgainstReference(m, reference, "composite", "the sphere block");
  }

  // 2. vtkGlyph3DMapper: unit spheres at three points 1 above a plain ground.
  {
    vtkNew<vtkRenderer> ren;
    AddGround(ren, 5);
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 1, 0);
    points->InsertNextPoint(3, 1, -3);
    points->InsertNextPoint(-3, 1, 3);
    vtkNew<vtkPolyData> centres;
    centres->SetPoints(points);
    vtkNew<vtkGlyph3DMapper> mapper;
    mapper->SetInputData(centres);
    mapper->SetSourceData(Sphere(0, 0, 0));
    mapper->ScalingOff();
    mapper->OrientOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    ren->AddActor(actor);
    const Measure m = Run(ren, 0, 0, "vtkGlyph3DMapper");
    CheckAgainstReference(m, reference, "glyphs", "a sphere glyph");
  }

  return Result();
}
