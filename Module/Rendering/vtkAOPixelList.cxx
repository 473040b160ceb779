// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAOPixelList.h"

#include "vtkAOGL.h" // transform feedback, queries
#include "vtkAOShaderUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransformFeedback.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkAOPixelList);

namespace
{
// One vertex per 4 x 4 block of pixels: the mask of its marked pixels.
const char* CompactVS = R"(//VTK::System::Dec
uniform sampler2D aoMarks;
uniform ivec2 aoSize;    // pixels
uniform int aoBlocksX;   // blocks per row
flat out int vMask;
flat out ivec2 vBase;
void main()
{
  ivec2 base = 4 * ivec2(gl_VertexID % aoBlocksX, gl_VertexID / aoBlocksX);
  int mask = 0;
  for (int k = 0; k < 16; ++k)
  {
    ivec2 p = base + ivec2(k & 3, k >> 2);
    if (all(lessThan(p, aoSize)) && texelFetch(aoMarks, p, 0).r < 0.5)
    {
      mask |= 1 << k;
    }
  }
  vMask = mask;
  vBase = base;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";

// One point per marked pixel, captured by transform feedback in emission order.
const char* CompactGS = R"(//VTK::System::Dec
layout(points) in;
layout(points, max_vertices = 16) out;
flat in int vMask[];
flat in ivec2 vBase[];
out vec4 aoListPixel;
void main()
{
  for (int k = 0; k < 16; ++k)
  {
    if ((vMask[0] & (1 << k)) != 0)
    {
      aoListPixel = vec4(vec2(vBase[0] + ivec2(k & 3, k >> 2)), 0.0, 0.0);
      gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
      EmitVertex();
      EndPrimitive();
    }
  }
}
)";

// Never runs (the rasterizer is off during the compaction); a program needs one.
const char* CompactFS = R"(//VTK::System::Dec
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(0.0);
}
)";

// One point per entry, on its pixel.
const char* ScatterVS = R"(//VTK::System::Dec
uniform samplerBuffer aoList;
uniform vec2 aoTargetSize;
flat out int vIndex;
void main()
{
  vIndex = gl_VertexID;
  vec2 p = texelFetch(aoList, gl_VertexID).xy + vec2(0.5);
  gl_Position = vec4(2.0 * p / aoTargetSize - vec2(1.0), 0.0, 1.0);
  gl_PointSize = 1.0;
}
)";

const char* ScatterFS = R"(//VTK::System::Dec
uniform sampler2D aoDense;
uniform int aoListWidth;
flat in int vIndex;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texelFetch(aoDense, ivec2(vIndex % aoListWidth, vIndex / aoListWidth), 0);
}
)";

constexpr int BlockSide = 4;
constexpr int MinimumCapacity = 16384;
}

//------------------------------------------------------------------------------
vtkAOPixelList::vtkAOPixelList() = default;

//------------------------------------------------------------------------------
vtkAOPixelList::~vtkAOPixelList()
{
  vtkAOShaderUtilities::DeleteObjects({ this->Buffer,
    this->ListTexture,
    this->Dense,
    this->Capture,
    this->Layout,
    this->FrameBufferObject });
}

//------------------------------------------------------------------------------
void vtkAOPixelList::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Count: " << this->Count << " (capacity " << this->Capacity << ")\n";
}

