// `vtkao bake --method hemisphere`: per-vertex A by hemicube rendering (vtkAOHemisphereBaker).
// Built into the vtkao program from Examples/Baking (see its CMakeLists.txt).
#ifndef vtkaoBakeHemisphere_h
#define vtkaoBakeHemisphere_h

#include <iosfwd>
#include <string>

namespace vtkao
{
/// The options of `bake --method hemisphere` (0 = automatic, as in vtkAOHemisphereBaker).
struct HemisphereBakeOptions
{
  double Radius = 0; ///< 0 = infinity (binary falloff)
  double Bias = 0;
  double Spread = 1;
  int Resolution = 64; ///< hemicube face, pixels (`--resolution`)
};

/// Read @p input (the first polydata actor, as `bake --method raycast|sattler`), bake A into
/// its points with vtkAOHemisphereBaker, write @p output (.vtp) through a temporary file. A
/// progress bar on stderr (one step per batch) and a one-line summary with the throughput
/// (vertices/s) on @p report. Throws std::runtime_error with a one-line message.
void BakeHemisphereFile(const std::string& input,
  const std::string& output,
  const HemisphereBakeOptions& options,
  std::ostream& report);
}

#endif
