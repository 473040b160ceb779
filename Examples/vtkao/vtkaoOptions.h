// Command-line parsing shared by the vtkao subcommands: a usage error (exit status 2) and
// numbers checked for syntax and range, each problem reported as one line naming the option;
// and the settings of the AO passes that `vtkao render` and `vtkao quality` both take, with
// their parsers and the code that hands them to a pass.
#ifndef vtkaoOptions_h
#define vtkaoOptions_h

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

class vtkAmbientOcclusionVolumesPass;
class vtkHybridAmbientOcclusionPass;

namespace vtkao
{
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Bad usage of `render --compare` and `view` (an unknown option or method, a bad number or
/// key): they throw it as a std::invalid_argument, which main turns into a UsageError.
struct InvalidUsage : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// @p text as a finite number in [lo, hi], or a UsageError naming @p option.
inline double ParseNumber(const std::string& option, const std::string& text, double lo, double hi)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
  {
    throw UsageError(option + ": '" + text + "' is not a number");
  }
  if (v < lo || v > hi)
  {
    std::ostringstream msg;
    msg << option << ": " << text << " is out of range [" << lo << ", " << hi << "]";
    throw UsageError(msg.str());
  }
  return v;
}

/// @p text as a whole number in [lo, hi], or a UsageError naming @p option.
inline int ParseInt(const std::string& option, const std::string& text, int lo, int hi)
{
  const double v = ParseNumber(option, text, lo, hi);
  if (v != std::floor(v))
  {
    throw UsageError(option + ": '" + text + "' is not a whole number");
  }
  return static_cast<int>(v);
}

/// @p text must be one of @p choices; the message names @p what and lists them.
inline std::string ParseChoice(const std::string& option,
  const std::string& what,
  const std::string& text,
  const std::vector<std::string>& choices)
{
  if (std::find(choices.begin(), choices.end(), text) != choices.end())
  {
    return text;
  }
  std::string expected;
  for (size_t i = 0; i < choices.size(); ++i)
  {
    expected += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  }
  throw UsageError(option + ": unknown " + what + " '" + text + "' (expected " + expected + ")");
}

/// --aov-combine add|multiply as vtkAmbientOcclusionVolumesPass's Combination (ADDITIVE 0,
/// MULTIPLICATIVE 1), or a UsageError.
inline int ParseAOVCombination(const std::string& text)
{
  if (text != "add" && text != "multiply")
  {
    throw UsageError(
      "--aov-combine: unknown combination '" + text + "' (expected add or multiply)");
  }
  return text == "multiply" ? 1 : 0;
}

/// --size WxH: @p width and @p height, each a whole number in [lo, hi].
inline void ParseSize(const std::string& text, int lo, int hi, int& width, int& height)
{
  const auto x = text.find('x');
  if (x == std::string::npos)
  {
    throw UsageError("--size: expected WxH, got '" + text + "'");
  }
  width = ParseInt("--size", text.substr(0, x), lo, hi);
  height = ParseInt("--size", text.substr(x + 1), lo, hi);
}

/// The parsers of the options that take a value, by option name.
using OptionParsers = std::map<std::string, std::function<void(const std::string&)>>;

/// Reads the arguments in order: --help or -h prints @p usage and exits (status 0); an option
/// of @p parsers is handed the argument after it (a UsageError when there is none); any other
/// argument is handed to @p other (flags, inputs; it throws for the unknown ones).
inline void ParseArguments(int argc,
  char* argv[],
  const char* usage,
  const OptionParsers& parsers,
  const std::function<void(const std::string&)>& other)
{
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto parser = parsers.find(arg);
    if (arg == "--help" || arg == "-h")
    {
      std::cout << usage;
      std::exit(0);
    }
    else if (parser != parsers.end())
    {
      if (i + 1 >= argc)
      {
        throw UsageError(arg + ": missing value");
      }
      parser->second(argv[++i]);
    }
    else
    {
      other(arg);
    }
  }
}

/// The settings of HAO and AOV that `vtkao render` and `vtkao quality` share. The defaults are
/// HAO's (AOV has its own scale and filter size: see AOScaleGiven and FilterSizeGiven).
struct PassSettings
{
  double Radius = 0; ///< 0: the pass's automatic radius
  double Bias = 0;
  double Spread = 1;
  double Intensity = 1;
  bool BinaryFalloff = false;
  int Rays = 8, Steps = 4, VoxelResolution = 0, VoxelAxes = 3;
  int Cascades = 0, CascadeResolution = 0, DenseLimit = 0; ///< 0: the pass's defaults
  int AOScale = 3, FilterSize = 16;
  bool AOScaleGiven = false, FilterSizeGiven = false; ///< on the command line
  bool Filter = true;
  bool Refine = true;
  bool RefineList = true;     ///< false: --refine-in-place
  int RefineRays = 0;         ///< 0: as many as NumberOfRays
  int RefineFilter = 2;       ///< the refinement filter's radius in pixels (0: off)
  double RefineContrast = 0;  ///< the refinement's marking contrast (0: automatic)
  double CellErosion = 0.25;  ///< cells the grid's exposed faces are moved in (0: off)
  double CellsPerRadius = 64; ///< the automatic grid's cells per occlusion radius
  std::string Region = "scene";
  int AOVCombination = -1; ///< --aov-combine; -1: the pass's default
  bool AOOnly = false;
};

/// Sets the fields of @p s that vtkHybridAmbientOcclusionPass::ApplyPreset sets, to the preset
/// @p name (interactive, balanced or quality; a UsageError otherwise). Options after --preset
/// on the command line override it.
void ApplyPreset(PassSettings& s, const std::string& name);

/// Adds to @p parsers the options both subcommands take that set @p s: --preset, --bias, --falloff,
/// --rays, --steps, --voxel-resolution, --voxel-axes, --cascades, --cascade-resolution,
/// --dense-limit, --ao-scale, --filter-size, --region and --aov-combine. @p s must outlive the
/// parsers.
void AddPassOptionParsers(OptionParsers& parsers, PassSettings& s);

/// The flags without a value both subcommands take (--no-filter, --no-refine,
/// --refine-in-place): whether @p arg is one of them (then @p s is set).
bool ParsePassFlag(const std::string& arg, PassSettings& s);

/// Sets every setting of @p s on @p hao (the radius, the cascades' resolution and the dense
/// limit only where they are given).
void ApplySettings(const PassSettings& s, vtkHybridAmbientOcclusionPass* hao);

/// Sets the radius, bias, intensity, falloff, AOOnly and (where given) the combination of @p s
/// on @p aov.
void ApplySettings(const PassSettings& s, vtkAmbientOcclusionVolumesPass* aov);
}

#endif
