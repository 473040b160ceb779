/**
 * @class   vtkAOReferenceRenderer
 * @brief   ray-traced (Embree) ambient occlusion of a renderer's view: the reference image
 *
 * For every pixel centre of the renderer's camera, a primary ray finds the visible surface
 * point p and its normal n (the interpolated point normal where the data has normals, else
 * the face normal, flipped where it points into the hidden side of its triangle: at a
 * silhouette an interpolated normal may lean away from the camera on a triangle that faces
 * it, and is kept). A(p, n) is then estimated with Samples
 * cosine-weighted rays in the cone of Spread around n, started at p + Bias n, exactly as
 * design/ao-definition.md defines it (Falloff Wendland or binary, Radius R).
 *
 * Occluders are all visible opaque props of the renderer (vtkActor with any polygonal,
 * dataset or composite input, vtkGlyph3DMapper glyphs, vtkAssembly parts), wherever they lie;
 * translucent props are excluded unless IncludeTranslucent is on.
 *
 * The image has the layout of vtkHybridAmbientOcclusionPass::GetAmbientOcclusionImage: width
 * x height points, rows bottom-up (OpenGL order), two float components per pixel named A and
 * Coverage (1 where a surface was hit; A = 1 and Coverage = 0 on the background).
 *
 * Rows are traced in parallel with vtkSMPTools. Directions are a Hammersley set rotated per
 * pixel (Cranley-Patterson) by a hash of the pixel index and Seed: the result is identical
 * run to run and for any number of threads. ProgressEvent (call data: a double in [0, 1]) is
 * invoked from the calling thread only.
 *
 * No OpenGL is used: the renderer does not need a render window when Width and Height are
 * set.
 */
#ifndef vtkAOReferenceRenderer_h
#define vtkAOReferenceRenderer_h

#include "vtkObject.h"
#include "vtkaoReferenceModule.h" // For export macro

#include <memory> // for std::unique_ptr

class vtkAOEmbreeScene;
class vtkImageData;
class vtkPolyData;
class vtkPolyDataCollection;
class vtkRenderer;

