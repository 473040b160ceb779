#include "vtkaoBakeHemisphere.h"
#include "vtkaoProgram.h"

#include "vtkaoScene.h"

#include "vtkAOHemisphereBaker.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace vtkao
{
void BakeHemisphereFile(const std::string& input,
  const std::string& output,
  const HemisphereBakeOptions& options,
  std::ostream& report)
{
  vtkNew<vtkRenderer> scene;
  AddFile(scene, input);
  const auto actors = PolyDataActors(scene); // the first one is baked, as by the other methods
  vtkPolyData* mesh = actors.empty() ? nullptr : actors.front().second;
  if (!mesh)
  {
    throw std::runtime_error("'" + input + "' contains no polygons");
  }
  // Fail on an unwritable destination before spending the time to bake.
  const std::string temporary = output + ".partial.vtp";
  {
    std::ofstream probe(temporary, std::ios::binary);
    if (!probe.good())
    {
      throw std::runtime_error("cannot write '" + output + "'");
    }
  }
  std::remove(temporary.c_str());

  vtkNew<vtkAOHemisphereBaker> baker;
  baker->SetInputData(mesh);
  baker->SetRadius(options.Radius);
  baker->SetBias(options.Bias);
  baker->SetSpread(options.Spread);
  baker->SetResolution(options.Resolution);
  {
    ProgressBar bar("baking");
    bar.Watch(baker);
    baker->Update();
  }
  if (!baker->GetOutput()->GetPointData()->GetArray(baker->GetArrayName().c_str()))
  {
    throw std::runtime_error("the hemisphere baker failed (see the message above)");
  }

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(baker->GetOutput());
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToBinary();
  if (!writer->Write() || std::rename(temporary.c_str(), output.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + output + "'");
  }
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
