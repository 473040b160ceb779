// The pass leaves the OpenGL state as it found it. Part 1 reads the state with raw glGet calls
// at the start and end of the renderer's Render() (the renderer's StartEvent and EndEvent),
// once with the delegate alone and once with the pass around it, and requires equal end
// states; it also requires vtkOpenGLState's cache and the shader cache to agree with OpenGL.
// Part 2 draws other renderers after the AO renderer: a neighbouring viewport and an overlay
// layer sharing the depth buffer. Their flat-coloured actors keep their exact colours and the
// depth test against the AO renderer's geometry still hides what lies behind it.
#include "vtkAOGL.h"
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkCallbackCommand.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

#include <map>
#include <string>
#include <vector>

namespace
{
using State = std::map<std::string, std::vector<long long>>;

State ReadGLState()
{
  State s;
  auto ints = [&](const char* name, GLenum pname, int n)
  {
    GLint v[4] = { 0, 0, 0, 0 };
    glGetIntegerv(pname, v);
    s[name].assign(v, v + n);
  };
  auto bools = [&](const char* name, GLenum pname, int n)
  {
    GLboolean v[4] = { 0, 0, 0, 0 };
    glGetBooleanv(pname, v);
    s[name].assign(v, v + n);
  };
  auto floats = [&](const char* name, GLenum pname)
  {
    GLfloat v = 0;
    glGetFloatv(pname, &v);
    s[name] = { static_cast<long long>(v * 1000) };
  };
  auto enabled = [&](const char* name, GLenum cap) { s[name] = { glIsEnabled(cap) ? 1 : 0 }; };
  ints("draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING, 1);
  ints("read framebuffer", GL_READ_FRAMEBUFFER_BINDING, 1);
  ints("draw buffer 0", GL_DRAW_BUFFER0, 1);
  ints("read buffer", GL_READ_BUFFER, 1);
  ints("viewport", GL_VIEWPORT, 4);
  ints("scissor box", GL_SCISSOR_BOX, 4);
  enabled("scissor test", GL_SCISSOR_TEST);
  enabled("depth test", GL_DEPTH_TEST);
  bools("depth mask", GL_DEPTH_WRITEMASK, 1);
  ints("depth func", GL_DEPTH_FUNC, 1);
  enabled("blend", GL_BLEND);
  ints("blend src rgb", GL_BLEND_SRC_RGB, 1);
  ints("blend dst rgb", GL_BLEND_DST_RGB, 1);
  ints("blend src alpha", GL_BLEND_SRC_ALPHA, 1);
  ints("blend dst alpha", GL_BLEND_DST_ALPHA, 1);
  ints("blend equation", GL_BLEND_EQUATION_RGB, 1);
  enabled("cull face", GL_CULL_FACE);
  ints("cull face mode", GL_CULL_FACE_MODE, 1);
  bools("color mask", GL_COLOR_WRITEMASK, 4);
  ints("active texture", GL_ACTIVE_TEXTURE, 1);
  enabled("polygon offset fill", GL_POLYGON_OFFSET_FILL);
  floats("polygon offset factor", GL_POLYGON_OFFSET_FACTOR);
  floats("polygon offset units", GL_POLYGON_OFFSET_UNITS);
  enabled("color logic op", GL_COLOR_LOGIC_OP);
  ints("logic op mode", GL_LOGIC_OP_MODE, 1);
  enabled("stencil test", GL_STENCIL_TEST);
  ints("pack alignment", GL_PACK_ALIGNMENT, 1);
  ints("unpack alignment", GL_UNPACK_ALIGNMENT, 1);
  return s;
}

struct Recorder
{
  vtkOpenGLRenderWindow* Window = nullptr;
  State Start, End;
  int CacheMismatches = 0;
  std::string CacheReport;
};

// vtkOpenGLState's cached values and the shader cache must describe the real state: VTK skips
// GL calls whose cached value already matches, so a stale cache breaks later rendering.
void CheckCaches(Recorder* r, const State& gl)
{
  vtkOpenGLState* ostate = r->Window->GetState();
  auto compare = [&](const char* name, const std::vector<long long>& cached)
  {
    if (cached != gl.at(name))
    {
      ++r->CacheMismatches;
      r->CacheReport += std::string(" ") + name;
    }
  };
  auto cachedInts = [&](GLenum pname, int n)
  {
    int v[4] = { 0, 0, 0, 0 };
    ostate->vtkglGetIntegerv(pname, v);
    return std::vector<long long>(v, v + n);
  };
  compare("viewport", cachedInts(GL_VIEWPORT, 4));
  compare("scissor box", cachedInts(GL_SCISSOR_BOX, 4));
  compare("draw framebuffer", cachedInts(GL_DRAW_FRAMEBUFFER_BINDING, 1));
  compare("read framebuffer", cachedInts(GL_READ_FRAMEBUFFER_BINDING, 1));
  compare("blend src rgb", cachedInts(GL_BLEND_SRC_RGB, 1));
  compare("blend dst rgb", cachedInts(GL_BLEND_DST_RGB, 1));
  compare("blend", { ostate->GetEnumState(GL_BLEND) ? 1 : 0 });
  compare("depth test", { ostate->GetEnumState(GL_DEPTH_TEST) ? 1 : 0 });
  compare("cull face", { ostate->GetEnumState(GL_CULL_FACE) ? 1 : 0 });
  compare("scissor test", { ostate->GetEnumState(GL_SCISSOR_TEST) ? 1 : 0 });
  vtkShaderProgram* bound = r->Window->GetShaderCache()->GetLastShaderBound();
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  if (bound && bound->GetHandle() != static_cast<unsigned int>(program))
  {
    ++r->CacheMismatches;
    r->CacheReport += " current program";
  }
}

void OnStart(vtkObject*, unsigned long, void* clientData, void*)
{
  auto r = static_cast<Recorder*>(clientData);
  r->Start = ReadGLState();
}

void OnEnd(vtkObject*, unsigned long, void* clientData, void*)
{
  auto r = static_cast<Recorder*>(clientData);
  r->End = ReadGLState();
  CheckCaches(r, r->End);
}

std::string Differences(const State& a, const State& b)
{
  std::string out;
  for (const auto& item : a)
  {
    if (b.at(item.first) != item.second)
    {
      out += " " + item.first + " (";
      for (long long v : item.second)
      {
        out += std::to_string(v) + " ";
      }
      out += "vs ";
      for (long long v : b.at(item.first))
      {
        out += std::to_string(v) + " ";
      }
      out += ")";
    }
  }
  return out.empty() ? " none" : out;
}

/// The RGB of pixel (x, y) of the window's back buffer.
std::vector<int> Pixel(vtkRenderWindow* win, int x, int y)
{
  int width = 0;
  const vtkSmartPointer<vtkUnsignedCharArray> rgb = vtkAOTest::GrabRGB(win, width);
  const vtkIdType i = static_cast<vtkIdType>(y) * width + x;
  return {
    rgb->GetTypedComponent(i, 0), rgb->GetTypedComponent(i, 1), rgb->GetTypedComponent(i, 2)
  };
}

bool Near(const std::vector<int>& a, int r, int g, int b)
{
  return std::abs(a[0] - r) <= 1 && std::abs(a[1] - g) <= 1 && std::abs(a[2] - b) <= 1;
}

vtkSmartPointer<vtkActor> FlatQuad(vtkRenderer* ren,
  double x0,
  double x1,
  double y,
  double z0,
  double z1,
  double r,
  double g,
  double b)
{
  vtkNew<vtkPlaneSource> quad;
  quad->SetOrigin(x0, y, z0);
  quad->SetPoint1(x0, y, z1);
  quad->SetPoint2(x1, y, z0);
  auto actor = vtkAOTest::AddActor(ren, quad);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}
}

int TestHAOGLState(int, char*[])
{
  using namespace vtkAOTest;

  // Part 1: raw GL state around the AO renderer's Render().
  {
    vtkNew<vtkRenderer> ren;
    auto win = MakeWindow(200, 200, ren);
    AddSphereOnGround(ren);
    Recorder recorder;
    recorder.Window = vtkOpenGLRenderWindow::SafeDownCast(win);
    vtkNew<vtkCallbackCommand> start, end;
    start->SetCallback(OnStart);
    start->SetClientData(&recorder);
    end->SetCallback(OnEnd);
    end->SetClientData(&recorder);
    ren->AddObserver(vtkCommand::StartEvent, start);
    ren->AddObserver(vtkCommand::EndEvent, end);

    vtkNew<vtkRenderStepsPass> basic;
    ren->SetPass(basic);
    win->Render();
    win->Render();
    const State plainStart = recorder.Start, plainEnd = recorder.End;
    const int plainCache = recorder.CacheMismatches;
    std::printf(
      "delegate alone: start -> end changes:%s\n", Differences(plainStart, plainEnd).c_str());

    recorder.CacheMismatches = 0;
    auto hao = InstallHAO(ren, 2.0);
    win->Render(); // voxelizes
    const State haoStart1 = recorder.Start, haoEnd1 = recorder.End;
    win->Render(); // static scene: no voxelization
    const State haoStart2 = recorder.Start, haoEnd2 = recorder.End;
    Check(hao->GetLastFrameHadOcclusion(), "the pass applied occlusion");
    std::printf(
      "with the pass, frame 1: end vs delegate alone:%s\n", Differences(haoEnd1, plainEnd).c_str());
    std::printf(
      "with the pass, frame 2: end vs delegate alone:%s\n", Differences(haoEnd2, plainEnd).c_str());
    Check(haoStart1 == plainStart && haoStart2 == plainStart,
      "the renderer starts from the same state in every frame");
    Check(haoEnd1 == plainEnd,
      "frame with voxelization: the GL state after Render() equals "
      "the state after the delegate alone");
    Check(haoEnd2 == plainEnd,
      "frame without voxelization: the GL state after Render() "
      "equals the state after the delegate alone");
    std::printf("cache mismatches: delegate alone %d, with the pass %d:%s\n",
      plainCache,
      recorder.CacheMismatches,
      recorder.CacheReport.c_str());
    Check(plainCache == 0 && recorder.CacheMismatches == 0,
      "vtkOpenGLState's cache and the shader cache agree with OpenGL after Render()");

    // The same for Ambient Occlusion Volumes, every pixel and with the filter stage.
    for (int scale : { 1, 2 })
    {
      ren->SetPass(nullptr);
      hao->ReleaseGraphicsResources(win);
      vtkNew<vtkAmbientOcclusionVolumesPass> aov;
      aov->SetDelegatePass(basic);
      aov->SetRadius(0.5); // the state is the point, not the occlusion: keep it cheap
      aov->SetAOScale(scale);
      ren->SetPass(aov);
      recorder.CacheMismatches = 0;
      recorder.CacheReport.clear();
      win->Render();
      win->Render();
      const std::string label = "AOV, AOScale " + std::to_string(scale) + ": ";
      std::printf(
        "%send vs delegate alone:%s\n", label.c_str(), Differences(recorder.End, plainEnd).c_str());
      Check(aov->GetLastFrameHadOcclusion(), label + "the pass applied occlusion");
      Check(recorder.End == plainEnd,
        label + "the GL state after Render() equals the state after the delegate alone");
      Check(recorder.CacheMismatches == 0,
        label + "vtkOpenGLState's cache agrees with OpenGL after Render()" + recorder.CacheReport);
      ren->SetPass(nullptr);
      aov->ReleaseGraphicsResources(win);
    }
    ren->ReleaseGraphicsResources(win);
  }

  // Part 2: renderers drawn after the AO renderer.
  {
    auto win = MakeWindow(300, 150);
    // Left half: the AO renderer, layer 0.
    vtkNew<vtkRenderer> ren;
    ren->SetViewport(0, 0, 0.5, 1);
    ren->SetBackground(0, 0, 0);
    AddGround(ren, 5);
    AddSphere(ren, 0, 0);
    TopView(ren, 0, 0, 12);
    win->AddRenderer(ren);
    // Right half: a neighbour, layer 0, drawn after it: a flat quad on a grey background.
    vtkNew<vtkRenderer> neighbour;
    neighbour->SetViewport(0.5, 0, 1, 1);
    neighbour->SetBackground(0.5, 0.5, 0.5);
    FlatQuad(neighbour, -1, 1, 0, -1, 1, 0.2, 0.6, 0.8);
    TopView(neighbour, 0, 0, 12);
    win->AddRenderer(neighbour);
    // Overlay on the left half, layer 1, same camera, sharing the AO renderer's depth buffer:
    // a green marker above everything and a red quad below the ground (must stay hidden).
    vtkNew<vtkRenderer> overlay;
    overlay->SetViewport(0, 0, 0.5, 1);
    overlay->SetLayer(1);
    overlay->PreserveDepthBufferOn();
    overlay->SetActiveCamera(ren->GetActiveCamera());
    FlatQuad(overlay, 1.5, 2.5, 3, 1.5, 2.5, 0.0, 0.8, 0.4);
    FlatQuad(overlay, -4, 4, -0.5, -4, 4, 1.0, 0.0, 0.0);
    win->SetNumberOfLayers(2);
    win->AddRenderer(overlay);

    auto measure = [&](const char* what)
    {
      win->Render();
      // Left half: 150 x 150, 17.2 px per unit on the ground, origin at (75, 75).
      // The marker's centre (2, 3, 2), 9 below the camera: 22.9 px per unit there.
      const std::vector<int> marker = Pixel(win, 75 + 46, 75 - 46);
      const std::vector<int> sphereTop = Pixel(win, 75, 75);
      const std::vector<int> openGround = Pixel(win, 20, 130);
      const std::vector<int> neighbourQuad = Pixel(win, 225, 75);
      const std::vector<int> neighbourBack = Pixel(win, 290, 10);
      std::printf("%s: marker %d %d %d, sphere top %d %d %d, open ground %d %d %d, neighbour "
                  "quad %d %d %d, neighbour background %d %d %d\n",
        what,
        marker[0],
        marker[1],
        marker[2],
        sphereTop[0],
        sphereTop[1],
        sphereTop[2],
        openGround[0],
        openGround[1],
        openGround[2],
        neighbourQuad[0],
        neighbourQuad[1],
        neighbourQuad[2],
        neighbourBack[0],
        neighbourBack[1],
        neighbourBack[2]);
      const std::string w = std::string(what) + ": ";
      Check(Near(marker, 0, 204, 102), w + "the overlay's marker keeps its exact colour");
      Check(
        !(sphereTop[0] > 200 && sphereTop[1] < 30), w + "the red quad behind the sphere is hidden");
      Check(!(openGround[0] > 200 && openGround[1] < 30),
        w + "the red quad under the ground is hidden");
      Check(Near(neighbourQuad, 51, 153, 204), w + "the neighbour's quad keeps its exact colour");
      Check(Near(neighbourBack, 128, 128, 128) || Near(neighbourBack, 127, 127, 127),
        w + "the neighbour's background keeps its exact colour");
      return openGround;
    };
    // The pass first, in the fresh window: the depth the overlay tests against is then only
    // what the pass wrote (nothing else writes the window's depth buffer in that frame).
    auto hao = InstallHAO(ren, 2.0);
    const std::vector<int> haoGround = measure("with the pass");
    Check(hao->GetLastFrameHadOcclusion(), "the pass applied occlusion");
    measure("with the pass, second frame");
    vtkNew<vtkRenderStepsPass> basic;
    ren->SetPass(basic);
    const std::vector<int> plainGround = measure("delegate alone");
    Check(std::abs(haoGround[0] - plainGround[0]) <= 2,
      "open ground looks the same with and without the pass (A = 1 there)");
    win->RemoveRenderer(overlay);
    win->RemoveRenderer(neighbour);
    ren->ReleaseGraphicsResources(win);
  }
  return Result();
}
