// libFuzzer target: the option parser of one vtkao subcommand (chosen at compile time, see
// CMakeLists.txt). The input is a command line: the arguments after the subcommand, separated
// by NUL bytes. Nothing is rendered and no window is opened.
//
// What counts as a finding (besides AddressSanitizer/UndefinedBehaviorSanitizer reports and
// crashes): any exception other than the subcommand's usage error (or, where the program goes on
// to touch files, std::runtime_error), and an error message that is empty or not one line.
//
// Arguments equal to --help or -h are dropped: those parsers print the usage and call
// std::exit(0), which libFuzzer would report as the target exiting.
#include "FuzzCommon.h"

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(VTKAO_FUZZ_RENDER) || defined(VTKAO_FUZZ_COMPARE) || defined(VTKAO_FUZZ_BAKE)
// ParseRenderOptions and Bake are in the program's anonymous namespace: compile it here.
#define main vtkaoProgramMain
#include "vtkao.cxx"
#undef main
#elif defined(VTKAO_FUZZ_VIEW)
#include "vtkaoView.cxx"
#elif defined(VTKAO_FUZZ_BENCH)
#include "vtkaoBench.cxx"
#elif defined(VTKAO_FUZZ_QUALITY)
#include "vtkaoQuality.cxx"
#else
#error "define one of VTKAO_FUZZ_RENDER, _COMPARE, _BAKE, _VIEW, _BENCH, _QUALITY"
#endif

#if defined(VTKAO_FUZZ_COMPARE)
#include "vtkaoCompare.h"
#include "vtkaoImageIO.h"
#endif

#include <unistd.h>

namespace
{
#if defined(VTKAO_FUZZ_COMPARE)
// A panel too large to stand in for cheaply (the real render would draw it).
struct TooLarge
{
};

// The stand-in for the program's Render: the real option parser (as Render starts with it),
// the inputs as missing files (the scratch directory is empty), then a flat image of the
// requested size and channels written with the program's own writer instead of a rendering.
int FakeRender(int argc, char* argv[], int& rendered)
{
  const Options o = ParseRenderOptions(argc, argv);
  if (!o.Inputs.empty())
  {
    throw std::runtime_error("cannot read input file '" + o.Inputs.front() + "'");
  }
  if (static_cast<long long>(o.Width) * o.Height > 64 * 64)
  {
    throw TooLarge();
  }
  vtkao::FloatImage image;
  image.Width = o.Width;
  image.Height = o.Height;
  image.Channels = o.Pass.AOOnly ? 2 : 4;
  image.Pixels.assign(static_cast<size_t>(image.Width) * image.Height * image.Channels, 0.5f);
  vtkao::WriteImage(image, o.Output);
  ++rendered;
  return 0;
}
#endif
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
#if defined(VTKAO_FUZZ_COMPARE) || defined(VTKAO_FUZZ_BAKE)
  // These go on to touch files named by the arguments: work in an empty private directory
  // (arguments containing '/' are skipped below). Give libFuzzer absolute paths.
  if (chdir(vtkaoFuzz::ScratchDirectory().c_str()) != 0)
  {
    std::perror("vtkao fuzz: chdir");
    std::abort();
  }
#endif
  // The parsers write nothing on success; the compare report goes to std::cout.
  std::cout.setstate(std::ios::badbit);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  std::vector<std::string> args;
  for (auto& a : vtkaoFuzz::Arguments(data, size))
  {
    if (a != "--help" && a != "-h")
    {
      args.push_back(a);
    }
  }
#if defined(VTKAO_FUZZ_COMPARE) || defined(VTKAO_FUZZ_BAKE)
  if (vtkaoFuzz::AnyContains(args, '/'))
  {
    return -1; // stays inside the scratch directory; not added to the corpus
  }
#endif
  const bool newline = vtkaoFuzz::AnyContains(args, '\n');
  std::vector<char*> argv = vtkaoFuzz::Argv(args);
  const int argc = static_cast<int>(args.size());
  try
  {
#if defined(VTKAO_FUZZ_RENDER)
    ParseRenderOptions(argc, argv.data());
#elif defined(VTKAO_FUZZ_BAKE)
    Bake(argc, argv.data());
    vtkaoFuzz::Fail("bake succeeded in an empty directory");
#elif defined(VTKAO_FUZZ_VIEW)
    vtkao::ParseViewOptions(argc, argv.data());
#elif defined(VTKAO_FUZZ_BENCH)
    ParseBenchOptions(argc, argv.data());
#elif defined(VTKAO_FUZZ_QUALITY)
    Parse(argc, argv.data());
#elif defined(VTKAO_FUZZ_COMPARE)
    // As main does: --compare anywhere makes it a comparison.
    if (vtkao::HasCompare(argc, argv.data()))
    {
      int rendered = 0;
      try
      {
        vtkao::RenderComparison(argc,
          argv.data(),
          { "none", "ssao", "hao", "aov", "reference" },
          [&](int n, char* v[]) { return FakeRender(n, v, rendered); });
      }
      catch (const TooLarge&)
      {
      }
      catch (const vtkao::CompareUsageError& e)
      {
        vtkaoFuzz::CheckMessage("compare usage error", e.what(), newline);
      }
      catch (const UsageError& e)
      {
        vtkaoFuzz::CheckMessage("render usage error", e.what(), newline);
      }
      catch (const std::runtime_error& e)
      {
        const std::string message = e.what();
        vtkaoFuzz::CheckMessage("compare error", message, newline);
        // Every panel was rendered as asked, yet the comparison failed on its own panels.
        if (rendered > 0 && message.rfind("cannot read the panel", 0) == 0)
        {
          vtkaoFuzz::Fail("compare rejected the panels the render wrote: " + message);
        }
      }
      vtkaoFuzz::EmptyDirectory(".");
    }
    else
    {
      ParseRenderOptions(argc, argv.data());
    }
#endif
  }
#if defined(VTKAO_FUZZ_VIEW)
  catch (const vtkao::ViewUsageError& e)
  {
    vtkaoFuzz::CheckMessage("view usage error", e.what(), newline);
  }
#elif defined(VTKAO_FUZZ_BENCH)
  // bench's usage errors are std::invalid_argument (main turns them into exit status 2).
  catch (const std::invalid_argument& e)
  {
    vtkaoFuzz::CheckMessage("bench usage error", e.what(), newline);
  }
#else
  catch (const UsageError& e)
  {
    vtkaoFuzz::CheckMessage("usage error", e.what(), newline);
  }
#endif
#if defined(VTKAO_FUZZ_BAKE)
  catch (const std::runtime_error& e)
  {
    // The INPUT cannot be read (the directory is empty): the one-line message of AddFile.
    vtkaoFuzz::CheckMessage("bake input error", e.what(), newline);
  }
#endif
  catch (const std::exception& e)
  {
    vtkaoFuzz::Fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}
