#include "vtkAOOccluderTriangles.h"

#include "vtkAOPropGeometry.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>

namespace
{
// A surface made ready for the volumes: its triangles (polygons and strips triangulated,
// coincident points merged, degenerate triangles dropped), each closed component
// consistently oriented with its front side out, and which triangles are one-sided.
struct PreparedSurface
{
  vtkMTimeType Time = 0;
  vtkSmartPointer<vtkPolyData> Source; // keeps the key alive while it is cached
  std::vector<double> Points;          // x y z of the merged points
  std::vector<vtkIdType> Triangles;    // 3 ids each, in the orientation to draw
  std::vector<unsigned char> OneSided; // per triangle: part of a closed, oriented component
  bool Used = false;
};

// Edge (either direction) -> the triangles that have it.
using EdgeMap = std::unordered_map<std::uint64_t, std::vector<vtkIdType>>;

std::uint64_t EdgeKey(vtkIdType a, vtkIdType b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) ^ lo;
}

EdgeMap BuildEdgeMap(const std::vector<vtkIdType>& t)
{
  const size_t n = t.size() / 3;
  EdgeMap edges;
  edges.reserve(3 * n);
  for (size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges[EdgeKey(t[3 * i + k], t[3 * i + (k + 1) % 3])].push_back(static_cast<vtkIdType>(i));
    }
  }
  return edges;
}

// The other triangle of a manifold edge shared by @p i.
size_t OtherTriangle(const std::vector<vtkIdType>& shared, size_t i)
{
  return static_cast<size_t>(shared[0] == static_cast<vtkIdType>(i) ? shared[1] : shared[0]);
}

// Whether triangle i of @p t runs along the directed edge a -> b.
bool Runs(const std::vector<vtkIdType>& t, size_t i, vtkIdType a, vtkIdType b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[3 * i + k] == a && t[3 * i + (k + 1) % 3] == b)
    {
      return true;
    }
  }
  return false;
}

// Propagates a consistent orientation from @p seed across manifold edges: flip[i] = +1 keep,
// -1 reverse for every triangle reached (listed in @p component). Returns whether the
// component is closed and orientable.
bool OrientComponent(const std::vector<vtkIdType>& t,
  EdgeMap& edges,
  size_t seed,
  std::vector<signed char>& flip,
  std::vector<size_t>& component)
{
  component.clear();
  std::vector<size_t> stack(1, seed);
  flip[seed] = 1;
  bool closed = true;
  while (!stack.empty())
  {
    const size_t i = stack.back();
    stack.pop_back();
    component.push_back(i);
    for (int k = 0; k < 3; ++k)
    {
      // The edge as triangle i will be drawn.
      vtkIdType a = t[3 * i + k], b = t[3 * i + (k + 1) % 3];
      if (flip[i] < 0)
      {
        std::swap(a, b);
      }
      const std::vector<vtkIdType>& shared = edges[EdgeKey(a, b)];
      if (shared.size() != 2)
      {
        closed = false; // a boundary or non-manifold edge
        continue;
      }
      const size_t j = OtherTriangle(shared, i);
      // Consistent when j, as drawn, runs b -> a.
      const signed char wanted = static_cast<signed char>(Runs(t, j, a, b) ? -1 : 1);
      if (flip[j] == 0)
      {
        flip[j] = wanted;
        stack.push_back(j);
      }
      else if (flip[j] != wanted)
      {
        closed = false; // non-orientable (or a triangle listed twice)
      }
    }
  }
  return closed;
}

// Six times the signed volume of a closed component as flipped, relative to one of its points.
double SignedVolume(const PreparedSurface& surface,
  const std::vector<size_t>& component,
  const std::vector<signed char>& flip)
{
  const std::vector<vtkIdType>& t = surface.Triangles;
  const double* o = &surface.Points[3 * t[3 * component[0]]];
  double volume = 0.0;
  for (size_t i : component)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const double* q = &surface.Points[3 * t[3 * i + k]];
      for (int c = 0; c < 3; ++c)
      {
        p[k][c] = q[c] - o[c];
      }
    }
    double bc[3];
    vtkMath::Cross(p[1], p[2], bc);
    volume += flip[i] * vtkMath::Dot(p[0], bc);
  }
  return volume;
}

