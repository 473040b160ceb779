#include "vtkAOBitmaskVoxelizer.h"

#include "vtkAOBitmaskVoxelizerFS.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVoxelMergeFS.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>

vtkStandardNewMacro(vtkAOBitmaskVoxelizer);

namespace
{
constexpr int SlicesPerLayer = 128; // 4 x 32-bit words per RGBA32UI texel

// A summary of an extra axis's grid (see Summaries): for each run of 32 slices k (the axis
// the merge loops over) the OR of the grid's texels there. Texel (u, k / 32 * layers + word
// block): u = y for the x grid, x for the y grid.
const char* SummaryFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform usampler3D aoAxis;
uniform int aoAlongFirst; // 1: the slices are the texture's first coordinate, 0: its second
out uvec4 fragOutput0;
void main()
{
  ivec3 size = textureSize(aoAxis, 0);
  int slices = aoAlongFirst != 0 ? size.x : size.y;
  ivec2 outSize = ivec2(aoAlongFirst != 0 ? size.y : size.x, (slices + 31) / 32 * size.z);
  ivec2 o = min(ivec2(texCoord * vec2(outSize)), outSize - 1);
  int run = o.y / size.z;
  int block = o.y - run * size.z;
  uvec4 any = uvec4(0u);
  for (int k = 32 * run; k < min(32 * run + 32, slices); ++k)
  {
    any |= texelFetch(aoAxis, aoAlongFirst != 0 ? ivec3(k, o.x, block) : ivec3(o.x, k, block), 0);
  }
  fragOutput0 = any;
}
)";

// Incremental voxelization: the base grid (the props that did not move) ORed into the grid by
// the logic op, one texel fetch per layer.
const char* BaseFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform usampler3D aoBase;
//AO::Base::Dec
void main()
{
  ivec3 size = textureSize(aoBase, 0);
  ivec2 ij = min(ivec2(texCoord * vec2(size.xy)), size.xy - 1);
//AO::Base::Outputs
}
)";

// @p source with its //AO::<tag>::Dec and //AO::<tag>::Outputs lines replaced: one output
// per layer of the grid, layer L set to value(L).
std::string LayerOutputsShader(const char* source,
  const std::string& tag,
  int layers,
  const std::function<std::string(int)>& value)
{
  std::ostringstream decl;
  std::ostringstream outputs;
  for (int layer = 0; layer < layers; ++layer)
  {
    decl << "out uvec4 fragOutput" << layer << "; // bound as gl_FragData[" << layer << "]\n";
    outputs << "  fragOutput" << layer << " = " << value(layer) << ";\n";
  }
  std::string shader = source;
  vtkShaderProgram::Substitute(shader, "//AO::" + tag + "::Dec", decl.str());
  vtkShaderProgram::Substitute(shader, "//AO::" + tag + "::Outputs", outputs.str());
  return shader;
}

void ReleaseTargetObjects(vtkTextureObject*& texture,
  vtkOpenGLFramebufferObject*& framebuffer,
  vtkWindow* w)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(w);
    texture->Delete();
    texture = nullptr;
  }
  if (framebuffer)
  {
    framebuffer->ReleaseGraphicsResources(w);
    framebuffer->Delete();
    framebuffer = nullptr;
  }
}

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
  const double u[3] = { s2, -s2, 0.0 };      // perpendicular to e2
  const double v[3] = { s6, s6, -2.0 * s6 }; // e2 x u, so (u, v, e2) is right-handed
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
  // Without a window the GL objects cannot be freed here; ReleaseGraphicsResources does that.
  for (Target* t : { &this->Targets[0], &this->Targets[1], &this->Targets[2], &this->Base })
  {
    if (t->Texture)
    {
      t->Texture->Delete();
    }
    if (t->Framebuffer)
    {
      t->Framebuffer->Delete();
    }
  }
  vtkAOShaderUtilities::DeleteObjects(
    { this->Summaries[0], this->Summaries[1], this->SummaryFramebuffer });
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "RandomRotation: " << this->RandomRotation << "\n";
  os << indent << "RotationSeed: " << this->RotationSeed << "\n";
  os << indent << "NumberOfAxes: " << this->NumberOfAxes << "\n";
  os << indent << "Region: (" << this->Region[0] << ", " << this->Region[1] << ", "
     << this->Region[2] << ", " << this->Region[3] << ", " << this->Region[4] << ", "
     << this->Region[5] << ")\n";
  os << indent << "GridDimensions: " << this->GridDimensions[0] << " x " << this->GridDimensions[1]
     << " x " << this->GridDimensions[2] << "\n";
  os << indent << "Focus: (" << this->Focus[0] << ", " << this->Focus[1] << ", " << this->Focus[2]
     << "; half-size " << this->Focus[3] << ")\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
  os << indent << "UseBase: " << this->UseBase << (this->Base.Texture ? " (base kept)" : "")
     << "\n";
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
int vtkAOBitmaskVoxelizer::GetSupportedResolution(vtkOpenGLRenderWindow* renWin)
{
  if (this->MaximumResolution == 0)
  {
    this->MaximumResolution = this->QueryMaximumResolution(renWin);
  }
  return this->MaximumResolution;
}

