#include "vtkAOVoxelTracer.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVoxelTracerFS.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkAOVoxelTracer);

namespace
{
constexpr int NoiseSize = 32; // texels per side of the tiled 3-D noise
}

//------------------------------------------------------------------------------
vtkAOVoxelTracer::vtkAOVoxelTracer() = default;

//------------------------------------------------------------------------------
vtkAOVoxelTracer::~vtkAOVoxelTracer()
{
  for (vtkObject* o : { static_cast<vtkObject*>(this->Output),
         static_cast<vtkObject*>(this->Noise),
         static_cast<vtkObject*>(this->FrameBufferObject) })
  {
    if (o)
    {
      o->Delete();
    }
  }
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Output: " << this->Output << "\n";
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::InitializeNoise(vtkOpenGLRenderWindow* renWin)
{
  if (this->Noise && this->Noise->GetContext() == renWin)
  {
    return;
  }
  vtkAOShaderUtilities::ReleaseTexture(this->Noise, renWin);
  // White noise, fixed seed: the same jitter every run, so images are repeatable.
  std::mt19937 generator(20090401u);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<unsigned char> texels(NoiseSize * NoiseSize * NoiseSize * 4);
  for (auto& t : texels)
  {
    t = static_cast<unsigned char>(byte(generator));
  }
  this->Noise = vtkTextureObject::New();
  this->Noise->SetContext(renWin);
  this->Noise->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Noise->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Noise->SetWrapS(vtkTextureObject::Repeat);
  this->Noise->SetWrapT(vtkTextureObject::Repeat);
  this->Noise->SetWrapR(vtkTextureObject::Repeat);
  this->Noise->Create3DFromRaw(
    NoiseSize, NoiseSize, NoiseSize, 4, VTK_UNSIGNED_CHAR, texels.data());
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::Trace(vtkOpenGLRenderWindow* renWin,
  vtkAOGBufferPass* gbuffer,
  vtkAOBitmaskVoxelizer* grid,
  vtkMatrix4x4* view,
  vtkMatrix4x4* projection,
  const Parameters& par)
{
  const int w = gbuffer->GetWidth(), h = gbuffer->GetHeight();
  const int lw = (w + par.Scale - 1) / par.Scale, lh = (h + par.Scale - 1) / par.Scale;
  vtkAOShaderUtilities::EnsureFloatTexture(this->Output, renWin, lw, lh, 2);
  this->InitializeNoise(renWin);
  if (!this->FrameBufferObject)
  {
    this->FrameBufferObject = vtkOpenGLFramebufferObject::New();
    this->FrameBufferObject->SetContext(renWin);
  }
  if (!vtkAOShaderUtilities::ReadyQuad(this->Quad,
        renWin,
        vtkAOShaderUtilities::ComposeFragmentShader(vtkAOVoxelTracerFS),
        this,
        "voxel tracer"))
  {
    return false;
  }
  vtkShaderProgram* program = this->Quad->Program;

  vtkNew<vtkMatrix4x4> invProjection;
  vtkMatrix4x4::Invert(projection, invProjection);
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(view, viewToWorld);
  vtkNew<vtkMatrix4x4> viewToGrid;
  vtkMatrix4x4::Multiply4x4(grid->GetWorldToGridMatrix(), viewToWorld, viewToGrid);

  gbuffer->GetDepthTexture()->Activate();
  gbuffer->GetNormalTexture()->Activate();
  grid->GetGridTexture()->Activate();
  this->Noise->Activate();
  program->SetUniformi("aoDepth", gbuffer->GetDepthTexture()->GetTextureUnit());
  program->SetUniformi("aoNormal", gbuffer->GetNormalTexture()->GetTextureUnit());
  program->SetUniformi("aoGrid", grid->GetGridTexture()->GetTextureUnit());
  program->SetUniformi("aoNoise", this->Noise->GetTextureUnit());
  vtkAOShaderUtilities::SetMatrix(program, "aoInvProjection", invProjection);
  vtkAOShaderUtilities::SetMatrix(program, "aoViewToGrid", viewToGrid);
  vtkAOShaderUtilities::SetMatrix(program, "aoViewToWorld", viewToWorld);
  int dims[3];
  grid->GetGridDimensions(dims);
  const float gridSize[3] = { float(dims[0]), float(dims[1]), float(dims[2]) };
  program->SetUniform3f("aoGridSize", gridSize);
  const int fullSize[2] = { w, h };
  program->SetUniform2i("aoFullSize", fullSize);
  program->SetUniformi("aoParallel", par.Parallel ? 1 : 0);
  program->SetUniformi("aoScale", par.Scale);
  program->SetUniformi("aoRays", par.Rays);
  const double cell = grid->GetCellSize();
  program->SetUniformi("aoSteps", par.Steps);
  const double cellsPerStep = par.Radius / cell / par.Steps;
  program->SetUniformi(
    "aoSubSteps", std::max(1, std::min(4, static_cast<int>(std::ceil(cellsPerStep)))));
  program->SetUniformi("aoFalloff", par.BinaryFalloff ? 1 : 0);
  program->SetUniformf("aoRadiusCells", static_cast<float>(par.Radius / cell));
  program->SetUniformf("aoBiasCells", static_cast<float>(par.Bias / cell));
  program->SetUniformf(
    "aoSinSpread", static_cast<float>(std::sin(par.Spread * 0.5 * vtkMath::Pi())));
  // About two noise texels per cell: finer than the grid, coarser than float noise.
  program->SetUniformf("aoNoiseScale", static_cast<float>(2.0 / (cell * NoiseSize)));

  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  this->FrameBufferObject->AddColorAttachment(0, this->Output);
  renWin->GetState()->vtkglDrawBuffer(GL_NONE);
  this->FrameBufferObject->ActivateDrawBuffers(1);
  this->FrameBufferObject->StartNonOrtho(lw, lh);
  renWin->GetState()->vtkglViewport(0, 0, lw, lh);
  this->Quad->Render();
  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();

  this->Noise->Deactivate();
  grid->GetGridTexture()->Deactivate();
  gbuffer->GetNormalTexture()->Deactivate();
  gbuffer->GetDepthTexture()->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  this->Quad.reset();
  vtkAOShaderUtilities::ReleaseTexture(this->Output, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Noise, renWin);
  if (this->FrameBufferObject)
  {
    this->FrameBufferObject->ReleaseGraphicsResources(w);
    this->FrameBufferObject->Delete();
    this->FrameBufferObject = nullptr;
  }
}
