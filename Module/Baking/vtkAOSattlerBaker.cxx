#include "vtkAOSattlerBaker.h"

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
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>

namespace
{
// Depth only: the fragment colour is irrelevant, but a colour target keeps every driver's
// framebuffer-completeness rules happy.
const char* DepthVS = R"(//VTK::System::Dec
in vec3 vertexMC;
uniform mat4 projection;
void main()
{
  gl_Position = projection * vec4(vertexMC, 1.0);
}
)";

const char* DepthFS = R"(//VTK::System::Dec
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(1.0);
}
)";

// The GPU point test: one point per vertex, the same arithmetic as the CPU test in float. The
// AO:: tags are replaced for the variant: LOGIC_OP puts a visible vertex's point on texel
// (i % width, i / width) of the bits texture (else outside the viewport) with the bit as its
// colour; STORAGE_BUFFER ORs the bit into word i of a storage buffer (the rasterizer discards
// everything).
const char* TestVS = R"(//VTK::System::Dec
//AO::Extension::Dec
in vec3 testMC;   // p + bias n, relative to the centre
in vec3 normalMC; // unit, or zero for points without a valid normal
uniform sampler2D depthMap;
uniform vec3 direction; // l
uniform vec3 axisU;
uniform vec3 axisV;
uniform float extent;
uniform int size;
uniform float tolerance;
uniform float slopeUnit;
uniform int bit;
//AO::Output::Dec
void main()
{
  //AO::Start::Impl
  float cosine = dot(normalMC, direction);
  if (cosine > 0.0)
  {
    float x = dot(testMC, axisU) / extent;
    float y = dot(testMC, axisV) / extent;
    float s = dot(testMC, direction) / extent;
    int px = clamp(int((x + 1.0) * 0.5 * float(size)), 0, size - 1);
    int py = clamp(int((y + 1.0) * 0.5 * float(size)), 0, size - 1);
    float pointDepth = 0.5 * (1.0 - s);
    float tangent = sqrt(max(0.0, 1.0 - cosine * cosine)) / cosine;
    float allowed = tolerance + slopeUnit * min(4.0, tangent);
    if (texelFetch(depthMap, ivec2(px, py), 0).r >= pointDepth - allowed)
    {
      //AO::Visible::Impl
    }
  }
}
)";

const char* TestFS = R"(//VTK::System::Dec
flat in uint mask;
out uvec4 bitsOut;
void main()
{
  bitsOut = uvec4(mask, 0u, 0u, 0u);
}
)";

// The vertex shader of a GPU point test.
std::string TestShader(bool storage)
{
  std::string source = TestVS;
  vtkShaderProgram::Substitute(source,
    "//AO::Extension::Dec",
    storage ? "#extension GL_ARB_shader_storage_buffer_object : require" : "");
  vtkShaderProgram::Substitute(source,
    "//AO::Output::Dec",
    storage ? "layout(std430) buffer BitsBlock\n{\n  uint words[];\n};"
            : "uniform ivec2 bitsSize;\nflat out uint mask;");
  vtkShaderProgram::Substitute(source,
    "//AO::Start::Impl",
    storage ? "gl_Position = vec4(0.0, 0.0, 0.0, 1.0);"
            : "gl_PointSize = 1.0;\n  gl_Position = vec4(2.0, 2.0, 0.0, 1.0); // clipped\n"
              "  mask = 0u;");
  vtkShaderProgram::Substitute(source,
    "//AO::Visible::Impl",
    storage ? "atomicOr(words[gl_VertexID], 1u << uint(bit));"
            : "vec2 texel = vec2(float(gl_VertexID % bitsSize.x), "
              "float(gl_VertexID / bitsSize.x)) + 0.5;\n"
              "      gl_Position = vec4(2.0 * texel / vec2(bitsSize) - 1.0, 0.0, 1.0);\n"
              "      mask = 1u << uint(bit);");
  return source;
}

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}
}

//------------------------------------------------------------------------------
class vtkAOSattlerBaker::vtkInternals
{
public:
  vtkSmartPointer<vtkRenderWindow> OwnWindow;
  vtkOpenGLRenderWindow* Context = nullptr; // the window the resources below belong to
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkOpenGLBufferObject> Points;
  vtkSmartPointer<vtkOpenGLBufferObject> Indices;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> Layout;
  int Size = 0;
  // The GPU point test: the test points and normals, and the bits texture.
  vtkSmartPointer<vtkOpenGLBufferObject> Tests;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> TestLayout;
  vtkSmartPointer<vtkOpenGLFramebufferObject> BitsFramebuffer;
  vtkSmartPointer<vtkTextureObject> Bits;
  int BitsSize[2] = { 0, 0 };
  unsigned int Storage = 0; // the shader storage buffer (STORAGE_BUFFER)
  vtkIdType StorageWords = 0;

