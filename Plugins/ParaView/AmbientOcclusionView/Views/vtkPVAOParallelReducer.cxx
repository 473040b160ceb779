#include "vtkPVAOParallelReducer.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h" // GL loader (glFinish)

#include <algorithm>
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

// Words per chunk of the sparse reduction: 16 voxel columns of 128 cells (256 bytes).
constexpr size_t ChunkWords = 64;

// OR of @p local over the ranks into @p global, moving only the chunks that some rank
// occupies: first the OR of one bit per chunk (1 / 2048 of the grid), then the OR of the
// occupied chunks, packed. Returns the bytes this rank contributed to the two AllReduces.
double SparseOr(vtkMultiProcessController* c,
  const std::vector<unsigned int>& local,
  std::vector<unsigned int>& global)
{
  const size_t words = local.size();
  const size_t chunks = (words + ChunkWords - 1) / ChunkWords;
  std::vector<unsigned char> mine((chunks + 7) / 8, 0), any(mine.size(), 0);
  for (size_t k = 0; k < chunks; ++k)
  {
    const size_t end = std::min(words, (k + 1) * ChunkWords);
    for (size_t w = k * ChunkWords; w < end; ++w)
    {
      if (local[w] != 0u)
      {
        mine[k / 8] |= static_cast<unsigned char>(1u << (k % 8));
        break;
      }
    }
  }
  c->AllReduce(
    mine.data(), any.data(), static_cast<vtkIdType>(mine.size()), vtkCommunicator::BITWISE_OR_OP);
  auto occupied = [&any](size_t k) { return ((any[k / 8] >> (k % 8)) & 1u) != 0u; };
  std::vector<unsigned int> packed, reduced;
  for (size_t k = 0; k < chunks; ++k)
  {
    if (occupied(k))
    {
      const size_t end = std::min(words, (k + 1) * ChunkWords);
      packed.insert(packed.end(), local.begin() + k * ChunkWords, local.begin() + end);
    }
  }
  reduced.resize(packed.size(), 0u);
  if (!packed.empty())
  {
    c->AllReduce(packed.data(),
      reduced.data(),
      static_cast<vtkIdType>(packed.size()),
      vtkCommunicator::BITWISE_OR_OP);
  }
  global.assign(words, 0u);
  size_t next = 0;
  for (size_t k = 0; k < chunks; ++k)
  {
    if (occupied(k))
    {
      const size_t end = std::min(words, (k + 1) * ChunkWords);
      std::copy(reduced.begin() + next,
        reduced.begin() + next + (end - k * ChunkWords),
        global.begin() + k * ChunkWords);
      next += end - k * ChunkWords;
    }
  }
  return static_cast<double>(mine.size() + packed.size() * sizeof(unsigned int));
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
  std::vector<unsigned int> global;
  const double messageBytes = SparseOr(c, local, global);
  const auto t2 = clock::now();
  const bool uploaded = voxelizer->UploadGrid(global);
  glFinish();
  const auto t3 = clock::now();

  this->LastDownloadTime = Milliseconds(t0, t1);
  this->LastSyncTime = Milliseconds(t1, t1b);
  this->LastAllReduceTime = Milliseconds(t1b, t2);
  this->LastUploadTime = Milliseconds(t2, t3);
  this->LastGridBytes = static_cast<double>(local.size()) * sizeof(unsigned int);
  this->LastMessageBytes = messageBytes;
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
  os << indent << "LastMessageBytes: " << this->LastMessageBytes << "\n";
  os << indent << "NumberOfGridReductions: " << this->NumberOfGridReductions << "\n";
}
