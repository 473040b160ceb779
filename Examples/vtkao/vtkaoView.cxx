#include "vtkaoView.h"
#include "vtkaoContext.h"

#include "vtkaoImageIO.h"
#include "vtkaoScene.h"
#ifdef VTKAO_HAS_REFERENCE
#include "vtkaoReference.h"
#endif

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSSAOPass.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vtkao
{
namespace
{
const char* ViewUsage =
  "usage: vtkao view [INPUT ...] [options]   interactive window (trackball camera)\n"
  "  INPUT: .vtp .vtu .vtk .stl .ply .obj .glb .gltf (several allowed); none = built-in scene\n"
  "  --method none|ssao|hao|aov|baked|reference   initial method (default hao)\n"
  "  --size WxH                   window size (default 1280x720)\n"
  "  --screenshot FILE            where p writes (.png or .exr; default vtkao-view-N.png)\n"
  "  --samples N                  rays per pixel/vertex of reference and baked (default 64)\n"
  "  --script \"K K ...\"           press these keys (one character each, space separated)\n"
  "                               after the first frame, one per 100 ms (for tests, demos)\n";

const char* Keys =
  "vtkao view keys:\n"
  "  n  no AO           s  SSAO (vtkSSAOPass)      h  HAO (vtkHybridAmbientOcclusionPass)\n"
  "  a  AOV (AOScale 2)   b  baked per vertex (Embree)  r  ray-traced reference (Embree;\n"
  "                         one image for the current camera, moving the camera leaves it)\n"
  "  o  toggle AO-only (A itself, for hao, aov and baked)\n"
  "  +/-  radius x1.25 / /1.25        ]/[  rays x2 / /2        }/{  steps x2 / /2\n"
  "  I/i  intensity +0.25 / -0.25     V/v  voxel resolution x2 / /2\n"
  "  c  reset the camera   p  screenshot   ?  print these keys   q/e  quit\n"
  "  mouse: left rotate, middle pan, right/wheel zoom (trackball camera)\n";

int ParseIntArg(const std::string& option, const std::string& text, int lo, int hi)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0')
  {
    throw ViewUsageError(option + ": '" + text + "' is not a whole number");
  }
  if (v < lo || v > hi)
  {
    throw ViewUsageError(option + ": " + text + " is out of range [" + std::to_string(lo) + ", " +
      std::to_string(hi) + "]");
  }
  return static_cast<int>(v);
}

struct ViewOptions
{
  std::vector<std::string> Inputs;
  std::string Method = "hao";
  int Width = 1280, Height = 720;
  std::string Screenshot;
  int Samples = 64;
  std::vector<char> Script;
};

ViewOptions ParseViewOptions(int argc, char* argv[])
{
  ViewOptions o;
  std::vector<std::string> methods = { "none", "ssao", "hao", "aov" };
#ifdef VTKAO_HAS_REFERENCE
  methods.insert(methods.end(), { "baked", "reference" });
#endif
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        throw ViewUsageError(arg + ": missing value");
      }
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h")
    {
      std::cout << ViewUsage << Keys;
      std::exit(0);
    }
    else if (arg == "--method")
    {
      o.Method = value();
      if (std::find(methods.begin(), methods.end(), o.Method) == methods.end())
      {
        std::string expected;
        for (const auto& m : methods)
        {
          expected += (expected.empty() ? "" : ", ") + m;
        }
        throw ViewUsageError(
          "--method: unknown method '" + o.Method + "' (expected " + expected + ")");
      }
    }
    else if (arg == "--size")
    {
      const std::string v = value();
      const auto x = v.find('x');
      if (x == std::string::npos)
      {
        throw ViewUsageError("--size: expected WxH, got '" + v + "'");
      }
      o.Width = ParseIntArg("--size", v.substr(0, x), 1, 16384);
      o.Height = ParseIntArg("--size", v.substr(x + 1), 1, 16384);
    }
    else if (arg == "--screenshot")
    {
      o.Screenshot = value();
      if (!IsSupportedImagePath(o.Screenshot))
      {
        throw ViewUsageError(
          "--screenshot: unsupported format for '" + o.Screenshot + "' (expected .png or .exr)");
      }
    }
    else if (arg == "--samples")
    {
      o.Samples = ParseIntArg("--samples", value(), 1, 1048576);
    }
    else if (arg == "--script")
    {
      std::istringstream in(value());
      std::string key;
      while (in >> key)
      {
        if (key.size() != 1 ||
          std::string("nshabroc+-][}{IiVvp?qe").find(key[0]) == std::string::npos)
        {
          throw ViewUsageError("--script: unknown key '" + key + "' (see vtkao view --help)");
        }
        o.Script.push_back(key[0]);
      }
    }
    else if (arg.rfind("--", 0) == 0)
    {
      throw ViewUsageError("unknown option '" + arg + "'");
    }
    else
    {
      o.Inputs.push_back(arg);
    }
  }
  return o;
}

