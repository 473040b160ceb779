#include "vtkAOSattlerBaker.h"

#include "vtkAOBakingOpenGL.h"
#include "vtkFloatArray.h"
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
#include "vtkPoints.h"
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
uniform float halfDiagonal;
uniform float biasDepth;
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
    float sine = sqrt(max(0.0, 1.0 - cosine * cosine));
    float allowed = tolerance + max(0.0, (halfDiagonal * sine - biasDepth) / cosine);
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

// Per component, the mean of the intensities (k x components values, direction major) over the
// directions: the radiance of a point without a valid normal.
std::vector<double> MeanIntensity(const std::vector<double>& intensities, size_t k, int components)
{
  std::vector<double> mean(components, 0.0);
  for (size_t j = 0; j < k; ++j)
  {
    for (int c = 0; c < components; ++c)
    {
      mean[c] += intensities[j * components + c] / k;
    }
  }
  return mean;
}

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}
}

//------------------------------------------------------------------------------
class vtkAOSattlerBaker::vtkInternals : public vtkAOOpenGLBaker::vtkContextResources
{
public:
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

  // One execution (BakePoints), shared by its steps.
  struct Execution
  {
    vtkIdType N = 0;                // input points
    double Center[3] = { 0, 0, 0 }; // of the bounds; the scene and test points are relative to it
    double Extent = 1.0;            // half-width of the orthographic view, world units
    int Size = 0;                   // depth map width and height, pixels
    double Pixel = 0.0;             // a depth-map pixel, world units
    double Tolerance = 0.0;         // the depth offset in depth units
    double HalfDiagonal = 0.0;      // half a pixel's diagonal in depth units (the snapping term)
    double BiasDepth = 0.0;         // the bias in depth units
    double U[3] = { 0, 0, 0 };      // the current direction's image axes
    double V[3] = { 0, 0, 0 };
    std::vector<double> Tests; // p + bias n relative to the centre, 3 per point
    std::vector<char> Valid;   // 1 for the baked points
    std::vector<float> VisibleSums;
    bool Radiance = false;
    int Components = 1;
    std::vector<double> RadianceSums; // Components per point
    vtkOpenGLRenderWindow* Context = nullptr;
    vtkShaderProgram* DepthProgram = nullptr;
    size_t TriangleCount = 0;
    int Test = POINT_TEST_CPU; // the point test used
    vtkShaderProgram* TestProgram = nullptr;
    int BitsWidth = 0;
    vtkIdType BitsHeight = 0;
    std::vector<float> DepthValues;   // the CPU test's read-back
    std::vector<std::uint32_t> Words; // the GPU test's read-back, one word per point

    /// Calls @p body(i) for every baked point i, in parallel (vtkSMPTools).
    template<typename Body>
    void ForEachBakedPoint(Body body) const
    {
      vtkSMPTools::For(0,
        this->N,
        [&](vtkIdType first, vtkIdType last)
        {
          for (vtkIdType i = first; i < last; ++i)
          {
            if (this->Valid[i])
            {
              body(i);
            }
          }
        });
    }
    std::vector<std::uint32_t> Zeros; // clears the storage buffer

    // How far (depth units) the map may lie in front of a test point before it counts as
    // occluded, for a point whose normal makes cos = @p cosine with the direction. The map is
    // sampled at the pixel centre, up to half a pixel diagonal h beside the test point; there
    // the point's own tangent plane can rise (h sin - bias) / cos above the test point (it
    // lies bias / cos below it straight down). Only that rise is allowed: a constant depth
    // tolerance on top of the bias would let through the real occluders nearest to the point
    // (creases, contacts), which the ray caster counts. The GPU test repeats this in float.
    double SnapAllowance(double cosine) const
    {
      const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
      return this->Tolerance +
        std::max(0.0, (this->HalfDiagonal * sine - this->BiasDepth) / cosine);
    }
  };
  Execution Run;

  // Point i sees or does not see direction j (with cosine > 0): the sums and the stored bit.
  void Record(vtkAOSattlerBaker* self, vtkIdType i, int j, double cosine, bool visible)
  {
    self->CosineSums[i] += static_cast<float>(cosine);
    if (!visible)
    {
      return;
    }
    this->Run.VisibleSums[i] += static_cast<float>(cosine);
    if (!self->Visibility.empty())
    {
      self->Visibility[static_cast<size_t>(i) * self->WordsPerPoint + j / 32] |= 1u << (j % 32);
    }
    if (this->Run.Radiance)
    {
      const int comps = this->Run.Components;
      const double* intensity = &self->Intensities[static_cast<size_t>(j) * comps];
      for (int c = 0; c < comps; ++c)
      {
        this->Run.RadianceSums[static_cast<size_t>(i) * comps + c] += cosine * intensity[c];
      }
    }
  }

