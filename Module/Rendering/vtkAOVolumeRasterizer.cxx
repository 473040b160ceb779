#include "vtkAOVolumeRasterizer.h"

#include "vtkAOGBufferPass.h"
#include "vtkAOOccluderTriangles.h"
#include "vtkAOPropGeometry.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVolumeFS.h"
#include "vtkAOVolumeGS.h"
#include "vtkAOVolumeInitFS.h"
#include "vtkAOVolumeVS.h"
#include "vtkMatrix4x4.h"
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

#include <algorithm>
#include <string>

vtkStandardNewMacro(vtkAOVolumeRasterizer);

namespace
{
// The pixel of its block that a texel stands for, along axis @p i.
int SampleOffset(const vtkAOVolumeRasterizer::Parameters& parameters, int i)
{
  const int s = parameters.Scale;
  return parameters.SampleOffset[i] < 0 ? s / 2 : std::min(parameters.SampleOffset[i], s - 1);
}
}

//------------------------------------------------------------------------------
vtkAOVolumeRasterizer::vtkAOVolumeRasterizer()
  : Triangulator(new vtkAOOccluderTriangles)
{
}

//------------------------------------------------------------------------------
vtkAOVolumeRasterizer::~vtkAOVolumeRasterizer()
{
  // The GL objects free themselves through their context's resource callbacks.
  if (this->Triangles)
  {
    this->Triangles->Delete();
  }
  for (vtkOpenGLVertexArrayObject* vao : this->VAOs)
  {
    if (vao)
    {
      vao->Delete();
    }
  }
  if (this->Accumulation)
  {
    this->Accumulation->Delete();
  }
  for (vtkTextureObject* texture : { this->Occlusion, this->Points, this->MapDepth })
  {
    if (texture)
    {
      texture->Delete();
    }
  }
}