class Viewer;

// Trackball camera whose character keys are the viewer's (none of the style's defaults).
class ViewerStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ViewerStyle* New();
  vtkTypeMacro(ViewerStyle, vtkInteractorStyleTrackballCamera);
  void OnChar() override;
  Viewer* Owner = nullptr;
};
vtkStandardNewMacro(ViewerStyle);

class Viewer
{
public:
  explicit Viewer(const ViewOptions& o)
    : Options(o)
  {
  }

  int Run();
  void Key(char key);

private:
  // The steps of Run.
  void AddScene();
  void SetUpWindow();
  void ObserveFrames();
  void RunScript(bool headless);
  void ReleasePasses();
  // Key: the keys that switch the method, and those that change a parameter of the methods
  // (whether @p key is one).
  bool SwitchMethod(char key);
  bool AdjustParameter(char key);

  void SetMethod(const std::string& method);
  void ApplyParameters();
  void UpdateText();
  void Screenshot();
  double SceneDiagonal();
  void FrameStart()
  {
    this->Start = std::chrono::steady_clock::now();
    this->DisplayedFrames = this->ShownFrames; // the text this frame draws
  }
  void FrameEnd();
#ifdef VTKAO_HAS_REFERENCE
  RayTracingOptions TracingOptions();
  void ShowBaked();
  void ShowReference();
#endif

  ViewOptions Options;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderer> Overlay;       // layer 2: the text
  vtkNew<vtkRenderer> ImageRenderer; // layer 1: the reference image when shown
  vtkNew<vtkImageActor> ReferenceImage;
  vtkSmartPointer<vtkRenderer> Baked; // a copy of the scene, baked
  std::string BakedKey;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<ViewerStyle> Style;
  vtkNew<vtkRenderStepsPass> Basic;
  vtkNew<vtkHybridAmbientOcclusionPass> HAO;
  vtkNew<vtkAmbientOcclusionVolumesPass> AOV;
  vtkNew<vtkSSAOPass> SSAO;
  vtkNew<vtkTextActor> Text;
  std::string Method = "hao";
  std::string PreviousMethod = "hao";
  bool AOOnly = false;
  double Radius = 0; // 0 = automatic
  double Intensity = 1;
  int Rays = 8, Steps = 4, VoxelResolution = 256;
  double FrameMs = 0;
  std::string Status;
  std::chrono::steady_clock::time_point Start;
  int Screenshots = 0;
  bool ScreenshotFailed = false;
  size_t ScriptPosition = 0;
  bool Quitting = false;
  bool Headless = false; // EGL or OSMesa window: no event loop (Run)
  int ScriptTimer = -1;
  int RefineTimer = -1;
  int ShownFrames = 0;     // the accumulated frames the text holds (drawn from the next frame)
  int DisplayedFrames = 0; // the accumulated frames the text on screen shows
  friend void ScriptTick(vtkObject*, unsigned long, void*, void*);
  friend void RefineTick(vtkObject*, unsigned long, void*, void*);
};

