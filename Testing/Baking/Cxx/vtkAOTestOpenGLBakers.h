// What every test of a vtkAOOpenGLBaker checks beyond its own method: the window contract.
#ifndef vtkAOTestOpenGLBakers_h
#define vtkAOTestOpenGLBakers_h

#include "vtkAOTestChecks.h"
#include "vtkAOTestSurfaces.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

namespace vtkAOTest
{
/// @p baker, set up as the one that baked @p expected, draws in a 64 x 48 window of the
/// caller's: it bakes the same A (max |difference| 1e-6), leaves the window's size alone, and
/// the window still renders afterwards.
template<class Baker>
void CheckUserWindow(Baker* baker, vtkDataArray* expected)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 48);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  baker->SetRenderWindow(window);
  baker->Update();
  CheckNear(Compare(PointArray(baker), expected).Maximum, 0.0, 1e-6, "user window: same A");
  Check(window->GetSize()[0] == 64 && window->GetSize()[1] == 48, "user window: size kept");
  window->Render(); // still renders after the baker used its context
}
}

#endif
