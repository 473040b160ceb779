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
 * Each frame (the pipeline of vtkAmbientOcclusionPassBase):
 * 1. vtkAOOccluderTriangles gathers the triangles of the visible opaque props (all of them,
 *    on screen or not) in world space into one vertex buffer, only when an occluder changed.
 * 2. vtkAOGBufferPass (shared with HAO) renders colour, normal and depth.
 * 3. vtkAOVolumeRasterizer: a geometry shader turns each triangle P into its ambient occlusion
 *    volume, the box that holds P dilated by the radius R and extruded by R along its normal;
 *    the volumes are rasterized over the G-buffer and, per covered pixel, the fragment shader
 *    adds the occlusion of P seen from the pixel's point: the form factor of P clipped to the
 *    tangent plane (McGuire's eq. 1), weighted by the falloff (see Documentation/aov.md for
 *    how). The occlusions O_P of all P are combined by blending in a float target
 *    (SetCombination): A = product of (1 - O_P) (default), or A = 1 - sum O_P.
 * 4. vtkAOBilateralUpsampler (when AOScale > 1) and vtkAOCompositor (shared with HAO): the
 *    image multiplied by A^Intensity, A clamped to [0, 1].
 *
 * The quantity is A of shared/design/ao-definition.md (Wendland or binary falloff, full
 * hemisphere). Which faces occlude: a triangle of an open surface occludes from both sides; a
 * triangle of a closed surface only from its front side, because from any point outside a
 * closed surface its back faces lie behind its front faces, and counting both would count the
 * same directions twice.
 *
 * Limitation (the method's): occlusions are combined without visibility, not unioned. Where
 * occluders overlap as seen from a point (stacked thin sheets, open surfaces seen through each
 * other, coincident faces of overlapping solids), the sum is darker than ray tracing; the
 * product is less dark there but lighter than ray tracing where many small triangles of one
 * surface each occlude a little (it tends to exp(-sum)). Closed occluders at least R/2 thick
 * are exact with the sum, up to the stated approximations. Cost grows with the number of
 * triangles times their screen coverage.
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
 *   screen-space subsampling: the volume stage's cost falls about as 1 / AOScale^2. With
 *   Accumulation (on by default) a still view then converges to the AOScale-1 map: each
 *   further render evaluates another pixel of every AOScale x AOScale block and writes it
 *   in place, so after AOScale^2 renders (at most MaximumAccumulatedFrames) every pixel
 *   has its own exact value, for the cost of AOScale 1 spread over the frames.
 * - FilterSize 6: the map has no sampling noise to hide, so a window of about 2 AOScale
 *   suffices.
 */
#ifndef vtkAmbientOcclusionVolumesPass_h
#define vtkAmbientOcclusionVolumesPass_h

#include "vtkAmbientOcclusionPassBase.h"
#include "vtkNew.h"               // For vtkNew
#include "vtkaoRenderingModule.h" // For export macro

class vtkAOVolumeRasterizer;

class VTKAORENDERING_EXPORT vtkAmbientOcclusionVolumesPass : public vtkAmbientOcclusionPassBase
{
public:
  static vtkAmbientOcclusionVolumesPass* New();
  vtkTypeMacro(vtkAmbientOcclusionVolumesPass, vtkAmbientOcclusionPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * GPU time of the volume stage of the last frame whose timer queries were read, in
   * milliseconds (see vtkAmbientOcclusionPassBase::GetGBufferTime for the others and when
   * they are read).
   */
  double GetVolumeTime() { return this->StageTimes[OCCLUSION]; }

  ///@{
  /**
   * Screen pixels per AO-map texel along each axis (see
   * vtkAmbientOcclusionPassBase::SetAOScale). Range [1, 8]. Default is 1.
   */
  vtkSetClampMacro(AOScale, int, 1, 8);
  ///@}

  enum CombinationType
  {
    ADDITIVE = 0,      ///< A = 1 - sum of O_P (McGuire's accumulation)
    MULTIPLICATIVE = 1 ///< A = product of (1 - O_P): occluders as independent
  };

  ///@{
  /**
   * How the occlusions O_P of the triangles are combined into A. ADDITIVE is exact for
   * occluders that do not overlap as seen from a point (each direction blocked once), and
   * counts overlapping ones twice; MULTIPLICATIVE counts overlapping ones less (an occluder
   * behind another darkens only what the first left open, as if they were independent) but
   * under-darkens a finely tessellated surface that subtends a large solid angle (the product
   * of many factors near 1 is exp(-sum), not 1 - sum; a quad is 2 factors). Default is
   * MULTIPLICATIVE: against the ray-traced reference over the 15 quality scenes its mean RMSE
   * is 0.017 (Wendland) and 0.039 (binary) against 0.025 and 0.061, its worst 0.049 and 0.081
   * against 0.080 and 0.165 (overlapping fins, stacked sheets, the iso-surface's folds and the
   * coincident faces of overlapping boxes improve; the sum stays better where a smooth
   * tessellated solid touches the surface: contact 0.003 against 0.017). Documentation/aov.md.
   */
  vtkSetClampMacro(Combination, int, ADDITIVE, MULTIPLICATIVE);
  vtkGetMacro(Combination, int);
  void SetCombinationToAdditive() { this->SetCombination(ADDITIVE); }
  void SetCombinationToMultiplicative() { this->SetCombination(MULTIPLICATIVE); }
  const char* GetCombinationAsString();
  ///@}

  /**
   * Number of occluding triangles (volumes) drawn by the last frame.
   */
  vtkIdType GetNumberOfOccludingTriangles();

  /**
   * How many times the occluding triangles were gathered and uploaded since creation.
   */
  int GetGeometryUpdateCount();

  /**
   * The volume stage, for inspection.
   */
  vtkAOVolumeRasterizer* GetRasterizer();

protected:
  vtkAmbientOcclusionVolumesPass();
  ~vtkAmbientOcclusionVolumesPass() override;

  /// The volume stage, vtkAOVolumeRasterizer, owns the triangles and the AO map.
  vtkNew<vtkAOVolumeRasterizer> Rasterizer;
  int Combination = MULTIPLICATIVE;

  // The occlusion stage of vtkAmbientOcclusionPassBase.
  /// Set the bias; gather and upload the occluding triangles when an occluder changed.
  bool PrepareOcclusion(const Frame& frame) override;
  /// Rasterize the triangles' volumes into the AO map.
  vtkTextureObject* RenderOcclusion(const Frame& frame) override;
  /// The map's textures and the triangles' buffer.
  long long GetOcclusionMemorySize() override;
  void ReleaseOcclusionResources(vtkWindow* w) override;
  /// Deterministic, each texel evaluated at Frame::SampleOffset: a still at AOScale s
  /// converges to the AOScale-1 map in s^2 frames.
  bool StratifiesSubsampledMap() override { return true; }

private:
  vtkAmbientOcclusionVolumesPass(const vtkAmbientOcclusionVolumesPass&) = delete;
  void operator=(const vtkAmbientOcclusionVolumesPass&) = delete;
};

#endif
