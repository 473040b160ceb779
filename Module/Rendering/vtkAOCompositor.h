/**
 * @class   vtkAOCompositor
 * @brief   Final stage of the ambient-occlusion passes: applies A to the shaded image.
 *
 * Draws a full-screen quad into the framebuffer that was bound when the pass began: the
 * G-buffer colour multiplied by A^Intensity (or A itself with AO-only), and the G-buffer
 * depth, so translucent props and overlays drawn afterwards are depth-tested correctly.
 */
#ifndef vtkAOCompositor_h
#define vtkAOCompositor_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr

class vtkAOGBufferPass;
class vtkFloatArray;
class vtkImageData;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOCompositor : public vtkObject
{
public:
  static vtkAOCompositor* New();
  vtkTypeMacro(vtkAOCompositor, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Composite into the current framebuffer's viewport (x, y, w, h). @p occlusionScale is 1 for
   * a full-resolution AO texture, the AO scale for a raw low-resolution one.
   * @p keepBackground leaves background pixels untouched (layered renderers).
   */
  bool Composite(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkTextureObject* occlusion,
    int occlusionScale,
    double intensity,
    bool aoOnly,
    bool keepBackground,
    const int viewport[4]);

  /**
   * Read A back at the G-buffer's resolution into @p image: two float components per pixel,
   * A (r of @p occlusion, an RG float texture, clamped to [0, 1]) and coverage (1 where the
   * G-buffer depth was written; A = 1 on the background), as in ao-definition.md.
   * @p occlusionScale as for Composite(). Needs the context current. False on GL errors.
   */
  static bool ReadOcclusion(vtkAOGBufferPass* gbuffer,
    vtkTextureObject* occlusion,
    int occlusionScale,
    vtkImageData* image);

  /**
   * Make @p values the array of an AO image (ReadOcclusion, vtkAOReferenceRenderer::Render):
   * named "AmbientOcclusion", two components A and Coverage, @p numberOfPixels tuples.
   */
  static void InitializeOcclusionArray(vtkFloatArray* values, vtkIdType numberOfPixels);

  /**
   * Free the program.
   */
  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkAOCompositor();
  ~vtkAOCompositor() override;

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;

private:
  vtkAOCompositor(const vtkAOCompositor&) = delete;
  void operator=(const vtkAOCompositor&) = delete;
};

#endif