// A closed component (every edge shared by exactly two of its triangles, in opposite
// directions once oriented) occludes from its outside only: its triangles are flagged
// one-sided and turned so that the enclosed volume is positive. Components that are open,
// non-manifold or non-orientable stay two-sided, as they were given. Orientation is
// propagated across shared edges, so sources with inconsistent winding (a box built from
// independently wound faces) are handled.
void OrientComponents(PreparedSurface& surface)
{
  std::vector<vtkIdType>& t = surface.Triangles;
  const size_t n = t.size() / 3;
  EdgeMap edges = BuildEdgeMap(t);
  surface.OneSided.assign(n, 0);
  std::vector<signed char> flip(n, 0); // 0 unvisited, +1 keep, -1 reverse
  std::vector<size_t> component;
  for (size_t seed = 0; seed < n; ++seed)
  {
    if (flip[seed] != 0)
    {
      continue;
    }
    if (!OrientComponent(t, edges, seed, flip, component))
    {
      for (size_t i : component)
      {
        flip[i] = 1; // two-sided: the given winding is as good as any
      }
      continue;
    }
    const signed char outward =
      static_cast<signed char>(SignedVolume(surface, component, flip) < 0.0 ? -1 : 1);
    for (size_t i : component)
    {
      flip[i] = static_cast<signed char>(flip[i] * outward);
      surface.OneSided[i] = 1;
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    if (flip[i] < 0)
    {
      std::swap(t[3 * i + 1], t[3 * i + 2]);
    }
  }
}

// Per triangle of a surface: its unit normal, plane offset and area; and the size of the
// surface (the diagonal of its triangles' bounds) for relative tolerances.
struct TrianglePlanes
{
  std::vector<std::array<double, 3>> Normal;
  std::vector<double> Offset;
  std::vector<double> Area;
  double Size = 0.0;

  explicit TrianglePlanes(const PreparedSurface& surface)
  {
    const std::vector<vtkIdType>& t = surface.Triangles;
    const size_t n = t.size() / 3;
    const double* p = surface.Points.data();
    this->Normal.resize(n);
    this->Offset.resize(n);
    this->Area.resize(n);
    double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
    for (size_t i = 0; i < n; ++i)
    {
      const double* a = p + 3 * t[3 * i];
      const double* b = p + 3 * t[3 * i + 1];
      const double* c = p + 3 * t[3 * i + 2];
      double e1[3], e2[3];
      vtkMath::Subtract(b, a, e1);
      vtkMath::Subtract(c, a, e2);
      vtkMath::Cross(e1, e2, this->Normal[i].data());
      this->Area[i] = 0.5 * vtkMath::Normalize(this->Normal[i].data());
      this->Offset[i] = vtkMath::Dot(this->Normal[i].data(), a);
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min({ lo[k], a[k], b[k], c[k] });
        hi[k] = std::max({ hi[k], a[k], b[k], c[k] });
      }
    }
    this->Size = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  }
};

using Point2 = std::array<double, 2>;
using PlanePoint = std::pair<Point2, vtkIdType>; // a point in a patch's plane, and its id

// Twice the signed area of the triangle o, a, b.
double Cross2(const Point2& o, const Point2& a, const Point2& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// The convex hull, counter-clockwise, of 2-D points sorted by x then y (Andrew's monotone
// chain), collinear points dropped: indices into @p pts.
std::vector<size_t> ConvexHull(const std::vector<PlanePoint>& pts, double eps)
{
  std::vector<size_t> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i)
  {
    while (k >= 2 && Cross2(pts[hull[k - 2]].first, pts[hull[k - 1]].first, pts[i].first) <= eps)
    {
      --k;
    }
    hull[k++] = i;
  }
  for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;)
  {
    while (
      k >= lower && Cross2(pts[hull[k - 2]].first, pts[hull[k - 1]].first, pts[i].first) <= eps)
    {
      --k;
    }
    hull[k++] = i;
  }
  hull.resize(k > 0 ? k - 1 : 0);
  return hull;
}

// The outline (point ids, counter-clockwise about the normal) of a coplanar patch if its
// triangles tile their convex hull (total area equal to the hull's, without holes or
// overlaps) and a fan over it has fewer triangles; empty otherwise.
std::vector<vtkIdType> ConvexOutline(const PreparedSurface& surface,
  const TrianglePlanes& planes,
  const std::vector<size_t>& patch)
{
  std::vector<vtkIdType> outline;
  if (patch.size() < 3)
  {
    return outline;
  }
  // The patch's points in a frame of its plane (u, v, normal right-handed).
  const std::vector<vtkIdType>& t = surface.Triangles;
  const double* p = surface.Points.data();
  const double* nn = planes.Normal[patch[0]].data();
  double u[3], v[3];
  vtkMath::Perpendiculars(nn, u, v, 0.0);
  std::vector<PlanePoint> pts;
  double total = 0.0;
  for (size_t i : patch)
  {
    total += planes.Area[i];
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType id = t[3 * i + k];
      pts.push_back({ { vtkMath::Dot(p + 3 * id, u), vtkMath::Dot(p + 3 * id, v) }, id });
    }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(),
              pts.end(),
              [](const auto& a, const auto& b) { return a.second == b.second; }),
    pts.end());
  const std::vector<size_t> hull = ConvexHull(pts, 1e-12 * planes.Size * planes.Size);
  double hullArea = 0.0;
  for (size_t i = 1; i + 1 < hull.size(); ++i)
  {
    hullArea += 0.5 * Cross2(pts[hull[0]].first, pts[hull[i]].first, pts[hull[i + 1]].first);
  }
  if (hull.size() >= 3 && hull.size() - 2 < patch.size() &&
    std::abs(hullArea - total) <= 1e-6 * total)
  {
    for (size_t i : hull)
    {
      outline.push_back(pts[i].second);
    }
  }
  return outline;
}

