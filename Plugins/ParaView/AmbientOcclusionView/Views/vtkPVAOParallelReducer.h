/**
 * @class   vtkPVAOParallelReducer
 * @brief   vtkAOParallelReducer over the ranks of a vtkMultiProcessController (MPI in
 *          pvserver/pvbatch): min/max of the bounds, OR of the decision, bitwise OR of the
 *          voxel grid (read back from its texture, AllReduce, uploaded again).
 *
 * With one process (or no controller) every call is the identity. Timings of the last grid
 * reduction are kept for benchmarks: read-back, AllReduce and upload, wall-clock ms.
 */
#ifndef vtkPVAOParallelReducer_h
#define vtkPVAOParallelReducer_h

#include "vtkAOParallelReducer.h"
#include "vtkaoParaViewViewsModule.h" // For export macro

class vtkMultiProcessController;

class VTKAOPARAVIEWVIEWS_EXPORT vtkPVAOParallelReducer : public vtkAOParallelReducer
{
public:
  static vtkPVAOParallelReducer* New();
  vtkTypeMacro(vtkPVAOParallelReducer, vtkAOParallelReducer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The controller whose ranks are combined. Default: the global controller at the time of
   * the call (vtkMultiProcessController::GetGlobalController()).
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  void ReduceBounds(double bounds[6]) override;
  bool ReduceAny(bool local) override;
  bool ReduceGrid(vtkAOBitmaskVoxelizer* voxelizer) override;

  ///@{
  /**
   * The last grid reduction: milliseconds spent reading the grid back (after a glFinish),
   * waiting for the other ranks (agreeing on the size), in the AllReduces themselves, and
   * uploading it; the grid's size in bytes; the bytes this rank sent into the AllReduces
   * (only the chunks of 16 voxel columns that some rank occupies travel, after one bit per
   * chunk); number of reductions so far.
   */
  vtkGetMacro(LastDownloadTime, double);
  vtkGetMacro(LastSyncTime, double);
  vtkGetMacro(LastAllReduceTime, double);
  vtkGetMacro(LastUploadTime, double);
  vtkGetMacro(LastGridBytes, double);
  vtkGetMacro(LastMessageBytes, double);
  vtkGetMacro(NumberOfGridReductions, int);
  ///@}

protected:
  vtkPVAOParallelReducer();
  ~vtkPVAOParallelReducer() override;

  /// The controller if it has more than one process, else nullptr.
  vtkMultiProcessController* ActiveController();

  vtkMultiProcessController* Controller = nullptr;
  double LastDownloadTime = 0.0;
  double LastSyncTime = 0.0;
  double LastAllReduceTime = 0.0;
  double LastUploadTime = 0.0;
  double LastGridBytes = 0.0;
  double LastMessageBytes = 0.0;
  int NumberOfGridReductions = 0;

private:
  vtkPVAOParallelReducer(const vtkPVAOParallelReducer&) = delete;
  void operator=(const vtkPVAOParallelReducer&) = delete;
};

#endif
