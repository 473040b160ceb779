#include "vtkAOVoxelTracer.h"

#include "vtkAOBitmaskVoxelizer.h"
#include "vtkAOGBufferPass.h"
#include "vtkAOGL.h" // glGenQueries, GL_SAMPLES_PASSED
#include "vtkAOPixelList.h"
#include "vtkAORefineFilterFS.h"
#include "vtkAOShaderUtilities.h"
#include "vtkAOVoxelTracerFS.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkAOVoxelTracer);

namespace
{
constexpr int NoiseSize = 32;       // texels per side of the tiled 3-D noise
constexpr int BlockSize = 2;        // cells per side of a coarse block (AO_BLOCK in the shaders)
constexpr int BlocksPerTexel = 128; // bits of an RGBA32UI texel

// vtkShaderProgram has no SetUniform3i in VTK 9.1; the program must be bound.
void SetUniform3i(vtkShaderProgram* program, const char* name, const int v[3])
{
  const GLint location = program->FindUniform(name);
  if (location >= 0)
  {
    glUniform3i(location, v[0], v[1], v[2]);
  }
}

constexpr int MaximumDistance = 16; // blocks; larger distances are stored as this
// Above this many blocks (a grid of more than 512^3 cells) the distance field is not built
// and rays march every point.
constexpr long long MaximumBlocks = 1LL << 25;

int CountTrailingZeros(std::uint64_t v) // v != 0
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(v);
#else
  int n = 0;
  while (!(v & 1u))
  {
    v >>= 1;
    ++n;
  }
  return n;
#endif
}

// Chessboard (L-infinity) distance, in blocks, from every block to the nearest occupied one
// (0: occupied), capped at MaximumDistance, written to @p d (x fastest, then y, then z).
// @p columns holds the occupancy as bit columns along z (@p words 64-bit words per column,
// column x + nx y). The L-infinity ball of radius k is a cube, so dilating the occupancy k
// times by the 3 x 3 x 3 cube (separably, and 64 blocks at a time) sets exactly the blocks
// at distance <= k: a block first set by dilation k is at distance k.
void ChessboardDistance(std::vector<std::uint64_t>& columns,
  int words,
  int nx,
  int ny,
  int nz,
  std::vector<unsigned char>& d)
{
  const size_t count = static_cast<size_t>(nx) * ny;
  d.assign(count * nz, static_cast<unsigned char>(MaximumDistance));
  const std::uint64_t lastMask =
    nz % 64 == 0 ? ~std::uint64_t(0) : (std::uint64_t(1) << (nz % 64)) - 1;
  auto record = [&](const std::vector<std::uint64_t>& bits, unsigned char k)
  {
    for (size_t c = 0; c < count; ++c)
    {
      for (int w = 0; w < words; ++w)
      {
        std::uint64_t v = bits[c * words + w];
        while (v)
        {
          const int z = 64 * w + CountTrailingZeros(v);
          v &= v - 1;
          d[static_cast<size_t>(z) * count + c] = k;
        }
      }
    }
  };
  record(columns, 0);
  std::vector<std::uint64_t> a(columns.size()), b(columns.size()), fresh(columns.size());
  std::vector<std::uint64_t>& current = columns;
  for (int k = 1; k < MaximumDistance; ++k)
  {
    // z: OR with the column shifted up and down by one block.
    for (size_t c = 0; c < count; ++c)
    {
      const std::uint64_t* in = &current[c * words];
      std::uint64_t* out = &a[c * words];
      for (int w = 0; w < words; ++w)
      {
        const std::uint64_t below = w > 0 ? in[w - 1] >> 63 : 0;
        const std::uint64_t above = w + 1 < words ? in[w + 1] << 63 : 0;
        out[w] = in[w] | (in[w] << 1) | below | (in[w] >> 1) | above;
      }
      out[words - 1] &= lastMask;
    }
    // y, then x: OR with the neighbouring columns.
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x)
      {
        const size_t c = static_cast<size_t>(y) * nx + x;
        for (int w = 0; w < words; ++w)
        {
          std::uint64_t v = a[c * words + w];
          v |= y > 0 ? a[(c - nx) * words + w] : 0;
          v |= y + 1 < ny ? a[(c + nx) * words + w] : 0;
          b[c * words + w] = v;
        }
      }
    }
    bool grew = false;
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x)
      {
        const size_t c = static_cast<size_t>(y) * nx + x;
        for (int w = 0; w < words; ++w)
        {
          std::uint64_t v = b[c * words + w];
          v |= x > 0 ? b[(c - 1) * words + w] : 0;
          v |= x + 1 < nx ? b[(c + 1) * words + w] : 0;
          fresh[c * words + w] = v & ~current[c * words + w];
          grew = grew || fresh[c * words + w] != 0;
          a[c * words + w] = v;
        }
      }
    }
    if (!grew)
    {
      break;
    }
    record(fresh, static_cast<unsigned char>(k));
    current.swap(a);
  }
}

