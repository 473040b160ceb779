#include "vtkAOGBufferPass.h"

#include "vtkAOGBufferFS.h"
#include "vtkAONormalResolveFS.h"
#include "vtkAOPropGeometry.h"
#include "vtkAOShaderUtilities.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkAOGBufferPass);
vtkCxxSetObjectMacro(vtkAOGBufferPass, DelegatePass, vtkRenderPass);

namespace
{
// A w x h RGBA colour attachment of renWin's context, nearest filtered, of internal format
// @p internalFormat uploaded as @p vtkType (VTK_UNSIGNED_CHAR or VTK_FLOAT).
vtkTextureObject* NewColorAttachment(vtkOpenGLRenderWindow* renWin,
  int internalFormat,
  int vtkType,
  int w,
  int h)
{
  vtkTextureObject* texture = vtkAOShaderUtilities::NewNearestTexture(renWin);
  texture->SetFormat(GL_RGBA);
  texture->SetInternalFormat(internalFormat);
  texture->SetDataType(vtkType == VTK_FLOAT ? GL_FLOAT : GL_UNSIGNED_BYTE);
  texture->Allocate2D(w, h, 4, vtkType);
  return texture;
}
}

//------------------------------------------------------------------------------
vtkAOGBufferPass::vtkAOGBufferPass() = default;

