/**
 * @class   vtkAmbientOcclusionPassBase
 * @brief   The pipeline shared by the object-space ambient occlusion passes: G-buffer, one
 *          occlusion stage, joint bilateral upsampling, composite.
 *
 * A template method. Each frame Render() runs
 * 1. the occluders: all visible opaque props of the renderer (on screen or not), their bounds
 *    and the effective radius; then PrepareOcclusion(), the subclass's per-scene work (HAO's
 *    voxelization, AOV's triangle buffer), normally only when an occluder changed;
 * 2. vtkAOGBufferPass: the delegate renders colour, normal and depth of the surfaces;
 * 3. RenderOcclusion(): the subclass's occlusion stage writes the AO map, one texel every
 *    AOScale pixels (HAO: vtkAOVoxelTracer; AOV: vtkAOVolumeRasterizer);
 * 4. vtkAOBilateralUpsampler: joint bilateral upsampling of the map to the screen (HAO eq. 5),
 *    when the subclass's UsesFilter() says so;
 * 5. vtkAOAccumulator: with Accumulation on, the running mean of the screen's A over the
 *    frames rendered since anything but the occlusion stage's jitter last changed (a still
 *    view converges frame after frame: see SetAccumulation);
 * 6. vtkAOCompositor: the image multiplied by A^Intensity (or A itself), and the G-buffer depth;
 * 7. volumes (vtkVolume props) over the composite, against that depth;
 * 8. 2-D props (vtkActor2D: text, scalar bars, annotations) and widget representations
 *    (vtkAOPropGeometry::IsOverlay) over everything, as the renderer draws them without a
 *    pass, after the overlay step of a vtkRenderStepsPass delegate for the surfaces (their own
 *    2-D content, such as vtkAxesActor's captions). Neither is drawn into the G-buffer: the
 *    shaders of 2-D actors write no normal, and they would be darkened by the occlusion of the
 *    surfaces under them.
 *
 * It also owns what goes with that pipeline: the shared parameters, the per-stage GPU timers,
 * picking (a hardware selector bypasses the pass), the plain-render fallbacks (no delegate's
 * window, nothing that occludes, a stage that failed), GetAmbientOcclusionImage() and the
 * memory accounting. The quantity is A of shared/design/ao-definition.md.
 *
 * @sa vtkHybridAmbientOcclusionPass vtkAmbientOcclusionVolumesPass
 */
#ifndef vtkAmbientOcclusionPassBase_h
#define vtkAmbientOcclusionPassBase_h

#include "vtkImageProcessingPass.h"
#include "vtkMatrix4x4.h"         // For the frame matrices
#include "vtkNew.h"               // For vtkNew
#include "vtkSmartPointer.h"      // For FrameProps
#include "vtkaoRenderingModule.h" // For export macro

#include <vector> // For the occluder list

class vtkAOAccumulator;
class vtkAOBilateralUpsampler;
class vtkAOCompositor;
class vtkAOGBufferPass;
class vtkImageData;
class vtkOpenGLRenderTimer;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkSequencePass;
class vtkTextureObject;
class vtkVolumetricPass;