std::string TracerDefines(int levels, bool erode)
{
  return "#define AO_BLOCK " + std::to_string(BlockSize) + ".0\n#define AO_LEVELS " +
    std::to_string(levels) + "\n#define AO_ERODE " + (erode ? "1" : "0");
}

// Coarse occupancy: bit bz of texel (bx, by + (bz / 128) * rows) is the OR of the cells of
// block (bx, by, bz), AO_BLOCK^3 cells (2 or 4). One texel gathers AO_BLOCK^2 columns of
// AO_BLOCK grid layers (128 blocks = 128 AO_BLOCK slices).
const char* CoarseFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform usampler3D aoGrid;
uniform ivec2 aoCoarseTexels; // size of the output
uniform ivec3 aoGridTexels; // texels of the grid along x, y and layers
uniform int aoCoarseRows;   // rows per 128 blocks along z
out uvec4 fragOutput0;      // the only output, bound as gl_FragData[0]

// OR each group of AO_BLOCK bits of w into one bit, packed at the bottom (32 / AO_BLOCK bits).
uint aoCompress(uint w)
{
#if AO_BLOCK == 2
  uint v = (w | (w >> 1u)) & 0x55555555u;
  v = (v | (v >> 1u)) & 0x33333333u;
  v = (v | (v >> 2u)) & 0x0F0F0F0Fu;
  v = (v | (v >> 4u)) & 0x00FF00FFu;
  return (v | (v >> 8u)) & 0xFFFFu;
#else
  uint v = w | (w >> 1u);
  v = (v | (v >> 2u)) & 0x11111111u;
  v = (v | (v >> 3u)) & 0x03030303u;
  v = (v | (v >> 6u)) & 0x000F000Fu;
  return (v | (v >> 12u)) & 0xFFu;
#endif
}

void main()
{
  ivec2 o = min(ivec2(texCoord * vec2(aoCoarseTexels)), aoCoarseTexels - 1);
  int group = o.y / aoCoarseRows;
  ivec2 b = ivec2(o.x, o.y - group * aoCoarseRows);
  uint compressed[AO_BLOCK * 4]; // the compressed words of the AO_BLOCK layers, in slice order
  for (int k = 0; k < AO_BLOCK; ++k)
  {
    int layer = group * AO_BLOCK + k;
    uvec4 acc = uvec4(0u);
    if (layer < aoGridTexels.z)
    {
      for (int y = 0; y < AO_BLOCK; ++y)
      {
        for (int x = 0; x < AO_BLOCK; ++x)
        {
          ivec2 c = b * AO_BLOCK + ivec2(x, y);
          if (c.x < aoGridTexels.x && c.y < aoGridTexels.y)
          {
            acc |= texelFetch(aoGrid, ivec3(c, layer), 0);
          }
        }
      }
    }
    compressed[4 * k] = aoCompress(acc.x);
    compressed[4 * k + 1] = aoCompress(acc.y);
    compressed[4 * k + 2] = aoCompress(acc.z);
    compressed[4 * k + 3] = aoCompress(acc.w);
  }
  // AO_BLOCK consecutive compressed words (32 / AO_BLOCK bits each) make one output word.
  uint words[4];
  for (int i = 0; i < 4; ++i)
  {
    uint w = 0u;
    for (int j = 0; j < AO_BLOCK; ++j)
    {
      w |= compressed[AO_BLOCK * i + j] << uint(j * (32 / AO_BLOCK));
    }
    words[i] = w;
  }
  fragOutput0 = uvec4(words[0], words[1], words[2], words[3]);
}
)";
}

//------------------------------------------------------------------------------
vtkAOVoxelTracer::vtkAOVoxelTracer()
  : List(vtkAOPixelList::New())
{
}

