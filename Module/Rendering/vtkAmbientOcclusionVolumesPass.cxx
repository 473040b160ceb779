#include "vtkAmbientOcclusionVolumesPass.h"

#include "vtkAOGBufferPass.h"
#include "vtkAOPropGeometry.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVolumeFS.h"
#include "vtkAOVolumeGS.h"
#include "vtkAOVolumeInitFS.h"
#include "vtkAOVolumeVS.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>

vtkStandardNewMacro(vtkAmbientOcclusionVolumesPass);

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

std::uint64_t EdgeKey(vtkIdType a, vtkIdType b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) ^ lo;
}

// A closed component (every edge shared by exactly two of its triangles, in opposite
// directions once oriented) occludes from its outside only: its triangles are flagged
// one-sided and turned so that the enclosed volume is positive. Components that are open,
// non-manifold or non-orientable stay two-sided, as they were given. Orientation is
// propagated across shared edges, so sources with inconsistent winding (a box built from
// independently wound faces) are handled.
void OrientComponents(PreparedSurface& surface)
{
  const size_t n = surface.Triangles.size() / 3;
  std::vector<vtkIdType>& t = surface.Triangles;
  std::unordered_map<std::uint64_t, std::vector<vtkIdType>> edges; // edge -> triangles
  edges.reserve(3 * n);
  for (size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges[EdgeKey(t[3 * i + k], t[3 * i + (k + 1) % 3])].push_back(static_cast<vtkIdType>(i));
    }
  }
  // Whether triangle i runs along the directed edge a -> b.
  auto runs = [&t](size_t i, vtkIdType a, vtkIdType b)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (t[3 * i + k] == a && t[3 * i + (k + 1) % 3] == b)
      {
        return true;
      }
    }
    return false;
  };
  surface.OneSided.assign(n, 0);
  std::vector<signed char> flip(n, 0); // 0 unvisited, +1 keep, -1 reverse
  std::vector<size_t> component, stack;
  for (size_t seed = 0; seed < n; ++seed)
  {
    if (flip[seed] != 0)
    {
      continue;
    }
    component.clear();
    stack.assign(1, seed);
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
        const auto j =
          static_cast<size_t>(shared[0] == static_cast<vtkIdType>(i) ? shared[1] : shared[0]);
        // Consistent when j, as drawn, runs b -> a.
        const bool jRunsAB = runs(j, a, b);
        const signed char wanted = static_cast<signed char>(jRunsAB ? -1 : 1);
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
    if (!closed)
    {
      for (size_t i : component)
      {
        flip[i] = 1; // two-sided: the given winding is as good as any
      }
      continue;
    }
    // Six times the signed volume, relative to a point of the component (exact for closed).
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
    const signed char outward = static_cast<signed char>(volume < 0.0 ? -1 : 1);
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
  const double* p = surface.Points.data();
  std::vector<std::array<double, 3>> normal(n);
  std::vector<double> offset(n), area(n);
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
    vtkMath::Cross(e1, e2, normal[i].data());
    area[i] = 0.5 * vtkMath::Normalize(normal[i].data());
    offset[i] = vtkMath::Dot(normal[i].data(), a);
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min({ lo[k], a[k], b[k], c[k] });
      hi[k] = std::max({ hi[k], a[k], b[k], c[k] });
    }
  }
  const double size = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  std::unordered_map<std::uint64_t, std::vector<vtkIdType>> edges;
  edges.reserve(3 * n);
  for (size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges[EdgeKey(t[3 * i + k], t[3 * i + (k + 1) % 3])].push_back(static_cast<vtkIdType>(i));
    }
  }
  auto coplanar = [&](size_t i, size_t j)
  {
    return vtkMath::Dot(normal[i].data(), normal[j].data()) > 1.0 - 1e-10 &&
      std::abs(offset[i] - offset[j]) <= 1e-9 * size && surface.OneSided[i] == surface.OneSided[j];
  };
  std::vector<unsigned char> visited(n, 0);
  std::vector<vtkIdType> kept;
  std::vector<unsigned char> keptOneSided;
  kept.reserve(t.size());
  std::vector<size_t> patch, stack;
  for (size_t seed = 0; seed < n; ++seed)
  {
    if (visited[seed])
    {
      continue;
    }
    patch.clear();
    stack.assign(1, seed);
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
        const auto j =
          static_cast<size_t>(shared[0] == static_cast<vtkIdType>(i) ? shared[1] : shared[0]);
        if (!visited[j] && coplanar(seed, j))
        {
          visited[j] = 1;
          stack.push_back(j);
        }
      }
    }
    std::vector<vtkIdType> outline;
    if (patch.size() >= 3)
    {
      // The patch's points in a frame of its plane (u, v, normal right-handed).
      const double* nn = normal[seed].data();
      double u[3], v[3];
      vtkMath::Perpendiculars(nn, u, v, 0.0);
      std::vector<std::pair<std::array<double, 2>, vtkIdType>> pts;
      double total = 0.0;
      for (size_t i : patch)
      {
        total += area[i];
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
      // Andrew's monotone chain, counter-clockwise about the normal, collinear points dropped.
      auto cross = [](const std::array<double, 2>& o,
                     const std::array<double, 2>& a,
                     const std::array<double, 2>& b)
      { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
      std::vector<size_t> hull(2 * pts.size());
      size_t k = 0;
      const double eps = 1e-12 * size * size;
      for (size_t i = 0; i < pts.size(); ++i)
      {
        while (k >= 2 && cross(pts[hull[k - 2]].first, pts[hull[k - 1]].first, pts[i].first) <= eps)
        {
          --k;
        }
        hull[k++] = i;
      }
      for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;)
      {
        while (
          k >= lower && cross(pts[hull[k - 2]].first, pts[hull[k - 1]].first, pts[i].first) <= eps)
        {
          --k;
        }
        hull[k++] = i;
      }
      hull.resize(k > 0 ? k - 1 : 0);
      double hullArea = 0.0;
      for (size_t i = 1; i + 1 < hull.size(); ++i)
      {
        hullArea += 0.5 * cross(pts[hull[0]].first, pts[hull[i]].first, pts[hull[i + 1]].first);
      }
      if (hull.size() >= 3 && hull.size() - 2 < patch.size() &&
        std::abs(hullArea - total) <= 1e-6 * total)
      {
        for (size_t i : hull)
        {
          outline.push_back(pts[i].second);
        }
      }
    }
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

void PrepareSurface(vtkPolyData* data, PreparedSurface& surface)
{
  surface.Points.clear();
  surface.Triangles.clear();
  surface.OneSided.clear();
  if (data->GetNumberOfPolys() + data->GetNumberOfStrips() == 0)
  {
    return;
  }
  // Only polygons and strips occlude; lines and vertices are dropped before merging.
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
  vtkPolyData* out = triangles->GetOutput();
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
    if (npts != 3 || ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2])
    {
      continue;
    }
    double p[3][3];
    bool finite = true;
    for (int k = 0; k < 3; ++k)
    {
      std::copy_n(&surface.Points[static_cast<size_t>(3 * ids[k])], 3, p[k]);
      finite = finite && std::isfinite(p[k][0]) && std::isfinite(p[k][1]) && std::isfinite(p[k][2]);
    }
    double e1[3], e2[3], c[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Cross(e1, e2, c);
    if (finite && vtkMath::Norm(c) > 0.0)
    {
      surface.Triangles.insert(surface.Triangles.end(), ids, ids + 3);
    }
  }
  OrientComponents(surface);
  MergeCoplanarPatches(surface);
}
}

