#include "vtkAOBakingOpenGL.h"

#include "vtkMath.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h" // glGetError (through VTK's loader)

#include <cmath>

namespace vtkAOBaking
{
//------------------------------------------------------------------------------
ScopedDrawState::ScopedDrawState(vtkOpenGLState* state,
  std::initializer_list<unsigned int> capabilities)
  : Viewport(state)
  , Scissor(state)
  , ColorMask(state)
  , DepthMask(state)
{
  for (unsigned int capability : capabilities)
  {
    this->Capabilities.emplace_back(new vtkOpenGLState::ScopedglEnableDisable(state, capability));
  }
}

//------------------------------------------------------------------------------
void ClearErrors()
{
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
}

//------------------------------------------------------------------------------
void Basis(const double l[3], double u[3], double v[3])
{
  const double helper[3] = {
    std::fabs(l[0]) < 0.9 ? 1.0 : 0.0, std::fabs(l[0]) < 0.9 ? 0.0 : 1.0, 0.0
  };
  vtkMath::Cross(helper, l, u);
  vtkMath::Normalize(u);
  vtkMath::Cross(l, u, v);
}

//------------------------------------------------------------------------------
bool UploadScene(std::vector<double>& points,
  std::vector<std::uint32_t>& triangles,
  const double center[3],
  vtkSmartPointer<vtkOpenGLBufferObject>& pointBuffer,
  vtkSmartPointer<vtkOpenGLBufferObject>& indexBuffer)
{
  std::vector<float> vertices(points.size());
  for (size_t v = 0; v < vertices.size(); ++v)
  {
    vertices[v] = static_cast<float>(points[v] - center[v % 3]);
  }
  points.clear();
  points.shrink_to_fit();
  pointBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  pointBuffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  indexBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  indexBuffer->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  const bool uploaded = pointBuffer->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer) &&
    indexBuffer->Upload(triangles, vtkOpenGLBufferObject::ElementArrayBuffer);
  triangles.clear();
  triangles.shrink_to_fit();
  return uploaded;
}
}
