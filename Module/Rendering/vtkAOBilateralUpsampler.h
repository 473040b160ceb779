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
 *
 * On request (Marking) the second pass also marks, in a full-resolution depth texture
 * (GetMarks()), the pixels the reduced map cannot represent, for Hybrid AO's refinement
 * (vtkAOVoxelTracer::Refine): that pass has each pixel's position and normal already, so the
 * marks cost four fetches of the map per pixel instead of a full-screen pass of their own.
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
   * Which full-resolution pixels the reduced map cannot represent (marked for refinement): a
   * pixel is marked where the (up to) four map samples around it differ by more than Contrast
   * in A, or where none of them lies on its own surface (its normal within NormalCosine of the
   * pixel's, its position within PlaneTolerance reduced texels' footprints of the pixel's
   * tangent plane): silhouettes, creases, fins and ribs finer than a texel, contacts.
   */
  struct Marking
  {
    bool Enabled = false;
    double NormalCosine = 0.9; ///< 26 degrees
    double PlaneTolerance = 0.5;
    double Contrast = 0.3;
  };

  /**
   * Filter @p input (RGBA: A, valid, window depth and packed normal of the pixel the sample
   * was taken at, as written by vtkAOVoxelTracer), traced every @p scale pixels, to the
   * G-buffer's resolution. @p window is m in pixels, @p radius the AO radius (world units).
   * With @p marking enabled, GetMarks() then holds the marks (depth 0 where marked, 1
   * elsewhere); otherwise it is freed.
   */
  bool Upsample(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkTextureObject* input,
    vtkMatrix4x4* projection,
    bool parallel,
    int scale,
    int window,
    double radius,
    const Marking& marking);

  /**
   * The marks of the last Upsample() with marking enabled (a full-resolution depth texture:
   * 0 where the pixel needs its own trace), nullptr otherwise.
   */
  vtkTextureObject* GetMarks() { return this->Marks; }

  ///@{
  /**
   * The full-resolution result of the last Upsample() is GetOutput() (RG32F); this stage
   * frees, and counts the memory of, its intermediate map and marks with the output.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;
  long long GetGraphicsMemorySize() override;
  ///@}

protected:
  vtkAOBilateralUpsampler();
  ~vtkAOBilateralUpsampler() override;

  vtkTextureObject* Intermediate = nullptr;
  vtkTextureObject* Marks = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> MarkQuad; ///< the second pass that also writes Marks

private:
  vtkAOBilateralUpsampler(const vtkAOBilateralUpsampler&) = delete;
  void operator=(const vtkAOBilateralUpsampler&) = delete;
};

#endif
