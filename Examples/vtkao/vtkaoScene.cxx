#include "vtkaoScene.h"
#include "vtkaoInputChecks.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExecutive.h"
#include "vtkGLTFImporter.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkImporter.h"
#include "vtkLightKit.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOBJImporter.h"
#include "vtkOBJReader.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStringOutputWindow.h"
#include "vtkTessellatedBoxSource.h"
#include "vtkTriangleFilter.h"
#include "vtkVersionMacros.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <new>
#include <random>
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

// While it lives, VTK's messages go to a string instead of the console, and the logger is
// muted: internal objects (the XML parser, importers) report through both directly.
class QuietConsole
{
public:
  QuietConsole()
    : Console(vtkOutputWindow::GetInstance())
    , Verbosity(vtkLogger::GetCurrentVerbosityCutoff())
  {
    this->Console->Register(nullptr);
    vtkOutputWindow::SetInstance(this->Capture);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~QuietConsole()
  {
    vtkLogger::SetStderrVerbosity(this->Verbosity);
    vtkOutputWindow::SetInstance(this->Console);
    this->Console->UnRegister(nullptr);
  }
  QuietConsole(const QuietConsole&) = delete;
  QuietConsole& operator=(const QuietConsole&) = delete;
  std::string Output() { return this->Capture->GetOutput(); }

private:
  vtkNew<vtkStringOutputWindow> Capture;
  vtkOutputWindow* Console;
  vtkLogger::Verbosity Verbosity;
};

// VTK 9.1's MTL parser reads past its tokens, and crashes, when a map_Ka or map_Kd statement
// ends the file without a line end (found by fuzzing; valid files do that): such a file is
// handed to it as a temporary copy that ends with one. Path is the file to give the parser.
class MaterialFileWithLineEnd
{
public:
  explicit MaterialFileWithLineEnd(const std::string& mtl)
    : Path(mtl)
  {
    std::ifstream in(mtl, std::ios::binary);
    const std::string text{ std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
    std::error_code error;
    const std::filesystem::path temporary = std::filesystem::temp_directory_path(error);
    if (text.empty() || text.back() == '\n' || error)
    {
      return;
    }
    this->Copy = temporary / ("vtkao-" + std::to_string(std::random_device()()) + ".mtl");
    std::ofstream out(this->Copy, std::ios::binary);
    out << text << '\n';
    if (out.good())
    {
      this->Path = this->Copy.string();
    }
  }
  ~MaterialFileWithLineEnd()
  {
    if (!this->Copy.empty())
    {
      std::error_code error;
      std::filesystem::remove(this->Copy, error);
    }
  }
  MaterialFileWithLineEnd(const MaterialFileWithLineEnd&) = delete;
  MaterialFileWithLineEnd& operator=(const MaterialFileWithLineEnd&) = delete;

  std::string Path;

private:
  std::filesystem::path Copy;
};

// The file named by an .obj's `mtllib` line, when it exists beside the .obj (else empty).
std::string MaterialFile(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("mtllib", 0) == 0 && line.size() > 7)
    {
      std::string name = line.substr(7);
      name.erase(name.find_last_not_of(" \t\r") + 1);
      name.erase(0, name.find_first_not_of(" \t"));
      const auto slash = path.find_last_of('/');
      const std::string mtl =
        (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + name;
      return std::ifstream(mtl).good() ? mtl : std::string();
    }
  }
  return std::string();
}

// Scenes (.glb/.gltf, .obj with materials): the importer fills a renderer of its own; its
// actors keep their transforms (user matrices), materials and textures and move to @p renderer.
// Cameras and lights of the file are not used. Errors are captured as one line.
void ImportScene(vtkRenderer* renderer, const std::string& path, const std::string& mtl);
}