//------------------------------------------------------------------------------
int vtkAOBitmaskVoxelizer::UsableResolution(vtkOpenGLRenderWindow* renWin)
{
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
  return resolution;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::FitCells(const double rotatedFocus[3],
  int resolution,
  double lo[3],
  double hi[3])
{
  const double half = this->Focus[3];
  if (half > 0.0)
  {
    // A cascade: cells fixed by the focus cube, the grid clipped to the region. The grid's
    // origin stays on the focus cube's lattice, so the cells do not depend on the clipping.
    this->CellSize = 2.0 * half / resolution;
    for (int i = 0; i < 3; ++i)
    {
      const double flo = rotatedFocus[i] - half;
      const double first = std::floor((std::max(lo[i], flo) - flo) / this->CellSize);
      const double last =
        std::ceil((std::min(hi[i], rotatedFocus[i] + half) - flo) / this->CellSize);
      int n = std::max(1, std::min(resolution, static_cast<int>(last - first)));
      if (i == 2)
      {
        n = 32 * ((n + 31) / 32); // whole words along the slices
      }
      this->GridDimensions[i] = n;
      lo[i] = flo + first * this->CellSize;
      hi[i] = lo[i] + n * this->CellSize;
      // Cells count from lo along x and y, but from hi along the slices (depth 0 is the
      // near face, the largest view z).
      this->FocusCells[2 * i] = i < 2 ? -first : first + n - resolution;
      this->FocusCells[2 * i + 1] = i < 2 ? resolution - first : first + n;
    }
    return;
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
    this->FocusCells[2 * i] = -1e30;
    this->FocusCells[2 * i + 1] = 1e30;
  }
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
  if (!(diagonal > 0.0) || b[1] < b[0] || b[3] < b[2] || b[5] < b[4] ||
    !std::isfinite(this->Focus[0] + this->Focus[1] + this->Focus[2] + this->Focus[3]))
  {
    return false;
  }
  const int resolution = this->UsableResolution(renWin);

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
  const double focus[4] = { this->Focus[0], this->Focus[1], this->Focus[2], 1.0 };
  double rotatedFocus[4];
  view->MultiplyPoint(focus, rotatedFocus);
  this->FitCells(rotatedFocus, resolution, lo, hi);
  this->NumberOfLayers = (this->GridDimensions[2] + SlicesPerLayer - 1) / SlicesPerLayer;

  // Orthographic projection of that box; the near face (largest view z) maps to depth 0.
  vtkMatrix4x4* projection = this->GridProjection;
  projection->Identity();
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
  vtkMatrix4x4::Multiply4x4(ndcToGrid, projection, this->ViewToGrid);
  vtkMatrix4x4::Multiply4x4(this->ViewToGrid, view, this->WorldToGrid);
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::ReleaseTarget(int axis, vtkWindow* w)
{
  ReleaseTargetObjects(this->Targets[axis].Texture, this->Targets[axis].Framebuffer, w);
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::EnsureTarget(int axis, vtkOpenGLRenderWindow* renWin)
{
  Target& t = this->Targets[axis];
  const int width = t.Size[0], height = t.Size[1];
  const int layers = (t.Size[2] + SlicesPerLayer - 1) / SlicesPerLayer;
  if (t.Texture &&
    (t.Texture->GetContext() != renWin || static_cast<int>(t.Texture->GetWidth()) != width ||
      static_cast<int>(t.Texture->GetHeight()) != height ||
      static_cast<int>(t.Texture->GetDepth()) != layers))
  {
    this->ReleaseTarget(axis, renWin);
  }
  if (!t.Texture)
  {
    t.Texture = vtkTextureObject::New();
    t.Texture->SetContext(renWin);
    t.Texture->SetInternalFormat(GL_RGBA32UI);
    t.Texture->SetFormat(GL_RGBA_INTEGER);
    t.Texture->SetDataType(GL_UNSIGNED_INT);
    t.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    t.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    t.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    t.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    t.Texture->SetWrapR(vtkTextureObject::ClampToEdge);
    if (!t.Texture->Allocate3D(width, height, layers, 4, VTK_UNSIGNED_INT))
    {
      vtkErrorMacro(<< "Couldn't allocate a " << width << " x " << height << " x " << layers
                    << " voxel grid texture.");
      this->ReleaseTarget(axis, renWin);
      return false;
    }
  }
  if (!t.Framebuffer)
  {
    t.Framebuffer = vtkOpenGLFramebufferObject::New();
    t.Framebuffer->SetContext(renWin);
    t.Framebuffer->SaveCurrentBindingsAndBuffers();
    t.Framebuffer->Bind();
    for (int layer = 0; layer < layers; ++layer)
    {
      t.Framebuffer->AddColorAttachment(layer, t.Texture, layer);
    }
    t.Framebuffer->UnBind();
    t.Framebuffer->RestorePreviousBindingsAndBuffers();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin)
{
  // The grid itself, then one render target per extra axis, in that axis's own layout:
  // looking along grid x the pixels are (y, z) and the bits x; along grid y, (z, x) and y.
  const int* d = this->GridDimensions;
  const int sizes[3][3] = { { d[0], d[1], d[2] }, { d[1], d[2], d[0] }, { d[2], d[0], d[1] } };
  int maxLayers = 0;
  for (int a = 0; a < 3; ++a)
  {
    std::copy(sizes[a], sizes[a] + 3, this->Targets[a].Size);
    if (a < this->NumberOfAxes)
    {
      if (!this->EnsureTarget(a, renWin))
      {
        return false;
      }
      maxLayers = std::max(maxLayers, (sizes[a][2] + SlicesPerLayer - 1) / SlicesPerLayer);
    }
    else
    {
      this->ReleaseTarget(a, renWin);
    }
  }
  if (maxLayers != this->NumberOfOutputs)
  {
    this->NumberOfOutputs = maxLayers; // the fragment shader declares this many outputs
    this->ShaderStageTime.Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::AxisProjection(int axis, vtkMatrix4x4* result) const
{
  // view -> grid cells (the main voxel camera), then the axis's permutation of the cells, then
  // cells -> NDC for that axis's target.
  vtkNew<vtkMatrix4x4> permute;
  permute->Zero();
  permute->SetElement(3, 3, 1.0);
  for (int row = 0; row < 3; ++row)
  {
    permute->SetElement(row, (row + axis) % 3, 1.0);
  }
  vtkNew<vtkMatrix4x4> toNdc;
  for (int i = 0; i < 3; ++i)
  {
    toNdc->SetElement(i, i, 2.0 / this->Targets[axis].Size[i]);
    toNdc->SetElement(i, 3, -1.0);
  }
  vtkMatrix4x4::Multiply4x4(permute, this->ViewToGrid, result);
  vtkMatrix4x4::Multiply4x4(toNdc, result, result);
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
  const auto capabilitiesSaver = vtkAOShaderUtilities::SaveCapabilities(
    ostate, { GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST, GL_COLOR_LOGIC_OP });
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
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

  // One render per axis. With several axes each polygon is drawn only by the axis it faces
  // most (its slope there is at most 1 cell per pixel), so it is closed and has no spikes
  // however it is oriented; the extra axes' grids are then merged into the first.
  const GLuint zeros[4] = { 0, 0, 0, 0 };
  for (int a = 0; a < this->NumberOfAxes; ++a)
  {
    Target& t = this->Targets[a];
    const int layers = (t.Size[2] + SlicesPerLayer - 1) / SlicesPerLayer;
    t.Framebuffer->SaveCurrentBindingsAndBuffers();
    t.Framebuffer->Bind();
    ostate->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
    t.Framebuffer->ActivateDrawBuffers(layers);
    t.Framebuffer->StartNonOrtho(t.Size[0], t.Size[1]);
    ostate->vtkglViewport(0, 0, t.Size[0], t.Size[1]);
    for (int layer = 0; layer < layers; ++layer)
    {
      glClearBufferuiv(GL_COLOR, layer, zeros);
    }
    vtkNew<vtkMatrix4x4> projection;
    this->AxisProjection(a, projection);
    this->VoxelCamera->SetExplicitProjectionTransformMatrix(projection);
    this->VoxelCamera->Modified();
    this->CurrentSlices = t.Size[2];
    // The screen axes of target a are grid axes a and a + 1 (its depth is a + 2); a slope
    // limit applies along one of them only if that grid axis has its own render.
    for (int k = 0; k < 2; ++k)
    {
      const int gridAxis = (a + k) % 3;
      const int renderOfAxis = gridAxis == 2 ? 0 : gridAxis + 1; // z: 0, x: 1, y: 2
      this->CurrentSlopeLimit[k] = renderOfAxis < this->NumberOfAxes ? 1.0f : 1e30f;
    }
    this->PreRender(s);
    this->OpaquePass->Render(s);
    this->PostRender(s);
    if (a == 0)
    {
      this->NumberOfRenderedProps = this->OpaquePass->GetNumberOfRenderedProps();
    }
    t.Framebuffer->UnBind();
    t.Framebuffer->RestorePreviousBindingsAndBuffers();
  }
  this->VoxelCamera->SetExplicitProjectionTransformMatrix(this->GridProjection);

  ren->SetActiveCamera(sceneCamera);
  sceneCamera->UnRegister(this);
  for (auto& c : culling)
  {
    c.first->SetBackfaceCulling(c.second.first);
    c.first->SetFrontfaceCulling(c.second.second);
  }

  if (this->NumberOfAxes > 1)
  {
    // Over a base the props are the few that move: merge only the grid columns they can
    // touch (the extra axes' grids hold nothing elsewhere), not the whole grid.
    int columns[4] = { 0, 0, this->GridDimensions[0], this->GridDimensions[1] };
    if (this->UseBase && this->HasBase())
    {
      this->PropColumns(s, columns);
    }
    this->MergeAxes(renWin, columns);
  }
  if (this->UseBase && !this->ApplyBase(renWin))
  {
    vtkErrorMacro(<< "No base grid for this grid's frame: only this render's props are in the "
                     "grid.");
  }
  glLogicOp(GL_COPY);
  ++this->GridVersion;
  vtkOpenGLCheckErrorMacro("failed after voxelization");
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::SummarizeAxis(vtkOpenGLRenderWindow* renWin, int axis)
{
  // Axis 1 (x): the texture is (y, z, x / 128), summarized to (y, z / 32 x x / 128); axis 2
  // (y): (z, x, y / 128) to (x, z / 32 x y / 128) (z its first coordinate).
  Target& t = this->Targets[axis];
  const bool alongFirst = axis == 2;
  const int slices =
    alongFirst ? static_cast<int>(t.Texture->GetWidth()) : static_cast<int>(t.Texture->GetHeight());
  const int w =
    alongFirst ? static_cast<int>(t.Texture->GetHeight()) : static_cast<int>(t.Texture->GetWidth());
  const int h = (slices + 31) / 32 * static_cast<int>(t.Texture->GetDepth());
  vtkTextureObject*& summary = this->Summaries[axis - 1];
  if (summary &&
    (summary->GetContext() != renWin || static_cast<int>(summary->GetWidth()) != w ||
      static_cast<int>(summary->GetHeight()) != h))
  {
    vtkAOShaderUtilities::ReleaseTexture(summary, renWin);
  }
  if (!summary)
  {
    summary = vtkTextureObject::New();
    summary->SetContext(renWin);
    summary->SetInternalFormat(GL_RGBA32UI);
    summary->SetFormat(GL_RGBA_INTEGER);
    summary->SetDataType(GL_UNSIGNED_INT);
    summary->SetMinificationFilter(vtkTextureObject::Nearest);
    summary->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!summary->Allocate2D(w, h, 4, VTK_UNSIGNED_INT))
    {
      vtkAOShaderUtilities::ReleaseTexture(summary, renWin);
      return false;
    }
  }
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->SummaryQuad, renWin, SummaryFS, this, "voxel merge summary"))
  {
    return false;
  }
  vtkAOShaderUtilities::EnsureFramebuffer(this->SummaryFramebuffer, renWin);
  vtkOpenGLFramebufferObject* fbo = this->SummaryFramebuffer;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  fbo->AddColorAttachment(0, summary);
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->vtkglDrawBuffer(GL_NONE);
  fbo->ActivateDrawBuffers(1);
  ostate->vtkglViewport(0, 0, w, h);
  const GLuint zeros[4] = { 0, 0, 0, 0 };
  glClearBufferuiv(GL_COLOR, 0, zeros); // the logic op ORs into what is there
  t.Texture->Activate();
  this->SummaryQuad->Program->SetUniformi("aoAxis", t.Texture->GetTextureUnit());
  this->SummaryQuad->Program->SetUniformi("aoAlongFirst", alongFirst ? 1 : 0);
  this->SummaryQuad->Render();
  t.Texture->Deactivate();
  fbo->RemoveColorAttachment(0);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::PropColumns(const vtkRenderState* s, int columns[4]) const
{
  // The props' world bounds in cells, padded by 2 cells (a rasterized polygon's footprint
  // lies within half a cell of its own). A prop without bounds: the whole grid.
  const int* d = this->GridDimensions;
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    const double* b = s->GetPropArray()[i]->GetBounds();
    if (!b || !vtkMath::AreBoundsInitialized(b) ||
      !std::isfinite(b[0] + b[1] + b[2] + b[3] + b[4] + b[5]))
    {
      columns[0] = columns[1] = 0;
      columns[2] = d[0];
      columns[3] = d[1];
      return;
    }
    for (int c = 0; c < 8; ++c)
    {
      const double p[4] = { b[c & 1], b[2 + ((c >> 1) & 1)], b[4 + ((c >> 2) & 1)], 1.0 };
      double q[4];
      this->WorldToGrid->MultiplyPoint(p, q);
      for (int k = 0; k < 2; ++k)
      {
        lo[k] = std::min(lo[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    }
  }
  for (int k = 0; k < 2; ++k)
  {
    const double first = std::max(0.0, std::floor(lo[k]) - 2.0);
    const double last = std::min(static_cast<double>(d[k]), std::ceil(hi[k]) + 2.0);
    columns[k] = static_cast<int>(first);
    columns[2 + k] = std::max(columns[k], static_cast<int>(last));
  }
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::MergeAxes(vtkOpenGLRenderWindow* renWin, const int columns[4])
{
  // Each texel of the grid ORs in, for every slice, the bit the other axes' grids hold for
  // the same cell (a transpose; logic op OR is on).
  const int layers = this->NumberOfLayers;
  if (!this->MergeQuad || this->MergeLayers != layers)
  {
    this->MergeQuad.reset();
    this->MergeLayers = layers;
  }
  const std::string source = LayerOutputsShader(vtkAOVoxelMergeFS, "Merge", layers,
    [](int layer) { return "words[" + std::to_string(layer) + "]"; });
  // The columns each extra axis occupies first (1/128 of the merge's reads), so that the
  // merge reads the others' slices only where a polygon of that axis lies.
  for (int a = 1; a < this->NumberOfAxes; ++a)
  {
    if (!this->SummarizeAxis(renWin, a))
    {
      vtkErrorMacro(<< "Could not summarize the voxel grid of axis " << a << ".");
      return;
    }
  }
  if (!vtkAOShaderUtilities::ReadyQuad(this->MergeQuad, renWin, source, this, "voxel merge"))
  {
    return;
  }
  vtkShaderProgram* program = this->MergeQuad->Program;
  const int* d = this->GridDimensions;
  for (int a = 1; a < 3; ++a)
  {
    const bool used = a < this->NumberOfAxes;
    // an unused axis samples the first extra axis's grid again (harmless: OR)
    Target& t = this->Targets[used ? a : 1];
    t.Texture->Activate();
    program->SetUniformi(a == 1 ? "aoAxisX" : "aoAxisY", t.Texture->GetTextureUnit());
  }
  for (int a = 1; a < this->NumberOfAxes; ++a)
  {
    this->Summaries[a - 1]->Activate();
    program->SetUniformi(
      a == 1 ? "aoSummaryX" : "aoSummaryY", this->Summaries[a - 1]->GetTextureUnit());
  }
  if (this->NumberOfAxes < 3)
  {
    program->SetUniformi("aoSummaryY", this->Summaries[0]->GetTextureUnit()); // not read
  }
  program->SetUniformi("aoAxes", this->NumberOfAxes);
  program->SetUniform3f("aoGridSize",
    std::array<float, 3>{
      static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2]) }
      .data());

  this->BindGrid(renWin);
  vtkOpenGLState* ostate = renWin->GetState();
  const bool part = columns[0] > 0 || columns[1] > 0 || columns[2] < d[0] || columns[3] < d[1];
  if (part)
  {
    ostate->vtkglEnable(GL_SCISSOR_TEST); // restored by Render
    ostate->vtkglScissor(columns[0], columns[1], columns[2] - columns[0], columns[3] - columns[1]);
  }
  if (columns[2] > columns[0] && columns[3] > columns[1])
  {
    this->MergeQuad->Render();
  }
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  this->UnbindGrid();
  for (int a = 1; a < this->NumberOfAxes; ++a)
  {
    this->Targets[a].Texture->Deactivate();
    this->Summaries[a - 1]->Deactivate();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkAOBitmaskVoxelizer::GridFrame() const
{
  std::vector<double> frame(this->GridDimensions, this->GridDimensions + 3);
  frame.push_back(this->NumberOfAxes);
  const double* m = &this->WorldToGrid->Element[0][0];
  frame.insert(frame.end(), m, m + 16);
  return frame;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::RenderBase(const vtkRenderState* s)
{
  const bool useBase = this->UseBase;
  this->UseBase = false;
  this->Render(s);
  this->UseBase = useBase;
  if (this->GridDimensions[0] == 0 || !this->Targets[0].Texture)
  {
    this->ReleaseBase(s->GetRenderer()->GetRenderWindow());
    return;
  }
  // The grid becomes the base (no copy); the next Render() allocates a grid again, or takes
  // the previous base's texture, which has the same size.
  std::swap(this->Targets[0], this->Base);
  this->BaseFrame = this->GridFrame();
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::HasBase()
{
  return this->Base.Texture && this->GridDimensions[0] > 0 && this->BaseFrame == this->GridFrame();
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::ReleaseBase(vtkWindow* w)
{
  ReleaseTargetObjects(this->Base.Texture, this->Base.Framebuffer, w);
  this->BaseFrame.clear();
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::ApplyBase(vtkOpenGLRenderWindow* renWin)
{
  if (!this->HasBase())
  {
    return false;
  }
  const int layers = this->NumberOfLayers;
  if (!this->BaseQuad || this->BaseLayers != layers)
  {
    this->BaseQuad.reset();
    this->BaseLayers = layers;
  }
  // An existing quad ignores the source: compose it only to build one.
  const std::string source = this->BaseQuad ? std::string()
                                            : LayerOutputsShader(BaseFS, "Base", layers,
                                                [](int layer) {
                                                  return "texelFetch(aoBase, ivec3(ij, " +
                                                    std::to_string(layer) + "), 0)";
                                                });
  if (!vtkAOShaderUtilities::ReadyQuad(this->BaseQuad, renWin, source, this, "voxel base"))
  {
    return false;
  }
  this->BindGrid(renWin);
  this->Base.Texture->Activate();
  this->BaseQuad->Program->SetUniformi("aoBase", this->Base.Texture->GetTextureUnit());
  this->BaseQuad->Render(); // the logic op ORs it in
  this->Base.Texture->Deactivate();
  this->UnbindGrid();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::BindGrid(vtkOpenGLRenderWindow* renWin)
{
  vtkOpenGLFramebufferObject* fbo = this->Targets[0].Framebuffer;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
  fbo->ActivateDrawBuffers(this->NumberOfLayers);
  ostate->vtkglViewport(0, 0, this->GridDimensions[0], this->GridDimensions[1]);
}

//------------------------------------------------------------------------------
void vtkAOBitmaskVoxelizer::UnbindGrid()
{
  this->Targets[0].Framebuffer->UnBind();
  this->Targets[0].Framebuffer->RestorePreviousBindingsAndBuffers();
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
  decl << "uniform int aoVoxelSlices;\nuniform vec2 aoSlopeLimit;\nvec4 aoUnusedFragData[8];\n";
  std::ostringstream names;
  std::ostringstream outputs;
  for (int layer = 0; layer < this->NumberOfOutputs; ++layer)
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
    program->SetUniformi("aoVoxelSlices", this->CurrentSlices);
  }
  if (program->IsUniformUsed("aoSlopeLimit"))
  {
    program->SetUniform2f("aoSlopeLimit", this->CurrentSlopeLimit);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::DownloadGrid(std::vector<unsigned int>& words)
{
#ifndef GL_ES_VERSION_3_0
  if (!this->Targets[0].Texture || this->GridDimensions[0] == 0)
  {
    return false;
  }
  const size_t count = static_cast<size_t>(this->GridDimensions[0]) * this->GridDimensions[1] *
    this->NumberOfLayers * 4;
  words.assign(count, 0u);
  vtkAOShaderUtilities::ClearErrors(); // earlier errors are not this read-back's
  vtkOpenGLState* ostate = this->Targets[0].Texture->GetContext()->GetState();
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  this->Targets[0].Texture->Activate();
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, words.data());
  this->Targets[0].Texture->Deactivate();
  return glGetError() == GL_NO_ERROR;
#else
  (void)words;
  return false;
#endif
}

//------------------------------------------------------------------------------
bool vtkAOBitmaskVoxelizer::UploadGrid(const std::vector<unsigned int>& words)
{
  vtkTextureObject* texture = this->Targets[0].Texture;
  const size_t count = static_cast<size_t>(this->GridDimensions[0]) * this->GridDimensions[1] *
    this->NumberOfLayers * 4;
  if (!texture || this->GridDimensions[0] == 0 || words.size() != count)
  {
    return false;
  }
  vtkAOShaderUtilities::ClearErrors(); // earlier errors are not this upload's
  vtkOpenGLState* ostate = texture->GetContext()->GetState();
  ostate->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  texture->Activate();
  glTexSubImage3D(GL_TEXTURE_3D,
    0,
    0,
    0,
    0,
    this->GridDimensions[0],
    this->GridDimensions[1],
    this->NumberOfLayers,
    GL_RGBA_INTEGER,
    GL_UNSIGNED_INT,
    words.data());
  texture->Deactivate();
  ++this->GridVersion; // new contents: what was built from the grid is stale
  return glGetError() == GL_NO_ERROR;
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
  for (int a = 0; a < 3; ++a)
  {
    this->ReleaseTarget(a, w);
  }
  this->ReleaseBase(w);
  if (this->BaseQuad)
  {
    this->BaseQuad->ReleaseGraphicsResources(w);
    this->BaseQuad.reset();
  }
  if (this->MergeQuad)
  {
    this->MergeQuad->ReleaseGraphicsResources(w);
    this->MergeQuad.reset();
  }
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Summaries[0], renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Summaries[1], renWin);
  vtkAOShaderUtilities::ReleaseFramebuffer(this->SummaryFramebuffer, w);
  if (this->SummaryQuad)
  {
    this->SummaryQuad->ReleaseGraphicsResources(w);
    this->SummaryQuad.reset();
  }
  this->MaximumResolution = 0;
}

//------------------------------------------------------------------------------
long long vtkAOBitmaskVoxelizer::GetGraphicsMemorySize()
{
  long long bytes = 0;
  for (const Target& t : this->Targets)
  {
    bytes += vtkAOShaderUtilities::TextureBytes(t.Texture);
  }
  bytes += vtkAOShaderUtilities::TextureBytes(this->Base.Texture);
  return bytes + vtkAOShaderUtilities::TextureBytes(this->Summaries[0]) +
    vtkAOShaderUtilities::TextureBytes(this->Summaries[1]);
}
