#include "vtkAOHemisphereBaker.h"

#include "vtkAOBakingOpenGL.h"
#include "vtkFloatArray.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace
{
// The hemicube of one vertex, unfolded into its tile (tile coordinates T in [-1, 1]^2, the
// tile's 2 Resolution pixels): the front face (axis n) fills |T| <= 1/2, the side faces (axes
// +t, -t, +b, -b) the four arms, their horizon on the tile's border. One instanced draw per
// face, instance = vertex of the batch. Every face's image is linear in the point, so the whole
// mapping is a clip-space position; five clip distances keep each face inside its part of the tile
// and in front of the eye. Black geometry on the white atlas; beyond the radius a fragment is
// discarded.
const char* CoverageVS = R"(//VTK::System::Dec
in vec3 vertexMC;    // scene point, relative to the centre
in vec3 eyeMC;       // per instance: p + bias n, relative to the centre
in vec3 tangentMC;   // t
in vec3 bitangentMC; // b
in vec3 normalMC;    // n
uniform int face;    // 0 front, 1 +t, 2 -t, 3 +b, 4 -b
uniform vec2 tiles;  // tiles per row, rows
uniform int tilesPerRow;
uniform float nearDistance;
out vec3 offsetVC;
void main()
{
  int tile = gl_InstanceID;
  vec3 d = vertexMC - eyeMC;
  vec3 l = vec3(dot(d, tangentMC), dot(d, bitangentMC), dot(d, normalMC));
  float w;     // depth along the face's axis
  float c;     // across the face
  float h;     // up the face (the height above the tangent plane on the side faces)
  float lower; // the face's lower edge: h >= -w (front), h >= 0 (sides)
  vec2 t;      // tile coordinates times w
  if (face == 0)
  {
    w = l.z; c = l.x; h = l.y; lower = w + h;
    t = 0.5 * vec2(c, h);
  }
  else if (face == 1)
  {
    w = l.x; c = l.y; h = l.z; lower = h;
    t = vec2(w - 0.5 * h, 0.5 * c);
  }
  else if (face == 2)
  {
    w = -l.x; c = l.y; h = l.z; lower = h;
    t = vec2(0.5 * h - w, 0.5 * c);
  }
  else if (face == 3)
  {
    w = l.y; c = l.x; h = l.z; lower = h;
    t = vec2(0.5 * c, w - 0.5 * h);
  }
  else
  {
    w = -l.y; c = l.x; h = l.z; lower = h;
    t = vec2(0.5 * c, 0.5 * h - w);
  }
  gl_ClipDistance[0] = w - c;
  gl_ClipDistance[1] = w + c;
  gl_ClipDistance[2] = w - h;
  gl_ClipDistance[3] = lower;
  gl_ClipDistance[4] = w - nearDistance;
  vec2 cell = vec2(float(tile % tilesPerRow), float(tile / tilesPerRow));
  // Atlas NDC = (T + 1 + 2 cell) / tiles - 1, times w.
  gl_Position = vec4((t + (vec2(1.0) + 2.0 * cell - tiles) * w) / tiles, 0.0, w);
  offsetVC = d;
}
)";

const char* CoverageFS = R"(//VTK::System::Dec
in vec3 offsetVC;
uniform float radius2; // squared radius, 0 = infinity
//VTK::Output::Dec
void main()
{
  if (radius2 > 0.0 && dot(offsetVC, offsetVC) > radius2)
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0);
}
)";

