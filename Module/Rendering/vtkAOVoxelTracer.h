/**
 * @class   vtkAOVoxelTracer
 * @brief   Occlusion sampling through a bitmask voxel grid (HAO section 6, eq. 4).
 *
 * For every texel of a reduced-resolution AO map, rebuild p and n from the G-buffer and march
 * Rays cosine-distributed rays (within the cone set by Spread) in Steps equal steps of
 * Radius / Steps through the grid; each step tests up to 4 evenly spaced points along its
 * segment (about one per cell), so a ray tests Steps x min(4, ceil(Radius / (Steps cell)))
 * points at fixed distances; the first occupied point on a ray counts with the falloff
 * weight of its distance (Wendland or binary). Rays start at p + Bias n. Directions and step
 * offsets are jittered by a 3-D white-noise texture evaluated in world space, so the noise
 * stays on the surfaces when the camera moves.
 *
 * Empty-space skipping: after each voxelization a coarse occupancy level is built on the GPU
 * (one bit per block of 4 x 4 x 4 cells, the OR of its cells). A ray reads it first and jumps
 * over every point that falls in an empty block; the fine grid is read only inside occupied
 * blocks. The points tested, and so the result, are those of the plain march.
 *
 * Cascades: Trace() and Refine() take up to MaximumLevels grids, finest first, each the
 * cascade of a clipmap (vtkAOBitmaskVoxelizer::SetFocus, cells doubling from one to the
 * next). Each pixel marches all its rays through the finest grid whose focus cube holds the
 * ball of radius Radius around it (the last grid holds every pixel), so every occluder
 * within reach is in the grid it reads.
 *
 * Output (RGBA32F, one texel per AO-map sample): R = A (shared/design/ao-definition.md),
 * G = 1 where there is geometry (0 on the background), B = the sample's window depth, A = its
 * view-space normal packed in one float (aoPackNormal in vtkAOCommon.glsl), so that the
 * bilateral filter reads a tap with a single fetch.
 */
#ifndef vtkAOVoxelTracer_h
#define vtkAOVoxelTracer_h

#include "vtkAOQuadStage.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For the cascades

class vtkAOBitmaskVoxelizer;
class vtkAOGBufferPass;
class vtkMatrix4x4;
class vtkAOPixelList;
class vtkShaderProgram;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOVoxelTracer : public vtkAOQuadStage
{
public:
  static vtkAOVoxelTracer* New();
  vtkTypeMacro(vtkAOVoxelTracer, vtkAOQuadStage);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What the tracer needs to know about one frame.
  struct Parameters
  {
    int Scale = 2;       // full-resolution pixels per AO-map texel along each axis
    int Rays = 8;        // rays per AO-map texel
    int Steps = 4;       // steps of Radius / Steps per ray (each tests up to 4 points)
    double Radius = 1.0; // world units
    double Bias = 0.0;   // world units: rays start at p + Bias n
    /// A hit whose cell centre lies within half a cell's extent along n of the tangent plane
    /// at p, plus SelfSlope per unit of distance along the ray, is the surface itself (see
    /// vtkAOVoxelTracerFS.glsl). The slope covers facets of a tessellated curved surface
    /// against its interpolated normal; it ignores occluders seen at elevations below
    /// atan(SelfSlope), a share sin^2 of the cosine-weighted hemisphere.
    double SelfSlope = 0.1;
    double Spread = 1.0; // cone half-angle in units of pi/2
    /// Cells by which the occupied cells' exposed faces (no occupied neighbour across them,
    /// nor diagonally where the surface goes on through an edge or corner) are moved in
    /// before a ray tests them, 0 to MaximumErosion. A surface anywhere in a cell fills the
    /// whole cell, so thin walls are a cell thick and the gaps between them a cell narrow on
    /// average; 0.25 halves that. A point of another surface's occupied cell that lies
    /// outside the thinned wall is followed by one more test half a spacing towards it, so
    /// that the thinner walls are not stepped over; 0 compiles the march without any of this
    /// (vtkAOVoxelTracerFS.glsl, aoMarch).
    double Erosion = 0.25;
    bool BinaryFalloff = false;
    bool Parallel = false; // orthographic scene camera
    /// true: each grid's coarse occupancy level is rebuilt only when the grid's
    /// GetGridVersion() changed since it was built (the caller changes a grid only through
    /// its Render() or UploadGrid()). false: rebuild every time (the grids' textures are
    /// changed some other way).
    bool FollowGridVersions = false;
    /// The frame's index in a progressive accumulation (0: the plain frame). Frame k rotates
    /// every pixel's jitter by the k-th point of the R3 sequence (Roberts 2018: k times the
    /// inverse powers of phi_3, the positive root of x^4 = x + 1, modulo 1), so that the
    /// frames of a still view sample each pixel's rays, azimuths and step offsets at low
    /// discrepancy.
    int FrameIndex = 0;
    /// The ray noise's frequency in world space, relative to two noise texels per cell of the
    /// finest grid. Refine() raises it to the map's Scale: neighbouring refined pixels then
    /// draw independent rays, as the map's samples (Scale pixels apart) do, and the refinement
    /// filter averages their noise away instead of keeping blotches a noise texel wide.
    double NoiseFrequency = 1.0;
  };