  // The resources, shader and vertex layout of a GPU point test; false when the context lacks
  // what it needs.
  bool ReadyPointTest(int variant, int maximumSize)
  {
    const bool storage = variant == POINT_TEST_STORAGE_BUFFER;
    const vtkIdType height = this->Run.BitsHeight;
    if (storage ? !this->AllocateStorage(this->Run.N)
                : (height > maximumSize ||
                    !this->AllocateBits(this->Run.BitsWidth, static_cast<int>(height))))
    {
      return false;
    }
    vtkShaderProgram* program = this->Context->GetShaderCache()->ReadyShaderProgram(
      TestShader(storage).c_str(), storage ? DepthFS : TestFS, "");
    this->Run.TestProgram = program;
    if (!program || !program->GetCompiled())
    {
      return false;
    }
#ifndef GL_ES_VERSION_3_0
    if (storage)
    {
      const GLuint handle = static_cast<GLuint>(program->GetHandle());
      const GLuint block = glGetProgramResourceIndex(handle, GL_SHADER_STORAGE_BLOCK, "BitsBlock");
      if (block == GL_INVALID_INDEX)
      {
        return false;
      }
      glShaderStorageBlockBinding(handle, block, 0);
    }
#endif
    this->TestLayout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->TestLayout->Bind();
    const int stride = 6 * sizeof(float);
    const bool bound = this->TestLayout->AddAttributeArray(
                         program, this->Tests, "testMC", 0, stride, VTK_FLOAT, 3, false) &&
      this->TestLayout->AddAttributeArray(
        program, this->Tests, "normalMC", 3 * sizeof(float), stride, VTK_FLOAT, 3, false);
    this->TestLayout->Release();
    return bound;
  }

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
    vtkAOBaking::ClearErrors(); // earlier errors are not this allocation's
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

  void Release() override
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
  this->ContextResources.reset(this->Internals);
}

vtkAOSattlerBaker::~vtkAOSattlerBaker() = default;

//------------------------------------------------------------------------------
void vtkAOSattlerBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "DepthOffset: " << this->DepthOffset << " (effective "
     << this->EffectiveDepthOffset << ")\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "StoreVisibility: " << this->StoreVisibility << "\n";
  os << indent << "PointTest: " << GetPointTestAsString(this->PointTest) << " (used "
     << GetPointTestAsString(this->PointTestUsed) << ")\n";
  os << indent << "Intensities: " << this->Intensities.size() << " values, "
     << this->IntensityComponents << " component(s)\n";
  os << indent << "RadianceArrayName: " << this->RadianceArrayName << "\n";
  os << indent << "TestTime: " << this->TestTime << "\n";
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
  const std::vector<double> mean = MeanIntensity(intensities, k, components);
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
void vtkAOSattlerBaker::InitializeResults(vtkIdType numberOfPoints)
{
  this->Superclass::InitializeResults(numberOfPoints);
  this->TestTime = 0.0;
  this->PointTestUsed = POINT_TEST_CPU;
  this->Visibility.clear();
  this->Visibility.shrink_to_fit();
  const int k = this->NumberOfDirections;
  this->Directions = MakeDirections(k, this->Seed);
  this->WordsPerPoint = (k + 31) / 32;
  const size_t comps = static_cast<size_t>(this->IntensityComponents);
  if (!this->Intensities.empty() && this->Intensities.size() != static_cast<size_t>(k) * comps)
  {
    vtkWarningMacro(<< "Intensities hold " << this->Intensities.size() << " values, expected " << k
                    << " x " << comps << ": no radiance array.");
  }
  const size_t n = static_cast<size_t>(numberOfPoints);
  this->Normals.assign(3 * n, 0.0f);
  this->CosineSums.assign(n, 0.0f);
  if (this->StoreVisibility)
  {
    this->Visibility.assign(n * this->WordsPerPoint, 0u);
  }
}

