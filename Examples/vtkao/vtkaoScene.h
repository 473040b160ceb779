// Scene set-up for the vtkao program: the built-in scene and reading input files.
#ifndef vtkaoScene_h
#define vtkaoScene_h

#include <string>
#include <vector>

class vtkRenderer;

namespace vtkao
{
/// Add the built-in scene (ground, sphere in contact, a box crease, a wall outside the
/// default view) and set its camera.
void AddBuiltInScene(vtkRenderer* renderer);

/// Read @p path and add it as an actor. Throws std::runtime_error with a one-line message
/// naming the file and the problem (missing, unreadable, unknown format, no polygons).
void AddFile(vtkRenderer* renderer, const std::string& path);
}

#endif
