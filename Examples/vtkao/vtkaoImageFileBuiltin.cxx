#include "vtkaoImageFileBuiltin.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

namespace vtkao
{
namespace
{
using Bytes = std::vector<unsigned char>;

// The largest image either reader accepts (pixels times channels): a corrupt size field must
// give a message, not a failed allocation.
const uint64_t MaximumSamples = uint64_t(1) << 30;

bool Fail(const std::string& message, BuiltinError error)
{
  if (error.Text && error.Size > 0)
  {
    std::strncpy(error.Text, message.c_str(), static_cast<size_t>(error.Size) - 1);
    error.Text[error.Size - 1] = '\0';
  }
  return false;
}

std::string LowerExtension(const char* path)
{
  const char* dot = std::strrchr(path, '.');
  std::string ext = dot ? dot : "";
  for (char& c : ext)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return ext;
}

bool WriteFile(const char* path, const Bytes& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  return static_cast<bool>(out);
}

bool ReadFile(const char* path, Bytes* bytes)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return false;
  }
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

void PutBE32(Bytes& b, uint32_t v)
{
  for (int s = 24; s >= 0; s -= 8)
  {
    b.push_back(static_cast<unsigned char>(v >> s));
  }
}

uint32_t GetBE32(const unsigned char* p)
{
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3];
}

void PutLE32(Bytes& b, uint32_t v)
{
  for (int s = 0; s < 32; s += 8)
  {
    b.push_back(static_cast<unsigned char>(v >> s));
  }
}

void PutLE64(Bytes& b, uint64_t v)
{
  for (int s = 0; s < 64; s += 8)
  {
    b.push_back(static_cast<unsigned char>(v >> s));
  }
}

