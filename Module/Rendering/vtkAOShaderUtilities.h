/**
 * @file   vtkAOShaderUtilities.h
 * @brief  Helpers shared by the full-screen stages of the ambient-occlusion passes.
 *
 * Not a class: a handful of free functions so that the stages (G-buffer, tracer, upsampler,
 * compositor) build, bind and feed their programs, and create and free their GL objects, the
 * same way. Internal to the module.
 */
#ifndef vtkAOShaderUtilities_h
#define vtkAOShaderUtilities_h

#include "vtkOpenGLState.h" // for vtkOpenGLState::ScopedglEnableDisable

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkObject;
class vtkObjectBase;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace vtkAOShaderUtilities
{
/// The full fragment shader for @p source with the shared functions (vtkAOCommon.glsl) inserted,
/// and @p defines (preprocessor lines, say "#define AO_MARK") right after the version line
/// VTK puts in place of //VTK::System::Dec.
std::string ComposeFragmentShader(const char* source, const std::string& defines = std::string());

/// Build @p quad from @p fragmentShader on first use, otherwise bind its program.
/// Returns false (after reporting through @p owner) if the program does not compile.
bool ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* renWin,
  const std::string& fragmentShader,
  vtkObject* owner,
  const char* what);

/// ReadyQuad for a stage's own fragment shader @p source (a glsl/ file) and @p defines: the
/// shader is composed (ComposeFragmentShader) only when @p quad is built, not on every call.
bool ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* renWin,
  const char* source,
  vtkObject* owner,
  const char* what,
  const std::string& defines = std::string());

/// Draw @p quad (its program bound and fed) into the whole of @p target, attached for the draw
/// as colour attachment 0 of @p framebuffer (and @p depth, if given, as its depth attachment;
/// the caller sets the depth state); the previous framebuffer bindings are restored.
void DrawQuad(vtkOpenGLRenderWindow* renWin,
  vtkOpenGLFramebufferObject* framebuffer,
  vtkOpenGLQuadHelper* quad,
  vtkTextureObject* target,
  vtkTextureObject* depth = nullptr);

/// Upload a VTK (row-major, column-vector) matrix as a GLSL mat4.
void SetMatrix(vtkShaderProgram* program, const char* name, const vtkMatrix4x4* matrix);

/// A new 2-D texture of @p renWin's context, nearest filtered, clamped to its edges; the caller
/// sets its format and allocates it.
vtkTextureObject* NewNearestTexture(vtkOpenGLRenderWindow* renWin);

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

/// Create @p framebuffer in @p renWin's context on first use.
void EnsureFramebuffer(vtkOpenGLFramebufferObject*& framebuffer, vtkOpenGLRenderWindow* renWin);

/// Free @p framebuffer's GL object and delete it (nullptr after).
void ReleaseFramebuffer(vtkOpenGLFramebufferObject*& framebuffer, vtkWindow* window);

/// Delete each object of @p objects that is not null: a stage's destructor, where no window
/// is at hand (the GL objects are freed through their context's resource callbacks).
void DeleteObjects(std::initializer_list<vtkObjectBase*> objects);

/// Savers of the enable state of OpenGL capabilities: each restores its capability when it
/// goes.
using SavedCapabilities = std::vector<std::unique_ptr<vtkOpenGLState::ScopedglEnableDisable>>;

/// Save the enable state of each of @p capabilities (GL_BLEND, GL_DEPTH_TEST, ...), so that a
/// stage's draws leave the context as they found it.
SavedCapabilities SaveCapabilities(vtkOpenGLState* state,
  std::initializer_list<unsigned int> capabilities);

/// Drain the errors earlier OpenGL calls (the application's, VTK's, another stage's) left
/// pending, at most 16, so that a later glGetError() reports what followed only: a stage that
/// checks its own allocation or read-back must not fail on someone else's error.
/// vtkOpenGLClearErrorMacro does this only in builds that report OpenGL errors (not in
/// release builds).
void ClearErrors();

/// Bytes of GPU memory a texture's storage takes (texels x components x component size);
/// 0 for a null or unallocated texture. What the driver pads or compresses is not counted.
long long TextureBytes(vtkTextureObject* texture);
}

#endif
// VTK-HeaderTest-Exclude: vtkAOShaderUtilities.h
