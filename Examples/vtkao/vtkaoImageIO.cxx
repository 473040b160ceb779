#include "vtkaoImageIO.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>

namespace vtkao
{
namespace
{
std::string Extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot);
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}
}

//------------------------------------------------------------------------------
bool IsSupportedImagePath(const std::string& path)
{
  const std::string ext = Extension(path);
  return ext == ".png" || ext == ".exr";
}

//------------------------------------------------------------------------------
void WriteImage(const FloatImage& image, const std::string& path)
{
  const std::string ext = Extension(path);
  if (!IsSupportedImagePath(path))
  {
    throw std::runtime_error("unsupported output format '" + ext + "' (expected .png or .exr)");
  }
  const std::string temporary = path + ".partial" + ext;
  auto out = OIIO::ImageOutput::create(temporary);
  if (!out)
  {
    throw std::runtime_error("cannot create an image writer for '" + path + "'");
  }
  const bool png = ext == ".png";
  OIIO::ImageSpec spec(
    image.Width, image.Height, image.Channels, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (image.Channels == 2)
  {
    spec.channelnames = { "Y", "A" };
    spec.alpha_channel = 1;
  }
  if (png)
  {
    // Linear values, stored as they are: no sRGB curve (ao-definition.md).
    spec.attribute("oiio:ColorSpace", "Linear");
  }
  if (!out->open(temporary, spec))
  {
    throw std::runtime_error("cannot open '" + path + "' for writing: " + out->geterror());
  }
  // Flip to top-down rows while converting.
  std::vector<float> rows(image.Pixels.size());
  const size_t stride = static_cast<size_t>(image.Width) * image.Channels;
  for (int y = 0; y < image.Height; ++y)
  {
    std::copy_n(&image.Pixels[static_cast<size_t>(y) * stride],
      stride,
      &rows[static_cast<size_t>(image.Height - 1 - y) * stride]);
  }
  if (png)
  {
    for (float& v : rows)
    {
      v = std::min(1.0f, std::max(0.0f, v));
    }
  }
  const bool written = out->write_image(OIIO::TypeDesc::FLOAT, rows.data());
  const std::string error = written ? std::string() : out->geterror();
  const bool closed = out->close();
  if (!written || !closed || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "'" + (error.empty() ? "" : ": " + error));
  }
}
}
