#include "vtkAOReferenceRenderer.h"

#include "vtkAOCompositor.h"
#include "vtkAOEmbreeScene.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

vtkStandardNewMacro(vtkAOReferenceRenderer);

namespace
{
// The parameters of the integral of @p self's scene (after BuildScene).
vtkAOIntegralParameters IntegralParameters(vtkAOReferenceRenderer* self)
{
  vtkAOIntegralParameters parameters;
  parameters.Radius = self->GetEffectiveRadius();
  parameters.Bias = self->GetEffectiveBias();
  parameters.Spread = self->GetSpread();
  parameters.BinaryFalloff = self->GetFalloff() == vtkAOReferenceRenderer::BINARY;
  parameters.Samples = self->GetSamples();
  parameters.Seed = self->GetSeed();
  return parameters;
}

// The image size: @p self's Width and Height, or the renderer's size where either is 0.
bool ImageSize(vtkAOReferenceRenderer* self, vtkRenderer* renderer, int& w, int& h)
{
  w = self->GetWidth();
  h = self->GetHeight();
  if (w > 0 && h > 0)
  {
    return true;
  }
  const int* size = renderer->GetRenderWindow() ? renderer->GetSize() : nullptr;
  if (!size || size[0] <= 0 || size[1] <= 0)
  {
    vtkErrorWithObjectMacro(self,
      << "The image size is unknown: set Width and Height or put the renderer "
         "in a render window.");
    return false;
  }
  w = size[0];
  h = size[1];
  return true;
}

// The first surface the segment origin + t dir, t in [tMin, tMax], meets: its t and A there
// (the directions of pixel @p pixel), with the normal on the side of its triangle that the
// segment comes from, and the triangle's geometric normal in @p face. At a silhouette of a
// smooth mesh the interpolated normal leans away from the camera on a triangle that faces
// it; flipping it there by its own facing (as before) turned the rays into the object.
// Counts the rays cast in @p rays.
bool ShadeFirstHit(const vtkAOEmbreeScene& scene,
  const vtkAOIntegralParameters& parameters,
  const double origin[3],
  const double dir[3],
  double tMin,
  double tMax,
  size_t pixel,
  std::int64_t& rays,
  double& t,
  double& a,
  double face[3])
{
  double p[3], n[3];
  ++rays;
  if (!scene.Intersect(origin, dir, tMin, tMax, t, p, n, face))
  {
    return false;
  }
  const double visible = vtkMath::Dot(face, dir) > 0.0 ? -1.0 : 1.0;
  if (visible * vtkMath::Dot(n, face) < 0.0)
  {
    n[0] = -n[0];
    n[1] = -n[1];
    n[2] = -n[2];
  }
  a = scene.ComputeAccessibility(p, n, parameters, pixel, rays);
  return true;
}

// The A and coverage of a w x h image, one pixel per primary ray, traced through a scene.
struct PixelTracer
{
  const vtkAOEmbreeScene* Scene;
  vtkAOIntegralParameters Parameters;
  double Inverse[16]; // NDC -> world: the inverse of the matrix VTK renders with
  int Width, Height;
  float* Out;                      // A, coverage per pixel
  double Offset[2] = { 0.0, 0.0 }; // of the primary rays from the pixel centres, in pixels
  std::atomic<std::int64_t> Rays{ 0 };

  // The primary ray of pixel (x, y): from the near plane to the far plane.
  void PixelRay(int x, vtkIdType y, double origin[3], double dir[3]) const
  {
    const double wx = x + 0.5 + this->Offset[0], wy = y + 0.5 + this->Offset[1];
    double farEnd[3];
    vtkAOReferenceRenderer::UnprojectWindowPoint(
      this->Inverse, this->Width, this->Height, wx, wy, 0.0, origin);
    vtkAOReferenceRenderer::UnprojectWindowPoint(
      this->Inverse, this->Width, this->Height, wx, wy, 1.0, farEnd);
    for (int i = 0; i < 3; ++i)
    {
      dir[i] = farEnd[i] - origin[i];
    }
  }

  // Rows [y0, y1) (vtkSMPTools::For).
  void operator()(vtkIdType y0, vtkIdType y1)
  {
    std::int64_t rays = 0;
    for (vtkIdType y = y0; y < y1; ++y)
    {
      for (int x = 0; x < this->Width; ++x)
      {
        double origin[3], dir[3];
        this->PixelRay(x, y, origin, dir);
        const size_t pixel = static_cast<size_t>(y) * this->Width + x;
        double t, a, face[3];
        if (ShadeFirstHit(
              *this->Scene, this->Parameters, origin, dir, 0.0, 1.0, pixel, rays, t, a, face))
        {
          this->Out[2 * pixel] = static_cast<float>(a);
          this->Out[2 * pixel + 1] = 1.0f;
        }
        else
        {
          this->Out[2 * pixel] = 1.0f;
          this->Out[2 * pixel + 1] = 0.0f;
        }
      }
    }
    this->Rays += rays;
  }
};
}

//------------------------------------------------------------------------------
vtkAOReferenceRenderer::vtkAOReferenceRenderer() = default;
vtkAOReferenceRenderer::~vtkAOReferenceRenderer() = default;

//------------------------------------------------------------------------------
void vtkAOReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "Bias: " << this->Bias << " (effective " << this->EffectiveBias << ")\n";
  os << indent << "Spread: " << this->Spread << "\n";
  os << indent << "Falloff: " << (this->Falloff == BINARY ? "binary" : "Wendland") << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "PixelOffset: " << this->PixelOffset[0] << ", " << this->PixelOffset[1] << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "IncludeTranslucent: " << this->IncludeTranslucent << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "TraceTime: " << this->TraceTime << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}

