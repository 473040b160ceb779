#include "vtkAOEmbreeScene.h"

#include "vtkAOCompat.h"
#include "vtkAOPropGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// One Embree triangle geometry and what Intersect() needs to shade a hit.
struct Mesh
{
  std::vector<float> Vertices; // x y z per vertex, plus one pad float (Embree reads 16 bytes)
  std::vector<unsigned int> Indices;
  std::vector<float> Normals; // per vertex, empty when the surface had none
};

bool Finite3(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void Union(double bounds[6], const double b[6])
{
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = std::min(bounds[2 * i], b[2 * i]);
    bounds[2 * i + 1] = std::max(bounds[2 * i + 1], b[2 * i + 1]);
  }
}

bool ValidBounds(const double b[6])
{
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(b[i]))
    {
      return false;
    }
  }
  return b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
}

// splitmix64: a well-mixed 64-bit hash, for the per-point rotation of the sample set.
std::uint64_t Mix(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Van der Corput radical inverse in base 2: the second coordinate of the Hammersley set.
double RadicalInverse(std::uint32_t bits)
{
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  return bits * 2.3283064365386963e-10; // / 2^32
}

double Fraction(double x)
{
  return x - std::floor(x);
}

double Diagonal(const double b[6])
{
  return std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

// A ray from @p org along @p dir over [tnear, tfar] (scene coordinates, relative to the origin).
void InitRay(RTCRay& ray, const float org[3], const double dir[3], double tnear, double tfar)
{
  ray.org_x = org[0];
  ray.org_y = org[1];
  ray.org_z = org[2];
  ray.dir_x = static_cast<float>(dir[0]);
  ray.dir_y = static_cast<float>(dir[1]);
  ray.dir_z = static_cast<float>(dir[2]);
  ray.tnear = static_cast<float>(tnear);
  ray.tfar = static_cast<float>(tfar);
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
}

}

struct vtkAOEmbreeScene::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  bool Committed = false;
  std::vector<Mesh> Meshes; // indexed by Embree geometry id
  bool HasOrigin = false;
  double Origin[3] = { 0, 0, 0 };
  double PolyBounds[6] = { VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN };
  double PropBounds[6] = { VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX,
    VTK_DOUBLE_MIN };
  bool HasProps = false;
  int Groups = 0; // vtkAOPropGeometry group numbers handed out so far
  vtkIdType Triangles = 0;
  std::string Error;
  vtkNew<vtkPolygon> Polygon;
  vtkNew<vtkIdList> PolygonTriangles;

  static void OnError(void* self, RTCError, const char* message)
  {
    static_cast<Internals*>(self)->Error = std::string("Embree: ") + message;
  }

  /// Append @p surface, transformed by @p matrix, to @p mesh.
  vtkIdType Append(Mesh& mesh, vtkPolyData* surface, vtkMatrix4x4* matrix);

  // The steps of Append.
  /// @p points transformed by @p matrix (x y z each); the first finite one becomes the Origin.
  std::vector<double> WorldPoints(vtkPoints* points, vtkMatrix4x4* matrix);
  /// @p world as floats relative to the Origin at the end of mesh.Vertices (before its pad);
  /// returns the index of the first.
  size_t AppendVertices(Mesh& mesh, const std::vector<double>& world);
  /// The first @p n point normals, made unit, transformed by the inverse transpose of @p matrix.
  static void AppendNormals(Mesh& mesh, vtkDataArray* normals, vtkMatrix4x4* matrix, vtkIdType n);
  /// The triangle of points a, b, c of @p world when it is finite and has an area.
  bool AddTriangle(Mesh& mesh,
    const std::vector<double>& world,
    size_t base,
    vtkIdType a,
    vtkIdType b,
    vtkIdType c);
  /// The polygons (ear cut) and strips of @p surface as triangles; returns how many.
  vtkIdType AppendCells(Mesh& mesh,
    vtkPolyData* surface,
    const std::vector<double>& world,
    size_t base);
};

