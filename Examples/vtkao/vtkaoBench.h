// vtkao bench: frame times, stage times and GPU memory of no AO, vtkSSAOPass and HAO, in one
// process.
#ifndef vtkaoBench_h
#define vtkaoBench_h

namespace vtkao
{
/// vtkao bench [--quick] [--frames N] [--size WxH] [--series LIST] [--output-json F]
/// [--output-md F] [--plots DIR] (Documentation/benchmark.md).
/// Throws std::invalid_argument on bad usage, std::runtime_error on other failures.
int Bench(int argc, char* argv[]);
}

#endif