void ViewerStyle::OnChar()
{
  if (this->Owner)
  {
    this->Owner->Key(this->Interactor->GetKeyCode());
  }
}

double Viewer::SceneDiagonal()
{
  double b[6];
  this->Renderer->ComputeVisiblePropBounds(b);
  if (b[0] > b[1])
  {
    return 1.0;
  }
  return std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

void Viewer::ApplyParameters()
{
  this->HAO->SetRadius(this->Radius);
  this->HAO->SetNumberOfRays(this->Rays);
  this->HAO->SetNumberOfSteps(this->Steps);
  this->HAO->SetVoxelResolution(this->VoxelResolution);
  this->HAO->SetIntensity(this->Intensity);
  this->HAO->SetAOOnly(this->AOOnly);
  // AOV is fill-rate bound (aov.md): every second pixel keeps it usable on software GL.
  this->AOV->SetRadius(this->Radius);
  this->AOV->SetIntensity(this->Intensity);
  this->AOV->SetAOOnly(this->AOOnly);
  this->AOV->SetAOScale(2);
  const double diagonal = this->SceneDiagonal();
  this->SSAO->SetRadius(this->Radius > 0 ? this->Radius : 0.1 * diagonal);
  this->SSAO->SetBias(0.001 * diagonal);
  this->SSAO->SetKernelSize(std::min(this->Rays, 1024));
}

#ifdef VTKAO_HAS_REFERENCE
RayTracingOptions Viewer::TracingOptions()
{
  RayTracingOptions t;
  t.Radius = this->Radius;
  t.Samples = this->Options.Samples;
  return t;
}

// A second renderer with copies of the scene's actors (own mappers: baking replaces their
// input), baked once per parameter set; it shares the camera and the lights.
void Viewer::ShowBaked()
{
  const std::string key = std::to_string(this->Radius) + "/" + std::to_string(this->AOOnly);
  if (!this->Baked || key != this->BakedKey)
  {
    auto baked = vtkSmartPointer<vtkRenderer>::New();
    baked->SetBackground(this->Renderer->GetBackground());
    baked->SetActiveCamera(this->Renderer->GetActiveCamera());
    vtkLightCollection* lights = this->Renderer->GetLights();
    lights->InitTraversal();
    while (vtkLight* light = lights->GetNextItem())
    {
      baked->AddLight(light);
    }
    baked->AutomaticLightCreationOff();
    ForEachPolyDataActor(this->Renderer,
      [&baked](vtkActor* actor, vtkPolyDataMapper* mapper)
      {
        vtkNew<vtkPolyDataMapper> copyMapper;
        copyMapper->SetInputData(mapper->GetInput());
        copyMapper->SetScalarVisibility(mapper->GetScalarVisibility());
        vtkNew<vtkActor> copy;
        copy->SetMapper(copyMapper);
        copy->GetProperty()->DeepCopy(actor->GetProperty());
        copy->SetTexture(actor->GetTexture());
        copy->SetVisibility(actor->GetVisibility());
        vtkNew<vtkTransform> transform;
        transform->SetMatrix(actor->GetMatrix());
        copy->SetUserTransform(transform);
        baked->AddActor(copy);
      });
    std::cout << "baking (" << this->Options.Samples << " rays per vertex)...\n";
    BakeRenderer(baked, this->TracingOptions(), this->AOOnly, std::cout);
    this->Baked = baked;
    this->BakedKey = key;
  }
  this->Window->RemoveRenderer(this->Renderer);
  this->Window->AddRenderer(this->Baked);
  this->Baked->SetLayer(0);
}

// Trace A for the current camera and show it as a grey image over the scene.
void Viewer::ShowReference()
{
  const int* size = this->Window->GetSize();
  std::cout << "tracing the reference (" << this->Options.Samples << " rays per pixel)...\n";
  const FloatImage traced =
    RenderReference(this->Renderer, size[0], size[1], this->TracingOptions(), std::cout);
  vtkNew<vtkImageData> image;
  image->SetDimensions(traced.Width, traced.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < static_cast<size_t>(traced.Width) * traced.Height; ++i)
  {
    const float a = std::min(1.0f, std::max(0.0f, traced.Pixels[i * traced.Channels]));
    out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = static_cast<unsigned char>(255 * a + 0.5f);
  }
  this->ReferenceImage->SetInputData(image);
  this->ImageRenderer->DrawOn();
  this->ImageRenderer->ResetCamera();
  vtkCamera* camera = this->ImageRenderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.5 * traced.Height);
}
#endif

