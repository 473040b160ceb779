// Command-line parsing shared by the vtkao subcommands: a usage error (exit status 2) and
// numbers checked for syntax and range, each problem reported as one line naming the option.
#ifndef vtkaoOptions_h
#define vtkaoOptions_h

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vtkao
{
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
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
}

#endif