// The triangles reached from @p seed across manifold edges whose planes agree with the
// seed's (and that are one-sided alike); marks them visited.
void GrowCoplanarPatch(const PreparedSurface& surface,
  const TrianglePlanes& planes,
  EdgeMap& edges,
  size_t seed,
  std::vector<unsigned char>& visited,
  std::vector<size_t>& patch)
{
  const std::vector<vtkIdType>& t = surface.Triangles;
  auto coplanar = [&](size_t i, size_t j)
  {
    return vtkMath::Dot(planes.Normal[i].data(), planes.Normal[j].data()) > 1.0 - 1e-10 &&
      std::abs(planes.Offset[i] - planes.Offset[j]) <= 1e-9 * planes.Size &&
      surface.OneSided[i] == surface.OneSided[j];
  };
  patch.clear();
  std::vector<size_t> stack(1, seed);
  visited[seed] = 1;
  while (!stack.empty())
  {
    const size_t i = stack.back();
    stack.pop_back();
    patch.push_back(i);
    for (int k = 0; k < 3; ++k)
    {
      const auto& shared = edges[EdgeKey(t[3 * i + k], t[3 * i + (k + 1) % 3])];
      if (shared.size() != 2)
      {
        continue;
      }
      const size_t j = OtherTriangle(shared, i);
      if (!visited[j] && coplanar(seed, j))
      {
        visited[j] = 1;
        stack.push_back(j);
      }
    }
  }
}

// Coplanar patches whose union is convex (a tessellated plane or rectangle face, the flat
// sides of a structured grid's surface) are re-triangulated as a fan over their outline. The
// occlusion of a region is the sum over any partition of it, so A is the same; but each
// triangle costs a volume, at least 2R across whatever its size, and a tessellated ground's
// thousands of overlapping volumes become two. Triangles join a patch across manifold edges
// when their planes agree; a patch is replaced only if its triangles' total area equals the
// area of their convex hull (so they tile the hull without holes or overlaps).
void MergeCoplanarPatches(PreparedSurface& surface)
{
  std::vector<vtkIdType>& t = surface.Triangles;
  const size_t n = t.size() / 3;
  if (n < 3)
  {
    return;
  }
  const TrianglePlanes planes(surface);
  EdgeMap edges = BuildEdgeMap(t);
  std::vector<unsigned char> visited(n, 0);
  std::vector<vtkIdType> kept;
  std::vector<unsigned char> keptOneSided;
  kept.reserve(t.size());
  std::vector<size_t> patch;
  for (size_t seed = 0; seed < n; ++seed)
  {
    if (visited[seed])
    {
      continue;
    }
    GrowCoplanarPatch(surface, planes, edges, seed, visited, patch);
    const std::vector<vtkIdType> outline = ConvexOutline(surface, planes, patch);
    if (!outline.empty())
    {
      for (size_t i = 1; i + 1 < outline.size(); ++i)
      {
        kept.insert(kept.end(), { outline[0], outline[i], outline[i + 1] });
        keptOneSided.push_back(surface.OneSided[seed]);
      }
    }
    else
    {
      for (size_t i : patch)
      {
        kept.insert(kept.end(), t.begin() + 3 * i, t.begin() + 3 * i + 3);
        keptOneSided.push_back(surface.OneSided[i]);
      }
    }
  }
  t.swap(kept);
  surface.OneSided.swap(keptOneSided);
}

// The polygons and strips of @p data as triangles with merged points (lines and vertices are
// dropped before merging: they do not occlude).
vtkSmartPointer<vtkPolyData> Triangulate(vtkPolyData* data)
{
  vtkNew<vtkPolyData> faces;
  faces->SetPoints(data->GetPoints());
  faces->SetPolys(data->GetPolys());
  faces->SetStrips(data->GetStrips());
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(faces);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  return triangles->GetOutput();
}

