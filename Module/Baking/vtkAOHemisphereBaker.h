/**
 * @class   vtkAOHemisphereBaker
 * @brief   per-vertex ambient occlusion by hemicube rendering on the GPU (inside looking out)
 *
 * The classic hardware method: for every vertex i the scene (the input and the optional
 * occluders on port 1) is rendered from the eye e_i = p_i + Bias n_i looking along n_i, black
 * geometry on white, over a hemicube (Cohen and Greenberg 1985): the front face (Resolution x
 * Resolution pixels, 90 degree field of view around n_i) and the upper halves of the four side
 * faces (Resolution x Resolution/2 each). Each pixel is weighted by its delta form factor, the
 * cosine-weighted solid angle it subtends,
 *
 *     front face pixel at (x, y, 1):  dF = dA / (pi (x^2 + y^2 + 1)^2)
 *     side face pixel at (x, z):      dF = z dA / (pi (x^2 + z^2 + 1)^2)
 *
 * (face half-width 1, z the height above the tangent plane, dA = (2 / Resolution)^2), normalised so
 * that the weights sum to 1. The output point-data array (ArrayName, default "AmbientOcclusion",
 * one float per point) is the weighted white fraction,
 *
 *     A_i = sum over pixels of dF * white / sum of dF,
 *
 * which is A(p, n) of design/ao-definition.md with the binary falloff: every surface within
 * Radius of the eye occludes (both faces; Radius 0 = infinity, every surface), over the cone of
 * half-angle Spread * pi/2 (pixels whose centre direction lies outside the cone get no weight).
 * The approximation is the hemicube's: each pixel's coverage is that of its centre direction
 * (rasterization), i.e. about 2 Resolution^2 point samples of the cosine-weighted hemisphere
 * on a fixed grid. A surface counts as within Radius when its distance to the eye is (exactly,
 * per pixel, in the fragment shader) at most Radius.
 *
 * Batching: the 2 Resolution x 2 Resolution tiles of up to BatchSize vertices (the unfolded
 * hemicube, corners unused) form one atlas texture; five instanced draws (one per face, instance
 * = vertex of the batch, the scene's triangles indexed) render every hemicube, clip distances
 * keeping each face inside its part of its tile; a second pass sums every tile with its weights
 * on the GPU, and one read-back per batch returns BatchSize floats. Cost: every vertex draws the
 * whole scene five times, so the time grows as vertices x triangles (see GetVerticesPerSecond()).
 *
 * The ports, the surface, the normals and the output array are vtkAOBaker's, as for
 * vtkAOVertexBaker: points no valid polygon uses, or with a zero or non-finite normal, get
 * A = 1; extra occluders (input port 1) occlude but get no array; lines and vertices do not
 * occlude. The automatic Bias is vtkAOVertexBaker's with its automatic radius; geometry nearer
 * to the eye than Bias / 100 along a face's axis is clipped. Progress events are sent per batch.
 *
 * OpenGL: vtkAOOpenGLBaker's (RenderWindow, or an off-screen window of the baker's own).
 *
 * @sa vtkAOSattlerBaker vtkAOVertexBaker
 */
#ifndef vtkAOHemisphereBaker_h
#define vtkAOHemisphereBaker_h

#include "vtkAOOpenGLBaker.h"
#include "vtkaoBakingModule.h" // For export macro

class VTKAOBAKING_EXPORT vtkAOHemisphereBaker : public vtkAOOpenGLBaker
{
public:
  static vtkAOHemisphereBaker* New();
  vtkTypeMacro(vtkAOHemisphereBaker, vtkAOOpenGLBaker);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Hemicube resolution: the front face is Resolution x Resolution pixels, each side face
   * Resolution x Resolution/2; a vertex's tile is 2 Resolution x 2 Resolution pixels. Odd values
   * are rounded up to the next even number. Range [8, 256]. Default is 64.
   */
  vtkSetClampMacro(Resolution, int, 8, 256);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * The largest number of vertices rendered into one atlas (one draw, one reduction, one
   * read-back and one progress event per batch). Fewer when the atlas would exceed 4096^2 pixels
   * or the maximum texture size. Range [1, 65536]. Default is 1024.
   */
  vtkSetClampMacro(BatchSize, int, 1, 65536);
  vtkGetMacro(BatchSize, int);
  ///@}

  ///@{
  /**
   * Occlusion radius R, world units: surfaces farther than R from the eye do not occlude
   * (binary falloff). 0 means infinity (every surface occludes, as vtkAOSattlerBaker; note that
   * 0 means automatic in vtkAOVertexBaker). Range [0, inf). Default is 0.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Half-angle of the cone of directions, in units of pi/2. Range [0.01, 1]. Default is 1.
   */
  vtkSetClampMacro(Spread, double, 0.01, 1.0);
  vtkGetMacro(Spread, double);
  ///@}

  ///@{
  /**
   * Statistics of the last execution (GetEffectiveBias() gives the bias, GetNumberOfTriangles()
   * the occluding triangles, GetRenderTime() the seconds spent in draws, reductions and
   * read-backs, GetTotalTime() the whole): the vertices per batch and the number of batches;
   * the number of vertices rendered (those with a valid normal); the throughput, rendered
   * vertices / TotalTime.
   */
  vtkGetMacro(EffectiveBatchSize, int);
  vtkGetMacro(NumberOfBatches, int);
  vtkGetMacro(NumberOfRenderedPoints, vtkIdType);
  double GetVerticesPerSecond() const;
  ///@}

protected:
  vtkAOHemisphereBaker();
  ~vtkAOHemisphereBaker() override;

  void InitializeResults(vtkIdType numberOfPoints) override;
  /// The visibility method: a hemicube per point, rendered and summed in batches.
  int BakePoints(Surface& surface, float* values) override;

  int Resolution = 64;
  int BatchSize = 1024;
  double Radius = 0.0;
  double Spread = 1.0;

  // Results.
  int EffectiveBatchSize = 0;
  int NumberOfBatches = 0;
  vtkIdType NumberOfRenderedPoints = 0;

private:
  vtkAOHemisphereBaker(const vtkAOHemisphereBaker&) = delete;
  void operator=(const vtkAOHemisphereBaker&) = delete;

  class vtkInternals;
  vtkInternals* Internals; // owned by ContextResources

  // The steps of BakePoints, in order.
  void PlaceEyes(const Surface& surface);
  bool PrepareAtlas();
  bool PrepareScene(Surface& surface);
  void RenderBatches(float* values);
  bool RenderHemicubes(vtkIdType first, int count);
  void SumTiles(vtkIdType first, int count, float* values);
};

#endif
