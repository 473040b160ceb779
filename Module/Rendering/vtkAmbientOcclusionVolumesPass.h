/**
 * @class   vtkAmbientOcclusionVolumesPass
 * @brief   Ambient Occlusion Volumes (McGuire 2010) as a VTK render pass: analytic,
 *          noise-free occlusion from every opaque triangle of the renderer.
 *
 * Used like vtkHybridAmbientOcclusionPass:
 * @code
 * vtkNew<vtkRenderStepsPass> basic;
 * vtkNew<vtkAmbientOcclusionVolumesPass> aov;
 * aov->SetDelegatePass(basic);
 * renderer->SetPass(aov);
 * @endcode
 *
 * Each frame:
 * 1. The triangles of the visible opaque props (all of them, on screen or not) are gathered in
 *    world space into one vertex buffer, only when an occluder changed.
 * 2. vtkAOGBufferPass (shared with HAO) renders colour, normal and depth.
 * 3. A geometry shader turns each triangle P into its ambient occlusion volume, the box that
 *    holds P dilated by the radius R and extruded by R along its normal; the volumes are
 *    rasterized over the G-buffer and, per covered pixel, the fragment shader adds the
 *    occlusion of P seen from the pixel's point: the form factor of P clipped to the tangent
 *    plane (McGuire's eq. 1), weighted by the falloff (see Documentation/aov.md for how). The
 *    sum of all P is accumulated with additive blending in a float target.
 * 4. vtkAOCompositor (shared with HAO) multiplies the image by A^Intensity, A = 1 - clamp(sum).
 *
 * The quantity is A of shared/design/ao-definition.md (Wendland or binary falloff, full
 * hemisphere). Which faces occlude: a triangle of an open surface occludes from both sides; a
 * triangle of a closed surface only from its front side, because from any point outside a
 * closed surface its back faces lie behind its front faces, and counting both would count the
 * same directions twice.
 *
 * Limitation (the method's): occlusions are summed, not unioned. Where occluders overlap as
 * seen from a point (stacked thin sheets, open surfaces seen through each other), the result
 * is darker than ray tracing; closed occluders at least R/2 thick are exact up to the stated
 * approximations. Cost grows with the number of triangles times their screen coverage.
 *
 * Translucent props receive AO but do not occlude. Picking bypasses the pass.
 *
 * The G-buffer, filter and composite, the shared parameters (Radius, Bias, Falloff,
 * Intensity, AOOnly, AOScale, FilterSize) and the timings of those stages come from
 * vtkAmbientOcclusionPassBase; this class adds the volumes. Its defaults for the shared
 * parameters:
 * - Bias 0 (automatic) is 1/2000 of the occluders' bounds padded by R (a quarter of a
 *   256-grid cell). The form factors are exact, so AOV needs far less bias than HAO (whose
 *   bias must clear grid cells): a large bias lifts points near a contact through the other
 *   surface, which then no longer occludes them (the reference, whose rays start beyond it,
 *   sees it from behind).
 * - AOScale 1 (every pixel evaluated, no filter); range [1, 8]. Larger values are McGuire's
 *   screen-space subsampling: the volume stage's cost falls about as 1 / AOScale^2.
 * - FilterSize 6: the map has no sampling noise to hide, so a window of about 2 AOScale
 *   suffices.
 */
#ifndef vtkAmbientOcclusionVolumesPass_h
#define vtkAmbientOcclusionVolumesPass_h

#include "vtkAmbientOcclusionPassBase.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <vector> // For the geometry signature

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;