// Whether the triangle @p ids of @p points has finite corners and a non-zero area.
bool ValidTriangle(const std::vector<double>& points, const vtkIdType* ids)
{
  if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2])
  {
    return false;
  }
  double p[3][3];
  bool finite = true;
  for (int k = 0; k < 3; ++k)
  {
    std::copy_n(&points[static_cast<size_t>(3 * ids[k])], 3, p[k]);
    finite = finite && std::isfinite(p[k][0]) && std::isfinite(p[k][1]) && std::isfinite(p[k][2]);
  }
  double e1[3], e2[3], c[3];
  vtkMath::Subtract(p[1], p[0], e1);
  vtkMath::Subtract(p[2], p[0], e2);
  vtkMath::Cross(e1, e2, c);
  return finite && vtkMath::Norm(c) > 0.0;
}

void PrepareSurface(vtkPolyData* data, PreparedSurface& surface)
{
  surface.Points.clear();
  surface.Triangles.clear();
  surface.OneSided.clear();
  if (data->GetNumberOfPolys() + data->GetNumberOfStrips() == 0)
  {
    return;
  }
  vtkSmartPointer<vtkPolyData> out = Triangulate(data);
  vtkPoints* points = out->GetPoints();
  if (!points)
  {
    return;
  }
  const vtkIdType np = points->GetNumberOfPoints();
  surface.Points.resize(static_cast<size_t>(3 * np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->GetPoint(i, &surface.Points[static_cast<size_t>(3 * i)]);
  }
  auto polys = vtk::TakeSmartPointer(out->GetPolys()->NewIterator());
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(npts, ids);
    if (npts == 3 && ValidTriangle(surface.Points, ids))
    {
      surface.Triangles.insert(surface.Triangles.end(), ids, ids + 3);
    }
  }
  OrientComponents(surface);
  MergeCoplanarPatches(surface);
}

// Appends the triangles of @p prepared, placed by @p matrix, to @p vertices.
void AppendTriangles(const PreparedSurface& prepared,
  vtkMatrix4x4* matrix,
  const double origin[3],
  std::vector<float>& vertices)
{
  // A mirroring matrix turns the winding inside out.
  double linear[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[r][c] = matrix->GetElement(r, c);
    }
  }
  const bool mirror = vtkMath::Determinant3x3(linear) < 0.0;
  const size_t count = prepared.OneSided.size();
  vertices.reserve(vertices.size() + 12 * count);
  for (size_t i = 0; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int corner = mirror && k > 0 ? 3 - k : k;
      double p[4] = { 0, 0, 0, 1 };
      std::copy_n(
        &prepared.Points[static_cast<size_t>(3 * prepared.Triangles[3 * i + corner])], 3, p);
      matrix->MultiplyPoint(p, p);
      for (int c = 0; c < 3; ++c)
      {
        vertices.push_back(static_cast<float>(p[c] / p[3] - origin[c]));
      }
      vertices.push_back(prepared.OneSided[i] ? 0.0f : 1.0f);
    }
  }
}
}

struct vtkAOOccluderTriangles::vtkInternals
{
  std::map<vtkPolyData*, PreparedSurface> Surfaces;
};

//------------------------------------------------------------------------------
vtkAOOccluderTriangles::vtkAOOccluderTriangles()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkAOOccluderTriangles::~vtkAOOccluderTriangles() = default;

//------------------------------------------------------------------------------
void vtkAOOccluderTriangles::Clear()
{
  this->Internals->Surfaces.clear();
}

//------------------------------------------------------------------------------
void vtkAOOccluderTriangles::Build(const std::vector<vtkProp*>& props,
  const double origin[3],
  std::vector<float>& vertices)
{
  vertices.clear();
  auto& cache = this->Internals->Surfaces;
  for (auto& entry : cache)
  {
    entry.second.Used = false;
  }
  auto append = [&](const vtkAOPropGeometry::Surface& surface)
  {
    PreparedSurface& prepared = cache[surface.Data];
    if (!prepared.Source || prepared.Time != surface.Data->GetMTime())
    {
      prepared.Source = surface.Data;
      prepared.Time = surface.Data->GetMTime();
      PrepareSurface(surface.Data, prepared);
    }
    prepared.Used = true;
    AppendTriangles(prepared, surface.Matrix, origin, vertices);
  };
  int group = 0;
  for (vtkProp* prop : props)
  {
    vtkAOPropGeometry::VisitProp(prop, false, group, append);
  }
  for (auto it = cache.begin(); it != cache.end();)
  {
    it = it->second.Used ? std::next(it) : cache.erase(it);
  }
}
