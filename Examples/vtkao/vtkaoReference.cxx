#include "vtkaoReference.h"
#include "vtkaoProgram.h"

#include "vtkaoScene.h"

#include "vtkAOReferenceRenderer.h"
#include "vtkAOSattlerBaker.h"
#include "vtkAOVertexBaker.h"
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace
{
const char* ArrayName = "AmbientOcclusion";

void Configure(vtkAOVertexBaker* baker, const vtkao::RayTracingOptions& options)
{
  baker->SetRadius(options.Radius);
  baker->SetBias(options.Bias);
  baker->SetSpread(options.Spread);
  baker->SetFalloff(options.BinaryFalloff ? vtkAOVertexBaker::BINARY : vtkAOVertexBaker::WENDLAND);
  baker->SetSamples(options.Samples);
  baker->SetArrayName(ArrayName);
}

// Write @p data to @p temporary, then rename it to @p output (no partial file is left).
void WritePolyData(vtkPolyData* data, const std::string& temporary, const std::string& output)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToBinary();
  if (!writer->Write() || std::rename(temporary.c_str(), output.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + output + "'");
  }
}
}

namespace vtkao
{
//------------------------------------------------------------------------------
FloatImage RenderReference(vtkRenderer* renderer,
  int width,
  int height,
  const RayTracingOptions& options,
  std::ostream& report)
{
  vtkNew<vtkAOReferenceRenderer> reference;
  reference->SetWidth(width);
  reference->SetHeight(height);
  reference->SetRadius(options.Radius);
  reference->SetBias(options.Bias);
  reference->SetSpread(options.Spread);
  reference->SetFalloff(
    options.BinaryFalloff ? vtkAOReferenceRenderer::BINARY : vtkAOReferenceRenderer::WENDLAND);
  reference->SetSamples(options.Samples);
  vtkNew<vtkImageData> ao;
  {
    ProgressBar bar("tracing");
    bar.Watch(reference);
    if (!reference->Render(renderer, ao))
    {
      throw std::runtime_error("the reference renderer failed (see the message above)");
    }
  }
  const double seconds = std::max(1e-9, reference->GetTraceTime());
  report << "reference: " << reference->GetNumberOfTriangles() << " triangles, " << options.Samples
         << " samples, radius " << reference->GetEffectiveRadius() << ", bias "
         << reference->GetEffectiveBias() << ": " << reference->GetNumberOfRays() << " rays in "
         << seconds << " s on " << reference->GetNumberOfThreads() << " thread(s) = "
         << reference->GetNumberOfRays() / seconds / reference->GetNumberOfThreads()
         << " rays/s/core\n";
  auto* a = vtkFloatArray::SafeDownCast(ao->GetPointData()->GetScalars());
  FloatImage image;
  image.Width = width;
  image.Height = height;
  image.Channels = 2;
  image.Pixels.assign(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues());
  return image;
}

namespace
{
// The steps of BakeRenderer.

// The actors' surfaces in world space, where they occlude one another.
std::vector<vtkSmartPointer<vtkPolyData>> WorldSurfaces(
  const std::vector<std::pair<vtkActor*, vtkPolyData*>>& actors)
{
  std::vector<vtkSmartPointer<vtkPolyData>> world;
  for (const auto& entry : actors)
  {
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(entry.first->GetMatrix());
    vtkNew<vtkTransformPolyDataFilter> move;
    move->SetInputData(entry.second);
    move->SetTransform(transform);
    move->Update();
    world.emplace_back(move->GetOutput());
  }
  return world;
}

// A baked file (`vtkao bake`, any --method) already carries A: its array, else null.
vtkDataArray* StoredAO(vtkPolyData* surface)
{
  vtkDataArray* existing = surface->GetPointData()->GetArray(ArrayName);
  return existing && existing->GetNumberOfComponents() == 1 &&
      existing->GetNumberOfTuples() == surface->GetNumberOfPoints()
    ? existing
    : nullptr;
}

// A of surface @p i of @p world, the others occluding it; adds its rays and seconds.
vtkSmartPointer<vtkDataArray> BakeSurface(const std::vector<vtkSmartPointer<vtkPolyData>>& world,
  size_t i,
  const RayTracingOptions& options,
  vtkIdType& rays,
  double& seconds)
{
  vtkNew<vtkAOVertexBaker> baker;
  Configure(baker, options);
  baker->SetInputData(world[i]);
  for (size_t j = 0; j < world.size(); ++j)
  {
    if (j != i)
    {
      baker->AddOccluderData(world[j]);
    }
  }
  {
    ProgressBar bar("baking " + std::to_string(i + 1) + "/" + std::to_string(world.size()));
    bar.Watch(baker);
    baker->Update();
  }
  rays += baker->GetNumberOfRays();
  seconds += baker->GetTraceTime();
  return baker->GetOutput()->GetPointData()->GetArray(ArrayName);
}

// The actor shows A (@p values, on its own data and matrix): the actor's colour times A, or A
// itself, unlit (@p aoOnly).
void ShowAO(vtkActor* actor, vtkPolyData* surface, vtkDataArray* values, bool aoOnly)
{
  auto baked = vtkSmartPointer<vtkPolyData>::New();
  baked->ShallowCopy(surface);
  baked->GetPointData()->AddArray(values);
  double base[3];
  actor->GetProperty()->GetColor(base);
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(256);
  table->SetTableRange(0.0, 1.0);
  for (int k = 0; k < 256; ++k)
  {
    const double a = k / 255.0;
    if (aoOnly)
    {
      table->SetTableValue(k, a, a, a, 1.0);
    }
    else
    {
      table->SetTableValue(k, base[0] * a, base[1] * a, base[2] * a, 1.0);
    }
  }
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetInputData(baked);
  mapper->SetLookupTable(table);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(ArrayName);
  mapper->SetColorModeToMapScalars();
  mapper->SetScalarRange(0.0, 1.0);
  mapper->ScalarVisibilityOn();
  mapper->InterpolateScalarsBeforeMappingOn();
  if (aoOnly)
  {
    // Unlit: the pixel is the table colour, i.e. A.
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetAmbient(0.0);
    actor->GetProperty()->SetDiffuse(1.0);
    actor->GetProperty()->SetSpecular(0.0);
  }
}
}

//------------------------------------------------------------------------------
void BakeRenderer(vtkRenderer* renderer,
  const RayTracingOptions& options,
  bool aoOnly,
  std::ostream& report)
{
  const auto actors = PolyDataActors(renderer);
  if (actors.empty())
  {
    throw std::runtime_error("nothing to bake: the scene has no opaque polygonal actors");
  }
  const std::vector<vtkSmartPointer<vtkPolyData>> world = WorldSurfaces(actors);
  vtkIdType rays = 0;
  double seconds = 0;
  size_t stored = 0;
  for (size_t i = 0; i < actors.size(); ++i)
  {
    vtkSmartPointer<vtkDataArray> values = StoredAO(actors[i].second);
    if (values)
    {
      ++stored;
    }
    else
    {
      values = BakeSurface(world, i, options, rays, seconds);
    }
    ShowAO(actors[i].first, actors[i].second, values, aoOnly);
  }
  if (stored)
  {
    report << "used the stored " << ArrayName << " array of " << stored << " actor(s)\n";
  }
  report << "baked " << actors.size() - stored << " actor(s), " << options.Samples
         << " samples: " << rays << " rays in " << seconds << " s\n";
}

//------------------------------------------------------------------------------
FloatImage ReadBakedAO(vtkRenderWindow* window, int width, int height)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  std::vector<float> depth(static_cast<size_t>(width) * height);
  window->GetZbufferData(0, 0, width - 1, height - 1, depth.data());
  FloatImage image;
  image.Width = width;
  image.Height = height;
  image.Channels = 2;
  image.Pixels.resize(2 * depth.size());
  for (size_t i = 0; i < depth.size(); ++i)
  {
    const bool covered = depth[i] < 1.0f;
    image.Pixels[2 * i] = covered ? rgb->GetValue(3 * static_cast<vtkIdType>(i)) / 255.0f : 1.0f;
    image.Pixels[2 * i + 1] = covered ? 1.0f : 0.0f;
  }
  return image;
}

