/**
 * @class   vtkAOBilateralUpsampler
 * @brief   Joint bilateral upsampling of a low-resolution AO map (HAO section 7).
 *
 * Resamples the AO map to screen resolution and removes its sampling noise with the
 * geometry-aware filter of Reinboth et al. (eq. 5-7, after Kopf et al. 2007): a Wendland
 * spatial kernel over an m x m window, times range kernels on the angle between normals, the
 * object-space distance (support d_max, the AO radius) and the difference of AO values. It
 * runs as the separable two-pass approximation of eq. 8: along x into a (width x low height)
 * map, then along y into the full-resolution result. Only input samples are summed, so each
 * pass costs m / scale taps per pixel, one texture fetch each: the input carries each sample's
 * depth and normal next to A, and the first pass writes the same layout for the second.
 */
#ifndef vtkAOBilateralUpsampler_h
#define vtkAOBilateralUpsampler_h

#include "vtkAOQuadStage.h"
#include "vtkaoRenderingModule.h" // For export macro

class vtkAOGBufferPass;
class vtkMatrix4x4;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOBilateralUpsampler : public vtkAOQuadStage
{
public:
  static vtkAOBilateralUpsampler* New();
  vtkTypeMacro(vtkAOBilateralUpsampler, vtkAOQuadStage);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Filter @p input (RGBA: A, valid, window depth and packed normal of the pixel the sample
   * was taken at, as written by vtkAOVoxelTracer), traced every @p scale pixels, to the
   * G-buffer's resolution. @p window is m in pixels, @p radius the AO radius (world units).
   */
  bool Upsample(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkTextureObject* input,
    vtkMatrix4x4* projection,
    bool parallel,
    int scale,
    int window,
    double radius);

  ///@{
  /**
   * The full-resolution result of the last Upsample() is GetOutput() (RG32F); this stage
   * frees, and counts the memory of, its intermediate map with the output.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;
  long long GetGraphicsMemorySize() override;
  ///@}

protected:
  vtkAOBilateralUpsampler();
  ~vtkAOBilateralUpsampler() override;

  vtkTextureObject* Intermediate = nullptr;

private:
  vtkAOBilateralUpsampler(const vtkAOBilateralUpsampler&) = delete;
  void operator=(const vtkAOBilateralUpsampler&) = delete;
};

#endif