  void ReleaseBuffers()
  {
    for (auto* buffer : { this->Points.Get(), this->Indices.Get(), this->Tests.Get() })
    {
      if (buffer && this->Context)
      {
        buffer->ReleaseGraphicsResources();
      }
    }
    for (auto* layout : { this->Layout.Get(), this->TestLayout.Get() })
    {
      if (layout && this->Context)
      {
        layout->ReleaseGraphicsResources();
      }
    }
    this->Points = this->Indices = this->Tests = nullptr;
    this->Layout = this->TestLayout = nullptr;
  }

  void ReleaseBits()
  {
    if (this->Context)
    {
      if (this->BitsFramebuffer)
      {
        this->BitsFramebuffer->ReleaseGraphicsResources(this->Context);
      }
      if (this->Bits)
      {
        this->Bits->ReleaseGraphicsResources(this->Context);
      }
    }
    this->BitsFramebuffer = nullptr;
    this->Bits = nullptr;
    this->BitsSize[0] = this->BitsSize[1] = 0;
#ifndef GL_ES_VERSION_3_0
    if (this->Storage && this->Context)
    {
      glDeleteBuffers(1, &this->Storage);
    }
#endif
    this->Storage = 0;
    this->StorageWords = 0;
  }

  // A shader storage buffer of @p words 32-bit words. False without OpenGL 4.3 and storage
  // buffers in vertex shaders (then another point test is used).
  bool AllocateStorage(vtkIdType words)
  {
#ifdef GL_ES_VERSION_3_0
    (void)words;
    return false;
#else
    int major = 0, minor = 0;
    this->Context->GetOpenGLVersion(major, minor);
    GLint blocks = 0;
    if (major * 10 + minor >= 43)
    {
      glGetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &blocks);
    }
    if (blocks < 1)
    {
      return false;
    }
    vtkOpenGLClearErrorMacro();
    if (this->Storage && this->StorageWords == words)
    {
      return true;
    }
    if (!this->Storage)
    {
      glGenBuffers(1, &this->Storage);
    }
    GLint previous = 0;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &previous);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Storage);
    glBufferData(GL_SHADER_STORAGE_BUFFER, 4 * words, nullptr, GL_DYNAMIC_READ);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(previous));
    this->StorageWords = words;
    return glGetError() == GL_NO_ERROR;
#endif
  }

  void Release()
  {
    if (this->Context)
    {
      this->Context->MakeCurrent();
      if (this->Framebuffer)
      {
        this->Framebuffer->ReleaseGraphicsResources(this->Context);
      }
      if (this->Depth)
      {
        this->Depth->ReleaseGraphicsResources(this->Context);
      }
      if (this->Color)
      {
        this->Color->ReleaseGraphicsResources(this->Context);
      }
    }
    this->ReleaseBuffers();
    this->ReleaseBits();
    this->Framebuffer = nullptr;
    this->Depth = nullptr;
    this->Color = nullptr;
    this->Size = 0;
    this->Context = nullptr;
  }

  // The framebuffer (depth texture + colour texture) of size x size in @p context.
  bool Allocate(vtkOpenGLRenderWindow* context, int size)
  {
    if (this->Context != context)
    {
      this->Release();
      this->Context = context;
    }
    if (this->Framebuffer && this->Size == size)
    {
      return true;
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(context);
      this->Depth->ReleaseGraphicsResources(context);
      this->Color->ReleaseGraphicsResources(context);
    }
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth->SetContext(context);
    this->Depth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Depth->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Depth->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!this->Depth->AllocateDepth(size, size, vtkTextureObject::Float32))
    {
      return false;
    }
    this->Color = vtkSmartPointer<vtkTextureObject>::New();
    this->Color->SetContext(context);
    if (!this->Color->Allocate2D(size, size, 4, VTK_UNSIGNED_CHAR))
    {
      return false;
    }
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(context);
    this->Framebuffer->SaveCurrentBindingsAndBuffers();
    this->Framebuffer->Bind();
    this->Framebuffer->AddColorAttachment(0, this->Color);
    this->Framebuffer->AddDepthAttachment(this->Depth);
    const char* status = nullptr;
    const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
    this->Framebuffer->UnBind();
    this->Framebuffer->RestorePreviousBindingsAndBuffers();
    this->Size = size;
    return complete;
  }

  // The R32UI bits texture of width x height texels and its framebuffer. False when the driver
  // cannot render to it (then the CPU test is used).
  bool AllocateBits(int width, int height)
  {
#ifdef GL_ES_VERSION_3_0
    (void)width;
    (void)height;
    return false; // no glLogicOp in OpenGL ES
#else
    if (this->BitsFramebuffer && this->BitsSize[0] == width && this->BitsSize[1] == height)
    {
      return true;
    }
    this->ReleaseBits();
    this->Bits = vtkSmartPointer<vtkTextureObject>::New();
    this->Bits->SetContext(this->Context);
    this->Bits->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Bits->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Bits->SetInternalFormat(GL_R32UI);
    this->Bits->SetFormat(GL_RED_INTEGER);
    this->Bits->SetDataType(GL_UNSIGNED_INT);
    if (!this->Bits->Allocate2D(width, height, 1, VTK_UNSIGNED_INT))
    {
      this->ReleaseBits();
      return false;
    }
    this->BitsFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->BitsFramebuffer->SetContext(this->Context);
    this->BitsFramebuffer->SaveCurrentBindingsAndBuffers();
    this->BitsFramebuffer->Bind();
    this->BitsFramebuffer->AddColorAttachment(0, this->Bits);
    const char* status = nullptr;
    const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
    this->BitsFramebuffer->UnBind();
    this->BitsFramebuffer->RestorePreviousBindingsAndBuffers();
    if (!complete)
    {
      this->ReleaseBits();
      return false;
    }
    this->BitsSize[0] = width;
    this->BitsSize[1] = height;
    return true;
#endif
  }
};

