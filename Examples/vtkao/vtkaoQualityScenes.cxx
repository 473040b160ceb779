#include "vtkaoQualityScenes.h"

#include "vtkaoScene.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <zlib.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace
{
using Vec = std::array<double, 3>;

Vec Add(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Mul(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
Vec Normalize(const Vec& a)
{
  return Mul(a, 1.0 / std::sqrt(Dot(a, a)));
}

vtkActor* AddPolyData(vtkRenderer* renderer, vtkPolyData* data, double grey = 0.8)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(grey, grey, grey);
  renderer->AddActor(actor);
  return actor;
}

// Run @p algorithm and add a copy of its (polydata) output: the pipeline is not kept.
vtkActor* AddOutput(vtkRenderer* renderer, vtkAlgorithm* algorithm)
{
  algorithm->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->ShallowCopy(algorithm->GetOutputDataObject(0));
  return AddPolyData(renderer, data);
}

// Run @p source, optionally rotated about y by @p degrees around @p pivot, and add it.
vtkActor* AddSource(vtkRenderer* renderer,
  vtkAlgorithm* source,
  double degrees = 0,
  const Vec& pivot = { 0, 0, 0 })
{
  vtkNew<vtkTransform> transform;
  transform->Translate(pivot.data());
  transform->RotateY(degrees);
  transform->Translate(-pivot[0], -pivot[1], -pivot[2]);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputConnection(source->GetOutputPort());
  move->SetTransform(transform);
  return AddOutput(renderer, move);
}

// The bounds of a box: x0, x1, y0, y1, z0, z1.
using Bounds = std::array<double, 6>;

// A box turned about the vertical axis through (px, pz).
void AddBoxAbout(vtkRenderer* renderer, const Bounds& b, double degrees, double px, double pz)
{
  vtkNew<vtkCubeSource> box;
  box->SetBounds(b.data());
  AddSource(renderer, box, degrees, { px, 0, pz });
}

// A box turned about its own centre.
void AddBox(vtkRenderer* renderer, const Bounds& b, double degrees = 0)
{
  AddBoxAbout(renderer, b, degrees, 0.5 * (b[0] + b[1]), 0.5 * (b[4] + b[5]));
}

void AddGround(vtkRenderer* renderer, double x0, double x1, double z0, double z1, double y = 0)
{
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(x0, y, z1);
  ground->SetPoint1(x1, y, z1);
  ground->SetPoint2(x0, y, z0); // normal +y
  AddSource(renderer, ground);
}

// A convex hexahedron from its 8 corners (0-3 one face, 4-7 the opposite one, same order).
void AddHexahedron(vtkRenderer* renderer, const Vec corners[8])
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const int faces[6][4] = {
    { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 4, 5, 1 }, { 1, 5, 6, 2 }, { 2, 6, 7, 3 }, { 3, 7, 4, 0 }
  };
  // Separate points per face: flat normals, as a box.
  for (const auto& face : faces)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(corners[face[k]].data());
    }
    quads->InsertNextCell(4, ids);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(quads);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(data);
  normals->AutoOrientNormalsOn();
  normals->SplittingOn();
  AddOutput(renderer, normals);
}

void SetCamera(vtkRenderer* renderer,
  const Vec& position,
  const Vec& focal,
  const Vec& up,
  double angle)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(position.data());
  camera->SetFocalPoint(focal.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(angle);
  camera->OrthogonalizeViewUp();
}

// Camera looking at the centre of @p bounds from direction @p from, framing the bounds.
void FrameBounds(vtkRenderer* renderer,
  const double bounds[6],
  const Vec& from,
  double angle,
  double distanceFactor = 1.0)
{
  const Vec centre = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
    std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  const double distance =
    distanceFactor * 0.5 * diagonal / std::tan(0.5 * angle * 3.14159265358979 / 180.0);
  SetCamera(renderer, Add(centre, Mul(Normalize(from), distance)), centre, { 0, 1, 0 }, angle);
}

