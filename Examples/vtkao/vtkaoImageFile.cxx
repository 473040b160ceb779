#include "vtkaoImageFile.h"

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <string>

namespace vtkao
{
namespace
{
bool Fail(const std::string& message, char* error, int errorSize)
{
  if (error && errorSize > 0)
  {
    std::strncpy(error, message.c_str(), static_cast<size_t>(errorSize) - 1);
    error[errorSize - 1] = '\0';
  }
  return false;
}

bool EndsWith(const std::string& s, const char* suffix)
{
  const size_t n = std::strlen(suffix);
  if (s.size() < n)
  {
    return false;
  }
  for (size_t i = 0; i < n; ++i)
  {
    if (std::tolower(static_cast<unsigned char>(s[s.size() - n + i])) != suffix[i])
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool WriteImageFile(const char* path, int width, int height, int channels, const float* pixels,
  char* error, int errorSize)
{
  const std::string file = path;
  auto out = OIIO::ImageOutput::create(file);
  if (!out)
  {
    return Fail("cannot create an image writer", error, errorSize);
  }
  const bool png = EndsWith(file, ".png");
  OIIO::ImageSpec spec(width, height, channels, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (channels == 2)
  {
    spec.channelnames = { "Y", "A" };
    spec.alpha_channel = 1;
  }
  if (png)
  {
    // Linear values, stored as they are: no sRGB curve (ao-definition.md).
    spec.attribute("oiio:ColorSpace", "Linear");
  }
  if (!out->open(file, spec))
  {
    return Fail(out->geterror(), error, errorSize);
  }
  const bool written = out->write_image(OIIO::TypeDesc::FLOAT, pixels);
  const std::string message = written ? std::string() : out->geterror();
  const bool closed = out->close();
  if (!written || !closed)
  {
    return Fail(message.empty() ? "write failed" : message, error, errorSize);
  }
  return true;
}

//------------------------------------------------------------------------------
bool ReadImageFile(const char* path, int* width, int* height, int* channels,
  std::vector<float>* pixels, char* error, int errorSize)
{
  auto in = OIIO::ImageInput::open(std::string(path));
  if (!in)
  {
    return Fail(OIIO::geterror(), error, errorSize);
  }
  const OIIO::ImageSpec& spec = in->spec();
  *width = spec.width;
  *height = spec.height;
  *channels = spec.nchannels;
  pixels->assign(static_cast<size_t>(spec.width) * spec.height * spec.nchannels, 0.0f);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels->data()))
  {
    const std::string message = in->geterror();
    in->close();
    return Fail(message.empty() ? "read failed" : message, error, errorSize);
  }
  in->close();
  return true;
}
}
