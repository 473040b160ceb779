#include "vtkAOOpenGLBaker.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

//------------------------------------------------------------------------------
vtkAOOpenGLBaker::vtkAOOpenGLBaker() = default;

vtkAOOpenGLBaker::~vtkAOOpenGLBaker()
{
  this->ReleaseGraphicsResources();
  if (this->RenderWindow)
  {
    this->RenderWindow->UnRegister(this);
  }
}

//------------------------------------------------------------------------------
void vtkAOOpenGLBaker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "RenderTime: " << this->RenderTime << "\n";
}

//------------------------------------------------------------------------------
void vtkAOOpenGLBaker::InitializeResults(vtkIdType numberOfPoints)
{
  this->Superclass::InitializeResults(numberOfPoints);
  this->NumberOfTriangles = 0;
  this->RenderTime = 0.0;
}

//------------------------------------------------------------------------------
void vtkAOOpenGLBaker::SetRenderWindow(vtkRenderWindow* window)
{
  if (window == this->RenderWindow)
  {
    return;
  }
  if (this->ContextResources)
  {
    this->ContextResources->Release(); // while the old window is still registered
  }
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

void vtkAOOpenGLBaker::ReleaseGraphicsResources()
{
  if (this->ContextResources)
  {
    this->ContextResources->Release();
  }
  this->OwnWindow = nullptr;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkAOOpenGLBaker::MakeContext()
{
  vtkRenderWindow* window = this->RenderWindow;
  if (!window)
  {
    if (!this->OwnWindow)
    {
      this->OwnWindow = vtkSmartPointer<vtkRenderWindow>::New();
      this->OwnWindow->SetOffScreenRendering(1);
      this->OwnWindow->SetMultiSamples(0);
      this->OwnWindow->SetSize(16, 16);
      vtkNew<vtkRenderer> empty;
      this->OwnWindow->AddRenderer(empty);
      this->OwnWindow->Render(); // creates the context
      this->OwnWindow->RemoveRenderer(empty);
    }
    window = this->OwnWindow;
  }
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context)
  {
    vtkErrorMacro(<< "The render window is not a vtkOpenGLRenderWindow.");
    return nullptr;
  }
  context->Initialize();
  context->MakeCurrent();
  return context;
}
