// Image files through OpenImageIO, behind an interface free of std::string.
//
// PyPI's VTK wheels are built with the old libstdc++ string ABI (manylinux2014,
// _GLIBCXX_USE_CXX11_ABI=0), Debian's OpenImageIO with the new one, so no translation unit can
// call both with std::string arguments. This file's .cxx is the only one that includes
// OpenImageIO; it is built in its own library without VTK (the system's ABI), and everything
// that crosses takes char pointers, numbers and std::vector<float>, which both ABIs share.
#ifndef vtkaoImageFile_h
#define vtkaoImageFile_h

#include <vector>

namespace vtkao
{
/// Writes @p pixels (rows top to bottom, @p channels floats a pixel) to @p path; PNG as 8 bits
/// (values clamped, stored linear), EXR as float. Channels 2 are named Y, A. On failure returns
/// false with a message in @p error (at most @p errorSize bytes, terminated).
bool WriteImageFile(const char* path, int width, int height, int channels, const float* pixels,
  char* error, int errorSize);

/// Reads an image as floats (rows top to bottom); false with a message in @p error on failure.
bool ReadImageFile(const char* path, int* width, int* height, int* channels,
  std::vector<float>* pixels, char* error, int errorSize);
}

#endif
