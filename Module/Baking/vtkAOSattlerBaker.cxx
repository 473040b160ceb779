#include "vtkAOSattlerBaker.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
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
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

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

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

bool Finite3(const double x[3])
{
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// Two unit vectors completing l to a right-handed orthonormal basis (u, v, l).
void Basis(const double l[3], double u[3], double v[3])
{
  const double helper[3] = {
    std::fabs(l[0]) < 0.9 ? 1.0 : 0.0, std::fabs(l[0]) < 0.9 ? 0.0 : 1.0, 0.0
  };
  vtkMath::Cross(helper, l, u);
  vtkMath::Normalize(u);
  vtkMath::Cross(l, u, v);
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
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> Layout;
  int Size = 0;

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
      if (this->Triangles)
      {
        this->Triangles->ReleaseGraphicsResources();
      }
      if (this->Layout)
      {
        this->Layout->ReleaseGraphicsResources();
      }
    }
    this->Framebuffer = nullptr;
    this->Depth = nullptr;
    this->Color = nullptr;
    this->Triangles = nullptr;
    this->Layout = nullptr;
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
  std::vector<float> triangles; // 9 floats each, relative to the centre (set below)
  std::vector<double> world;    // the same in double, before centring
  std::vector<char> onSurface(static_cast<size_t>(n), 0);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkCellArray> strips;
  double bounds[6] = { VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  auto addTriangle = [&](const double a[3], const double b[3], const double c[3])
  {
    double e1[3], e2[3], cross[3];
    vtkMath::Subtract(b, a, e1);
    vtkMath::Subtract(c, a, e2);
    vtkMath::Cross(e1, e2, cross);
    if (!(vtkMath::Norm(cross) > 0.0))
    {
      return false;
    }
    for (const double* p : { a, b, c })
    {
      for (int d = 0; d < 3; ++d)
      {
        world.push_back(p[d]);
        bounds[2 * d] = std::min(bounds[2 * d], p[d]);
        bounds[2 * d + 1] = std::max(bounds[2 * d + 1], p[d]);
      }
    }
    return true;
  };
  const int occluders = inputVector[1]->GetNumberOfInformationObjects();
  for (int source = -1; source < occluders; ++source)
  {
    vtkPolyData* data = source < 0 ? input : vtkPolyData::GetData(inputVector[1], source);
    if (!data || !data->GetPoints())
    {
      continue;
    }
    vtkPoints* points = data->GetPoints();
    const vtkIdType count = data->GetNumberOfPoints();
    for (int kind = 0; kind < 2; ++kind)
    {
      vtkCellArray* cells = kind == 0 ? data->GetPolys() : data->GetStrips();
      vtkIdType npts = 0;
      const vtkIdType* pts = nullptr;
      auto it = vtk::TakeSmartPointer(cells->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        it->GetCurrentCell(npts, pts);
        bool valid = npts >= 3;
        for (vtkIdType c = 0; valid && c < npts; ++c)
        {
          double x[3];
          valid = pts[c] >= 0 && pts[c] < count;
          if (valid)
          {
            points->GetPoint(pts[c], x);
            valid = Finite3(x);
          }
        }
        if (!valid)
        {
          continue;
        }
        // Polygons as fans, strips with alternating orientation (orientation does not matter:
        // both faces occlude).
        bool any = false;
        for (vtkIdType c = 2; c < npts; ++c)
        {
          double a[3], b[3], d[3];
          points->GetPoint(kind == 0 ? pts[0] : pts[c - 2], a);
          points->GetPoint(pts[c - 1], b);
          points->GetPoint(pts[c], d);
          any = addTriangle(a, b, d) || any;
        }
        if (source < 0 && any)
        {
          (kind == 0 ? polys : strips)->InsertNextCell(npts, pts);
          for (vtkIdType c = 0; c < npts; ++c)
          {
            onSurface[pts[c]] = 1;
          }
        }
      }
    }
  }
  const size_t triangleCount = world.size() / 9;
  this->NumberOfTriangles = static_cast<vtkIdType>(triangleCount);
  if (n == 0 || triangleCount == 0)
  {
    this->TotalTime = Seconds(start);
    return 1;
  }

  // Point normals: the input's, or computed without splitting (point ids are kept).
  vtkSmartPointer<vtkDataArray> normals = input->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n)
  {
    vtkNew<vtkPolyDataNormals> compute;
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(input->GetPoints());
    surface->SetPolys(polys);
    surface->SetStrips(strips);
    compute->SetInputData(surface);
    compute->SplittingOff();
    compute->ConsistencyOn();
    compute->AutoOrientNormalsOff();
    compute->ComputePointNormalsOn();
    compute->ComputeCellNormalsOff();
    compute->Update();
    normals = compute->GetOutput()->GetPointData()->GetNormals();
    if (!normals || normals->GetNumberOfTuples() != n)
    {
      vtkErrorMacro(<< "Couldn't compute point normals for the input.");
      return 0;
    }
  }

  // The frame: a sphere around the bounds; automatic bias as vtkAOVertexBaker's.
  const double center[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  this->EffectiveBias = this->Bias > 0.0 ? this->Bias : 2.0 * (longest + 0.2 * diagonal) / 256.0;
  double extent = 0.5 * diagonal * 1.01 + 2.0 * this->EffectiveBias;
  if (!(extent > 0.0))
  {
    extent = 1.0;
  }
  const int size = this->Resolution;
  const double pixel = 2.0 * extent / size;
  this->EffectiveDepthOffset = this->DepthOffset > 0.0 ? this->DepthOffset : 1.5 * pixel;

  triangles.resize(world.size());
  for (size_t v = 0; v < world.size(); ++v)
  {
    triangles[v] = static_cast<float>(world[v] - center[v % 3]);
  }
  world.clear();
  world.shrink_to_fit();

  // Test points (relative to the centre) and unit normals.
  std::vector<double> tests(3 * static_cast<size_t>(n), 0.0);
  std::vector<char> valid(static_cast<size_t>(n), 0);
  vtkPoints* points = input->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], nrm[3];
    points->GetPoint(i, p);
    normals->GetTuple(i, nrm);
    if (!onSurface[i] || !Finite3(p) || !Finite3(nrm) || vtkMath::Normalize(nrm) == 0.0)
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
  vtkRenderWindow* window = this->RenderWindow;
  if (!window)
  {
    if (!this->Internals->OwnWindow)
    {
      this->Internals->OwnWindow = vtkSmartPointer<vtkRenderWindow>::New();
      this->Internals->OwnWindow->SetOffScreenRendering(1);
      this->Internals->OwnWindow->SetMultiSamples(0);
      this->Internals->OwnWindow->SetSize(16, 16);
      vtkNew<vtkRenderer> empty;
      this->Internals->OwnWindow->AddRenderer(empty);
      this->Internals->OwnWindow->Render(); // creates the context
      this->Internals->OwnWindow->RemoveRenderer(empty);
    }
    window = this->Internals->OwnWindow;
  }
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context)
  {
    vtkErrorMacro(<< "The render window is not a vtkOpenGLRenderWindow.");
    return 0;
  }
  context->Initialize();
  context->MakeCurrent();
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
  internals.Triangles = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  internals.Triangles->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  if (!internals.Triangles->Upload(triangles, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorMacro(<< "Couldn't upload " << triangleCount << " triangles.");
    return 0;
  }
  internals.Layout = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  internals.Layout->Bind();
  if (!internals.Layout->AddAttributeArray(
        program, internals.Triangles, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false))
  {
    vtkErrorMacro(<< "Couldn't bind the vertex layout.");
    internals.Layout->Release();
    return 0;
  }
  internals.Layout->Release();
  triangles.clear();
  triangles.shrink_to_fit();

  std::vector<float> depth(static_cast<size_t>(size) * size);
  std::vector<float> visibleSums(static_cast<size_t>(n), 0.0f);
  std::vector<double> radianceSums(radiance ? static_cast<size_t>(n) * comps : 0, 0.0);
  const double tolerance = this->EffectiveDepthOffset / (2.0 * extent);
  const double slopeUnit = pixel / (2.0 * extent);
  float* cosineSums = this->CosineSums.data();
  const float* unit = this->Normals.data();
  std::uint32_t* bits = this->Visibility.empty() ? nullptr : this->Visibility.data();
  const int words = this->WordsPerPoint;

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
      Basis(l, u, v);
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
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangleCount));
      internals.Layout->Release();
      glReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
      this->RenderTime += Seconds(drawStart);

      const auto testStart = Clock::now();
      const float* map = depth.data();
      const std::uint32_t mask = 1u << (j % 32);
      const int word = j / 32;
      const double* intensity =
        radiance ? &this->Intensities[static_cast<size_t>(j) * comps] : nullptr;
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
            cosineSums[i] += static_cast<float>(cosine);
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
            if (map[static_cast<size_t>(py) * size + px] >= pointDepth - allowed)
            {
              visibleSums[i] += static_cast<float>(cosine);
              if (bits)
              {
                bits[static_cast<size_t>(i) * words + word] |= mask;
              }
              if (intensity)
              {
                for (int c = 0; c < comps; ++c)
                {
                  radianceSums[static_cast<size_t>(i) * comps + c] += cosine * intensity[c];
                }
              }
            }
          }
        });
      this->TestTime += Seconds(testStart);
      this->UpdateProgress(static_cast<double>(j + 1) / k);
    }
    internals.Framebuffer->UnBind();
    internals.Framebuffer->RestorePreviousBindingsAndBuffers();
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
