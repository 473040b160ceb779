// vtkaoImageFile.h without OpenImageIO (VTKAO_IMAGE_IO=builtin): vtkaoImageFileBuiltin.h.
#include "vtkaoImageFile.h"
#include "vtkaoImageFileBuiltin.h"

namespace vtkao
{
bool WriteImageFile(const char* path,
  int width,
  int height,
  int channels,
  const float* pixels,
  char* error,
  int errorSize)
{
  return BuiltinWriteImageFile(
    path, BuiltinImageView{ width, height, channels, pixels }, BuiltinError{ error, errorSize });
}

bool ReadImageFile(const char* path,
  int* width,
  int* height,
  int* channels,
  std::vector<float>* pixels,
  char* error,
  int errorSize)
{
  BuiltinImage image;
  if (!BuiltinReadImageFile(path, &image, BuiltinError{ error, errorSize }))
  {
    return false;
  }
  *width = image.Width;
  *height = image.Height;
  *channels = image.Channels;
  pixels->swap(image.Pixels);
  return true;
}
}
