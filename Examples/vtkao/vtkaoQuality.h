// `vtkao quality` (issue 3): each method's A against the ray-traced reference, per scene.
#ifndef vtkaoQuality_h
#define vtkaoQuality_h

namespace vtkao
{
/// Run `vtkao quality` with the arguments after the subcommand. Writes quality.md,
/// quality.json and error maps to the output directory. Returns the exit code: 0, 2 for a
/// usage error (one line on stderr), 3 when a --max-hao-* check fails. Throws
/// std::runtime_error for other failures.
int Quality(int argc, char* argv[]);
}

#endif