struct vtkAmbientOcclusionVolumesPass::vtkInternals
{
  std::map<vtkPolyData*, PreparedSurface> Surfaces;
};

//------------------------------------------------------------------------------
vtkAmbientOcclusionVolumesPass::vtkAmbientOcclusionVolumesPass()
  : Internals(new vtkInternals)
{
  // The defaults of the shared parameters measured for AOV (see the class documentation).
  this->AOScale = 1;
  this->FilterSize = 6;
}

//------------------------------------------------------------------------------
vtkAmbientOcclusionVolumesPass::~vtkAmbientOcclusionVolumesPass()
{
  delete this->Internals;
  // The GL objects free themselves through their context's resource callbacks.
  if (this->Triangles)
  {
    this->Triangles->Delete();
  }
  for (vtkOpenGLVertexArrayObject* vao : this->VAOs)
  {
    if (vao)
    {
      vao->Delete();
    }
  }
  if (this->Accumulation)
  {
    this->Accumulation->Delete();
  }
  for (vtkTextureObject* texture : { this->Occlusion, this->Points, this->MapDepth })
  {
    if (texture)
    {
      texture->Delete();
    }
  }
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfOccludingTriangles: " << this->NumberOfOccludingTriangles << "\n";
  os << indent << "GeometryUpdateCount: " << this->GeometryUpdateCount << "\n";
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::PrepareOcclusion(vtkOpenGLRenderWindow* renWin,
  vtkRenderer* vtkNotUsed(ren),
  const std::vector<vtkProp*>& occluders,
  const double bounds[6])
{
  std::copy_n(bounds, 6, this->SceneBounds);
  // Enough to clear depth-reconstruction error, no more (see the class documentation).
  const double* b = bounds;
  const double longest =
    std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] }) + 2.0 * this->EffectiveRadius;
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : longest / 2000.0;
  return this->UpdateOccluderGeometry(renWin, occluders);
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::UpdateOccluderGeometry(vtkOpenGLRenderWindow* renWin,
  const std::vector<vtkProp*>& props)
{
  // Everything the triangles depend on; properties (colour, culling) are left out.
  std::vector<double> signature;
  for (vtkProp* prop : props)
  {
    vtkAOPropGeometry::AppendSignature(prop, signature);
  }
  if (this->Triangles && this->TrianglesWindow != renWin)
  {
    // Another context: its buffer is not ours to reuse.
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  if (signature == this->GeometrySignature && this->Triangles)
  {
    return this->NumberOfOccludingTriangles > 0;
  }
  this->GeometrySignature.swap(signature);

  // World positions relative to the scene's centre (float precision where it matters), w = 1
  // for two-sided triangles (open surfaces), 0 for one-sided ones (closed components, turned
  // outwards). Each distinct surface is prepared once (a glyph source serves all its glyphs)
  // and kept while it is unchanged, so a moving actor only costs the transform.
  for (int i = 0; i < 3; ++i)
  {
    this->SceneOrigin[i] = 0.5 * (this->SceneBounds[2 * i] + this->SceneBounds[2 * i + 1]);
  }
  auto& cache = this->Internals->Surfaces;
  for (auto& entry : cache)
  {
    entry.second.Used = false;
  }
  std::vector<float> data;
  int group = 0;
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
    // A mirroring matrix turns the winding inside out.
    double linear[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        linear[r][c] = surface.Matrix->GetElement(r, c);
      }
    }
    const bool mirror = vtkMath::Determinant3x3(linear) < 0.0;
    const size_t count = prepared.OneSided.size();
    data.reserve(data.size() + 12 * count);
    for (size_t i = 0; i < count; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int corner = mirror && k > 0 ? 3 - k : k;
        double p[4] = { 0, 0, 0, 1 };
        std::copy_n(
          &prepared.Points[static_cast<size_t>(3 * prepared.Triangles[3 * i + corner])], 3, p);
        surface.Matrix->MultiplyPoint(p, p);
        for (int c = 0; c < 3; ++c)
        {
          data.push_back(static_cast<float>(p[c] / p[3] - this->SceneOrigin[c]));
        }
        data.push_back(prepared.OneSided[i] ? 0.0f : 1.0f);
      }
    }
  };
  for (vtkProp* prop : props)
  {
    vtkAOPropGeometry::VisitProp(prop, false, group, append);
  }
  for (auto it = cache.begin(); it != cache.end();)
  {
    it = it->second.Used ? std::next(it) : cache.erase(it);
  }
  this->NumberOfOccludingTriangles = static_cast<vtkIdType>(data.size() / 12);
  ++this->GeometryUpdateCount;
  if (!this->Triangles)
  {
    this->Triangles = vtkOpenGLBufferObject::New();
    this->Triangles->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->TrianglesWindow = renWin;
  }
  if (!data.empty() && !this->Triangles->Upload(data, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload the occluding triangles.");
    this->NumberOfOccludingTriangles = 0;
    this->GeometrySignature.clear();
  }
  for (vtkOpenGLVertexArrayObject* vao : this->VAOs)
  {
    if (vao)
    {
      // The buffer may have been re-created: bind the attribute again.
      vao->ShaderProgramChanged();
    }
  }
  return this->NumberOfOccludingTriangles > 0;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin,
  int w,
  int h)
{
  vtkAOShaderUtilities::EnsureFloatTexture(this->Occlusion, renWin, w, h, 4);
  vtkAOShaderUtilities::EnsureFloatTexture(this->Points, renWin, w, h, 4);
  vtkAOShaderUtilities::EnsureDepthTexture(this->MapDepth, renWin, w, h);
  if (!this->Accumulation)
  {
    this->Accumulation = vtkOpenGLFramebufferObject::New();
  }
  this->Accumulation->SetContext(renWin);
  for (int k = 0; k < 2; ++k)
  {
    if (!this->VAOs[k])
    {
      this->VAOs[k] = vtkOpenGLVertexArrayObject::New();
    }
    const std::string define =
      std::string("#define AO_LARGE_TRIANGLES ") + (k == LARGE_TRIANGLES ? "1" : "0");
    std::string vs = vtkAOVolumeVS;
    std::string gs = vtkAOVolumeGS;
    std::string fs = vtkAOShaderUtilities::ComposeFragmentShader(vtkAOVolumeFS);
    vtkShaderProgram::Substitute(gs, "//AO::VolumeClass", define);
    vtkShaderProgram::Substitute(fs, "//AO::VolumeClass", define);
    vtkShaderProgram* program =
      renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
    if (!program || !program->GetCompiled())
    {
      vtkErrorMacro(<< "Couldn't build the ambient occlusion volume shader program.");
      this->Programs[0] = this->Programs[1] = nullptr;
      return false;
    }
    if (program != this->Programs[k])
    {
      this->Programs[k] = program;
      this->VAOs[k]->ShaderProgramChanged();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkAmbientOcclusionVolumesPass::RenderOcclusion(vtkOpenGLRenderWindow* renWin,
  vtkRenderer* ren,
  vtkMatrix4x4* vtkNotUsed(view),
  vtkMatrix4x4* vtkNotUsed(projection))
{
  return this->RenderVolumes(renWin, ren) ? this->Occlusion : nullptr;
}

//------------------------------------------------------------------------------
bool vtkAmbientOcclusionVolumesPass::RenderVolumes(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren)
{
  const int fullW = this->GBuffer->GetWidth(), fullH = this->GBuffer->GetHeight();
  const int scale = this->AOScale;
  const int w = (fullW + scale - 1) / scale, h = (fullH + scale - 1) / scale;
  if (!this->InitializeGraphicsResources(renWin, w, h))
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate); // the map is smaller than the screen
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);

  this->Accumulation->SaveCurrentBindingsAndBuffers();
  this->Accumulation->Bind();
  this->Accumulation->AddColorAttachment(0, this->Occlusion);
  this->Accumulation->AddColorAttachment(1, this->Points);
  this->Accumulation->AddDepthAttachment(this->MapDepth);
  ostate->vtkglDrawBuffer(GL_NONE); // see vtkAOGBufferPass: reset the draw-buffer cache
  this->Accumulation->ActivateDrawBuffers(2);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkCamera* cam = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(cam->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
  vtkNew<vtkMatrix4x4> inverseProjection;
  inverseProjection->DeepCopy(projection);
  inverseProjection->Invert();
  const int fullSize[2] = { fullW, fullH };
  vtkTextureObject* depth = this->GBuffer->GetDepthTexture();
  vtkTextureObject* normal = this->GBuffer->GetNormalTexture();
  depth->Activate();
  normal->Activate();

  // The initial map: A = 1 with the coverage, depth and normal of each texel's pixel; the
  // points x and normals the volumes read; the pixels' depths.
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  if (!vtkAOShaderUtilities::ReadyQuad(this->InitQuad,
        renWin,
        vtkAOShaderUtilities::ComposeFragmentShader(vtkAOVolumeInitFS),
        this,
        "AO map"))
  {
    normal->Deactivate();
    depth->Deactivate();
    this->Accumulation->UnBind();
    this->Accumulation->RestorePreviousBindingsAndBuffers();
    return false;
  }
  vtkShaderProgram* init = this->InitQuad->Program;
  init->SetUniformi("aoDepth", depth->GetTextureUnit());
  init->SetUniformi("aoNormal", normal->GetTextureUnit());
  vtkAOShaderUtilities::SetMatrix(init, "aoInvProjection", inverseProjection);
  init->SetUniform2i("aoFullSize", fullSize);
  init->SetUniformi("aoParallel", cam->GetParallelProjection() ? 1 : 0);
  init->SetUniformi("aoScale", scale);
  init->SetUniformf("aoBias", static_cast<float>(this->EffectiveBias));
  this->InitQuad->Render();
  normal->Deactivate();
  depth->Deactivate();

  // Each fragment subtracts the occlusion of its triangle: 1 - sum, unclamped in a float target.
  // The geometry shader emits the volume's faces turned away from the eye (no face culling
  // needed): a covered point x lies inside the volume, so in front of the face the pixel's ray
  // leaves by. The depth test rejects, before shading, the pixels whose visible surface lies
  // beyond that face (volumes floating in front of a farther surface or of the background).
  this->Accumulation->RemoveColorAttachment(1); // sampled now: no feedback loop
  this->Accumulation->ActivateDrawBuffers(1);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  ostate->vtkglBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  ostate->vtkglColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE); // coverage, depth, normal stay

  vtkNew<vtkMatrix4x4> modelView;
  modelView->DeepCopy(cam->GetViewTransformMatrix());
  vtkNew<vtkMatrix4x4> shift;
  for (int i = 0; i < 3; ++i)
  {
    shift->SetElement(i, 3, this->SceneOrigin[i]);
  }
  vtkMatrix4x4::Multiply4x4(modelView, shift, modelView);
  this->Points->Activate();
  bool ok = true;
  for (int k = 0; k < 2 && ok; ++k)
  {
    vtkShaderProgram* program = this->Programs[k];
    renWin->GetShaderCache()->ReadyShaderProgram(program, nullptr);
    program->SetUniformi("aoPoints", this->Points->GetTextureUnit());
    vtkAOShaderUtilities::SetMatrix(program, "aoModelView", modelView);
    vtkAOShaderUtilities::SetMatrix(program, "aoProjection", projection);
    program->SetUniformi("aoParallel", cam->GetParallelProjection() ? 1 : 0);
    program->SetUniformf("aoRadius", static_cast<float>(this->EffectiveRadius));
    program->SetUniformi("aoBinary", this->Falloff == BINARY ? 1 : 0);
    vtkOpenGLVertexArrayObject* vao = this->VAOs[k];
    vao->Bind();
    vao->RemoveAttributeArray("vertexMC");
    ok = vao->AddAttributeArray(
      program, this->Triangles, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    if (!ok)
    {
      vtkErrorMacro(<< "Couldn't bind the occluding triangles to the volume shader.");
    }
    else
    {
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->NumberOfOccludingTriangles));
    }
    vao->Release();
  }

  this->Points->Deactivate();
  ostate->vtkglBlendEquation(GL_FUNC_ADD);
  this->Accumulation->UnBind();
  this->Accumulation->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after rendering the ambient occlusion volumes");
  return ok;
}

