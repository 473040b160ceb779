/**
 * @class   vtkAOVolumeRasterizer
 * @brief   Occlusion stage of vtkAmbientOcclusionVolumesPass: rasterizes each occluding
 *          triangle's ambient occlusion volume (McGuire 2010) over the G-buffer into an AO map.
 *
 * UpdateOccluders() gathers the occluders' triangles with vtkAOOccluderTriangles and uploads
 * them, only when an occluder changed. Render() then draws, into a map of one texel every
 * Scale pixels:
 * 1. the initial map (A = 1 with the coverage, depth and normal of each texel's pixel), the
 *    lifted points p + Bias n the volumes read, and the pixels' depths (each texel stands
 *    for one pixel of its Scale x Scale block: the centre, or Parameters::SampleOffset);
 * 2. the volumes: a geometry shader turns each triangle P into the box that holds P dilated
 *    by the radius R and extruded by R along its normal; per covered texel the fragment shader
 *    removes the occlusion O_P of P seen from the texel's point (the form factor of P clipped
 *    to the tangent plane, McGuire's eq. 1, weighted by the falloff; Documentation/aov.md)
 *    by blending in a float target: subtracted (A = 1 - sum O_P) or multiplied in
 *    (A = product of (1 - O_P)), Parameters::Multiplicative.
 *
 * The map has the layout vtkAOBilateralUpsampler and vtkAOCompositor read (RGBA float: A,
 * coverage, window depth, packed normal).
 */
#ifndef vtkAOVolumeRasterizer_h
#define vtkAOVolumeRasterizer_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <vector> // For the occluder list

class vtkAOGBufferPass;
class vtkAOOccluderTriangles;
class vtkMatrix4x4;
class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkProp;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOVolumeRasterizer : public vtkObject
{
public:
  static vtkAOVolumeRasterizer* New();
  vtkTypeMacro(vtkAOVolumeRasterizer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Gather and upload the triangles of @p props (whose bounds are @p bounds) if an occluder
   * changed since the last call. Returns whether there is any triangle.
   */
  bool UpdateOccluders(vtkOpenGLRenderWindow* renWin,
    const std::vector<vtkProp*>& props,
    const double bounds[6]);

  /// What Render() needs besides the G-buffer.
  struct Parameters
  {
    int Scale = 1;               ///< screen pixels per map texel along each axis
    double Radius = 1.0;         ///< R, world units
    double Bias = 0.0;           ///< occlusion is evaluated from p + Bias n, world units
    bool BinaryFalloff = false;  ///< W = 1 up to R instead of Wendland's kernel
    bool Multiplicative = false; ///< A = product of (1 - O_P) instead of 1 - sum of O_P
    bool Parallel = false;       ///< parallel projection
    /// The pixel of each Scale x Scale block (from its lower left corner) at which the
    /// block's texel is evaluated; negative: the block's centre (Scale / 2).
    int SampleOffset[2] = { -1, -1 };
  };

  /**
   * Write the AO map for the G-buffer's view; @p view and @p projection are the camera's
   * matrices. False (after an error) on failure.
   */
  bool Render(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkMatrix4x4* view,
    vtkMatrix4x4* projection,
    const Parameters& parameters);

  /**
   * The AO map written by the last Render() (RGBA32F: A, coverage, depth, packed normal).
   */
  vtkTextureObject* GetOutput() { return this->Occlusion; }

  /**
   * Number of occluding triangles (volumes) uploaded by the last UpdateOccluders().
   */
  vtkGetMacro(NumberOfTriangles, vtkIdType);

  /**
   * How many times the occluding triangles were gathered and uploaded since creation.
   */
  vtkGetMacro(UpdateCount, int);

  /**
   * Bytes of GPU memory this stage owns: the AO map with its point map and depth, and the
   * triangles' buffer (48 bytes a triangle). 0 after ReleaseGraphicsResources.
   */
  long long GetGraphicsMemorySize();

  /**
   * Free the textures, framebuffer, buffers and programs.
   */
  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkAOVolumeRasterizer();
  ~vtkAOVolumeRasterizer() override;

  /// Create the map's textures, the framebuffer and the programs; false after an error.
  bool InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h);
  /// Upload the triangles (see vtkAOOccluderTriangles); false after an error.
  bool UploadTriangles(vtkOpenGLRenderWindow* renWin, const std::vector<float>& vertices);
  /// Step 1: the initial map, the lifted points and the pixels' depths.
  bool RenderInitialMap(vtkOpenGLRenderWindow* renWin,
    vtkAOGBufferPass* gbuffer,
    vtkMatrix4x4* projection,
    const Parameters& parameters);
  /// Step 2: the volumes, subtracted from or multiplied into the map. @p mapProjection
  /// projects onto the map (see MapProjection).
  bool RenderVolumes(vtkOpenGLRenderWindow* renWin,
    const Parameters& parameters,
    vtkMatrix4x4* view,
    vtkMatrix4x4* mapProjection);
  /// The camera's @p projection followed by the screen-to-map transform of x and y that puts
  /// each map texel's centre on the centre of the pixel it is evaluated at (Scale and
  /// SampleOffset of @p parameters, the screen @p fullSize, the map @p mapSize), so that a
  /// volume covers a texel exactly when it covers that pixel.
  static void MapProjection(vtkMatrix4x4* projection,
    const Parameters& parameters,
    const int fullSize[2],
    const int mapSize[2],
    vtkMatrix4x4* mapProjection);

  vtkIdType NumberOfTriangles = 0;
  int UpdateCount = 0;
  std::vector<double> Signature;  ///< of the occluders the triangles were built from
  double Origin[3] = { 0, 0, 0 }; ///< the triangles are stored relative to it
  std::unique_ptr<vtkAOOccluderTriangles> Triangulator;
  vtkOpenGLBufferObject* Triangles = nullptr;
  vtkOpenGLRenderWindow* TrianglesWindow = nullptr; ///< the context Triangles lives in
  /// The volumes are drawn twice, by two programs: triangles small against the radius (their
  /// occlusion is the form factor weighted at the centroid's distance), then the others (the
  /// falloff integrated over distance). Each geometry shader keeps only its own class.
  enum VolumeClass
  {
    SMALL_TRIANGLES = 0,
    LARGE_TRIANGLES = 1
  };
  vtkOpenGLVertexArrayObject* VAOs[2] = { nullptr, nullptr };
  vtkShaderProgram* Programs[2] = { nullptr, nullptr }; ///< owned by the window's shader cache
  vtkOpenGLFramebufferObject* Accumulation = nullptr;
  vtkTextureObject* Occlusion = nullptr; ///< r = 1 - sum, g coverage, b depth, a normal
  vtkTextureObject* Points = nullptr;    ///< per texel: lifted x (view space), packed normal
  vtkTextureObject* MapDepth = nullptr;  ///< per texel: its pixel's depth, for early rejection
  std::unique_ptr<vtkOpenGLQuadHelper> InitQuad; ///< writes the initial AO map

private:
  vtkAOVolumeRasterizer(const vtkAOVolumeRasterizer&) = delete;
  void operator=(const vtkAOVolumeRasterizer&) = delete;
};

#endif
