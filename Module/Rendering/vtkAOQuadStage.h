/**
 * @class   vtkAOQuadStage
 * @brief   Base of the AO stages that draw full-screen quads into a texture of their own.
 *
 * Owns what such a stage needs on the GPU, and frees it: the output texture, the framebuffer
 * it is drawn through and the quad program (vtkAOShaderUtilities::ReadyQuad builds it,
 * vtkAOShaderUtilities::DrawQuad draws it). A subclass adds its step (Trace, Upsample, ...)
 * and frees its other resources in its ReleaseGraphicsResources before calling this one.
 */
#ifndef vtkAOQuadStage_h
#define vtkAOQuadStage_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOQuadStage : public vtkObject
{
public:
  vtkTypeMacro(vtkAOQuadStage, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The texture the stage wrote last (nullptr before its first run).
   */
  vtkTextureObject* GetOutput() { return this->Output; }

  /**
   * Free the textures, framebuffer and programs.
   */
  virtual void ReleaseGraphicsResources(vtkWindow* w);

  /// Bytes of GPU memory in the textures this stage owns (0 after ReleaseGraphicsResources).
  virtual long long GetGraphicsMemorySize();

protected:
  vtkAOQuadStage();
  ~vtkAOQuadStage() override;

  vtkTextureObject* Output = nullptr;
  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;

private:
  vtkAOQuadStage(const vtkAOQuadStage&) = delete;
  void operator=(const vtkAOQuadStage&) = delete;
};

#endif
