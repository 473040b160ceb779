/**
 * @class   vtkAOVoxelTracer
 * @brief   Occlusion sampling through a bitmask voxel grid (HAO section 6, eq. 4).
 *
 * For every texel of a reduced-resolution AO map, rebuild p and n from the G-buffer and march
 * Rays cosine-distributed rays (within the cone set by Spread) in Steps equal steps of
 * Radius / Steps through the grid; the first occupied cell on a ray counts with the falloff
 * weight of its distance (Wendland or binary). Rays start at p + Bias n. Directions and step
 * offsets are jittered by a 3-D white-noise texture evaluated in world space, so the noise
 * stays on the surfaces when the camera moves. The result is A (shared/design/ao-definition.md)
 * in the red channel and 1 in the green channel where there is geometry.
 */
#ifndef vtkAOVoxelTracer_h
#define vtkAOVoxelTracer_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr

class vtkAOBitmaskVoxelizer;
class vtkAOGBufferPass;
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOVoxelTracer : public vtkObject
{
public:
  static vtkAOVoxelTracer* New();
  vtkTypeMacro(vtkAOVoxelTracer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What the tracer needs to know about one frame.
  struct Parameters
  {
    int Scale = 2;       // full-resolution pixels per AO-map texel along each axis
    int Rays = 32;       // rays per AO-map texel
    int Steps = 8;       // grid tests per ray
    double Radius = 1.0; // world units
    double Bias = 0.0;   // world units
    double Spread = 1.0; // cone half-angle in units of pi/2
    bool BinaryFalloff = false;
    bool Parallel = false; // orthographic scene camera
  };

  /**
   * Trace the AO map for the G-buffer's view. @p view and @p projection are the scene
   * camera's view and projection matrices (VTK convention). Returns false on failure.
   */
  bool Trace(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkAOBitmaskVoxelizer* grid,
    vtkMatrix4x4* view,
    vtkMatrix4x4* projection,
    const Parameters& parameters);

  /**
   * The AO map written by the last Trace() (RG32F).
   */
  vtkTextureObject* GetOutput() { return this->Output; }

  /**
   * Free the textures, framebuffer and program.
   */
  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkAOVoxelTracer();
  ~vtkAOVoxelTracer() override;

  /// Create the noise texture on first use.
  void InitializeNoise(vtkOpenGLRenderWindow* renWin);

  vtkTextureObject* Output = nullptr;
  vtkTextureObject* Noise = nullptr;
  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;

private:
  vtkAOVoxelTracer(const vtkAOVoxelTracer&) = delete;
  void operator=(const vtkAOVoxelTracer&) = delete;
};

#endif