void Viewer::SetMethod(const std::string& method)
{
  // Leave the previous method's display.
  if (this->Baked)
  {
    this->Window->RemoveRenderer(this->Baked);
  }
  if (!this->Window->GetRenderers()->IsItemPresent(this->Renderer))
  {
    this->Window->AddRenderer(this->Renderer);
  }
  this->ImageRenderer->DrawOff();
  if (method != "reference")
  {
    this->PreviousMethod = method;
  }
  this->Method = method;
  this->Status.clear();
  this->ApplyParameters();
  if (method == "hao")
  {
    this->Renderer->SetPass(this->HAO);
  }
  else if (method == "ssao")
  {
    this->Renderer->SetPass(this->SSAO);
  }
  else if (method == "aov")
  {
    this->Renderer->SetPass(this->AOV);
  }
  else
  {
    this->Renderer->SetPass(nullptr);
  }
#ifdef VTKAO_HAS_REFERENCE
  if (method == "baked")
  {
    this->ShowBaked();
  }
  else if (method == "reference")
  {
    this->ShowReference();
  }
#endif
}

void Viewer::UpdateText()
{
  std::ostringstream t;
  t << std::fixed << std::setprecision(2);
  t << "method " << this->Method << (this->AOOnly ? "  (AO only)" : "") << "\n";
  if (this->Method == "hao" || this->Method == "ssao" || this->Method == "aov")
  {
    t << "radius ";
    if (this->Radius > 0)
    {
      t << this->Radius;
    }
    else
    {
      t << "auto";
      if (this->Method == "hao")
      {
        t << " (" << this->HAO->GetEffectiveRadius() << ")";
      }
      else if (this->Method == "aov")
      {
        t << " (" << this->AOV->GetEffectiveRadius() << ")";
      }
    }
    if (this->Method != "aov")
    {
      t << (this->Method == "hao" ? "   rays " : "   kernel ") << this->Rays;
    }
    if (this->Method == "hao")
    {
      t << "   steps " << this->Steps << "   voxels " << this->VoxelResolution << "   intensity "
        << this->Intensity;
    }
    t << "\n";
  }
  t << "frame " << std::setprecision(1) << this->FrameMs << " ms";
  if (this->Method == "hao" || this->Method == "aov")
  {
    vtkAmbientOcclusionPassBase* pass = this->Method == "hao"
      ? static_cast<vtkAmbientOcclusionPassBase*>(this->HAO)
      : static_cast<vtkAmbientOcclusionPassBase*>(this->AOV);
    this->ShownFrames = pass->GetAccumulatedFrames();
    t << " | accumulated " << this->ShownFrames << "/" << pass->GetAccumulationTarget();
  }
  if (this->Method == "hao")
  {
    t << " | GPU ms: voxelize " << this->HAO->GetVoxelizeTime() << "  gbuffer "
      << this->HAO->GetGBufferTime() << "  trace " << this->HAO->GetTraceTime() << "  filter "
      << this->HAO->GetFilterTime() << "  composite " << this->HAO->GetCompositeTime();
  }
  else if (this->Method == "aov")
  {
    t << " | GPU ms: gbuffer " << this->AOV->GetGBufferTime() << "  volumes "
      << this->AOV->GetVolumeTime() << "  filter " << this->AOV->GetFilterTime() << "  composite "
      << this->AOV->GetCompositeTime();
  }
  if (!this->Status.empty())
  {
    t << "\n" << this->Status;
  }
  t << "\npress ? for keys";
  this->Text->SetInput(t.str().c_str());
}

