// `vtkao view [INPUT ...] [options]`: an interactive window with live switching of the AO
// method and its parameters (keys: see vtkao view --help, or press ? in the window).
#ifndef vtkaoView_h
#define vtkaoView_h

#include "vtkaoOptions.h"

namespace vtkao
{
/// Bad `view` usage (unknown option, bad number, bad key in --script): a usage error (exit 2).
using ViewUsageError = InvalidUsage;

/// Run the viewer until the window is closed or q is pressed. Returns the exit code; throws
/// ViewUsageError for bad usage and std::runtime_error (one line) for other failures.
int View(int argc, char* argv[]);
}

#endif