  /// The largest Parameters::Erosion: thin walls keep half a cell, which the points, half a
  /// cell apart where they meet an occupied cell, cannot step over.
  static constexpr double MaximumErosion = 0.25;

  /// The most grids (cascades) Trace() and Refine() use; more are ignored.
  static constexpr int MaximumLevels = 4;
  using Grids = std::vector<vtkAOBitmaskVoxelizer*>;

  /// What Trace() and Refine() read of one frame.
  struct Input
  {
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkAOGBufferPass* GBuffer = nullptr; ///< the frame's G-buffer, the view traced
    Grids Cascades;                      ///< the grids, finest first (at least one)
    vtkMatrix4x4* View = nullptr;        ///< the scene camera's matrices (VTK convention)
    vtkMatrix4x4* Projection = nullptr;
    Parameters Settings;
  };

  /**
   * Trace the AO map for the G-buffer's view through the grids of @p input. Returns false on
   * failure.
   */
  bool Trace(const Input& input);

  /**
   * After Trace() with Scale > 1: trace again, at full resolution, the pixels @p marks marks
   * (a depth texture of the G-buffer's size, 0 where the reduced map cannot represent the
   * pixel: vtkAOBilateralUpsampler::Marking), with @p rays rays each (0: the map's count), and
   * write their A and coverage into @p target (the upsampled, full-resolution RG32F map) in
   * place. The other pixels are not shaded: the marks, as the depth attachment, reject them
   * before the tracer runs. With @p filterRadius > 0 each refined pixel is then replaced by
   * the weighted mean of the pixels of its own surface within that many pixels, the refined
   * ones' traced A and the others' upsampled A (glsl/vtkAORefineFilterFS.glsl): the refined
   * pixels get a denoising filter as the others do. Returns false on failure.
   */
  bool Refine(const Input& input,
    int rays,
    int filterRadius,
    vtkTextureObject* marks,
    vtkTextureObject* target);

  /**
   * How Refine() shades the marked pixels. On (the default): listed first (vtkAOPixelList:
   * compacted by a geometry shader into transform feedback), then traced and filtered as a
   * dense rectangle and scattered back, so that no SIMD group of the tracer holds unmarked
   * pixels. Off, or where the context cannot list them: in place, by a full-screen pass whose
   * depth test (the marks) rejects the unmarked pixels. Both give the same values.
   */
  void SetListRefinement(bool list) { this->ListRefinement = list; }
  bool GetListRefinement() const { return this->ListRefinement; }

  /**
   * The share of the viewport's pixels the last Refine() traced (in place, reads an occlusion
   * query: waits for that frame). 0 if Refine() did nothing.
   */
  double GetRefinedFraction();

  /**
   * Free what only Refine() uses (the refinement filter's texture and program), for frames
   * that do not refine; the share refined becomes 0.
   */
  void ReleaseRefinement(vtkOpenGLRenderWindow* renWin);

