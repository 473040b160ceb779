// vtkAOSattlerBaker: the two GPU point tests (STORAGE_BUFFER, the default with OpenGL 4.3, and
// LOGIC_OP) against the CPU test on the same scene, directions and depth maps:
// - each requested variant is the one used (llvmpipe has OpenGL 4.5), AUTOMATIC picks
//   STORAGE_BUFFER;
// - the visibility bits agree: at most 1 in 10^4 differs (the GPU tests in float, the CPU in
//   double; a bit can only differ for a test point within float rounding of a depth-map pixel
//   edge or of the depth threshold; none differs here with llvmpipe), and the RMS difference of
//   A and of the radiance over the vertices is at most 1e-3 (one flipped bit moves a vertex's A
//   by cos / sum of cos, about 0.05 at k = 70, so a maximum would not fit the bit tolerance);
// - more than 4096 points (several rows of the bits texture) and k = 70 (a partial last word);
// - on the fly (nothing stored), the GPU gives the same A as with the matrix stored.
// Prints the time per direction of each.
#include "vtkAOSattlerBaker.h"
#include "vtkAOTestChecks.h"
#include "vtkAOTestSurfaces.h"
#include "vtkaoBakingScene.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using namespace vtkAOTest;

int TestSattlerGPUTest(int, char*[])
{
  // A floor (81 x 81 points), a ball of radius 0.5 half a unit above it and a box sunk into it.
  vtkSmartPointer<vtkPolyData> mesh = vtkao::FloorBallAndSunkBox(80, 0.5, 16);
  const vtkIdType n = mesh->GetNumberOfPoints();
  const int k = 70;
  std::vector<double> sky(3 * k);
  const std::vector<double> directions = vtkAOSattlerBaker::MakeDirections(k, 3);
  for (int j = 0; j < k; ++j)
  {
    for (int c = 0; c < 3; ++c)
    {
      sky[3 * j + c] = directions[3 * j + 1] > 0 ? 0.3 + 0.2 * c * directions[3 * j + 1] : 0.1;
    }
  }

  vtkNew<vtkAOSattlerBaker> cpu;
  vtkNew<vtkAOSattlerBaker> logicOp;
  vtkNew<vtkAOSattlerBaker> storage;
  vtkNew<vtkAOSattlerBaker> automatic;
  for (vtkAOSattlerBaker* baker : { cpu.Get(), logicOp.Get(), storage.Get(), automatic.Get() })
  {
    baker->SetInputData(mesh);
    baker->SetNumberOfDirections(k);
    baker->SetResolution(256);
    baker->SetBias(0.01);
    baker->SetSeed(3);
    baker->SetIntensities(sky, 3);
  }
  cpu->SetPointTestToCPU();
  logicOp->SetPointTestToLogicOp();
  storage->SetPointTestToStorageBuffer();
  automatic->StoreVisibilityOff(); // on the fly
  cpu->Update();
  Check(n > 4096, "more than one row of the bits texture: " + std::to_string(n) + " points");
  Check(cpu->GetPointTestUsed() == vtkAOSattlerBaker::POINT_TEST_CPU, "CPU: the CPU test was used");
  vtkDataArray* cpuA = cpu->GetOutput()->GetPointData()->GetArray("AmbientOcclusion");
  vtkDataArray* cpuC = cpu->GetOutput()->GetPointData()->GetArray("Radiance");
  const std::vector<std::uint32_t>& reference = cpu->GetVisibility();
  const double total = static_cast<double>(n) * k;
  long long visible = 0;
  for (std::uint32_t word : reference)
  {
    visible += __builtin_popcount(word);
  }
  Check(visible > total / 10 && visible < 0.9 * total,
    "the scene is not trivially occluded or open: " + std::to_string(visible) + " of " +
      std::to_string(static_cast<long long>(total)) + " bits set");

  for (vtkAOSattlerBaker* gpu : { logicOp.Get(), storage.Get() })
  {
    gpu->Update();
    const std::string name = vtkAOSattlerBaker::GetPointTestAsString(gpu->GetPointTest());
    Check(gpu->GetPointTestUsed() == gpu->GetPointTest(), name + ": that variant was used");
    const std::vector<std::uint32_t>& bits = gpu->GetVisibility();
    Check(!bits.empty() && bits.size() == reference.size(), name + ": n x 3 words stored");
    long long differing = 0;
    for (size_t w = 0; w < std::min(bits.size(), reference.size()); ++w)
    {
      differing += __builtin_popcount(bits[w] ^ reference[w]);
    }
    Check(differing <= total * 1e-4,
      name + ": " + std::to_string(differing) + " bits differ from the CPU test (at most 1e-4)");
    const Difference aoError = Compare(PointArray(gpu), cpuA);
    const Difference lightError = Compare(PointArray(gpu, "Radiance"), cpuC);
    const double ao = aoError.RMS, aoWorst = aoError.Maximum;
    const double light = lightError.RMS, lightWorst = lightError.Maximum;
    std::printf("%s: A: RMS difference %.3g, max %.3g; radiance: RMS %.3g, max %.3g\n",
      name.c_str(),
      ao,
      aoWorst,
      light,
      lightWorst);
    Check(ao <= 1e-3, name + ": A agrees (RMS difference <= 1e-3)");
    Check(light <= 1e-3, name + ": the radiance agrees (RMS difference <= 1e-3)");
  }

  // AUTOMATIC, on the fly (nothing stored): the storage buffer, the same A.
  automatic->Update();
  Check(automatic->GetPointTestUsed() == vtkAOSattlerBaker::POINT_TEST_STORAGE_BUFFER,
    std::string("automatic: used ") +
      vtkAOSattlerBaker::GetPointTestAsString(automatic->GetPointTestUsed()));
  const double flyWorst = Compare(PointArray(automatic), PointArray(storage)).Maximum;
  Check(automatic->GetVisibilityMemory() == 0 && flyWorst == 0.0,
    "on the fly: the same A as with the matrix stored");

  std::printf("%lld points, %d directions, 256^2 depth maps, ms per direction: CPU test %.2f, "
              "LogicOp %.2f, StorageBuffer %.2f\n",
    static_cast<long long>(n),
    k,
    1000.0 * cpu->GetTotalTime() / k,
    1000.0 * logicOp->GetTotalTime() / k,
    1000.0 * storage->GetTotalTime() / k);
  return Result();
}
