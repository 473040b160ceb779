// vtkao bench: frame times of no AO, vtkSSAOPass and HAO on the built-in scene, in one process.
#ifndef vtkaoBench_h
#define vtkaoBench_h

namespace vtkao
{
/// vtkao bench [--quick] [--frames N] [--size WxH] [--output-json F] [--output-md F].
/// Throws std::invalid_argument on bad usage, std::runtime_error on other failures.
int Bench(int argc, char* argv[]);
}

#endif
