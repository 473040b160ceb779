/**
 * Internal to vtkAO::BakingAO (not installed): what vtkAOSattlerBaker and vtkAOHemisphereBaker
 * share: the occluding triangles of the input and of the occluders, the input's point normals,
 * the automatic bias and the OpenGL context (the given window or an off-screen one of the
 * baker's own).
 */
#ifndef vtkAOBakingGeometry_h
#define vtkAOBakingGeometry_h

#include "vtkSmartPointer.h"

#include <cstdint> // for std::uint32_t
#include <vector>  // for std::vector

class vtkCellArray;
class vtkDataArray;
class vtkInformationVector;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderWindow;

namespace vtkAOBaking
{
/// The triangles that occlude: the input's and every occluder's polygons (as fans) and strips,
/// finite and non-degenerate, in the order the cells come.
struct Geometry
{
  Geometry();
  ~Geometry();

  std::vector<double> Points;           // 3 per point: the input's points, then each occluder's
  std::vector<std::uint32_t> Triangles; // 3 indices into Points per triangle
  double Bounds[6];                     // of the triangles' corners
  std::vector<char> OnSurface;          // per input point: 1 when a kept input cell uses it
  vtkSmartPointer<vtkCellArray> Polys;  // the input's kept polygons ...
  vtkSmartPointer<vtkCellArray> Strips; // ... and strips (the surface that defines normals)

  std::size_t GetNumberOfTriangles() const { return this->Triangles.size() / 3; }
};

/// Fills @p geometry from @p input and the polydata of @p occluders (may be nullptr). Returns
/// false when the points do not fit 32-bit indices.
bool GatherGeometry(vtkPolyData* input, vtkInformationVector* occluders, Geometry& geometry);

/// The input's point normals when it has a 3-component array of the right size, else normals
/// computed from the kept cells with vtkPolyDataNormals (no splitting, consistent ordering; point
/// ids are kept). nullptr on failure.
vtkSmartPointer<vtkDataArray> PointNormals(vtkPolyData* input, const Geometry& geometry);

/// vtkAOVertexBaker's automatic bias for these bounds: 2/256 of the longest side of the bounds
/// grown by the automatic radius (a tenth of the diagonal).
double AutomaticBias(const double bounds[6]);

/// The context to draw in: @p window when set, else an off-screen window created in @p own on
/// first use. Made current. nullptr (with @p error set) when it is not a vtkOpenGLRenderWindow.
vtkOpenGLRenderWindow* MakeContext(vtkRenderWindow* window,
  vtkSmartPointer<vtkRenderWindow>& own,
  const char*& error);

/// True when the three coordinates are finite.
bool Finite3(const double x[3]);

/// Two unit vectors completing @p l (unit) to a right-handed orthonormal basis (u, v, l).
void Basis(const double l[3], double u[3], double v[3]);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOBakingGeometry.h
