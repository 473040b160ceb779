// The checks every ambient-occlusion test reports with: one line per check ("ok" or "FAILED",
// with the measured and expected values where there are numbers), and the exit code.
#ifndef vtkAOTestChecks_h
#define vtkAOTestChecks_h

#include <cmath>
#include <cstdio>
#include <string>

namespace vtkAOTest
{
inline int Failures = 0;

inline void Check(bool condition, const std::string& what)
{
  std::printf("%s: %s\n", condition ? "ok" : "FAILED", what.c_str());
  Failures += condition ? 0 : 1;
}

/// |value - expected| <= tolerance, reported with the numbers.
inline void CheckNear(double value, double expected, double tolerance, const std::string& what)
{
  const bool ok = std::isfinite(value) && std::fabs(value - expected) <= tolerance;
  std::printf("%s: %s: %.5f (expected %.5f +- %.4f)\n",
    ok ? "ok" : "FAILED",
    what.c_str(),
    value,
    expected,
    tolerance);
  Failures += ok ? 0 : 1;
}

/// The exit code: prints the number of failed checks, non-zero when there is one.
inline int Result()
{
  std::printf("%d check(s) failed\n", Failures);
  return Failures ? 1 : 0;
}
}

#endif
