/**
 * @class   vtkAOParallelReducer
 * @brief   Hooks that make the ambient-occlusion voxel grid the same on every process of a
 *          distributed (sort-last) render.
 *
 * In ParaView's pvserver/pvbatch each process renders only its own piece of the data before
 * the images are composited: without help, its voxel grid holds only its own occluders, and a
 * surface on one process is not occluded by geometry on another. A reducer set on
 * vtkHybridAmbientOcclusionPass::SetParallelReducer() lets the application combine:
 * - the occluders' bounds (ReduceBounds), so that every process computes the same radius and
 *   voxelizes the same box with the same cells;
 * - the decision to re-voxelize (ReduceAny), so that all processes voxelize together;
 * - the grid itself after voxelization (ReduceGrid): a bitwise OR over the processes.
 *
 * The pass calls these on every frame (bounds, decision) and after every voxelization (grid),
 * in the same order on every process: an implementation may use collective operations. This
 * base class is the single-process identity; the module itself does not depend on MPI.
 * ParaView's plugin (Plugins/ParaView) implements it with vtkMultiProcessController.
 */
#ifndef vtkAOParallelReducer_h
#define vtkAOParallelReducer_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

class vtkAOBitmaskVoxelizer;

class VTKAORENDERING_EXPORT vtkAOParallelReducer : public vtkObject
{
public:
  static vtkAOParallelReducer* New();
  vtkTypeMacro(vtkAOParallelReducer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Replace the local bounds (xmin, xmax, ymin, ymax, zmin, zmax) by their union over all
   * processes. A process without occluders passes an empty box (min > max). Identity here.
   */
  virtual void ReduceBounds(double bounds[6]);

  /**
   * Whether any process passes true. Identity here.
   */
  virtual bool ReduceAny(bool local);

  /**
   * Combine the grid @p voxelizer has just built with the other processes' grids (bitwise
   * OR), e.g. with vtkAOBitmaskVoxelizer::DownloadGrid and UploadGrid. Every process has the
   * same grid dimensions. Returns false if the grid could not be combined. Nothing here.
   */
  virtual bool ReduceGrid(vtkAOBitmaskVoxelizer* voxelizer);

protected:
  vtkAOParallelReducer() = default;
  ~vtkAOParallelReducer() override = default;

private:
  vtkAOParallelReducer(const vtkAOParallelReducer&) = delete;
  void operator=(const vtkAOParallelReducer&) = delete;
};

#endif
