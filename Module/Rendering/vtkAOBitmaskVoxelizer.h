/**
 * @class   vtkAOBitmaskVoxelizer
 * @brief   Single-pass bitmask voxelization of the opaque props in a box (Eisemann & Decoret
 *          2006; Reinboth et al. 2009, section 5).
 *
 * Render() draws the props of the render state once, with an orthographic "voxel camera"
 * looking through the region, into a stack of RGBA32UI attachments: each fragment sets the
 * bit of its depth slice and the framebuffer ORs it in (glLogicOp(GL_OR)). An attachment holds
 * 128 slices; the grid is a 3-D texture of (x, y, slices / 128) texels. Cells are cubes: the
 * longest side of the region gets Resolution cells, the others proportionally fewer.
 *
 * Polygons parallel to the voxel camera's view direction have no footprint and are lost
 * (the method's known drawback). With RandomRotation the voxel camera looks along the
 * diagonal of the world axes, rolled about it by a seeded random angle, so the axis-aligned
 * polygons common in CAD and scientific scenes are all seen at 54.7 degrees. The slices a
 * fragment sets are bounded (3 slices per pixel of slope): steeper polygons seen almost
 * edge-on would otherwise grow spikes of stray voxels out of the surface.
 *
 * Both faces of every polygon are voxelized: back-face culling set on a property is
 * suspended for the voxelization. Props must be opaque polygonal geometry; the caller
 * chooses them (see vtkHybridAmbientOcclusionPass).
 */
#ifndef vtkAOBitmaskVoxelizer_h
#define vtkAOBitmaskVoxelizer_h

#include "vtkNew.h" // For vtkNew
#include "vtkOpenGLRenderPass.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <vector> // For DownloadGrid