// One fragment per tile: the weighted sum of its white pixels (the corners have no weight and
// are skipped).
const char* ReduceFS = R"(//VTK::System::Dec
in vec2 texCoord; // the quad's texture coordinates, (i + 1/2) / tiles at tile i
uniform sampler2D coverage;
uniform sampler2D weights;
uniform vec2 tiles;   // tiles per row, rows
uniform int tileSize; // 2 Resolution
//VTK::Output::Dec
void main()
{
  ivec2 origin = ivec2(floor(texCoord * tiles)) * tileSize;
  int quarter = tileSize / 4;
  float open = 0.0;
  for (int y = 0; y < tileSize; ++y)
  {
    bool band = y >= quarter && y < tileSize - quarter;
    int first = band ? 0 : quarter;
    int last = band ? tileSize : tileSize - quarter;
    for (int x = first; x < last; ++x)
    {
      open += texelFetch(weights, ivec2(x, y), 0).r *
        texelFetch(coverage, origin + ivec2(x, y), 0).r;
    }
  }
  gl_FragData[0] = vec4(open);
}
)";

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// The delta form factors of a tile of 2 resolution x 2 resolution pixels (row major, bottom row
// first), zero in the corners and outside the cone of half-angle spread * pi/2, summing to 1.
std::vector<float> HemicubeWeights(int resolution, double spread)
{
  const int tile = 2 * resolution;
  const double minimumCosine = std::cos(spread * vtkMath::Pi() / 2.0);
  std::vector<double> weights(static_cast<size_t>(tile) * tile, 0.0);
  double sum = 0.0;
  for (int pass = 0; pass < 2 && !(sum > 0.0); ++pass)
  {
    for (int py = 0; py < tile; ++py)
    {
      for (int px = 0; px < tile; ++px)
      {
        const double tx = (px + 0.5) / resolution - 1.0;
        const double ty = (py + 0.5) / resolution - 1.0;
        double across = 0.0, height = 1.0, weight = 0.0;
        if (std::fabs(tx) < 0.5 && std::fabs(ty) < 0.5)
        {
          across = 2.0 * tx; // the front face at (x, y, 1): cos = 1 / r
          const double y = 2.0 * ty;
          const double r2 = across * across + y * y + 1.0;
          weight = 1.0 / (r2 * r2);
          height = 1.0 / std::sqrt(r2);
        }
        else if (std::fabs(tx) < 0.5 || std::fabs(ty) < 0.5)
        {
          // A side face at (x, z): z = the height above the tangent plane, cos = z / r.
          const double z = 2.0 * (1.0 - std::max(std::fabs(tx), std::fabs(ty)));
          across = 2.0 * (std::fabs(tx) < 0.5 ? tx : ty);
          const double r2 = across * across + z * z + 1.0;
          weight = z / (r2 * r2);
          height = z / std::sqrt(r2);
        }
        // The first pass keeps the cone; if no pixel centre lies in it, the second keeps the
        // four pixels around the axis.
        const bool keep = pass == 0
          ? height >= minimumCosine
          : std::fabs(tx) < 1.0 / resolution && std::fabs(ty) < 1.0 / resolution;
        if (weight > 0.0 && keep)
        {
          weights[static_cast<size_t>(py) * tile + px] = weight;
          sum += weight;
        }
      }
    }
  }
  std::vector<float> normalised(weights.size());
  for (size_t i = 0; i < weights.size(); ++i)
  {
    normalised[i] = static_cast<float>(weights[i] / sum);
  }
  return normalised;
}
}

//------------------------------------------------------------------------------
class vtkAOHemisphereBaker::vtkInternals : public vtkAOOpenGLBaker::vtkContextResources
{
public:
  vtkOpenGLRenderWindow* Context = nullptr; // the window the resources below belong to
  vtkSmartPointer<vtkTextureObject> Atlas;  // R8: 1 = white (open), 0 = black (occluder)
  vtkSmartPointer<vtkOpenGLFramebufferObject> AtlasFramebuffer;
  vtkSmartPointer<vtkTextureObject> Sums; // R32F: one texel per tile
  vtkSmartPointer<vtkOpenGLFramebufferObject> SumsFramebuffer;
  vtkSmartPointer<vtkTextureObject> Weights; // R32F: the tile's delta form factors
  vtkSmartPointer<vtkOpenGLBufferObject> Points;
  vtkSmartPointer<vtkOpenGLBufferObject> Indices;
  vtkSmartPointer<vtkOpenGLBufferObject> Instances;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> Layout;
  std::unique_ptr<vtkOpenGLQuadHelper> Reduce;
  int AtlasSize[2] = { 0, 0 };
  int SumsSize[2] = { 0, 0 };