//------------------------------------------------------------------------------
int vtkAOSattlerBaker::BakePoints(Surface& surface, float* values)
{
  this->NumberOfTriangles = static_cast<vtkIdType>(surface.GetNumberOfTriangles());
  this->PlaceTestPoints(surface);
  if (!this->PrepareDepthPass(surface))
  {
    return 0;
  }
  this->SelectPointTest();
  this->RenderDirections();
  vtkOpenGLCheckErrorMacro("failed after baking visibility");
  this->WriteResults(surface, values);
  if (!this->StoreVisibility)
  {
    this->Normals.clear(); // nothing of the matrix is kept
    this->CosineSums.clear();
  }
  return 1;
}

//------------------------------------------------------------------------------
// The frame (a sphere around the bounds, seen by an orthographic camera), the effective bias
// and depth offset, and every baked point's test point p + bias n and unit normal.
void vtkAOSattlerBaker::PlaceTestPoints(const Surface& surface)
{
  auto& run = this->Internals->Run;
  const double* bounds = surface.Bounds;
  Center(bounds, run.Center);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : AutomaticBias(bounds);
  run.Extent = 0.5 * diagonal * 1.01 + 2.0 * this->EffectiveBias;
  if (!(run.Extent > 0.0))
  {
    run.Extent = 1.0;
  }
  run.Size = this->Resolution;
  run.Pixel = 2.0 * run.Extent / run.Size;
  // Float rounding of the rasterized depth only: the snapping term covers the point's own
  // surface, and any more tolerance lets real occluders near the point through.
  this->EffectiveDepthOffset = this->DepthOffset > 0.0 ? this->DepthOffset : 0.02 * run.Pixel;

  const vtkIdType n = surface.Input->GetNumberOfPoints();
  run.N = n;
  run.Tests.assign(3 * static_cast<size_t>(n), 0.0);
  run.Valid.assign(static_cast<size_t>(n), 0);
  vtkPoints* points = surface.Input->GetPoints();
  for (vtkIdType i : surface.Baked)
  {
    double p[3];
    points->GetPoint(i, p);
    const double* nrm = &surface.Normals[3 * i];
    run.Valid[i] = 1;
    for (int d = 0; d < 3; ++d)
    {
      run.Tests[3 * i + d] = p[d] - run.Center[d] + this->EffectiveBias * nrm[d];
      this->Normals[3 * i + d] = static_cast<float>(nrm[d]);
    }
  }
  run.VisibleSums.assign(static_cast<size_t>(n), 0.0f);
  const int k = this->NumberOfDirections;
  run.Components = this->IntensityComponents;
  run.Radiance = !this->Intensities.empty() &&
    this->Intensities.size() == static_cast<size_t>(k) * run.Components;
  run.RadianceSums.assign(run.Radiance ? static_cast<size_t>(n) * run.Components : 0, 0.0);
  run.Tolerance = this->EffectiveDepthOffset / (2.0 * run.Extent);
  run.HalfDiagonal = std::sqrt(0.5) * run.Pixel / (2.0 * run.Extent);
  run.BiasDepth = this->EffectiveBias / (2.0 * run.Extent);
}

//------------------------------------------------------------------------------
// The OpenGL context, the depth framebuffer and shader, and the scene (relative to the centre)
// in a vertex array drawn indexed.
bool vtkAOSattlerBaker::PrepareDepthPass(Surface& surface)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  run.Context = this->MakeContext();
  if (!run.Context)
  {
    return false;
  }
  if (!internals.Allocate(run.Context, run.Size))
  {
    vtkErrorMacro(<< "Couldn't create a " << run.Size << "x" << run.Size << " depth framebuffer.");
    internals.Release();
    return false;
  }
  run.DepthProgram = run.Context->GetShaderCache()->ReadyShaderProgram(DepthVS, DepthFS, "");
  if (!run.DepthProgram || !run.DepthProgram->GetCompiled())
  {
    vtkErrorMacro(<< "Couldn't build the depth shader.");
    return false;
  }
  internals.ReleaseBuffers();
  run.TriangleCount = surface.GetNumberOfTriangles();
  if (!vtkAOBaking::UploadScene(
        surface.Points, surface.Triangles, run.Center, internals.Points, internals.Indices))
  {
    vtkErrorMacro(<< "Couldn't upload " << run.TriangleCount << " triangles.");
    return false;
  }
  internals.Layout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  internals.Layout->Bind();
  if (!internals.Layout->AddAttributeArray(
        run.DepthProgram, internals.Points, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false))
  {
    vtkErrorMacro(<< "Couldn't bind the vertex layout.");
    internals.Layout->Release();
    return false;
  }
  internals.Indices->Bind(); // recorded in the vertex array object
  internals.Layout->Release();
  return true;
}

