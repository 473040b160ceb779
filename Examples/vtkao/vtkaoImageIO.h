// Image output for the vtkao program. Files are written to a temporary name beside the
// target and renamed when complete, so a failure never leaves a partial file.
#ifndef vtkaoImageIO_h
#define vtkaoImageIO_h

#include <string>
#include <vector>

namespace vtkao
{
/// A float image, rows bottom-up (OpenGL order), @p channels interleaved per pixel.
struct FloatImage
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  std::vector<float> Pixels;
};

/// Write @p image to @p path (.png: 8-bit, values clamped to [0, 1]; .exr: 32-bit float).
/// Throws std::runtime_error with a one-line message.
void WriteImage(const FloatImage& image, const std::string& path);

/// Whether @p path names a format WriteImage supports.
bool IsSupportedImagePath(const std::string& path);
}

#endif
