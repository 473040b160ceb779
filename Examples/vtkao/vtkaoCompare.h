// `vtkao render --compare none,ssao,hao[,aov,reference] --output grid.png`: the methods side by
// side in one labelled image, every panel from the same camera and options.
#ifndef vtkaoCompare_h
#define vtkaoCompare_h

#include "vtkaoOptions.h"

#include <functional>
#include <string>
#include <vector>

namespace vtkao
{
/// Bad --compare usage (unknown method, duplicate, unsupported option): the caller turns it
/// into a usage error (exit 2).
using CompareUsageError = InvalidUsage;

/// Whether the arguments of `render` ask for a comparison (contain --compare).
bool HasCompare(int argc, char* argv[]);

/// Render one image: the program's own `render` with these arguments (which include
/// --method M and --output FILE.png). Returns the exit code; throws on errors.
using RenderFunction = std::function<int(int argc, char* argv[])>;

/// Run the comparison: parse and strip --compare LIST and --output FILE, render each method
/// with @p render and otherwise unchanged arguments into a temporary PNG beside the output,
/// compose the panels in a grid with a label on each, write FILE (.png) through a temporary
/// name and remove the panels. @p available lists the method names the program supports.
/// Throws CompareUsageError for bad usage, std::runtime_error for other failures; no partial
/// or temporary file is left behind either way.
int RenderComparison(int argc,
  char* argv[],
  const std::vector<std::string>& available,
  const RenderFunction& render);
}

#endif
