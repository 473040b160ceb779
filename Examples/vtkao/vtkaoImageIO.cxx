#include "vtkaoImageIO.h"

#include "vtkaoImageFile.h"

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
  const bool png = ext == ".png";
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
  char error[512] = "";
  const bool written = WriteImageFile(temporary.c_str(), image.Width, image.Height,
    image.Channels, rows.data(), error, sizeof(error));
  if (!written || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw std::runtime_error(
      "cannot write '" + path + "'" + (error[0] ? std::string(": ") + error : std::string()));
  }
}
}