//------------------------------------------------------------------------------
// The GPU point test: the test points and normals as vertex attributes, and a shader storage
// buffer (STORAGE_BUFFER) or an R32UI texture of BitsWidth x BitsHeight texels (LOGIC_OP) of
// one word per point. Any failure: the next variant, at last the CPU test.
void vtkAOSattlerBaker::SelectPointTest()
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  const vtkIdType n = run.N;
  run.Test = POINT_TEST_CPU;
  run.TestProgram = nullptr;
  const int maximumSize = vtkTextureObject::GetMaximumTextureSize(run.Context);
  run.BitsWidth = static_cast<int>(std::min<vtkIdType>(n, std::min(4096, maximumSize)));
  run.BitsHeight = (n + run.BitsWidth - 1) / run.BitsWidth;
  if (this->PointTest != POINT_TEST_CPU)
  {
    std::vector<float> attributes(6 * static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int d = 0; d < 3; ++d)
      {
        attributes[6 * i + d] = static_cast<float>(run.Tests[3 * i + d]);
        attributes[6 * i + 3 + d] = this->Normals[3 * i + d]; // zero for invalid points
      }
    }
    internals.Tests = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    internals.Tests->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    const bool uploaded = internals.Tests->Upload(attributes, vtkOpenGLBufferObject::ArrayBuffer);
    for (int variant : { POINT_TEST_STORAGE_BUFFER, POINT_TEST_LOGIC_OP })
    {
      if (uploaded && run.Test == POINT_TEST_CPU &&
        !(variant == POINT_TEST_STORAGE_BUFFER && this->PointTest == POINT_TEST_LOGIC_OP))
      {
        run.Test = internals.ReadyPointTest(variant, maximumSize) ? variant : POINT_TEST_CPU;
      }
    }
    if (run.Test == POINT_TEST_CPU)
    {
      vtkDebugMacro(<< "No GPU point test is available: testing on the CPU.");
    }
  }
  this->PointTestUsed = run.Test;
  const bool gpu = run.Test != POINT_TEST_CPU;
  run.DepthValues.assign(gpu ? 0 : static_cast<size_t>(run.Size) * run.Size, 0.0f);
  run.Words.assign(
    gpu ? static_cast<size_t>(std::max<vtkIdType>(n, run.BitsWidth * run.BitsHeight)) : 0, 0u);
  run.Zeros.assign(run.Test == POINT_TEST_STORAGE_BUFFER ? static_cast<size_t>(n) : 0, 0u);
}

//------------------------------------------------------------------------------
// Every direction: its depth map, then every point tested against it. The OpenGL state that
// is touched is saved and restored (the window may belong to someone else).
void vtkAOSattlerBaker::RenderDirections()
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLState* state = run.Context->GetState();
  vtkAOBaking::ScopedDrawState stateSaver(
    state, { GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_SCISSOR_TEST });
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
#ifndef GL_ES_VERSION_3_0
  vtkOpenGLState::ScopedglEnableDisable logicOpSaver(state, GL_COLOR_LOGIC_OP);
  vtkOpenGLState::ScopedglEnableDisable pointSizeSaver(state, GL_PROGRAM_POINT_SIZE);
  vtkOpenGLState::ScopedglEnableDisable discardSaver(state, GL_RASTERIZER_DISCARD);
  GLint logicOpMode = GL_COPY;
  glGetIntegerv(GL_LOGIC_OP_MODE, &logicOpMode);
  GLint storageBinding = 0, storageBinding0 = 0;
  if (run.Test == POINT_TEST_STORAGE_BUFFER)
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
  state->vtkglViewport(0, 0, run.Size, run.Size);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);

  this->UpdateProgress(0.0);
  const int k = this->NumberOfDirections;
  for (int j = 0; j < k && !this->GetAbortExecute(); ++j)
  {
    this->RenderDepthMap(j);
    if (run.Test != POINT_TEST_CPU)
    {
      this->TestPointsOnGPU(j);
    }
    else
    {
      this->TestPointsOnCPU(j);
    }
    this->UpdateProgress(static_cast<double>(j + 1) / k);
  }
  internals.Framebuffer->UnBind();
  internals.Framebuffer->RestorePreviousBindingsAndBuffers();
