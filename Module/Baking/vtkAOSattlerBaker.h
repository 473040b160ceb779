/**
 * @class   vtkAOSattlerBaker
 * @brief   per-vertex ambient occlusion and precomputed visibility on the GPU (Sattler 2004)
 *
 * Outside-in visibility (Sattler, Sarlette, Zachmann, Klein: "Hardware-accelerated ambient
 * occlusion computation", VMV 2004). For k directions l_j spread over the sphere (a Fibonacci
 * sphere, randomly rotated when Seed != 0) the scene's depth is rendered with an orthographic
 * camera looking along -l_j, and every vertex i is tested against that depth map: vertex i
 * sees direction l_j when nothing lies in front of its test point p_i + Bias n_i (allowing only
 * for the map being sampled at the pixel centre, see DepthOffset). This gives the visibility
 * matrix
 *
 *     M_ij = max(0, <n_i, l_j>) if vertex i sees l_j, else 0,
 *
 * and the output point-data array (ArrayName, default "AmbientOcclusion", one float per point)
 *
 *     A_i = sum_j M_ij / sum_j max(0, <n_i, l_j>),
 *
 * which is A(p, n) of design/ao-definition.md with a binary falloff, R = infinity and the full
 * hemisphere (Spread = 1): every surface, at any distance, occludes, with both faces.
 *
 * With StoreVisibility on (the default) the matrix is kept as one bit per vertex and direction
 * (ceil(k / 32) 32-bit words per vertex; the cosines are recomputed from the stored normals), so
 * that Relight() evaluates c_i = sum_j M_ij I_j / sum_j max(0, <n_i, l_j>) for any per-direction
 * intensities I_j (an environment) without new visibility: with I_j = 1, c = A. With
 * StoreVisibility off nothing of size n x k is kept: A (and, when Intensities are set, the
 * radiance c) is accumulated on the fly.
 *
 * The ports, the surface, the normals and the output array are vtkAOBaker's, as for
 * vtkAOVertexBaker: points no valid polygon uses, or with a zero or non-finite normal, get
 * A = 1; extra occluders (input port 1) occlude but get no array; lines and vertices do not
 * occlude. The automatic Bias is vtkAOVertexBaker's with its automatic radius.
 *
 * The point test (PointTest) runs on the GPU when it can: after each depth map the vertices are
 * drawn as GL_POINTS with a vertex shader that projects the test point into the map and
 * compares it with the sampled depth exactly as the CPU test does; when visible, it sets bit
 * (j % 32) of the vertex's word, either
 * - STORAGE_BUFFER (OpenGL 4.3): atomicOr into a shader storage buffer of n words, with the
 *   rasterizer discarded (no fragments, no framebuffer switch), or
 * - LOGIC_OP (OpenGL 3.2): a point on texel (i % W, i / W) of an R32UI texture of
 *   W x ceil(n / W) texels, OR-ed in with glLogicOp(GL_OR).
 * The words are read back once per 32 directions (4 n bytes instead of 4 Resolution^2 bytes per
 * direction). The CPU test (every depth map read back and tested with vtkSMPTools) is the
 * fallback. AUTOMATIC (the default) uses the first of STORAGE_BUFFER, LOGIC_OP, CPU that the
 * context supports; a GPU variant that is requested but unavailable falls back the same way
 * (GetPointTestUsed() tells). All give the same bits except for test points within float
 * rounding (about 1e-7 of the scene size) of a depth-map pixel edge or of the depth threshold
 * (the GPU computes in float, the CPU in double): 1 bit in 6.8 million on a 106 k vertex mesh,
 * none in TestSattlerGPUTest.
 *
 * OpenGL: vtkAOOpenGLBaker's (RenderWindow, or an off-screen window of the baker's own).
 * Progress events are sent per direction.
 */
#ifndef vtkAOSattlerBaker_h
#define vtkAOSattlerBaker_h

#include "vtkAOOpenGLBaker.h"
#include "vtkaoBakingModule.h" // For export macro

#include <cstdint> // for std::uint32_t
#include <string>  // for std::string
#include <vector>  // for std::vector

class vtkFloatArray;

