#include "vtkAOBitmaskVoxelizer.h"

#include "vtkAOBitmaskVoxelizerFS.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <random>
#include <sstream>

vtkStandardNewMacro(vtkAOBitmaskVoxelizer);

namespace
{
constexpr int SlicesPerLayer = 128; // 4 x 32-bit words per RGBA32UI texel

// The voxel camera looks along the diagonal of the world axes, rolled about it by an angle
// drawn from the seed. Seen along the diagonal, every axis-aligned polygon (the bulk of CAD
// and scientific scenes) is inclined by 54.7 degrees: it has a footprint in every pixel
// column it crosses and spans at most two slices per pixel, so the slice-conservative
// rasterization closes it without spikes. A direction drawn uniformly would, for some seeds,
// look almost along one of the axes and lose the polygons parallel to it.
void DiagonalRotationMatrix(unsigned int seed, double r[3][3])
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(0.0, 2.0 * vtkMath::Pi());
  const double roll = uniform(generator);
  const double s3 = 1.0 / std::sqrt(3.0), s2 = 1.0 / std::sqrt(2.0), s6 = 1.0 / std::sqrt(6.0);
  const double e2[3] = { s3, s3, s3 };
  const double u[3] = { s2, -s2, 0.0 };         // perpendicular to e2
  const double v[3] = { s6, s6, -2.0 * s6 };    // e2 x u, so (u, v, e2) is right-handed
  const double c = std::cos(roll), s = std::sin(roll);
  for (int i = 0; i < 3; ++i)
  {
    r[i][0] = c * u[i] + s * v[i];
    r[i][1] = -s * u[i] + c * v[i];
    r[i][2] = e2[i];
  }
}
}

//------------------------------------------------------------------------------
vtkAOBitmaskVoxelizer::vtkAOBitmaskVoxelizer()
{
  this->VoxelCamera->ParallelProjectionOn();
}

//------------------------------------------------------------------------------
vtkAOBitmaskVoxelizer::~vtkAOBitmaskVoxelizer()
{
  if (this->GridTexture)
  {
    this->GridTexture->Delete();
  }
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "RandomRotation: " << this->RandomRotation << "\n";
  os << indent << "RotationSeed: " << this->RotationSeed << "\n";
  os << indent << "Region: (" << this->Region[0] << ", " << this->Region[1] << ", "
     << this->Region[2] << ", " << this->Region[3] << ", " << this->Region[4] << ", "
     << this->Region[5] << ")\n";
  os << indent << "GridDimensions: " << this->GridDimensions[0] << " x " << this->GridDimensions[1]
     << " x " << this->GridDimensions[2] << "\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
}