vtkStandardNewMacro(vtkAOSattlerBaker);

//------------------------------------------------------------------------------
vtkAOSattlerBaker::vtkAOSattlerBaker()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2);
}

vtkAOSattlerBaker::~vtkAOSattlerBaker()
{
  this->ReleaseGraphicsResources();
  this->SetRenderWindow(nullptr);
  delete this->Internals;
}

void vtkAOSattlerBaker::ReleaseGraphicsResources()
{
  this->Internals->Release();
  this->Internals->OwnWindow = nullptr;
}

//------------------------------------------------------------------------------
void vtkAOSattlerBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "DepthOffset: " << this->DepthOffset << " (effective "
     << this->EffectiveDepthOffset << ")\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "StoreVisibility: " << this->StoreVisibility << "\n";
  os << indent << "PointTest: " << GetPointTestAsString(this->PointTest) << " (used "
     << GetPointTestAsString(this->PointTestUsed) << ")\n";
  os << indent << "Intensities: " << this->Intensities.size() << " values, "
     << this->IntensityComponents << " component(s)\n";
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "RadianceArrayName: " << this->RadianceArrayName << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "RenderTime: " << this->RenderTime << "\n";
  os << indent << "TestTime: " << this->TestTime << "\n";
  os << indent << "TotalTime: " << this->TotalTime << "\n";
  os << indent << "VisibilityMemory: " << this->GetVisibilityMemory() << "\n";
}

