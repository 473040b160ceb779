// Scene set-up for the vtkao program: the built-in scene and reading input files.
#ifndef vtkaoScene_h
#define vtkaoScene_h

#include <functional>
#include <string>
#include <vector>

class vtkActor;
class vtkPolyDataMapper;
class vtkRenderer;

namespace vtkao
{
/// Add the built-in scene (ground, sphere in contact, a box and a wall making creases, a
/// slab outside the default view) and set its camera. With @p triangles > 0 the same shapes
/// are tessellated finer, to about that many triangles in all (for scaling measurements).
void AddBuiltInScene(vtkRenderer* renderer, long long triangles = 0);

/// Call @p visit for every actor of @p renderer that a vtkPolyDataMapper draws, with that
/// mapper, updated.
void ForEachPolyDataActor(vtkRenderer* renderer,
  const std::function<void(vtkActor*, vtkPolyDataMapper*)>& visit);

/// The number of triangles of the props of @p renderer (polygons and strips, triangulated).
long long CountTriangles(vtkRenderer* renderer);

/// Read @p path and add it as an actor. Throws std::runtime_error with a one-line message
/// naming the file and the problem (missing, unreadable, unknown format, no polygons).
void AddFile(vtkRenderer* renderer, const std::string& path);
}

#endif
