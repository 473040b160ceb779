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
 */
#ifndef vtkAmbientOcclusionVolumesPass_h
#define vtkAmbientOcclusionVolumesPass_h

#include "vtkImageProcessingPass.h"
#include "vtkNew.h"               // For vtkNew
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <vector> // For the geometry signature

class vtkAOBilateralUpsampler;
class vtkAOCompositor;
class vtkAOGBufferPass;
class vtkImageData;
class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderTimer;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkProp;
class vtkShaderProgram;
class vtkTextureObject;

class VTKAORENDERING_EXPORT vtkAmbientOcclusionVolumesPass : public vtkImageProcessingPass
{
public:
  static vtkAmbientOcclusionVolumesPass* New();
  vtkTypeMacro(vtkAmbientOcclusionVolumesPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render the delegate with ambient occlusion.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Free every GL resource of every stage (and of the delegate).
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * Occlusion radius R (McGuire's delta), world units: geometry farther than R does not
   * occlude, and each volume extends R around its triangle. 0 means automatic: a tenth of the
   * diagonal of the occluders' bounds (as HAO and the reference). Range [0, inf). Default 0.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  /**
   * The radius used by the last frame (Radius, or the automatic value).
   */
  vtkGetMacro(EffectiveRadius, double);

  ///@{
  /**
   * Occlusion is evaluated from p + Bias n, world units, as the reference starts its rays;
   * it keeps a surface from occluding itself through depth-reconstruction error. The form
   * factors are exact, so AOV needs far less than HAO (whose bias must clear grid cells): a
   * large bias lifts points near a contact through the other surface, which then no longer
   * occludes them (the reference, whose rays start beyond it, sees it from behind).
   * 0 means automatic: 1/2000 of the occluders' bounds padded by R (a quarter of a 256-grid
   * cell). Range [0, inf). Default is 0 (automatic).
   */
  vtkSetClampMacro(Bias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Bias, double);
  ///@}

  /**
   * The bias used by the last frame (Bias, or the automatic value).
   */
  vtkGetMacro(EffectiveBias, double);

  enum FalloffType
  {
    WENDLAND = 0, ///< W(t) = (1 - t/R)^4 (4t/R + 1) (HAO eq. 3)
    BINARY = 1    ///< W(t) = 1 for t <= R ("None" in ao-definition.md)
  };

  ///@{
  /**
   * Falloff kernel of the occluder distance. Default is WENDLAND.
   */
  vtkSetClampMacro(Falloff, int, WENDLAND, BINARY);
  vtkGetMacro(Falloff, int);
  void SetFalloffToWendland() { this->SetFalloff(WENDLAND); }
  void SetFalloffToBinary() { this->SetFalloff(BINARY); }
  ///@}

  ///@{
  /**
   * Strength of the darkening at composite time: the colour is multiplied by A^Intensity.
   * Does not change A itself. Range [0, 10]. Default is 1.
   */
  vtkSetClampMacro(Intensity, double, 0.0, 10.0);
  vtkGetMacro(Intensity, double);
  ///@}

  ///@{
  /**
   * Show A itself (linear grey, background white) instead of the shaded image. Default off.
   */
  vtkSetMacro(AOOnly, bool);
  vtkGetMacro(AOOnly, bool);
  vtkBooleanMacro(AOOnly, bool);
  ///@}

  ///@{
  /**
   * Screen pixels per AO-map texel along each axis: McGuire's screen-space subsampling. The
   * volumes are drawn into a (width / AOScale) x (height / AOScale) map, each texel evaluated
   * exactly at one full-resolution pixel, and the map is resampled to the screen by HAO's
   * joint bilateral filter (vtkAOBilateralUpsampler: depth, normal and AO range kernels, so
   * occlusion does not bleed across silhouettes). The volume stage's cost falls about as
   * 1 / AOScale^2; 1 evaluates every pixel (no filter). Range [1, 8]. Default is 1.
   */
  vtkSetClampMacro(AOScale, int, 1, 8);
  vtkGetMacro(AOScale, int);
  ///@}

  ///@{
  /**
   * Width m, in screen pixels, of the bilateral filter's window when AOScale > 1 (HAO eq. 5).
   * The map has no sampling noise to hide, so a window of about 2 AOScale suffices.
   * Range [2, 64]. Default is 6.
   */
  vtkSetClampMacro(FilterSize, int, 2, 64);
  vtkGetMacro(FilterSize, int);
  ///@}

  ///@{
  /**
   * GPU time of each stage of the last frame whose timer queries were read, in milliseconds
   * (the previous frame's, read without waiting when the next frame starts; FinishTimings()
   * reads the frame just rendered).
   */
  double GetGBufferTime() { return this->StageTimes[0]; }
  double GetVolumeTime() { return this->StageTimes[1]; }
  double GetFilterTime() { return this->StageTimes[2]; }
  double GetCompositeTime() { return this->StageTimes[3]; }
  ///@}

  /**
   * Wait for the last frame's timer queries and update the stage times. Needs the context.
   */
  void FinishTimings();

  /**
   * Number of occluding triangles (volumes) drawn by the last frame.
   */
  vtkGetMacro(NumberOfOccludingTriangles, vtkIdType);

  /**
   * How many times the occluding triangles were gathered and uploaded since creation.
   */
  vtkGetMacro(GeometryUpdateCount, int);

  /**
   * Whether the last frame applied ambient occlusion (false for empty scenes, picking).
   */
  vtkGetMacro(LastFrameHadOcclusion, bool);

  /**
   * Copy A of the last frame into @p image: two float components per pixel, A and coverage
   * (A = 1 on the background), as in ao-definition.md. Needs the render window's context
   * current (right after Render()). Returns false if the last frame had no occlusion.
   */
  bool GetAmbientOcclusionImage(vtkImageData* image);

  /**
   * Bytes of GPU memory the pass owns now: the G-buffer, the AO map with its point map and
   * depth, the filter's targets, and the occluding triangles' buffer (48 bytes a triangle).
   * 0 before the first frame and after ReleaseGraphicsResources.
   */
  long long GetGraphicsMemorySize();

protected:
  vtkAmbientOcclusionVolumesPass();
  ~vtkAmbientOcclusionVolumesPass() override;

  /// Gather the visible opaque props of the renderer (all of them, not only those in view).
  void CollectOccluders(vtkRenderer* ren, std::vector<vtkProp*>& props, double bounds[6]);
  /// Rebuild and upload the triangle buffer if an occluder changed; false if there is none.
  bool UpdateOccluderGeometry(vtkOpenGLRenderWindow* renWin, const std::vector<vtkProp*>& props);
  /// Create the accumulation target and program; false (after an error) on failure.
  bool InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h);
  /// Rasterize the volumes over the G-buffer into the accumulation target.
  bool RenderVolumes(vtkOpenGLRenderWindow* renWin, vtkRenderer* ren);
  /// Read back finished timer queries.
  void CollectTimings(bool wait);

  double Radius = 0.0;
  double EffectiveRadius = 0.0;
  double Bias = 0.0;
  double EffectiveBias = 0.0;
  int Falloff = WENDLAND;
  double Intensity = 1.0;
  bool AOOnly = false;
  int AOScale = 1;
  int FilterSize = 6;

  vtkIdType NumberOfOccludingTriangles = 0;
  int GeometryUpdateCount = 0;
  bool LastFrameHadOcclusion = false;
  bool Warned = false;
  std::vector<double> GeometrySignature;
  double SceneOrigin[3] = { 0, 0, 0 }; ///< the triangles are stored relative to it
  double SceneBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double StageTimes[4] = { 0, 0, 0, 0 };
  bool TimingsPending = false;

  struct vtkInternals;
  vtkInternals* Internals;

  vtkNew<vtkAOGBufferPass> GBuffer;
  vtkNew<vtkAOCompositor> Compositor;
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
  vtkNew<vtkAOBilateralUpsampler> Upsampler;
  std::unique_ptr<vtkOpenGLQuadHelper> InitQuad; ///< writes the initial AO map
  vtkTextureObject* Result = nullptr; ///< what the last frame composited (Occlusion or filtered)
  int ResultScale = 1;
  vtkOpenGLRenderTimer* Timers[4];

private:
  vtkAmbientOcclusionVolumesPass(const vtkAmbientOcclusionVolumesPass&) = delete;
  void operator=(const vtkAmbientOcclusionVolumesPass&) = delete;
};

#endif
