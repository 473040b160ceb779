/**
 * @class   vtkPVAmbientOcclusionView
 * @brief   ParaView render view with object-space ambient occlusion (vtkao's Hybrid Ambient
 *          Occlusion pass), correct when the data is distributed over MPI ranks.
 *
 * The pass is installed as the view's render pass: in pvserver/pvbatch with several ranks it
 * runs on every rank on that rank's geometry, before IceT composites the images by depth.
 * A vtkPVAOParallelReducer combines the occluders' bounds and ORs the voxel grids over the
 * ranks, so every rank traces its pixels against the occluders of all ranks (ParaView's
 * built-in screen-space AO, UseSSAO, sees only the local geometry of each rank).
 *
 * Method NONE renders exactly as ParaView's render view.
 */
#ifndef vtkPVAmbientOcclusionView_h
#define vtkPVAmbientOcclusionView_h

#include "vtkNew.h" // For vtkNew
#include "vtkPVRenderView.h"
#include "vtkaoParaViewViewsModule.h" // For export macro

class vtkHybridAmbientOcclusionPass;
class vtkPVAOParallelReducer;
class vtkRenderStepsPass;

class VTKAOPARAVIEWVIEWS_EXPORT vtkPVAmbientOcclusionView : public vtkPVRenderView
{
public:
  static vtkPVAmbientOcclusionView* New();
  vtkTypeMacro(vtkPVAmbientOcclusionView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MethodType
  {
    NONE = 0,
    HAO = 1
    // AOV = 2 when vtkAmbientOcclusionVolumesPass is ready
  };

  ///@{
  /**
   * Ambient occlusion technique. Default NONE.
   */
  void SetAmbientOcclusionMethod(int method);
  vtkGetMacro(AmbientOcclusionMethod, int);
  ///@}

  ///@{
  /**
   * Parameters forwarded to vtkHybridAmbientOcclusionPass (see its documentation).
   */
  void SetAmbientOcclusionRadius(double radius);
  void SetAmbientOcclusionRays(int rays);
  void SetAmbientOcclusionSteps(int steps);
  void SetAmbientOcclusionVoxelResolution(int resolution);
  void SetAmbientOcclusionRegionMode(int mode);
  void SetAmbientOcclusionExplicitRegion(double xmin,
    double xmax,
    double ymin,
    double ymax,
    double zmin,
    double zmax);
  void SetAmbientOcclusionIntensity(double intensity);
  void SetAmbientOcclusionFalloff(int falloff);
  void SetAmbientOcclusionFilterSize(int size);
  void SetAmbientOcclusionOnly(bool only);
  void SetAmbientOcclusionScale(int scale);
  void SetAmbientOcclusionRefinement(bool on);
  void SetAmbientOcclusionRefinementContrast(double contrast);
  void SetAmbientOcclusionIncrementalVoxelization(bool on);
  void SetAmbientOcclusionCellsPerRadius(double cells);
  void SetAmbientOcclusionVoxelizationAxes(int axes);
  ///@}

  ///@{
  /**
   * Frames averaged into a still (progressive accumulation, see
   * vtkAmbientOcclusionPassBase::SetAccumulation). A still render (not an interactive one)
   * renders the view this many times, each frame re-jittered and added to the mean while
   * nothing changes, so that a screenshot shows the converged still; renders of a still
   * whose mean is complete skip the occlusion stage. The count is the same on every rank, so
   * every rank renders (and IceT composites) the same number of frames. Range [1, 1024].
   * Default 1 (a still costs one frame, as before).
   */
  void SetAmbientOcclusionAccumulatedFrames(int frames);
  vtkGetMacro(AmbientOcclusionAccumulatedFrames, int);
  ///@}

  ///@{
  /**
   * Combine the voxel grids across ranks (default on). Off: each rank sees only its own
   * occluders (for comparison and tests).
   */
  void SetAmbientOcclusionParallelReduction(bool on);
  vtkGetMacro(AmbientOcclusionParallelReduction, bool);
  ///@}

  /**
   * The pass (for inspection: timings, voxelization count) and the reducer (reduction timings).
   */
  vtkHybridAmbientOcclusionPass* GetHybridAmbientOcclusionPass();
  vtkPVAOParallelReducer* GetParallelReducer();

  /**
   * Figures of this rank after the last render, for pvpython (information property
   * AmbientOcclusionStatistics, read from rank 0): voxelization count, grid reductions, grid
   * bytes, read-back ms, wait ms, AllReduce ms, upload ms, voxelization GPU ms (previous
   * frame), whether the last frame had occlusion, grid dimensions x, y, z, bytes sent into
   * the AllReduces (the sparse reduction moves only occupied chunks), the frames in the
   * accumulated mean the last render showed, the share of the pixels refined at full
   * resolution (vtkHybridAmbientOcclusionPass::GetRefinedFraction), the voxelizations that
   * rendered only the props that moved over the kept base of the others
   * (vtkHybridAmbientOcclusionPass::GetIncrementalVoxelizationCount).
   */
  vtkGetVectorMacro(AmbientOcclusionStatistics, double, 16);

protected:
  vtkPVAmbientOcclusionView();
  ~vtkPVAmbientOcclusionView() override;

  /**
   * Every rank must run the pass on every frame (its reductions are collective): ask IceT to
   * call each rank's render even when its local geometry is out of view. A still render
   * renders AmbientOcclusionAccumulatedFrames frames.
   */
  void Render(bool interactive, bool skip_rendering) override;

  /// Install the pass for the current method (or ParaView's default pass).
  void UpdateAmbientOcclusionPass();

  int AmbientOcclusionMethod = NONE;
  bool AmbientOcclusionParallelReduction = true;
  int AmbientOcclusionAccumulatedFrames = 1;
  double AmbientOcclusionStatistics[16] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  vtkNew<vtkHybridAmbientOcclusionPass> HybridPass;
  vtkNew<vtkRenderStepsPass> HybridDelegate;
  vtkNew<vtkPVAOParallelReducer> Reducer;

private:
  vtkPVAmbientOcclusionView(const vtkPVAmbientOcclusionView&) = delete;
  void operator=(const vtkPVAmbientOcclusionView&) = delete;
};

#endif