// Where the view ray through normalized device coordinates (x, y) meets the plane y = 0.
Vec GroundPoint(vtkCamera* camera, double aspect, double x, double y)
{
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  inverse->Invert();
  Vec ends[2];
  for (int k = 0; k < 2; ++k)
  {
    const double in[4] = { x, y, k == 0 ? -1.0 : 1.0, 1.0 };
    double out[4];
    inverse->MultiplyPoint(in, out);
    ends[k] = { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
  }
  const Vec d = Sub(ends[1], ends[0]);
  const double t = -ends[0][1] / d[1];
  return Add(ends[0], Mul(d, t));
}

// A slab of height @p height and thickness @p thickness standing on the ground line a-b and
// lying in the frustum side plane through a, b and the eye, moved out of the frustum by
// @p margin: entirely off screen, right beside the visible ground.
void AddOffscreenSlab(vtkRenderer* renderer,
  Vec a,
  Vec b,
  const Vec& eye,
  const Vec& inside,
  double height,
  double thickness,
  double margin,
  double extend)
{
  const Vec along = Normalize(Sub(b, a));
  a = Sub(a, Mul(along, extend));
  b = Add(b, Mul(along, extend));
  Vec n = Normalize(Cross(Sub(b, a), Sub(eye, a)));
  if (Dot(n, Sub(inside, a)) > 0)
  {
    n = Mul(n, -1);
  }
  const double f = height / eye[1];
  const Vec quad[4] = { a, b, Add(b, Mul(Sub(eye, b), f)), Add(a, Mul(Sub(eye, a), f)) };
  Vec corners[8];
  for (int k = 0; k < 4; ++k)
  {
    corners[k] = Add(quad[k], Mul(n, margin));
    corners[k + 4] = Add(quad[k], Mul(n, margin + thickness));
  }
  AddHexahedron(renderer, corners);
}

// Read an STL file (optionally gzip-compressed) with normals (split at 40 degrees); nullptr
// if the file is missing or holds no triangles.
vtkSmartPointer<vtkPolyData> LoadMesh(const std::string& path, std::string& note)
{
  if (!std::ifstream(path, std::ios::binary).good())
  {
    note = "file '" + path + "' not found";
    return nullptr;
  }
  std::string file = path;
  std::string temporary;
  if (path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0)
  {
    char name[] = "/tmp/vtkao-quality-XXXXXX.stl";
    const int fd = mkstemps(name, 4);
    gzFile in = gzopen(path.c_str(), "rb");
    if (fd < 0 || !in)
    {
      note = "cannot decompress '" + path + "'";
      return nullptr;
    }
    temporary = file = name;
    char buffer[65536];
    int n;
    bool ok = true;
    while ((n = gzread(in, buffer, sizeof(buffer))) > 0)
    {
      ok = ok && write(fd, buffer, n) == n;
    }
    ok = ok && n == 0;
    gzclose(in);
    close(fd);
    if (!ok)
    {
      std::remove(name);
      note = "cannot decompress '" + path + "'";
      return nullptr;
    }
  }
  vtkNew<vtkSTLReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(triangles->GetOutputPort());
  normals->SetFeatureAngle(40);
  normals->SplittingOn();
  normals->ConsistencyOn();
  normals->Update();
  if (!temporary.empty())
  {
    std::remove(temporary.c_str());
  }
  if (normals->GetOutput()->GetNumberOfPolys() == 0)
  {
    note = "'" + path + "' holds no triangles";
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(normals->GetOutput());
  return mesh;
}

double Diagonal(const double b[6])
{
  return std::sqrt(std::pow(b[1] - b[0], 2) + std::pow(b[3] - b[2], 2) + std::pow(b[5] - b[4], 2));
}

//------------------------------------------------------------------------------
bool Contact(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -8, 8, -6, 6);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-3, 1, 0);
  sphere->SetRadius(1);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  AddSource(renderer, sphere);
  AddBox(renderer, { -0.5, 1.5, 0, 2, -1.5, 0.5 }, 30);
  vtkNew<vtkCylinderSource> cylinder; // axis y: lay it along x, resting on the ground
  cylinder->SetRadius(0.6);
  cylinder->SetHeight(3);
  cylinder->SetResolution(64);
  vtkNew<vtkTransform> lay;
  lay->Translate(4, 0.6, 0.5);
  lay->RotateY(-20);
  lay->RotateZ(90);
  vtkNew<vtkTransformPolyDataFilter> laid;
  laid->SetInputConnection(cylinder->GetOutputPort());
  laid->SetTransform(lay);
  AddSource(renderer, laid);
  SetCamera(renderer, { 0, 6, 9 }, { 0.3, 0.6, 0 }, { 0, 1, 0 }, 40);
  radius = 1.5;
  return true;
}