const char* vtkAOSattlerBaker::GetPointTestAsString(int test)
{
  switch (test)
  {
    case POINT_TEST_AUTOMATIC:
      return "Automatic";
    case POINT_TEST_CPU:
      return "CPU";
    case POINT_TEST_LOGIC_OP:
      return "LogicOp";
    case POINT_TEST_STORAGE_BUFFER:
      return "StorageBuffer";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
void vtkAOSattlerBaker::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

void vtkAOSattlerBaker::AddOccluderData(vtkPolyData* occluder)
{
  this->AddInputData(1, occluder);
}

void vtkAOSattlerBaker::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

void vtkAOSattlerBaker::SetArrayName(const std::string& name)
{
  if (name != this->ArrayName)
  {
    this->ArrayName = name;
    this->Modified();
  }
}

void vtkAOSattlerBaker::SetRadianceArrayName(const std::string& name)
{
  if (name != this->RadianceArrayName)
  {
    this->RadianceArrayName = name;
    this->Modified();
  }
}

void vtkAOSattlerBaker::SetIntensities(const std::vector<double>& intensities, int components)
{
  components = std::max(1, std::min(4, components));
  if (intensities != this->Intensities || components != this->IntensityComponents)
  {
    this->Intensities = intensities;
    this->IntensityComponents = components;
    this->Modified();
  }
}

void vtkAOSattlerBaker::SetRenderWindow(vtkRenderWindow* window)
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

//------------------------------------------------------------------------------
std::vector<double> vtkAOSattlerBaker::MakeDirections(int count, unsigned int seed)
{
  count = std::max(1, count);
  // A random rotation (uniform unit quaternion) when seeded.
  double rotation[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  if (seed != 0)
  {
    std::mt19937 random(seed);
    std::normal_distribution<double> gauss;
    double q[4];
    double norm = 0.0;
    do
    {
      for (double& c : q)
      {
        c = gauss(random);
      }
      norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    } while (norm < 1e-6);
    for (double& c : q)
    {
      c /= norm;
    }
    vtkMath::QuaternionToMatrix3x3(q, rotation);
  }
  std::vector<double> directions(3 * static_cast<size_t>(count));
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int j = 0; j < count; ++j)
  {
    const double z = 1.0 - (2.0 * j + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * j;
    const double d[3] = { r * std::cos(phi), r * std::sin(phi), z };
    double* out = &directions[3 * static_cast<size_t>(j)];
    vtkMath::Multiply3x3(rotation, d, out);
    vtkMath::Normalize(out);
  }
  return directions;
}

//------------------------------------------------------------------------------
bool vtkAOSattlerBaker::IsVisible(vtkIdType point, int direction) const
{
  if (this->Visibility.empty() || point < 0 || direction < 0 ||
    direction >= static_cast<int>(this->Directions.size() / 3) ||
    static_cast<size_t>(point) * this->WordsPerPoint >= this->Visibility.size())
  {
    return false;
  }
  const std::uint32_t word =
    this->Visibility[static_cast<size_t>(point) * this->WordsPerPoint + direction / 32];
  return (word >> (direction % 32)) & 1u;
}

//------------------------------------------------------------------------------
bool vtkAOSattlerBaker::Relight(const std::vector<double>& intensities,
  int components,
  vtkFloatArray* out) const
{
  const size_t k = this->Directions.size() / 3;
  const vtkIdType n = static_cast<vtkIdType>(this->CosineSums.size());
  if (!out || components < 1 || k == 0 || this->Visibility.empty() ||
    intensities.size() != k * static_cast<size_t>(components) ||
    this->Visibility.size() != static_cast<size_t>(n) * this->WordsPerPoint)
  {
    return false;
  }
  out->SetNumberOfComponents(components);
  out->SetNumberOfTuples(n);
  std::vector<double> mean(components, 0.0);
  for (size_t j = 0; j < k; ++j)
  {
    for (int c = 0; c < components; ++c)
    {
      mean[c] += intensities[j * components + c] / k;
    }
  }
  float* result = out->GetPointer(0);
  const int words = this->WordsPerPoint;
  vtkSMPTools::For(0,
    n,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<double> sum(components);
      for (vtkIdType i = first; i < last; ++i)
      {
        const float* nrm = &this->Normals[3 * i];
        const double total = this->CosineSums[i];
        if (total <= 0.0)
        {
          for (int c = 0; c < components; ++c)
          {
            result[i * components + c] = static_cast<float>(mean[c]);
          }
          continue;
        }
        std::fill(sum.begin(), sum.end(), 0.0);
        const std::uint32_t* bits = &this->Visibility[static_cast<size_t>(i) * words];
        for (int w = 0; w < words; ++w)
        {
          std::uint32_t word = bits[w];
          while (word)
          {
            const int b = __builtin_ctz(word);
            word &= word - 1;
            const size_t j = static_cast<size_t>(w) * 32 + b;
            const double* l = &this->Directions[3 * j];
            const double cosine = nrm[0] * l[0] + nrm[1] * l[1] + nrm[2] * l[2];
            if (cosine > 0.0)
            {
              for (int c = 0; c < components; ++c)
              {
                sum[c] += cosine * intensities[j * components + c];
              }
            }
          }
        }
        for (int c = 0; c < components; ++c)
        {
          result[i * components + c] = static_cast<float>(sum[c] / total);
        }
      }
    });
  return true;
}

//------------------------------------------------------------------------------
int vtkAOSattlerBaker::FillInputPortInformation(int port, vtkInformation* info)
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
int vtkAOSattlerBaker::RequestData(vtkInformation* vtkNotUsed(request),
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
  this->RenderTime = this->TestTime = this->TotalTime = 0.0;
  this->NumberOfTriangles = 0;
  this->PointTestUsed = POINT_TEST_CPU;
  this->Visibility.clear();
  this->Visibility.shrink_to_fit();
  this->Normals.clear();
  this->CosineSums.clear();
  const int k = this->NumberOfDirections;
  this->Directions = MakeDirections(k, this->Seed);
  this->WordsPerPoint = (k + 31) / 32;

  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> values;
  values->SetName(this->ArrayName.c_str());
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  values->FillValue(1.0f);
  output->GetPointData()->AddArray(values);
  const int comps = this->IntensityComponents;
  const bool radiance =
    !this->Intensities.empty() && this->Intensities.size() == static_cast<size_t>(k) * comps;
  if (!this->Intensities.empty() && !radiance)
  {
    vtkWarningMacro(<< "Intensities hold " << this->Intensities.size() << " values, expected " << k
                    << " x " << comps << ": no radiance array.");
  }
  this->Normals.assign(3 * static_cast<size_t>(n), 0.0f);
  this->CosineSums.assign(static_cast<size_t>(n), 0.0f);
  if (this->StoreVisibility)
  {
    this->Visibility.assign(static_cast<size_t>(n) * this->WordsPerPoint, 0u);
  }

  // The triangles that occlude (input and occluders, finite and non-degenerate), and the input
  // cells that define its surface (only their points get a value).
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

  // Point normals: the input's, or computed without splitting (point ids are kept).
  vtkSmartPointer<vtkDataArray> normals = vtkAOBaking::PointNormals(input, geometry);
  if (!normals)
  {
    vtkErrorMacro(<< "Couldn't compute point normals for the input.");
    return 0;
  }

  // The frame: a sphere around the bounds; automatic bias as vtkAOVertexBaker's.
  const double* bounds = geometry.Bounds;
  const double center[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : vtkAOBaking::AutomaticBias(bounds);
  double extent = 0.5 * diagonal * 1.01 + 2.0 * this->EffectiveBias;
  if (!(extent > 0.0))
  {
    extent = 1.0;
  }
  const int size = this->Resolution;
  const double pixel = 2.0 * extent / size;
  this->EffectiveDepthOffset = this->DepthOffset > 0.0 ? this->DepthOffset : 1.5 * pixel;

  // Scene points relative to the centre (drawn indexed).
  std::vector<float> vertices(geometry.Points.size());
  for (size_t v = 0; v < vertices.size(); ++v)
  {
    vertices[v] = static_cast<float>(geometry.Points[v] - center[v % 3]);
  }
  geometry.Points.clear();
  geometry.Points.shrink_to_fit();

  // Test points (relative to the centre) and unit normals.
  std::vector<double> tests(3 * static_cast<size_t>(n), 0.0);
  std::vector<char> valid(static_cast<size_t>(n), 0);
  vtkPoints* points = input->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], nrm[3];
    points->GetPoint(i, p);
    normals->GetTuple(i, nrm);
    if (!geometry.OnSurface[i] || !vtkAOBaking::Finite3(p) || !vtkAOBaking::Finite3(nrm) ||
      vtkMath::Normalize(nrm) == 0.0)
    {
      continue;
    }
    valid[i] = 1;
    for (int d = 0; d < 3; ++d)
    {
      tests[3 * i + d] = p[d] - center[d] + this->EffectiveBias * nrm[d];
      this->Normals[3 * i + d] = static_cast<float>(nrm[d]);
    }
  }

  // The OpenGL context.
  const char* contextError = nullptr;
  vtkOpenGLRenderWindow* context =
    vtkAOBaking::MakeContext(this->RenderWindow, this->Internals->OwnWindow, contextError);
  if (!context)
  {
    vtkErrorMacro(<< contextError);
    return 0;
  }
  vtkOpenGLState* state = context->GetState();
  if (!this->Internals->Allocate(context, size))
  {
    vtkErrorMacro(<< "Couldn't create a " << size << "x" << size << " depth framebuffer.");
    this->Internals->Release();
    return 0;
  }
  vtkShaderProgram* program = context->GetShaderCache()->ReadyShaderProgram(DepthVS, DepthFS, "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the depth shader.");
    return 0;
  }
  auto& internals = *this->Internals;
  internals.ReleaseBuffers();
  internals.Points = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Points->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  internals.Indices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Indices->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  if (!internals.Points->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer) ||
    !internals.Indices->Upload(geometry.Triangles, vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload " << triangleCount << " triangles.");
    return 0;
  }
  internals.Layout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  internals.Layout->Bind();
  if (!internals.Layout->AddAttributeArray(
        program, internals.Points, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false))
  {
    vtkErrorMacro(<< "Couldn't bind the vertex layout.");
    internals.Layout->Release();
    return 0;
  }
  internals.Indices->Bind(); // recorded in the vertex array object
  internals.Layout->Release();
  vertices.clear();
  vertices.shrink_to_fit();
  geometry.Triangles.clear();
  geometry.Triangles.shrink_to_fit();

  // The GPU point test: the test points and normals as vertex attributes, and a shader storage
  // buffer (STORAGE_BUFFER) or an R32UI texture of bitsWidth x bitsHeight texels (LOGIC_OP) of
  // one word per point. Any failure: the next variant, at last the CPU test.
  int test = POINT_TEST_CPU;
  vtkShaderProgram* testProgram = nullptr;
  const int maximumSize = vtkTextureObject::GetMaximumTextureSize(context);
  const int bitsWidth = static_cast<int>(std::min<vtkIdType>(n, std::min(4096, maximumSize)));
  const vtkIdType bitsHeight = (n + bitsWidth - 1) / bitsWidth;
  if (this->PointTest != POINT_TEST_CPU)
  {
    std::vector<float> attributes(6 * static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int d = 0; d < 3; ++d)
      {
        attributes[6 * i + d] = static_cast<float>(tests[3 * i + d]);
        attributes[6 * i + 3 + d] = this->Normals[3 * i + d]; // zero for invalid points
      }
    }
    internals.Tests = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    internals.Tests->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    const bool uploaded = internals.Tests->Upload(attributes, vtkOpenGLBufferObject::ArrayBuffer);
    for (int variant : { POINT_TEST_STORAGE_BUFFER, POINT_TEST_LOGIC_OP })
    {
      if (!uploaded || test != POINT_TEST_CPU ||
        (variant == POINT_TEST_STORAGE_BUFFER && this->PointTest == POINT_TEST_LOGIC_OP))
      {
        continue;
      }
      const bool storage = variant == POINT_TEST_STORAGE_BUFFER;
      if (storage ? !internals.AllocateStorage(n)
                  : (bitsHeight > maximumSize ||
                      !internals.AllocateBits(bitsWidth, static_cast<int>(bitsHeight))))
      {
        continue;
      }
      testProgram = context->GetShaderCache()->ReadyShaderProgram(
        TestShader(storage).c_str(), storage ? DepthFS : TestFS, "");
      if (!testProgram || !testProgram->GetCompiled())
      {
        continue;
      }
#ifndef GL_ES_VERSION_3_0
      if (storage)
      {
        const GLuint block = glGetProgramResourceIndex(
          static_cast<GLuint>(testProgram->GetHandle()), GL_SHADER_STORAGE_BLOCK, "BitsBlock");
        if (block == GL_INVALID_INDEX)
        {
          continue;
        }
        glShaderStorageBlockBinding(static_cast<GLuint>(testProgram->GetHandle()), block, 0);
      }
#endif
      internals.TestLayout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
      internals.TestLayout->Bind();
      const bool bound =
        internals.TestLayout->AddAttributeArray(
          testProgram, internals.Tests, "testMC", 0, 6 * sizeof(float), VTK_FLOAT, 3, false) &&
        internals.TestLayout->AddAttributeArray(testProgram,
          internals.Tests,
          "normalMC",
          3 * sizeof(float),
          6 * sizeof(float),
          VTK_FLOAT,
          3,
          false);
      internals.TestLayout->Release();
      test = bound ? variant : POINT_TEST_CPU;
    }
    if (test == POINT_TEST_CPU)
    {
      vtkDebugMacro(<< "No GPU point test is available: testing on the CPU.");
    }
  }
  this->PointTestUsed = test;
  const bool gpu = test != POINT_TEST_CPU;

  std::vector<float> depth(gpu ? 0 : static_cast<size_t>(size) * size);
  std::vector<std::uint32_t> words(
    gpu ? static_cast<size_t>(std::max<vtkIdType>(n, bitsWidth * bitsHeight)) : 0);
  const std::vector<std::uint32_t> zeros(
    test == POINT_TEST_STORAGE_BUFFER ? static_cast<size_t>(n) : 0, 0u);
  std::vector<float> visibleSums(static_cast<size_t>(n), 0.0f);
  std::vector<double> radianceSums(radiance ? static_cast<size_t>(n) * comps : 0, 0.0);
  const double tolerance = this->EffectiveDepthOffset / (2.0 * extent);
  const double slopeUnit = pixel / (2.0 * extent);
  float* cosineSums = this->CosineSums.data();
  const float* unit = this->Normals.data();
  std::uint32_t* bits = this->Visibility.empty() ? nullptr : this->Visibility.data();
  const int wordsPerPoint = this->WordsPerPoint;

  // Point i sees or does not see direction j (with cosine > 0): the sums and the stored bit.
  auto record = [&](vtkIdType i, int j, double cosine, bool visible)
  {
    cosineSums[i] += static_cast<float>(cosine);
    if (!visible)
    {
      return;
    }
    visibleSums[i] += static_cast<float>(cosine);
    if (bits)
    {
      bits[static_cast<size_t>(i) * wordsPerPoint + j / 32] |= 1u << (j % 32);
    }
    if (radiance)
    {
      const double* intensity = &this->Intensities[static_cast<size_t>(j) * comps];
      for (int c = 0; c < comps; ++c)
      {
        radianceSums[static_cast<size_t>(i) * comps + c] += cosine * intensity[c];
      }
    }
  };

  {
    // Save every piece of state touched, in a window that may belong to someone else.
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
#ifndef GL_ES_VERSION_3_0
    vtkOpenGLState::ScopedglEnableDisable logicOpSaver(state, GL_COLOR_LOGIC_OP);
    vtkOpenGLState::ScopedglEnableDisable pointSizeSaver(state, GL_PROGRAM_POINT_SIZE);
    vtkOpenGLState::ScopedglEnableDisable discardSaver(state, GL_RASTERIZER_DISCARD);
    GLint logicOpMode = GL_COPY;
    glGetIntegerv(GL_LOGIC_OP_MODE, &logicOpMode);
    GLint storageBinding = 0, storageBinding0 = 0;
    if (test == POINT_TEST_STORAGE_BUFFER)
    {
      glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageBinding);
      glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &storageBinding0);
    }
