// The built-in scene of the baking examples (vtkaoRelight), which the baking tests measure the
// bakers on too (Testing/Baking/Cxx).
#ifndef vtkaoBakingScene_h
#define vtkaoBakingScene_h

#include "vtkAppendPolyData.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

namespace vtkao
{
/// A floor [-3, 3]^2 at y = 0 (floorResolution^2 quads, normal +y), a ball of radius
/// @p ballRadius centred 1 above the floor's middle (2 ballResolution x ballResolution facets)
/// and a box [1.25, 2.25] x [-0.3, 1.5] x [-0.95, 1.05] sunk into the floor beside it
/// (triangulated, its split normals kept), in one polydata: contact shadows, creases, open and
/// occluded vertices.
inline vtkSmartPointer<vtkPolyData> FloorBallAndSunkBox(int floorResolution,
  double ballRadius,
  int ballResolution)
{
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-3, 0, -3);
  floor->SetPoint1(-3, 0, 3);
  floor->SetPoint2(3, 0, -3);
  floor->SetResolution(floorResolution, floorResolution);
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0, 1, 0);
  ball->SetRadius(ballRadius);
  ball->SetThetaResolution(2 * ballResolution);
  ball->SetPhiResolution(ballResolution);
  vtkNew<vtkCubeSource> box;
  box->SetBounds(1.25, 2.25, -0.3, 1.5, -0.95, 1.05);
  vtkNew<vtkTriangleFilter> boxTriangles;
  boxTriangles->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputConnection(floor->GetOutputPort());
  scene->AddInputConnection(ball->GetOutputPort());
  scene->AddInputConnection(boxTriangles->GetOutputPort());
  scene->Update();
  return scene->GetOutput();
}
}

#endif
