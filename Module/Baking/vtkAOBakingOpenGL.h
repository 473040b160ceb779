/**
 * Internal to vtkAO::BakingAO (not installed): what vtkAOSattlerBaker and vtkAOHemisphereBaker
 * share on top of vtkAOOpenGLBaker: the scene's triangles in buffer objects, and the frame
 * around a direction.
 */
#ifndef vtkAOBakingOpenGL_h
#define vtkAOBakingOpenGL_h

#include "vtkSmartPointer.h"

#include <cstdint> // for std::uint32_t
#include <vector>  // for std::vector

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

/// Two unit vectors completing @p l (unit) to a right-handed orthonormal basis (u, v, l).
void Basis(const double l[3], double u[3], double v[3]);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOBakingOpenGL.h