// The crease scenes' ground with its grooved block (grooves 0.3 wide, 1 deep).
void AddGroovedGround(vtkRenderer* renderer)
{
  AddGround(renderer, -9, 9, -6, 6);
  AddBox(renderer, { -7, -2.5, 0, 0.5, -2, 2 });
  for (int i = 0; i < 8; ++i)
  {
    const double x0 = -7 + i * 0.6;
    AddBox(renderer, { x0, x0 + 0.3, 0.5, 1.5, -2, 2 });
  }
}

// The crease scenes' wall behind the staircase, camera and radius.
void FinishCreaseScene(vtkRenderer* renderer, double& radius)
{
  AddBox(renderer, { 3, 7, 0, 2.5, -2.5, -2 });
  SetCamera(renderer, { 0, 7, 9 }, { 0, 0.5, -0.3 }, { 0, 1, 0 }, 45);
  radius = 1.0;
}

bool Crease(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGroovedGround(renderer);
  // An open box (a cavity), turned.
  const double t = 0.15;
  AddBox(renderer, { -1.5, 1.5, 0, t, -1.5, 1.5 }, 20);
  AddBox(renderer, { -1.5, 1.5, 0, 1.5, -1.5, -1.5 + t }, 20);
  AddBox(renderer, { -1.5, 1.5, 0, 1.5, 1.5 - t, 1.5 }, 20);
  AddBox(renderer, { -1.5, -1.5 + t, 0, 1.5, -1.5, 1.5 }, 20);
  AddBox(renderer, { 1.5 - t, 1.5, 0, 1.5, -1.5, 1.5 }, 20);
  // A staircase against a wall: a crease at every step.
  for (int i = 0; i < 6; ++i)
  {
    AddBox(renderer, { 3 + i * 0.6, 7, 0, 0.3 * (i + 1), -2, 1 });
  }
  FinishCreaseScene(renderer, radius);
  return true;
}

// The crease scene's shapes built from boxes that touch but do not overlap: no two faces of
// the same orientation lie on each other and no face is buried inside another box. It sets
// AOV's limitation (summed form factors of overlapping solids: in `crease` the staircase's six
// boxes share their front and bottom faces, the cavity's walls overlap its floor) apart from
// the creases themselves.
bool CreaseDisjoint(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGroovedGround(renderer);
  // The open box, turned 20 degrees about its centre as one piece: floor, then walls on it.
  const double t = 0.15;
  AddBoxAbout(renderer, { -1.5, 1.5, 0, t, -1.5, 1.5 }, 20, 0, 0);
  AddBoxAbout(renderer, { -1.5, 1.5, t, 1.5, -1.5, -1.5 + t }, 20, 0, 0);
  AddBoxAbout(renderer, { -1.5, 1.5, t, 1.5, 1.5 - t, 1.5 }, 20, 0, 0);
  AddBoxAbout(renderer, { -1.5, -1.5 + t, t, 1.5, -1.5 + t, 1.5 - t }, 20, 0, 0);
  AddBoxAbout(renderer, { 1.5 - t, 1.5, t, 1.5, -1.5 + t, 1.5 - t }, 20, 0, 0);
  // The staircase as side-by-side columns in front of the wall.
  for (int i = 0; i < 6; ++i)
  {
    AddBox(renderer, { 3 + i * 0.6, i == 5 ? 7 : 3 + (i + 1) * 0.6, 0, 0.3 * (i + 1), -2, 1 });
  }
  FinishCreaseScene(renderer, radius);
  return true;
}