uint32_t GetLE32(const unsigned char* p)
{
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

uint64_t GetLE64(const unsigned char* p)
{
  return uint64_t(GetLE32(p)) | (uint64_t(GetLE32(p + 4)) << 32);
}

uint32_t FloatBits(float f)
{
  uint32_t u;
  std::memcpy(&u, &f, sizeof(u));
  return u;
}

float BitsFloat(uint32_t u)
{
  float f;
  std::memcpy(&f, &u, sizeof(f));
  return f;
}

float HalfToFloat(uint16_t h)
{
  const int sign = (h >> 15) & 1, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  float value;
  if (exponent == 0)
  {
    value = std::ldexp(static_cast<float>(mantissa), -24);
  }
  else if (exponent == 31)
  {
    value = mantissa ? std::nanf("") : HUGE_VALF;
  }
  else
  {
    value = std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
  }
  return sign ? -value : value;
}

// Inflates a zlib stream of exactly @p size bytes.
bool Inflate(const unsigned char* data, size_t length, size_t size, Bytes* out)
{
  out->assign(size, 0);
  z_stream z{};
  if (inflateInit(&z) != Z_OK)
  {
    return false;
  }
  z.next_in = const_cast<unsigned char*>(data);
  z.avail_in = static_cast<uInt>(length);
  z.next_out = out->data();
  z.avail_out = static_cast<uInt>(size);
  const int status = inflate(&z, Z_FINISH);
  const bool complete = status == Z_STREAM_END && z.total_out == size;
  inflateEnd(&z);
  return complete;
}

bool Deflate(const Bytes& raw, Bytes* out)
{
  uLongf length = compressBound(static_cast<uLong>(raw.size()));
  out->resize(length);
  if (compress2(out->data(), &length, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
  {
    return false;
  }
  out->resize(length);
  return true;
}

//------------------------------------------------------------------------------
// PNG (ISO/IEC 15948): IHDR, gAMA, IDAT, IEND; each row filtered with the filter whose bytes
// have the smallest sum of magnitudes (the usual heuristic).
unsigned char Paeth(int a, int b, int c)
{
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return static_cast<unsigned char>(pa <= pb && pa <= pc ? a : (pb <= pc ? b : c));
}

void PutChunk(Bytes& png, const char* type, const Bytes& data)
{
  PutBE32(png, static_cast<uint32_t>(data.size()));
  const size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  PutBE32(
    png, static_cast<uint32_t>(crc32(0L, &png[start], static_cast<uInt>(png.size() - start))));
}

// PNG's filter types 0-4: the value a row's byte is stored relative to, from its left (a),
// upper (b) and upper-left (c) neighbours.
int Predictor(int type, int a, int b, int c)
{
  switch (type)
  {
    case 1:
      return a;
    case 2:
      return b;
    case 3:
      return (a + b) / 2;
    case 4:
      return Paeth(a, b, c);
    default:
      return 0;
  }
}

const unsigned char PngSignature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };

bool WritePNG(const char* path, const BuiltinImageView& image, BuiltinError error)
{
  const int width = image.Width, height = image.Height, channels = image.Channels;
  const float* pixels = image.Pixels;
  static const unsigned char colourTypes[5] = { 0, 0, 4, 2, 6 };
  const size_t rowBytes = static_cast<size_t>(width) * channels;
  Bytes filtered;
  filtered.reserve((rowBytes + 1) * height);
  Bytes previous(rowBytes, 0), row(rowBytes), candidate(rowBytes), best(rowBytes);
  for (int y = 0; y < height; ++y)
  {
    const float* source = pixels + static_cast<size_t>(y) * rowBytes;
    const bool alpha = channels == 2 || channels == 4;
    for (size_t i = 0; i < rowBytes; ++i)
    {
      float v = source[i];
      // Premultiplied in memory, not in the file, as OpenImageIO does (gamma 1).
      const float a = source[i - i % channels + channels - 1];
      if (alpha && i % channels != size_t(channels - 1) && a != 0.0f)
      {
        v /= a;
      }
      v = std::min(1.0f, std::max(0.0f, v == v ? v : 0.0f)); // NaN -> 0
      row[i] = static_cast<unsigned char>(std::lround(v * 255.0f));
    }
    uint64_t bestCost = UINT64_MAX;
    unsigned char bestType = 0;
    for (unsigned char type = 0; type < 5; ++type)
    {
      uint64_t cost = 0;
      for (size_t i = 0; i < rowBytes; ++i)
      {
        const int a = i >= size_t(channels) ? row[i - channels] : 0;
        const int b = previous[i];
        const int c = i >= size_t(channels) ? previous[i - channels] : 0;
        const int predictor = Predictor(type, a, b, c);
        candidate[i] = static_cast<unsigned char>(row[i] - predictor);
        cost += static_cast<uint64_t>(std::abs(static_cast<signed char>(candidate[i])));
      }
      if (cost < bestCost)
      {
        bestCost = cost;
        bestType = type;
        best.swap(candidate);
      }
    }
    filtered.push_back(bestType);
    filtered.insert(filtered.end(), best.begin(), best.end());
    previous.swap(row);
  }
  Bytes compressed;
  if (!Deflate(filtered, &compressed))
  {
    return Fail("zlib could not compress the PNG data", error);
  }
  Bytes png(PngSignature, PngSignature + 8);
  Bytes header;
  PutBE32(header, static_cast<uint32_t>(width));
  PutBE32(header, static_cast<uint32_t>(height));
  header.insert(header.end(), { 8, colourTypes[channels], 0, 0, 0 });
  PutChunk(png, "IHDR", header);
  Bytes gamma;
  PutBE32(gamma, 100000); // gamma 1.0: linear values, stored as they are (ao-definition.md)
  PutChunk(png, "gAMA", gamma);
  PutChunk(png, "IDAT", compressed);
  PutChunk(png, "IEND", Bytes());
  return WriteFile(path, png) ? true : Fail("cannot write the file", error);
}

bool ReadPNG(const Bytes& file, BuiltinImage* image, BuiltinError error)
{
  int *width = &image->Width, *height = &image->Height, *channels = &image->Channels;
  std::vector<float>* pixels = &image->Pixels;
  size_t at = 8;
  uint32_t w = 0, h = 0;
  int depth = 0, colour = -1;
  Bytes idat, palette, transparency;
  bool ended = false;
  while (!ended)
  {
    if (at + 12 > file.size())
    {
      return Fail("truncated PNG (no IEND chunk)", error);
    }
    const uint32_t length = GetBE32(&file[at]);
    if (length > file.size() - at - 12)
    {
      return Fail("truncated PNG (a chunk runs past the end of the file)", error);
    }
    const unsigned char* type = &file[at + 4];
    const unsigned char* data = &file[at + 8];
    if (crc32(0L, type, length + 4) != GetBE32(data + length))
    {
      return Fail("corrupt PNG (a chunk's CRC does not match)", error);
    }
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (name == "IHDR")
    {
      if (length != 13)
      {
        return Fail("corrupt PNG (IHDR of " + std::to_string(length) + " bytes)", error);
      }
      w = GetBE32(data);
      h = GetBE32(data + 4);
      depth = data[8];
      colour = data[9];
      if (data[12] != 0)
      {
        return Fail("interlaced PNG is not supported (builtin image I/O)", error);
      }
    }
    else if (name == "PLTE")
    {
      palette.assign(data, data + length);
    }
    else if (name == "tRNS")
    {
      transparency.assign(data, data + length);
    }
    else if (name == "IDAT")
    {
      idat.insert(idat.end(), data, data + length);
    }
    else if (name == "IEND")
    {
      ended = true;
    }
    else if (!(type[0] & 0x20))
    {
      return Fail("PNG with an unknown critical chunk '" + name + "'", error);
    }
    at += 12 + static_cast<size_t>(length);
  }
  int samples = colour == 0 ? 1 : colour == 2 ? 3 : colour == 3 ? 1 : colour == 4 ? 2 : 4;
  if (colour < 0 || colour == 1 || colour == 5 || colour > 6)
  {
    return Fail("corrupt PNG (colour type " + std::to_string(colour) + ")", error);
  }
  const bool lowDepth = (colour == 0 || colour == 3) && (depth == 1 || depth == 2 || depth == 4);
  if (!(lowDepth || depth == 8 || (depth == 16 && colour != 3)))
  {
    return Fail("corrupt PNG (" + std::to_string(depth) + "-bit samples of colour type " +
        std::to_string(colour) + ")",
      error);
  }
  if (w == 0 || h == 0 || uint64_t(w) * h * 4 > MaximumSamples)
  {
    return Fail("PNG of unsupported size " + std::to_string(w) + "x" + std::to_string(h), error);
  }
  if (colour == 3 && (palette.empty() || palette.size() % 3 != 0))
  {
    return Fail("corrupt PNG (palette image without a valid PLTE chunk)", error);
  }
  // Filters work on bytes; samples under 8 bits are packed, first one in the high bits.
  const size_t bitsPerPixel = samples * depth, bpp = std::max<size_t>(1, bitsPerPixel / 8);
  const size_t rowBytes = (w * bitsPerPixel + 7) / 8;
  auto sample = [depth](const unsigned char* row, size_t index) -> unsigned
  {
    if (depth == 16)
    {
      return unsigned(row[2 * index]) << 8 | row[2 * index + 1];
    }
    const size_t bit = index * depth;
    return (row[bit / 8] >> (8 - depth - bit % 8)) & ((1u << depth) - 1);
  };
  Bytes raw;
  if (!Inflate(idat.data(), idat.size(), (rowBytes + 1) * h, &raw))
  {
    return Fail("corrupt PNG (the image data does not inflate to the image's size)", error);
  }
  // Undo the filters in place: row y's bytes start at y * (rowBytes + 1) + 1.
  for (size_t y = 0; y < h; ++y)
  {
    unsigned char* row = &raw[y * (rowBytes + 1) + 1];
    const unsigned char* above = y ? &raw[(y - 1) * (rowBytes + 1) + 1] : nullptr;
    const int type = row[-1];
    if (type > 4)
    {
      return Fail("corrupt PNG (filter type " + std::to_string(type) + ")", error);
    }
    for (size_t i = 0; i < rowBytes; ++i)
    {
      const int a = i >= bpp ? row[i - bpp] : 0;
      const int b = above ? above[i] : 0;
      const int c = above && i >= bpp ? above[i - bpp] : 0;
      const int predictor = Predictor(type, a, b, c);
      row[i] = static_cast<unsigned char>(row[i] + predictor);
    }
  }
  const int out = colour == 3 ? (transparency.empty() ? 3 : 4) : samples;
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  *channels = out;
  pixels->assign(static_cast<size_t>(w) * h * out, 0.0f);
  const float scale = 1.0f / static_cast<float>((1u << depth) - 1);
  for (size_t y = 0; y < h; ++y)
  {
    const unsigned char* row = &raw[y * (rowBytes + 1) + 1];
    float* target = &(*pixels)[y * w * out];
    for (size_t x = 0; x < w; ++x)
    {
      if (colour == 3)
      {
        const size_t index = sample(row, x);
        if (3 * index + 2 >= palette.size())
        {
          return Fail("corrupt PNG (a palette index past the palette)", error);
        }
        for (int k = 0; k < 3; ++k)
        {
          target[x * out + k] = palette[3 * index + k] / 255.0f;
        }
        if (out == 4)
        {
          target[x * out + 3] = (index < transparency.size() ? transparency[index] : 255) / 255.0f;
        }
        continue;
      }
      for (int k = 0; k < samples; ++k)
      {
        target[x * out + k] = static_cast<float>(sample(row, x * samples + k)) * scale;
      }
    }
  }
  if (out == 2 || out == 4)
  {
    // Premultiplied in memory, as OpenImageIO does (with gamma 1; it uses the file's gamma).
    for (size_t p = 0; p < pixels->size(); p += out)
    {
      for (int k = 0; k < out - 1; ++k)
      {
        (*pixels)[p + k] *= (*pixels)[p + out - 1];
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// OpenEXR 2 (openexr.com, "OpenEXR File Layout"): single part, scanline, float channels sorted
// by name, ZIP compression (16 lines a block: bytes split into even and odd halves, differenced,
// zlib), a block stored raw when that is not smaller.
const char* CompressionNames[] = { "none",
  "RLE",
  "ZIPS",
  "ZIP",
  "PIZ",
  "PXR24",
  "B44",
  "B44A",
  "DWAA",
  "DWAB" };

void PutAttribute(Bytes& b, const char* name, const char* type, const Bytes& value)
{
  b.insert(b.end(), name, name + std::strlen(name) + 1);
  b.insert(b.end(), type, type + std::strlen(type) + 1);
  PutLE32(b, static_cast<uint32_t>(value.size()));
  b.insert(b.end(), value.begin(), value.end());
}

// ZIP's reordering and differencing (and their inverses), in place.
void ZipPredict(Bytes& data)
{
  Bytes split(data.size());
  const size_t half = (data.size() + 1) / 2;
  for (size_t i = 0; i < data.size(); ++i)
  {
    split[(i % 2 ? half : 0) + i / 2] = data[i];
  }
  for (size_t i = split.size(); i-- > 1;)
  {
    split[i] = static_cast<unsigned char>(int(split[i]) - int(split[i - 1]) + 128);
  }
  data.swap(split);
}

void ZipUnpredict(Bytes& data)
{
  for (size_t i = 1; i < data.size(); ++i)
  {
    data[i] = static_cast<unsigned char>(int(data[i - 1]) + int(data[i]) - 128);
  }
  Bytes merged(data.size());
  const size_t half = (data.size() + 1) / 2;
  for (size_t i = 0; i < data.size(); ++i)
  {
    merged[i] = data[(i % 2 ? half : 0) + i / 2];
  }
  data.swap(merged);
}

bool WriteEXR(const char* path, const BuiltinImageView& image, BuiltinError error)
{
  const int width = image.Width, height = image.Height, channels = image.Channels;
  const float* pixels = image.Pixels;
  static const char* const names[5][4] = {
    {}, { "Y" }, { "Y", "A" }, { "R", "G", "B" }, { "R", "G", "B", "A" }
  };
  // The file's channel order (by name) -> the channel in @p pixels.
  std::vector<int> order(channels);
  for (int c = 0; c < channels; ++c)
  {
    order[c] = c;
  }
  std::sort(order.begin(),
    order.end(),
    [&](int a, int b) { return std::strcmp(names[channels][a], names[channels][b]) < 0; });

  Bytes exr = { 0x76, 0x2f, 0x31, 0x01 };
  PutLE32(exr, 2); // version 2, single-part scanline
  Bytes list;
  for (int c : order)
  {
    list.insert(list.end(), names[channels][c], names[channels][c] + 2); // the name and its 0
    PutLE32(list, 2);                                                    // FLOAT
    list.insert(list.end(), { 0, 0, 0, 0 });                             // pLinear, reserved
    PutLE32(list, 1);                                                    // x sampling
    PutLE32(list, 1);                                                    // y sampling
  }
  list.push_back(0);
  PutAttribute(exr, "channels", "chlist", list);
  PutAttribute(exr, "compression", "compression", { 3 });
  Bytes window;
  for (int v : { 0, 0, width - 1, height - 1 })
  {
    PutLE32(window, static_cast<uint32_t>(v));
  }
  PutAttribute(exr, "dataWindow", "box2i", window);
  PutAttribute(exr, "displayWindow", "box2i", window);
  PutAttribute(exr, "lineOrder", "lineOrder", { 0 });
  Bytes one, center;
  PutLE32(one, FloatBits(1.0f));
  PutLE64(center, 0);
  PutAttribute(exr, "pixelAspectRatio", "float", one);
  PutAttribute(exr, "screenWindowCenter", "v2f", center);
  PutAttribute(exr, "screenWindowWidth", "float", one);
  exr.push_back(0);

  const int linesPerBlock = 16;
  const int blocks = (height + linesPerBlock - 1) / linesPerBlock;
  const size_t table = exr.size();
  exr.resize(table + 8 * static_cast<size_t>(blocks));
  for (int block = 0; block < blocks; ++block)
  {
    const int y0 = block * linesPerBlock, y1 = std::min(height, y0 + linesPerBlock);
    Bytes raw;
    raw.reserve(static_cast<size_t>(y1 - y0) * width * channels * 4);
    for (int y = y0; y < y1; ++y)
    {
      const float* row = pixels + static_cast<size_t>(y) * width * channels;
      for (int c : order)
      {
        for (int x = 0; x < width; ++x)
        {
          PutLE32(raw, FloatBits(row[static_cast<size_t>(x) * channels + c]));
        }
      }
    }
    Bytes predicted = raw, compressed;
    ZipPredict(predicted);
    if (!Deflate(predicted, &compressed))
    {
      return Fail("zlib could not compress the EXR data", error);
    }
    const Bytes& stored = compressed.size() < raw.size() ? compressed : raw;
    Bytes offset;
    PutLE64(offset, exr.size());
    std::copy(offset.begin(), offset.end(), exr.begin() + table + 8 * block);
    PutLE32(exr, static_cast<uint32_t>(y0));
    PutLE32(exr, static_cast<uint32_t>(stored.size()));
    exr.insert(exr.end(), stored.begin(), stored.end());
  }
  return WriteFile(path, exr) ? true : Fail("cannot write the file", error);
}

struct ExrChannel
{
  std::string Name;
  int Type = 0; // 0 uint, 1 half, 2 float
  int Rank = 0; // R G B Y A first, in that order, then the rest in the file's order
  int Output = 0;
};

bool ReadEXR(const Bytes& file, BuiltinImage* image, BuiltinError error)
{
  int *width = &image->Width, *height = &image->Height, *channels = &image->Channels;
  std::vector<float>* pixels = &image->Pixels;
  if (file.size() < 8)
  {
    return Fail("truncated EXR", error);
  }
  const uint32_t version = GetLE32(&file[4]);
  if ((version & 0xff) != 2 || (version & 0x1a00))
  {
    return Fail(std::string("EXR ") +
        ((version & 0x1000)     ? "multi-part"
            : (version & 0x800) ? "deep"
            : (version & 0x200) ? "tiled"
                                : "of an unknown version") +
        " files are not supported (builtin image I/O reads single-part scanline files)",
      error);
  }
  size_t at = 8;
  auto text = [&](std::string* s) -> bool
  {
    if (at >= file.size())
    {
      return false;
    }
    const auto* end =
      static_cast<const unsigned char*>(std::memchr(&file[at], 0, file.size() - at));
    if (!end)
    {
      return false;
    }
    s->assign(reinterpret_cast<const char*>(&file[at]), end - &file[at]);
    at = end - file.data() + 1;
    return true;
  };
  std::vector<ExrChannel> list;
  int compression = -1;
  int32_t box[4] = { 0, 0, -1, -1 };
  for (;;)
  {
    std::string name, type;
    if (!text(&name))
    {
      return Fail("truncated EXR header", error);
    }
    if (name.empty())
    {
      break;
    }
    if (!text(&type) || at + 4 > file.size())
    {
      return Fail("truncated EXR header", error);
    }
    const uint32_t size = GetLE32(&file[at]);
    at += 4;
    if (size > file.size() - at)
    {
      return Fail("truncated EXR header", error);
    }
    const unsigned char* value = &file[at];
    if (name == "channels" && type == "chlist")
    {
      size_t i = 0;
      while (i < size && value[i] != 0)
      {
        const auto* end = static_cast<const unsigned char*>(std::memchr(value + i, 0, size - i));
        if (!end || static_cast<size_t>(end - value) + 17 > size)
        {
          return Fail("corrupt EXR channel list", error);
        }
        ExrChannel c;
        c.Name.assign(reinterpret_cast<const char*>(value + i), end - (value + i));
        c.Type = static_cast<int>(GetLE32(end + 1));
        if (c.Type < 0 || c.Type > 2 || GetLE32(end + 9) != 1 || GetLE32(end + 13) != 1)
        {
          return Fail("EXR channel '" + c.Name + "' is subsampled or of an unknown type", error);
        }
        static const char* const first[] = { "R", "G", "B", "Y", "A" };
        c.Rank = 5;
        for (int k = 0; k < 5; ++k)
        {
          c.Rank = c.Name == first[k] ? k : c.Rank;
        }
        list.push_back(c);
        i = static_cast<size_t>(end - value) + 17;
      }
    }
    else if (name == "compression" && size == 1)
    {
      compression = value[0];
    }
    else if (name == "dataWindow" && size == 16)
    {
      for (int k = 0; k < 4; ++k)
      {
        box[k] = static_cast<int32_t>(GetLE32(value + 4 * k));
      }
    }
    at += size;
  }
  if (compression != 0 && compression != 2 && compression != 3)
  {
    return Fail(std::string("EXR with ") +
        (compression > 0 && compression < 10 ? CompressionNames[compression] : "unknown") +
        " compression is not supported (builtin image I/O reads none, ZIPS and ZIP)",
      error);
  }
  const int64_t w = int64_t(box[2]) - box[0] + 1, h = int64_t(box[3]) - box[1] + 1;
  if (list.empty() || w <= 0 || h <= 0 || uint64_t(w) * uint64_t(h) * list.size() > MaximumSamples)
  {
    return Fail("EXR without channels or of unsupported size", error);
  }
  std::vector<size_t> byRank(list.size());
  for (size_t c = 0; c < list.size(); ++c)
  {
    byRank[c] = c;
  }
  std::stable_sort(
    byRank.begin(), byRank.end(), [&](size_t a, size_t b) { return list[a].Rank < list[b].Rank; });
  for (size_t k = 0; k < byRank.size(); ++k)
  {
    list[byRank[k]].Output = static_cast<int>(k);
  }
  size_t lineBytes = 0;
  for (const ExrChannel& c : list)
  {
    lineBytes += static_cast<size_t>(w) * (c.Type == 1 ? 2 : 4);
  }
  const int linesPerBlock = compression == 3 ? 16 : 1;
  const int64_t blocks = (h + linesPerBlock - 1) / linesPerBlock;
  if (at + 8 * blocks > file.size())
  {
    return Fail("truncated EXR (offset table)", error);
  }
  const int n = static_cast<int>(list.size());
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  *channels = n;
  pixels->assign(static_cast<size_t>(w) * h * n, 0.0f);
  Bytes raw;
  for (int64_t block = 0; block < blocks; ++block)
  {
    const uint64_t offset = GetLE64(&file[at + 8 * block]);
    if (offset > file.size() || file.size() - offset < 8)
    {
      return Fail("truncated EXR (a block past the end of the file)", error);
    }
    const int64_t y0 = static_cast<int32_t>(GetLE32(&file[offset])) - int64_t(box[1]);
    const uint32_t size = GetLE32(&file[offset + 4]);
    if (y0 < 0 || y0 >= h || y0 % linesPerBlock != 0 || size > file.size() - offset - 8)
    {
      return Fail("corrupt EXR block", error);
    }
    const int64_t lines = std::min<int64_t>(linesPerBlock, h - y0);
    const size_t expected = static_cast<size_t>(lines) * lineBytes;
    const unsigned char* data = &file[offset + 8];
    if (size == expected)
    {
      raw.assign(data, data + size);
    }
    else if (compression == 0 || !Inflate(data, size, expected, &raw))
    {
      return Fail("corrupt EXR block (its data does not decompress to its size)", error);
    }
    else
    {
      ZipUnpredict(raw);
    }
    const unsigned char* p = raw.data();
    for (int64_t y = y0; y < y0 + lines; ++y)
    {
      float* row = &(*pixels)[static_cast<size_t>(y) * w * n];
      for (const ExrChannel& c : list)
      {
        for (int64_t x = 0; x < w; ++x)
        {
          float v;
          if (c.Type == 1)
          {
            v = HalfToFloat(static_cast<uint16_t>(p[0] | (p[1] << 8)));
            p += 2;
          }
          else
          {
            const uint32_t bits = GetLE32(p);
            v = c.Type == 2 ? BitsFloat(bits) : static_cast<float>(bits);
            p += 4;
          }
          row[x * n + c.Output] = v;
        }
      }
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool BuiltinWriteImageFile(const char* path, const BuiltinImageView& image, BuiltinError error)
{
  const int width = image.Width, height = image.Height, channels = image.Channels;
  const std::string ext = LowerExtension(path);
  if (ext != ".png" && ext != ".exr")
  {
    return Fail("unsupported format '" + ext + "' (builtin image I/O writes .png and .exr)", error);
  }
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
  {
    return Fail("cannot write an image of " + std::to_string(width) + "x" + std::to_string(height) +
        " pixels and " + std::to_string(channels) + " channels",
      error);
  }
  return ext == ".png" ? WritePNG(path, image, error) : WriteEXR(path, image, error);
}

//------------------------------------------------------------------------------
bool BuiltinReadImageFile(const char* path, BuiltinImage* image, BuiltinError error)
{
  Bytes file;
  if (!ReadFile(path, &file))
  {
    return Fail(std::string("cannot open '") + path + "'", error);
  }
  if (file.size() >= 8 && std::memcmp(file.data(), PngSignature, 8) == 0)
  {
    return ReadPNG(file, image, error);
  }
  if (file.size() >= 4 && GetLE32(file.data()) == 20000630)
  {
    return ReadEXR(file, image, error);
  }
  return Fail(std::string("'") + path + "' is neither PNG nor OpenEXR (builtin image I/O)", error);
}
}
