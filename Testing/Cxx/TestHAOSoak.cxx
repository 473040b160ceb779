// Soak: many frames with everything that changes in a real application. The camera orbits, an
// actor moves every frame (HAO re-voxelizes every frame), the window is resized every
// 500 frames, the method switches every 1000 (none, vtkSSAOPass, HAO), and every 2000 frames
// the renderer's graphics resources are released. Reports the resident memory at intervals
// and counts GL errors; asserts no GL error, occlusion still present at the end, and memory
// flat after the warm-up: growth below max(4 MiB, 1%). The warm-up is the first half of the run
// and at least three cycles of the methods: with three voxelization axes and the refinement's
// targets, the driver's allocations settle only after the third HAO period (a 1200-frame run
// grows to frame 720 and is flat after it).
//
// In the suite it runs a short version (400 frames, intervals scaled down); the full soak:
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/vtkaoCxxTests TestHAOSoak --frames
//   10000 [--csv soak.csv]
#include "vtkAOTestUtilities.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkSSAOPass.h"
#include "vtkAOGL.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <unistd.h>
#include <vector>

namespace
{
// Resident set size in KiB, from /proc/self/statm (Linux); 0 where unavailable.
long ResidentKiB()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  if (!(statm >> pages >> resident))
  {
    return 0;
  }
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}
}

int TestHAOSoak(int argc, char* argv[])
{
  using namespace vtkAOTest;
  int frames = 400;
  const char* csvPath = nullptr;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--frames"))
    {
      frames = std::max(40, std::atoi(argv[i + 1]));
    }
    else if (!std::strcmp(argv[i], "--csv"))
    {
      csvPath = argv[i + 1];
    }
  }
  // The full soak's periods; a short run scales them down so each event still happens.
  const double scale = std::min(1.0, frames / 10000.0);
  const int resizeEvery = std::max(10, static_cast<int>(500 * scale));
  const int methodEvery = std::max(20, static_cast<int>(1000 * scale));
  const int releaseEvery = std::max(40, static_cast<int>(2000 * scale));
  const int reportEvery = std::max(10, frames / 40);

  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(160, 120, ren);
  AddGround(ren, 5);
  vtkSmartPointer<vtkActor> sphere = AddSphere(ren, 0, 0);
  TopView(ren, 0, 0, 12);
  ren->GetActiveCamera()->Elevation(-30);
  ren->ResetCameraClippingRange();

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkHybridAmbientOcclusionPass> hao;
  hao->SetDelegatePass(basic);
  hao->SetRadius(2.0);
  vtkNew<vtkRenderStepsPass> basicSSAO;
  vtkNew<vtkSSAOPass> ssao;
  ssao->SetDelegatePass(basicSSAO);
  ssao->SetRadius(2.0);
  vtkRenderPass* methods[3] = { nullptr, ssao, hao };
  const char* names[3] = { "none", "ssao", "hao" };

  std::ofstream csv;
  if (csvPath)
  {
    csv.open(csvPath);
    csv << "frame,resident_kib,gl_errors,method\n";
  }
  const int sizes[3][2] = { { 160, 120 }, { 200, 150 }, { 120, 160 } };
  int glErrors = 0;
  long warmResident = 0, peakAfterWarm = 0;
  // Every event has happened at least twice by then; driver and allocator caches settle. A
  // run too short for that before its last 40 frames (some runs of 319 to 390 frames with the
  // scaled periods, every shorter one: scripts/run-valgrind.sh runs 60) still checks
  // GL errors and the occlusion, but not the resident memory: its "warm-up" ends before the
  // caches have settled (60 frames: +2.7 %, 4.3 MiB, with nothing leaked).
  const int settled = std::max({ frames / 2, 2 * releaseEvery, 9 * methodEvery });
  const int warmUp = std::min(frames - 40, settled);
  const bool warmedUp = warmUp >= settled;
  int method = 2;
  ren->SetPass(methods[method]);
  for (int frame = 0; frame < frames; ++frame)
  {
    if (frame > 0 && frame % methodEvery == 0)
    {
      method = (method + 1) % 3;
      ren->SetPass(methods[method]);
    }
    if (frame > 0 && frame % resizeEvery == 0)
    {
      const int* size = sizes[(frame / resizeEvery) % 3];
      win->SetSize(size[0], size[1]);
    }
    if (frame > 0 && frame % releaseEvery == 0)
    {
      ren->ReleaseGraphicsResources(win);
    }
    ren->GetActiveCamera()->Azimuth(1.0);
    sphere->SetPosition(0.5 * std::sin(frame * 0.05), 0, 0.5 * std::cos(frame * 0.05));
    win->Render();
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    {
      ++glErrors;
    }
    const long resident = ResidentKiB();
    if (frame == warmUp)
    {
      warmResident = resident;
    }
    if (frame > warmUp)
    {
      peakAfterWarm = std::max(peakAfterWarm, resident);
    }
    if (frame % reportEvery == 0 || frame == frames - 1)
    {
      std::printf("frame %d: resident %ld KiB, GL errors %d, method %s\n",
        frame,
        resident,
        glErrors,
        names[method]);
      if (csv)
      {
        csv << frame << "," << resident << "," << glErrors << "," << names[method] << "\n";
      }
    }
  }

  // The last frames ran with HAO or another method: end on HAO to check it still works.
  ren->SetPass(hao);
  win->SetSize(160, 120);
  sphere->SetPosition(0, 0, 0);
  TopView(ren, 0, 0, 12); // 13.7 pixels per unit, the sphere in the middle
  win->Render();
  const double ring = MeanAO(hao, 94, 57, 99, 63); // 1.1 .. 1.4 units from the centre
  const double open = MeanAO(hao, 3, 3, 13, 13);
  std::printf("after the soak: A beside the sphere %.3f, open ground %.3f\n", ring, open);

  Check(glErrors == 0, "no GL error in " + std::to_string(frames) + " frames");
  Check(
    ring >= 0.0 && ring < open - 0.05 && open > 0.95, "HAO still gives occlusion after the soak");
  const double growth = warmResident > 0 ? double(peakAfterWarm - warmResident) / warmResident : 0;
  std::printf("resident after warm-up %ld KiB, peak after %ld KiB (growth %.2f%%)\n",
    warmResident,
    peakAfterWarm,
    100.0 * growth);
  // Allocator and driver caches move in steps of about 1 MiB (measured: +1.7 MiB over the
  // second half of a 10,000-frame soak, flat for thousands of frames in between); a leak of
  // one G-buffer-sized texture per frame would grow by tens of MiB over the second half.
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed memory in quarantine: the resident set grows by design.
  std::printf("resident-memory check skipped under AddressSanitizer\n");
#else
  if (!warmedUp)
  {
    std::printf("resident-memory check skipped: the warm-up needs %d frames and %d leave only "
                "%d before the last 40\n",
      settled,
      frames,
      frames - 40);
  }
  else
  {
    Check(peakAfterWarm - warmResident < std::max(4096L, warmResident / 100),
      "resident memory flat after the warm-up");
  }
#endif
  // Every pass that rendered holds GL objects: release each, not only the current one
  // (vtkSSAOPass frees its textures only in ReleaseGraphicsResources).
  ren->ReleaseGraphicsResources(win);
  ssao->ReleaseGraphicsResources(win);
  hao->ReleaseGraphicsResources(win);
  return Result();
}
