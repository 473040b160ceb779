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
 * 4. vtkAOBilateralUpsampler: separable joint bilateral upsampling (section 7). Pixels the
 *    reduced map cannot represent (no map sample on their own surface, or samples around
 *    them that disagree) are then traced again at full resolution (Refinement). Then
 *    vtkAOCompositor multiplies the image by A^Intensity and restores the depth buffer.
 *
 * The quantity computed is A of shared/design/ao-definition.md, so AOOnly images compare pixel
 * for pixel with the project's ray-traced reference. Use one pass per renderer.
 *
 * Translucent props receive AO but do not occlude. Volumes, images and 2-D props neither.
 * Picking (a hardware selector on the renderer) bypasses the pass.
 *
 * The G-buffer, filter and composite, the shared parameters (Radius, Bias, Falloff,
 * Intensity, AOOnly, AOScale, FilterSize) and the timings of those stages come from
 * vtkAmbientOcclusionPassBase; this class adds the voxelization and the voxel tracer. Its
 * defaults for the shared parameters, tuned against the ray-traced reference:
 * - Bias 0: rays start on the surface, as the reference's tiny offset. A surface's own voxels
 *   are recognised by their place against its tangent plane (vtkAOVoxelTracer), not skipped
 *   by the bias, so any Bias >= 0 gives a sensible A; the bias only moves where rays start.
 * - AOScale 3 (the paper: 2, its 400x300 map for 800x600). Measured before the fidelity work
 *   (a 256^3 grid; Documentation/quality.md, benchmark.md): mean RMSE 0.0440 / 0.0469 /
 *   0.0492 / 0.0531 at 1 / 2 / 3 / 4, vtkSSAOPass 0.0955; AO overhead on the built-in scene at
 *   1280x720 about 3.6 / 1.3 / 0.73 / 0.7 x vtkSSAOPass's (kernel 32). Since, the
 *   full-resolution refinement recovers what the map misses at 3; ApplyPreset(QUALITY) uses 2.
 * - FilterSize 16 (the paper's setting).
 *
 * Accumulation (vtkAmbientOcclusionPassBase::SetAccumulation, on by default): each render of
 * an unchanged view rotates every pixel's jitter (Cranley-Patterson) by the next point of
 * the R3 low-discrepancy sequence (vtkAOVoxelTracer::Parameters::FrameIndex), and the
 * screen's A is averaged over those frames: a still converges towards the grid's own
 * A as 8 x N rays per texel would. The first frame after any change is the one without
 * accumulation.
 */
#ifndef vtkHybridAmbientOcclusionPass_h
#define vtkHybridAmbientOcclusionPass_h

#include "vtkAOVoxelTracer.h" // For vtkAOVoxelTracer::Parameters
#include "vtkAmbientOcclusionPassBase.h"
#include "vtkNew.h"               // For vtkNew
#include "vtkSmartPointer.h"      // For the parallel reducer
#include "vtkaoRenderingModule.h" // For export macro

#include <map>    // For the occluders' records
#include <vector> // For the voxelization signature

class vtkAOBitmaskVoxelizer;
class vtkOpenGLRenderWindow;
class vtkAOParallelReducer;
class vtkAOVoxelTracer;

class VTKAORENDERING_EXPORT vtkHybridAmbientOcclusionPass : public vtkAmbientOcclusionPassBase
{
public:
  static vtkHybridAmbientOcclusionPass* New();
  vtkTypeMacro(vtkHybridAmbientOcclusionPass, vtkAmbientOcclusionPassBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Measured trade-offs between speed and fidelity (see ApplyPreset).
  enum PresetType
  {
    INTERACTIVE = 0, ///< fast: a 256^3 grid, one voxelization axis, no refinement
    BALANCED = 1,    ///< the defaults: automatic grid, three axes, refinement
    QUALITY = 2      ///< the defaults with a finer map and more rays
  };

  /**
   * Set the parameters that trade speed against fidelity to a measured set, leaving the
   * others (Radius, Bias, Falloff, Intensity, region, accumulation...) as they are:
   * | preset | VoxelResolution | VoxelizationAxes | Refinement | AOScale | Rays | CellErosion |
   * |---|---|---|---|---|---|---|
   * | INTERACTIVE | 256 | 1 | off | 3 | 8 | 0 |
   * | BALANCED (the defaults) | 0 (automatic, R/64 up to 1024) | 3 | on | 3 | 8 | 0.25 |
   * | QUALITY | 0 (automatic, R/192, cascades of 1024) | 3 | on, contrast 0.05 | 2 | 16 | 0.25 |
   * NumberOfSteps 4, FilterSize 16 and the cascades' automatic choice in all three;
   * CellsPerRadius 64, CascadeResolution 512 and RefinementContrast 0 (automatic) but in
   * QUALITY (192, 1024, 0.05), whose RMSE is at most 0.028 with either falloff on
   * every quality scene, for up to 4 grids of 1024^3 (1.4 GiB of GPU memory on fins) and
   * up to 35 % (Wendland) and 67 % (binary) of the pixels refined (quality.md "Quality preset",
   * 2026-12-04). It is for stills: on llvmpipe it costs about 27 x vtkSSAOPass with kernel 128
   * on the built-in scene, and its cascades re-voxelize as the camera moves (benchmark.md).
   * Measured on llvmpipe against the true integral and vtkSSAOPass (kernel 32), 1280x720,
   * Documentation/benchmark.md ("The main series at the current defaults", 2026-12-05) and
   * quality.md: AO overhead over vtkSSAOPass's 0.78 (INTERACTIVE), 1.32 (BALANCED) and about
   * 50 (QUALITY) on the built-in scene orbiting; 0.85-1.26, 1.9-3.0 and 56-59 with an
   * occluder moving every frame; mean RMSE over 17 scenes (Wendland) 0.043, 0.017 and 0.011
   * (vtkSSAOPass 0.076).
   * INTERACTIVE shows moire on fins and thin parts (no refinement, coarse cells).
   * Unknown values are ignored with an error.
   */
  void ApplyPreset(int preset);
  static const char* GetPresetAsString(int preset);

  ///@{
  /**
   * Cells by which the voxel grid's exposed faces (no occupied neighbour across them, nor
   * diagonally where a slanted surface goes on through an edge or corner) are moved in before
   * the rays test them. A surface anywhere in a cell fills the whole cell, so thin walls, fins
   * and ribs come out a cell thick and the gaps between them a cell narrower than they are,
   * which darkens thin parts by an amount linear in the cell; 0.25 halves that (quality.md,
   * "Thin walls"). 0 turns it off and compiles the tracer without it (the INTERACTIVE preset:
   * the test makes the trace a fifth to a third slower on llvmpipe, which runs every branch
   * of the march loop for every pixel; on GPUs the extra work is confined to the lanes that
   * meet an occupied cell). Range [0, 0.25]. Default is 0.25.
   */
  vtkSetClampMacro(CellErosion, double, 0.0, 0.25);
  vtkGetMacro(CellErosion, double);
  ///@}

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
   * upper bound (default 1024: a 128 MiB bit grid). Coarser cells darken occluders that lie
   * near R (their voxels reach inside R); see Documentation/results.md.
   */
  vtkSetClampMacro(CellsPerRadius, double, 1.0, 1024.0);
  vtkGetMacro(CellsPerRadius, double);
  vtkSetClampMacro(MaximumAutomaticResolution, int, 64, 4096);
  vtkGetMacro(MaximumAutomaticResolution, int);
  ///@}

  /**
   * The resolution the last voxelization used (VoxelResolution, or the automatic value); with
   * cascades, that of each cascade.
   */
  vtkGetMacro(EffectiveVoxelResolution, int);

  ///@{
  /**
   * Cascaded grids, a clipmap around the view (for regions too large for cells of
   * R / CellsPerRadius in one grid). The finest cascade has cells of R / CellsPerRadius and
   * covers a cube of CascadeResolution cells around the camera (its position, or its focal
   * point with a parallel projection, moved into the region); each next cascade has cells
   * and cube twice as large; the last covers the whole region. Each pixel traces through the
   * finest cascade that holds every occluder within R of it, so cells grow with the distance
   * from the camera, as the pixels' footprints do. Memory is about NumberOfCascades x
   * CascadeResolution^3 / 8 bytes per voxelization axis. The cascades move with the camera in
   * steps of 1/16 of their cubes, each grid re-voxelized only when it crosses its own step;
   * turning the camera on the spot moves none.
   *
   * 0 (default) is automatic: one grid unless one grid of MaximumAutomaticResolution cells
   * would have cells coarser than 8 R / CellsPerRadius (R / 8: a region more than 128 R
   * wide at the defaults), otherwise as many cascades (at most 4) as take the cells from
   * R / CellsPerRadius to the region's size. Cascades give the pixels beyond the finest cube
   * coarser cells, so below that size one grid of up to 1024^3 is the better choice (on a
   * city 80 R wide: RMSE 0.026 / 0.049 with Wendland / binary falloff in one grid, 0.025 /
   * 0.064 in 4 cascades of 512, which voxelize 5 x faster). 1: always one grid. 2 to 4: that many
   * cascades (with VoxelResolution 0; an explicit VoxelResolution sets each cascade's).
   * CascadeResolution: cells along each cascade's cube, [64, 1024], default 512 (the city:
   * RMSE 0.025 at 512, 0.030 at 384, 0.041 at 256 with Wendland falloff; 4 cascades of 512
   * take about the GPU memory of one 1024^3 grid, 248 against 237 MiB).
   */
  vtkSetClampMacro(NumberOfCascades, int, 0, 4);
  vtkGetMacro(NumberOfCascades, int);
  vtkSetClampMacro(CascadeResolution, int, 64, 1024);
  vtkGetMacro(CascadeResolution, int);
  ///@}

  /**
   * The number of grids the last voxelization used (1 without cascades).
   */
  vtkGetMacro(EffectiveNumberOfCascades, int);

  ///@{
  /**
   * Trace again, at full resolution, the pixels the reduced AO map cannot represent: those
   * for which none of the four nearest map samples lies on their own surface (silhouettes,
   * creases, fins and ribs finer than a texel), or whose samples' A differ by more than
   * RefinementContrast (see vtkAOBilateralUpsampler::Marking and vtkAOVoxelTracer::Refine).
   * Needs Filter and AOScale > 1. RefinementRays: rays per refined pixel (0, automatic:
   * NumberOfRays with the Wendland falloff, twice that with the binary falloff, whose refined
   * pixels otherwise show its noise as dots and blotches where few neighbours of the same
   * surface average them).
   * RefinementContrast: 0 (automatic) is 0.15 with the Wendland falloff, which marks creases
   * and mouldings finer than a texel, and 0.3 with the binary falloff, whose samples are noisy
   * enough that 0.15 would mark their noise; lower refines more pixels (GetRefinedFraction).
   * RefinementFilterRadius: each refined pixel is then replaced by the weighted mean of the
   * pixels of its own surface within this many pixels, refined or not (0: not filtered; the
   * refined pixels then show their few rays' noise as speckle where many are refined).
   * Default: on, 0, 2, 0.
   */
  vtkSetMacro(Refinement, bool);
  vtkGetMacro(Refinement, bool);
  vtkBooleanMacro(Refinement, bool);
  vtkSetClampMacro(RefinementRays, int, 0, 1024);
  vtkGetMacro(RefinementRays, int);
  vtkSetClampMacro(RefinementFilterRadius, int, 0, 8);
  vtkGetMacro(RefinementFilterRadius, int);
  vtkSetClampMacro(RefinementContrast, double, 0.0, 1.0);
  vtkGetMacro(RefinementContrast, double);
  ///@}

  ///@{
  /**
   * How the refined pixels are shaded. On (the default): listed (a geometry shader compacts
   * them into a transform-feedback buffer), traced and filtered as a dense block, and written
   * back to their pixels, so that no SIMD group of the tracer works on unrefined pixels. Off:
   * in place, a full-screen pass whose depth test rejects the unrefined pixels (a group with
   * one refined pixel then costs as much as a full one). Both give the same image; contexts
   * without geometry shaders or transform feedback fall back to the latter with a warning.
   */
  vtkSetMacro(RefinementList, bool);
  vtkGetMacro(RefinementList, bool);
  vtkBooleanMacro(RefinementList, bool);
  ///@}

  /**
   * The contrast the refinement marks at: RefinementContrast, or where that is 0 the automatic
   * choice for the Falloff (0.15 Wendland, 0.3 binary).
   */
  double GetEffectiveRefinementContrast() const;

  /**
   * The rays per refined pixel: RefinementRays, or where that is 0 the automatic choice
   * (NumberOfRays with the Wendland falloff, twice NumberOfRays with the binary one).
   */
  int GetEffectiveRefinementRays() const;

  /**
   * The share of the viewport's pixels the last frame refined (waits for that frame's GPU
   * work; needs the window's context current). 0 when the last frame did not refine
   * (Refinement off, AOScale 1 or Filter off).
   */
  double GetRefinedFraction();

  ///@{
  /**
   * Apply the joint bilateral upsampling filter. Off shows the raw AO map (nearest).
   * Default is on.
   */
  vtkSetMacro(Filter, bool);
  vtkGetMacro(Filter, bool);
  vtkBooleanMacro(Filter, bool);
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
   * Incremental voxelization. When some occluders change (move, deform, are added) while
   * others do not, the unchanged ones are voxelized once into a base grid, kept, and each
   * later voxelization renders only the changing props and ORs the base in: the grid is the
   * same, bit for bit, as a voxelization of all, since the cells a polygon sets depend on no
   * other polygon. A prop counts as changing from its change until it has been unchanged for
   * 16 frames; then it joins the base, which is made again once. The base is made
   * again too when the grid's frame moves (region, resolution, a cascade's focus), and it
   * costs a second grid's GPU memory per grid while it is kept (released with the other
   * resources, or when nothing moves any more). Default is on; off voxelizes all props
   * whenever one changed.
   */
  vtkSetMacro(IncrementalVoxelization, bool);
  vtkGetMacro(IncrementalVoxelization, bool);
  vtkBooleanMacro(IncrementalVoxelization, bool);
  ///@}

  /**
   * How many of the voxelizations (see GetVoxelizationCount) were incremental (rendered the
   * changing props only, over a kept base), and how many props the last voxelization rendered
   * (its changing props if it was incremental).
   */
  vtkGetMacro(IncrementalVoxelizationCount, int);
  vtkGetMacro(NumberOfVoxelizedProps, int);

  ///@{
  /**
   * GPU time of HAO's own stages of the last frame whose timer queries were read, in
   * milliseconds (see vtkAmbientOcclusionPassBase::GetGBufferTime for the others and when they
   * are read). Voxelization of an unchanged scene does not run and reports 0.
   */
  double GetVoxelizeTime() { return this->StageTimes[PREPARE]; }
  double GetTraceTime() { return this->StageTimes[OCCLUSION]; }
  ///@}

  /**
   * How many times the scene was voxelized since the pass was created.
   */
  vtkGetMacro(VoxelizationCount, int);

  /**
   * The voxelization stage, for inspection (grid, dimensions, cell size).
   */
  vtkAOBitmaskVoxelizer* GetVoxelizer();

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

  /// The occluders of this process, and with a parallel reducer the bounds of all processes'.
  bool CollectOccluders(vtkRenderer* ren, std::vector<vtkProp*>& props, double bounds[6]) override;
  /// The region to voxelize for the current mode; false if empty.
  bool ComputeRegion(vtkRenderer* ren, const double sceneBounds[6], double region[6]);
  /// The automatic voxel resolution for @p region (see SetVoxelResolution).
  int AutomaticVoxelResolution(vtkOpenGLRenderWindow* renWin, const double region[6]);
  /// Whether anything that occludes, the region or the grids' settings changed since the
  /// last call (the cascades' foci are compared grid by grid). Sorts @p props into those
  /// that changed within the last 16 frames (@p moving) and the others (@p still).
  bool NeedsVoxelization(const std::vector<vtkProp*>& props,
    const double region[6],
    std::vector<vtkProp*>& moving,
    std::vector<vtkProp*>& still);
  /// Forget what was voxelized: the next frame voxelizes every prop.
  void ResetVoxelizationState();
  /// Set EffectiveNumberOfCascades and EffectiveVoxelResolution for @p region.
  void ChooseGrids(vtkOpenGLRenderWindow* renWin, const double region[6]);
  /// Each cascade's focus (centre and half-size, see vtkAOBitmaskVoxelizer::SetFocus).
  std::vector<double> CascadeFoci(vtkRenderer* ren, const double region[6]);
  /// Set FrameGrids to the voxelizers in use, finest first (the first is Voxelizer),
  /// creating the cascades on first use.
  void UpdateFrameGrids();

  double Spread = 1.0;
  double CellErosion = 0.25;
  int NumberOfRays = 8;
  int NumberOfSteps = 4;
  int VoxelResolution = 0;
  double CellsPerRadius = 64.0;
  int MaximumAutomaticResolution = 1024;
  int EffectiveVoxelResolution = 0;
  int NumberOfCascades = 0;
  int CascadeResolution = 512;
  int EffectiveNumberOfCascades = 1;
  bool Refinement = true;
  int RefinementRays = 0;
  int RefinementFilterRadius = 2;
  double RefinementContrast = 0.0;
  bool RefinementList = true;
  bool Filter = true;
  int RegionMode = SCENE;
  double ExplicitRegion[6] = { -1, 1, -1, 1, -1, 1 };

  int VoxelizationCount = 0;
  int IncrementalVoxelizationCount = 0;
  int NumberOfVoxelizedProps = 0;
  bool IncrementalVoxelization = true;
  /// What the grids depend on but the props and the cascades' foci (see NeedsVoxelization).
  std::vector<double> GridSignature;
  /// Per occluder: what its voxels depend on, and the frame in which that last changed.
  struct PropRecord
  {
    std::vector<double> Signature;
    long long LastChange = 0;
  };
  std::map<vtkProp*, PropRecord> PropRecords;
  std::vector<vtkProp*> LastOccluders;
  long long FrameNumber = 0;
  /// Per grid: what its kept base holds (grid signature, focus, the still props); empty if
  /// none.
  std::vector<double> BaseKeys[vtkAOVoxelTracer::MaximumLevels];

  vtkNew<vtkAOBitmaskVoxelizer> Voxelizer;
  /// Cascades 1 to 3 (created when first used; Voxelizer is cascade 0).
  vtkSmartPointer<vtkAOBitmaskVoxelizer> Cascades[vtkAOVoxelTracer::MaximumLevels - 1];
  /// The grids of the current frame (set by PrepareOcclusion; traced and refined through).
  vtkAOVoxelTracer::Grids FrameGrids;
  vtkNew<vtkAOVoxelTracer> Tracer;
  vtkSmartPointer<vtkAOParallelReducer> ParallelReducer;

  // The occlusion stage of vtkAmbientOcclusionPassBase.
  /// Compute the region and the bias; voxelize it when an occluder changed.
  bool PrepareOcclusion(const Frame& frame) override;
  /// What the tracer reads of @p frame: its view, the G-buffer, FrameGrids and the settings.
  vtkAOVoxelTracer::Input TracerInput(const Frame& frame);
  /// Trace the AO map through the grid (vtkAOVoxelTracer).
  vtkTextureObject* RenderOcclusion(const Frame& frame) override;
  /// The grid's and the tracer's textures.
  long long GetOcclusionMemorySize() override;
  void ReleaseOcclusionResources(vtkWindow* w) override;
  /// Refinement: the filter marks the pixels the reduced map cannot represent ...
  bool RefinesOcclusion() override { return this->Refinement && this->Filter && this->AOScale > 1; }
  /// The contrast of the marks: GetEffectiveRefinementContrast().
  double RefinementMarkingContrast() override { return this->GetEffectiveRefinementContrast(); }
  /// ... and they are traced again at full resolution.
  bool RefineOcclusion(const Frame& frame,
    vtkTextureObject* upsampled,
    vtkTextureObject* marks) override;
  /// The tracer's jitter follows the accumulation index.
  bool JittersOcclusion() override { return true; }
  /// The voxelizations (a new grid, a cascade that moved) and the voxelizer's settings.
  void AppendAccumulationSignature(std::vector<double>& signature) override;
  /// Filter unless Filter is off.
  bool UsesFilter() override { return this->Filter; }

private:
  vtkHybridAmbientOcclusionPass(const vtkHybridAmbientOcclusionPass&) = delete;
  void operator=(const vtkHybridAmbientOcclusionPass&) = delete;
};

#endif
