#include "vtkPVAOParallelReducer.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h" // GL loader (glFinish)

#include <chrono>
#include <vector>

vtkStandardNewMacro(vtkPVAOParallelReducer);

namespace
{
double Milliseconds(std::chrono::steady_clock::time_point a,
  std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double, std::milli>(b - a).count();
}
}

//------------------------------------------------------------------------------
vtkPVAOParallelReducer::vtkPVAOParallelReducer() = default;

//------------------------------------------------------------------------------
vtkPVAOParallelReducer::~vtkPVAOParallelReducer()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkPVAOParallelReducer::SetController(vtkMultiProcessController* controller)
{
  vtkSetObjectBodyMacro(Controller, vtkMultiProcessController, controller);
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkPVAOParallelReducer::GetController()
{
  return this->Controller;
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkPVAOParallelReducer::ActiveController()
{
  vtkMultiProcessController* c =
    this->Controller ? this->Controller : vtkMultiProcessController::GetGlobalController();
  return c && c->GetNumberOfProcesses() > 1 ? c : nullptr;
}

//------------------------------------------------------------------------------
void vtkPVAOParallelReducer::ReduceBounds(double bounds[6])
{
  vtkMultiProcessController* c = this->ActiveController();
  if (!c)
  {
    return;
  }
  const double mins[3] = { bounds[0], bounds[2], bounds[4] };
  const double maxs[3] = { bounds[1], bounds[3], bounds[5] };
  double gmins[3], gmaxs[3];
  c->AllReduce(mins, gmins, 3, vtkCommunicator::MIN_OP);
  c->AllReduce(maxs, gmaxs, 3, vtkCommunicator::MAX_OP);
  for (int i = 0; i < 3; ++i)
  {
    bounds[2 * i] = gmins[i];
    bounds[2 * i + 1] = gmaxs[i];
  }
}

//------------------------------------------------------------------------------
bool vtkPVAOParallelReducer::ReduceAny(bool local)
{
  vtkMultiProcessController* c = this->ActiveController();
  if (!c)
  {
    return local;
  }
  const int mine = local ? 1 : 0;
  int any = 0;
  c->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  return any != 0;
}

//------------------------------------------------------------------------------
bool vtkPVAOParallelReducer::ReduceGrid(vtkAOBitmaskVoxelizer* voxelizer)
{
  vtkMultiProcessController* c = this->ActiveController();
  if (!c)
  {
    return true;
  }
  using clock = std::chrono::steady_clock;
  glFinish(); // time the read-back, not the voxelization still in flight
  const auto t0 = clock::now();
  std::vector<unsigned int> local;
  const bool ok = voxelizer && voxelizer->DownloadGrid(local);
  const auto t1 = clock::now();

  // Every rank must take part; all agree on the size first (a rank whose grid failed
  // contributes -1, and then nobody combines).
  const double size[2] = { ok ? static_cast<double>(local.size()) : -1.0,
    ok ? -static_cast<double>(local.size()) : 1.0 };
  double agreed[2];
  c->AllReduce(size, agreed, 2, vtkCommunicator::MIN_OP);
  if (agreed[0] <= 0.0 || agreed[0] != -agreed[1])
  {
    vtkWarningMacro(<< "Voxel grids differ across ranks or could not be read: ambient "
                       "occlusion uses local occluders only.");
    return false;
  }
  const auto t1b = clock::now(); // after the ranks met: the rest is the transfer itself
  std::vector<unsigned int> global(local.size(), 0u);
  c->AllReduce(local.data(),
    global.data(),
    static_cast<vtkIdType>(local.size()),
    vtkCommunicator::BITWISE_OR_OP);
  const auto t2 = clock::now();
  const bool uploaded = voxelizer->UploadGrid(global);
  glFinish();
  const auto t3 = clock::now();

  this->LastDownloadTime = Milliseconds(t0, t1);
  this->LastSyncTime = Milliseconds(t1, t1b);
  this->LastAllReduceTime = Milliseconds(t1b, t2);
  this->LastUploadTime = Milliseconds(t2, t3);
  this->LastGridBytes = static_cast<double>(local.size()) * sizeof(unsigned int);
  ++this->NumberOfGridReductions;
  if (!uploaded)
  {
    vtkWarningMacro(<< "Could not upload the combined voxel grid.");
  }
  return uploaded;
}

//------------------------------------------------------------------------------
void vtkPVAOParallelReducer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastDownloadTime: " << this->LastDownloadTime << "\n";
  os << indent << "LastSyncTime: " << this->LastSyncTime << "\n";
  os << indent << "LastAllReduceTime: " << this->LastAllReduceTime << "\n";
  os << indent << "LastUploadTime: " << this->LastUploadTime << "\n";
  os << indent << "LastGridBytes: " << this->LastGridBytes << "\n";
  os << indent << "NumberOfGridReductions: " << this->NumberOfGridReductions << "\n";
}
