#include "vtkaoContext.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVersionMacros.h"

#include <cerrno>
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
// The child: make a window, render one small frame, and write one byte to @p answer, '1' if
// the OpenGL functions were loaded. Not the exit status: a tool the program runs under may
// rewrite it (valgrind's --error-exitcode turns the child's exit into an error for the
// leaks of the libraries it loaded). Its output goes nowhere: VTK's warnings about each
// window system it tried are not the user's business when the parent prints one line.
[[noreturn]] void ProbeInChild(int answer)
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
  const char byte = ok ? '1' : '0';
  const bool told = write(answer, &byte, 1) == 1;
  std::_Exit(ok && told ? 0 : 3);
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
    // Close-on-exec: a process the driver might start must not hold the pipe open.
    int answer[2] = { -1, -1 };
    const bool piped = pipe(answer) == 0 && fcntl(answer[0], F_SETFD, FD_CLOEXEC) == 0 &&
      fcntl(answer[1], F_SETFD, FD_CLOEXEC) == 0;
    const pid_t child = piped ? fork() : -1;
    if (child == 0)
    {
      close(answer[0]);
      ProbeInChild(answer[1]);
    }
    state = 0;
    if (child > 0)
    {
      close(answer[1]);
      answer[1] = -1;
      char byte = '0';
      ssize_t got = 0;
      do
      {
        got = read(answer[0], &byte, 1);
      } while (got < 0 && errno == EINTR);
      int status = 0;
      while (waitpid(child, &status, 0) < 0 && errno == EINTR)
      {
      }
      state = got == 1 && byte == '1' ? 1 : 0;
    }
    for (int fd : answer)
    {
      if (fd >= 0)
      {
        close(fd);
      }
    }
  }
  if (state == 0)
  {
    throw std::runtime_error(Advice());
  }
}
}