class VTKAORENDERING_EXPORT vtkAmbientOcclusionPassBase : public vtkImageProcessingPass
{
public:
  vtkTypeMacro(vtkAmbientOcclusionPassBase, vtkImageProcessingPass);
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
   * Bytes of GPU memory in the textures and buffers the pass's stages own now: the G-buffer
   * (colour, normal, depth at the renderer's size), the occlusion stage's (see the subclass),
   * the filter's two targets. 0 before the first frame and after ReleaseGraphicsResources.
   */
  long long GetGraphicsMemorySize();

  ///@{
  /**
   * Occlusion radius R (HAO's d_max, McGuire's delta), world units: geometry farther than R
   * does not occlude. 0 means automatic: a tenth of the diagonal of the occluders' bounds (as
   * the reference). Range [0, inf). Default is 0 (automatic).
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
   * Occlusion is evaluated from p + Bias n, world units, as the reference starts its rays.
   * 0 means the subclass's rule: HAO starts on the surface (its own voxels are recognised
   * against the tangent plane, so any bias is safe); AOV uses 1/2000 of the occluders'
   * bounds padded by R. Range [0, inf). Default is 0.
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

  ///@{
  /**
   * Screen pixels per AO-map texel along each axis: the occlusion stage writes a
   * (width / AOScale) x (height / AOScale) map, each texel evaluated at one full-resolution
   * pixel, which the joint bilateral filter resamples to the screen. Range [1, 16] (AOV:
   * [1, 8]). Default: the subclass's, with the measurement behind it (HAO 3, AOV 1).
   */
  vtkSetClampMacro(AOScale, int, 1, 16);
  vtkGetMacro(AOScale, int);
  ///@}

  ///@{
  /**
   * Width m, in screen pixels, of the bilateral filter's m x m window (HAO eq. 5).
   * Range [2, 64]. Default: the subclass's (HAO 16, the paper's; AOV 6).
   */
  vtkSetClampMacro(FilterSize, int, 2, 64);
  vtkGetMacro(FilterSize, int);
  ///@}

  ///@{
  /**
   * GPU time of each shared stage of the last frame whose timer queries were read, in
   * milliseconds: the previous frame's are read, without waiting, when the next frame starts;
   * FinishTimings() reads the frame just rendered. A stage that did not run reports 0. The
   * subclasses name the times of their own stages (HAO: GetVoxelizeTime, GetTraceTime; AOV:
   * GetVolumeTime).
   */
  double GetGBufferTime() { return this->StageTimes[GBUFFER]; }
  double GetFilterTime() { return this->StageTimes[FILTER]; }
  double GetCompositeTime() { return this->StageTimes[COMPOSITE]; }
  ///@}

  ///@{
  /**
   * Progressive refinement of a still view. While nothing that changes A changes between two
   * renders (the camera, the window or viewport size, a prop, its transform, mapper or data,
   * which props are visible, a parameter of the pass: anything that modifies it), each new
   * render evaluates the occlusion stage with a new jitter (the frame's index in a
   * low-discrepancy sequence; HAO) and the composite shows the running mean of A over the
   * frames since the last change, at screen resolution after upsampling and refinement. Any
   * change restarts the mean, and its first frame is exactly the frame without accumulation,
   * so an interactive view looks and costs as before. A deterministic stage that subsamples
   * (AOV with AOScale s > 1) converges by stratification instead: each further render
   * evaluates another pixel of every s x s block and writes those exact values in place,
   * so after s^2 renders every pixel has its own (StratifiesSubsampledMap). Once the mean
   * holds MaximumAccumulatedFrames (s^2 if fewer for such a stage; 1 for a deterministic
   * stage that does not subsample, AOV at AOScale 1), further renders of the unchanged view
   * skip the occlusion stage and the filter and composite the mean: they cost less than a
   * plain frame. Each accumulated frame costs one frame plus one full-screen blend.
   * Default: on, at most 16 frames (HAO's error against the reference stops falling there on
   * most scenes: Documentation/quality.md). Range of MaximumAccumulatedFrames [1, 4096].
   */
  vtkSetMacro(Accumulation, bool);
  vtkGetMacro(Accumulation, bool);
  vtkBooleanMacro(Accumulation, bool);
  vtkSetClampMacro(MaximumAccumulatedFrames, int, 1, 4096);
  vtkGetMacro(MaximumAccumulatedFrames, int);
  ///@}

  /**
   * The number of frames in the mean the last render composited: 1 for the first frame after
   * a change (and always without Accumulation), up to MaximumAccumulatedFrames (see
   * SetAccumulation for deterministic stages); 0 when the last render had no occlusion.
   */
  vtkGetMacro(AccumulatedFrames, int);

  /**
   * The number of frames the mean of an unchanged view can hold with the current settings:
   * MaximumAccumulatedFrames for a stage that jitters (HAO), AOScale^2 (at most that) for
   * AOV's subsampled map, 1 otherwise (what a viewer shows as "k of N").
   */
  int GetAccumulationTarget() { return this->Accumulation ? this->AccumulationTarget() : 1; }

  /**
   * Whether another render of the unchanged view would still improve A (Accumulation on, the
   * last render had occlusion and fewer frames than the maximum are in the mean). What an
   * idle viewer's timer checks before it renders again.
   */
  bool IsAccumulating();

  /**
   * Wait for the last frame's timer queries and update the stage times. Needs the context.
   */
  void FinishTimings();

  /**
   * Whether the last frame applied ambient occlusion (false for empty scenes, bad bounds,
   * picking, a stage that failed).
   */
  vtkGetMacro(LastFrameHadOcclusion, bool);

  /**
   * Whether the last frame's G-buffer rebuilt normals from the depths, in a full-screen pass of
   * its own, because a prop may have drawn without them (lighting off, a mapper outside
   * vtkPolyDataMapper's render-pass hooks: vtkAOGBufferPass::GetNormalsCompleted).
   */
  bool GetLastFrameCompletedNormals();

  /**
   * Copy A of the last frame at screen resolution into @p image: two float components per
   * pixel, A and coverage (1 where geometry was hit; A = 1 on the background), as in
   * ao-definition.md. Needs the render window's context current (right after Render()).
   * Returns false if the last frame had no occlusion.
   */
  bool GetAmbientOcclusionImage(vtkImageData* image);

protected:
  vtkAmbientOcclusionPassBase();
  ~vtkAmbientOcclusionPassBase() override;

  /// The stages timed each frame. PREPARE is the subclass's per-scene work, OCCLUSION its
  /// occlusion stage.
  enum Stage
  {
    PREPARE = 0,
    GBUFFER,
    OCCLUSION,
    FILTER,
    COMPOSITE,
    NUMBER_OF_STAGES
  };

  /// What the occlusion stage of a frame works from.
  struct Frame
  {
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkRenderer* Renderer = nullptr;
    std::vector<vtkProp*> Occluders; ///< the visible opaque props, on screen or not
    double Bounds[6];                ///< the occluders' bounds
    // The camera, as the G-buffer was rendered with it (set for RenderOcclusion).
    vtkNew<vtkMatrix4x4> View;       ///< view matrix
    vtkNew<vtkMatrix4x4> Projection; ///< projection, for the renderer's aspect
    bool Parallel = false;           ///< whether the projection is parallel
    /// The frame's index in the accumulation (0: the first frame after a change): the
    /// occlusion stage's jitter index. Always 0 without Accumulation.
    int AccumulationIndex = 0;
    /// The pixel of each AOScale x AOScale block at which the map's texel is evaluated, from
    /// the block's lower left corner: its centre (AOScale / 2 on each axis), or for a stage
    /// that StratifiesSubsampledMap() the frame's own pixel of the block (see there).
    int SampleOffset[2] = { 0, 0 };
  };

  ///@{
  /// The occlusion stage, supplied by each subclass.
  /// Per-scene work before the G-buffer (GL state is saved around it): set EffectiveBias and
  /// bring the stage's occluder representation up to date. False when nothing occludes: the
  /// frame is then rendered without AO.
  virtual bool PrepareOcclusion(const Frame& frame) = 0;
  /// Write the AO map (RGBA float: A, coverage, window depth and packed normal of the pixel
  /// each texel was evaluated at, one texel every AOScale pixels) from the G-buffer.
  /// nullptr (after an error) on failure.
  virtual vtkTextureObject* RenderOcclusion(const Frame& frame) = 0;
  /// Bytes of GPU memory the occlusion stage owns.
  virtual long long GetOcclusionMemorySize() = 0;
  /// Free the occlusion stage's GL resources.
  virtual void ReleaseOcclusionResources(vtkWindow* w) = 0;
  ///@}

  /// Whether the occlusion stage's result changes with Frame::AccumulationIndex (jitter).
  /// False here: such a stage converges in one frame.
  virtual bool JittersOcclusion() { return false; }
  /// Append to @p signature what the subclass's occlusion depends on besides the pass's
  /// parameters, the camera and the props (HAO: its voxelizations). Nothing here.
  virtual void AppendAccumulationSignature(std::vector<double>& /*signature*/) {}

  /// Whether the occlusion stage is deterministic and evaluates each map texel at the pixel
  /// Frame::SampleOffset of its block (AOV). Accumulation then converges by stratification
  /// instead of averaging: the first frame after a change is filtered as usual, and each
  /// later frame evaluates the map at another pixel of every block and writes those raw
  /// values at their own pixels of the mean, so after AOScale^2 frames (capped by
  /// MaximumAccumulatedFrames) every pixel holds the stage's exact value at that pixel, as
  /// with AOScale 1. False here.
  virtual bool StratifiesSubsampledMap() { return false; }

  /// Whether the AO map is filtered and upsampled. Default: when AOScale > 1.
  virtual bool UsesFilter() { return this->AOScale > 1; }
  /// Whether the filter marks the pixels the reduced map cannot represent, for
  /// RefineOcclusion (HAO's refinement). False here.
  virtual bool RefinesOcclusion() { return false; }
  /// The A contrast within a map texel above which the filter marks a pixel for refinement
  /// (here vtkAOBilateralUpsampler::Marking's default).
  virtual double RefinementMarkingContrast();
  /// After the filter, when RefinesOcclusion(): improve the full-resolution map @p upsampled
  /// in place at the pixels @p marks marks (depth 0; vtkAOBilateralUpsampler::Marking).
  /// Nothing here.
  virtual bool RefineOcclusion(const Frame& /*frame*/,
    vtkTextureObject* /*upsampled*/,
    vtkTextureObject* /*marks*/)
  {
    return true;
  }

  /// Gather the visible opaque props of the renderer (all of them, not only those in view)
  /// and their bounds; false if there are none.
  virtual bool CollectOccluders(vtkRenderer* ren, std::vector<vtkProp*>& props, double bounds[6]);

  /// Whether all six numbers are finite and each minimum is at most its maximum.
  static bool ValidBounds(const double bounds[6]);

  ///@{
  /// The steps of Render().
  /// Render for a hardware selector (picking): the props through the selector, no AO.
  void RenderForSelection(const vtkRenderState* s);
  /// Render the delegate alone (no AO).
  void RenderWithoutOcclusion(const vtkRenderState* s);
  /// EffectiveRadius from Radius or the occluders' bounds; false if it is not usable.
  bool UpdateEffectiveRadius(const double bounds[6]);
  /// The occluders, their bounds and the radius of @p frame; false if nothing occludes.
  bool CollectFrame(Frame& frame);
  /// G-buffer, occlusion, filter, composite and volumes, with the GL state saved around them.
  void RenderOccludedFrame(const vtkRenderState* s, Frame& frame);
  /// The camera matrices of @p frame, after the G-buffer.
  void UpdateFrameCamera(Frame& frame);
  /// The props of a frame's render state, by where they are drawn.
  struct FrameProps
  {
    std::vector<vtkProp*> Surfaces; ///< into the G-buffer
    std::vector<vtkProp*> Volumes;  ///< over the composite
    std::vector<vtkProp*> Overlays; ///< 2-D props (vtkAOPropGeometry::IsOverlay), last
    /// The delegate's overlay step (a vtkRenderStepsPass's), run for the surfaces after the
    /// composite instead of in the G-buffer; null if the delegate has none.
    vtkSmartPointer<vtkRenderPass> SurfaceOverlayStep;
  };
  /// Sort the props of @p s into @p props and render the surfaces into the G-buffer.
  void RenderGBuffer(const vtkRenderState* s, FrameProps& props);
  /// Filter @p occlusion to the screen if UsesFilter(); updates Result and ResultScale.
  bool FilterOcclusion(const Frame& frame, vtkTextureObject* occlusion);
  /// Restart the accumulation if anything A depends on changed since the last frame, and set
  /// frame.AccumulationIndex; true if the mean already holds all the frames it can use (the
  /// occlusion stage need not run).
  bool UpdateAccumulation(const vtkRenderState* s, Frame& frame);
  /// The numbers that change when A may change (see SetAccumulation), but the camera's
  /// matrices (compared with a tolerance in UpdateAccumulation).
  std::vector<double> AccumulationSignature(const vtkRenderState* s, const Frame& frame);
  /// Add Result to the running mean and make the mean the Result; false on failure.
  bool AccumulateOcclusion(const Frame& frame);
  /// Whether this frame takes the stratified path (see StratifiesSubsampledMap): a later
  /// frame of an accumulation of a subsampled, filtered, deterministic stage.
  bool StratifiedFrame(const Frame& frame);
  /// The stratified path's occlusion: evaluate the map at the frame's pixel of each block
  /// and write it at those pixels of the mean (with, on the second frame, the first frame's
  /// map at its own pixels); the mean becomes the Result. False on failure.
  bool RenderStratifiedOcclusion(Frame& frame);
  /// The pixel of each block at which the k-th frame of an accumulation evaluates the map.
  void GetSampleOffset(int k, int offset[2]);
  /// The frames the mean can use: MaximumAccumulatedFrames, or 1 without jitter.
  int AccumulationTarget();
  /// Composite Result (or, if @p ok is false, no occlusion) into the renderer's framebuffer.
  bool Composite(const vtkRenderState* s, vtkOpenGLRenderWindow* renWin, bool ok);
  /// Draw @p props with @p pass over the composite (VolumetricPass for the volumes, the
  /// delegate's overlay step for the surfaces, Props2DPass for the 2-D props).
  void RenderOverComposite(const vtkRenderState* s,
    vtkOpenGLRenderWindow* renWin,
    vtkRenderPass* pass,
    const std::vector<vtkProp*>& props);
  /// The renderer's viewport in the framebuffer it draws into.
  void GetTargetViewport(const vtkRenderState* s, int viewport[4]);
  /// Read back finished timer queries.
  void CollectTimings(bool wait);
  ///@}

  double Radius = 0.0;
  double EffectiveRadius = 0.0;
  double Bias = 0.0;
  double EffectiveBias = 0.0;
  int Falloff = WENDLAND;
  double Intensity = 1.0;
  bool AOOnly = false;
  int AOScale = 1;    ///< AOV's default; HAO sets its own
  int FilterSize = 6; ///< AOV's default; HAO sets its own

  bool Accumulation = true;
  int MaximumAccumulatedFrames = 16;
  int AccumulatedFrames = 0;
  std::vector<double> LastAccumulationSignature;
  std::vector<double> LastAccumulationCamera; ///< view and projection at the restart
  int AccumulatedScale = 1;                   ///< ResultScale of the frames in the mean
  /// The stratified path's order of the pixels of a block (StratifiedOrder[k] for the k-th
  /// frame; the centre first, then each the farthest from those before it), for the block
  /// size StratifiedOrderScale.
  std::vector<int> StratifiedOrder;
  int StratifiedOrderScale = 0;
  vtkTextureObject* FirstMap = nullptr; ///< the map of the accumulation's first frame

  bool LastFrameHadOcclusion = false;
  bool Warned = false;
  double StageTimes[NUMBER_OF_STAGES] = { 0, 0, 0, 0, 0 };
  bool TimingsPending = false; ///< timers of a rendered frame not yet read
  vtkOpenGLRenderTimer* Timers[NUMBER_OF_STAGES];

  vtkNew<vtkAOGBufferPass> GBuffer;
  vtkNew<vtkAOBilateralUpsampler> Upsampler;
  vtkNew<vtkAOAccumulator> Accumulator;
  vtkNew<vtkAOCompositor> Compositor;
  vtkNew<vtkVolumetricPass> VolumetricPass; ///< volumes, drawn after the composite
  vtkNew<vtkSequencePass> Props2DPass;      ///< 2-D props, drawn last
  vtkTextureObject* Result = nullptr; ///< what the last frame composited (the map or filtered)
  int ResultScale = 1;
  vtkTextureObject* NoOcclusion = nullptr; ///< 1 texel, A = 1: composites a frame without AO

private:
  vtkAmbientOcclusionPassBase(const vtkAmbientOcclusionPassBase&) = delete;
  void operator=(const vtkAmbientOcclusionPassBase&) = delete;
};

#endif
