/**
 * @file   vtkAOShaderUtilities.h
 * @brief  Helpers shared by the full-screen stages of the ambient-occlusion passes.
 *
 * Not a class: a handful of free functions so that the stages (tracer, upsampler,
 * compositor) build, bind and feed their programs the same way. Internal to the module.
 */
#ifndef vtkAOShaderUtilities_h
#define vtkAOShaderUtilities_h

#include <memory>
#include <string>

class vtkMatrix4x4;
class vtkObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace vtkAOShaderUtilities
{
/// The full fragment shader for @p source with the shared functions (vtkAOCommon.glsl) inserted.
std::string ComposeFragmentShader(const char* source);

/// Build @p quad from @p fragmentShader on first use, otherwise bind its program.
/// Returns false (after reporting through @p owner) if the program does not compile.
bool ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* renWin,
  const std::string& fragmentShader,
  vtkObject* owner,
  const char* what);

/// Upload a VTK (row-major, column-vector) matrix as a GLSL mat4.
void SetMatrix(vtkShaderProgram* program, const char* name, const vtkMatrix4x4* matrix);

/// Create (or resize) a 2-D float texture of @p components channels, nearest filtered.
void EnsureFloatTexture(vtkTextureObject*& texture,
  vtkOpenGLRenderWindow* renWin,
  int width,
  int height,
  int components);

/// Create (or resize) a 32-bit float depth texture, nearest filtered, for a depth attachment.
void EnsureDepthTexture(vtkTextureObject*& texture,
  vtkOpenGLRenderWindow* renWin,
  int width,
  int height);

/// Delete a texture created by EnsureFloatTexture or EnsureDepthTexture (releasing its GL object).
void ReleaseTexture(vtkTextureObject*& texture, vtkOpenGLRenderWindow* renWin);

/// Bytes of GPU memory a texture's storage takes (texels x components x component size);
/// 0 for a null or unallocated texture. What the driver pads or compresses is not counted.
long long TextureBytes(vtkTextureObject* texture);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOShaderUtilities.h