#endif
    internals.Framebuffer->SaveCurrentBindingsAndBuffers();
    internals.Framebuffer->Bind();
    state->vtkglDrawBuffer(GL_NONE); // reset vtkOpenGLState's draw-buffer cache
    internals.Framebuffer->ActivateDrawBuffers(1);
    internals.Framebuffer->ActivateReadBuffer(0);
    state->vtkglViewport(0, 0, size, size);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);

    this->UpdateProgress(0.0);
    for (int j = 0; j < k && !this->GetAbortExecute(); ++j)
    {
      const double* l = &this->Directions[3 * static_cast<size_t>(j)];
      double u[3], v[3];
      vtkAOBaking::Basis(l, u, v);
      // Camera on the +l side looking along -l: NDC (u.x, v.x, -l.x) / extent. Column major.
      float projection[16] = { 0 };
      for (int d = 0; d < 3; ++d)
      {
        projection[4 * d + 0] = static_cast<float>(u[d] / extent);
        projection[4 * d + 1] = static_cast<float>(v[d] / extent);
        projection[4 * d + 2] = static_cast<float>(-l[d] / extent);
      }
      projection[15] = 1.0f;

      const auto drawStart = Clock::now();
      context->GetShaderCache()->ReadyShaderProgram(program);
      program->SetUniformMatrix4x4("projection", projection);
      state->vtkglClearDepth(1.0);
      state->vtkglClear(GL_DEPTH_BUFFER_BIT);
      internals.Layout->Bind();
      glDrawElements(
        GL_TRIANGLES, static_cast<GLsizei>(3 * triangleCount), GL_UNSIGNED_INT, nullptr);
      internals.Layout->Release();

#ifndef GL_ES_VERSION_3_0
      if (gpu)
      {
        this->RenderTime += Seconds(drawStart);
        const auto testStart = Clock::now();
        const bool storage = test == POINT_TEST_STORAGE_BUFFER;
        if (storage)
        {
          // No fragments: the depth framebuffer stays bound.
          glBindBuffer(GL_SHADER_STORAGE_BUFFER, internals.Storage);
          if (j % 32 == 0)
          {
            glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, 4 * n, zeros.data());
          }
          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, internals.Storage);
          state->vtkglEnable(GL_RASTERIZER_DISCARD);
        }
        else
        {
          internals.BitsFramebuffer->Bind();
          internals.BitsFramebuffer->ActivateDrawBuffers(1);
          internals.BitsFramebuffer->ActivateReadBuffer(0);
          state->vtkglViewport(0, 0, bitsWidth, static_cast<int>(bitsHeight));
          state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
          state->vtkglDisable(GL_DEPTH_TEST);
          if (j % 32 == 0)
          {
            const GLuint zero[4] = { 0, 0, 0, 0 };
            glClearBufferuiv(GL_COLOR, 0, zero);
          }
          state->vtkglEnable(GL_COLOR_LOGIC_OP);
          state->vtkglEnable(GL_PROGRAM_POINT_SIZE);
          glLogicOp(GL_OR);
        }
        context->GetShaderCache()->ReadyShaderProgram(testProgram);
        internals.Depth->Activate();
        testProgram->SetUniformi("depthMap", internals.Depth->GetTextureUnit());
        testProgram->SetUniform3f("direction", l);
        testProgram->SetUniform3f("axisU", u);
        testProgram->SetUniform3f("axisV", v);
        testProgram->SetUniformf("extent", static_cast<float>(extent));
        testProgram->SetUniformi("size", size);
        testProgram->SetUniformf("tolerance", static_cast<float>(tolerance));
        testProgram->SetUniformf("slopeUnit", static_cast<float>(slopeUnit));
        testProgram->SetUniformi("bit", j % 32);
        if (!storage)
        {
          const int bitsSize[2] = { bitsWidth, static_cast<int>(bitsHeight) };
          testProgram->SetUniform2i("bitsSize", bitsSize);
        }
        internals.TestLayout->Bind();
        glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(n));
        internals.TestLayout->Release();
        internals.Depth->Deactivate();
        if (storage)
        {
          state->vtkglDisable(GL_RASTERIZER_DISCARD);
        }
        else
        {
          glLogicOp(GL_COPY);
          state->vtkglDisable(GL_COLOR_LOGIC_OP);
        }
        if (j % 32 == 31 || j == k - 1)
        {
          // One read-back per 32 directions, then the sums in direction order (as the CPU test).
          if (storage)
          {
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, 4 * n, words.data());
          }
          else
          {
            glReadPixels(0,
              0,
              bitsWidth,
              static_cast<GLsizei>(bitsHeight),
              GL_RED_INTEGER,
              GL_UNSIGNED_INT,
              words.data());
          }
          const int first = j - j % 32;
          vtkSMPTools::For(0,
            n,
            [&](vtkIdType begin, vtkIdType end)
            {
              for (vtkIdType i = begin; i < end; ++i)
              {
                if (!valid[i])
                {
                  continue;
                }
                const float* nrm = unit + 3 * i;
                for (int jj = first; jj <= j; ++jj)
                {
                  const double* lj = &this->Directions[3 * static_cast<size_t>(jj)];
                  const double cosine = nrm[0] * lj[0] + nrm[1] * lj[1] + nrm[2] * lj[2];
                  if (cosine > 0.0)
                  {
                    record(i, jj, cosine, (words[i] >> (jj % 32)) & 1u);
                  }
                }
              }
            });
        }
        if (!storage)
        {
          internals.Framebuffer->Bind();
          state->vtkglViewport(0, 0, size, size);
          state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
          state->vtkglEnable(GL_DEPTH_TEST);
        }
        this->TestTime += Seconds(testStart);
        this->UpdateProgress(static_cast<double>(j + 1) / k);
        continue;
      }
