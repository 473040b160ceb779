/**
 * @class   vtkAOEmbreeScene
 * @brief   Embree triangle scene of VTK surfaces and the Monte Carlo AO estimator
 *
 * The one place where VTK geometry becomes Embree triangles and where the ambient-occlusion
 * integral of design/ao-definition.md is estimated. Shared by vtkAOReferenceRenderer (per
 * pixel) and vtkAOVertexBaker (per vertex), so both compute exactly the same quantity.
 *
 * Geometry: polygons (triangulated) and triangle strips; vertices and lines are ignored.
 * Triangles with a non-finite coordinate or zero area are skipped. Coordinates are stored
 * relative to the first point added (float precision is spent near the scene, not near the
 * world origin). Not a VTK object and not installed: a private helper of the module.
 *
 * Thread safety: the Add* methods and Commit() are not thread safe; after Commit() every
 * query (Intersect, ComputeAccessibility) is const and may run on any number of threads.
 */
#ifndef vtkAOEmbreeScene_h
#define vtkAOEmbreeScene_h

#include "vtkType.h"

#include <cstdint>
#include <memory>
#include <string>

class vtkActor;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

/// The parameters of the AO integral (design/ao-definition.md), world units.
struct vtkAOIntegralParameters
{
  double Radius = 1.0;        ///< R: occluders farther than R do not occlude
  double Bias = 0.0;          ///< rays start at p + Bias n
  double Spread = 1.0;        ///< cone half-angle in units of pi/2
  bool BinaryFalloff = false; ///< W = 1 within R (else Wendland)
  bool CosineSampling = true; ///< cosine-weighted directions (else uniform, weighted by cos)
  int Samples = 256;          ///< directions per point
  unsigned int Seed = 0;      ///< with the point's key, fixes the directions
};

class vtkAOEmbreeScene
{
public:
  vtkAOEmbreeScene();
  ~vtkAOEmbreeScene();
  vtkAOEmbreeScene(const vtkAOEmbreeScene&) = delete;
  vtkAOEmbreeScene& operator=(const vtkAOEmbreeScene&) = delete;

  /// Add the triangles of @p surface transformed by @p matrix (may be null). Point normals,
  /// when present, are kept for Intersect(). Returns the number of triangles added.
  vtkIdType AddPolyData(vtkPolyData* surface, vtkMatrix4x4* matrix = nullptr);

  /**
   * Add what @p prop draws: a vtkActor (or the parts of a vtkAssembly) whose mapper input is
   * vtkPolyData, any other vtkDataSet (its outer surface), a composite dataset (every leaf),
   * or a vtkGlyph3DMapper (the glyphs expanded with their per-point transforms). Invisible
   * props are skipped, and so are props without opaque geometry unless @p translucent.
   * Returns true if the prop contributed (even zero triangles); bounds of contributing props
   * are accumulated in GetPropBounds().
   */
  bool AddProp(vtkProp* prop, bool translucent);

  /// Add every visible prop of @p renderer (AddProp). Returns the number of props used.
  int AddRenderer(vtkRenderer* renderer, bool translucent);

  /// Build the acceleration structure. Returns false (and sets the error) if Embree failed.
  bool Commit();

  /// Number of triangles in the scene.
  vtkIdType GetNumberOfTriangles() const;

  /// Union of the bounds of the props added with AddProp (their GetBounds(), as the HAO pass
  /// computes its automatic radius), or of the surfaces added with AddPolyData.
  /// Invalid (min > max) when nothing was added.
  void GetBounds(double bounds[6]) const;

  /// The last error message (empty if none).
  const std::string& GetError() const;

  /**
   * First surface along origin + t dir, t in [tmin, tmax] (dir need not be unit length; t is
   * in units of |dir|). On a hit fills @p t, the hit point and the unit normal: the
   * interpolated point normal when the surface had normals, else the face normal (not
   * flipped), and when @p faceNormal is given the triangle's unit face normal (in the
   * winding's direction). Returns false on a miss.
   */
  bool Intersect(const double origin[3],
    const double dir[3],
    double tmin,
    double tmax,
    double& t,
    double point[3],
    double normal[3],
    double faceNormal[3] = nullptr) const;

  /**
   * A(p, n) per ao-definition.md, estimated with @p parameters.Samples rays. @p key selects
   * the point's random rotation of the low-discrepancy direction set (pixel or point index);
   * with parameters.Seed it makes the result deterministic. @p n must be unit length.
   * Adds the number of rays cast to @p rays.
   */
  double ComputeAccessibility(const double p[3],
    const double n[3],
    const vtkAOIntegralParameters& parameters,
    std::uint64_t key,
    std::int64_t& rays) const;

  /// The radius and the bias rays start at: @p radius and @p bias where they are positive, else
  /// the automatic values for GetBounds() (AutomaticRadius, AutomaticBias).
  void GetEffectiveRadiusAndBias(double radius,
    double bias,
    double& effectiveRadius,
    double& effectiveBias) const;

  /// The HAO pass's automatic radius for these bounds: a tenth of their diagonal.
  static double AutomaticRadius(const double bounds[6]);

  /// The automatic bias of the reference and the ray-cast baker: 1e-4 of the bounds'
  /// diagonal, the tiny offset of offline renderers; it does not grow with the radius.
  static double AutomaticBias(const double bounds[6]);

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
// VTK-HeaderTest-Exclude: vtkAOEmbreeScene.h
