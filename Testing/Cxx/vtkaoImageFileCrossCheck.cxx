// The builtin PNG and EXR reader and writer (Examples/vtkao/vtkaoImageFileBuiltin.h): its own
// round trip for 1 to 4 channels, and, when built with OpenImageIO (VTKAO_HAS_OIIO), its files
// read by OpenImageIO and OpenImageIO's files (EXR: float and half; none, ZIPS and ZIP; PNG: 8
// and 16 bits) read by it, the channels in the same order. Anything it cannot read (EXR PIZ)
// must fail with a message. Usage: vtkaoImageFileCrossCheck WORK_DIR
#include "vtkaoImageFileBuiltin.h"

#ifdef VTKAO_HAS_OIIO
#include <OpenImageIO/imageio.h>
#endif

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  Failures += ok ? 0 : 1;
}

const int W = 37, H = 21;

// A pattern with every byte value on PNG's path; EXR's also goes outside [0, 1].
std::vector<float> Pattern(int channels, bool exr)
{
  std::vector<float> p(static_cast<size_t>(W) * H * channels);
  for (size_t i = 0; i < p.size(); ++i)
  {
    p[i] = static_cast<float>((i * 37 + (i / W) * 11) % 256) / 255.0f;
    if (exr && i % 17 == 0)
    {
      p[i] = static_cast<float>(i) * -0.03125f + 0.1f;
    }
  }
  return p;
}

double MaxDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size())
  {
    return 1e30;
  }
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    d = std::max(d, std::fabs(static_cast<double>(a[i]) - b[i]));
  }
  return d;
}

bool ReadBuiltin(const std::string& path, int channels, std::vector<float>* pixels)
{
  char error[256] = "";
  vtkao::BuiltinImage image;
  const bool ok = vtkao::BuiltinReadImageFile(path.c_str(), &image, { error, 256 });
  if (!ok)
  {
    std::printf("  %s: %s\n", path.c_str(), error);
  }
  pixels->swap(image.Pixels);
  return ok && image.Width == W && image.Height == H && image.Channels == channels;
}

#ifdef VTKAO_HAS_OIIO
const char* Names[5] = { "", "Y", "Y A", "R G B", "R G B A" };

bool ReadOIIO(const std::string& path, int channels, std::vector<float>* pixels)
{
  auto in = OIIO::ImageInput::open(path);
  if (!in)
  {
    std::printf("  OpenImageIO: %s\n", OIIO::geterror().c_str());
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  std::string names;
  for (const auto& n : spec.channelnames)
  {
    names += (names.empty() ? "" : " ") + n;
  }
  pixels->resize(static_cast<size_t>(W) * H * channels);
  const bool ok = spec.width == W && spec.height == H && spec.nchannels == channels &&
    in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels->data());
  std::printf(
    "  OpenImageIO reads %s: %s, channels %s\n", path.c_str(), in->format_name(), names.c_str());
  // PNG has no channel names; OpenImageIO names them R, G, B, A or Y, A.
  return ok && (path.find(".exr") == std::string::npos || names == Names[channels]);
}

bool WriteOIIO(const std::string& path,
  int channels,
  const std::vector<float>& pixels,
  OIIO::TypeDesc type,
  const char* compression)
{
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(W, H, channels, type);
  if (channels == 2)
  {
    spec.channelnames = { "Y", "A" };
    spec.alpha_channel = 1;
  }
  if (compression)
  {
    spec.attribute("compression", compression);
  }
  else
  {
    spec.attribute("oiio:ColorSpace", "Linear"); // as vtkaoImageFile.cxx writes PNG
  }
  return out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) &&
    out->close();
}
#endif
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: vtkaoImageFileCrossCheck WORK_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  for (int channels = 1; channels <= 4; ++channels)
  {
    for (const char* ext : { ".png", ".exr" })
    {
      const bool exr = std::string(ext) == ".exr";
      const std::string c = std::to_string(channels);
      const std::string path = dir + "/builtin-" + c + ext;
      const std::vector<float> pattern = Pattern(channels, exr);
      // PNG with alpha: premultiplied in memory, not in the file (as OpenImageIO has it), so the
      // values come back from bytes of colour / alpha times alpha.
      const bool alpha = channels % 2 == 0;
      std::vector<float> expected = pattern;
      for (size_t i = 0; i < expected.size() && !exr; ++i)
      {
        const float a = pattern[i - i % channels + channels - 1];
        const bool colour = alpha && i % channels != size_t(channels - 1);
        const float v = colour && a != 0.0f ? pattern[i] / a : pattern[i];
        expected[i] = std::round(std::min(1.0f, std::max(0.0f, v)) * 255.0f) / 255.0f;
        expected[i] *= colour ? std::round(a * 255.0f) / 255.0f : 1.0f;
      }
      // OpenImageIO premultiplies 8-bit PNG in bytes (truncating), this code in floats.
      const double tolerance = exr ? 1e-6 : alpha ? 1.0 / 255.0 + 1e-6 : 1e-6;
      char error[256] = "";
      Check(vtkao::BuiltinWriteImageFile(
              path.c_str(), { W, H, channels, pattern.data() }, { error, 256 }),
        "builtin writes " + path + (error[0] ? std::string(": ") + error : std::string()));
      std::vector<float> back;
      Check(ReadBuiltin(path, channels, &back) && MaxDifference(back, expected) < 1e-5,
        "builtin reads back " + path);
#ifdef VTKAO_HAS_OIIO
      Check(ReadOIIO(path, channels, &back) && MaxDifference(back, expected) < tolerance,
        "OpenImageIO reads " + path);
      struct Variant
      {
        OIIO::TypeDesc Type;
        const char* Compression;
        const char* Name;
      };
      const std::vector<Variant> variants = exr
        ? std::vector<Variant>{ { OIIO::TypeDesc::FLOAT, "none", "float-none" },
            { OIIO::TypeDesc::FLOAT, "zips", "float-zips" },
            { OIIO::TypeDesc::FLOAT, "zip", "float-zip" },
            { OIIO::TypeDesc::HALF, "zip", "half-zip" } }
        : std::vector<Variant>{ { OIIO::TypeDesc::UINT8, nullptr, "8bit" },
            { OIIO::TypeDesc::UINT16, nullptr, "16bit" } };
      for (const Variant& v : variants)
      {
        const std::string other = dir + "/oiio-" + c + "-" + v.Name + ext;
        Check(WriteOIIO(other, channels, pattern, v.Type, v.Compression),
          "OpenImageIO writes " + other);
        std::vector<float> oiio, builtin;
        const bool both =
          ReadOIIO(other, channels, &oiio) && ReadBuiltin(other, channels, &builtin);
        Check(both && MaxDifference(oiio, builtin) < tolerance,
          "builtin reads " + other + " as OpenImageIO does");
      }
      if (exr)
      {
        const std::string piz = dir + "/oiio-" + c + "-piz.exr";
        vtkao::BuiltinImage ignored;
        const bool refused = WriteOIIO(piz, channels, pattern, OIIO::TypeDesc::FLOAT, "piz") &&
          !vtkao::BuiltinReadImageFile(piz.c_str(), &ignored, { error, 256 });
        Check(refused && std::string(error).find("PIZ") != std::string::npos,
          std::string("builtin refuses PIZ with a message: ") + error);
      }
#endif
    }
  }
  std::printf("%d failure(s)\n", Failures);
  return Failures ? 1 : 0;
}