  // One execution (BakePoints), shared by its steps.
  struct Execution
  {
    double Center[3] = { 0, 0, 0 }; // of the bounds; the scene and eyes are relative to it
    std::vector<vtkIdType> Order;   // the rendered points, instance order
    std::vector<float> Frames;      // per rendered point: eye, t, b, n (12 floats)
    int Resolution = 0;             // even
    int Tile = 0;                   // 2 Resolution
    int Batch = 0;                  // points per atlas
    int TilesPerRow = 0;
    int Rows = 0;
    size_t TriangleCount = 0;
    vtkShaderProgram* Program = nullptr; // the hemicube shader
  };
  Execution Run;

  void ReleaseBuffers()
  {
    for (auto* buffer : { this->Points.Get(), this->Indices.Get(), this->Instances.Get() })
    {
      if (buffer)
      {
        buffer->ReleaseGraphicsResources();
      }
    }
    if (this->Layout)
    {
      this->Layout->ReleaseGraphicsResources();
    }
    this->Points = this->Indices = this->Instances = nullptr;
    this->Layout = nullptr;
  }

  void Release() override
  {
    if (this->Context)
    {
      this->Context->MakeCurrent();
      for (auto* framebuffer : { this->AtlasFramebuffer.Get(), this->SumsFramebuffer.Get() })
      {
        if (framebuffer)
        {
          framebuffer->ReleaseGraphicsResources(this->Context);
        }
      }
      for (auto* texture : { this->Atlas.Get(), this->Sums.Get(), this->Weights.Get() })
      {
        if (texture)
        {
          texture->ReleaseGraphicsResources(this->Context);
        }
      }
      this->ReleaseBuffers();
      if (this->Reduce)
      {
        this->Reduce->ReleaseGraphicsResources(this->Context);
      }
    }
    this->AtlasFramebuffer = this->SumsFramebuffer = nullptr;
    this->Atlas = this->Sums = this->Weights = nullptr;
    this->Points = this->Indices = this->Instances = nullptr;
    this->Layout = nullptr;
    this->Reduce.reset();
    this->AtlasSize[0] = this->AtlasSize[1] = this->SumsSize[0] = this->SumsSize[1] = 0;
    this->Context = nullptr;
  }

  // A single-channel texture (R8 or R32F) of width x height and a framebuffer around it.
  bool Target(vtkSmartPointer<vtkTextureObject>& texture,
    vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
    int current[2],
    int width,
    int height,
    int type)
  {
    if (framebuffer && current[0] == width && current[1] == height)
    {
      return true;
    }
    if (framebuffer)
    {
      framebuffer->ReleaseGraphicsResources(this->Context);
      texture->ReleaseGraphicsResources(this->Context);
    }
    current[0] = current[1] = 0;
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(this->Context);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    if (!texture->Allocate2D(width, height, 1, type))
    {
      framebuffer = nullptr;
      return false;
    }
    framebuffer->SetContext(this->Context);
    framebuffer->SaveCurrentBindingsAndBuffers();
    framebuffer->Bind();
    framebuffer->AddColorAttachment(0, texture);
    const char* status = nullptr;
    const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
    framebuffer->UnBind();
    framebuffer->RestorePreviousBindingsAndBuffers();
    if (!complete)
    {
      framebuffer->ReleaseGraphicsResources(this->Context);
      framebuffer = nullptr;
      return false;
    }
    current[0] = width;
    current[1] = height;
    return true;
  }
};

vtkStandardNewMacro(vtkAOHemisphereBaker);

//------------------------------------------------------------------------------
vtkAOHemisphereBaker::vtkAOHemisphereBaker()
  : Internals(new vtkInternals)
{
  this->ContextResources.reset(this->Internals);
}

vtkAOHemisphereBaker::~vtkAOHemisphereBaker() = default;