namespace vtkao
{
//------------------------------------------------------------------------------
void AddBuiltInScene(vtkRenderer* renderer, long long triangles)
{
  // Refinement: about 40% of the triangles to the ground, 50% to the sphere, 10% to the boxes.
  const double n = static_cast<double>(std::max(0LL, triangles));
  const int groundCells = triangles > 0 ? std::max(1, static_cast<int>(std::sqrt(0.2 * n))) : 1;
  const int phi = triangles > 0 ? std::max(32, static_cast<int>(std::sqrt(0.125 * n))) : 32;
  const int boxLevel =
    triangles > 0 ? std::max(0, static_cast<int>(std::sqrt(0.1 * n / 36.0)) - 1) : 0;
  auto addBox = [&](double x0,
                  double x1,
                  double y0,
                  double y1,
                  double z0,
                  double z1,
                  double r,
                  double g,
                  double b)
  {
    vtkNew<vtkTessellatedBoxSource> box;
    box->SetBounds(x0, x1, y0, y1, z0, z1);
    box->SetLevel(boxLevel);
    box->QuadsOff();                    // triangles
    vtkNew<vtkPolyDataNormals> normals; // flat faces: split at the box's edges
    normals->SetInputConnection(box->GetOutputPort());
    normals->SetFeatureAngle(30);
    AddActor(renderer, normals, r, g, b);
  };

  // Ground (y = 0): receives the contact shadows.
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-12, 0, -10);
  // Point1 and Point2 in this order make the normal +y (up, towards the camera).
  ground->SetPoint1(-12, 0, 10);
  ground->SetPoint2(12, 0, -10);
  ground->SetResolution(groundCells, groundCells);
  vtkNew<vtkTriangleFilter> groundTriangles;
  groundTriangles->SetInputConnection(ground->GetOutputPort());
  AddActor(renderer, groundTriangles, 0.85, 0.85, 0.8);

  // A sphere resting on the ground: contact occlusion.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 1, 0);
  sphere->SetRadius(1);
  sphere->SetThetaResolution(2 * phi);
  sphere->SetPhiResolution(phi);
  AddActor(renderer, sphere, 0.8, 0.3, 0.25);

  // A box and a wall meeting the ground: creases.
  addBox(-4.5, -2.5, 0, 2, -2, 0, 0.3, 0.5, 0.8);
  addBox(-6, 3, 0, 3, -4.5, -4, 0.75, 0.75, 0.7);

  // A tall slab just outside the default view (to the right, all of it beyond the frame's
  // edge): screen-space AO cannot see it, HAO darkens the visible ground beside it.
  addBox(11, 11.6, 0, 4, -4, 4, 0.6, 0.6, 0.6);

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

namespace
{
// The steps of AddFile.

// @p path's extension in lower case ("" if none), after checking that the file can be opened.
std::string ReadableExtension(const std::string& path)
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
  return ext;
}

// The error of a file that cannot be parsed, with the @p problem found (if any).
std::runtime_error ParseError(const std::string& path, const std::string& problem)
{
  return std::runtime_error(
    "cannot parse '" + path + "'" + (problem.empty() ? std::string() : ": " + problem));
}

// Throws the ParseError of @p problem unless it is empty (vtkaoInputChecks.h).
void Check(const std::string& path, const std::string& problem)
{
  if (!problem.empty())
  {
    throw ParseError(path, problem);
  }
}

// Whether the reader of @p format (the extension; ".obj+.mtl" for the OBJ importer) may crash
// inside itself on a malformed file that no check recognizes, so that CheckCrash reads the
// file first in a child process. Every VTK 9.1 reader and importer does (fuzzing keeps finding
// new ones: Testing/Fuzz/unhandled). VTK 9.5's vtkSTLReader survived the whole fuzz corpus and
// mutants of it (Testing/Fuzz/reader-survey.py, Documentation/reliability.md: no crash, hang or
// abort); its XML, legacy and PLY readers, the OBJ reader and importer and the glTF loader still
// crash on some of it.
bool ReaderMayCrash(const std::string& format)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 5, 0)
  return format != ".stl";
#else
  (void)format;
  return true;
#endif
}