class VTKAOREFERENCE_EXPORT vtkAOReferenceRenderer : public vtkObject
{
public:
  static vtkAOReferenceRenderer* New();
  vtkTypeMacro(vtkAOReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FalloffType
  {
    WENDLAND = 0, ///< W(t) = (1 - t/R)^4 (4t/R + 1) (HAO eq. 3)
    BINARY = 1    ///< W(t) = 1 for t <= R ("None" in ao-definition.md)
  };

  ///@{
  /**
   * Occlusion radius R, world units. 0 means automatic: a tenth of the diagonal of the
   * occluders' bounds, as vtkHybridAmbientOcclusionPass computes it. Range [0, inf).
   * Default is 0 (automatic).
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Rays start at p + Bias n, world units. 0 means automatic: 1e-4 of the diagonal of the
   * scene's bounds, the tiny offset offline renderers use, so the image is the true integral
   * (it does not grow with the radius). Range [0, inf). Default is 0 (automatic).
   */
  vtkSetClampMacro(Bias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /**
   * Half-angle of the cone of directions around n, in units of pi/2 (1 = the hemisphere).
   * Range [0.01, 1]. Default is 1.
   */
  vtkSetClampMacro(Spread, double, 0.01, 1.0);
  vtkGetMacro(Spread, double);
  ///@}

  ///@{
  /**
   * Falloff kernel of the occluder distance. Default is WENDLAND.
   */
  vtkSetClampMacro(Falloff, int, WENDLAND, BINARY);
  vtkGetMacro(Falloff, int);
  void SetFalloffToWendland() { this->SetFalloff(WENDLAND); }
  void SetFalloffToBinary() { this->SetFalloff(BINARY); }
  ///@}

  ///@{
  /**
   * Cosine-weighted directions per pixel (or per ComputeAO call). The noise of A is about
   * 0.5 / sqrt(Samples) at worst; ao-definition.md asks for 1024 or more for a reference.
   * Range [1, 1048576]. Default is 256.
   */
  vtkSetClampMacro(Samples, int, 1, 1048576);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /**
   * Seed of the per-pixel rotation of the direction set. Default is 0.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Offset of every primary ray from its pixel's centre, in pixels (x, y; each clamped to
   * [-0.5, 0.5] when used). Default (0, 0): the pixel centres, where a rasterizer samples.
   * A tiny offset (1/512 of a pixel, below the sub-pixel precision of rasterizers) re-decides
   * which polygon a pixel sees only where that is ambiguous (silhouettes, rims of fins and
   * ribs, faces seen edge-on): against an unshifted image, the pixels that change measure the
   * reference's own pixel-centre aliasing.
   */
  vtkSetVector2Macro(PixelOffset, double);
  vtkGetVector2Macro(PixelOffset, double);
  ///@}

  ///@{
  /**
   * Image size in pixels. 0 (either) means the renderer's size in its render window.
   * Range [0, 65536]. Default is 0.
   */
  vtkSetClampMacro(Width, int, 0, 65536);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 0, 65536);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /**
   * Let translucent props (opacity < 1 and the like) occlude and receive. Default is off,
   * as in ao-definition.md.
   */
  vtkSetMacro(IncludeTranslucent, bool);
  vtkGetMacro(IncludeTranslucent, bool);
  vtkBooleanMacro(IncludeTranslucent, bool);
  ///@}

  /**
   * Build the ray-tracing scene from the visible props of @p renderer and fix the effective
   * radius and bias. Returns false (with an error) if Embree failed; an empty scene is valid
   * (every pixel is background).
   */
  bool BuildScene(vtkRenderer* renderer);

  /**
   * Build the scene from the surfaces in @p surfaces (world coordinates). The automatic
   * radius uses the bounds of their triangles.
   */
  bool BuildScene(vtkPolyDataCollection* surfaces);

  /**
   * A(p, n) for the current scene (BuildScene first) at point @p p with unit normal @p n
   * (normalized here), with the current parameters. The pixel-independent rotation of the
   * direction set is taken from Seed alone. Returns -1 if no scene was built.
   */
  double ComputeAO(const double p[3], const double n[3]);

  /**
   * The first surface of the current scene (BuildScene or Render first) that the segment
   * @p origin + t @p direction, t in [@p tMin, @p tMax], meets: its t in @p t and A there in
   * @p a, as Render computes it for pixel number @p pixel of its image (row-major from the
   * bottom row: the same directions), with the normal on the side of its triangle that the
   * segment comes from; the triangle's unit geometric normal (either orientation) in
   * @p face. Returns false, leaving @p t, @p a and @p face as they were, where the segment
   * meets nothing, @p pixel is negative or no scene was built. With Render's primary ray of a
   * pixel and tMin just before the depth a rasterizer wrote there, it gives the integral on
   * the surface the rasterizer shows, where the pixel-centre ray meets another one.
   */
  bool ComputeAOAlongRay(const double origin[3],
    const double direction[3],
    double tMin,
    double tMax,
    vtkIdType pixel,
    double& t,
    double& a,
    double face[3]);

  /**
   * The world point at window position (@p x, @p y) in pixels of a @p width x @p height view
   * (pixel (i, j) spans [i, i + 1) x [j, j + 1), rows from the bottom) and window depth
   * @p depth in [0, 1] (0: the near plane, 1: the far plane), through @p inverse, the inverse
   * of the matrix VTK renders that view with (vtkCamera::GetCompositeProjectionTransformMatrix
   * with aspect width / height and z range [-1, 1], row-major). Render's primary ray of a
   * pixel runs from depth 0 to depth 1 through its centre (plus PixelOffset).
   */
  static void UnprojectWindowPoint(const double inverse[16],
    int width,
    int height,
    double x,
    double y,
    double depth,
    double world[3]);

  /**
   * Build the scene from @p renderer and trace its view into @p image (see the class
   * documentation for the layout). Returns false if the size is unknown or Embree failed.
   */
  bool Render(vtkRenderer* renderer, vtkImageData* image);

  ///@{
  /**
   * Radius and bias used by the last BuildScene (Radius/Bias, or the automatic values).
   */
  vtkGetMacro(EffectiveRadius, double);
  vtkGetMacro(EffectiveBias, double);
  ///@}

  /**
   * Number of triangles in the current scene.
   */
  vtkIdType GetNumberOfTriangles();

  ///@{
  /**
   * Statistics of the last Render: rays cast (primary and occlusion), wall-clock seconds of
   * the tracing (scene build excluded), and the number of threads vtkSMPTools used.
   * Rays per second per core = NumberOfRays / TraceTime / NumberOfThreads.
   */
  vtkGetMacro(NumberOfRays, vtkTypeInt64);
  vtkGetMacro(TraceTime, double);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

protected:
  vtkAOReferenceRenderer();
  ~vtkAOReferenceRenderer() override;

  /// Fix the effective radius and bias from the scene bounds, and commit the scene.
  bool FinishScene();

  double Radius = 0.0;
  double Bias = 0.0;
  double Spread = 1.0;
  int Falloff = WENDLAND;
  int Samples = 256;
  unsigned int Seed = 0;
  double PixelOffset[2] = { 0.0, 0.0 };
  int Width = 0;
  int Height = 0;
  bool IncludeTranslucent = false;

  double EffectiveRadius = 0.0;
  double EffectiveBias = 0.0;
  vtkTypeInt64 NumberOfRays = 0;
  double TraceTime = 0.0;
  int NumberOfThreads = 1;

  std::unique_ptr<vtkAOEmbreeScene> Scene;

private:
  vtkAOReferenceRenderer(const vtkAOReferenceRenderer&) = delete;
  void operator=(const vtkAOReferenceRenderer&) = delete;
};

#endif