bool Offscreen(vtkRenderer* renderer, double aspect, double& radius, std::string&)
{
  AddGround(renderer, -20, 20, -20, 20);
  // Something on screen besides the ground.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0.8, -1);
  sphere->SetRadius(0.8);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  AddSource(renderer, sphere);
  const Vec eye = { 0, 8, 8 };
  SetCamera(renderer, eye, { 0, 0, 0 }, { 0, 1, 0 }, 30);
  vtkCamera* camera = renderer->GetActiveCamera();
  const Vec centre = GroundPoint(camera, aspect, 0, 0);
  const Vec bl = GroundPoint(camera, aspect, -1, -1), br = GroundPoint(camera, aspect, 1, -1);
  const Vec tl = GroundPoint(camera, aspect, -1, 1), tr = GroundPoint(camera, aspect, 1, 1);
  radius = 1.5;
  // Walls beyond the left, right and bottom edges of the frame (leaning with the frustum).
  AddOffscreenSlab(renderer, bl, tl, eye, centre, 2.5, 0.3, 0.03, 2);
  AddOffscreenSlab(renderer, br, tr, eye, centre, 2.5, 0.3, 0.03, 2);
  AddOffscreenSlab(renderer, bl, br, eye, centre, 2.0, 0.3, 0.03, 2);
  return true;
}

bool Hidden(vtkRenderer* renderer, double, double& radius, std::string&)
{
  // Looking straight down through a hole in a plate (height 3) at the floor. Blocks on the
  // floor just outside the part seen through the hole are hidden under the plate.
  AddGround(renderer, -12, 12, -10, 10);
  const double y0 = 3, y1 = 3.2, hx = 3.5, hz = 2;
  AddBox(renderer, { -10, -hx, y0, y1, -8, 8 });
  AddBox(renderer, { hx, 10, y0, y1, -8, 8 });
  AddBox(renderer, { -hx, hx, y0, y1, -8, -hz });
  AddBox(renderer, { -hx, hx, y0, y1, hz, 8 });
  AddBox(renderer, { 4.72, 5.75, 0, 2.8, -2.5, 2.5 });
  AddBox(renderer, { -5.75, -4.72, 0, 2.8, -2.5, 2.5 });
  AddBox(renderer, { -4, 4, 0, 2.8, 2.72, 3.75 });
  AddBox(renderer, { -4, 4, 0, 2.0, -3.75, -2.72 });
  SetCamera(renderer, { 0, 12, 0 }, { 0, 0, 0 }, { 0, 0, -1 }, 30);
  radius = 2.0; // the plate's underside is 3 above the floor: out of reach
  return true;
}

bool Thin(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -8, 8, -6, 6);
  const double t = 0.02;
  // Shelves: thin plates stacked 0.4 apart, each shifted back.
  for (int i = 0; i < 4; ++i)
  {
    const double y = 0.4 * (i + 1);
    AddBox(renderer, { -5, -1.5, y, y + t, -1.5 - 0.4 * i, 0.5 - 0.4 * i });
  }
  // Fins standing on the ground, 0.35 apart.
  for (int i = 0; i < 8; ++i)
  {
    const double x = 0.5 + 0.35 * i;
    AddBox(renderer, { x, x + t, 0, 1.5, -1.5, 0.5 }, 15);
  }
  // A thin table top 0.25 above the ground.
  AddBox(renderer, { 4, 6.5, 0.25, 0.25 + t, -1, 1 }, -10);
  SetCamera(renderer, { 0, 4.5, 8 }, { 0.3, 0.5, -0.5 }, { 0, 1, 0 }, 45);
  radius = 1.0;
  return true;
}

// Open sheets (single planes, no thickness) stacked within R: the case where AOV's summed form
// factors over-darken (seen from the ground, every sheet adds while rays see the lowest one).
bool Sheets(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -8, 8, -6, 6);
  for (int i = 0; i < 4; ++i)
  {
    const double y = 0.3 + 0.08 * i;
    const double shift = 0.5 * i;
    vtkNew<vtkPlaneSource> sheet;
    sheet->SetOrigin(-4 + shift, y, 1);
    sheet->SetPoint1(-1 + shift, y, 1);
    sheet->SetPoint2(-4 + shift, y, -2);
    AddSource(renderer, sheet);
  }
  // A single sheet beside them: what one open sheet does alone.
  vtkNew<vtkPlaneSource> single;
  single->SetOrigin(2, 0.3, 1);
  single->SetPoint1(5, 0.3, 1);
  single->SetPoint2(2, 0.3, -2);
  AddSource(renderer, single);
  SetCamera(renderer, { 0, 4.5, 8 }, { 0.3, 0.5, -0.5 }, { 0, 1, 0 }, 45);
  radius = 1.0;
  return true;
}