// A first read of @p path, by @p read, in a child process finds the reader crashes of
// ReaderMayCrash(@p format), for the price of reading the file twice.
void CheckCrash(const std::string& path,
  const std::string& format,
  const std::function<void()>& read)
{
  if (!ReaderMayCrash(format))
  {
    return;
  }
  const std::string crash = ReaderCrashProblem(read);
  if (!crash.empty())
  {
    throw std::runtime_error("cannot read '" + path + "': " + crash);
  }
}

// The reader of @p path, of its format @p ext (one per format; each has SetFileName, so one
// template serves them all), after the checks of that format.
vtkSmartPointer<vtkAlgorithm> CheckedReader(const std::string& path, const std::string& ext)
{
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
      "' (expected .vtp .vtu .vtk .stl .ply .obj .glb .gltf)");
  }
  if (ext == ".stl")
  {
    Check(path, BinarySTLProblem(path));
  }
  if (ext == ".ply")
  {
    Check(path, PLYProblem(path));
  }
  CheckCrash(path,
    ext,
    [&]
    {
      QuietConsole quiet;
      factory->second(path)->Update();
    });
  return factory->second(path);
}

// What @p reader reads, as triangles (volumetric cells become their outer surface).
vtkSmartPointer<vtkPolyData> ReadTriangles(vtkAlgorithm* reader, const std::string& path)
{
  // Problems are reported once, by us, as one line: every algorithm and executive on the way
  // reports to the observer instead of the console.
  vtkNew<ErrorObserver> errors;
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(surface->GetOutputPort());
  for (vtkAlgorithm* algorithm :
    { reader, static_cast<vtkAlgorithm*>(surface), static_cast<vtkAlgorithm*>(triangles) })
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
  try
  {
    QuietConsole quiet;
    reader->Update();
    vtkDataSet* raw = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    if (errors->Failed || !raw)
    {
      throw ParseError(path, errors->Message);
    }
    Check(path, DataSetProblem(raw));
    triangles->Update();
    if (errors->Failed)
    {
      throw ParseError(path, errors->Message);
    }
  }
  catch (const std::bad_alloc&)
  {
    throw ParseError(path, "out of memory (does the file declare more data than it holds?)");
  }
  return triangles->GetOutput();
}

// An actor drawing @p mesh in light grey, with smooth point normals.
void AddMeshActor(vtkRenderer* renderer, vtkPolyData* mesh)
{
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

//------------------------------------------------------------------------------
void AddFile(vtkRenderer* renderer, const std::string& path)
{
  const std::string ext = ReadableExtension(path);
  // Inputs VTK 9.1's readers and importers would crash on are rejected before they see them,
  // or what they read before the filters see it (vtkaoInputChecks.h; found by fuzzing).
  // Scenes with transforms and materials go through VTK's importers.
  const std::string mtl = ext == ".obj" ? MaterialFile(path) : std::string();
  if (ext == ".obj")
  {
    Check(path, OBJProblem(path));
  }
  if (!mtl.empty())
  {
    Check(path, MTLProblem(mtl));
  }
  if (ext == ".glb" || ext == ".gltf")
  {
    Check(path, GLTFProblem(path, ext == ".glb"));
  }
  if (ext == ".glb" || ext == ".gltf" || !mtl.empty())
  {
    CheckCrash(path,
      mtl.empty() ? ext : ".obj+.mtl",
      [&]
      {
        QuietConsole quiet;
        vtkNew<vtkRenderer> scratch;
        ImportScene(scratch, path, mtl);
      });
    ImportScene(renderer, path, mtl);
    return;
  }
  vtkSmartPointer<vtkAlgorithm> reader = CheckedReader(path, ext);
  vtkSmartPointer<vtkPolyData> mesh = ReadTriangles(reader, path);
  if (mesh->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("'" + path + "' contains no polygons");
  }
  AddMeshActor(renderer, mesh);
}

//------------------------------------------------------------------------------
void ForEachPolyDataActor(vtkRenderer* renderer,
  const std::function<void(vtkActor*, vtkPolyDataMapper*)>& visit)
{
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      mapper->Update();
      visit(actor, mapper);
    }
  }
}

