#include "vtkAOHemisphereBaker.h"

#include "vtkAOBakingGeometry.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
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
class vtkAOHemisphereBaker::vtkInternals
{
public:
  vtkSmartPointer<vtkRenderWindow> OwnWindow;
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

  void Release()
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
  this->SetNumberOfInputPorts(2);
}

vtkAOHemisphereBaker::~vtkAOHemisphereBaker()
{
  this->ReleaseGraphicsResources();
  this->SetRenderWindow(nullptr);
  delete this->Internals;
}

void vtkAOHemisphereBaker::ReleaseGraphicsResources()
{
  this->Internals->Release();
  this->Internals->OwnWindow = nullptr;
}

//------------------------------------------------------------------------------
void vtkAOHemisphereBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "BatchSize: " << this->BatchSize << " (effective " << this->EffectiveBatchSize
     << ")\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "NumberOfBatches: " << this->NumberOfBatches << "\n";
  os << indent << "NumberOfRenderedPoints: " << this->NumberOfRenderedPoints << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "RenderTime: " << this->RenderTime << "\n";
  os << indent << "TotalTime: " << this->TotalTime << "\n";
}

//------------------------------------------------------------------------------
void vtkAOHemisphereBaker::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

void vtkAOHemisphereBaker::AddOccluderData(vtkPolyData* occluder)
{
  this->AddInputData(1, occluder);
}

void vtkAOHemisphereBaker::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

void vtkAOHemisphereBaker::SetArrayName(const std::string& name)
{
  if (name != this->ArrayName)
  {
    this->ArrayName = name;
    this->Modified();
  }
}

void vtkAOHemisphereBaker::SetRenderWindow(vtkRenderWindow* window)
{
  if (window == this->RenderWindow)
  {
    return;
  }
  this->Internals->Release();
  if (this->RenderWindow)
  {
    this->RenderWindow->UnRegister(this);
  }
  this->RenderWindow = window;
  if (window)
  {
    window->Register(this);
  }
  this->Modified();
}

double vtkAOHemisphereBaker::GetVerticesPerSecond() const
{
  return this->TotalTime > 0.0 ? this->NumberOfRenderedPoints / this->TotalTime : 0.0;
}

