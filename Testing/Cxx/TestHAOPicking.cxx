// Picking with the pass set: vtkHardwareSelector, vtkPropPicker and vtkCellPicker return the
// prop and cell under a pixel, and rendering afterwards gives the same occlusion as before.
#include "vtkAOTestUtilities.h"
#include "vtkCellPicker.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkPropPicker.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

namespace
{
struct Hit
{
  vtkProp* Prop = nullptr;
  vtkIdType Cell = -1;
};

Hit HardwareSelect(vtkRenderer* ren, int x, int y)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(ren);
  selector->SetArea(x, y, x, y);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  Hit hit;
  if (selection && selection->GetNumberOfNodes() > 0)
  {
    vtkSelectionNode* node = selection->GetNode(0);
    hit.Prop = vtkProp::SafeDownCast(node->GetProperties()->Get(vtkSelectionNode::PROP()));
    vtkIdTypeArray* ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    if (ids && ids->GetNumberOfTuples() > 0)
    {
      hit.Cell = ids->GetValue(0);
    }
  }
  return hit;
}
}

int TestHAOPicking(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(250, 250, ren);
  vtkSmartPointer<vtkActor> ground = AddGround(ren, 5);
  vtkSmartPointer<vtkActor> sphere = AddSphere(ren, 0, 0);
  vtkNew<vtkCubeSource> cubeSource;
  cubeSource->SetBounds(2, 3, 0, 1, 2, 3);
  vtkSmartPointer<vtkActor> cube = AddActor(ren, cubeSource);
  TopView(ren, 0, 0, 12);
  auto hao = InstallHAO(ren, 2.0);
  // The render after picking is compared with the one before, exactly: single frames (with
  // accumulation the second would be the mean of two differently jittered frames).
  hao->AccumulationOff();
  win->Render();

  // 28.6 pixels per unit: the origin at (125, 125), +x right, +z down in the image.
  const int ring[4] = { 159, 120, 165, 130 }; // ground 1.2-1.4 right of the sphere's centre
  const int open[4] = { 10, 220, 30, 240 };
  const double ringBefore = MeanAO(hao, ring);
  const double openBefore = MeanAO(hao, open);
  const int voxelizations = hao->GetVoxelizationCount();
  std::printf("before picking: A ring %.4f, open %.4f\n", ringBefore, openBefore);
  // The exact A there (the sphere alone, Wendland falloff, R = 2, integrated numerically over
  // the box) is 0.923: half of that darkening is asked for.
  Check(ringBefore >= 0.0 && ringBefore < openBefore - 0.04, "the scene has contact occlusion");

  // Pixels: on the sphere (off its pole), on open ground, on the cube's top (x 2.5, z 2.5,
  // seen from 11 units away: 125 + 2.5 * 28.6 * 12 / 11 = 203).
  const int onSphere[2] = { 130, 133 };
  const int onGround[2] = { 20, 230 };
  const int onCube[2] = { 203, 47 };

  // Software ray casting: the reference cell.
  vtkNew<vtkCellPicker> cellPicker;
  cellPicker->SetTolerance(0.0);
  Check(cellPicker->Pick(onSphere[0], onSphere[1], 0, ren) && cellPicker->GetActor() == sphere,
    "vtkCellPicker: the sphere pixel picks the sphere");
  const vtkIdType sphereCell = cellPicker->GetCellId();
  Check(cellPicker->Pick(onCube[0], onCube[1], 0, ren) && cellPicker->GetActor() == cube,
    "vtkCellPicker: the cube pixel picks the cube");
  const vtkIdType cubeCell = cellPicker->GetCellId();

  // Hardware selection with the pass set.
  const Hit hs = HardwareSelect(ren, onSphere[0], onSphere[1]);
  const Hit hg = HardwareSelect(ren, onGround[0], onGround[1]);
  const Hit hc = HardwareSelect(ren, onCube[0], onCube[1]);
  std::printf("hardware selector: sphere cell %lld (cell picker %lld), cube cell %lld (cell "
              "picker %lld), ground cell %lld\n",
    static_cast<long long>(hs.Cell),
    static_cast<long long>(sphereCell),
    static_cast<long long>(hc.Cell),
    static_cast<long long>(cubeCell),
    static_cast<long long>(hg.Cell));
  Check(hs.Prop == sphere, "vtkHardwareSelector: the sphere pixel selects the sphere");
  Check(hs.Cell >= 0 && hs.Cell == sphereCell, "vtkHardwareSelector: the sphere cell matches");
  Check(hg.Prop == ground && hg.Cell == 0,
    "vtkHardwareSelector: the ground pixel selects cell 0 of the ground");
  Check(hc.Prop == cube && hc.Cell >= 0 && hc.Cell == cubeCell,
    "vtkHardwareSelector: the cube pixel selects the cube's top cell");

  // vtkPropPicker (hardware picking in VTK 9.1).
  vtkNew<vtkPropPicker> propPicker;
  propPicker->Pick(onSphere[0], onSphere[1], 0, ren);
  Check(propPicker->GetActor() == sphere, "vtkPropPicker: the sphere pixel picks the sphere");
  propPicker->Pick(onGround[0], onGround[1], 0, ren);
  Check(propPicker->GetActor() == ground, "vtkPropPicker: the ground pixel picks the ground");
  propPicker->Pick(onCube[0], onCube[1], 0, ren);
  Check(propPicker->GetActor() == cube, "vtkPropPicker: the cube pixel picks the cube");

  // Rendering afterwards: the same occlusion, no new voxelization.
  win->Render();
  const double ringAfter = MeanAO(hao, ring);
  const double openAfter = MeanAO(hao, open);
  std::printf("after picking: A ring %.4f, open %.4f, voxelizations %d -> %d\n",
    ringAfter,
    openAfter,
    voxelizations,
    hao->GetVoxelizationCount());
  Check(hao->GetLastFrameHadOcclusion(), "the pass applies occlusion again after picking");
  Check(std::abs(ringAfter - ringBefore) < 1e-5 && std::abs(openAfter - openBefore) < 1e-5,
    "the occlusion after picking equals the occlusion before");
  Check(hao->GetVoxelizationCount() == voxelizations, "picking does not force a re-voxelization");

  ren->ReleaseGraphicsResources(win);
  return Result();
}