//------------------------------------------------------------------------------
bool vtkAOPixelList::Reserve(vtkOpenGLRenderWindow* renWin, int entries)
{
  // The dense texture holds Capacity / Width rows (within the texture size limit) and the
  // buffer texture Capacity texels (within its own limit: OpenGL guarantees only 65536, which
  // a 1080p frame's list can pass; desktop drivers allow 2^27 or more).
  int maximumSize = 4096, maximumTexels = 65536;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maximumSize);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maximumTexels);
  long long limit = std::min(static_cast<long long>(this->Width) * std::max(1, maximumSize),
    std::max<long long>(maximumTexels, this->Width) / this->Width * this->Width);
  if (this->MaximumEntries > 0)
  {
    limit = std::min<long long>(limit, this->MaximumEntries);
  }
  long long wanted = std::max<long long>(entries, MinimumCapacity);
  wanted = std::min(limit, (wanted + this->Width - 1) / this->Width * this->Width);
  if (this->Buffer && this->ListTexture && this->Dense && wanted <= this->Capacity)
  {
    return true;
  }
  vtkAOShaderUtilities::ClearErrors(); // earlier errors are not this allocation's
  this->Capacity = 0;                  // until the new storage exists
  if (!this->Buffer)
  {
    this->Buffer = vtkOpenGLBufferObject::New();
  }
  // Four floats per entry (x, y, 0, 0): RGBA32F is the buffer-texture format OpenGL 3.2 has.
  // Storage only (glBufferData with no data: VTK's Upload copies from its argument).
  if (!this->Buffer->GenerateBuffer(vtkOpenGLBufferObject::ArrayBuffer) || !this->Buffer->Bind())
  {
    return false;
  }
  glBufferData(
    GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(wanted) * 4 * sizeof(float), nullptr, GL_DYNAMIC_COPY);
  this->Buffer->Release();
  if (!this->ListTexture || this->ListTexture->GetContext() != renWin)
  {
    vtkAOShaderUtilities::ReleaseTexture(this->ListTexture, renWin);
    this->ListTexture = vtkTextureObject::New();
    this->ListTexture->SetContext(renWin);
  }
  if (!this->ListTexture->CreateTextureBuffer(
        static_cast<unsigned int>(wanted), 4, VTK_FLOAT, this->Buffer))
  {
    return false;
  }
  vtkAOShaderUtilities::EnsureFloatTexture(this->Dense,
    renWin,
    this->Width,
    static_cast<int>((wanted + this->Width - 1) / this->Width),
    2);
  if (glGetError() != GL_NO_ERROR) // GL_OUT_OF_MEMORY: the list is unusable
  {
    return false;
  }
  this->Capacity = static_cast<int>(wanted);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOPixelList::Build(vtkOpenGLRenderWindow* renWin, vtkTextureObject* marks)
{
  this->Count = 0;
  if (this->Failed || !renWin || !marks)
  {
    return false;
  }
  const int w = static_cast<int>(marks->GetWidth()), h = static_cast<int>(marks->GetHeight());
  vtkOpenGLShaderCache* cache = renWin->GetShaderCache();
  if (!this->CompactProgram)
  {
    if (!this->Capture)
    {
      this->Capture = vtkTransformFeedback::New();
      this->Capture->AddVarying(vtkTransformFeedback::Color_RGBA_F, "aoListPixel");
    }
    this->CompactProgram =
      cache->ReadyShaderProgram(CompactVS, CompactFS, CompactGS, this->Capture);
    this->ScatterProgram = cache->ReadyShaderProgram(ScatterVS, ScatterFS, "");
    if (!this->CompactProgram || !this->CompactProgram->GetCompiled() || !this->ScatterProgram ||
      !this->ScatterProgram->GetCompiled())
    {
      vtkWarningMacro("This OpenGL context cannot list the refined pixels (geometry shaders and "
                      "transform feedback): they are shaded in place.");
      this->Failed = true;
      this->CompactProgram = this->ScatterProgram = nullptr;
      return false;
    }
  }
  if (!this->Reserve(renWin, std::max(this->Capacity, w * h / 16)))
  {
    vtkWarningMacro("Could not allocate the list of refined pixels: they are shaded in place.");
    this->Failed = true;
    return false;
  }
  if (!this->Layout)
  {
    this->Layout = vtkOpenGLVertexArrayObject::New();
  }
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable discardSaver(ostate, GL_RASTERIZER_DISCARD);
  ostate->vtkglEnable(GL_RASTERIZER_DISCARD);

  const int bx = (w + BlockSide - 1) / BlockSide, by = (h + BlockSide - 1) / BlockSide;
  GLuint generated = 0;
  bool stale = false; // the buffer was reallocated after the last listing
  for (int attempt = 0; attempt < 2; ++attempt)
  {
    if (!cache->ReadyShaderProgram(this->CompactProgram, this->Capture))
    {
      return false;
    }
    marks->Activate();
    this->CompactProgram->SetUniformi("aoMarks", marks->GetTextureUnit());
    const int size[2] = { w, h };
    this->CompactProgram->SetUniform2i("aoSize", size);
    this->CompactProgram->SetUniformi("aoBlocksX", bx);
    glBindBufferBase(
      GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLuint>(this->Buffer->GetHandle()));
    glBeginQuery(GL_PRIMITIVES_GENERATED, this->Query);
    glBeginTransformFeedback(GL_POINTS);
    this->Layout->Bind();
    glDrawArrays(GL_POINTS, 0, bx * by);
    this->Layout->Release();
    glEndTransformFeedback();
    glEndQuery(GL_PRIMITIVES_GENERATED);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    marks->Deactivate();
    // The dense pass needs the count: the CPU waits here for the GPU to finish the frame's
    // work so far (the G-buffer, the trace, the filter and this compaction).
    glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &generated);
    stale = false;
    if (static_cast<long long>(generated) <= this->Capacity)
    {
      break;
    }
    // More marked pixels than room: grow (with a margin for the next frames) and list again,
    // unless the capacity is at its limit.
    const long long wanted = static_cast<long long>(generated) + generated / 4;
    const int before = this->Capacity;
    if (!this->Reserve(renWin, static_cast<int>(std::min<long long>(wanted, 1LL * w * h))))
    {
      // The buffer was reallocated but not filled: nothing listed (shaded in place).
      vtkWarningMacro("Could not grow the list of refined pixels: they are shaded in place.");
      this->Failed = true;
      return false;
    }
    if (this->Capacity == before)
    {
      break; // at its limit: the entries past it are dropped below
    }
    stale = true;
  }
  if (stale)
  {
    return false; // the count grew between the two listings (it does not, for the same marks)
  }
  const int room =
    this->MaximumEntries > 0 ? std::min(this->Capacity, this->MaximumEntries) : this->Capacity;
  if (static_cast<long long>(generated) > room)
  {
    // Only past the texture size limits (an 8K viewport refined nearly everywhere, or a
    // driver's small buffer-texture limit) or MaximumEntries: the entries past the capacity
    // keep their upsampled A.
    if (!this->WarnedTruncation)
    {
      vtkWarningMacro("Only " << room << " of " << generated
                              << " refined pixels fit the list (the GL's texture limits or "
                                 "MaximumEntries); the rest keep the reduced map.");
      this->WarnedTruncation = true;
    }
    generated = static_cast<GLuint>(room);
  }
  this->Count = static_cast<int>(generated);
  vtkOpenGLCheckErrorMacro("failed after listing the refined pixels");
  return true;
}

