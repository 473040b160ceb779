// PNG and OpenEXR files without OpenImageIO: zlib only (VTKAO_IMAGE_IO=builtin, the relocatable
// tarball of scripts/make-tarball.sh). Same contract as vtkaoImageFile.h, whose functions
// forward here in that configuration; built in every configuration so that the tests can read
// its files with OpenImageIO (Testing/Cxx/vtkaoImageFileCrossCheck.cxx).
//
// Written: PNG 8 bits (grey, grey + alpha, RGB, RGBA; values clamped, stored linear with gAMA
// 1.0), OpenEXR single-part scanline float with ZIP compression (channels Y; Y, A; R, G, B;
// R, G, B, A). Read: PNG of any colour type and bit depth, palettes included, not interlaced;
// OpenEXR single-part scanline, half, float or uint pixels, uncompressed, ZIPS or ZIP. Anything
// else is refused with a one-line message. Alpha as OpenImageIO has it: pixels in memory are
// premultiplied, PNG files are not (the writer divides by alpha, the reader multiplies).
// OpenImageIO does that through the file's gamma; this code with gamma 1, which is what the
// project writes (the same values for its own files; within a few 1/255 for sRGB files).
#ifndef vtkaoImageFileBuiltin_h
#define vtkaoImageFileBuiltin_h

#include <vector>

namespace vtkao
{
/// An image to write: Width x Height pixels, rows top to bottom, Channels floats a pixel.
struct BuiltinImageView
{
  int Width = 0, Height = 0, Channels = 0;
  const float* Pixels = nullptr;
};

/// An image read: as BuiltinImageView, owning its pixels.
struct BuiltinImage
{
  int Width = 0, Height = 0, Channels = 0;
  std::vector<float> Pixels;
};

/// Where a failure's one-line message goes: at most Size bytes, terminated.
struct BuiltinError
{
  char* Text = nullptr;
  int Size = 0;
};

/// Writes @p image to @p path (.png or .exr, by its extension); false with a message in
/// @p error on failure.
bool BuiltinWriteImageFile(const char* path, const BuiltinImageView& image, BuiltinError error);

/// Reads a PNG or OpenEXR file (by its signature) into @p image; false with a message in
/// @p error on failure.
bool BuiltinReadImageFile(const char* path, BuiltinImage* image, BuiltinError error);
}

#endif