//------------------------------------------------------------------------------
void vtkAOHemisphereBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "BatchSize: " << this->BatchSize << " (effective " << this->EffectiveBatchSize
     << ")\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "NumberOfBatches: " << this->NumberOfBatches << "\n";
  os << indent << "NumberOfRenderedPoints: " << this->NumberOfRenderedPoints << "\n";
}

double vtkAOHemisphereBaker::GetVerticesPerSecond() const
{
  return this->TotalTime > 0.0 ? this->NumberOfRenderedPoints / this->TotalTime : 0.0;
}

//------------------------------------------------------------------------------
void vtkAOHemisphereBaker::InitializeResults(vtkIdType numberOfPoints)
{
  this->Superclass::InitializeResults(numberOfPoints);
  this->NumberOfRenderedPoints = 0;
  this->NumberOfBatches = this->EffectiveBatchSize = 0;
}

//------------------------------------------------------------------------------
int vtkAOHemisphereBaker::BakePoints(Surface& surface, float* values)
{
  this->NumberOfTriangles = static_cast<vtkIdType>(surface.GetNumberOfTriangles());
  this->PlaceEyes(surface);
  if (!this->PrepareAtlas() || !this->PrepareScene(surface))
  {
    return 0;
  }
  const auto renderStart = Clock::now();
  this->RenderBatches(values);
  vtkOpenGLCheckErrorMacro("failed after rendering the hemicubes");
  this->RenderTime = Seconds(renderStart);
  return 1;
}

//------------------------------------------------------------------------------
// Every baked point's eye p + bias n (relative to the centre of the bounds) and frame (t, b, n):
// 12 floats, one instance each.
void vtkAOHemisphereBaker::PlaceEyes(const Surface& surface)
{
  auto& run = this->Internals->Run;
  Center(surface.Bounds, run.Center);
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : AutomaticBias(surface.Bounds);
  run.Order = surface.Baked;
  run.Frames.clear();
  run.Frames.reserve(12 * run.Order.size());
  vtkPoints* points = surface.Input->GetPoints();
  for (vtkIdType i : run.Order)
  {
    double p[3], t[3], b[3];
    points->GetPoint(i, p);
    const double* nrm = &surface.Normals[3 * i];
    vtkAOBaking::Basis(nrm, t, b);
    for (int d = 0; d < 3; ++d)
    {
      run.Frames.push_back(static_cast<float>(p[d] - run.Center[d] + this->EffectiveBias * nrm[d]));
    }
    const double* axes[3] = { t, b, nrm };
    for (const double* axis : axes)
    {
      run.Frames.insert(run.Frames.end(),
        { static_cast<float>(axis[0]), static_cast<float>(axis[1]), static_cast<float>(axis[2]) });
    }
  }
  this->NumberOfRenderedPoints = static_cast<vtkIdType>(run.Order.size());
}

