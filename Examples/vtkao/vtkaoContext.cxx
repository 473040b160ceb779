#include "vtkaoContext.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVersionMacros.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vtkao
{
namespace
{
// The child: make a window, render one small frame, and say through the exit status whether
// the OpenGL functions were loaded. Its output goes nowhere: VTK's warnings about each window
// system it tried are not the user's business when the parent prints one line.
[[noreturn]] void ProbeInChild()
{
  const int devnull = open("/dev/null", O_WRONLY);
  if (devnull >= 0)
  {
    dup2(devnull, STDOUT_FILENO);
    dup2(devnull, STDERR_FILENO);
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  int major = 0, minor = 0;
  if (gl)
  {
    gl->GetOpenGLVersion(major, minor);
  }
  const bool ok = major * 10 + minor >= 32; // VTK's OpenGL2 backend needs OpenGL 3.2
  std::_Exit(ok ? 0 : 3);
}

std::string Advice()
{
  std::string window;
  if (const char* forced = std::getenv("VTK_DEFAULT_OPENGL_WINDOW"))
  {
    window = std::string(" (VTK_DEFAULT_OPENGL_WINDOW=") + forced + ")";
  }
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
  return "no OpenGL context could be made" + window +
    ": VTK " VTK_VERSION " found no usable X display, EGL or OSMesa; install EGL (Debian: "
    "libegl1 libegl-mesa0, or the GPU vendor's driver) or OSMesa (libosmesa6), or set DISPLAY "
    "to a running X server; VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow or "
    "vtkOSOpenGLRenderWindow chooses one";
#else
  return "no OpenGL context could be made" + window + ": VTK " VTK_VERSION
         " renders only through X; set DISPLAY to a running X server (or run under "
         "xvfb-run -a -s \"-screen 0 1920x1080x24\"), or use the build against VTK 9.5 "
         "(scripts/setup-vtk95.sh), which renders headless through EGL or OSMesa";
#endif
}
}

void RequireRenderingContext()
{
  static int state = -1; // -1 not asked, 0 no context, 1 context
  if (state < 0)
  {
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t child = fork();
    if (child == 0)
    {
      ProbeInChild();
    }
    int status = 0;
    state = child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) &&
        WEXITSTATUS(status) == 0
      ? 1
      : 0;
  }
  if (state == 0)
  {
    throw std::runtime_error(Advice());
  }
}
}
