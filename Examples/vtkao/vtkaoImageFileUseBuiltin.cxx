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
  return BuiltinWriteImageFile(path, width, height, channels, pixels, error, errorSize);
}

bool ReadImageFile(const char* path,
  int* width,
  int* height,
  int* channels,
  std::vector<float>* pixels,
  char* error,
  int errorSize)
{
  return BuiltinReadImageFile(path, width, height, channels, pixels, error, errorSize);
}
}