//------------------------------------------------------------------------------
void vtkAOVolumeRasterizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "UpdateCount: " << this->UpdateCount << "\n";
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::UpdateOccluders(vtkOpenGLRenderWindow* renWin,
  const std::vector<vtkProp*>& props,
  const double bounds[6])
{
  // Everything the triangles depend on; properties (colour, culling) are left out.
  std::vector<double> signature;
  for (vtkProp* prop : props)
  {
    vtkAOPropGeometry::AppendSignature(prop, signature);
  }
  if (this->Triangles && this->TrianglesWindow != renWin)
  {
    // Another context: its buffer is not ours to reuse.
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  if (signature == this->Signature && this->Triangles)
  {
    return this->NumberOfTriangles > 0;
  }
  this->Signature.swap(signature);

  // World positions relative to the scene's centre (float precision where it matters).
  for (int i = 0; i < 3; ++i)
  {
    this->Origin[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
  }
  std::vector<float> vertices;
  this->Triangulator->Build(props, this->Origin, vertices);
  this->NumberOfTriangles = static_cast<vtkIdType>(vertices.size() / 12);
  ++this->UpdateCount;
  if (!this->UploadTriangles(renWin, vertices))
  {
    this->NumberOfTriangles = 0;
    this->Signature.clear();
  }
  return this->NumberOfTriangles > 0;
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::UploadTriangles(vtkOpenGLRenderWindow* renWin,
  const std::vector<float>& vertices)
{
  if (!this->Triangles)
  {
    this->Triangles = vtkOpenGLBufferObject::New();
    this->Triangles->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->TrianglesWindow = renWin;
  }
  bool ok = true;
  if (!vertices.empty() && !this->Triangles->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload the occluding triangles.");
    ok = false;
  }
  for (vtkOpenGLVertexArrayObject* vao : this->VAOs)
  {
    if (vao)
    {
      // The buffer may have been re-created: bind the attribute again.
      vao->ShaderProgramChanged();
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  vtkAOShaderUtilities::EnsureFloatTexture(this->Occlusion, renWin, w, h, 4);
  vtkAOShaderUtilities::EnsureFloatTexture(this->Points, renWin, w, h, 4);
  vtkAOShaderUtilities::EnsureDepthTexture(this->MapDepth, renWin, w, h);
  if (!this->Accumulation)
  {
    this->Accumulation = vtkOpenGLFramebufferObject::New();
  }
  this->Accumulation->SetContext(renWin);
  for (int k = 0; k < 2; ++k)
  {
    if (!this->VAOs[k])
    {
      this->VAOs[k] = vtkOpenGLVertexArrayObject::New();
    }
    const std::string define =
      std::string("#define AO_LARGE_TRIANGLES ") + (k == LARGE_TRIANGLES ? "1" : "0");
    std::string vs = vtkAOVolumeVS;
    std::string gs = vtkAOVolumeGS;
    std::string fs = vtkAOShaderUtilities::ComposeFragmentShader(vtkAOVolumeFS);
    vtkShaderProgram::Substitute(gs, "//AO::VolumeClass", define);
    vtkShaderProgram::Substitute(fs, "//AO::VolumeClass", define);
    vtkShaderProgram* program =
      renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), gs.c_str());
    if (!program || !program->GetCompiled())
    {
      vtkErrorMacro(<< "Couldn't build the ambient occlusion volume shader program.");
      this->Programs[0] = this->Programs[1] = nullptr;
      return false;
    }
    if (program != this->Programs[k])
    {
      this->Programs[k] = program;
      this->VAOs[k]->ShaderProgramChanged();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::Render(vtkOpenGLRenderWindow* renWin,
  vtkAOGBufferPass* gbuffer,
  vtkMatrix4x4* view,
  vtkMatrix4x4* projection,
  const Parameters& parameters)
{
  const int scale = parameters.Scale;
  const int w = (gbuffer->GetWidth() + scale - 1) / scale;
  const int h = (gbuffer->GetHeight() + scale - 1) / scale;
  if (!this->InitializeGraphicsResources(renWin, w, h))
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate); // the map is smaller than the screen
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);

  this->Accumulation->SaveCurrentBindingsAndBuffers();
  this->Accumulation->Bind();
  this->Accumulation->AddColorAttachment(0, this->Occlusion);
  this->Accumulation->AddColorAttachment(1, this->Points);
  this->Accumulation->AddDepthAttachment(this->MapDepth);
  ostate->vtkglDrawBuffer(GL_NONE); // see vtkAOGBufferPass: reset the draw-buffer cache
  this->Accumulation->ActivateDrawBuffers(2);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const int fullSize[2] = { gbuffer->GetWidth(), gbuffer->GetHeight() };
  const int mapSize[2] = { w, h };
  vtkNew<vtkMatrix4x4> mapProjection;
  vtkAOVolumeRasterizer::MapProjection(projection, parameters, fullSize, mapSize, mapProjection);
  const bool ok = this->RenderInitialMap(renWin, gbuffer, projection, parameters) &&
    this->RenderVolumes(renWin, parameters, view, mapProjection);
  this->Accumulation->UnBind();
  this->Accumulation->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after rendering the ambient occlusion volumes");
  return ok;
}

//------------------------------------------------------------------------------
void vtkAOVolumeRasterizer::MapProjection(vtkMatrix4x4* projection,
  const Parameters& parameters,
  const int fullSize[2],
  const int mapSize[2],
  vtkMatrix4x4* mapProjection)
{
  // Screen pixel u (from 0 at the left edge) lies at map coordinate v = (u - o - 1/2) / s +
  // 1/2: the centre of pixel b s + o is the centre of texel b. In normalized device
  // coordinates (ndc = 2 u / W - 1 on the screen, 2 v / w - 1 on the map) that is
  // ndc' = a ndc + c with a = W / (s w), c = a + (1 - (2 o + 1) / s) / w - 1, applied to
  // clip x as a x + c w. Identity for s = 1; for odd s, the centre and W = s w, too.
  const int s = parameters.Scale;
  vtkNew<vtkMatrix4x4> remap;
  for (int i = 0; i < 2; ++i)
  {
    const int o = SampleOffset(parameters, i);
    const double a = static_cast<double>(fullSize[i]) / (s * mapSize[i]);
    remap->SetElement(i, i, a);
    remap->SetElement(i, 3, a + (1.0 - (2.0 * o + 1.0) / s) / mapSize[i] - 1.0);
  }
  vtkMatrix4x4::Multiply4x4(remap, projection, mapProjection);
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::RenderInitialMap(vtkOpenGLRenderWindow* renWin,
  vtkAOGBufferPass* gbuffer,
  vtkMatrix4x4* projection,
  const Parameters& parameters)
{
  // The initial map: A = 1 with the coverage, depth and normal of each texel's pixel; the
  // points x and normals the volumes read; the pixels' depths.
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  if (!vtkAOShaderUtilities::ReadyQuad(this->InitQuad, renWin, vtkAOVolumeInitFS, this, "AO map"))
  {
    return false;
  }
  vtkShaderProgram* init = this->InitQuad->Program;
  // Depth, normal, the polygon's plane (for the normal's side), the inverse projection.
  gbuffer->BindViewGeometry(init, projection, parameters.Parallel);
  init->SetUniformi("aoScale", parameters.Scale);
  const int offset[2] = { SampleOffset(parameters, 0), SampleOffset(parameters, 1) };
  init->SetUniform2i("aoOffset", offset);
  init->SetUniformf("aoBias", static_cast<float>(parameters.Bias));
  this->InitQuad->Render();
  gbuffer->UnbindViewGeometry();
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOVolumeRasterizer::RenderVolumes(vtkOpenGLRenderWindow* renWin,
  const Parameters& parameters,
  vtkMatrix4x4* view,
  vtkMatrix4x4* mapProjection)
{
  // Each fragment writes the occlusion O_P of its triangle (in [0, 1]) and the blend removes it
  // from the map: additive, A - O_P (1 - sum, unclamped); multiplicative, A (1 - O_P), which
  // stays in [0, 1]. The map is 32-bit float, so a product of thousands of factors near 1 and
  // a sum of thousands of small terms both keep their precision.
  // The geometry shader emits the volume's faces turned away from the eye (no face culling
  // needed): a covered point x lies inside the volume, so in front of the face the pixel's ray
  // leaves by. The depth test rejects, before shading, the pixels whose visible surface lies
  // beyond that face (volumes floating in front of a farther surface or of the background).
  vtkOpenGLState* ostate = renWin->GetState();
  this->Accumulation->RemoveColorAttachment(1); // sampled now: no feedback loop
  this->Accumulation->ActivateDrawBuffers(1);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_CULL_FACE);
  GLint equation[2] = { GL_FUNC_ADD, GL_FUNC_ADD }; // not saved by vtkOpenGLState's scopes
  ostate->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, &equation[0]);
  ostate->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, &equation[1]);
  ostate->vtkglEnable(GL_BLEND);
  if (parameters.Multiplicative)
  {
    ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_ONE_MINUS_SRC_COLOR, GL_ZERO, GL_ONE);
    ostate->vtkglBlendEquation(GL_FUNC_ADD);
  }
  else
  {
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    ostate->vtkglBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  }
  ostate->vtkglColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE); // coverage, depth, normal stay

  // The triangles are stored relative to Origin.
  vtkNew<vtkMatrix4x4> modelView;
  vtkNew<vtkMatrix4x4> shift;
  for (int i = 0; i < 3; ++i)
  {
    shift->SetElement(i, 3, this->Origin[i]);
  }
  vtkMatrix4x4::Multiply4x4(view, shift, modelView);
  this->Points->Activate();
  bool ok = true;
  for (int k = 0; k < 2 && ok; ++k)
  {
    vtkShaderProgram* program = this->Programs[k];
    renWin->GetShaderCache()->ReadyShaderProgram(program, nullptr);
    program->SetUniformi("aoPoints", this->Points->GetTextureUnit());
    vtkAOShaderUtilities::SetMatrix(program, "aoModelView", modelView);
    vtkAOShaderUtilities::SetMatrix(program, "aoProjection", mapProjection);
    program->SetUniformi("aoParallel", parameters.Parallel ? 1 : 0);
    program->SetUniformf("aoRadius", static_cast<float>(parameters.Radius));
    program->SetUniformi("aoBinary", parameters.BinaryFalloff ? 1 : 0);
    vtkOpenGLVertexArrayObject* vao = this->VAOs[k];
    vao->Bind();
    vao->RemoveAttributeArray("vertexMC");
    ok = vao->AddAttributeArray(
      program, this->Triangles, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    if (!ok)
    {
      vtkErrorMacro(<< "Couldn't bind the occluding triangles to the volume shader.");
    }
    else
    {
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->NumberOfTriangles));
    }
    vao->Release();
  }
  this->Points->Deactivate();
  ostate->vtkglBlendEquationSeparate(equation[0], equation[1]);
  return ok;
}

