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

  /// How Composite() draws.
  struct Parameters
  {
    int OcclusionScale = 1;           ///< 1 for a full-resolution AO texture, else the AO scale
    double Intensity = 1.0;           ///< colour x A^Intensity
    bool AOOnly = false;              ///< A itself, background white
    bool KeepBackground = false;      ///< leave background pixels untouched (layered renderers)
    int Viewport[4] = { 0, 0, 0, 0 }; ///< x, y, w, h in the current framebuffer
  };

  /**
   * Composite the G-buffer's colour times A of @p occlusion (and its depth) into the current
   * framebuffer's viewport. False if the program cannot be made.
   */
  bool Composite(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkTextureObject* occlusion,
    const Parameters& parameters);

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