//------------------------------------------------------------------------------
long long vtkAmbientOcclusionVolumesPass::GetOcclusionMemorySize()
{
  long long bytes = vtkAOShaderUtilities::TextureBytes(this->Occlusion) +
    vtkAOShaderUtilities::TextureBytes(this->Points) +
    vtkAOShaderUtilities::TextureBytes(this->MapDepth);
  if (this->Triangles && this->Triangles->GetHandle() != 0)
  {
    bytes += static_cast<long long>(this->NumberOfOccludingTriangles) * 12 * sizeof(float);
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkAmbientOcclusionVolumesPass::ReleaseOcclusionResources(vtkWindow* w)
{
  this->InitQuad.reset();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Occlusion, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Points, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->MapDepth, renWin);
  if (this->Accumulation)
  {
    this->Accumulation->ReleaseGraphicsResources(w);
    this->Accumulation->Delete();
    this->Accumulation = nullptr;
  }
  for (vtkOpenGLVertexArrayObject*& vao : this->VAOs)
  {
    if (vao)
    {
      vao->ReleaseGraphicsResources();
      vao->Delete();
      vao = nullptr;
    }
  }
  if (this->Triangles)
  {
    this->Triangles->ReleaseGraphicsResources();
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  this->TrianglesWindow = nullptr;
  this->Programs[0] = this->Programs[1] = nullptr; // released with the window's shader cache
  this->GeometrySignature.clear();
}