//------------------------------------------------------------------------------
// The context, the batch layout (tiles per row and rows of the atlas), the atlas and the
// per-tile sums, and the tile's weights.
bool vtkAOHemisphereBaker::PrepareAtlas()
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLRenderWindow* context = this->MakeContext();
  if (!context)
  {
    return false;
  }
  if (internals.Context != context)
  {
    internals.Release();
    internals.Context = context;
  }
  run.Resolution = this->Resolution + this->Resolution % 2;
  run.Tile = 2 * run.Resolution;
  const int largest = std::min(4096, vtkTextureObject::GetMaximumTextureSize(context));
  const int perRow = std::max(1, largest / run.Tile);
  run.Batch = static_cast<int>(std::min<vtkIdType>({ static_cast<vtkIdType>(this->BatchSize),
    static_cast<vtkIdType>(perRow) * perRow,
    static_cast<vtkIdType>(run.Order.size()) }));
  run.TilesPerRow =
    std::min(perRow, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(run.Batch)))));
  run.Rows = (run.Batch + run.TilesPerRow - 1) / run.TilesPerRow;
  this->EffectiveBatchSize = run.Batch;
  if (!internals.Target(internals.Atlas,
        internals.AtlasFramebuffer,
        internals.AtlasSize,
        run.TilesPerRow * run.Tile,
        run.Rows * run.Tile,
        VTK_UNSIGNED_CHAR) ||
    !internals.Target(internals.Sums,
      internals.SumsFramebuffer,
      internals.SumsSize,
      run.TilesPerRow,
      run.Rows,
      VTK_FLOAT))
  {
    vtkErrorMacro(<< "Couldn't create a " << run.TilesPerRow * run.Tile << "x"
                  << run.Rows * run.Tile << " hemicube atlas.");
    internals.Release();
    return false;
  }
  const std::vector<float> weights = HemicubeWeights(run.Resolution, this->Spread);
  if (internals.Weights)
  {
    internals.Weights->ReleaseGraphicsResources(context);
  }
  internals.Weights = vtkSmartPointer<vtkTextureObject>::New();
  internals.Weights->SetContext(context);
  internals.Weights->SetMinificationFilter(vtkTextureObject::Nearest);
  internals.Weights->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!internals.Weights->Create2DFromRaw(
        run.Tile, run.Tile, 1, VTK_FLOAT, const_cast<float*>(weights.data())))
  {
    vtkErrorMacro(<< "Couldn't upload the hemicube weights.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The hemicube and reduction shaders, the scene (drawn indexed) and the eyes (instances).
bool vtkAOHemisphereBaker::PrepareScene(Surface& surface)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLRenderWindow* context = internals.Context;
  run.Program = context->GetShaderCache()->ReadyShaderProgram(CoverageVS, CoverageFS, "");
  if (!run.Program || !run.Program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the hemicube shader.");
    return false;
  }
  internals.ReleaseBuffers();
  run.TriangleCount = surface.GetNumberOfTriangles();
  internals.Instances = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Instances->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  if (!vtkAOBaking::UploadScene(
        surface.Points, surface.Triangles, run.Center, internals.Points, internals.Indices) ||
    !internals.Instances->Upload(run.Frames, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload " << run.TriangleCount << " triangles.");
    return false;
  }
  internals.Layout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  if (!internals.Reduce)
  {
    internals.Reduce.reset(new vtkOpenGLQuadHelper(context, nullptr, ReduceFS, ""));
  }
  if (!internals.Reduce->Program || !internals.Reduce->Program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the hemicube reduction shader.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The batches: their hemicubes into the atlas, then one sum per tile. The OpenGL state that is
// touched is saved and restored (the window may belong to someone else).
void vtkAOHemisphereBaker::RenderBatches(float* values)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLState* state = internals.Context->GetState();
  vtkAOBaking::ScopedDrawState stateSaver(state,
    { GL_BLEND,
      GL_DEPTH_TEST,
      GL_CULL_FACE,
      GL_SCISSOR_TEST,
      GL_CLIP_DISTANCE0,
      GL_CLIP_DISTANCE1,
      GL_CLIP_DISTANCE2,
      GL_CLIP_DISTANCE3,
      GL_CLIP_DISTANCE4 });
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
  internals.AtlasFramebuffer->SaveCurrentBindingsAndBuffers();
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);

  this->UpdateProgress(0.0);
  const vtkIdType rendered = static_cast<vtkIdType>(run.Order.size());
  for (vtkIdType first = 0; first < rendered && !this->GetAbortExecute(); first += run.Batch)
  {
    const int count = static_cast<int>(std::min<vtkIdType>(run.Batch, rendered - first));
    if (!this->RenderHemicubes(first, count))
    {
      break;
    }
    this->SumTiles(first, count, values);
    ++this->NumberOfBatches;
    this->UpdateProgress(static_cast<double>(first + count) / rendered);
  }
  internals.SumsFramebuffer->UnBind();
  internals.AtlasFramebuffer->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
// The hemicubes of the batch's count points from first on, black on white: five instanced
// draws, one per face.
bool vtkAOHemisphereBaker::RenderHemicubes(vtkIdType first, int count)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLState* state = internals.Context->GetState();
  internals.AtlasFramebuffer->Bind();
  state->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
  internals.AtlasFramebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, internals.AtlasSize[0], internals.AtlasSize[1]);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  for (int plane = 0; plane < 5; ++plane)
  {
    state->vtkglEnable(GL_CLIP_DISTANCE0 + plane);
  }
  vtkShaderProgram* program = run.Program;
  internals.Context->GetShaderCache()->ReadyShaderProgram(program);
  const float tiles[2] = { static_cast<float>(run.TilesPerRow), static_cast<float>(run.Rows) };
  const double radius = this->Radius;
  program->SetUniform2f("tiles", tiles);
  program->SetUniformi("tilesPerRow", run.TilesPerRow);
  program->SetUniformf("nearDistance", static_cast<float>(0.01 * this->EffectiveBias));
  program->SetUniformf(
    "radius2", radius > 0.0 ? static_cast<float>(std::min(radius * radius, 1e30)) : 0.0f);
  internals.Layout->Bind();
  const int stride = 12 * sizeof(float);
  const int offset = static_cast<int>(first * stride);
  bool bound = internals.Layout->AddAttributeArray(
    program, internals.Points, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
  const char* names[4] = { "eyeMC", "tangentMC", "bitangentMC", "normalMC" };
  for (int a = 0; a < 4; ++a)
  {
    bound = bound &&
      internals.Layout->AddAttributeArrayWithDivisor(program,
        internals.Instances,
        names[a],
        offset + 3 * a * static_cast<int>(sizeof(float)),
        stride,
        VTK_FLOAT,
        3,
        false,
        1,
        false);
  }
  if (bound)
  {
    internals.Indices->Bind(); // recorded in the vertex array object
    for (int face = 0; face < 5; ++face)
    {
      program->SetUniformi("face", face);
      glDrawElementsInstanced(
        GL_TRIANGLES, static_cast<GLsizei>(3 * run.TriangleCount), GL_UNSIGNED_INT, nullptr, count);
    }
  }
  internals.Layout->Release();
  if (!bound)
  {
    vtkErrorMacro(<< "Couldn't bind the vertex layout.");
    return false;
  }
  for (int plane = 0; plane < 5; ++plane)
  {
    state->vtkglDisable(GL_CLIP_DISTANCE0 + plane);
  }
  return true;
}

//------------------------------------------------------------------------------
// Every tile's weighted white fraction, one texel each, read back in one go: A of the batch's
// points.
void vtkAOHemisphereBaker::SumTiles(vtkIdType first, int count, float* values)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLState* state = internals.Context->GetState();
  internals.SumsFramebuffer->Bind();
  state->vtkglDrawBuffer(GL_NONE);
  internals.SumsFramebuffer->ActivateDrawBuffers(1);
  internals.SumsFramebuffer->ActivateReadBuffer(0);
  state->vtkglViewport(0, 0, run.TilesPerRow, run.Rows);
  vtkShaderProgram* program = internals.Reduce->Program;
  internals.Context->GetShaderCache()->ReadyShaderProgram(program);
  internals.Atlas->Activate();
  internals.Weights->Activate();
  const float tiles[2] = { static_cast<float>(run.TilesPerRow), static_cast<float>(run.Rows) };
  program->SetUniformi("coverage", internals.Atlas->GetTextureUnit());
  program->SetUniformi("weights", internals.Weights->GetTextureUnit());
  program->SetUniform2f("tiles", tiles);
  program->SetUniformi("tileSize", run.Tile);
  internals.Reduce->Render();
  internals.Weights->Deactivate();
  internals.Atlas->Deactivate();
  std::vector<float> sums(static_cast<size_t>(run.TilesPerRow) * run.Rows);
  glReadPixels(0, 0, run.TilesPerRow, run.Rows, GL_RED, GL_FLOAT, sums.data());
  for (int m = 0; m < count; ++m)
  {
    values[run.Order[first + m]] = std::max(0.0f, std::min(1.0f, sums[m]));
  }
}