class vtkCamera;
class vtkMatrix4x4;
class vtkOpaquePass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKAORENDERING_EXPORT vtkAOBitmaskVoxelizer : public vtkOpenGLRenderPass
{
public:
  static vtkAOBitmaskVoxelizer* New();
  vtkTypeMacro(vtkAOBitmaskVoxelizer, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of cells along the longest side of the region. Range [8, 4096]; clamped, with a
   * warning, to what the OpenGL implementation supports (texture size, and 128 slices per
   * draw buffer). Default is 256 (the HAO paper's setting).
   */
  vtkSetClampMacro(Resolution, int, 8, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Look along the diagonal of the world axes, rolled by a random angle drawn from
   * RotationSeed (runs are repeatable), so that polygons aligned with the world axes are not
   * lost. Off: the voxel camera looks along -z with the grid aligned with the world axes.
   * Default is on.
   */
  vtkSetMacro(RandomRotation, bool);
  vtkGetMacro(RandomRotation, bool);
  vtkBooleanMacro(RandomRotation, bool);
  vtkSetMacro(RotationSeed, unsigned int);
  vtkGetMacro(RotationSeed, unsigned int);
  ///@}

  ///@{
  /**
   * Number of axes the props are voxelized along. 1: the voxel camera's axis only, one
   * render (the HAO paper's method); polygons seen almost edge-on from it are voxelized
   * with gaps that rays can pass through (about 1 in 10 rays leaves a sphere unseen at
   * resolution 128; beside a unit sphere on a plane A comes out 0.05 too light). 3 (default):
   * the three axes of the grid, each polygon drawn by the axis it faces most, then merged:
   * closed surfaces of any orientation, for three renders of the props and a merge pass per
   * voxelization. 2 uses the voxel camera's axis and the grid's x axis.
   */
  vtkSetClampMacro(NumberOfAxes, int, 1, 3);
  vtkGetMacro(NumberOfAxes, int);
  ///@}

  ///@{
  /**
   * The world-space box to voxelize (xmin, xmax, ymin, ymax, zmin, zmax). Geometry outside is
   * clipped. Default is the unit cube around the origin.
   */
  vtkSetVector6Macro(Region, double);
  vtkGetVector6Macro(Region, double);
  ///@}

  ///@{
  /**
   * A cascade of a clipmap (see vtkHybridAmbientOcclusionPass::SetNumberOfCascades): with a
   * half-size Focus[3] > 0, the grid covers only the cube of that half-size around the world
   * point (Focus[0], Focus[1], Focus[2]), axis-aligned in the voxel camera's frame and clipped
   * to the Region, with cells of 2 Focus[3] / Resolution (so that cascades of the same
   * Resolution and doubling half-sizes have doubling cells). Default (0, 0, 0, 0): the whole
   * Region.
   */
  vtkSetVector4Macro(Focus, double);
  vtkGetVector4Macro(Focus, double);
  ///@}

  /**
   * After Render() with a Focus: the focus cube in continuous cell coordinates (xmin, xmax,
   * ymin, ymax, zmin, zmax), before clipping to the Region; a point whose ball of radius r
   * lies inside it has every occluder within r in this grid. Without a Focus: an unbounded box.
   */
  vtkGetVector6Macro(FocusCells, double);

  /**
   * Incremented each time Render() or UploadGrid() fills the grid: what was built from the
   * grid (the tracer's distance field) is stale when this changed.
   */
  vtkGetMacro(GridVersion, long long);

  /**
   * Voxelize the props of @p s into the region. Clears the grid first.
   */
  void Render(const vtkRenderState* s) override;

  ///@{
  /**
   * Incremental voxelization (see vtkHybridAmbientOcclusionPass::SetIncrementalVoxelization).
   * RenderBase() voxelizes the props of @p s into a base grid kept beside the grid (the props
   * that do not move); the grid itself is undefined until the next Render(). With UseBase on,
   * Render() voxelizes its own props (those that move) and ORs the base in: the grid is then
   * the one Render() would give for both sets of props together, bit for bit, since the cells
   * a polygon sets depend on no other polygon. The base is used only while the grid's frame
   * (region, focus, resolution, rotation, axes) is the one it was made in: HasBase() says
   * whether it is, for the frame of the last Render() or RenderBase(); Render() with UseBase
   * and no such base voxelizes its own props alone, with an error. Over a base, Render()
   * merges the extra axes' grids only in the columns its props' bounds cover. ReleaseBase()
   * frees the base (it costs the grid's memory again). UseBase default: off.
   */
  void RenderBase(const vtkRenderState* s);
  vtkSetMacro(UseBase, bool);
  vtkGetMacro(UseBase, bool);
  bool HasBase();
  void ReleaseBase(vtkWindow* w);
  ///@}

  /**
   * Free the grid texture and framebuffer.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// Bytes of GPU memory in the textures this stage owns (0 after ReleaseGraphicsResources).
  long long GetGraphicsMemorySize();

  ///@{
  /**
   * The grid after Render(): the texture (RGBA32UI, 3-D), the number of cells along x, y and
   * z (z counts slices, a multiple of 32), the cell edge length in world units, and the
   * matrix taking world coordinates to continuous cell coordinates ([0, dims)).
   */
  vtkTextureObject* GetGridTexture() { return this->Targets[0].Texture; }
  vtkGetVector3Macro(GridDimensions, int);
  vtkGetMacro(CellSize, double);
  vtkMatrix4x4* GetWorldToGridMatrix() { return this->WorldToGrid; }
  ///@}

  /**
   * The largest Resolution the current context supports (0 before the first Render()).
   */
  vtkGetMacro(MaximumResolution, int);

  /**
   * The largest Resolution @p renWin's OpenGL implementation supports (queried once).
   */
  int GetSupportedResolution(vtkOpenGLRenderWindow* renWin);

  /**
   * Read the grid back (for tests and diagnostics): four words per (x, y, layer) texel,
   * x fastest, then y, then layer. Returns false if there is no grid. Needs a desktop GL context.
   */
  bool DownloadGrid(std::vector<unsigned int>& words);

  /**
   * Replace the grid by @p words, laid out as DownloadGrid writes them (e.g. a grid combined
   * across processes, see vtkAOParallelReducer). The size must match the current grid.
   * Returns false if there is no grid or the size differs. Needs the grid's context current.
   */
  bool UploadGrid(const std::vector<unsigned int>& words);

  /**
   * Whether cell (i, j, k) of a downloaded grid is occupied.
   */
  bool IsOccupied(const std::vector<unsigned int>& words, int i, int j, int k) const;

  /**
   * Number of occupied cells (downloads the grid).
   */
  long long CountOccupiedCells();

  /**
   * Write the voxel's slice bit into the integer outputs instead of a colour.
   */
  bool PostReplaceShaderValues(std::string& vertexShader,
    std::string& geometryShader,
    std::string& fragmentShader,
    vtkAbstractMapper* mapper,
    vtkProp* prop) override;

  /**
   * Give the shader the number of slices.
   */
  bool SetShaderParameters(vtkShaderProgram* program,
    vtkAbstractMapper* mapper,
    vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

  /**
   * Moves when the number of attachments (and so the shader code) changes.
   */
  vtkMTimeType GetShaderStageMTime() override { return this->ShaderStageTime.GetMTime(); }

protected:
  vtkAOBitmaskVoxelizer();
  ~vtkAOBitmaskVoxelizer() override;

  /// Place the voxel camera and the cells over the region; false if the region is empty.
  bool ComputeGridFrame(vtkOpenGLRenderWindow* renWin);
  /// The resolution asked for, clamped (with a warning) to what the implementation supports.
  int UsableResolution(vtkOpenGLRenderWindow* renWin);
  /// Cells and grid box (in the voxel camera's frame, lo and hi) over the region's box
  /// [lo, hi] in that frame, with or without a Focus; fills CellSize and GridDimensions.
  void FitCells(const double rotatedFocus[3], int resolution, double lo[3], double hi[3]);
  /// Create or re-create the grid texture and framebuffer for the current dimensions.
  bool InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin);
  /// The GL limit on the resolution.
  int QueryMaximumResolution(vtkOpenGLRenderWindow* renWin);
  /// Create (or re-create at a new size) the texture and framebuffer of one axis.
  bool EnsureTarget(int axis, vtkOpenGLRenderWindow* renWin);
  void ReleaseTarget(int axis, vtkWindow* w);
  /// The projection of the voxel camera that renders along grid axis @p axis (0: z, 1: x, 2: y).
  void AxisProjection(int axis, vtkMatrix4x4* result) const;
  /// OR the extra axes' grids into the grid.
  /// Only in the grid columns [columns[0], columns[2]) x [columns[1], columns[3]).
  void MergeAxes(vtkOpenGLRenderWindow* renWin, const int columns[4]);
  /// The grid columns the props of @p s can touch (x0, y0, x1, y1).
  void PropColumns(const vtkRenderState* s, int columns[4]) const;
  /// Draw into every layer of the grid, over the whole grid / restore the previous binding.
  void BindGrid(vtkOpenGLRenderWindow* renWin);
  void UnbindGrid();
  /// OR the base into the grid (UseBase); false if the base's frame is not the grid's.
  bool ApplyBase(vtkOpenGLRenderWindow* renWin);
  /// The grid's frame: dimensions and world-to-cell matrix (what a base must match).
  std::vector<double> GridFrame() const;

  /// A render target: pixels (Size[0] x Size[1]) of Size[2] slices, 128 per texture layer.
  struct Target
  {
    vtkTextureObject* Texture = nullptr;
    vtkOpenGLFramebufferObject* Framebuffer = nullptr;
    int Size[3] = { 0, 0, 0 };
  };

  int Resolution = 256;
  bool RandomRotation = true;
  unsigned int RotationSeed = 1;
  double Region[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  double Focus[4] = { 0.0, 0.0, 0.0, 0.0 };
  double FocusCells[6] = { -1e30, 1e30, -1e30, 1e30, -1e30, 1e30 };
  long long GridVersion = 0;

  int GridDimensions[3] = { 0, 0, 0 };
  int NumberOfLayers = 0;
  double CellSize = 0.0;
  int MaximumResolution = 0;
  int WarnedResolution = 0;

  vtkNew<vtkMatrix4x4> WorldToGrid;
  vtkNew<vtkCamera> VoxelCamera;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkMatrix4x4> ViewToGrid;
  vtkNew<vtkMatrix4x4> GridProjection;
  Target Targets[3]; // the grid, then the x and y axes' grids (with NumberOfAxes > 1)
  /// The base of an incremental voxelization (RenderBase) and the grid frame it was made in.
  Target Base;
  std::vector<double> BaseFrame;
  bool UseBase = false;
  std::unique_ptr<vtkOpenGLQuadHelper> BaseQuad;
  int BaseLayers = 0;
  std::unique_ptr<vtkOpenGLQuadHelper> MergeQuad;
  int MergeLayers = 0;
  /// The merge's summaries: for the x (y) axis's grid, texel (y, z / 32 x layers + x / 128)
  /// (resp. (x, z / 32 x layers + y / 128)) ORs that grid's texels over 32 slices of z, so
  /// that the merge reads only the runs of slices a polygon of that axis occupies.
  vtkTextureObject* Summaries[2] = { nullptr, nullptr };
  vtkOpenGLFramebufferObject* SummaryFramebuffer = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> SummaryQuad;
  bool SummarizeAxis(vtkOpenGLRenderWindow* renWin, int axis);
  int NumberOfAxes = 3;
  int NumberOfOutputs = 0; // integer outputs the fragment shader declares
  int CurrentSlices = 0;   // slices of the axis being rendered
  float CurrentSlopeLimit[2] = { 1e30f, 1e30f };
  vtkTimeStamp ShaderStageTime;

private:
  vtkAOBitmaskVoxelizer(const vtkAOBitmaskVoxelizer&) = delete;
  void operator=(const vtkAOBitmaskVoxelizer&) = delete;
};

#endif
