/**
 * @class   vtkAOVertexBaker
 * @brief   per-vertex ambient occlusion by ray casting (Embree)
 *
 * The ray-cast visibility method of vtkAOBaker (which owns the ports, the surface, the normals
 * and the output array): A(p, n) of design/ao-definition.md at every point, estimated with
 * Samples rays from p + Bias n against the exact triangles of the input and the occluders
 * (Embree; non-convex polygons are cut into ears). Degenerate and non-finite triangles are
 * ignored.
 *
 * With uniform sampling each direction is weighted by its cosine, so both sampling modes
 * estimate the same integral (cosine sampling has less noise). Points are processed in
 * parallel with vtkSMPTools; the result is deterministic for a given Seed. Progress is
 * reported from the calling thread.
 */
#ifndef vtkAOVertexBaker_h
#define vtkAOVertexBaker_h

#include "vtkAOBaker.h"
#include "vtkaoReferenceModule.h" // For export macro

class VTKAOREFERENCE_EXPORT vtkAOVertexBaker : public vtkAOBaker
{
public:
  static vtkAOVertexBaker* New();
  vtkTypeMacro(vtkAOVertexBaker, vtkAOBaker);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FalloffType
  {
    WENDLAND = 0, ///< W(t) = (1 - t/R)^4 (4t/R + 1) (HAO eq. 3)
    BINARY = 1    ///< W(t) = 1 for t <= R ("None" in ao-definition.md)
  };

  enum SamplingType
  {
    COSINE = 0, ///< cosine-weighted directions (less noise)
    UNIFORM = 1 ///< uniform directions in the cone, each weighted by its cosine
  };

  ///@{
  /**
   * Occlusion radius R, world units. 0 means automatic: a tenth of the diagonal of the bounds
   * of the input and the occluders (as the HAO pass). Range [0, inf). Default is 0.
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
   * Falloff kernel. Default is WENDLAND.
   */
  vtkSetClampMacro(Falloff, int, WENDLAND, BINARY);
  vtkGetMacro(Falloff, int);
  void SetFalloffToWendland() { this->SetFalloff(WENDLAND); }
  void SetFalloffToBinary() { this->SetFalloff(BINARY); }
  ///@}

  ///@{
  /**
   * Direction distribution. Default is COSINE.
   */
  vtkSetClampMacro(Sampling, int, COSINE, UNIFORM);
  vtkGetMacro(Sampling, int);
  void SetSamplingToCosine() { this->SetSampling(COSINE); }
  void SetSamplingToUniform() { this->SetSampling(UNIFORM); }
  ///@}

  ///@{
  /**
   * Rays per point. Range [1, 1048576]. Default is 256.
   */
  vtkSetClampMacro(Samples, int, 1, 1048576);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /**
   * Seed of the per-point rotation of the direction set. Default is 0.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Radius used by the last execution (GetEffectiveBias() gives the bias); rays cast and
   * seconds spent tracing.
   */
  vtkGetMacro(EffectiveRadius, double);
  vtkGetMacro(NumberOfRays, vtkTypeInt64);
  vtkGetMacro(TraceTime, double);
  ///@}

protected:
  vtkAOVertexBaker();
  ~vtkAOVertexBaker() override;

  void InitializeResults(vtkIdType numberOfPoints) override;
  /// Casts the rays of every baked point (in parallel, in blocks with progress between them).
  int BakePoints(Surface& surface, float* values) override;

  double Radius = 0.0;
  double Spread = 1.0;
  int Falloff = WENDLAND;
  int Sampling = COSINE;
  int Samples = 256;
  unsigned int Seed = 0;

  double EffectiveRadius = 0.0;
  vtkTypeInt64 NumberOfRays = 0;
  double TraceTime = 0.0;

private:
  vtkAOVertexBaker(const vtkAOVertexBaker&) = delete;
  void operator=(const vtkAOVertexBaker&) = delete;
};

#endif