//------------------------------------------------------------------------------
long long CountTriangles(vtkRenderer* renderer)
{
  long long count = 0;
  ForEachPolyDataActor(renderer,
    [&count](vtkActor*, vtkPolyDataMapper* mapper)
    {
      vtkPolyData* data = mapper->GetInput();
      if (!data)
      {
        return;
      }
      for (vtkCellArray* cells : { data->GetPolys(), data->GetStrips() })
      {
        for (vtkIdType i = 0; i < cells->GetNumberOfCells(); ++i)
        {
          count += std::max<vtkIdType>(0, cells->GetCellSize(i) - 2);
        }
      }
    });
  return count;
}
}

namespace
{
//------------------------------------------------------------------------------
void ImportScene(vtkRenderer* renderer, const std::string& path, const std::string& mtl)
{
  vtkSmartPointer<vtkImporter> importer;
  const MaterialFileWithLineEnd material(mtl);
  if (mtl.empty())
  {
    auto gltf = vtkSmartPointer<vtkGLTFImporter>::New();
    gltf->SetFileName(path.c_str());
    importer = gltf;
  }
  else
  {
    auto obj = vtkSmartPointer<vtkOBJImporter>::New();
    obj->SetFileName(path.c_str());
    obj->SetFileNameMTL(material.Path.c_str());
    const auto slash = path.find_last_of('/');
    obj->SetTexturePath(slash == std::string::npos ? "." : path.substr(0, slash).c_str());
    importer = obj;
  }
  // The importer's own window is never rendered (no context is created).
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> imported;
  window->AddRenderer(imported);
  importer->SetRenderWindow(window);

  vtkNew<ErrorObserver> errors;
  importer->AddObserver(vtkCommand::ErrorEvent, errors);
  std::string captured;
  try
  {
    QuietConsole quiet;
    importer->Update();
    captured = quiet.Output();
  }
  catch (const std::exception& e)
  {
    // VTK's glTF loader lets exceptions of jsoncpp and of the standard library through (a
    // value of the wrong JSON type, a length beyond what a string can hold; found by fuzzing).
    throw std::runtime_error("cannot parse '" + path +
      "': " + (dynamic_cast<const std::bad_alloc*>(&e) ? std::string("out of memory") : e.what()));
  }

  std::string message = errors->Message;
  if (message.empty() && captured.find("ERROR") != std::string::npos)
  {
    // The last line of the first error report.
    std::string first = captured.substr(captured.find("ERROR"));
    first = first.substr(0, first.find("\n\n"));
    first.erase(first.find_last_not_of("\n ") + 1);
    const auto nl = first.rfind('\n');
    message = nl == std::string::npos ? first : first.substr(nl + 1);
  }
  // Move the actors; count their polygons.
  std::vector<vtkSmartPointer<vtkActor>> actors;
  vtkIdType polygons = 0;
  vtkActorCollection* collection = imported->GetActors();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkActor* actor = collection->GetNextActor(it))
  {
    actors.emplace_back(actor);
    if (auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      mapper->Update();
      if (vtkPolyData* data = mapper->GetInput())
      {
        // What the importer built from the file's indices (bounds, normals and drawing read it).
        const std::string problem = vtkao::DataSetProblem(data);
        if (!problem.empty())
        {
          throw std::runtime_error("cannot parse '" + path + "': " + problem);
        }
        polygons += data->GetNumberOfPolys() + data->GetNumberOfStrips();
      }
    }
  }
  if (actors.empty() && (errors->Failed || !message.empty()))
  {
    throw std::runtime_error(
      "cannot parse '" + path + "'" + (message.empty() ? std::string() : ": " + message));
  }
  if (polygons == 0)
  {
    throw std::runtime_error("'" + path + "' contains no polygons");
  }
  for (const auto& actor : actors)
  {
    imported->RemoveActor(actor);
    renderer->AddActor(actor);
  }
}
}