//------------------------------------------------------------------------------
vtkAOEmbreeScene::vtkAOEmbreeScene()
  : Impl(new Internals)
{
  this->Impl->Device = rtcNewDevice(nullptr);
  if (!this->Impl->Device)
  {
    this->Impl->Error = "Embree: cannot create a device";
    return;
  }
  rtcSetDeviceErrorFunction(this->Impl->Device, &Internals::OnError, this->Impl.get());
  this->Impl->Scene = rtcNewScene(this->Impl->Device);
  // Reference quality over build speed: the scene is traced with many rays per point.
  rtcSetSceneBuildQuality(this->Impl->Scene, RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(this->Impl->Scene, RTC_SCENE_FLAG_ROBUST);
}

//------------------------------------------------------------------------------
vtkAOEmbreeScene::~vtkAOEmbreeScene()
{
  if (this->Impl->Scene)
  {
    rtcReleaseScene(this->Impl->Scene);
  }
  if (this->Impl->Device)
  {
    rtcReleaseDevice(this->Impl->Device);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkAOEmbreeScene::Internals::Append(Mesh& mesh,
  vtkPolyData* surface,
  vtkMatrix4x4* matrix)
{
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  if (!points || points->GetNumberOfPoints() == 0 ||
    (surface->GetNumberOfPolys() == 0 && surface->GetNumberOfStrips() == 0))
  {
    return 0;
  }
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  const bool keepNormals = normals && normals->GetNumberOfComponents() == 3 &&
    (mesh.Indices.empty() || !mesh.Normals.empty());
  const std::vector<double> world = this->WorldPoints(points, matrix);
  const size_t base = this->AppendVertices(mesh, world);
  if (keepNormals)
  {
    AppendNormals(mesh, normals, matrix, points->GetNumberOfPoints());
  }
  else
  {
    mesh.Normals.clear();
  }
  const vtkIdType added = this->AppendCells(mesh, surface, world, base);
  this->Triangles += added;
  return added;
}

//------------------------------------------------------------------------------
std::vector<double> vtkAOEmbreeScene::Internals::WorldPoints(vtkPoints* points,
  vtkMatrix4x4* matrix)
{
  const vtkIdType n = points->GetNumberOfPoints();
  std::vector<double> world(static_cast<size_t>(3 * n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[4] = { 0, 0, 0, 1 };
    points->GetPoint(i, p);
    if (matrix)
    {
      matrix->MultiplyPoint(p, p);
      if (p[3] != 1.0 && p[3] != 0.0)
      {
        p[0] /= p[3];
        p[1] /= p[3];
        p[2] /= p[3];
      }
    }
    std::copy(p, p + 3, world.begin() + 3 * i);
    if (!this->HasOrigin && Finite3(p))
    {
      std::copy(p, p + 3, this->Origin);
      this->HasOrigin = true;
    }
  }
  return world;
}

//------------------------------------------------------------------------------
size_t vtkAOEmbreeScene::Internals::AppendVertices(Mesh& mesh, const std::vector<double>& world)
{
  if (!mesh.Vertices.empty())
  {
    mesh.Vertices.pop_back(); // the pad
  }
  const size_t base = mesh.Vertices.size() / 3;
  mesh.Vertices.reserve(mesh.Vertices.size() + world.size() + 1);
  for (size_t i = 0; i < world.size(); ++i)
  {
    mesh.Vertices.push_back(static_cast<float>(world[i] - this->Origin[i % 3]));
  }
  mesh.Vertices.push_back(0.0f);
  return base;
}

//------------------------------------------------------------------------------
void vtkAOEmbreeScene::Internals::AppendNormals(Mesh& mesh,
  vtkDataArray* normals,
  vtkMatrix4x4* matrix,
  vtkIdType n)
{
  // Normals transform with the inverse transpose of the linear part.
  double normalMatrix[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  if (matrix)
  {
    double linear[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        linear[r][c] = matrix->GetElement(r, c);
      }
    }
    double inverse[3][3];
    vtkMath::Invert3x3(linear, inverse);
    vtkMath::Transpose3x3(inverse, normalMatrix);
  }
  mesh.Normals.reserve(mesh.Normals.size() + 3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v[3];
    normals->GetTuple(i, v);
    double w[3];
    vtkMath::Multiply3x3(normalMatrix, v, w);
    if (!Finite3(w) || vtkMath::Normalize(w) == 0.0)
    {
      w[0] = w[1] = w[2] = 0.0; // falls back to the face normal at hits
    }
    mesh.Normals.insert(mesh.Normals.end(),
      { static_cast<float>(w[0]), static_cast<float>(w[1]), static_cast<float>(w[2]) });
  }
}

//------------------------------------------------------------------------------
bool vtkAOEmbreeScene::Internals::AddTriangle(Mesh& mesh,
  const std::vector<double>& world,
  size_t base,
  vtkIdType a,
  vtkIdType b,
  vtkIdType c)
{
  const vtkIdType n = static_cast<vtkIdType>(world.size() / 3);
  if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n)
  {
    return false;
  }
  const double* pa = &world[3 * a];
  const double* pb = &world[3 * b];
  const double* pc = &world[3 * c];
  if (!Finite3(pa) || !Finite3(pb) || !Finite3(pc))
  {
    return false;
  }
  const double e1[3] = { pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2] };
  const double e2[3] = { pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2] };
  double cross[3];
  vtkMath::Cross(e1, e2, cross);
  if (!(vtkMath::Norm(cross) > 0.0))
  {
    return false; // degenerate: no area, cannot occlude
  }
  mesh.Indices.insert(mesh.Indices.end(),
    { static_cast<unsigned int>(base + a),
      static_cast<unsigned int>(base + b),
      static_cast<unsigned int>(base + c) });
  for (const double* p : { pa, pb, pc })
  {
    for (int i = 0; i < 3; ++i)
    {
      this->PolyBounds[2 * i] = std::min(this->PolyBounds[2 * i], p[i]);
      this->PolyBounds[2 * i + 1] = std::max(this->PolyBounds[2 * i + 1], p[i]);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkAOEmbreeScene::Internals::AppendCells(Mesh& mesh,
  vtkPolyData* surface,
  const std::vector<double>& world,
  size_t base)
{
  vtkIdType added = 0;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  { added += this->AddTriangle(mesh, world, base, a, b, c) ? 1 : 0; };
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  auto polys = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(npts, pts);
    if (npts == 3)
    {
      addTriangle(pts[0], pts[1], pts[2]);
    }
    else if (npts > 3)
    {
      // Ear cutting, so non-convex polygons are covered exactly.
      this->Polygon->Initialize(static_cast<int>(npts), pts, surface->GetPoints());
      this->PolygonTriangles->Reset();
      vtkAOTriangulatePolygon(this->Polygon, this->PolygonTriangles);
      for (vtkIdType t = 0; t + 2 < this->PolygonTriangles->GetNumberOfIds(); t += 3)
      {
        addTriangle(pts[this->PolygonTriangles->GetId(t)],
          pts[this->PolygonTriangles->GetId(t + 1)],
          pts[this->PolygonTriangles->GetId(t + 2)]);
      }
    }
  }
  auto strips = vtk::TakeSmartPointer(surface->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType i = 0; i + 2 < npts; ++i)
    {
      addTriangle(pts[i], pts[i + 1], pts[i + 2]);
    }
  }
  return added;
}

//------------------------------------------------------------------------------
vtkIdType vtkAOEmbreeScene::AddPolyData(vtkPolyData* surface, vtkMatrix4x4* matrix)
{
  Mesh mesh;
  const vtkIdType added = this->Impl->Append(mesh, surface, matrix);
  if (added > 0)
  {
    this->Impl->Meshes.push_back(std::move(mesh));
    this->Impl->Committed = false;
  }
  return added;
}

//------------------------------------------------------------------------------
bool vtkAOEmbreeScene::AddProp(vtkProp* prop, bool translucent)
{
  // The same props and surfaces as the passes (vtkAOPropGeometry); each mapper's surfaces (a
  // composite's leaves, a glyph mapper's glyphs) go into one mesh, as the mapper draws them.
  double b[6];
  if (!vtkAOPropGeometry::Occludes(prop, translucent, b))
  {
    return false;
  }
  Mesh mesh;
  int current = -1;
  auto flush = [this, &mesh]()
  {
    if (!mesh.Indices.empty())
    {
      this->Impl->Meshes.push_back(std::move(mesh));
      this->Impl->Committed = false;
    }
    mesh = Mesh();
  };
  vtkAOPropGeometry::VisitProp(prop,
    translucent,
    this->Impl->Groups,
    [&](const vtkAOPropGeometry::Surface& surface)
    {
      if (surface.Group != current)
      {
        flush();
        current = surface.Group;
      }
      this->Impl->Append(mesh, surface.Data, surface.Matrix);
    });
  flush();
  Union(this->Impl->PropBounds, b);
  this->Impl->HasProps = true;
  return true;
}

//------------------------------------------------------------------------------
int vtkAOEmbreeScene::AddRenderer(vtkRenderer* renderer, bool translucent)
{
  int used = 0;
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  if (!props)
  {
    return 0;
  }
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    used += this->AddProp(prop, translucent) ? 1 : 0;
  }
  return used;
}

//------------------------------------------------------------------------------
bool vtkAOEmbreeScene::Commit()
{
  Internals& s = *this->Impl;
  if (!s.Scene)
  {
    return false;
  }
  if (s.Committed)
  {
    return s.Error.empty();
  }
  for (unsigned int id = 0; id < s.Meshes.size(); ++id)
  {
    Mesh& mesh = s.Meshes[id];
    RTCGeometry geometry = rtcNewGeometry(s.Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_VERTEX,
      0,
      RTC_FORMAT_FLOAT3,
      mesh.Vertices.data(),
      0,
      3 * sizeof(float),
      (mesh.Vertices.size() - 1) / 3);
    rtcSetSharedGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_INDEX,
      0,
      RTC_FORMAT_UINT3,
      mesh.Indices.data(),
      0,
      3 * sizeof(unsigned int),
      mesh.Indices.size() / 3);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(s.Scene, geometry, id);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(s.Scene);
  s.Committed = true;
  return s.Error.empty();
}

//------------------------------------------------------------------------------
vtkIdType vtkAOEmbreeScene::GetNumberOfTriangles() const
{
  return this->Impl->Triangles;
}

//------------------------------------------------------------------------------
void vtkAOEmbreeScene::GetBounds(double bounds[6]) const
{
  const double* b = this->Impl->HasProps ? this->Impl->PropBounds : this->Impl->PolyBounds;
  std::copy(b, b + 6, bounds);
}

//------------------------------------------------------------------------------
const std::string& vtkAOEmbreeScene::GetError() const
{
  return this->Impl->Error;
}

//------------------------------------------------------------------------------
bool vtkAOEmbreeScene::Intersect(const double origin[3],
  const double dir[3],
  double tmin,
  double tmax,
  double& t,
  double point[3],
  double normal[3],
  double faceNormal[3]) const
{
  const Internals& s = *this->Impl;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  const float org[3] = { static_cast<float>(origin[0] - s.Origin[0]),
    static_cast<float>(origin[1] - s.Origin[1]),
    static_cast<float>(origin[2] - s.Origin[2]) };
  RTCRayHit rh;
  InitRay(rh.ray, org, dir, tmin, tmax);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(s.Scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  t = rh.ray.tfar;
  for (int i = 0; i < 3; ++i)
  {
    point[i] = origin[i] + t * dir[i];
  }
  normal[0] = rh.hit.Ng_x;
  normal[1] = rh.hit.Ng_y;
  normal[2] = rh.hit.Ng_z;
  if (faceNormal)
  {
    std::copy(normal, normal + 3, faceNormal);
    vtkMath::Normalize(faceNormal);
  }
  const Mesh& mesh = s.Meshes[rh.hit.geomID];
  if (!mesh.Normals.empty())
  {
    const unsigned int* tri = &mesh.Indices[3 * static_cast<size_t>(rh.hit.primID)];
    const double w[3] = { 1.0 - rh.hit.u - rh.hit.v, rh.hit.u, rh.hit.v };
    double n[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      for (int i = 0; i < 3; ++i)
      {
        n[i] += w[k] * mesh.Normals[3 * static_cast<size_t>(tri[k]) + i];
      }
    }
    if (vtkMath::Norm(n) > 1e-6)
    {
      std::copy(n, n + 3, normal);
    }
  }
  vtkMath::Normalize(normal);
  return true;
}

//------------------------------------------------------------------------------
double vtkAOEmbreeScene::ComputeAccessibility(const double p[3],
  const double n[3],
  const vtkAOIntegralParameters& parameters,
  std::uint64_t key,
  std::int64_t& rays) const
{
  const Internals& s = *this->Impl;
  const int count = std::max(1, parameters.Samples);
  const double radius = parameters.Radius;
  if (!(radius > 0.0) || s.Meshes.empty())
  {
    return 1.0;
  }
  // Tangent frame (Duff et al. 2017, branchless).
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double b = n[0] * n[1] * a;
  const double tangent[3] = { 1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0] };
  const double bitangent[3] = { b, sign + n[1] * n[1] * a, -n[1] };

  // Cone of half-angle Spread * pi/2 around n.
  const double halfAngle = std::min(1.0, std::max(1e-6, parameters.Spread)) * vtkMath::Pi() / 2;
  const double cosMax = std::max(0.0, std::cos(halfAngle));
  const double sin2Max = 1.0 - cosMax * cosMax;

  // Cranley-Patterson rotation of the Hammersley set, fixed by (seed, key).
  const std::uint64_t h = Mix(key ^ Mix(parameters.Seed + 0x632BE59BD9B4E019ull));
  const double r1 = (h >> 40) * (1.0 / 16777216.0);
  const double r2 = ((h >> 16) & 0xFFFFFF) * (1.0 / 16777216.0);

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  const float org[3] = { static_cast<float>(p[0] + parameters.Bias * n[0] - s.Origin[0]),
    static_cast<float>(p[1] + parameters.Bias * n[1] - s.Origin[1]),
    static_cast<float>(p[2] + parameters.Bias * n[2] - s.Origin[2]) };
  double occlusion = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const double u1 = Fraction((i + 0.5) / count + r1);
    const double u2 = Fraction(RadicalInverse(static_cast<std::uint32_t>(i)) + r2);
    double cosTheta;
    if (parameters.CosineSampling)
    {
      // pdf proportional to cos: sin^2(theta) uniform in [0, sin^2(max)].
      cosTheta = std::sqrt(std::max(0.0, 1.0 - u1 * sin2Max));
    }
    else
    {
      // Uniform in solid angle: cos(theta) uniform in [cos(max), 1].
      cosTheta = 1.0 - u1 * (1.0 - cosMax);
    }
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * vtkMath::Pi() * u2;
    const double x = sinTheta * std::cos(phi), y = sinTheta * std::sin(phi);
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = x * tangent[k] + y * bitangent[k] + cosTheta * n[k];
    }

    double w = 0.0;
    if (parameters.BinaryFalloff)
    {
      RTCRay ray;
      InitRay(ray, org, d, 0.0, radius);
      rtcOccluded1(s.Scene, &context, &ray);
      w = ray.tfar < 0.0f ? 1.0 : 0.0; // Embree sets tfar to -inf when occluded
    }
    else
    {
      RTCRayHit rh;
      InitRay(rh.ray, org, d, 0.0, radius);
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(s.Scene, &context, &rh);
      if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
      {
        // Wendland (HAO eq. 3): W(t) = (1 - t/R)^4 (4 t/R + 1).
        const double q = std::min(1.0, std::max(0.0, rh.ray.tfar / radius));
        const double m = 1.0 - q;
        w = m * m * m * m * (4.0 * q + 1.0);
      }
    }
    // Uniform directions carry the cosine weight explicitly.
    occlusion += parameters.CosineSampling ? w : w * cosTheta;
  }
  rays += count;
  double fraction = occlusion / count;
  if (!parameters.CosineSampling)
  {
    // E[W cos] under the uniform pdf 1/(2 pi (1 - cosMax)), divided by C = pi sin^2(max).
    fraction *= 2.0 * (1.0 - cosMax) / sin2Max;
  }
  return std::min(1.0, std::max(0.0, 1.0 - fraction));
}

//------------------------------------------------------------------------------
void vtkAOEmbreeScene::GetEffectiveRadiusAndBias(double radius,
  double bias,
  double& effectiveRadius,
  double& effectiveBias) const
{
  double bounds[6];
  this->GetBounds(bounds);
  effectiveRadius = radius > 0.0 ? radius : AutomaticRadius(bounds);
  effectiveBias = bias > 0.0 ? bias : AutomaticBias(bounds);
}

//------------------------------------------------------------------------------
double vtkAOEmbreeScene::AutomaticRadius(const double b[6])
{
  if (!ValidBounds(b))
  {
    return 0.0;
  }
  return 0.1 * Diagonal(b);
}

//------------------------------------------------------------------------------
double vtkAOEmbreeScene::AutomaticBias(const double b[6])
{
  if (!ValidBounds(b))
  {
    return 0.0;
  }
  // A tiny offset, as offline renderers use: 1e-4 of the diagonal (single-precision hit
  // points are good to about 1e-7 of the coordinates). Independent of the radius.
  return 1e-4 * Diagonal(b);
}