bool Glyphs(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -8, 8, -6, 6);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 16; ++i)
  {
    for (int j = 0; j < 12; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        double jitter[3];
        for (double& v : jitter)
        {
          v = random->GetValue() - 0.5;
          random->Next();
        }
        points->InsertNextPoint(-5.6 + 0.75 * i + 0.2 * jitter[0],
          0.3 + 0.7 * k + 0.2 * jitter[1],
          -4.2 + 0.75 * j + 0.2 * jitter[2]);
      }
    }
  }
  vtkNew<vtkPolyData> centres;
  centres->SetPoints(points);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.28);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputData(centres);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->ScalingOff();
  glyphs->OrientOff();
  glyphs->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(glyphs);
  actor->GetProperty()->SetColor(0.8, 0.8, 0.8);
  renderer->AddActor(actor);
  SetCamera(renderer, { 0, 7, 9 }, { 0, 0.5, 0 }, { 0, 1, 0 }, 45);
  radius = 0.7;
  return true;
}

bool Iso(vtkRenderer* renderer, double, double& radius, std::string&)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-12, 12, -12, 12, -12, 12);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 165);
  contour->ComputeNormalsOn();
  contour->ComputeScalarsOff();
  double b[6];
  AddOutput(renderer, contour)->GetBounds(b);
  FrameBounds(renderer, b, { 1, 0.8, 1.5 }, 30, 0.8);
  radius = 0.1 * Diagonal(b);
  return true;
}

// Boxes merged into one actor (many thin parts: fins, ribs, bars).
class BoxSet
{
public:
  void Add(double x0, double x1, double y0, double y1, double z0, double z1)
  {
    vtkNew<vtkCubeSource> box;
    box->SetBounds(x0, x1, y0, y1, z0, z1);
    box->Update();
    this->Append->AddInputData(box->GetOutput());
  }
  void AddTo(vtkRenderer* renderer)
  {
    this->Append->Update();
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->ShallowCopy(this->Append->GetOutput());
    AddPolyData(renderer, data);
  }

private:
  vtkNew<vtkAppendPolyData> Append;
};

// A vertical cylinder (axis y) from y0 to y1 around (x, z).
void AddCylinder(vtkRenderer* renderer, double x, double z, double r, double y0, double y1, int n)
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetCenter(x, 0.5 * (y0 + y1), z);
  cylinder->SetRadius(r);
  cylinder->SetHeight(y1 - y0);
  cylinder->SetResolution(n);
  cylinder->CappingOn();
  AddSource(renderer, cylinder);
}

// An air-cooled engine's cylinder: a core with thin annular fins (discs) 0.045 apart.
void AddFinnedCylinder(vtkRenderer* renderer, double x, double z)
{
  AddCylinder(renderer, x, z, 0.3, 0.0, 1.1, 48);
  for (int i = 0; i < 20; ++i)
  {
    const double y = 0.12 + 0.045 * i;
    AddCylinder(renderer, x, z, 0.55, y, y + 0.015, 64);
  }
  AddCylinder(renderer, x, z, 0.2, 1.1, 1.3, 32); // the head's spark-plug boss
}