//------------------------------------------------------------------------------
bool vtkAOReferenceRenderer::BuildScene(vtkRenderer* renderer)
{
  this->Scene.reset(new vtkAOEmbreeScene);
  if (renderer)
  {
    this->Scene->AddRenderer(renderer, this->IncludeTranslucent);
  }
  return this->FinishScene();
}

//------------------------------------------------------------------------------
bool vtkAOReferenceRenderer::BuildScene(vtkPolyDataCollection* surfaces)
{
  this->Scene.reset(new vtkAOEmbreeScene);
  if (surfaces)
  {
    vtkCollectionSimpleIterator it;
    surfaces->InitTraversal(it);
    while (vtkPolyData* surface = surfaces->GetNextPolyData(it))
    {
      this->Scene->AddPolyData(surface);
    }
  }
  return this->FinishScene();
}

//------------------------------------------------------------------------------
bool vtkAOReferenceRenderer::FinishScene()
{
  this->Scene->GetEffectiveRadiusAndBias(
    this->Radius, this->Bias, this->EffectiveRadius, this->EffectiveBias);
  if (!this->Scene->Commit())
  {
    vtkErrorMacro(<< "Couldn't build the ray-tracing scene: " << this->Scene->GetError());
    this->Scene.reset();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkAOReferenceRenderer::GetNumberOfTriangles()
{
  return this->Scene ? this->Scene->GetNumberOfTriangles() : 0;
}

//------------------------------------------------------------------------------
double vtkAOReferenceRenderer::ComputeAO(const double p[3], const double n[3])
{
  if (!this->Scene)
  {
    vtkErrorMacro(<< "ComputeAO needs a scene: call BuildScene first.");
    return -1.0;
  }
  double unit[3] = { n[0], n[1], n[2] };
  if (vtkMath::Normalize(unit) == 0.0)
  {
    return 1.0;
  }
  std::int64_t rays = 0;
  return this->Scene->ComputeAccessibility(p, unit, IntegralParameters(this), 0, rays);
}

//------------------------------------------------------------------------------
void vtkAOReferenceRenderer::UnprojectWindowPoint(const double inverse[16],
  int width,
  int height,
  double x,
  double y,
  double depth,
  double world[3])
{
  const double in[4] = { 2.0 * x / width - 1.0, 2.0 * y / height - 1.0, 2.0 * depth - 1.0, 1.0 };
  double out[4];
  vtkMatrix4x4::MultiplyPoint(inverse, in, out);
  for (int i = 0; i < 3; ++i)
  {
    world[i] = out[i] / out[3];
  }
}

//------------------------------------------------------------------------------
bool vtkAOReferenceRenderer::ComputeAOAlongRay(const double origin[3],
  const double direction[3],
  double tMin,
  double tMax,
  vtkIdType pixel,
  double& t,
  double& a,
  double face[3])
{
  if (!this->Scene)
  {
    vtkErrorMacro(<< "ComputeAOAlongRay needs a scene: call BuildScene first.");
    return false;
  }
  std::int64_t rays = 0;
  double hitT, hitA, hitFace[3];
  if (pixel < 0 ||
    !ShadeFirstHit(*this->Scene,
      IntegralParameters(this),
      origin,
      direction,
      tMin,
      tMax,
      static_cast<size_t>(pixel),
      rays,
      hitT,
      hitA,
      hitFace))
  {
    return false;
  }
  t = hitT;
  a = hitA;
  std::copy(hitFace, hitFace + 3, face);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOReferenceRenderer::Render(vtkRenderer* renderer, vtkImageData* image)
{
  if (!renderer || !image)
  {
    vtkErrorMacro(<< "Render needs a renderer and an output image.");
    return false;
  }
  int w, h;
  if (!ImageSize(this, renderer, w, h) || !this->BuildScene(renderer))
  {
    return false;
  }

  vtkNew<vtkFloatArray> values;
  vtkAOCompositor::InitializeOcclusionArray(values, static_cast<vtkIdType>(w) * h);
  PixelTracer tracer{
    this->Scene.get(), IntegralParameters(this), {}, w, h, values->GetPointer(0)
  };
  for (int i = 0; i < 2; ++i)
  {
    tracer.Offset[i] = std::max(-0.5, std::min(0.5, this->PixelOffset[i]));
  }
  // Pixel centres through the inverse of the matrix VTK renders with: NDC -> world.
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(w) / h, -1, 1));
  inverse->Invert();
  std::copy(&inverse->Element[0][0], &inverse->Element[0][0] + 16, tracer.Inverse);

  const auto start = std::chrono::steady_clock::now();
  this->NumberOfThreads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  // Blocks of rows in parallel; progress is reported between blocks, on this thread.
  const int block = std::max(1, h / 50);
  double progress = 0.0;
  this->InvokeEvent(vtkCommand::StartEvent);
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  for (int y0 = 0; y0 < h; y0 += block)
  {
    const int y1 = std::min(h, y0 + block);
    vtkSMPTools::For(y0, y1, 1, tracer);
    progress = static_cast<double>(y1) / h;
    this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  }
  this->InvokeEvent(vtkCommand::EndEvent);
  this->TraceTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfRays = tracer.Rays;

  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(values);
  return true;
}