//------------------------------------------------------------------------------
long long vtkAOVolumeRasterizer::GetGraphicsMemorySize()
{
  long long bytes = vtkAOShaderUtilities::TextureBytes(this->Occlusion) +
    vtkAOShaderUtilities::TextureBytes(this->Points) +
    vtkAOShaderUtilities::TextureBytes(this->MapDepth);
  if (this->Triangles && this->Triangles->GetHandle() != 0)
  {
    bytes += static_cast<long long>(this->NumberOfTriangles) * 12 * sizeof(float);
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkAOVolumeRasterizer::ReleaseGraphicsResources(vtkWindow* w)
{
  this->InitQuad.reset();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Occlusion, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Points, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->MapDepth, renWin);
  if (this->Accumulation)
  {
    this->Accumulation->ReleaseGraphicsResources(w);
    this->Accumulation->Delete();
    this->Accumulation = nullptr;
  }
  for (vtkOpenGLVertexArrayObject*& vao : this->VAOs)
  {
    if (vao)
    {
      vao->ReleaseGraphicsResources();
      vao->Delete();
      vao = nullptr;
    }
  }
  if (this->Triangles)
  {
    this->Triangles->ReleaseGraphicsResources();
    this->Triangles->Delete();
    this->Triangles = nullptr;
  }
  this->TrianglesWindow = nullptr;
  this->Programs[0] = this->Programs[1] = nullptr; // released with the window's shader cache
  this->Signature.clear();
}
