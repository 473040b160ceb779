#include "vtkAOQuadStage.h"

#include "vtkAOShaderUtilities.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

//------------------------------------------------------------------------------
vtkAOQuadStage::vtkAOQuadStage() = default;

//------------------------------------------------------------------------------
vtkAOQuadStage::~vtkAOQuadStage()
{
  vtkAOShaderUtilities::DeleteObjects({ this->Output, this->FrameBufferObject });
}

//------------------------------------------------------------------------------
void vtkAOQuadStage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Output: " << this->Output << "\n";
}

//------------------------------------------------------------------------------
void vtkAOQuadStage::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Quad.reset();
  vtkAOShaderUtilities::ReleaseTexture(this->Output, vtkOpenGLRenderWindow::SafeDownCast(w));
  vtkAOShaderUtilities::ReleaseFramebuffer(this->FrameBufferObject, w);
}

//------------------------------------------------------------------------------
long long vtkAOQuadStage::GetGraphicsMemorySize()
{
  return vtkAOShaderUtilities::TextureBytes(this->Output);
}