void Viewer::FrameEnd()
{
  this->FrameMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->Start)
      .count();
  if (this->Method == "hao")
  {
    this->HAO->FinishTimings(); // the context is current right after the frame
  }
  else if (this->Method == "aov")
  {
    this->AOV->FinishTimings();
  }
  this->UpdateText(); // shown from the next frame on
}

void Viewer::Screenshot()
{
  std::string path = this->Options.Screenshot;
  if (path.empty())
  {
    path = "vtkao-view-" + std::to_string(++this->Screenshots) + ".png";
  }
  this->Window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(this->Window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  FloatImage image;
  const int* dims = grab->GetOutput()->GetDimensions();
  image.Width = dims[0];
  image.Height = dims[1];
  image.Channels = 3;
  image.Pixels.resize(static_cast<size_t>(rgb->GetNumberOfValues()));
  for (vtkIdType i = 0; i < rgb->GetNumberOfValues(); ++i)
  {
    image.Pixels[i] = rgb->GetValue(i) / 255.0f;
  }
  try
  {
    WriteImage(image, path);
    std::cout << "wrote " << path << "\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "vtkao: " << e.what() << "\n";
    this->ScreenshotFailed = true;
  }
}

void Viewer::Key(char key)
{
  bool changed = true;
  switch (key)
  {
#ifndef VTKAO_HAS_REFERENCE
    case 'b':
    case 'r':
      this->Status = "baked and reference need Embree (not in this build)";
      std::cout << this->Status << "\n";
      break;
#endif
    case 'o':
      this->AOOnly = !this->AOOnly;
      if (this->Method == "baked")
      {
        this->SetMethod("baked");
      }
      break;
    case 'c':
      this->Renderer->ResetCamera();
      break;
    case 'p':
      this->Screenshot();
      changed = false;
      break;
    case '?':
      std::cout << Keys << std::flush;
      changed = false;
      break;
    case 'q':
    case 'e':
      this->Quitting = true;
      if (!this->Headless)
      {
        this->Interactor->TerminateApp();
      }
      return;
    default:
      changed = this->SwitchMethod(key) || this->AdjustParameter(key);
  }
  if (changed)
  {
    this->ApplyParameters();
    this->UpdateText();
    this->Window->Render();
  }
}

bool Viewer::SwitchMethod(char key)
{
  static const std::map<char, std::string> methods = {
    { 'n', "none" },
    { 's', "ssao" },
    { 'h', "hao" },
    { 'a', "aov" },
#ifdef VTKAO_HAS_REFERENCE
    { 'b', "baked" },
    { 'r', "reference" },
#endif
  };
  const auto method = methods.find(key);
  if (method == methods.end())
  {
    return false;
  }
  this->SetMethod(method->second);
  return true;
}

bool Viewer::AdjustParameter(char key)
{
  if (key == '+' || key == '=' || key == '-')
  {
    double r = this->Radius > 0 ? this->Radius : this->HAO->GetEffectiveRadius();
    if (r <= 0)
    {
      r = 0.1 * this->SceneDiagonal();
    }
    this->Radius = key == '-' ? r / 1.25 : r * 1.25;
    return true;
  }
  if (key == 'I' || key == 'i')
  {
    this->Intensity = std::min(10.0, std::max(0.0, this->Intensity + (key == 'I' ? 0.25 : -0.25)));
    return true;
  }
  // The settings a pair of keys doubles or halves, within their range.
  struct Doubling
  {
    char Up, Down;
    int Viewer::*Value;
    int Minimum, Maximum;
  };
  static const Doubling doublings[] = {
    { ']', '[', &Viewer::Rays, 1, 1024 },
    { '}', '{', &Viewer::Steps, 1, 256 },
    { 'V', 'v', &Viewer::VoxelResolution, 8, 4096 },
  };
  for (const Doubling& d : doublings)
  {
    if (key == d.Up || key == d.Down)
    {
      int& value = this->*d.Value;
      value = key == d.Up ? std::min(d.Maximum, value * 2) : std::max(d.Minimum, value / 2);
      return true;
    }
  }
  return false;
}

// Refines a still view while idle: renders again while the pass's mean is below its maximum
// (and once more so that the text shows the last count), never during an interaction.
void RefineTick(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<Viewer*>(clientData);
  if (!callData || *static_cast<int*>(callData) != self->RefineTimer || self->Quitting ||
    self->Style->GetState() != VTKIS_NONE || (self->Method != "hao" && self->Method != "aov"))
  {
    return;
  }
  vtkAmbientOcclusionPassBase* pass = self->Method == "hao"
    ? static_cast<vtkAmbientOcclusionPassBase*>(self->HAO)
    : static_cast<vtkAmbientOcclusionPassBase*>(self->AOV);
  if (pass->IsAccumulating() ||
    (pass->GetLastFrameHadOcclusion() && pass->GetAccumulatedFrames() != self->DisplayedFrames))
  {
    self->Window->Render();
  }
}

void ScriptTick(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<Viewer*>(clientData);
  if (callData && *static_cast<int*>(callData) != self->ScriptTimer)
  {
    return; // the refinement's timer
  }
  if (self->Quitting || self->ScriptPosition >= self->Options.Script.size())
  {
    return;
  }
  // Through the interactor, as a key press would come.
  const char key = self->Options.Script[self->ScriptPosition++];
  self->Interactor->SetKeyEventInformation(0, 0, key, 1, nullptr);
  self->Interactor->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
  self->Interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
  self->Interactor->InvokeEvent(vtkCommand::KeyReleaseEvent, nullptr);
}

// The files given, or the built-in scene.
void Viewer::AddScene()
{
  this->Renderer->SetBackground(1, 1, 1);
  if (this->Options.Inputs.empty())
  {
    AddBuiltInScene(this->Renderer);
  }
  else
  {
    for (const auto& input : this->Options.Inputs)
    {
      AddFile(this->Renderer, input);
    }
    this->Renderer->ResetCamera();
  }
}

// The passes around the basic one, and the window's layers: the scene, the reference image, the
// text.
void Viewer::SetUpWindow()
{
  this->HAO->SetDelegatePass(this->Basic);
  this->AOV->SetDelegatePass(this->Basic);
  this->SSAO->SetDelegatePass(this->Basic);
  this->SSAO->BlurOn();

  this->Window->SetNumberOfLayers(3);
  this->Window->SetMultiSamples(0);
  this->Window->SetSize(this->Options.Width, this->Options.Height);
  this->Window->SetWindowName("vtkao view");
  this->Renderer->SetLayer(0);
  this->ImageRenderer->SetLayer(1);
  this->ImageRenderer->InteractiveOff();
  this->ImageRenderer->DrawOff();
  this->ImageRenderer->AddActor(this->ReferenceImage);
  this->Overlay->SetLayer(2);
  this->Overlay->InteractiveOff();
  this->Text->GetTextProperty()->SetFontSize(15);
  this->Text->GetTextProperty()->SetColor(0.05, 0.05, 0.05);
  this->Text->GetTextProperty()->SetBackgroundColor(1, 1, 1);
  this->Text->GetTextProperty()->SetBackgroundOpacity(0.7);
  this->Text->GetTextProperty()->SetVerticalJustificationToTop();
  this->Text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Text->GetPositionCoordinate()->SetValue(0.01, 0.98);
  this->Overlay->AddViewProp(this->Text);
  this->Window->AddRenderer(this->Renderer);
  this->Window->AddRenderer(this->ImageRenderer);
  this->Window->AddRenderer(this->Overlay);
}

// The frame times, and leaving the reference image when the camera moves.
void Viewer::ObserveFrames()
{
  vtkNew<vtkCallbackCommand> start, end, interaction;
  start->SetClientData(this);
  start->SetCallback(
    [](vtkObject*, unsigned long, void* c, void*) { static_cast<Viewer*>(c)->FrameStart(); });
  end->SetClientData(this);
  end->SetCallback(
    [](vtkObject*, unsigned long, void* c, void*) { static_cast<Viewer*>(c)->FrameEnd(); });
  this->Window->AddObserver(vtkCommand::StartEvent, start);
  this->Window->AddObserver(vtkCommand::EndEvent, end);
  // Moving the camera leaves the reference image (traced for one camera).
  interaction->SetClientData(this);
  interaction->SetCallback(
    [](vtkObject*, unsigned long, void* c, void*)
    {
      auto* self = static_cast<Viewer*>(c);
      if (self->Method == "reference")
      {
        self->SetMethod(self->PreviousMethod);
      }
    });
  this->Style->AddObserver(vtkCommand::StartInteractionEvent, interaction);
}

// --script: its keys one after the other (headless), or one every 100 ms through the
// interactor.
void Viewer::RunScript(bool headless)
{
  if (headless)
  {
    // Straight to the key handler: the interactor has no window to work with here.
    while (!this->Quitting && this->ScriptPosition < this->Options.Script.size())
    {
      this->Key(this->Options.Script[this->ScriptPosition++]);
    }
  }
  else if (!this->Options.Script.empty())
  {
    vtkNew<vtkCallbackCommand> tick;
    tick->SetClientData(this);
    tick->SetCallback(ScriptTick);
    this->Interactor->AddObserver(vtkCommand::TimerEvent, tick);
    this->ScriptTimer = this->Interactor->CreateRepeatingTimer(100);
  }
}

void Viewer::ReleasePasses()
{
  // The renderer releases only the pass it has now; every pass is released while the context
  // exists (vtkSSAOPass frees its textures, framebuffer and quads only there, not when deleted:
  // LeakSanitizer showed them after a session that had used s and then n).
  this->Renderer->ReleaseGraphicsResources(this->Window);
  this->HAO->ReleaseGraphicsResources(this->Window);
  this->AOV->ReleaseGraphicsResources(this->Window);
  this->SSAO->ReleaseGraphicsResources(this->Window);
}

int Viewer::Run()
{
  this->AddScene();
  this->SetUpWindow();
  this->Style->Owner = this;
  this->Interactor->SetInteractorStyle(this->Style);
  this->Interactor->SetRenderWindow(this->Window);
  this->ObserveFrames();

  // Headless windows (VTK 9.4+: EGL, OSMesa) have no event loop: there a --script runs its
  // keys one after the other, and without one there is nothing to view.
  const std::string windowClass = this->Window->GetClassName();
  const bool headless =
    windowClass == "vtkEGLRenderWindow" || windowClass == "vtkOSOpenGLRenderWindow";
  this->Headless = headless;
  if (headless && this->Options.Script.empty())
  {
    throw std::runtime_error("view: no display (rendering through " + windowClass +
      "): set DISPLAY to an X server, or give --script KEYS to run the keys without one");
  }
  this->Interactor->Initialize();
  this->SetMethod(this->Options.Method);
  this->UpdateText();
  this->Window->Render();
  std::cout << "vtkao view: press ? in the window for the keys\n" << std::flush;
  this->RunScript(headless);
  if (!headless)
  {
    vtkNew<vtkCallbackCommand> refine;
    refine->SetClientData(this);
    refine->SetCallback(RefineTick);
    this->Interactor->AddObserver(vtkCommand::TimerEvent, refine);
    this->RefineTimer = this->Interactor->CreateRepeatingTimer(10);
    this->Interactor->Start();
  }
  this->ReleasePasses();
  return this->ScreenshotFailed ? 1 : 0;
}
}

//------------------------------------------------------------------------------
int View(int argc, char* argv[])
{
  ViewOptions options = ParseViewOptions(argc, argv);
  vtkao::RequireRenderingContext();
  Viewer viewer(options);
  return viewer.Run();
}
}
