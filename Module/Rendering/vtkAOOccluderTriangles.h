/**
 * @class   vtkAOOccluderTriangles
 * @brief   the occluding triangles of a renderer's props, in world space, made ready for the
 *          ambient occlusion volumes
 *
 * First stage of vtkAmbientOcclusionVolumesPass (on the CPU). Each surface that
 * vtkAOPropGeometry gives for the occluders is prepared once and kept while it is unchanged
 * (a glyph source serves all its glyphs; a moving actor only costs its transform):
 * - polygons and strips triangulated, coincident points merged, degenerate and non-finite
 *   triangles dropped; lines and vertices do not occlude;
 * - each closed component (every edge shared by exactly two triangles) consistently oriented
 *   with its front side out and flagged one-sided: from outside a closed surface its back
 *   faces lie behind its front faces, and counting both would count the same directions
 *   twice. Open, non-manifold or non-orientable components stay two-sided;
 * - coplanar patches whose union is convex re-triangulated as a fan over their outline:
 *   occlusion is additive over a partition, so A is the same, but each triangle costs a volume
 *   at least 2R across, and a tessellated ground's thousands of volumes become two.
 *
 * Build() writes per triangle corner x, y, z relative to an origin (float precision where it
 * matters) and w = 1 for two-sided, 0 for one-sided triangles; a mirroring matrix turns the
 * winding back outwards.
 *
 * Not a vtkObject: a helper that owns the cache of prepared surfaces.
 */
#ifndef vtkAOOccluderTriangles_h
#define vtkAOOccluderTriangles_h

#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkProp;

class VTKAORENDERING_EXPORT vtkAOOccluderTriangles
{
public:
  vtkAOOccluderTriangles();
  ~vtkAOOccluderTriangles();

  /**
   * Replace @p vertices by the triangles of the surfaces of @p props (12 floats a triangle:
   * three corners of x, y, z relative to @p origin and w, see the class documentation).
   * Surfaces prepared by an earlier call are reused while their data is unchanged; those no
   * prop uses any more are forgotten.
   */
  void Build(const std::vector<vtkProp*>& props,
    const double origin[3],
    std::vector<float>& vertices);

  /**
   * Forget every prepared surface.
   */
  void Clear();

private:
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  vtkAOOccluderTriangles(const vtkAOOccluderTriangles&) = delete;
  void operator=(const vtkAOOccluderTriangles&) = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkAOOccluderTriangles.h
