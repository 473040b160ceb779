#include "vtkaoScene.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExecutive.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkLightKit.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStringOutputWindow.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <stdexcept>

namespace
{
void AddActor(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
}

template<class Reader>
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

// Turns VTK's error events into a flag instead of console noise.
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Failed = true;
    if (data && this->Message.empty())
    {
      this->Message = static_cast<const char*>(data);
      const auto end = this->Message.find_last_not_of("\n ");
      this->Message.erase(end == std::string::npos ? 0 : end + 1);
      const auto nl = this->Message.rfind('\n');
      if (nl != std::string::npos)
      {
        this->Message = this->Message.substr(nl + 1);
      }
    }
  }
  bool Failed = false;
  std::string Message;
};
}

namespace vtkao
{
//------------------------------------------------------------------------------
void AddBuiltInScene(vtkRenderer* renderer)
{
  // Ground (y = 0): receives the contact shadows.
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-12, 0, -10);
  // Point1 and Point2 in this order make the normal +y (up, towards the camera).
  ground->SetPoint1(-12, 0, 10);
  ground->SetPoint2(12, 0, -10);
  AddActor(renderer, ground, 0.85, 0.85, 0.8);

  // A sphere resting on the ground: contact occlusion.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 1, 0);
  sphere->SetRadius(1);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  AddActor(renderer, sphere, 0.8, 0.3, 0.25);

  // A box and a wall meeting the ground: creases.
  vtkNew<vtkCubeSource> box;
  box->SetBounds(-4.5, -2.5, 0, 2, -2, 0);
  AddActor(renderer, box, 0.3, 0.5, 0.8);
  vtkNew<vtkCubeSource> wall;
  wall->SetBounds(-6, 3, 0, 3, -4.5, -4);
  AddActor(renderer, wall, 0.75, 0.75, 0.7);

  // A tall slab just outside the default view (to the right, all of it beyond the frame's
  // edge): screen-space AO cannot see it, HAO darkens the visible ground beside it.
  vtkNew<vtkCubeSource> outside;
  outside->SetBounds(11, 11.6, 0, 4, -4, 4);
  AddActor(renderer, outside, 0.6, 0.6, 0.6);

  // A key light from above and fill lights: the ground is lit, so its occlusion shows.
  vtkNew<vtkLightKit> lights;
  lights->SetKeyLightElevation(60);
  lights->AddLightsToRenderer(renderer);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.5, 5.5, 11);
  camera->SetFocalPoint(0.5, 0.5, -0.5);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(40);
  renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
void AddFile(vtkRenderer* renderer, const std::string& path)
{
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe.good())
    {
      throw std::runtime_error("cannot read input file '" + path + "'");
    }
  }
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot);
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });

  // One reader per format; each has SetFileName, so one template serves them all.
  using Factory = vtkSmartPointer<vtkAlgorithm> (*)(const std::string&);
  static const std::map<std::string, Factory> readers = {
    { ".vtp", &MakeReader<vtkXMLPolyDataReader> },
    { ".vtu", &MakeReader<vtkXMLUnstructuredGridReader> },
    { ".vtk", &MakeReader<vtkGenericDataObjectReader> },
    { ".stl", &MakeReader<vtkSTLReader> },
    { ".ply", &MakeReader<vtkPLYReader> },
    { ".obj", &MakeReader<vtkOBJReader> },
  };
  const auto factory = readers.find(ext);
  if (factory == readers.end())
  {
    throw std::runtime_error("unsupported input format '" + ext + "' for '" + path +
      "' (expected .vtp .vtu .vtk .stl .ply .obj)");
  }
  vtkSmartPointer<vtkAlgorithm> reader = factory->second(path);

  // Problems are reported once, by us, as one line: every algorithm and executive on the way
  // reports to the observer instead of the console.
  vtkNew<ErrorObserver> errors;
  // Volumetric cells become their outer surface.
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(surface->GetOutputPort());
  for (vtkAlgorithm* algorithm : { reader.GetPointer(),
         static_cast<vtkAlgorithm*>(surface),
         static_cast<vtkAlgorithm*>(triangles) })
  {
    for (vtkObject* source :
      { static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive()) })
    {
      source->AddObserver(vtkCommand::ErrorEvent, errors);
      source->AddObserver(vtkCommand::WarningEvent, errors);
    }
  }
  // Internal objects (the XML parser) report through the output window and the logger
  // directly: capture the one and mute the other while reading.
  vtkNew<vtkStringOutputWindow> capture;
  vtkOutputWindow* console = vtkOutputWindow::GetInstance();
  console->Register(nullptr);
  vtkOutputWindow::SetInstance(capture);
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  triangles->Update();
  vtkLogger::SetStderrVerbosity(verbosity);
  vtkOutputWindow::SetInstance(console);
  console->UnRegister(nullptr);
  vtkDataSet* raw = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (errors->Failed || !raw)
  {
    throw std::runtime_error("cannot parse '" + path + "'" +
      (errors->Message.empty() ? std::string() : ": " + errors->Message));
  }
  vtkPolyData* mesh = triangles->GetOutput();
  if (mesh->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("'" + path + "' contains no polygons");
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(normals->GetOutput());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(copy);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.85, 0.85);
  renderer->AddActor(actor);
}
}