//------------------------------------------------------------------------------
vtkAOVoxelTracer::~vtkAOVoxelTracer()
{
  vtkAOShaderUtilities::DeleteObjects({ this->Noise, this->Refined, this->List });
  for (Level& level : this->Levels)
  {
    vtkAOShaderUtilities::DeleteObjects({ level.Coarse, level.Distance });
  }
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::InitializeNoise(vtkOpenGLRenderWindow* renWin)
{
  if (this->Noise && this->Noise->GetContext() == renWin)
  {
    return;
  }
  vtkAOShaderUtilities::ReleaseTexture(this->Noise, renWin);
  // White noise, fixed seed: the same jitter every run, so images are repeatable.
  std::mt19937 generator(20090401u);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<unsigned char> texels(NoiseSize * NoiseSize * NoiseSize * 4);
  for (auto& t : texels)
  {
    t = static_cast<unsigned char>(byte(generator));
  }
  this->Noise = vtkTextureObject::New();
  this->Noise->SetContext(renWin);
  this->Noise->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Noise->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Noise->SetWrapS(vtkTextureObject::Repeat);
  this->Noise->SetWrapT(vtkTextureObject::Repeat);
  this->Noise->SetWrapR(vtkTextureObject::Repeat);
  this->Noise->Create3DFromRaw(
    NoiseSize, NoiseSize, NoiseSize, 4, VTK_UNSIGNED_CHAR, texels.data());
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::DisableSkipping(vtkOpenGLRenderWindow* renWin, Level& level)
{
  // A 1-texel placeholder: the shader then treats every block as occupied.
  level.Skipping = false;
  level.CoarseSize[0] = level.CoarseSize[1] = level.CoarseSize[2] = 1;
  vtkAOShaderUtilities::ReleaseTexture(level.Distance, renWin);
  const unsigned char zero = 0;
  level.Distance = vtkTextureObject::New();
  level.Distance->SetContext(renWin);
  level.Distance->Create3DFromRaw(1, 1, 1, 1, VTK_UNSIGNED_CHAR, const_cast<unsigned char*>(&zero));
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::RenderCoarseOccupancy(vtkOpenGLRenderWindow* renWin,
  vtkTextureObject* gridTexture,
  Level& level,
  int rows,
  int cw,
  int ch)
{
  if (level.Coarse &&
    (level.Coarse->GetContext() != renWin || static_cast<int>(level.Coarse->GetWidth()) != cw ||
      static_cast<int>(level.Coarse->GetHeight()) != ch))
  {
    vtkAOShaderUtilities::ReleaseTexture(level.Coarse, renWin);
  }
  if (!level.Coarse)
  {
    level.Coarse = vtkAOShaderUtilities::NewNearestTexture(renWin);
    level.Coarse->SetInternalFormat(GL_RGBA32UI);
    level.Coarse->SetFormat(GL_RGBA_INTEGER);
    level.Coarse->SetDataType(GL_UNSIGNED_INT);
    if (!level.Coarse->Allocate2D(cw, ch, 4, VTK_UNSIGNED_INT))
    {
      vtkErrorMacro(<< "Couldn't allocate the coarse occupancy texture.");
      return false;
    }
  }
  std::string coarseFS = CoarseFS;
  vtkShaderProgram::Substitute(coarseFS,
    "//VTK::System::Dec",
    "//VTK::System::Dec\n#define AO_BLOCK " + std::to_string(BlockSize));
  if (!vtkAOShaderUtilities::ReadyQuad(
        this->CoarseQuad, renWin, coarseFS, this, "coarse occupancy"))
  {
    return false;
  }
  vtkShaderProgram* program = this->CoarseQuad->Program;
  gridTexture->Activate();
  program->SetUniformi("aoGrid", gridTexture->GetTextureUnit());
  const int texels[3] = { static_cast<int>(gridTexture->GetWidth()),
    static_cast<int>(gridTexture->GetHeight()),
    static_cast<int>(gridTexture->GetDepth()) };
  SetUniform3i(program, "aoGridTexels", texels);
  program->SetUniformi("aoCoarseRows", std::max(1, rows));
  const int coarseTexels[2] = { cw, ch };
  program->SetUniform2i("aoCoarseTexels", coarseTexels);

  // The coarse level can be larger than the window (its rows are blocks times groups), and
  // the renderer's scissor box is the window's: without this, rows beyond the window's
  // height were never written and read back as empty, so rays skipped occupied blocks.
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(renWin->GetState(), GL_SCISSOR_TEST);
  renWin->GetState()->vtkglDisable(GL_SCISSOR_TEST);
  vtkAOShaderUtilities::DrawQuad(
    renWin, this->FrameBufferObject, this->CoarseQuad.get(), level.Coarse);
  gridTexture->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::UploadDistance(vtkOpenGLRenderWindow* renWin,
  Level& level,
  const int blocks[3],
  const std::vector<unsigned char>& distance)
{
  const int bx = blocks[0], by = blocks[1], bz = blocks[2];
  if (level.Distance &&
    (level.Distance->GetContext() != renWin || static_cast<int>(level.Distance->GetWidth()) != bx ||
      static_cast<int>(level.Distance->GetHeight()) != by ||
      static_cast<int>(level.Distance->GetDepth()) != bz))
  {
    vtkAOShaderUtilities::ReleaseTexture(level.Distance, renWin);
  }
  if (!level.Distance)
  {
    level.Distance = vtkAOShaderUtilities::NewNearestTexture(renWin);
    level.Distance->SetWrapR(vtkTextureObject::ClampToEdge);
    level.Distance->Create3DFromRaw(
      bx, by, bz, 1, VTK_UNSIGNED_CHAR, const_cast<unsigned char*>(distance.data()));
  }
  else
  {
    level.Distance->Activate();
    renWin->GetState()->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage3D(GL_TEXTURE_3D,
      0,
      0,
      0,
      0,
      bx,
      by,
      bz,
      level.Distance->GetFormat(VTK_UNSIGNED_CHAR, 1, false),
      GL_UNSIGNED_BYTE,
      distance.data());
    level.Distance->Deactivate();
  }
  std::copy(blocks, blocks + 3, level.CoarseSize);
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::BuildCoarseLevel(vtkOpenGLRenderWindow* renWin,
  vtkAOBitmaskVoxelizer* grid,
  Level& level)
{
  int dims[3];
  grid->GetGridDimensions(dims);
  const int blocks[3] = { (dims[0] + BlockSize - 1) / BlockSize,
    (dims[1] + BlockSize - 1) / BlockSize,
    (dims[2] + BlockSize - 1) / BlockSize };
  const int bx = blocks[0], by = blocks[1], bz = blocks[2];
  const int groups = (bz + BlocksPerTexel - 1) / BlocksPerTexel;
  const int cw = std::max(1, bx), ch = std::max(1, by * groups);
  // Leave the pixel-store state as found (the downloads and uploads below change it).
  GLint packAlignment = 4, unpackAlignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
  struct AlignmentRestorer
  {
    vtkOpenGLState* State;
    GLint Pack, Unpack;
    ~AlignmentRestorer()
    {
      this->State->vtkglPixelStorei(GL_PACK_ALIGNMENT, this->Pack);
      this->State->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, this->Unpack);
    }
  } alignmentRestorer{ renWin->GetState(), packAlignment, unpackAlignment };
  GLint max2D = 0, max3D = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max2D);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  bool skipping = static_cast<long long>(bx) * by * bz <= MaximumBlocks && cw <= max2D &&
    ch <= max2D && std::max({ bx, by, bz }) <= max3D;
#ifdef GL_ES_VERSION_3_0
  skipping = false; // no glGetTexImage to read the coarse level back
#endif
  if (!skipping)
  {
    this->DisableSkipping(renWin, level);
    return true;
  }
  if (!this->RenderCoarseOccupancy(renWin, grid->GetGridTexture(), level, by, cw, ch))
  {
    return false;
  }

  // The distance to the nearest occupied block, on the CPU from the (small) coarse level.
  std::vector<unsigned char> distance;
#ifndef GL_ES_VERSION_3_0
  std::vector<unsigned int> coarseWords(static_cast<size_t>(cw) * ch * 4);
  renWin->GetState()->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
  level.Coarse->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, coarseWords.data());
  level.Coarse->Deactivate();
  // Bit columns along z, 64 blocks per word: 64-bit word w of a column is 32-bit words
  // 2 (w % 2) and 2 (w % 2) + 1 of the column's texel in group w / 2.
  const int words = (bz + 63) / 64;
  std::vector<std::uint64_t> columns(static_cast<size_t>(bx) * by * words);
  for (int y = 0; y < by; ++y)
  {
    for (int x = 0; x < bx; ++x)
    {
      for (int w = 0; w < words; ++w)
      {
        const unsigned int* texel =
          &coarseWords[(static_cast<size_t>(y + (w / 2) * by) * cw + x) * 4];
        columns[(static_cast<size_t>(y) * bx + x) * words + w] =
          texel[2 * (w % 2)] | (static_cast<std::uint64_t>(texel[2 * (w % 2) + 1]) << 32);
      }
    }
  }
  ChessboardDistance(columns, words, bx, by, bz, distance);
#endif
  this->UploadDistance(renWin, level, blocks, distance);
  level.Skipping = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::Prepare(const Input& input)
{
  vtkOpenGLRenderWindow* renWin = input.Window;
  const Grids& grids = input.Cascades;
  const Parameters& par = input.Settings;
  if (grids.empty() || !grids[0] || !grids[0]->GetGridTexture())
  {
    return false;
  }
  this->InitializeNoise(renWin);
  vtkAOShaderUtilities::EnsureFramebuffer(this->FrameBufferObject, renWin);
  // The coarse levels follow the grids: rebuild them after every voxelization (or every
  // frame when the caller cannot tell).
  const int count = std::min(static_cast<int>(grids.size()), MaximumLevels);
  for (int l = 0; l < count; ++l)
  {
    Level& level = this->Levels[l];
    if (!grids[l] || !grids[l]->GetGridTexture())
    {
      return false;
    }
    const unsigned int gridHandle = grids[l]->GetGridTexture()->GetHandle();
    const long long version = grids[l]->GetGridVersion();
    if (!par.FollowGridVersions || version != level.Version || gridHandle != level.GridHandle ||
      !level.Distance || level.Distance->GetContext() != renWin)
    {
      if (!this->BuildCoarseLevel(renWin, grids[l], level))
      {
        return false;
      }
      level.Version = version;
      level.GridHandle = gridHandle;
    }
  }
  for (int l = count; l < MaximumLevels; ++l)
  {
    // Levels of cascades no longer in use.
    vtkAOShaderUtilities::ReleaseTexture(this->Levels[l].Coarse, renWin);
    vtkAOShaderUtilities::ReleaseTexture(this->Levels[l].Distance, renWin);
    this->Levels[l] = Level();
  }
  // One program per number of grids (the shader cache keeps each): with one grid, the
  // per-fetch choice of grid compiles away. Without erosion, the program's march loop keeps
  // none of the code that tests the thinned walls (llvmpipe runs every branch of a loop's body
  // on each iteration).
  const bool erode = input.Settings.Erosion > 0.0;
  const int variant = 2 * count + (erode ? 1 : 0);
  if (this->Quad && this->QuadVariant != variant)
  {
    this->Quad.reset();
    this->ListQuad.reset();
  }
  this->QuadVariant = variant;
  this->QuadDefines = TracerDefines(count, erode);
  return vtkAOShaderUtilities::ReadyQuad(
    this->Quad, renWin, vtkAOVoxelTracerFS, this, "voxel tracer", this->QuadDefines);
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::SetLevelUniforms(vtkShaderProgram* program,
  const Grids& grids,
  vtkMatrix4x4* viewToWorld,
  const Parameters& par)
{
  const int count = std::min(static_cast<int>(grids.size()), MaximumLevels);
  float viewToGrid[MaximumLevels][16];
  float gridSize[MaximumLevels][3], coarseSize[MaximumLevels][3];
  float focusLo[MaximumLevels][3], focusHi[MaximumLevels][3];
  float cell[MaximumLevels];
  int skip[MaximumLevels];
  for (int l = 0; l < count; ++l)
  {
    vtkAOBitmaskVoxelizer* grid = grids[l];
    vtkNew<vtkMatrix4x4> m;
    vtkMatrix4x4::Multiply4x4(grid->GetWorldToGridMatrix(), viewToWorld, m);
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        viewToGrid[l][4 * c + r] = static_cast<float>(m->GetElement(r, c)); // column-major
      }
    }
    const int* dims = grid->GetGridDimensions();
    const double* focus = grid->GetFocusCells();
    for (int i = 0; i < 3; ++i)
    {
      gridSize[l][i] = static_cast<float>(dims[i]);
      coarseSize[l][i] = static_cast<float>(this->Levels[l].CoarseSize[i]);
      focusLo[l][i] = static_cast<float>(focus[2 * i]);
      focusHi[l][i] = static_cast<float>(focus[2 * i + 1]);
    }
    cell[l] = static_cast<float>(grid->GetCellSize());
    skip[l] = this->Levels[l].Skipping ? 1 : 0;
  }
  program->SetUniformMatrix4x4v("aoViewToGridL", count, &viewToGrid[0][0]);
  program->SetUniform3fv("aoGridSizeL", count, gridSize);
  program->SetUniform3fv("aoCoarseSizeL", count, coarseSize);
  program->SetUniform3fv("aoFocusLoL", count, focusLo);
  program->SetUniform3fv("aoFocusHiL", count, focusHi);
  program->SetUniform1fv("aoCellL", count, cell);
  program->SetUniform1iv("aoSkipL", count, skip);
  program->SetUniformf("aoRadius", static_cast<float>(par.Radius));
  program->SetUniformf("aoBias", static_cast<float>(par.Bias));
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::BindTracer(vtkShaderProgram* program,
  const Input& input,
  const Parameters& par)
{
  const Grids& grids = input.Cascades;
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(input.View, viewToWorld);

  input.GBuffer->BindViewGeometry(program, input.Projection, par.Parallel);
  this->Noise->Activate();
  program->SetUniformi("aoNoise", this->Noise->GetTextureUnit());
  const int count = std::min(static_cast<int>(grids.size()), MaximumLevels);
  for (int l = 0; l < count; ++l)
  {
    grids[l]->GetGridTexture()->Activate();
    this->Levels[l].Distance->Activate();
    const std::string suffix = std::to_string(l);
    program->SetUniformi(("aoGrid" + suffix).c_str(), grids[l]->GetGridTexture()->GetTextureUnit());
    program->SetUniformi(
      ("aoDistance" + suffix).c_str(), this->Levels[l].Distance->GetTextureUnit());
  }
  this->SetLevelUniforms(program, grids, viewToWorld, par);
  vtkAOShaderUtilities::SetMatrix(program, "aoViewToWorld", viewToWorld);
  program->SetUniformi("aoScale", par.Scale);
  program->SetUniformi("aoRays", par.Rays);
  program->SetUniformi("aoSteps", par.Steps);
  program->SetUniformi("aoFalloff", par.BinaryFalloff ? 1 : 0);
  program->SetUniformf("aoSelfSlope", static_cast<float>(par.SelfSlope));
  program->SetUniformf(
    "aoErosion", static_cast<float>(std::min(std::max(par.Erosion, 0.0), MaximumErosion)));
  program->SetUniformf(
    "aoSinSpread", static_cast<float>(std::sin(par.Spread * 0.5 * vtkMath::Pi())));
  // About two noise texels per cell of the finest grid: finer than the grid, coarser than
  // float noise.
  program->SetUniformf("aoNoiseScale",
    static_cast<float>(2.0 * par.NoiseFrequency / (grids[0]->GetCellSize() * NoiseSize)));
  // R3 (Roberts 2018): frame k adds k / phi3^(i+1) modulo 1 to noise channel i, where phi3
  // is the positive root of x^4 = x + 1. Frame 0 adds 0: the frame without accumulation.
  float jitter[3];
  const double phi3 = 1.22074408460575947536;
  double power = 1.0;
  for (int i = 0; i < 3; ++i)
  {
    power /= phi3;
    const double v = power * par.FrameIndex;
    jitter[i] = static_cast<float>(v - std::floor(v));
  }
  program->SetUniform3f("aoJitter", jitter);
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::UnbindTracer(const Input& input)
{
  const Grids& grids = input.Cascades;
  this->Noise->Deactivate();
  const int count = std::min(static_cast<int>(grids.size()), MaximumLevels);
  for (int l = 0; l < count; ++l)
  {
    this->Levels[l].Distance->Deactivate();
    grids[l]->GetGridTexture()->Deactivate();
  }
  input.GBuffer->UnbindViewGeometry();
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::Trace(const Input& input)
{
  const int scale = input.Settings.Scale;
  const int w = input.GBuffer->GetWidth(), h = input.GBuffer->GetHeight();
  const int lw = (w + scale - 1) / scale, lh = (h + scale - 1) / scale;
  vtkAOShaderUtilities::EnsureFloatTexture(this->Output, input.Window, lw, lh, 4);
  if (!this->Prepare(input))
  {
    return false;
  }
  this->BindTracer(this->Quad->Program, input, input.Settings);
  vtkAOShaderUtilities::DrawQuad(
    input.Window, this->FrameBufferObject, this->Quad.get(), this->Output);
  this->UnbindTracer(input);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::Refine(const Input& input,
  int rays,
  int filterRadius,
  vtkTextureObject* marks,
  vtkTextureObject* target)
{
  vtkOpenGLRenderWindow* renWin = input.Window;
  const Parameters& par = input.Settings;
  this->RefinedFraction = 0.0;
  if (!this->Output || par.Scale <= 1 || !target || !marks)
  {
    return true; // nothing reduced (or nothing marked): nothing to refine
  }
  const int w = input.GBuffer->GetWidth(), h = input.GBuffer->GetHeight();
  if (static_cast<int>(marks->GetWidth()) != w || static_cast<int>(marks->GetHeight()) != h ||
    static_cast<int>(target->GetWidth()) != w || static_cast<int>(target->GetHeight()) != h)
  {
    vtkErrorMacro("Refine: the marks and the target must be the G-buffer's size.");
    return false;
  }
  const bool filter = filterRadius > 0;
  if (!this->Prepare(input))
  {
    return false;
  }
  // The tracer at full resolution over the marked pixels.
  Parameters full = par;
  full.Scale = 1;
  full.Rays = rays > 0 ? rays : par.Rays;
  full.NoiseFrequency = par.NoiseFrequency * par.Scale;
  if (this->ListRefinement && this->RefineListed(input, full, filterRadius, marks, target))
  {
    vtkAOShaderUtilities::ReleaseTexture(this->Refined, renWin); // the listing needs no copy
    return true;
  }
  // In place, the filter reads a copy of the target (it writes the target's marked pixels).
  if (filter)
  {
    vtkAOShaderUtilities::EnsureFloatTexture(this->Refined, renWin, w, h, 2);
  }
  else
  {
    vtkAOShaderUtilities::ReleaseTexture(this->Refined, renWin);
  }
  if (filter &&
    !vtkAOShaderUtilities::ReadyQuad(
      this->FilterQuad, renWin, vtkAORefineFilterFS, this, "refinement filter"))
  {
    return false;
  }

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST); // the marks and the target cover the whole G-buffer
  if (filter)
  {
    this->CopyToRefined(renWin, target);
  }
  this->FrameBufferObject->SaveCurrentBindingsAndBuffers();
  this->FrameBufferObject->Bind();
  this->FrameBufferObject->AddColorAttachment(0, filter ? this->Refined : target);
  this->FrameBufferObject->AddDepthAttachment(marks);
  ostate->vtkglDrawBuffer(GL_NONE);
  this->FrameBufferObject->ActivateDrawBuffers(1);
  this->FrameBufferObject->StartNonOrtho(w, h);
  ostate->vtkglViewport(0, 0, w, h);

  // In place: the quad lies at depth 0.5, so GL_GREATER passes where the marks are 0; the
  // others are rejected before shading.
  renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program, nullptr);
  this->BindTracer(this->Quad->Program, input, full);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE); // A and coverage
  if (!this->SamplesQuery)
  {
    glGenQueries(1, &this->SamplesQuery);
  }
  glBeginQuery(GL_SAMPLES_PASSED, this->SamplesQuery);
  this->Quad->Render();
  glEndQuery(GL_SAMPLES_PASSED);
  this->QueryPending = true;
  this->QueryPixels = static_cast<double>(w) * h;
  this->UnbindTracer(input);

  if (filter)
  {
    // The marked pixels, denoised, into the target.
    this->FrameBufferObject->AddColorAttachment(0, target);
    this->FrameBufferObject->ActivateDrawBuffers(1);
    vtkShaderProgram* program = this->FilterQuad->Program;
    renWin->GetShaderCache()->ReadyShaderProgram(program);
    input.GBuffer->BindViewGeometry(program, input.Projection, par.Parallel);
    this->Refined->Activate();
    program->SetUniformi("aoRefined", this->Refined->GetTextureUnit());
    program->SetUniformi("aoTaps", filterRadius);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE); // A and coverage
    this->FilterQuad->Render();
    this->Refined->Deactivate();
    input.GBuffer->UnbindViewGeometry();
  }

  this->FrameBufferObject->RemoveDepthAttachment();
  this->FrameBufferObject->UnBind();
  this->FrameBufferObject->RestorePreviousBindingsAndBuffers();
  return true;
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::CopyToRefined(vtkOpenGLRenderWindow* renWin, vtkTextureObject* target)
{
  // The filter's input: a copy of the upsampled map, the refined samples drawn over it. Of
  // the fragment operations only the scissor test applies to a blit: off, the whole map.
  const int w = static_cast<int>(target->GetWidth()), h = static_cast<int>(target->GetHeight());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  vtkOpenGLFramebufferObject* fbo = this->FrameBufferObject;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  fbo->AddColorAttachment(0, this->Refined);
  fbo->AddColorAttachment(1, target);
  fbo->ActivateReadBuffer(1);
  fbo->ActivateDrawBuffer(0);
  ostate->vtkglBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  fbo->RemoveColorAttachment(1);
  fbo->RemoveColorAttachment(0);
  fbo->ActivateReadBuffer(0);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
bool vtkAOVoxelTracer::RefineListed(const Input& input,
  const Parameters& full,
  int filterRadius,
  vtkTextureObject* marks,
  vtkTextureObject* target)
{
  vtkOpenGLRenderWindow* renWin = input.Window;
  const bool filter = filterRadius > 0;
  if (this->ListUnavailable)
  {
    return false;
  }
  // The programs first: a context that cannot compile them must not pay for the listing.
  if (!vtkAOShaderUtilities::ReadyQuad(this->ListQuad,
        renWin,
        vtkAOVoxelTracerFS,
        this,
        "voxel tracer (listed pixels)",
        this->QuadDefines + "\n#define AO_LIST") ||
    (filter &&
      !vtkAOShaderUtilities::ReadyQuad(this->ListFilterQuad,
        renWin,
        vtkAORefineFilterFS,
        this,
        "refinement filter (listed pixels)",
        "#define AO_LIST")))
  {
    this->ListUnavailable = true; // in place from now on (until the resources are released)
    return false;
  }
  if (!this->List->Build(renWin, marks))
  {
    return false;
  }
  const int count = this->List->GetCount();
  this->RefinedFraction =
    static_cast<double>(count) / (static_cast<double>(marks->GetWidth()) * marks->GetHeight());
  this->QueryPending = false;
  if (count == 0)
  {
    return true;
  }
  // (DrawDense and Scatter each set and restore the GL state they need.) The refined samples
  // go straight into the target: the filter then reads the target (the refined pixels holding
  // their trace, the others their upsampled A) and writes the dense rectangle, which is
  // scattered over the same pixels again; no pass reads the texture it writes.

  // The marked pixels traced densely, then written to their pixels.
  vtkShaderProgram* program = this->ListQuad->Program;
  if (!renWin->GetShaderCache()->ReadyShaderProgram(program))
  {
    return false;
  }
  this->BindTracer(program, input, full);
  this->List->Bind(program);
  this->List->DrawDense(renWin, this->ListQuad.get());
  this->List->Unbind();
  this->UnbindTracer(input);
  if (!this->List->Scatter(renWin, target))
  {
    return false;
  }
  if (filter)
  {
    // Each denoised among its surface's pixels (the refined ones now hold their trace).
    program = this->ListFilterQuad->Program;
    if (!renWin->GetShaderCache()->ReadyShaderProgram(program))
    {
      return false;
    }
    input.GBuffer->BindViewGeometry(program, input.Projection, full.Parallel);
    target->Activate();
    program->SetUniformi("aoRefined", target->GetTextureUnit());
    program->SetUniformi("aoTaps", filterRadius);
    this->List->Bind(program);
    this->List->DrawDense(renWin, this->ListFilterQuad.get());
    this->List->Unbind();
    target->Deactivate();
    input.GBuffer->UnbindViewGeometry();
    if (!this->List->Scatter(renWin, target))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::ReleaseRefinement(vtkOpenGLRenderWindow* renWin)
{
  this->FilterQuad.reset();
  this->ListQuad.reset();
  this->ListFilterQuad.reset();
  this->ListUnavailable = false;
  this->List->ReleaseGraphicsResources(renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Refined, renWin);
  this->RefinedFraction = 0.0;
  this->QueryPending = false;
}

//------------------------------------------------------------------------------
double vtkAOVoxelTracer::GetRefinedFraction()
{
  if (this->QueryPending && this->SamplesQuery)
  {
    GLuint samples = 0;
    glGetQueryObjectuiv(this->SamplesQuery, GL_QUERY_RESULT, &samples);
    this->RefinedFraction = this->QueryPixels > 0 ? samples / this->QueryPixels : 0.0;
    this->QueryPending = false;
  }
  return this->RefinedFraction;
}

//------------------------------------------------------------------------------
void vtkAOVoxelTracer::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  this->CoarseQuad.reset();
  if (this->SamplesQuery && renWin)
  {
    glDeleteQueries(1, &this->SamplesQuery);
  }
  this->SamplesQuery = 0;
  this->QueryPending = false;
  this->FilterQuad.reset();
  this->ListQuad.reset();
  this->ListFilterQuad.reset();
  this->ListUnavailable = false;
  this->List->ReleaseGraphicsResources(w);
  vtkAOShaderUtilities::ReleaseTexture(this->Refined, renWin);
  vtkAOShaderUtilities::ReleaseTexture(this->Noise, renWin);
  for (Level& level : this->Levels)
  {
    vtkAOShaderUtilities::ReleaseTexture(level.Coarse, renWin);
    vtkAOShaderUtilities::ReleaseTexture(level.Distance, renWin);
    level = Level();
  }
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
long long vtkAOVoxelTracer::GetGraphicsMemorySize()
{
  long long bytes = this->Superclass::GetGraphicsMemorySize() +
    vtkAOShaderUtilities::TextureBytes(this->Noise) +
    vtkAOShaderUtilities::TextureBytes(this->Refined) + this->List->GetGraphicsMemorySize();
  for (const Level& level : this->Levels)
  {
    bytes += vtkAOShaderUtilities::TextureBytes(level.Coarse) +
      vtkAOShaderUtilities::TextureBytes(level.Distance);
  }
  return bytes;
}
