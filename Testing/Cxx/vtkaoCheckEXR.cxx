// Checks an EXR written by `vtkao render`: size, channels, and for AO-only files (channels Y,
// A) that Y = A lies in [0, 1], some covered pixels are occluded (< 1), background is 1.
// Usage: vtkaoCheckEXR FILE WIDTH HEIGHT rgba|ao
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  if (argc != 5)
  {
    std::fprintf(stderr, "usage: vtkaoCheckEXR FILE WIDTH HEIGHT rgba|ao\n");
    return 2;
  }
  const std::string mode = argv[4];
  auto in = OIIO::ImageInput::open(argv[1]);
  if (!in)
  {
    std::fprintf(stderr, "cannot open %s: %s\n", argv[1], OIIO::geterror().c_str());
    return 1;
  }
  const OIIO::ImageSpec spec = in->spec();
  std::string names;
  for (const auto& n : spec.channelnames)
  {
    names += n + " ";
  }
  std::printf("%s: %s, %d x %d, %d channels (%s), %s\n",
    argv[1],
    in->format_name(),
    spec.width,
    spec.height,
    spec.nchannels,
    names.c_str(),
    spec.format.c_str());
  int failures = 0;
  auto check = [&](bool ok, const char* what)
  {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
    failures += ok ? 0 : 1;
  };
  check(std::string(in->format_name()) == "openexr", "the file is OpenEXR");
  check(spec.width == std::atoi(argv[2]) && spec.height == std::atoi(argv[3]), "size as requested");
  check(spec.format == OIIO::TypeDesc::FLOAT || spec.format == OIIO::TypeDesc::HALF,
    "floating-point pixels");
  const int ny = spec.channelnames.size() > 0 ? static_cast<int>(spec.channelindex("Y")) : -1;
  const int na = spec.alpha_channel >= 0 ? spec.alpha_channel : spec.channelindex("A");
  if (mode == "rgba")
  {
    check(spec.nchannels == 4 && spec.channelindex("R") >= 0 && spec.channelindex("G") >= 0 &&
        spec.channelindex("B") >= 0 && na >= 0,
      "four channels R, G, B, A");
  }
  else
  {
    check(spec.nchannels == 2 && ny >= 0 && na >= 0 && ny != na, "two channels, Y and A");
  }
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  check(
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()), "pixels read");
  in->close();
  if (failures == 0 && mode == "ao")
  {
    size_t outside = 0, covered = 0, occluded = 0, background = 0, backgroundNotOne = 0;
    double minimum = 1.0;
    for (size_t p = 0; p < pixels.size() / spec.nchannels; ++p)
    {
      const float a = pixels[p * spec.nchannels + ny];
      const float coverage = pixels[p * spec.nchannels + na];
      outside += (a < 0.0f || a > 1.0f || (coverage != 0.0f && coverage != 1.0f)) ? 1 : 0;
      if (coverage > 0.5f)
      {
        ++covered;
        occluded += a < 0.99f ? 1 : 0;
        minimum = std::min(minimum, static_cast<double>(a));
      }
      else
      {
        ++background;
        backgroundNotOne += a != 1.0f ? 1 : 0;
      }
    }
    std::printf("covered %zu, occluded (A < 0.99) %zu, background %zu, min A %.3f\n",
      covered,
      occluded,
      background,
      minimum);
    check(outside == 0, "every A in [0, 1], coverage 0 or 1");
    check(covered > 0 && occluded > 0, "some covered pixels are occluded (A < 0.99)");
    check(occluded < covered, "not every covered pixel is occluded");
    check(backgroundNotOne == 0, "background pixels carry A = 1");
  }
  std::printf("%d check(s) failed\n", failures);
  return failures ? 1 : 0;
}