class VTKAOBAKING_EXPORT vtkAOSattlerBaker : public vtkAOOpenGLBaker
{
public:
  static vtkAOSattlerBaker* New();
  vtkTypeMacro(vtkAOSattlerBaker, vtkAOOpenGLBaker);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of directions k over the whole sphere (about k/2 fall in each vertex's hemisphere).
   * Range [1, 65536]. Default is 256.
   */
  vtkSetClampMacro(NumberOfDirections, int, 1, 65536);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /**
   * Width and height of the depth map, pixels. Range [16, 8192]. Default is 1024.
   */
  vtkSetClampMacro(Resolution, int, 16, 8192);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Depth tolerance of the test, world units: a test point counts as visible when the depth map
   * holds nothing nearer to the camera than the point minus this offset. A snapping term is
   * always added, because the map samples the surface at the pixel centre, up to half a pixel
   * diagonal h beside the test point, where the point's own tangent plane can rise above it:
   * max(0, (h sin(a) - Bias) / cos(a)), a the angle between n and l (0 once Bias exceeds h).
   * 0 means automatic: 0.02 depth-map pixels (float rounding only; a larger offset lets the
   * occluders nearest to a vertex through: an earlier automatic 1.5 pixels plus a slope term
   * made creases and contacts too bright, RMSE 0.03 against the ray caster on a 100 k triangle
   * mesh, see Documentation/baking.md). Range [0, inf). Default is 0.
   */
  vtkSetClampMacro(DepthOffset, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DepthOffset, double);
  ///@}

  ///@{
  /**
   * Seed of the random rotation of the direction set; 0 = the unrotated Fibonacci sphere.
   * Default is 0.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  enum PointTestType
  {
    POINT_TEST_AUTOMATIC = 0,     ///< the first available of STORAGE_BUFFER, LOGIC_OP, CPU
    POINT_TEST_CPU = 1,           ///< every depth map read back, points tested with vtkSMPTools
    POINT_TEST_LOGIC_OP = 2,      ///< GPU, R32UI texture and glLogicOp(GL_OR) (OpenGL 3.2)
    POINT_TEST_STORAGE_BUFFER = 3 ///< GPU, atomicOr into a shader storage buffer (OpenGL 4.3)
  };

  ///@{
  /**
   * Where the points are tested against the depth maps (see the class description). Range
   * [POINT_TEST_AUTOMATIC, POINT_TEST_STORAGE_BUFFER]. Default is POINT_TEST_AUTOMATIC.
   */
  vtkSetClampMacro(PointTest, int, POINT_TEST_AUTOMATIC, POINT_TEST_STORAGE_BUFFER);
  vtkGetMacro(PointTest, int);
  void SetPointTestToAutomatic() { this->SetPointTest(POINT_TEST_AUTOMATIC); }
  void SetPointTestToCPU() { this->SetPointTest(POINT_TEST_CPU); }
  void SetPointTestToLogicOp() { this->SetPointTest(POINT_TEST_LOGIC_OP); }
  void SetPointTestToStorageBuffer() { this->SetPointTest(POINT_TEST_STORAGE_BUFFER); }
  static const char* GetPointTestAsString(int test);
  ///@}

  ///@{
  /**
   * Keep the visibility bits (n x ceil(k/32) words) for Relight(). Default is on.
   */
  vtkSetMacro(StoreVisibility, bool);
  vtkGetMacro(StoreVisibility, bool);
  vtkBooleanMacro(StoreVisibility, bool);
  ///@}

  ///@{
  /**
   * Per-direction intensities for the radiance output, k x components values (direction major);
   * empty (the default) = no radiance array. When set, the output also gets the point-data array
   * RadianceArrayName (default "Radiance") with c_i as in Relight(); in the on-the-fly mode this
   * is the only way to get c. components is 1 to 4.
   */
  void SetIntensities(const std::vector<double>& intensities, int components);
  const std::vector<double>& GetIntensities() const { return this->Intensities; }
  int GetIntensityComponents() const { return this->IntensityComponents; }
  void SetRadianceArrayName(const std::string& name);
  const std::string& GetRadianceArrayName() const { return this->RadianceArrayName; }
  ///@}

  /**
   * The k unit directions l_j of the last execution, 3 values each (the direction towards the
   * light: vertex i sees l_j when the ray p_i + t l_j, t > 0, is free).
   */
  const std::vector<double>& GetDirections() const { return this->Directions; }

  /**
   * The direction set used for a given k and seed (what an execution will use).
   */
  static std::vector<double> MakeDirections(int count, unsigned int seed);

  /**
   * The visibility bits of the last execution with StoreVisibility on: point i, direction j is
   * bit (j % 32) of word i * GetWordsPerPoint() + j / 32. Empty otherwise.
   */
  const std::vector<std::uint32_t>& GetVisibility() const { return this->Visibility; }
  int GetWordsPerPoint() const { return this->WordsPerPoint; }
  bool IsVisible(vtkIdType point, int direction) const;

  /**
   * c_i = sum_j M_ij I_j / sum_j max(0, <n_i, l_j>) for every point, from the stored bits:
   * @p intensities holds k x @p components values (direction major). @p out gets one tuple of
   * @p components per point (points without a valid normal get the mean of I over the
   * directions). Linear in I. Returns false (and leaves @p out alone) when there is no stored
   * matrix or the sizes do not match. Multithreaded (vtkSMPTools).
   */
  bool Relight(const std::vector<double>& intensities, int components, vtkFloatArray* out) const;

  ///@{
  /**
   * Statistics of the last execution (GetEffectiveBias() gives the bias, GetNumberOfTriangles()
   * the occluding triangles): the effective depth offset; seconds spent drawing and reading
   * back the depth maps (GetRenderTime()), testing the points, and in total (GetTotalTime();
   * the cost of recomputing visibility for a deforming mesh is TotalTime / k per direction);
   * bytes of the stored matrix (n x ceil(k/32) x 4, 0 on the fly); the point test used (CPU,
   * LOGIC_OP or STORAGE_BUFFER). With a GPU test OpenGL runs asynchronously: RenderTime is the time
   * to issue the depth passes and TestTime includes the rasterization that the read-back waits for,
   * so only the total is comparable between the point tests.
   */
  vtkGetMacro(EffectiveDepthOffset, double);
  vtkGetMacro(TestTime, double);
  vtkGetMacro(PointTestUsed, int);
  bool GetGPUTestUsed() const { return this->PointTestUsed != POINT_TEST_CPU; }
  std::size_t GetVisibilityMemory() const { return this->Visibility.size() * 4; }
  ///@}

protected:
  vtkAOSattlerBaker();
  ~vtkAOSattlerBaker() override;

  void InitializeResults(vtkIdType numberOfPoints) override;
  /// The visibility method: a depth map per direction, every point tested against it.
  int BakePoints(Surface& surface, float* values) override;

  int NumberOfDirections = 256;
  int Resolution = 1024;
  double DepthOffset = 0.0;
  unsigned int Seed = 0;
  bool StoreVisibility = true;
  int PointTest = POINT_TEST_AUTOMATIC;
  std::vector<double> Intensities;
  int IntensityComponents = 1;
  std::string RadianceArrayName = "Radiance";

  // Results.
  std::vector<double> Directions;
  std::vector<std::uint32_t> Visibility;
  int WordsPerPoint = 0;
  std::vector<float> Normals;    // 3 per point, unit; zero when the point has no valid normal
  std::vector<float> CosineSums; // sum_j max(0, <n_i, l_j>), 0 for invalid points
  double EffectiveDepthOffset = 0.0;
  double TestTime = 0.0;
  int PointTestUsed = POINT_TEST_CPU;

private:
  vtkAOSattlerBaker(const vtkAOSattlerBaker&) = delete;
  void operator=(const vtkAOSattlerBaker&) = delete;

  class vtkInternals;
  vtkInternals* Internals; // owned by ContextResources

  // The steps of BakePoints, in order.
  void PlaceTestPoints(const Surface& surface);
  bool PrepareDepthPass(Surface& surface);
  void SelectPointTest();
  void RenderDirections();
  void RenderDepthMap(int direction);
  void TestPointsOnGPU(int direction);
  void RecordGPUBits(int direction);
  void TestPointsOnCPU(int direction);
  void WriteResults(Surface& surface, float* values);
};

#endif
