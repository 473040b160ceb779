/**
 * Internal to vtkAO::BakingAO (not installed): what vtkAOSattlerBaker and vtkAOHemisphereBaker
 * share on top of vtkAOOpenGLBaker: the scene's triangles in buffer objects, the frame around
 * a direction, and the OpenGL state their draws save and restore.
 */
#ifndef vtkAOBakingOpenGL_h
#define vtkAOBakingOpenGL_h

#include "vtkOpenGLState.h" // for the scoped savers
#include "vtkSmartPointer.h"

#include <cstdint>          // for std::uint32_t
#include <initializer_list> // for the capabilities
#include <memory>           // for std::unique_ptr
#include <vector>           // for std::vector

class vtkOpenGLBufferObject;

namespace vtkAOBaking
{
/// Uploads the scene for indexed drawing: @p points (3 per point, made relative to @p center
/// and stored as float) into a new array buffer @p pointBuffer and @p triangles into a new
/// element buffer @p indexBuffer. Both vectors are emptied (the GPU holds them now). Returns
/// false when an upload failed.
bool UploadScene(std::vector<double>& points,
  std::vector<std::uint32_t>& triangles,
  const double center[3],
  vtkSmartPointer<vtkOpenGLBufferObject>& pointBuffer,
  vtkSmartPointer<vtkOpenGLBufferObject>& indexBuffer);

/// Drain the errors earlier OpenGL calls left pending (at most 16), so that a later
/// glGetError() reports what followed only (vtkOpenGLClearErrorMacro does this only in builds
/// that report OpenGL errors, not in release builds).
void ClearErrors();

/// The OpenGL state a baker's draws change, saved on construction and restored on destruction
/// (the window may be the caller's): the viewport, the scissor box, the colour and depth write
/// masks, and whether each of the capabilities given (GL_BLEND, GL_DEPTH_TEST, ...) is enabled.
class ScopedDrawState
{
public:
  ScopedDrawState(vtkOpenGLState* state, std::initializer_list<unsigned int> capabilities);

private:
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  std::vector<std::unique_ptr<vtkOpenGLState::ScopedglEnableDisable>> Capabilities;
};

/// Two unit vectors completing @p l (unit) to a right-handed orthonormal basis (u, v, l).
void Basis(const double l[3], double u[3], double v[3]);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOBakingOpenGL.h