#endif
      glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
      this->RenderTime += Seconds(drawStart);

      const auto testStart = Clock::now();
      const float* map = depth.data();
      vtkSMPTools::For(0,
        n,
        [&](vtkIdType first, vtkIdType last)
        {
          for (vtkIdType i = first; i < last; ++i)
          {
            if (!valid[i])
            {
              continue;
            }
            const float* nrm = unit + 3 * i;
            const double cosine = nrm[0] * l[0] + nrm[1] * l[1] + nrm[2] * l[2];
            if (cosine <= 0.0)
            {
              continue;
            }
            const double* q = &tests[3 * i];
            const double x = (q[0] * u[0] + q[1] * u[1] + q[2] * u[2]) / extent;
            const double y = (q[0] * v[0] + q[1] * v[1] + q[2] * v[2]) / extent;
            const double s = (q[0] * l[0] + q[1] * l[1] + q[2] * l[2]) / extent;
            const int px =
              std::min(size - 1, std::max(0, static_cast<int>((x + 1.0) * 0.5 * size)));
            const int py =
              std::min(size - 1, std::max(0, static_cast<int>((y + 1.0) * 0.5 * size)));
            const double pointDepth = 0.5 * (1.0 - s);
            const double tangent = std::sqrt(std::max(0.0, 1.0 - cosine * cosine)) / cosine;
            const double allowed = tolerance + slopeUnit * std::min(4.0, tangent);
            record(i, j, cosine, map[static_cast<size_t>(py) * size + px] >= pointDepth - allowed);
          }
        });
      this->TestTime += Seconds(testStart);
      this->UpdateProgress(static_cast<double>(j + 1) / k);
    }
    internals.Framebuffer->UnBind();
    internals.Framebuffer->RestorePreviousBindingsAndBuffers();
