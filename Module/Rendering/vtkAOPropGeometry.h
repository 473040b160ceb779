/**
 * @class   vtkAOPropGeometry
 * @brief   the surfaces a renderer's props contribute to ambient occlusion
 *
 * One definition, shared by every method that needs the occluders as triangles rather than
 * through their mappers (vtkAmbientOcclusionVolumesPass, the ray-traced reference), of which
 * props occlude and what their surfaces are:
 *
 * - a prop occludes when it is visible, an actor with a mapper or an assembly, has valid
 *   (finite, non-empty) bounds and, unless translucent props are asked for, opaque geometry
 *   (ao-definition.md); vtkHybridAmbientOcclusionPass draws the same props into its grid.
 *   An actor without a mapper (vtkFlagpoleLabel, vtkCubeAxesActor, vtkPolarAxesActor) draws
 *   annotation through internal actors and does not occlude (IsOverlay);
 * - an assembly contributes its visible opaque parts with their path matrices;
 * - a mapper's input: polydata as is, other data sets through vtkGeometryFilter, composite
 *   data leaf by leaf;
 * - a vtkGlyph3DMapper: one surface per glyph, the glyph source with the glyph's matrix
 *   (translation, orientation by ROTATION/QUATERNION/DIRECTION, scaling by the scale array
 *   with clamping and the scale factor, source indexing and masking, as the mapper draws it).
 *
 * The visitor receives each surface with the matrix taking its points to world coordinates
 * (never null) and a group number shared by all surfaces of one mapper (the glyphs of one
 * mapper share it, so a consumer can pack them into one mesh). Surfaces may hold lines,
 * vertices, polygons and strips: consumers take what they need.
 *
 * Not a vtkObject: a stateless helper (static functions only).
 */
#ifndef vtkAOPropGeometry_h
#define vtkAOPropGeometry_h

#include "vtkaoRenderingModule.h" // For export macro

#include <functional> // for std::function
#include <vector>     // for std::vector

class vtkActor;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

class VTKAORENDERING_EXPORT vtkAOPropGeometry
{
public:
  /// One surface of an occluding prop.
  struct Surface
  {
    vtkPolyData* Data;    ///< the surface, in the coordinates of the mapper's input
    vtkMatrix4x4* Matrix; ///< to world coordinates (never null)
    vtkActor* Actor;      ///< the actor drawing it (an assembly's part for assemblies)
    int Group;            ///< the same for all surfaces of one mapper in one visit
  };
  using Visitor = std::function<void(const Surface&)>;

  /**
   * Whether @p prop takes part in ambient occlusion (see the class documentation). Asks for
   * the bounds first: they bring the mappers' inputs up to date, which some mappers
   * (composite) need before they can tell whether they have opaque geometry. The bounds are
   * returned in @p bounds when it is not null.
   */
  static bool Occludes(vtkProp* prop, bool translucent, double bounds[6] = nullptr);

  /**
   * The view props of @p renderer that occlude (all of them, on screen or not: not the
   * frustum-culled list of a render state), with the union of their bounds in @p bounds
   * (inverted, VTK_DOUBLE_MAX/MIN, when there is none). Returns true when some visible actor
   * or assembly was left out because its bounds are not finite (NaN or infinite coordinates:
   * an input defect the caller may want to warn about; empty data is not reported).
   */
  static bool CollectOccluders(vtkRenderer* renderer,
    bool translucent,
    std::vector<vtkProp*>& props,
    double bounds[6]);

  /**
   * Calls @p visit for every surface of @p prop if it occludes. Group numbers continue from
   * @p group, which is advanced past the ones used. Returns whether the prop occludes.
   */
  static bool VisitProp(vtkProp* prop, bool translucent, int& group, const Visitor& visit);

  /**
   * Append to @p signature numbers that change whenever the surfaces VisitProp gives for
   * @p prop, or their matrices, may have changed: per actor (assembly part) its address, its
   * world matrix, its mapper's modification time and that of every input of the mapper (the
   * glyph sources included). Cheap: nothing is executed or copied.
   */
  static void AppendSignature(vtkProp* prop, std::vector<double>& signature);

  /**
   * Whether the passes draw @p prop over the image after the composite rather than into the
   * G-buffer: a vtkActor2D (text, scalar bars, annotations), any prop that is neither a
   * vtkProp3D nor a vtkPropAssembly (widget representations, which draw 2-D actors or
   * interaction handles through internal actors), and annotation placed in 3-D: text on a
   * textured quad (vtkBillboardTextActor3D, vtkTextActor3D) and actors without a mapper
   * (vtkFlagpoleLabel, the cube and polar axes). Such props neither receive nor cast AO; they
   * are depth-tested against the surfaces.
   */
  static bool IsOverlay(vtkProp* prop);

  /**
   * VisitProp for every view prop of @p renderer; returns the number of props that occlude.
   */
  static int VisitRenderer(vtkRenderer* renderer, bool translucent, const Visitor& visit);

private:
  vtkAOPropGeometry() = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkAOPropGeometry.h