class VTKAORENDERING_EXPORT vtkAmbientOcclusionVolumesPass : public vtkAmbientOcclusionPassBase
{
public:
  static vtkAmbientOcclusionVolumesPass* New();
  vtkTypeMacro(vtkAmbientOcclusionVolumesPass, vtkAmbientOcclusionPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Screen pixels per AO-map texel along each axis (see
   * vtkAmbientOcclusionPassBase::SetAOScale). Range [1, 8]. Default is 1.
   */
  vtkSetClampMacro(AOScale, int, 1, 8);
  ///@}

  /**
   * GPU time of the volume stage of the last frame whose timer queries were read, in
   * milliseconds (see vtkAmbientOcclusionPassBase::GetGBufferTime for the others and when
   * they are read).
   */
  double GetVolumeTime() { return this->StageTimes[OCCLUSION]; }

  /**
   * Number of occluding triangles (volumes) drawn by the last frame.
   */
  vtkGetMacro(NumberOfOccludingTriangles, vtkIdType);

  /**
   * How many times the occluding triangles were gathered and uploaded since creation.
   */
  vtkGetMacro(GeometryUpdateCount, int);

protected:
  vtkAmbientOcclusionVolumesPass();
  ~vtkAmbientOcclusionVolumesPass() override;

  ///@{
  /// The occlusion stage (see vtkAmbientOcclusionPassBase): gather and upload the occluding
  /// triangles when an occluder changed, then rasterize their volumes into the AO map.
  bool PrepareOcclusion(vtkOpenGLRenderWindow* renWin,
    vtkRenderer* ren,
    const std::vector<vtkProp*>& occluders,
    const double bounds[6]) override;
  vtkTextureObject* RenderOcclusion(vtkOpenGLRenderWindow* renWin,
    vtkRenderer* ren,
    vtkMatrix4x4* view,
    vtkMatrix4x4* projection) override;
  long long GetOcclusionMemorySize() override;
  void ReleaseOcclusionResources(vtkWindow* w) override;
  ///@}

  /// Rebuild and upload the triangle buffer if an occluder changed; false if there is none.
  bool UpdateOccluderGeometry(vtkOpenGLRenderWindow* renWin, const std::vector<vtkProp*>& props);
  /// Create the accumulation target and program; false (after an error) on failure.
  bool InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h);
  /// Rasterize the volumes over the G-buffer into the accumulation target.
  bool RenderVolumes(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren);

  vtkIdType NumberOfOccludingTriangles = 0;
  int GeometryUpdateCount = 0;
  std::vector<double> GeometrySignature;
  double SceneOrigin[3] = { 0, 0, 0 }; ///< the triangles are stored relative to it
  double SceneBounds[6] = { 0, 0, 0, 0, 0, 0 };

  struct vtkInternals;
  vtkInternals* Internals;

  vtkOpenGLBufferObject* Triangles = nullptr;
  vtkOpenGLRenderWindow* TrianglesWindow = nullptr; ///< the context Triangles lives in
  /// The volumes are drawn twice, by two programs: triangles small against the radius (their
  /// occlusion is the form factor weighted at the centroid's distance), then the others (the
  /// falloff integrated over distance). Each geometry shader keeps only its own class.
  enum VolumeClass
  {
    SMALL_TRIANGLES = 0,
    LARGE_TRIANGLES = 1
  };
  vtkOpenGLVertexArrayObject* VAOs[2] = { nullptr, nullptr };
  vtkShaderProgram* Programs[2] = { nullptr, nullptr }; ///< owned by the window's shader cache
  vtkOpenGLFramebufferObject* Accumulation = nullptr;
  vtkTextureObject* Occlusion = nullptr; ///< r = 1 - sum, g coverage, b depth, a normal
  vtkTextureObject* Points = nullptr;    ///< per texel: lifted x (view space), packed normal
  vtkTextureObject* MapDepth = nullptr;  ///< per texel: its pixel's depth, for early rejection
  std::unique_ptr<vtkOpenGLQuadHelper> InitQuad; ///< writes the initial AO map

private:
  vtkAmbientOcclusionVolumesPass(const vtkAmbientOcclusionVolumesPass&) = delete;
  void operator=(const vtkAmbientOcclusionVolumesPass&) = delete;
};

#endif
