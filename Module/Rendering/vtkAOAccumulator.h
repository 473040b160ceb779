/**
 * @class   vtkAOAccumulator
 * @brief   Running mean of A over the frames of a still view (progressive refinement).
 *
 * Each call to Accumulate() adds one frame's occlusion texture to the mean: the first copies
 * it (every channel: A, coverage and whatever the stage stores beside them), the k-th blends
 * its A into the mean with weight 1/k (GL blending with the fragment's alpha, on the red
 * channel only, so the other channels stay those of the first frame). The frames must have
 * the same size and layout, which the caller guarantees by restarting (count 1) whenever
 * anything but the jitter changed. Used by vtkAmbientOcclusionPassBase.
 */
#ifndef vtkAOAccumulator_h
#define vtkAOAccumulator_h

#include "vtkAOQuadStage.h"
#include "vtkaoRenderingModule.h" // For export macro

class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKAORENDERING_EXPORT vtkAOAccumulator : public vtkAOQuadStage
{
public:
  static vtkAOAccumulator* New();
  vtkTypeMacro(vtkAOAccumulator, vtkAOQuadStage);

  /**
   * Make the mean that of @p count frames, @p frame (a float texture, A in red) the last:
   * count 1 copies @p frame, count k > 1 blends its A with weight 1/k. Returns false on
   * failure (then the output is undefined until the next count-1 call).
   */
  bool Accumulate(vtkOpenGLRenderWindow* renWin, vtkTextureObject* frame, int count);

  /**
   * Write the texels of @p map, a map of one texel every @p scale pixels evaluated at the
   * pixel @p offset of each block (see vtkAmbientOcclusionPassBase::StratifiesSubsampledMap),
   * into the mean at those pixels only, every channel; the other pixels keep their values.
   * Needs a mean (a count-1 Accumulate of the screen's size); false otherwise or on failure.
   */
  bool Scatter(vtkOpenGLRenderWindow* renWin,
    vtkTextureObject* map,
    int scale,
    const int offset[2]);

  // GetOutput(): the running mean (same size and channels as the accumulated frames), nullptr
  // before the first Accumulate(); ReleaseGraphicsResources and GetGraphicsMemorySize: the
  // mean's texture, framebuffer and program (vtkAOQuadStage).

protected:
  vtkAOAccumulator();
  ~vtkAOAccumulator() override;

  /// How Draw() writes a frame into the mean.
  enum Mode
  {
    COPY,   ///< every channel of every pixel
    BLEND,  ///< A only, blended with weight @p weight
    SCATTER ///< every channel, only at the pixels @p offset of the @p scale blocks
  };
  /// Draw @p frame into Output; false if the program cannot be made.
  bool Draw(vtkOpenGLRenderWindow* renWin,
    vtkTextureObject* frame,
    Mode mode,
    float weight,
    int scale,
    const int offset[2]);

private:
  vtkAOAccumulator(const vtkAOAccumulator&) = delete;
  void operator=(const vtkAOAccumulator&) = delete;
};

#endif