// Real-model stand-ins with fins and ribs (issue 16): an inline row of three finned
// cylinders, a heat sink of 16 fins 0.02 thick, and a ribbed bracket, on a 6 x 6 plane;
// R = 0.2, the fins' gaps (0.03 to 0.06) are well inside it.
bool Fins(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -3, 3, -3, 3);
  for (int i = 0; i < 3; ++i)
  {
    AddFinnedCylinder(renderer, -1.3 + 1.2 * i, -0.6);
  }
  BoxSet sink;
  sink.Add(-1.2, 0.4, 0.0, 0.08, 0.5, 1.3);
  for (int i = 0; i < 16; ++i)
  {
    const double x = -1.18 + 0.1 * i;
    sink.Add(x, x + 0.02, 0.08, 0.45, 0.5, 1.3);
  }
  sink.AddTo(renderer);
  BoxSet bracket; // an angle bracket with five triangular-ish ribs (stepped boxes)
  bracket.Add(0.8, 1.8, 0.0, 0.05, 0.5, 1.2);
  bracket.Add(0.8, 0.85, 0.05, 0.8, 0.5, 1.2);
  for (int i = 0; i < 5; ++i)
  {
    const double z = 0.52 + 0.155 * i;
    for (int k = 0; k < 6; ++k)
    {
      bracket.Add(0.85, 0.85 + 0.15 * (6 - k), 0.05 + 0.12 * k, 0.05 + 0.12 * (k + 1), z, z + 0.02);
    }
  }
  bracket.AddTo(renderer);
  SetCamera(renderer, { 1.2, 2.6, 4.2 }, { 0.1, 0.4, 0.2 }, { 0, 1, 0 }, 30);
  radius = 0.2;
  return true;
}

// A thin cubic lattice (bars 0.03 thick, cells 0.25) standing on a plane, R = 0.25.
bool Lattice(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -3, 3, -3, 3);
  BoxSet bars;
  const int n = 6, layers = 4;
  const double cell = 0.25, t = 0.015, x0 = -0.75, z0 = -0.75;
  for (int j = 0; j <= layers; ++j)
  {
    const double y = cell * j + t;
    for (int i = 0; i <= n; ++i)
    {
      const double c = x0 + cell * i;
      bars.Add(x0 - t, x0 + cell * n + t, y - t, y + t, c - t, c + t); // along x
      bars.Add(c - t, c + t, y - t, y + t, z0 - t, z0 + cell * n + t); // along z
    }
  }
  for (int i = 0; i <= n; ++i)
  {
    for (int k = 0; k <= n; ++k)
    {
      const double x = x0 + cell * i, z = z0 + cell * k;
      bars.Add(x - t, x + t, 0, cell * layers + 2 * t, z - t, z + t); // posts
    }
  }
  bars.AddTo(renderer);
  SetCamera(renderer, { 2.2, 2.4, 3.2 }, { 0, 0.45, 0 }, { 0, 1, 0 }, 30);
  radius = 0.25;
  return true;
}

// A large scene (about 7 x 6 in view) with R = 1.2 whose occluders lie between R/2 and R
// from what is seen: slabs floating 0.6 to 1.05 above the floor (the floor under them is
// seen from the oblique camera), walls 0.6 and 0.9 beyond the left and right frame edges and
// a block 0.8 beyond the top edge. Coarse cells darken here: their voxels reach inside R.
bool NearRadius(vtkRenderer* renderer, double aspect, double& radius, std::string&)
{
  AddGround(renderer, -10, 10, -10, 10);
  const Vec eye = { 0, 4.5, 6.5 };
  SetCamera(renderer, eye, { 0, 0, 0.3 }, { 0, 1, 0 }, 40);
  vtkCamera* camera = renderer->GetActiveCamera();
  const Vec bl = GroundPoint(camera, aspect, -1, -1), br = GroundPoint(camera, aspect, 1, -1);
  const Vec tl = GroundPoint(camera, aspect, -1, 1), tr = GroundPoint(camera, aspect, 1, 1);
  BoxSet parts;
  const double heights[4] = { 0.6, 0.75, 0.9, 1.05 };
  for (int i = 0; i < 4; ++i)
  {
    const double x = -3.0 + 1.6 * i;
    parts.Add(x, x + 1.4, heights[i], heights[i] + 0.06, -1.8 + 0.6 * i, -0.6 + 0.6 * i);
  }
  const double left = std::min(bl[0], tl[0]), right = std::max(br[0], tr[0]);
  parts.Add(left - 0.6 - 0.2, left - 0.6, 0, 1.5, tl[2] - 1, bl[2] + 1);
  parts.Add(right + 0.9, right + 0.9 + 0.2, 0, 1.5, tr[2] - 1, br[2] + 1);
  parts.Add(tl[0], tr[0], 0, 1.5, tl[2] - 0.8 - 0.3, tl[2] - 0.8);
  parts.AddTo(renderer);
  radius = 1.2;
  return true;
}

