// Whether an OpenGL context can be made, asked before the program renders anything.
#ifndef vtkaoContext_h
#define vtkaoContext_h

namespace vtkao
{
/// Throws std::runtime_error with one line saying what to install or set when no OpenGL
/// context can be made (no X display for VTK 9.1; no X, EGL or OSMesa for VTK 9.4+). The
/// probe renders one tiny frame in a forked child, because VTK does not always report a
/// failed context: 9.1 aborts without a display, and 9.5 hands out an OSMesa window when
/// nothing else works, whose first render crashes when OSMesa cannot make a context either.
/// The answer is kept: later calls cost nothing.
void RequireRenderingContext();
}

#endif
