#include "vtkAOShaderUtilities.h"

#include "vtkAOCommon.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace vtkAOShaderUtilities
{
//------------------------------------------------------------------------------
std::string ComposeFragmentShader(const char* source, const std::string& defines)
{
  std::string fs = source;
  vtkShaderProgram::Substitute(fs, "//AO::Common", vtkAOCommon);
  if (!defines.empty())
  {
    vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines);
  }
  return fs;
}

//------------------------------------------------------------------------------
bool ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* renWin,
  const std::string& fragmentShader,
  vtkObject* owner,
  const char* what)
{
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
      fragmentShader.c_str(),
      ""));
  }
  else if (quad->Program)
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    vtkErrorWithObjectMacro(owner, << "Couldn't build the " << what << " shader program.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ReadyQuad(std::unique_ptr<vtkOpenGLQuadHelper>& quad,
  vtkOpenGLRenderWindow* renWin,
  const char* source,
  vtkObject* owner,
  const char* what,
  const std::string& defines)
{
  // An existing quad ignores the shader text: compose it only to build one.
  return ReadyQuad(
    quad, renWin, quad ? std::string() : ComposeFragmentShader(source, defines), owner, what);
}

//------------------------------------------------------------------------------
void DrawQuad(vtkOpenGLRenderWindow* renWin,
  vtkOpenGLFramebufferObject* framebuffer,
  vtkOpenGLQuadHelper* quad,
  vtkTextureObject* target,
  vtkTextureObject* depth)
{
  const int w = static_cast<int>(target->GetWidth());
  const int h = static_cast<int>(target->GetHeight());
  framebuffer->SaveCurrentBindingsAndBuffers();
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, target);
  if (depth)
  {
    framebuffer->AddDepthAttachment(depth);
  }
  renWin->GetState()->vtkglDrawBuffer(GL_NONE);
  framebuffer->ActivateDrawBuffers(1);
  framebuffer->StartNonOrtho(w, h);
  renWin->GetState()->vtkglViewport(0, 0, w, h);
  quad->Render();
  if (depth)
  {
    framebuffer->RemoveDepthAttachment();
  }
  framebuffer->RemoveColorAttachment(0);
  framebuffer->UnBind();
  framebuffer->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
void SetMatrix(vtkShaderProgram* program, const char* name, const vtkMatrix4x4* matrix)
{
  // vtkShaderProgram uploads the elements in memory order without transposing, so a VTK
  // matrix arrives in GLSL transposed: hand it the transpose.
  vtkMatrix4x4* transposed = vtkMatrix4x4::New();
  vtkMatrix4x4::Transpose(matrix, transposed);
  program->SetUniformMatrix(name, transposed);
  transposed->Delete();
}

//------------------------------------------------------------------------------
vtkTextureObject* NewNearestTexture(vtkOpenGLRenderWindow* renWin)
{
  vtkTextureObject* texture = vtkTextureObject::New();
  texture->SetContext(renWin);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture;
}

//------------------------------------------------------------------------------
// The texture of renWin's context at width x height: created by @p allocate when missing (or
// made in another context), resized when its size differs.
template<typename Allocate>
static void EnsureTexture(vtkTextureObject*& texture,
  vtkOpenGLRenderWindow* renWin,
  int width,
  int height,
  Allocate allocate)
{
  width = width < 1 ? 1 : width;
  height = height < 1 ? 1 : height;
  if (texture && texture->GetContext() != renWin)
  {
    ReleaseTexture(texture, renWin);
  }
  if (!texture)
  {
    texture = NewNearestTexture(renWin);
    allocate(texture, width, height);
  }
  else if (static_cast<int>(texture->GetWidth()) != width ||
    static_cast<int>(texture->GetHeight()) != height)
  {
    texture->Resize(width, height);
  }
}

//------------------------------------------------------------------------------
void EnsureFloatTexture(vtkTextureObject*& texture,
  vtkOpenGLRenderWindow* renWin,
  int width,
  int height,
  int components)
{
  EnsureTexture(texture,
    renWin,
    width,
    height,
    [components](vtkTextureObject* t, int w, int h)
    {
      t->SetInternalFormat(components == 2 ? GL_RG32F : GL_RGBA32F);
      t->SetFormat(components == 2 ? GL_RG : GL_RGBA);
      t->SetDataType(GL_FLOAT);
      t->Allocate2D(w, h, components, VTK_FLOAT);
    });
}

//------------------------------------------------------------------------------
void EnsureDepthTexture(vtkTextureObject*& texture,
  vtkOpenGLRenderWindow* renWin,
  int width,
  int height)
{
  EnsureTexture(texture,
    renWin,
    width,
    height,
    [](vtkTextureObject* t, int w, int h) { t->AllocateDepth(w, h, vtkTextureObject::Float32); });
}

//------------------------------------------------------------------------------
void ReleaseTexture(vtkTextureObject*& texture, vtkOpenGLRenderWindow* renWin)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(renWin);
    texture->Delete();
    texture = nullptr;
  }
}

//------------------------------------------------------------------------------
void EnsureFramebuffer(vtkOpenGLFramebufferObject*& framebuffer, vtkOpenGLRenderWindow* renWin)
{
  if (!framebuffer)
  {
    framebuffer = vtkOpenGLFramebufferObject::New();
    framebuffer->SetContext(renWin);
  }
}

//------------------------------------------------------------------------------
void ReleaseFramebuffer(vtkOpenGLFramebufferObject*& framebuffer, vtkWindow* window)
{
  if (framebuffer)
  {
    framebuffer->ReleaseGraphicsResources(window);
    framebuffer->Delete();
    framebuffer = nullptr;
  }
}

//------------------------------------------------------------------------------
void DeleteObjects(std::initializer_list<vtkObjectBase*> objects)
{
  for (vtkObjectBase* object : objects)
  {
    if (object)
    {
      object->Delete();
    }
  }
}

//------------------------------------------------------------------------------
SavedCapabilities SaveCapabilities(vtkOpenGLState* state,
  std::initializer_list<unsigned int> capabilities)
{
  SavedCapabilities savers;
  for (unsigned int capability : capabilities)
  {
    savers.emplace_back(new vtkOpenGLState::ScopedglEnableDisable(state, capability));
  }
  return savers;
}

//------------------------------------------------------------------------------
void ClearErrors()
{
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
}

//------------------------------------------------------------------------------
long long TextureBytes(vtkTextureObject* texture)
{
  if (!texture || texture->GetHandle() == 0)
  {
    return 0;
  }
  const long long texels = static_cast<long long>(texture->GetWidth()) *
    std::max(1u, texture->GetHeight()) * std::max(1u, texture->GetDepth());
  const int type = texture->GetVTKDataType();
  const int components = std::max(1, texture->GetComponents());
  int size = type == 0 ? 4 : vtkDataArray::GetDataTypeSize(type);
  // Half-float storage is uploaded from floats: its size is the internal format's.
  switch (texture->GetInternalFormat(type, components, false))
  {
    case GL_R16F:
    case GL_RG16F:
    case GL_RGB16F:
    case GL_RGBA16F:
      size = 2;
      break;
    default:
      break;
  }
  return texels * components * size;
}
}