// A city block grid far larger than R: 30 x 30 buildings (2.5 x 2.5, 1 to 6 high) on a
// 120 x 120 ground with streets 1.5 wide, R = 1.5, seen from above a street. One grid with
// cells of R / 64 would need 5,200 cells across: the automatic settings use cascades.
bool City(vtkRenderer* renderer, double, double& radius, std::string&)
{
  AddGround(renderer, -61, 61, -61, 61);
  BoxSet buildings;
  unsigned int state = 12345u;
  for (int i = 0; i < 30; ++i)
  {
    for (int k = 0; k < 30; ++k)
    {
      state = state * 1664525u + 1013904223u; // a fixed LCG: the same city every run
      const double height = 1.0 + 5.0 * ((state >> 8) & 0xffff) / 65535.0;
      const double x = -60.0 + 4.0 * i, z = -60.0 + 4.0 * k;
      buildings.Add(x, x + 2.5, 0, height, z, z + 2.5);
    }
  }
  buildings.AddTo(renderer);
  SetCamera(renderer, { -14, 16, 34 }, { 2, 0, 8 }, { 0, 1, 0 }, 50);
  radius = 1.5;
  return true;
}

// A STEP file (optionally gzipped) meshed into triangles by gmsh (Debian's gmsh package),
// through a temporary STL file. Null with @p note set when gmsh or the file is missing.
vtkSmartPointer<vtkPolyData> MeshSTEP(const std::string& path, std::string& note)
{
  if (!std::ifstream(path, std::ios::binary).good())
  {
    note = "file '" + path + "' not found";
    return nullptr;
  }
  if (std::system("command -v gmsh >/dev/null 2>&1") != 0)
  {
    note = "gmsh is not installed (apt-get install gmsh)";
    return nullptr;
  }
  char step[] = "/tmp/vtkao-quality-XXXXXX.step";
  const int fd = mkstemps(step, 5);
  if (fd < 0)
  {
    note = "cannot create a temporary file";
    return nullptr;
  }
  close(fd);
  const std::string stl = std::string(step) + ".stl";
  const std::string command = "(gzip -dcf '" + path + "' > '" + step + "') && gmsh -v 0 '" + step +
    "' -2 -format stl -o '" + stl + "' >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  std::remove(step);
  vtkSmartPointer<vtkPolyData> mesh;
  if (status == 0)
  {
    mesh = LoadMesh(stl, note);
  }
  else
  {
    note = "gmsh could not mesh '" + path + "'";
  }
  std::remove(stl.c_str());
  return mesh;
}

// The AP203 test assembly "as1" (a plate with L-brackets, bolts, nuts and a rod; gmsh-doc's
// demos/boolean/as1-tu-203.stp.gz) meshed by gmsh, z up in the file, on a large ground plane.
bool CAD(vtkRenderer* renderer, double, double& radius, std::string& note)
{
  vtkSmartPointer<vtkPolyData> mesh =
    MeshSTEP("/usr/share/doc/gmsh-doc/doc/gmsh/demos/boolean/as1-tu-203.stp.gz", note);
  if (!mesh)
  {
    return false;
  }
  vtkNew<vtkTransform> upright; // the file's z up becomes y up; millimetres become 1/100
  upright->Scale(0.01, 0.01, 0.01);
  upright->RotateX(-90);
  vtkNew<vtkTransformPolyDataFilter> move;
  move->SetInputData(mesh);
  move->SetTransform(upright);
  move->Update();
  AddPolyData(renderer, move->GetOutput());
  double b[6];
  move->GetOutput()->GetBounds(b);
  AddGround(renderer, b[0] - 3, b[1] + 3, b[4] - 3, b[5] + 3, b[2]);
  FrameBounds(renderer, b, { 0.8, 1.1, 1.3 }, 30, 0.75);
  radius = 0.3;
  return true;
}

