// The ray-traced methods of the vtkao program (vtkAO::ReferenceAO, built with Embree):
// `render --method reference`, `render --method baked` and `bake`.
#ifndef vtkaoReference_h
#define vtkaoReference_h

#include "vtkaoImageIO.h"

#include <iosfwd>
#include <string>

class vtkAOBaker;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;

namespace vtkao
{
/// The AO parameters the reference and the baker share (0 = automatic, as in the HAO pass).
struct RayTracingOptions
{
  double Radius = 0;
  double Bias = 0;
  double Spread = 1;
  bool BinaryFalloff = false;
  int Samples = 256;
  /// `bake --method`: "raycast" (vtkAOVertexBaker) or "sattler" (vtkAOSattlerBaker, GPU
  /// visibility from Samples directions, R = infinity, binary falloff).
  std::string BakeMethod = "raycast";
};

/// Trace A for the renderer's view at @p width x @p height: two channels (A, coverage), rows
/// bottom-up, as the HAO pass's AO-only image. Writes a progress bar to stderr and a one-line
/// summary (rays, rays/s/core) to @p report. Throws std::runtime_error on failure.
FloatImage RenderReference(vtkRenderer* renderer,
  int width,
  int height,
  const RayTracingOptions& options,
  std::ostream& report);

/// Bake A into every visible opaque polydata actor of @p renderer (in world space; every other
/// actor occludes it) and colour the actors by it: base colour x A, or, with @p aoOnly, A as
/// unlit grey so the window shows A itself. Throws std::runtime_error on failure.
void BakeRenderer(vtkRenderer* renderer,
  const RayTracingOptions& options,
  bool aoOnly,
  std::ostream& report);

/// Read back what BakeRenderer(..., aoOnly = true) drew: two channels (A from the grey level,
/// 8-bit; coverage from the depth buffer). Background pixels are A = 1, coverage 0.
FloatImage ReadBakedAO(vtkRenderWindow* window, int width, int height);

/// `vtkao bake`: read @p input, bake A per vertex, write @p output (.vtp) through a temporary
/// file. Progress bar on stderr. Throws std::runtime_error with a one-line message.
void BakeFile(const std::string& input,
  const std::string& output,
  const RayTracingOptions& options,
  std::ostream& report);

/// The mesh `bake` bakes: the first polydata actor @p input adds to @p scene. Throws (before
/// any time is spent baking) when there is none or when @p output cannot be written.
vtkPolyData* MeshToBake(vtkRenderer* scene, const std::string& input, const std::string& output);

/// Runs @p baker (set up, with its input) under a progress bar and writes its output to
/// @p output (.vtp) through a temporary file. Throws @p failure when the baker made no array.
void BakeAndWrite(vtkAOBaker* baker, const std::string& output, const std::string& failure);
}

#endif