//------------------------------------------------------------------------------
void vtkAOPixelList::Bind(vtkShaderProgram* program)
{
  this->ListTexture->Activate();
  program->SetUniformi("aoList", this->ListTexture->GetTextureUnit());
  program->SetUniformi("aoListCount", this->Count);
  program->SetUniformi("aoListWidth", this->Width);
  program->SetUniformi("aoListRows", std::max(1, this->GetRows()));
}

//------------------------------------------------------------------------------
void vtkAOPixelList::Unbind()
{
  this->ListTexture->Deactivate();
}

//------------------------------------------------------------------------------
void vtkAOPixelList::DrawDense(vtkOpenGLRenderWindow* renWin, vtkOpenGLQuadHelper* quad)
{
  const int rows = this->GetRows();
  if (rows <= 0)
  {
    return;
  }
  // Every fragment writes its entry's result as it is: no blending, depth or scissor test.
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  auto saved =
    vtkAOShaderUtilities::SaveCapabilities(ostate, { GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST });
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  fbo->AddColorAttachment(0, this->Dense);
  ostate->vtkglDrawBuffer(GL_NONE);
  fbo->ActivateDrawBuffers(1);
  fbo->StartNonOrtho(
    static_cast<int>(this->Dense->GetWidth()), static_cast<int>(this->Dense->GetHeight()));
  ostate->vtkglViewport(0, 0, this->Width, rows);
  quad->Render();
  fbo->RemoveColorAttachment(0);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
bool vtkAOPixelList::Scatter(vtkOpenGLRenderWindow* renWin, vtkTextureObject* target)
{
  if (this->Count <= 0)
  {
    return true;
  }
  if (!this->ScatterProgram || !target)
  {
    return false;
  }
  const int w = static_cast<int>(target->GetWidth()), h = static_cast<int>(target->GetHeight());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  auto saved = vtkAOShaderUtilities::SaveCapabilities(
    ostate, { GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_PROGRAM_POINT_SIZE });
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglEnable(GL_PROGRAM_POINT_SIZE);
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  fbo->AddColorAttachment(0, target);
  ostate->vtkglDrawBuffer(GL_NONE);
  fbo->ActivateDrawBuffers(1);
  fbo->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE); // A and coverage

  if (!renWin->GetShaderCache()->ReadyShaderProgram(this->ScatterProgram))
  {
    fbo->RemoveColorAttachment(0);
    fbo->UnBind();
    fbo->RestorePreviousBindingsAndBuffers();
    return false;
  }
  this->Bind(this->ScatterProgram);
  this->Dense->Activate();
  this->ScatterProgram->SetUniformi("aoDense", this->Dense->GetTextureUnit());
  const float size[2] = { static_cast<float>(w), static_cast<float>(h) };
  this->ScatterProgram->SetUniform2f("aoTargetSize", size);
  this->Layout->Bind();
  glDrawArrays(GL_POINTS, 0, this->Count);
  this->Layout->Release();
  this->Dense->Deactivate();
  this->Unbind();

  fbo->RemoveColorAttachment(0);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOPixelList::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  if (this->Query && renWin)
  {
    glDeleteQueries(1, &this->Query);
  }
  this->Query = 0;
  vtkAOShaderUtilities::ReleaseTexture(this->ListTexture, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Dense, renWin);
  if (this->Buffer)
  {
    this->Buffer->ReleaseGraphicsResources();
    this->Buffer->Delete();
    this->Buffer = nullptr;
  }
  if (this->Layout)
  {
    this->Layout->ReleaseGraphicsResources();
    this->Layout->Delete();
    this->Layout = nullptr;
  }
  vtkAOShaderUtilities::ReleaseFramebuffer(this->FrameBufferObject, w);
  // The programs belong to the window's shader cache, which frees them with its context.
  this->CompactProgram = this->ScatterProgram = nullptr;
  this->Capacity = 0;
  this->Count = 0;
  this->Failed = false;
}

//------------------------------------------------------------------------------
long long vtkAOPixelList::GetGraphicsMemorySize()
{
  return (this->Buffer ? 16LL * this->Capacity : 0LL) +
    vtkAOShaderUtilities::TextureBytes(this->Dense);
}