bool RealMesh(vtkRenderer* renderer,
  const std::string& path,
  bool upright,
  bool ground,
  const Vec& from,
  double radiusFraction,
  double& radius,
  std::string& note)
{
  vtkSmartPointer<vtkPolyData> mesh = LoadMesh(path, note);
  if (!mesh)
  {
    return false;
  }
  if (upright)
  {
    vtkNew<vtkTransform> rotate;
    rotate->RotateZ(90);
    vtkNew<vtkTransformPolyDataFilter> move;
    move->SetInputData(mesh);
    move->SetTransform(rotate);
    move->Update();
    mesh = move->GetOutput();
  }
  AddPolyData(renderer, mesh);
  double b[6];
  mesh->GetBounds(b);
  const double diagonal = Diagonal(b);
  if (ground)
  {
    const double m = 0.4 * diagonal;
    AddGround(renderer, b[0] - m, b[1] + m, b[4] - m, b[5] + m, b[2]);
  }
  FrameBounds(renderer, b, from, 30, 0.85);
  radius = radiusFraction * diagonal;
  return true;
}
}

namespace vtkao
{
std::vector<QualityScene> QualityScenes()
{
  const std::string aneurysm = "/usr/share/doc/gmsh-doc/doc/gmsh/demos/api/aneurysm_data.stl.gz";
  const std::string tardis = "/usr/share/openscad/testdata/scad/misc/bad-stl-tardis.stl";
  return {
    { "contact", "sphere, turned box and lying cylinder resting on a plane", false, Contact },
    { "crease", "grooves, an open box (cavity) and a staircase", false, Crease },
    { "crease-disjoint",
      "the crease scene built from boxes that touch without overlapping",
      false,
      CreaseDisjoint },
    { "offscreen",
      "ground beside walls just outside the left, right and bottom frame edges",
      true,
      Offscreen },
    { "hidden",
      "floor seen through a hole in a plate; blocks hidden under the plate",
      true,
      Hidden },
    { "thin", "thin shelves, fins and a low table top (0.02 thick, R = 1)", false, Thin },
    { "sheets",
      "four open sheets stacked 0.08 apart (R = 1) and one alone, above a plane",
      false,
      Sheets },
    { "glyphs", "576 sphere glyphs (vtkGlyph3DMapper) in 3 layers above a plane", false, Glyphs },
    { "iso", "iso-surface 165 of vtkRTAnalyticSource on [-12, 12]^3", false, Iso },
    { "fins",
      "three finned engine cylinders, a 16-fin heat sink and a ribbed bracket on a 6 x 6 plane "
      "(fins 0.015 to 0.02 thick, R = 0.2)",
      false,
      Fins },
    { "lattice",
      "a cubic lattice of bars 0.03 thick (cells 0.25, R = 0.25) on a plane",
      false,
      Lattice },
    { "cad",
      "AP203 assembly as1 (plate, L-brackets, bolts, nuts; gmsh-doc's as1-tu-203.stp.gz meshed "
      "by gmsh) on a 8 x 7.5 ground plane, R = 0.3",
      false,
      CAD },
    { "near-radius",
      "floor seen over about 7 x 6, R = 1.2: slabs floating 0.6-1.05 above it, walls and a "
      "block just outside the frame, all between R/2 and R from what is seen",
      true,
      NearRadius },
    { "city",
      "30 x 30 buildings (1 to 6 high, streets 1.5 wide) on a 120 x 120 ground, R = 1.5, seen "
      "from above a street: a region 80 R wide",
      false,
      City },
    { "builtin",
      "the vtkao built-in scene (its camera, wall outside the view)",
      true,
      [](vtkRenderer* r, double, double& radius, std::string&)
      {
        AddBuiltInScene(r);
        radius = 2.0;
        return true;
      } },
    { "aneurysm",
      "vessel surface from gmsh-doc (demos/api/aneurysm_data.stl.gz), R = 0.2 diagonal",
      false,
      [aneurysm](vtkRenderer* r, double, double& radius, std::string& note) {
        return RealMesh(r, aneurysm, false, false, { 0.3, 0.2, 1 }, 0.2, radius, note);
      } },
    { "tardis",
      "TARDIS model from openscad-testing-data (bad-stl-tardis.stl) on a plane",
      false,
      [tardis](vtkRenderer* r, double, double& radius, std::string& note) {
        return RealMesh(r, tardis, true, true, { 1, 0.7, 1.6 }, 0.1, radius, note);
      } },
  };
}
}