#ifndef GL_ES_VERSION_3_0
  glLogicOp(static_cast<GLenum>(logicOpMode));
  if (run.Test == POINT_TEST_STORAGE_BUFFER)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLuint>(storageBinding0));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageBinding));
  }
#endif
}

//------------------------------------------------------------------------------
// The depth of the scene seen along -l_j by an orthographic camera on the +l_j side; the CPU
// test reads it back (its time counts as rendering).
void vtkAOSattlerBaker::RenderDepthMap(int j)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  const double* l = &this->Directions[3 * static_cast<size_t>(j)];
  vtkAOBaking::Basis(l, run.U, run.V);
  // NDC (u.x, v.x, -l.x) / extent. Column major.
  float projection[16] = { 0 };
  for (int d = 0; d < 3; ++d)
  {
    projection[4 * d + 0] = static_cast<float>(run.U[d] / run.Extent);
    projection[4 * d + 1] = static_cast<float>(run.V[d] / run.Extent);
    projection[4 * d + 2] = static_cast<float>(-l[d] / run.Extent);
  }
  projection[15] = 1.0f;

  const auto drawStart = Clock::now();
  vtkOpenGLState* state = run.Context->GetState();
  run.Context->GetShaderCache()->ReadyShaderProgram(run.DepthProgram);
  run.DepthProgram->SetUniformMatrix4x4("projection", projection);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  internals.Layout->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * run.TriangleCount), GL_UNSIGNED_INT, nullptr);
  internals.Layout->Release();
  if (run.Test == POINT_TEST_CPU)
  {
    glReadPixels(0, 0, run.Size, run.Size, GL_DEPTH_COMPONENT, GL_FLOAT, run.DepthValues.data());
  }
  this->RenderTime += Seconds(drawStart);
}

//------------------------------------------------------------------------------
// The GPU test of direction j: one point per vertex sets its bit; every 32 directions the words
// are read back and recorded in direction order (as the CPU test does).
void vtkAOSattlerBaker::TestPointsOnGPU(int j)
{
#ifndef GL_ES_VERSION_3_0
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  vtkOpenGLState* state = run.Context->GetState();
  const auto testStart = Clock::now();
  const bool storage = run.Test == POINT_TEST_STORAGE_BUFFER;
  const int bitsHeight = static_cast<int>(run.BitsHeight);
  if (storage)
  {
    // No fragments: the depth framebuffer stays bound.
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, internals.Storage);
    if (j % 32 == 0)
    {
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, 4 * run.N, run.Zeros.data());
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, internals.Storage);
    state->vtkglEnable(GL_RASTERIZER_DISCARD);
  }
  else
  {
    internals.BitsFramebuffer->Bind();
    internals.BitsFramebuffer->ActivateDrawBuffers(1);
    internals.BitsFramebuffer->ActivateReadBuffer(0);
    state->vtkglViewport(0, 0, run.BitsWidth, bitsHeight);
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
  vtkShaderProgram* program = run.TestProgram;
  run.Context->GetShaderCache()->ReadyShaderProgram(program);
  internals.Depth->Activate();
  program->SetUniformi("depthMap", internals.Depth->GetTextureUnit());
  program->SetUniform3f("direction", &this->Directions[3 * static_cast<size_t>(j)]);
  program->SetUniform3f("axisU", run.U);
  program->SetUniform3f("axisV", run.V);
  program->SetUniformf("extent", static_cast<float>(run.Extent));
  program->SetUniformi("size", run.Size);
  program->SetUniformf("tolerance", static_cast<float>(run.Tolerance));
  program->SetUniformf("halfDiagonal", static_cast<float>(run.HalfDiagonal));
  program->SetUniformf("biasDepth", static_cast<float>(run.BiasDepth));
  program->SetUniformi("bit", j % 32);
  if (!storage)
  {
    const int bitsSize[2] = { run.BitsWidth, bitsHeight };
    program->SetUniform2i("bitsSize", bitsSize);
  }
  internals.TestLayout->Bind();
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(run.N));
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
  if (j % 32 == 31 || j == this->NumberOfDirections - 1)
  {
    this->RecordGPUBits(j);
  }
  if (!storage)
  {
    internals.Framebuffer->Bind();
    state->vtkglViewport(0, 0, run.Size, run.Size);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglEnable(GL_DEPTH_TEST);
  }
  this->TestTime += Seconds(testStart);
#else
  (void)j;
#endif
}

