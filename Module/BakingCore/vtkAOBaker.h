/**
 * @class   vtkAOBaker
 * @brief   base of the per-vertex ambient-occlusion bakers: ports, surface, normals, array
 *
 * Adds a point-data array (ArrayName, default "AmbientOcclusion", one float per point) holding
 * A(p, n) of design/ao-definition.md at every point of the input polydata. The subclasses
 * differ only in their visibility method, BakePoints(): vtkAOVertexBaker casts rays (Embree),
 * vtkAOSattlerBaker tests the points against depth maps from many directions, and
 * vtkAOHemisphereBaker renders a hemicube per point (both OpenGL).
 *
 * What every baker does the same way (RequestData, a template method):
 * - input port 0 holds the surface to bake; port 1 (optional, repeatable) extra occluders, which
 *   occlude but get no array (AddOccluderConnection / AddOccluderData); all in one coordinate
 *   system;
 * - the surface: the input's polygons and strips whose points are all valid and finite and of
 *   which one triangle (of the cell's fan or strip) spans an area. Only their points get a
 *   value; lines and vertices neither get one nor occlude;
 * - point normals: the input's when it has a 3-component array with one tuple per point, else
 *   computed from the surface with vtkPolyDataNormals (no splitting, consistent ordering, so
 *   point ids are kept). Duplicated points each get their own value from their own normal;
 * - the output is a shallow copy of the input with the array, which starts at 1: points that no
 *   surface cell uses, or whose position or normal is not finite or is zero, keep A = 1.
 *
 * @sa vtkAOVertexBaker vtkAOSattlerBaker vtkAOHemisphereBaker
 */
#ifndef vtkAOBaker_h
#define vtkAOBaker_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"       // for vtkSmartPointer
#include "vtkaoBakingCoreModule.h" // For export macro

#include <cstdint> // for std::uint32_t
#include <string>  // for std::string
#include <vector>  // for std::vector

class vtkCellArray;

class VTKAOBAKINGCORE_EXPORT vtkAOBaker : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkAOBaker, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Extra occluders (input port 1, optional, repeatable): they occlude but get no array.
   */
  void AddOccluderConnection(vtkAlgorithmOutput* output);
  void AddOccluderData(vtkPolyData* occluder);
  void RemoveAllOccluders();
  ///@}

  ///@{
  /**
   * The baker looks from p + Bias n (ray origins, test points, hemicube eyes), world units, so
   * that a surface does not occlude itself. 0 means automatic: two cells of the HAO pass's
   * default 256^3 grid, 2/256 of the longest side of the bounds grown by twice the radius (the
   * effective radius for vtkAOVertexBaker, the automatic one, a tenth of the diagonal, for the
   * GPU bakers). Range [0, inf). Default is 0.
   */
  vtkSetClampMacro(Bias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /**
   * Name of the output point-data array. Default is "AmbientOcclusion".
   */
  void SetArrayName(const std::string& name);
  const std::string& GetArrayName() const { return this->ArrayName; }
  ///@}

  /**
   * The bias used by the last execution (Bias, or the automatic value).
   */
  vtkGetMacro(EffectiveBias, double);

  /**
   * Seconds the last execution took, all of it (surface, normals, baking).
   */
  vtkGetMacro(TotalTime, double);

protected:
  vtkAOBaker();
  ~vtkAOBaker() override;

  /**
   * The input surface as every baker sees it, gathered by RequestData for BakePoints().
   */
  struct Surface
  {
    Surface();
    ~Surface();

    vtkPolyData* Input = nullptr;
    vtkPolyData* Output = nullptr;             ///< the input's shallow copy, with the array
    vtkInformationVector* Occluders = nullptr; ///< port 1's polydata (may be empty)
    /// The occluding triangles, filled when GatherTriangles is on: the input's and every
    /// occluder's kept polygons (as fans) and strips, in the order the cells come.
    std::vector<double> Points;           ///< 3 per point: the input's, then each occluder's
    std::vector<std::uint32_t> Triangles; ///< 3 indices into Points per triangle
    double Bounds[6];                     ///< of the occluding triangles' corners
    std::vector<char> OnSurface;          ///< per input point: 1 when a kept input cell uses it
    vtkSmartPointer<vtkCellArray> Polys;  ///< the input's kept polygons ...
    vtkSmartPointer<vtkCellArray> Strips; ///< ... and strips (the surface that defines normals)
    /// The points that get a value (on the surface, finite, with a non-zero finite normal), in
    /// id order, and every input point's unit normal (3 each, zero for the other points).
    std::vector<vtkIdType> Baked;
    std::vector<double> Normals;

    std::size_t GetNumberOfTriangles() const { return this->Triangles.size() / 3; }
  };

  /**
   * Called first by RequestData, with the input's number of points: reset the results and
   * statistics of the last execution. Default does nothing.
   */
  virtual void InitializeResults(vtkIdType vtkNotUsed(numberOfPoints)) {}

  /**
   * The visibility method: write A for every point of @p surface.Baked into @p values (one
   * float per input point, all 1 on entry), and set EffectiveBias. Called only when there is a
   * point to bake. Returns 1 on success, 0 on failure (after vtkErrorMacro).
   */
  virtual int BakePoints(Surface& surface, float* values) = 0;

  /**
   * InitializeResults(), then the surface, the normals and the points to bake, the array, and
   * BakePoints(); TotalTime is the time it all took.
   */
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /**
   * The automatic bias of the GPU bakers for these bounds: vtkAOVertexBaker's with its
   * automatic radius, 2/256 of the longest side of the bounds grown by a fifth of their diagonal.
   */
  static double AutomaticBias(const double bounds[6]);

  /**
   * The centre of @p bounds.
   */
  static void Center(const double bounds[6], double center[3]);

  /// Whether RequestData fills Surface::Points and Surface::Triangles (the rasterizing bakers
  /// draw them; the ray caster builds its own scene). Default is on.
  bool GatherTriangles = true;
  double Bias = 0.0;
  double EffectiveBias = 0.0;
  double TotalTime = 0.0; ///< seconds, the whole of the last execution
  std::string ArrayName = "AmbientOcclusion";

private:
  vtkAOBaker(const vtkAOBaker&) = delete;
  void operator=(const vtkAOBaker&) = delete;

  int Bake(vtkPolyData* input, vtkInformationVector* occluders, vtkPolyData* output);
  bool GatherSurface(Surface& surface);
  bool GatherNormals(Surface& surface);
};

#endif
