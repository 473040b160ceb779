#include "vtkaoBakeHemisphere.h"
#include "vtkaoReference.h"

#include "vtkAOHemisphereBaker.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <iostream>

namespace vtkao
{
void BakeHemisphereFile(const std::string& input,
  const std::string& output,
  const HemisphereBakeOptions& options,
  std::ostream& report)
{
  vtkNew<vtkRenderer> scene;
  vtkPolyData* mesh = MeshToBake(scene, input, output); // as by the other methods

  vtkNew<vtkAOHemisphereBaker> baker;
  baker->SetInputData(mesh);
  baker->SetRadius(options.Radius);
  baker->SetBias(options.Bias);
  baker->SetSpread(options.Spread);
  baker->SetResolution(options.Resolution);
  BakeAndWrite(baker, output, "the hemisphere baker failed (see the message above)");
  const int resolution = baker->GetResolution() + baker->GetResolution() % 2;
  report << "baked " << baker->GetOutput()->GetNumberOfPoints() << " points (hemisphere), "
         << resolution << "^2 hemicube faces, " << baker->GetNumberOfTriangles()
         << " triangles, radius ";
  if (options.Radius > 0)
  {
    report << options.Radius;
  }
  else
  {
    report << "infinity";
  }
  report << ", bias " << baker->GetEffectiveBias() << ": " << baker->GetTotalTime() << " s, "
         << baker->GetNumberOfBatches() << " batch(es) of " << baker->GetEffectiveBatchSize()
         << " = " << baker->GetVerticesPerSecond() << " vertices/s\nwrote " << output << "\n";
}
}