//------------------------------------------------------------------------------
// The words of the last (up to) 32 directions read back, then recorded in direction order (as
// the CPU test does).
void vtkAOSattlerBaker::RecordGPUBits(int j)
{
#ifndef GL_ES_VERSION_3_0
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  const bool storage = run.Test == POINT_TEST_STORAGE_BUFFER;
  const int bitsHeight = static_cast<int>(run.BitsHeight);
  if (storage)
  {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, 4 * run.N, run.Words.data());
  }
  else
  {
    glReadPixels(
      0, 0, run.BitsWidth, bitsHeight, GL_RED_INTEGER, GL_UNSIGNED_INT, run.Words.data());
  }
  const int first = j - j % 32;
  run.ForEachBakedPoint(
    [&](vtkIdType i)
    {
      const float* nrm = &this->Normals[3 * i];
      for (int jj = first; jj <= j; ++jj)
      {
        const double* lj = &this->Directions[3 * static_cast<size_t>(jj)];
        const double cosine = nrm[0] * lj[0] + nrm[1] * lj[1] + nrm[2] * lj[2];
        if (cosine > 0.0)
        {
          internals.Record(this, i, jj, cosine, (run.Words[i] >> (jj % 32)) & 1u);
        }
      }
    });
#else
  (void)j;
#endif
}

//------------------------------------------------------------------------------
// The CPU test of direction j against the depth map read back: a point sees l_j when nothing
// in the map lies nearer to the camera than its test point, less the allowance for the
// pixel-centre sampling (SnapAllowance).
void vtkAOSattlerBaker::TestPointsOnCPU(int j)
{
  auto& internals = *this->Internals;
  auto& run = internals.Run;
  const auto testStart = Clock::now();
  const double* l = &this->Directions[3 * static_cast<size_t>(j)];
  const double* u = run.U;
  const double* v = run.V;
  const double extent = run.Extent;
  const int size = run.Size;
  const float* map = run.DepthValues.data();
  run.ForEachBakedPoint(
    [&](vtkIdType i)
    {
      const float* nrm = &this->Normals[3 * i];
      const double cosine = nrm[0] * l[0] + nrm[1] * l[1] + nrm[2] * l[2];
      if (cosine <= 0.0)
      {
        return;
      }
      const double* q = &run.Tests[3 * i];
      const double x = (q[0] * u[0] + q[1] * u[1] + q[2] * u[2]) / extent;
      const double y = (q[0] * v[0] + q[1] * v[1] + q[2] * v[2]) / extent;
      const double s = (q[0] * l[0] + q[1] * l[1] + q[2] * l[2]) / extent;
      const int px = std::min(size - 1, std::max(0, static_cast<int>((x + 1.0) * 0.5 * size)));
      const int py = std::min(size - 1, std::max(0, static_cast<int>((y + 1.0) * 0.5 * size)));
      const double pointDepth = 0.5 * (1.0 - s);
      const double allowed = run.SnapAllowance(cosine);
      internals.Record(
        this, i, j, cosine, map[static_cast<size_t>(py) * size + px] >= pointDepth - allowed);
    });
  this->TestTime += Seconds(testStart);
}

//------------------------------------------------------------------------------
// A = visible cosines / all cosines; the radiance c_i when intensities are set (the mean
// intensity where a point has no valid normal).
void vtkAOSattlerBaker::WriteResults(Surface& surface, float* values)
{
  auto& run = this->Internals->Run;
  const vtkIdType n = run.N;
  const float* cosineSums = this->CosineSums.data();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (run.Valid[i] && cosineSums[i] > 0.0f)
    {
      values[i] = std::min(1.0f, run.VisibleSums[i] / cosineSums[i]);
    }
  }
  if (!run.Radiance)
  {
    return;
  }
  const int comps = run.Components;
  const int k = this->NumberOfDirections;
  vtkNew<vtkFloatArray> light;
  light->SetName(this->RadianceArrayName.c_str());
  light->SetNumberOfComponents(comps);
  light->SetNumberOfTuples(n);
  const std::vector<double> mean = MeanIntensity(this->Intensities, k, comps);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < comps; ++c)
    {
      light->SetTypedComponent(i,
        c,
        static_cast<float>(run.Valid[i] && cosineSums[i] > 0.0f
            ? run.RadianceSums[static_cast<size_t>(i) * comps + c] / cosineSums[i]
            : mean[c]));
    }
  }
  surface.Output->GetPointData()->AddArray(light);
}
