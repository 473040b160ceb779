/**
 * Internal to vtkAO::BakingAO (not installed): what vtkAOSattlerBaker and vtkAOHemisphereBaker
 * share on top of vtkAOBaker: the OpenGL context (the given window or an off-screen one of the
 * baker's own), the scene's triangles in buffer objects, and the frame around a direction.
 */
#ifndef vtkAOBakingOpenGL_h
#define vtkAOBakingOpenGL_h

#include "vtkSmartPointer.h"

#include <cstdint> // for std::uint32_t
#include <vector>  // for std::vector

class vtkObject;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderWindow;

namespace vtkAOBaking
{
/// The context to draw in: @p window when set, else an off-screen window created in @p own on
/// first use. Made current. nullptr (with @p error set) when it is not a vtkOpenGLRenderWindow.
vtkOpenGLRenderWindow* MakeContext(vtkRenderWindow* window,
  vtkSmartPointer<vtkRenderWindow>& own,
  const char*& error);

/// Replaces the window a baker draws in (@p current, registered by @p owner) with @p window
/// and marks the owner modified. The caller releases its resources in the old one first.
void ReplaceWindow(vtkObject* owner, vtkRenderWindow*& current, vtkRenderWindow* window);

/// Uploads the scene for indexed drawing: @p points (3 per point, made relative to @p center
/// and stored as float) into a new array buffer @p pointBuffer and @p triangles into a new
/// element buffer @p indexBuffer. Both vectors are emptied (the GPU holds them now). Returns
/// false when an upload failed.
bool UploadScene(std::vector<double>& points,
  std::vector<std::uint32_t>& triangles,
  const double center[3],
  vtkSmartPointer<vtkOpenGLBufferObject>& pointBuffer,
  vtkSmartPointer<vtkOpenGLBufferObject>& indexBuffer);

/// Two unit vectors completing @p l (unit) to a right-handed orthonormal basis (u, v, l).
void Basis(const double l[3], double u[3], double v[3]);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOBakingOpenGL.h
