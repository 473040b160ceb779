// The checks every ambient-occlusion test reports with: one line per check ("ok" or "FAILED",
// with the measured and expected values where there are numbers), the exit code, and a record
// of an algorithm's progress events.
#ifndef vtkAOTestChecks_h
#define vtkAOTestChecks_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

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

/// The progress events of an object: how many, the first and the last value.
struct ProgressLog
{
  int Events = 0;
  double First = -1.0;
  double Last = -1.0;

  void Watch(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> progress;
    progress->SetClientData(this);
    progress->SetCallback(
      [](vtkObject*, unsigned long, void* client, void* data)
      {
        auto* log = static_cast<ProgressLog*>(client);
        const double value = *static_cast<double*>(data);
        log->First = log->Events == 0 ? value : log->First;
        ++log->Events;
        log->Last = value;
      });
    object->AddObserver(vtkCommand::ProgressEvent, progress);
  }

  /// From 0 to 1 in at least @p least events.
  bool RanFromZeroToOne(int least) const
  {
    return this->Events >= least && this->First == 0.0 && this->Last == 1.0;
  }

  std::string Describe() const
  {
    return std::to_string(this->Events) + " events from " + std::to_string(this->First) +
      " to " + std::to_string(this->Last);
  }
};

/// The exit code: prints the number of failed checks, non-zero when there is one.
inline int Result()
{
  std::printf("%d check(s) failed\n", Failures);
  return Failures ? 1 : 0;
}
}

#endif