//------------------------------------------------------------------------------
int vtkAOBitmaskVoxelizer::QueryMaximumResolution(vtkOpenGLRenderWindow* renWin)
{
  vtkOpenGLState* ostate = renWin->GetState();
  int maxTexture = 0, max3D = 0, maxDrawBuffers = 0, maxAttachments = 0;
  int viewport[2] = { 0, 0 };
  ostate->vtkglGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  ostate->vtkglGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  ostate->vtkglGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  ostate->vtkglGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxAttachments);
  ostate->vtkglGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  int limit = std::min({ maxTexture, max3D, viewport[0], viewport[1] });
  limit = std::min(limit, SlicesPerLayer * std::min(maxDrawBuffers, maxAttachments));
  return std::max(limit, 8);
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::ComputeGridFrame(vtkOpenGLRenderWindow* renWin)
{
  const double* b = this->Region;
  for (int i = 0; i < 6; ++i)
  {
    if (!std::isfinite(b[i]))
    {
      return false;
    }
  }
  const double center[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  if (!(diagonal > 0.0) || b[1] < b[0] || b[3] < b[2] || b[5] < b[4])
  {
    return false;
  }

  if (this->MaximumResolution == 0)
  {
    this->MaximumResolution = this->QueryMaximumResolution(renWin);
  }
  int resolution = this->Resolution;
  if (resolution > this->MaximumResolution)
  {
    if (this->WarnedResolution != resolution)
    {
      vtkWarningMacro(<< "Voxel resolution " << resolution << " exceeds what this OpenGL "
                      << "implementation supports; using " << this->MaximumResolution << ".");
      this->WarnedResolution = resolution;
    }
    resolution = this->MaximumResolution;
  }

  // The voxel camera: axes e0, e1, e2 (columns of the rotation), looking along e2.
  double r[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  if (this->RandomRotation)
  {
    DiagonalRotationMatrix(this->RotationSeed, r);
  }
  vtkCamera* cam = this->VoxelCamera;
  cam->UseExplicitProjectionTransformMatrixOff();
  cam->SetFocalPoint(center);
  cam->SetPosition(
    center[0] - r[0][2] * diagonal, center[1] - r[1][2] * diagonal, center[2] - r[2][2] * diagonal);
  cam->SetViewUp(r[0][1], r[1][1], r[2][1]);
  vtkMatrix4x4* view = cam->GetViewTransformMatrix();

  // The region's extent in the voxel camera's frame.
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  for (int c = 0; c < 8; ++c)
  {
    const double p[4] = { b[c & 1], b[2 + ((c >> 1) & 1)], b[4 + ((c >> 2) & 1)], 1.0 };
    double q[4];
    view->MultiplyPoint(p, q);
    for (int i = 0; i < 3; ++i)
    {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
  }
  const double longest = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  this->CellSize = longest / resolution;
  for (int i = 0; i < 3; ++i)
  {
    int n = static_cast<int>(std::ceil((hi[i] - lo[i]) / this->CellSize - 1e-6));
    n = std::max(1, std::min(n, resolution));
    if (i == 2)
    {
      n = 32 * ((n + 31) / 32); // whole words along the slices
    }
    this->GridDimensions[i] = n;
    const double mid = 0.5 * (lo[i] + hi[i]);
    lo[i] = mid - 0.5 * n * this->CellSize;
    hi[i] = mid + 0.5 * n * this->CellSize;
  }
  this->NumberOfLayers = (this->GridDimensions[2] + SlicesPerLayer - 1) / SlicesPerLayer;

  // Orthographic projection of that box; the near face (largest view z) maps to depth 0.
  vtkNew<vtkMatrix4x4> projection;
  projection->Zero();
  projection->SetElement(0, 0, 2.0 / (hi[0] - lo[0]));
  projection->SetElement(0, 3, -(hi[0] + lo[0]) / (hi[0] - lo[0]));
  projection->SetElement(1, 1, 2.0 / (hi[1] - lo[1]));
  projection->SetElement(1, 3, -(hi[1] + lo[1]) / (hi[1] - lo[1]));
  projection->SetElement(2, 2, -2.0 / (hi[2] - lo[2]));
  projection->SetElement(2, 3, (hi[2] + lo[2]) / (hi[2] - lo[2]));
  projection->SetElement(3, 3, 1.0);
  cam->SetExplicitProjectionTransformMatrix(projection);
  cam->UseExplicitProjectionTransformMatrixOn();

  // NDC -> cells, exactly as the rasterizer maps x, y to pixels and depth to slices.
  vtkNew<vtkMatrix4x4> ndcToGrid;
  for (int i = 0; i < 3; ++i)
  {
    ndcToGrid->SetElement(i, i, 0.5 * this->GridDimensions[i]);
    ndcToGrid->SetElement(i, 3, 0.5 * this->GridDimensions[i]);
  }
  vtkMatrix4x4::Multiply4x4(projection, view, this->WorldToGrid);
  vtkMatrix4x4::Multiply4x4(ndcToGrid, this->WorldToGrid, this->WorldToGrid);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin)
{
  const int* d = this->GridDimensions;
  if (this->GridTexture &&
    (this->GridTexture->GetContext() != renWin ||
      static_cast<int>(this->GridTexture->GetWidth()) != d[0] ||
      static_cast<int>(this->GridTexture->GetHeight()) != d[1] ||
      static_cast<int>(this->GridTexture->GetDepth()) != this->NumberOfLayers))
  {
    this->GridTexture->ReleaseGraphicsResources(renWin);
    this->GridTexture->Delete();
    this->GridTexture = nullptr;
    if (this->FrameBufferObject)
    {
      this->FrameBufferObject->ReleaseGraphicsResources(renWin);
      this->FrameBufferObject->Delete();
      this->FrameBufferObject = nullptr;
    }
  }
  if (!this->GridTexture)
  {
    this->GridTexture = vtkTextureObject::New();
    this->GridTexture->SetContext(renWin);
    this->GridTexture->SetInternalFormat(GL_RGBA32UI);
    this->GridTexture->SetFormat(GL_RGBA_INTEGER);
    this->GridTexture->SetDataType(GL_UNSIGNED_INT);
    this->GridTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->GridTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->GridTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->GridTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->GridTexture->SetWrapR(vtkTextureObject::ClampToEdge);
    if (!this->GridTexture->Allocate3D(d[0], d[1], this->NumberOfLayers, 4, VTK_UNSIGNED_INT))
    {
      vtkErrorMacro(<< "Couldn't allocate the " << d[0] << " x " << d[1] << " x "
                    << this->NumberOfLayers << " voxel grid texture.");
      return false;
    }
    this->ShaderStageTime.Modified();
  }
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(renWin);
    this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
    this->FrameBufferObject->Bind();
    for (int layer = 0; layer < this->NumberOfLayers; ++layer)
    {
      this->FrameBufferObject->AddColorAttachment(layer, this->GridTexture, layer);
    }
    this->FrameBufferObject->UnBind();
    this->FrameBufferObject->RestorePreviousBindingsAndBuffers();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!renWin || !this->ComputeGridFrame(renWin) || !this->InitializeGraphicsResources(renWin))
  {
    this->GridDimensions[0] = this->GridDimensions[1] = this->GridDimensions[2] = 0;
    return;
  }

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable logicSaver(ostate, GL_COLOR_LOGIC_OP);

  const int* d = this->GridDimensions;
  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  ostate->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
  this->FrameBufferObject->ActivateDrawBuffers(this->NumberOfLayers);
  this->FrameBufferObject->StartNonOrtho(d[0], d[1]);
  ostate->vtkglViewport(0, 0, d[0], d[1]);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const GLuint zeros[4] = { 0, 0, 0, 0 };
  for (int layer = 0; layer < this->NumberOfLayers; ++layer)
  {
    glClearBufferuiv(GL_COLOR, layer, zeros);
  }
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_OR);

  // Both faces occlude: suspend culling set on properties for this render only.
  std::vector<std::pair<vtkProperty*, std::pair<bool, bool>>> culling;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkProperty* property = actor ? actor->GetProperty() : nullptr;
    if (property && (property->GetBackfaceCulling() || property->GetFrontfaceCulling()))
    {
      culling.push_back({ property,
        { property->GetBackfaceCulling() != 0, property->GetFrontfaceCulling() != 0 } });
      property->BackfaceCullingOff();
      property->FrontfaceCullingOff();
    }
  }

  vtkCamera* sceneCamera = ren->GetActiveCamera();
  sceneCamera->Register(this);
  ren->SetActiveCamera(this->VoxelCamera);

  this->PreRender(s);
  this->OpaquePass->Render(s);
  this->NumberOfRenderedProps = this->OpaquePass->GetNumberOfRenderedProps();
  this->PostRender(s);

  ren->SetActiveCamera(sceneCamera);
  sceneCamera->UnRegister(this);
  for (auto& c : culling)
  {
    c.first->SetBackfaceCulling(c.second.first);
    c.first->SetFrontfaceCulling(c.second.second);
  }

  glLogicOp(GL_COPY);
  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();
  vtkOpenGLCheckErrorMacro("failed after voxelization");
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::PostReplaceShaderValues(std::string&,
  std::string&,
  std::string& fragmentShader,
  vtkAbstractMapper* mapper,
  vtkProp*)
{
  if (!vtkPolyDataMapper::SafeDownCast(mapper))
  {
    return true;
  }
  // The mapper's colour outputs become a local array (its discard test still reads [0]).
  vtkShaderProgram::Substitute(fragmentShader, "gl_FragData[", "aoUnusedFragData[");
  std::ostringstream decl;
  decl << "uniform int aoVoxelSlices;\nvec4 aoUnusedFragData[8];\n";
  std::ostringstream names;
  std::ostringstream outputs;
  for (int layer = 0; layer < this->NumberOfLayers; ++layer)
  {
    decl << "out uvec4 fragOutput" << layer << ";\n";
    names << " gl_FragData[" << layer << "]";
    outputs << "    fragOutput" << layer << " = aoWords[" << layer << "];\n";
  }
  // vtkOpenGLShaderCache counts and binds outputs by finding gl_FragData[i] in the source.
  decl << "// integer outputs, bound in order as" << names.str() << "\n";
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec", decl.str());

  const std::string::size_type mainPos = fragmentShader.find("void main()");
  const std::string::size_type open = fragmentShader.find('{', mainPos);
  const std::string::size_type close = fragmentShader.rfind('}');
  if (mainPos == std::string::npos || open == std::string::npos || close == std::string::npos)
  {
    vtkErrorMacro(<< "Unexpected fragment shader layout; cannot voxelize with this mapper.");
    return false;
  }
  std::string bits = vtkAOBitmaskVoxelizerFS;
  vtkShaderProgram::Substitute(bits, "//AO::Voxel::Outputs", outputs.str());
  fragmentShader.insert(close, bits);
  fragmentShader.insert(open + 1, "\n  aoUnusedFragData[0] = vec4(1.0);\n");
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::SetShaderParameters(vtkShaderProgram* program,
  vtkAbstractMapper*,
  vtkProp*,
  vtkOpenGLVertexArrayObject*)
{
  if (program->IsUniformUsed("aoVoxelSlices"))
  {
    program->SetUniformi("aoVoxelSlices", this->GridDimensions[2]);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::DownloadGrid(std::vector<unsigned int>& words)
{
#ifndef GL_ES_VERSION_3_0
  if (!this->GridTexture || this->GridDimensions[0] == 0)
  {
    return false;
  }
  const size_t count = static_cast<size_t>(this->GridDimensions[0]) * this->GridDimensions[1] *
    this->NumberOfLayers * 4;
  words.assign(count, 0u);
  vtkOpenGLState* ostate = this->GridTexture->GetContext()->GetState();
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  this->GridTexture->Activate();
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, words.data());
  this->GridTexture->Deactivate();
  return glGetError() == GL_NO_ERROR;
#else
  (void)words;
  return false;
#endif
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::IsOccupied(const std::vector<unsigned int>& words,
  int i,
  int j,
  int k) const
{
  const int* d = this->GridDimensions;
  if (i < 0 || j < 0 || k < 0 || i >= d[0] || j >= d[1] || k >= d[2])
  {
    return false;
  }
  const size_t texel = (static_cast<size_t>(k / SlicesPerLayer) * d[1] + j) * d[0] + i;
  const unsigned int word = words[texel * 4 + ((k / 32) & 3)];
  return ((word >> (k & 31)) & 1u) != 0;
}

//------------------------------------------------------------------------------
long long vtkAOBitmaskVoxelizer::CountOccupiedCells()
{
  std::vector<unsigned int> words;
  if (!this->DownloadGrid(words))
  {
    return -1;
  }
  long long count = 0;
  for (unsigned int w : words)
  {
    count += std::bitset<32>(w).count();
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->OpaquePass->ReleaseGraphicsResources(w);
  if (this->GridTexture)
  {
    this->GridTexture->ReleaseGraphicsResources(w);
    this->GridTexture->Delete();
    this->GridTexture = nullptr;
  }
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->ReleaseGraphicsResources(w);
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
  this->MaximumResolution = 0;
}
