/**
 * @class   vtkHybridAmbientOcclusionPass
 * @brief   Hybrid Ambient Occlusion (Reinboth, Boubekeur, Alexa, Eurographics 2009) as a
 *          VTK render pass.
 *
 * Used like vtkSSAOPass:
 * @code
 * vtkNew<vtkRenderStepsPass> basic;
 * vtkNew<vtkHybridAmbientOcclusionPass> hao;
 * hao->SetDelegatePass(basic);
 * renderer->SetPass(hao);
 * @endcode
 *
 * Unlike screen-space AO it sees every opaque prop of the renderer, on screen or not, behind
 * the camera or hidden behind other surfaces. Each frame it runs four stages, each a class of
 * its own:
 * 1. vtkAOBitmaskVoxelizer: a single-pass bitmask voxelization of the opaque props in a box
 *    (section 5). Only when an occluder changed: a static scene under a moving camera pays
 *    no voxelization.
 * 2. vtkAOGBufferPass: the delegate renders colour, normal and depth.
 * 3. vtkAOVoxelTracer: rays marched through the grid from each texel of a reduced-resolution
 *    AO map, Wendland-weighted, jittered in object space (section 6).
 * 4. vtkAOBilateralUpsampler: separable joint bilateral upsampling (section 7), then
 *    vtkAOCompositor multiplies the image by A^Intensity and restores the depth buffer.
 *
 * The quantity computed is A of shared/design/ao-definition.md, so AOOnly images compare pixel
 * for pixel with the project's ray-traced reference. Use one pass per renderer.
 *
 * Translucent props receive AO but do not occlude. Volumes, images and 2-D props neither.
 * Picking (a hardware selector on the renderer) bypasses the pass.
 */
#ifndef vtkHybridAmbientOcclusionPass_h
#define vtkHybridAmbientOcclusionPass_h

#include "vtkImageProcessingPass.h"
#include "vtkNew.h"               // For vtkNew
#include "vtkSmartPointer.h"      // For the parallel reducer
#include "vtkaoRenderingModule.h" // For export macro

#include <vector> // For the voxelization signature

class vtkAOBilateralUpsampler;
class vtkAOBitmaskVoxelizer;
class vtkOpenGLRenderWindow;
class vtkAOCompositor;
class vtkVolumetricPass;
class vtkAOGBufferPass;
class vtkAOParallelReducer;
class vtkAOVoxelTracer;
class vtkImageData;
class vtkOpenGLRenderTimer;
class vtkProp;