//------------------------------------------------------------------------------
int vtkAOHemisphereBaker::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkAOHemisphereBaker::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  const auto start = Clock::now();
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  this->RenderTime = this->TotalTime = 0.0;
  this->NumberOfTriangles = this->NumberOfRenderedPoints = 0;
  this->NumberOfBatches = this->EffectiveBatchSize = 0;

  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> values;
  values->SetName(this->ArrayName.c_str());
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  values->FillValue(1.0f);
  output->GetPointData()->AddArray(values);

  vtkAOBaking::Geometry geometry;
  if (!vtkAOBaking::GatherGeometry(input, inputVector[1], geometry))
  {
    vtkErrorMacro(<< "Too many points for 32-bit indices.");
    return 0;
  }
  const size_t triangleCount = geometry.GetNumberOfTriangles();
  this->NumberOfTriangles = static_cast<vtkIdType>(triangleCount);
  if (n == 0 || triangleCount == 0)
  {
    this->TotalTime = Seconds(start);
    return 1;
  }
  vtkSmartPointer<vtkDataArray> normals = vtkAOBaking::PointNormals(input, geometry);
  if (!normals)
  {
    vtkErrorMacro(<< "Couldn't compute point normals for the input.");
    return 0;
  }

  const double* bounds = geometry.Bounds;
  const double center[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : vtkAOBaking::AutomaticBias(bounds);
  std::vector<float> vertices(geometry.Points.size());
  for (size_t v = 0; v < vertices.size(); ++v)
  {
    vertices[v] = static_cast<float>(geometry.Points[v] - center[v % 3]);
  }
  geometry.Points.clear();
  geometry.Points.shrink_to_fit();

  // The rendered vertices: eye (relative to the centre) and frame (t, b, n), 12 floats each.
  std::vector<vtkIdType> order;
  std::vector<float> frames;
  vtkPoints* points = input->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], nrm[3], t[3], b[3];
    points->GetPoint(i, p);
    normals->GetTuple(i, nrm);
    if (!geometry.OnSurface[i] || !vtkAOBaking::Finite3(p) || !vtkAOBaking::Finite3(nrm) ||
      vtkMath::Normalize(nrm) == 0.0)
    {
      continue;
    }
    vtkAOBaking::Basis(nrm, t, b);
    order.push_back(i);
    for (int d = 0; d < 3; ++d)
    {
      frames.push_back(static_cast<float>(p[d] - center[d] + this->EffectiveBias * nrm[d]));
    }
    for (const double* axis : { t, b, nrm })
    {
      frames.insert(frames.end(),
        { static_cast<float>(axis[0]), static_cast<float>(axis[1]), static_cast<float>(axis[2]) });
    }
  }
  const vtkIdType rendered = static_cast<vtkIdType>(order.size());
  this->NumberOfRenderedPoints = rendered;
  if (rendered == 0)
  {
    this->TotalTime = Seconds(start);
    return 1;
  }

  // The OpenGL context and resources.
  const char* contextError = nullptr;
  vtkOpenGLRenderWindow* context =
    vtkAOBaking::MakeContext(this->RenderWindow, this->Internals->OwnWindow, contextError);
  if (!context)
  {
    vtkErrorMacro(<< contextError);
    return 0;
  }
  auto& internals = *this->Internals;
  if (internals.Context != context)
  {
    internals.Release();
    internals.Context = context;
  }
  vtkOpenGLState* state = context->GetState();
  const int resolution = this->Resolution + this->Resolution % 2;
  const int tile = 2 * resolution;
  const int largest = std::min(4096, vtkTextureObject::GetMaximumTextureSize(context));
  const int perRow = std::max(1, largest / tile);
  const int batch = static_cast<int>(std::min<vtkIdType>({ static_cast<vtkIdType>(this->BatchSize),
    static_cast<vtkIdType>(perRow) * perRow,
    rendered }));
  const int tilesPerRow =
    std::min(perRow, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(batch)))));
  const int rows = (batch + tilesPerRow - 1) / tilesPerRow;
  this->EffectiveBatchSize = batch;
  if (!internals.Target(internals.Atlas,
        internals.AtlasFramebuffer,
        internals.AtlasSize,
        tilesPerRow * tile,
        rows * tile,
        VTK_UNSIGNED_CHAR) ||
    !internals.Target(
      internals.Sums, internals.SumsFramebuffer, internals.SumsSize, tilesPerRow, rows, VTK_FLOAT))
  {
    vtkErrorMacro(<< "Couldn't create a " << tilesPerRow * tile << "x" << rows * tile
                  << " hemicube atlas.");
    internals.Release();
    return 0;
  }
  const std::vector<float> weights = HemicubeWeights(resolution, this->Spread);
  if (internals.Weights)
  {
    internals.Weights->ReleaseGraphicsResources(context);
  }
  internals.Weights = vtkSmartPointer<vtkTextureObject>::New();
  internals.Weights->SetContext(context);
  internals.Weights->SetMinificationFilter(vtkTextureObject::Nearest);
  internals.Weights->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!internals.Weights->Create2DFromRaw(
        tile, tile, 1, VTK_FLOAT, const_cast<float*>(weights.data())))
  {
    vtkErrorMacro(<< "Couldn't upload the hemicube weights.");
    return 0;
  }

  vtkShaderProgram* program =
    context->GetShaderCache()->ReadyShaderProgram(CoverageVS, CoverageFS, "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the hemicube shader.");
    return 0;
  }
  for (auto* buffer :
    { internals.Points.Get(), internals.Indices.Get(), internals.Instances.Get() })
  {
    if (buffer)
    {
      buffer->ReleaseGraphicsResources();
    }
  }
  if (internals.Layout)
  {
    internals.Layout->ReleaseGraphicsResources();
  }
  internals.Points = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Points->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  internals.Indices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Indices->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  internals.Instances = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Instances->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  if (!internals.Points->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer) ||
    !internals.Indices->Upload(geometry.Triangles, vtkOpenGLBufferObject::ElementArrayBuffer) ||
    !internals.Instances->Upload(frames, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload " << triangleCount << " triangles.");
    return 0;
  }
  vertices.clear();
  vertices.shrink_to_fit();
  geometry.Triangles.clear();
  geometry.Triangles.shrink_to_fit();
  internals.Layout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  if (!internals.Reduce)
  {
    internals.Reduce.reset(new vtkOpenGLQuadHelper(context, nullptr, ReduceFS, ""));
  }
  if (!internals.Reduce->Program || !internals.Reduce->Program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the hemicube reduction shader.");
    return 0;
  }

  std::vector<float> sums(static_cast<size_t>(tilesPerRow) * rows);
  float* out = values->GetPointer(0);
  const double radius = this->Radius;
  const float radius2 = radius > 0.0 ? static_cast<float>(std::min(radius * radius, 1e30)) : 0.0f;
  const auto renderStart = Clock::now();
  {
    // Save every piece of state touched, in a window that may belong to someone else.
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglEnableDisable clip0Saver(state, GL_CLIP_DISTANCE0);
    vtkOpenGLState::ScopedglEnableDisable clip1Saver(state, GL_CLIP_DISTANCE1);
    vtkOpenGLState::ScopedglEnableDisable clip2Saver(state, GL_CLIP_DISTANCE2);
    vtkOpenGLState::ScopedglEnableDisable clip3Saver(state, GL_CLIP_DISTANCE3);
    vtkOpenGLState::ScopedglEnableDisable clip4Saver(state, GL_CLIP_DISTANCE4);
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
    for (vtkIdType first = 0; first < rendered && !this->GetAbortExecute(); first += batch)
    {
      const int count = static_cast<int>(std::min<vtkIdType>(batch, rendered - first));

      // 1. The hemicubes of the batch, black on white.
      internals.AtlasFramebuffer->Bind();
      state->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
      internals.AtlasFramebuffer->ActivateDrawBuffers(1);
      state->vtkglViewport(0, 0, internals.AtlasSize[0], internals.AtlasSize[1]);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      for (int plane = 0; plane < 5; ++plane)
      {
        state->vtkglEnable(GL_CLIP_DISTANCE0 + plane);
      }
      context->GetShaderCache()->ReadyShaderProgram(program);
      const float tiles[2] = { static_cast<float>(tilesPerRow), static_cast<float>(rows) };
      program->SetUniform2f("tiles", tiles);
      program->SetUniformi("tilesPerRow", tilesPerRow);
      program->SetUniformf("nearDistance", static_cast<float>(0.01 * this->EffectiveBias));
      program->SetUniformf("radius2", radius2);
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
      if (!bound)
      {
        internals.Layout->Release();
        vtkErrorMacro(<< "Couldn't bind the vertex layout.");
        break;
      }
      internals.Indices->Bind(); // recorded in the vertex array object
      for (int face = 0; face < 5; ++face)
      {
        program->SetUniformi("face", face);
        glDrawElementsInstanced(
          GL_TRIANGLES, static_cast<GLsizei>(3 * triangleCount), GL_UNSIGNED_INT, nullptr, count);
      }
      internals.Layout->Release();
      for (int plane = 0; plane < 5; ++plane)
      {
        state->vtkglDisable(GL_CLIP_DISTANCE0 + plane);
      }

      // 2. Every tile's weighted white fraction, one texel each; one read-back.
      internals.SumsFramebuffer->Bind();
      state->vtkglDrawBuffer(GL_NONE);
      internals.SumsFramebuffer->ActivateDrawBuffers(1);
      internals.SumsFramebuffer->ActivateReadBuffer(0);
      state->vtkglViewport(0, 0, tilesPerRow, rows);
      context->GetShaderCache()->ReadyShaderProgram(internals.Reduce->Program);
      internals.Atlas->Activate();
      internals.Weights->Activate();
      internals.Reduce->Program->SetUniformi("coverage", internals.Atlas->GetTextureUnit());
      internals.Reduce->Program->SetUniformi("weights", internals.Weights->GetTextureUnit());
      internals.Reduce->Program->SetUniform2f("tiles", tiles);
      internals.Reduce->Program->SetUniformi("tileSize", tile);
      internals.Reduce->Render();
      internals.Weights->Deactivate();
      internals.Atlas->Deactivate();
      glReadPixels(0, 0, tilesPerRow, rows, GL_RED, GL_FLOAT, sums.data());
      for (int m = 0; m < count; ++m)
      {
        out[order[first + m]] = std::max(0.0f, std::min(1.0f, sums[m]));
      }
      ++this->NumberOfBatches;
      this->UpdateProgress(static_cast<double>(first + count) / rendered);
    }
    internals.SumsFramebuffer->UnBind();
    internals.AtlasFramebuffer->RestorePreviousBindingsAndBuffers();
  }
  vtkOpenGLCheckErrorMacro("failed after rendering the hemicubes");
  this->RenderTime = Seconds(renderStart);
  this->TotalTime = Seconds(start);
  return 1;
}