//------------------------------------------------------------------------------
vtkAOGBufferPass::~vtkAOGBufferPass()
{
  this->SetDelegatePass(nullptr);
  vtkAOShaderUtilities::DeleteObjects({ this->FrameBufferObject,
    this->ResolveFramebuffer,
    this->ColorTexture,
    this->NormalTexture,
    this->FacetTexture,
    this->DepthTexture });
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h)
{
  if (!this->ColorTexture)
  {
    this->ColorTexture = NewColorAttachment(renWin, GL_RGBA8, VTK_UNSIGNED_CHAR, w, h);
  }
  if (!this->NormalTexture)
  {
    this->NormalTexture = NewColorAttachment(renWin, GL_RGBA16F, VTK_FLOAT, w, h);
  }
  if (!this->FacetTexture)
  {
    this->FacetTexture = NewColorAttachment(renWin, GL_RGBA16F, VTK_FLOAT, w, h);
  }
  if (!this->DepthTexture)
  {
    this->DepthTexture = vtkAOShaderUtilities::NewNearestTexture(renWin);
    this->DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
  }
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  this->ColorTexture->Resize(w, h);
  this->NormalTexture->Resize(w, h);
  this->FacetTexture->Resize(w, h);
  this->DepthTexture->Resize(w, h);
  this->Size[0] = w;
  this->Size[1] = h;
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: the G-buffer stays empty.");
    return;
  }

  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->Parallel = ren->GetActiveCamera() && ren->GetActiveCamera()->GetParallelProjection();
  int w, h;
  if (s->GetFrameBuffer())
  {
    int size[2];
    s->GetWindowSize(size);
    w = size[0];
    h = size[1];
  }
  else
  {
    int x, y;
    ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  }
  this->InitializeGraphicsResources(renWin, w, h);

  // The delegate draws into our framebuffer at the origin: give it a state that says so
  // (vtkCameraPass would otherwise offset the viewport by the renderer's origin).
  vtkRenderState state(ren);
  state.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  state.SetRequiredKeys(s->GetRequiredKeys());
  state.SetFrameBuffer(this->FrameBufferObject);

  this->PreRender(&state);
  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  this->FrameBufferObject->AddColorAttachment(0, this->ColorTexture);
  this->FrameBufferObject->AddColorAttachment(1, this->NormalTexture);
  this->FrameBufferObject->AddColorAttachment(2, this->FacetTexture);
  this->FrameBufferObject->AddDepthAttachment(this->DepthTexture);
  // vtkOpenGLState caches draw buffers per framebuffer poorly when passes nest: reset it.
  renWin->GetState()->vtkglDrawBuffer(GL_NONE);
  this->FrameBufferObject->ActivateDrawBuffers(3);
  this->FrameBufferObject->StartNonOrtho(w, h);
  renWin->GetState()->vtkglViewport(0, 0, w, h);
  renWin->GetState()->vtkglScissor(0, 0, w, h);

  this->DrawnKeys.clear();
  this->NormalsCompleted = false; // set by the draws that leave normals missing
  this->DelegatePass->Render(&state);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();

  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();
  this->PostRender(&state);

  // A visible prop none of whose draws went through SetShaderParameters with its property keys
  // (a mapper outside the render-pass hooks, an empty prop) may have left depth without a
  // normal: complete the attachment. Props that draw through an internal actor (vtkLODActor
  // and ParaView's vtkPVLODActor, assemblies, image slices) hand it their keys, which is how
  // the render passes reach it. 2-D props (IsOverlay) draw no depth.
  for (int i = 0; i < s->GetPropArrayCount() && !this->NormalsCompleted; ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    this->NormalsCompleted = prop && prop->GetVisibility() && !vtkAOPropGeometry::IsOverlay(prop) &&
      this->DrawnKeys.count(prop->GetPropertyKeys()) == 0;
  }
  this->DrawnKeys.clear();
  if (this->NormalsCompleted)
  {
    this->NormalsCompleted = this->CompleteNormals(ren, renWin);
  }
  vtkOpenGLCheckErrorMacro("failed after rendering the G-buffer");
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::BindViewGeometry(vtkShaderProgram* program,
  vtkMatrix4x4* projection,
  bool parallel)
{
  this->BindDepthGeometry(program, projection, parallel);
  this->NormalTexture->Activate();
  program->SetUniformi("aoNormal", this->NormalTexture->GetTextureUnit());
  if (program->IsUniformUsed("aoFacet"))
  {
    this->FacetTexture->Activate();
    program->SetUniformi("aoFacet", this->FacetTexture->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::BindDepthGeometry(vtkShaderProgram* program,
  vtkMatrix4x4* projection,
  bool parallel)
{
  this->DepthTexture->Activate();
  program->SetUniformi("aoDepth", this->DepthTexture->GetTextureUnit());
  vtkNew<vtkMatrix4x4> invProjection;
  vtkMatrix4x4::Invert(projection, invProjection);
  vtkAOShaderUtilities::SetMatrix(program, "aoInvProjection", invProjection);
  program->SetUniform2i("aoFullSize", this->Size);
  program->SetUniformi("aoParallel", parallel ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::UnbindViewGeometry()
{
  this->NormalTexture->Deactivate();
  this->FacetTexture->Deactivate();
  this->DepthTexture->Deactivate();
}

//------------------------------------------------------------------------------
bool vtkAOGBufferPass::CompleteNormals(vtkRenderer* ren, vtkOpenGLRenderWindow* renWin)
{
  if (!this->ResolveFramebuffer)
  {
    this->ResolveFramebuffer = vtkOpenGLFramebufferObject::New();
    this->ResolveFramebuffer->SetContext(renWin);
  }
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->ResolveQuad, renWin, vtkAONormalResolveFS, this, "G-buffer normal completion"))
  {
    return false; // the stages then take the normals that are missing as facing the viewer
  }
  // The depth only: the pass draws into the normal attachment.
  this->BindDepthGeometry(this->ResolveQuad->Program,
    ren->GetActiveCamera()->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1),
    this->Parallel);

  // Over the attachment, keeping what the mappers wrote: src (1 - dst.a) + dst dst.a.
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkAOShaderUtilities::DrawQuad(
    renWin, this->ResolveFramebuffer, this->ResolveQuad.get(), this->NormalTexture, nullptr);
  this->DepthTexture->Deactivate();
  vtkOpenGLCheckErrorMacro("failed after completing the G-buffer's normals");
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOGBufferPass::PreReplaceShaderValues(std::string&,
  std::string&,
  std::string& fragmentShader,
  vtkAbstractMapper* mapper,
  vtkProp*)
{
  if (vtkPolyDataMapper::SafeDownCast(mapper))
  {
    vtkShaderProgram::Substitute(fragmentShader,
      "//VTK::Light::Impl",
      std::string("//VTK::Light::Impl\n") + vtkAOGBufferFS,
      false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOGBufferPass::PostReplaceShaderValues(std::string&,
  std::string&,
  std::string& fragmentShader,
  vtkAbstractMapper* mapper,
  vtkProp*)
{
  if (vtkPolyDataMapper::SafeDownCast(mapper))
  {
    // The polygon's own plane, exact, where the shader has the view-space position and its
    // screen derivatives span a plane; w = 0 otherwise (lines and points, whose derivatives
    // are parallel or zero, polygons seen edge-on, shaders without the position).
    // The plane's normal faces the camera on a front face (by the winding, gl_FrontFacing) and
    // away from it on a back face: the AO stages tell the two apart by it (a back face kept by
    // a depth tie at a closed mesh's silhouette, vtkAOVoxelTracerFS's aoFrontFaceAt); every
    // other use of the plane is independent of its orientation.
    const bool position = fragmentShader.find("vertexVCVSOutput") != std::string::npos;
    const bool normal = fragmentShader.find("normalVCVSOutput") != std::string::npos;
    std::string output;
    if (position)
    {
      output += "vec3 aoDx = dFdx(vertexVCVSOutput.xyz);\n"
                "vec3 aoDy = dFdy(vertexVCVSOutput.xyz);\n"
                "vec3 aoFacetVC = cross(aoDx, aoDy);\n"
                "float aoFacet2 = dot(aoFacetVC, aoFacetVC);\n"
                "vec3 aoToEyeVC = aoGBufferParallel == 1 ? vec3(0.0, 0.0, 1.0) : "
                "-vertexVCVSOutput.xyz;\n"
                "aoFacetVC *= (dot(aoFacetVC, aoToEyeVC) < 0.0) == gl_FrontFacing ? -1.0 : 1.0;\n"
                "bool aoHasFacet = aoFacet2 > 1e-8 * dot(aoDx, aoDx) * dot(aoDy, aoDy) && "
                "aoFacet2 > 0.0;\n"
                "vec4 aoFacetOut = aoHasFacet ? aoGBufferOpaque * "
                "vec4(aoFacetVC * inversesqrt(aoFacet2), 1.0) : vec4(0.0);\n"
                "gl_FragData[2] = aoFacetOut;\n";
    }
    else
    {
      output += "bool aoHasFacet = false;\n"
                "vec4 aoFacetOut = vec4(0.0);\n"
                "gl_FragData[2] = vec4(0.0);\n";
    }
    // The shading normal; where it is degenerate (zero or not a number in the data), the
    // polygon's plane, and w = 0 where that is missing too (the AO stages then take the
    // normal as facing the viewer). A shader without a normal (lighting off) writes the
    // polygon's plane where it has one and otherwise w = 0 through aoGBufferNoNormal (0): by
    // that uniform SetShaderParameters knows that the draw may leave normals for
    // CompleteNormals to rebuild from the depths.
    if (normal)
    {
      output += "vec3 aoNormalVC = normalVCVSOutput;\n"
                "gl_FragData[1] = dot(aoNormalVC, aoNormalVC) > 1e-16 ? "
                "aoGBufferOpaque * vec4(aoNormalVC, 1.0) : aoFacetOut;\n";
    }
    else
    {
      output += "gl_FragData[1] = aoHasFacet ? aoFacetOut : "
                "vec4(0.0, 0.0, 0.0, aoGBufferNoNormal);\n";
    }
    vtkShaderProgram::Substitute(fragmentShader, "//AO::GBuffer::Normal", output);
    vtkShaderProgram::Substitute(fragmentShader,
      "//VTK::System::Dec",
      "//VTK::System::Dec\nuniform float aoGBufferOpaque;\nuniform int aoGBufferParallel;\n"
      "uniform float aoGBufferNoNormal;",
      false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOGBufferPass::SetShaderParameters(vtkShaderProgram* program,
  vtkAbstractMapper* mapper,
  vtkProp* prop,
  vtkOpenGLVertexArrayObject*)
{
  if (!vtkPolyDataMapper::SafeDownCast(mapper))
  {
    // Colour only: the normals under it are left for CompleteNormals.
    this->FrameBufferObject->ActivateDrawBuffers(1);
    this->NormalsCompleted = true;
    return true;
  }
  const bool translucent = prop && prop->HasTranslucentPolygonalGeometry();
  if (prop)
  {
    this->DrawnKeys.insert(prop->GetPropertyKeys());
  }
  if (program->IsUniformUsed("aoGBufferNoNormal"))
  {
    program->SetUniformf("aoGBufferNoNormal", 0.0f);
    this->NormalsCompleted = this->NormalsCompleted || !translucent;
  }
  if (!translucent)
  {
    // A translucent prop may be drawn into another pass's framebuffer (peeling, OIT): leave
    // its draw buffers alone; its normal output has alpha 0 and blends to nothing here.
    this->FrameBufferObject->ActivateDrawBuffers(3);
  }
  if (program->IsUniformUsed("aoGBufferOpaque"))
  {
    program->SetUniformf("aoGBufferOpaque", translucent ? 0.0f : 1.0f);
  }
  if (program->IsUniformUsed("aoGBufferParallel"))
  {
    program->SetUniformi("aoGBufferParallel", this->Parallel ? 1 : 0);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAOGBufferPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->ColorTexture, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->NormalTexture, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->FacetTexture, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->DepthTexture, renWin);
  vtkAOShaderUtilities::ReleaseFramebuffer(this->FrameBufferObject, w);
  vtkAOShaderUtilities::ReleaseFramebuffer(this->ResolveFramebuffer, w);
  this->ResolveQuad.reset();
  this->Size[0] = this->Size[1] = 0;
}

//------------------------------------------------------------------------------
long long vtkAOGBufferPass::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->ColorTexture) +
    vtkAOShaderUtilities::TextureBytes(this->NormalTexture) +
    vtkAOShaderUtilities::TextureBytes(this->FacetTexture) +
    vtkAOShaderUtilities::TextureBytes(this->DepthTexture);
}
