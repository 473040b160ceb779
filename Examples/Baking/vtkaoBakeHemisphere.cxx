#include "vtkaoBakeHemisphere.h"

#include "vtkaoScene.h"

#include "vtkAOHemisphereBaker.h"
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace
{
// The first visible opaque actor's polydata (what the other bake methods bake).
vtkPolyData* FirstPolyData(vtkRenderer* renderer)
{
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || !actor->GetVisibility())
    {
      continue;
    }
    actor->GetBounds(); // updates the mapper's input
    auto* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (data && actor->HasOpaqueGeometry())
    {
      return data;
    }
  }
  return nullptr;
}

// "baking [####    ] 50%" on stderr, redrawn when the percentage changes.
void ShowProgress(vtkObject* caller, unsigned long, void* client, void*)
{
  auto* shown = static_cast<int*>(client);
  const double fraction = static_cast<vtkAlgorithm*>(caller)->GetProgress();
  const int percent = static_cast<int>(100.0 * std::min(1.0, std::max(0.0, fraction)));
  if (percent != *shown)
  {
    *shown = percent;
    const int width = 40, filled = percent * width / 100;
    std::cerr << "\rbaking [" << std::string(filled, '#') << std::string(width - filled, ' ')
              << "] " << percent << "%" << std::flush;
  }
}
}

namespace vtkao
{
void BakeHemisphereFile(const std::string& input,
  const std::string& output,
  const HemisphereBakeOptions& options,
  std::ostream& report)
{
  vtkNew<vtkRenderer> scene;
  AddFile(scene, input);
  vtkPolyData* mesh = FirstPolyData(scene);
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
  int shown = -1;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(ShowProgress);
  progress->SetClientData(&shown);
  baker->AddObserver(vtkCommand::ProgressEvent, progress);
  baker->Update();
  if (shown >= 0)
  {
    std::cerr << "\n";
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