//------------------------------------------------------------------------------
vtkPolyData* MeshToBake(vtkRenderer* scene, const std::string& input, const std::string& output)
{
  // Read through the program's one reader table (one-line errors for bad files).
  AddFile(scene, input);
  const auto actors = PolyDataActors(scene);
  if (actors.empty())
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
  return actors.front().second;
}

//------------------------------------------------------------------------------
void BakeAndWrite(vtkAOBaker* baker, const std::string& output, const std::string& failure)
{
  {
    ProgressBar bar("baking");
    bar.Watch(baker);
    baker->Update();
  }
  if (!baker->GetOutput()->GetPointData()->GetArray(baker->GetArrayName().c_str()))
  {
    throw std::runtime_error(failure);
  }
  WritePolyData(baker->GetOutput(), output + ".partial.vtp", output);
}

//------------------------------------------------------------------------------
void BakeFile(const std::string& input,
  const std::string& output,
  const RayTracingOptions& options,
  std::ostream& report)
{
  vtkNew<vtkRenderer> scene;
  vtkPolyData* mesh = MeshToBake(scene, input, output);
  if (options.BakeMethod == "sattler")
  {
    // GPU visibility from Samples directions (Sattler et al. 2004): R = infinity, binary.
    vtkNew<vtkAOSattlerBaker> sattler;
    sattler->SetNumberOfDirections(std::min(options.Samples, 65536));
    sattler->SetBias(options.Bias);
    sattler->SetArrayName(ArrayName);
    sattler->StoreVisibilityOff();
    sattler->SetInputData(mesh);
    BakeAndWrite(sattler, output, "the GPU visibility baker failed (see the message above)");
    const double seconds = std::max(1e-9, sattler->GetTotalTime());
    const double pairs = static_cast<double>(sattler->GetOutput()->GetNumberOfPoints()) *
      sattler->GetNumberOfDirections();
    report << "baked " << sattler->GetOutput()->GetNumberOfPoints() << " points (sattler), "
           << sattler->GetNumberOfDirections() << " directions, " << sattler->GetResolution()
           << "^2 depth maps, bias " << sattler->GetEffectiveBias() << ": " << seconds
           << " s (draw+read " << sattler->GetRenderTime() << " s, test " << sattler->GetTestTime()
           << " s) = " << pairs / seconds << " vertex-directions/s, "
           << 1000.0 * seconds / sattler->GetNumberOfDirections() << " ms/direction\nwrote "
           << output << "\n";
    return;
  }

  vtkNew<vtkAOVertexBaker> baker;
  Configure(baker, options);
  baker->SetInputData(mesh);
  BakeAndWrite(baker, output, "the ray-cast baker failed (see the message above)");
  report << "baked " << baker->GetOutput()->GetNumberOfPoints() << " points, " << options.Samples
         << " samples, radius " << baker->GetEffectiveRadius() << ", bias "
         << baker->GetEffectiveBias() << ": " << baker->GetNumberOfRays() << " rays in "
         << baker->GetTraceTime() << " s\nwrote " << output << "\n";
}
}