  ///@{
  /**
   * The AO map written by the last Trace() is GetOutput() (RGBA32F: A, coverage, depth, packed
   * normal); this stage frees, and counts the memory of, its noise, the refinement filter's
   * texture and the empty-space-skipping levels with it (the refinement's marks are the
   * upsampler's).
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;
  long long GetGraphicsMemorySize() override;
  ///@}

protected:
  vtkAOVoxelTracer();
  ~vtkAOVoxelTracer() override;

  /// The empty-space-skipping data of one grid.
  struct Level
  {
    vtkTextureObject* Coarse = nullptr;   ///< RGBA32UI, 2-D: 128 blocks along z per texel
    vtkTextureObject* Distance = nullptr; ///< R8, 3-D: blocks to the nearest occupied block
    int CoarseSize[3] = { 0, 0, 0 };      ///< blocks along x, y, z
    bool Skipping = false;                ///< whether the distance field was built
    long long Version = -1;               ///< the grid's GetGridVersion() it was built from
    unsigned int GridHandle = 0;          ///< GL name of the grid texture it was built from
  };

  /// The noise, the coarse levels and the program, ready for @p input's grids. False on
  /// failure.
  bool Prepare(const Input& input);
  /// Activate the tracer's textures and set @p program's uniforms (Quad's or ListQuad's) for
  /// one draw with @p par (the input's settings, or Refine()'s).
  void BindTracer(vtkShaderProgram* program, const Input& input, const Parameters& par);
  /// Refine() through the list of marked pixels; false (nothing drawn) if it cannot.
  bool RefineListed(const Input& input,
    const Parameters& full,
    int filterRadius,
    vtkTextureObject* marks,
    vtkTextureObject* target);
  /// Copy @p target into Refined (the in-place refinement filter's input).
  void CopyToRefined(vtkOpenGLRenderWindow* renWin, vtkTextureObject* target);
  void UnbindTracer(const Input& input);
  /// Create the noise texture on first use.
  void InitializeNoise(vtkOpenGLRenderWindow* renWin);
  /// Build the coarse occupancy level (OR of blocks) of @p grid and its distance field.
  bool BuildCoarseLevel(vtkOpenGLRenderWindow* renWin, vtkAOBitmaskVoxelizer* grid, Level& level);
  /// A 1-texel distance field that marks every block occupied (no skipping).
  void DisableSkipping(vtkOpenGLRenderWindow* renWin, Level& level);
  /// Draw the coarse occupancy of @p gridTexture into level.Coarse (cw x ch texels).
  bool RenderCoarseOccupancy(vtkOpenGLRenderWindow* renWin,
    vtkTextureObject* gridTexture,
    Level& level,
    int rows,
    int cw,
    int ch);
  /// Upload a distance field of bx x by x bz blocks into level.Distance.
  void UploadDistance(vtkOpenGLRenderWindow* renWin,
    Level& level,
    const int blocks[3],
    const std::vector<unsigned char>& distance);
  /// Set the per-grid uniforms (arrays indexed by cascade) for @p grids.
  void SetLevelUniforms(vtkShaderProgram* program,
    const Grids& grids,
    vtkMatrix4x4* viewToWorld,
    const Parameters& par);

  vtkTextureObject* Noise = nullptr;
  int QuadVariant = 0;           ///< Quad's program: 2 x its number of grids, + 1 with erosion
  unsigned int SamplesQuery = 0; ///< GL_SAMPLES_PASSED of the refining draw
  bool QueryPending = false;
  double QueryPixels = 0.0;
  double RefinedFraction = 0.0;
  Level Levels[MaximumLevels];
  std::unique_ptr<vtkOpenGLQuadHelper> CoarseQuad;
  vtkTextureObject* Refined = nullptr;             ///< full resolution, in place with the filter on
  std::unique_ptr<vtkOpenGLQuadHelper> FilterQuad; ///< the refinement filter
  std::string QuadDefines;                         ///< Quad's preprocessor lines
  bool ListRefinement = true;
  vtkAOPixelList* List = nullptr;                      ///< the marked pixels, listed
  std::unique_ptr<vtkOpenGLQuadHelper> ListQuad;       ///< the tracer over List
  std::unique_ptr<vtkOpenGLQuadHelper> ListFilterQuad; ///< the refinement filter over List
  bool ListUnavailable = false; ///< the listed programs did not compile: refine in place

private:
  vtkAOVoxelTracer(const vtkAOVoxelTracer&) = delete;
  void operator=(const vtkAOVoxelTracer&) = delete;
};

#endif