class VTKAORENDERING_EXPORT vtkHybridAmbientOcclusionPass : public vtkImageProcessingPass
{
public:
  static vtkHybridAmbientOcclusionPass* New();
  vtkTypeMacro(vtkHybridAmbientOcclusionPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render the delegate with ambient occlusion.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Free every GL resource of every stage (and of the delegate).
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /**
   * Bytes of GPU memory in the textures the pass's stages own now: G-buffer (colour, normal,
   * depth at the renderer's size), voxel grid(s), the tracer's AO map, noise, coarse level and
   * distance field, the filter's two targets. 0 before the first frame and after
   * ReleaseGraphicsResources.
   */
  long long GetGraphicsMemorySize();

  ///@{
  /**
   * Occlusion radius R (the paper's d_max), world units: geometry farther than R does not
   * occlude. 0 means automatic: a tenth of the diagonal of the occluders' bounds.
   * Range [0, inf). Default is 0 (automatic).
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
   * Rays start at p + Bias n, world units (shared/design/ao-definition.md). Any value is
   * safe: a surface's own voxels are recognised by their place against its tangent plane
   * (see vtkAOVoxelTracer), not skipped by the bias, so the bias only moves where rays start,
   * as it does for the ray-traced reference. Range [0, inf). Default is 0: rays start on the
   * surface, which is the integral the reference computes with its tiny offset.
   */
  vtkSetClampMacro(Bias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Bias, double);
  ///@}

  /**
   * The bias used by the last frame (equal to Bias; kept for compatibility).
   */
  vtkGetMacro(EffectiveBias, double);

  ///@{
  /**
   * Half-angle of the cone of rays around the normal, in units of pi/2 (1 = the full
   * hemisphere, as the reference). Smaller values give sharper, darker creases. Range
   * [0.01, 1]. Default is 1.
   */
  vtkSetClampMacro(Spread, double, 0.01, 1.0);
  vtkGetMacro(Spread, double);
  ///@}

  ///@{
  /**
   * Rays per AO-map texel: the main cost and the main noise control. Range [1, 1024].
   * Default is 8. The paper uses 32; tuned against the ray-traced reference (vtkao quality,
   * 10 scenes, 640x360, 512 reference samples: Documentation/quality.md): 8 rays with 4 steps
   * give a mean RMSE of 0.0475 against 0.0481 for 16 rays with 8 steps (the bilateral filter
   * removes the extra noise; the error left is the grid's), at about two thirds of the trace
   * time.
   */
  vtkSetClampMacro(NumberOfRays, int, 1, 1024);
  vtkGetMacro(NumberOfRays, int);
  ///@}

  ///@{
  /**
   * Steps per ray, evenly spaced over the radius (the paper's fixed step count). Each step
   * tests the cells along its segment, one point per cell, so one-cell-thick surfaces are
   * not stepped over; points in empty space are skipped with the grid's distance field.
   * The step count sets where the falloff is sampled and the jitter's stratification.
   * Range [1, 256]. Default is 4 (the paper uses 8; 4 measured as good or better against
   * the reference on every scene but contact, where it is 0.001 worse: quality.md).
   */
  vtkSetClampMacro(NumberOfSteps, int, 1, 256);
  vtkGetMacro(NumberOfSteps, int);
  ///@}

  ///@{
  /**
   * Cells along the longest side of the voxelized region. Memory is about N^3 / 8 bytes.
   * 0 means automatic: cells of at most EffectiveRadius / CellsPerRadius, between 64 and
   * MaximumAutomaticResolution (and what the OpenGL implementation supports, silently).
   * An explicit value in [8, 4096] is clamped with a warning to the implementation's limits
   * (texture size; 128 slices per draw buffer). Default is 0 (automatic).
   */
  vtkSetClampMacro(VoxelResolution, int, 0, 4096);
  vtkGetMacro(VoxelResolution, int);
  ///@}

  ///@{
  /**
   * The automatic resolution's target: cells per occlusion radius (default 64), and its
   * upper bound (default 1024: a 128 MiB bit grid). Coarser cells darken occluders that
   * lie near R (their voxels reach inside R); see Documentation/results.md.
   */
  vtkSetClampMacro(CellsPerRadius, double, 1.0, 1024.0);
  vtkGetMacro(CellsPerRadius, double);
  vtkSetClampMacro(MaximumAutomaticResolution, int, 64, 4096);
  vtkGetMacro(MaximumAutomaticResolution, int);
  ///@}

  /**
   * The resolution the last voxelization used (VoxelResolution, or the automatic value).
   */
  vtkGetMacro(EffectiveVoxelResolution, int);

  ///@{
  /**
   * The AO map is traced at 1/AOScale of the viewport's resolution along each axis, then
   * upsampled. Range [1, 16]. Default is 3 (the paper: 2, its 400x300 map for 800x600).
   * Measured against the ray-traced reference and vtkSSAOPass (Documentation/quality.md,
   * benchmark.md): mean RMSE 0.0440 / 0.0469 / 0.0492 / 0.0531 at 1 / 2 / 3 / 4, vtkSSAOPass
   * 0.0955; AO overhead on the built-in scene at 1280x720 about 3.6 / 1.3 / 0.73 / 0.7 x
   * vtkSSAOPass's (kernel 32). 3 is the finest map that costs no more than vtkSSAOPass; use 2
   * or 1 where quality matters more than speed.
   */
  vtkSetClampMacro(AOScale, int, 1, 16);
  vtkGetMacro(AOScale, int);
  ///@}

  ///@{
  /**
   * Trace again, at full resolution, the pixels the reduced AO map cannot represent: those
   * for which none of the four nearest map samples lies on their own surface (silhouettes,
   * creases, fins and ribs finer than a texel; see vtkAOVoxelTracer::Refine). Needs Filter
   * and AOScale > 1. RefinementRays: rays per refined pixel (0: NumberOfRays). Default: on,
   * 0.
   */
  vtkSetMacro(Refinement, bool);
  vtkGetMacro(Refinement, bool);
  vtkBooleanMacro(Refinement, bool);
  vtkSetClampMacro(RefinementRays, int, 0, 1024);
  vtkGetMacro(RefinementRays, int);
  ///@}

  /**
   * The share of the viewport's pixels the last frame refined (waits for that frame's GPU
   * work; needs the window's context current). 0 when refinement is off.
   */
  double GetRefinedFraction();

  ///@{
  /**
   * Size m of the bilateral filter's m x m window in screen pixels. Range [2, 64].
   * Default is 16 (the paper's setting).
   */
  vtkSetClampMacro(FilterSize, int, 2, 64);
  vtkGetMacro(FilterSize, int);
  ///@}

  ///@{
  /**
   * Apply the joint bilateral upsampling filter. Off shows the raw AO map (nearest).
   * Default is on.
   */
  vtkSetMacro(Filter, bool);
  vtkGetMacro(Filter, bool);
  vtkBooleanMacro(Filter, bool);
  ///@}

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
   * Strength of the darkening at composite time: the colour is multiplied by A^Intensity
   * (0 = no AO, 1 = A, larger = darker). Does not change A itself. Range [0, 10]. Default 1.
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

  enum RegionModeType
  {
    SCENE = 0,   ///< bounds of all visible opaque props (with a 1% margin)
    VIEW = 1,    ///< the view frustum clipped to the scene, dilated by the radius
    EXPLICIT = 2 ///< ExplicitRegion
  };

  ///@{
  /**
   * The box that is voxelized. SCENE (default) does not change when only the camera moves.
   * VIEW gives sharper grids for large scenes but re-voxelizes when the camera moves.
   * EXPLICIT uses ExplicitRegion (the paper's "arbitrary spatial domain").
   */
  vtkSetClampMacro(RegionMode, int, SCENE, EXPLICIT);
  vtkGetMacro(RegionMode, int);
  void SetRegionModeToScene() { this->SetRegionMode(SCENE); }
  void SetRegionModeToView() { this->SetRegionMode(VIEW); }
  void SetRegionModeToExplicit() { this->SetRegionMode(EXPLICIT); }
  vtkSetVector6Macro(ExplicitRegion, double);
  vtkGetVector6Macro(ExplicitRegion, double);
  ///@}

  ///@{
  /**
   * Rotate the voxel camera by a random rotation drawn from RotationSeed, so polygons aligned
   * with the axes are not lost. Default is on, seed 1.
   */
  void SetRandomRotation(bool);
  bool GetRandomRotation();
  vtkBooleanMacro(RandomRotation, bool);
  void SetRotationSeed(unsigned int);
  unsigned int GetRotationSeed();
  ///@}

  ///@{
  /**
   * Voxelization axes (see vtkAOBitmaskVoxelizer::SetNumberOfAxes). 1: one render of the
   * props along the voxel camera's axis, as in the paper; rays slip through the gaps it
   * leaves where the voxel camera sees surfaces edge-on (A about 0.05 too light beside a
   * sphere). 3 (default): each polygon is voxelized along the grid axis it faces most, so
   * curved surfaces have no gaps, for three renders and a merge per voxelization.
   * Range [1, 3].
   */
  void SetVoxelizationAxes(int);
  int GetVoxelizationAxes();
  ///@}

  ///@{
  /**
   * GPU time of each stage of the last frame whose timer queries were read, in milliseconds:
   * the previous frame's are read, without waiting, when the next frame starts; FinishTimings()
   * reads the frame just rendered. A stage that did not run (voxelization of an unchanged
   * scene) reports 0.
   */
  double GetVoxelizeTime() { return this->StageTimes[0]; }
  double GetGBufferTime() { return this->StageTimes[1]; }
  double GetTraceTime() { return this->StageTimes[2]; }
  double GetFilterTime() { return this->StageTimes[3]; }
  double GetCompositeTime() { return this->StageTimes[4]; }
  ///@}

  /**
   * Wait for the last frame's timer queries and update the stage times. Needs the context.
   */
  void FinishTimings();

  /**
   * How many times the scene was voxelized since the pass was created.
   */
  vtkGetMacro(VoxelizationCount, int);

  /**
   * Whether the last frame applied ambient occlusion (false for empty scenes, bad bounds,
   * picking).
   */
  vtkGetMacro(LastFrameHadOcclusion, bool);

  /**
   * The voxelization stage, for inspection (grid, dimensions, cell size).
   */
  vtkAOBitmaskVoxelizer* GetVoxelizer();

  /**
   * Copy A of the last frame at screen resolution into @p image: two float components per
   * pixel, A and coverage (1 where geometry was hit; A = 1 on the background), as in
   * ao-definition.md. Needs the render window's context current (right after Render()).
   * Returns false if the last frame had no occlusion.
   */
  bool GetAmbientOcclusionImage(vtkImageData* image);

  ///@{
  /**
   * Distributed rendering (sort-last, e.g. ParaView with several ranks): a reducer combines
   * the occluders' bounds, the re-voxelization decision and the voxel grid across processes,
   * so that every process traces against the occluders of all (see vtkAOParallelReducer).
   * With a reducer the pass calls it on every frame in the same order on every process, also
   * on processes without occluders. Default is none (single process).
   */
  void SetParallelReducer(vtkAOParallelReducer* reducer);
  vtkAOParallelReducer* GetParallelReducer();
  ///@}

protected:
  vtkHybridAmbientOcclusionPass();
  ~vtkHybridAmbientOcclusionPass() override;

  /// Gather the visible opaque props of the renderer (all of them, not only those in view).
  void CollectOccluders(vtkRenderer* ren, std::vector<vtkProp*>& props, double bounds[6]);
  /// The region to voxelize for the current mode; false if empty.
  bool ComputeRegion(vtkRenderer* ren, const double sceneBounds[6], double region[6]);
  /// The automatic voxel resolution for @p region (see SetVoxelResolution).
  int AutomaticVoxelResolution(vtkOpenGLRenderWindow* renWin, const double region[6]);
  /// Whether anything that occludes changed since the last voxelization.
  bool NeedsVoxelization(const std::vector<vtkProp*>& props, const double region[6]);
  /// Read back finished timer queries.
  void CollectTimings(bool wait);

  double Radius = 0.0;
  double EffectiveRadius = 0.0;
  double Bias = 0.0;
  double EffectiveBias = 0.0;
  double CellsPerRadius = 64.0;
  bool Refinement = true;
  int RefinementRays = 0;
  int MaximumAutomaticResolution = 1024;
  int EffectiveVoxelResolution = 0;
  double Spread = 1.0;
  int NumberOfRays = 8;
  int NumberOfSteps = 4;
  int VoxelResolution = 0;
  int AOScale = 3;
  int FilterSize = 16;
  bool Filter = true;
  int Falloff = WENDLAND;
  double Intensity = 1.0;
  bool AOOnly = false;
  int RegionMode = SCENE;
  double ExplicitRegion[6] = { -1, 1, -1, 1, -1, 1 };

  int VoxelizationCount = 0;
  bool LastFrameHadOcclusion = false;
  bool Warned = false;
  std::vector<double> VoxelizationSignature;
  double StageTimes[5] = { 0, 0, 0, 0, 0 };
  bool TimingsPending = false; ///< timers of a rendered frame not yet read

  vtkNew<vtkAOBitmaskVoxelizer> Voxelizer;
  vtkNew<vtkAOGBufferPass> GBuffer;
  vtkNew<vtkAOVoxelTracer> Tracer;
  vtkNew<vtkAOBilateralUpsampler> Upsampler;
  vtkNew<vtkAOCompositor> Compositor;
  vtkNew<vtkVolumetricPass> VolumetricPass; // volumes, drawn after the composite
  vtkOpenGLRenderTimer* Timers[5];
  vtkSmartPointer<vtkAOParallelReducer> ParallelReducer;

private:
  vtkHybridAmbientOcclusionPass(const vtkHybridAmbientOcclusionPass&) = delete;
  void operator=(const vtkHybridAmbientOcclusionPass&) = delete;
};

#endif