#ifndef GL_ES_VERSION_3_0
    glLogicOp(static_cast<GLenum>(logicOpMode));
    if (test == POINT_TEST_STORAGE_BUFFER)
    {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLuint>(storageBinding0));
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageBinding));
    }
#endif
  }
  vtkOpenGLCheckErrorMacro("failed after baking visibility");

  float* out = values->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (valid[i] && cosineSums[i] > 0.0f)
    {
      out[i] = std::min(1.0f, visibleSums[i] / cosineSums[i]);
    }
  }
  if (radiance)
  {
    vtkNew<vtkFloatArray> light;
    light->SetName(this->RadianceArrayName.c_str());
    light->SetNumberOfComponents(comps);
    light->SetNumberOfTuples(n);
    std::vector<double> mean(comps, 0.0);
    for (int j = 0; j < k; ++j)
    {
      for (int c = 0; c < comps; ++c)
      {
        mean[c] += this->Intensities[static_cast<size_t>(j) * comps + c] / k;
      }
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < comps; ++c)
      {
        light->SetTypedComponent(i,
          c,
          static_cast<float>(valid[i] && cosineSums[i] > 0.0f
              ? radianceSums[static_cast<size_t>(i) * comps + c] / cosineSums[i]
              : mean[c]));
      }
    }
    output->GetPointData()->AddArray(light);
  }
  if (!this->StoreVisibility)
  {
    this->Normals.clear();
    this->CosineSums.clear();
  }
  this->TotalTime = Seconds(start);
  return 1;
}
