// Incremental voxelization: while one actor moves, only it is voxelized, over a kept base of
// the actors that do not move, and the grid is the one a voxelization of every actor gives,
// bit for bit. The occlusion of the still actors stays, the moving one's follows it, an actor
// that stops moving joins the base, and the base is freed when nothing moves any more.
#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOTestUtilities.h"

namespace
{
// The ground seen from above, 400 x 400 px, 45.8 px per unit: pixel (200 + 45.8 x, 200 - 45.8 z).
struct Patch
{
  double X, Z;
  int Box[4];
  Patch(double x, double z)
    : X(x)
    , Z(z)
  {
    const int px = static_cast<int>(std::lround(200 + 45.8 * x));
    const int py = static_cast<int>(std::lround(200 - 45.8 * z));
    Box[0] = px - 4;
    Box[1] = py - 4;
    Box[2] = px + 4;
    Box[3] = py + 4;
  }
};
}

int TestHAOIncrementalVoxelization(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(400, 400, ren);
  AddGround(ren, 5);
  // A unit cube at (0, 0.5, -2.5) that stays (until the end), and the mover, a unit cube from
  // (-2, 0.5, 1.5) to (2, 0.5, 1.5) in 8 frames.
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0, 0.5, -2.5);
  vtkSmartPointer<vtkActor> box = AddActor(ren, cube);
  vtkNew<vtkCubeSource> moverCube;
  moverCube->SetCenter(-2, 0.5, 1.5);
  vtkSmartPointer<vtkActor> mover = AddActor(ren, moverCube);
  TopView(ren, 0, 0, 12);
  ren->GetActiveCamera()->SetClippingRange(0.1, 20);
  auto hao = InstallHAO(ren, 2.0);
  hao->AccumulationOff();
  vtkAOBitmaskVoxelizer* voxelizer = hao->GetVoxelizer();

  const Patch besideStart(-2, 2.3); // 0.3 beyond the mover's face at its start
  const Patch besideEnd(2, 2.3);   // 0.3 beyond it at its end
  const Patch besideBox(0, -1.7);    // 0.3 beyond the cube
  const Patch besideBoxEnd(1, -1.7); // the cube moved by 1 in x at the end; far from its start
  auto report = [&](const char* when)
  {
    const double a = MeanAO(hao, besideStart.Box), b = MeanAO(hao, besideEnd.Box),
                 c = MeanAO(hao, besideBox.Box);
    std::printf("%s: A beside the start %.3f, the end %.3f, the cube %.3f (%d voxelizations, %d "
                "incremental, %d props in the last)\n",
      when, a, b, c, hao->GetVoxelizationCount(), hao->GetIncrementalVoxelizationCount(),
      hao->GetNumberOfVoxelizedProps());
  };

  win->Render();
  report("first frame");
  Check(hao->GetIncrementalVoxelizationCount() == 0 && hao->GetNumberOfVoxelizedProps() == 3,
    "the first voxelization renders every actor");
  const double openBefore = MeanAO(hao, besideEnd.Box);
  Check(MeanAO(hao, besideStart.Box) >= 0.0 && MeanAO(hao, besideStart.Box) < openBefore - 0.1,
    "occlusion beside the mover");
  Check(MeanAO(hao, besideBox.Box) >= 0.0 && MeanAO(hao, besideBox.Box) < openBefore - 0.1,
    "occlusion beside the cube");
  const long long singleGrid = voxelizer->GetGraphicsMemorySize();

  // The mover moves: each frame voxelizes it alone over the base (ground, still cube).
  const int before = hao->GetVoxelizationCount();
  for (int i = 1; i <= 8; ++i)
  {
    mover->SetPosition(0.5 * i, 0, 0);
    win->Render();
    Check(hao->GetNumberOfVoxelizedProps() == 1 && voxelizer->GetNumberOfRenderedProps() == 1,
      "a moving frame voxelizes the moving actor only");
  }
  report("mover moved");
  Check(hao->GetVoxelizationCount() == before + 8, "every moving frame re-voxelizes");
  Check(hao->GetIncrementalVoxelizationCount() == 8, "and each of them incrementally");
  Check(voxelizer->HasBase() && voxelizer->GetGraphicsMemorySize() > singleGrid,
    "the base is kept beside the grid");
  const double openStart = MeanAO(hao, besideStart.Box);
  const double darkEnd = MeanAO(hao, besideEnd.Box);
  const double darkBox = MeanAO(hao, besideBox.Box);
  Check(openStart > 0.95, "the mover's old place is open again");
  Check(darkEnd >= 0.0 && darkEnd < openStart - 0.1, "the occlusion moved with the mover");
  Check(darkBox >= 0.0 && darkBox < openStart - 0.1, "the cube (in the base) still occludes");
  std::vector<unsigned int> incremental;
  Check(voxelizer->DownloadGrid(incremental), "downloading the incremental grid");

  // The same frame voxelized as a whole: the same grid, bit for bit; the base is freed.
  hao->IncrementalVoxelizationOff();
  mover->GetMapper()->Modified();
  win->Render();
  Check(hao->GetNumberOfVoxelizedProps() == 3 && hao->GetIncrementalVoxelizationCount() == 8,
    "with IncrementalVoxelization off every actor is voxelized");
  std::vector<unsigned int> full;
  Check(voxelizer->DownloadGrid(full), "downloading the full grid");
  size_t differing = 0, occupied = 0;
  for (size_t i = 0; i < std::min(full.size(), incremental.size()); ++i)
  {
    differing += full[i] != incremental[i] ? 1 : 0;
    occupied += full[i] != 0 ? 1 : 0;
  }
  std::printf("grid words: %zu, occupied %zu, differing %zu\n", full.size(), occupied, differing);
  Check(!full.empty() && full.size() == incremental.size() && differing == 0 && occupied > 0,
    "the incremental grid is the full grid, bit for bit");
  Check(!voxelizer->HasBase() && voxelizer->GetGraphicsMemorySize() == singleGrid,
    "without incremental voxelization no base is kept");

  // The mover stops: after 16 unchanged frames it is in the base, which nothing needs any
  // more (freed); then the cube moves and is voxelized alone over ground and mover.
  hao->IncrementalVoxelizationOn();
  for (int i = 0; i < 16; ++i)
  {
    win->Render();
  }
  Check(!voxelizer->HasBase(), "no base while nothing moves");
  box->SetPosition(1, 0, 0);
  win->Render();
  report("cube moved");
  Check(hao->GetNumberOfVoxelizedProps() == 1 && hao->GetIncrementalVoxelizationCount() == 9,
    "the cube is voxelized alone once the mover stopped");
  Check(MeanAO(hao, besideEnd.Box) >= 0.0 && MeanAO(hao, besideEnd.Box) < openStart - 0.1,
    "the mover (now in the base) still occludes");
  const double boxEnd = MeanAO(hao, besideBoxEnd.Box);
  Check(boxEnd >= 0.0 && boxEnd < openStart - 0.1, "the cube's occlusion moved with it");
  Check(MeanAO(hao, besideStart.Box) > 0.95, "and nothing is left where the mover started");

  // Removing an actor re-voxelizes; no crash, and its occlusion is gone.
  ren->RemoveActor(mover);
  win->Render();
  Check(MeanAO(hao, besideEnd.Box) > 0.95, "a removed actor occludes nothing");

  ren->ReleaseGraphicsResources(win);
  Check(voxelizer->GetGraphicsMemorySize() == 0, "ReleaseGraphicsResources frees the base");
  return Result();
}
