//VTK::System::Dec
// Multi-axis voxelization: the grids rendered along the grid's x and y axes, transposed into
// the grid's own layout (texel (x, y, z / 128), bits along z) and ORed in by the logic op.
// Along x the pixels are (y, z) and the bits x; along y the pixels are (z, x) and the bits y.
// Each grid's summary (vtkAOBitmaskVoxelizer::SummarizeAxis) skips the runs of 32 slices it
// leaves empty in a column.
in vec2 texCoord;
uniform usampler3D aoAxisX;
uniform usampler3D aoAxisY;
uniform usampler2D aoSummaryX; // (y, z / 32 * layers + x / 128): the x bits any of those 32
                               // slices of the x grid holds
uniform usampler2D aoSummaryY; // (x, z / 32 * layers + y / 128): the same for the y grid
uniform int aoAxes;            // 2: no y grid
uniform vec3 aoGridSize;
//AO::Merge::Dec

uint aoBit(uvec4 words, int index)
{
  return (words[(index >> 5) & 3] >> uint(index & 31)) & 1u;
}

void main()
{
  ivec3 size = ivec3(aoGridSize);
  ivec2 ij = min(ivec2(texCoord * aoGridSize.xy), size.xy - 1);
  uvec4 words[8];
  for (int w = 0; w < 8; ++w)
  {
    words[w] = uvec4(0u);
  }
  // Only the runs of 32 slices in which a polygon of that axis touches the column (most
  // columns are empty, and a polygon tilted towards its axis crosses a column in few slices).
  ivec3 sizeX = textureSize(aoAxisX, 0);
  ivec3 sizeY = textureSize(aoAxisY, 0);
  for (int run = 0; 32 * run < size.z; ++run)
  {
    uint word = 0u;
    int k0 = 32 * run;
    int k1 = min(k0 + 32, size.z);
    if (aoBit(texelFetch(aoSummaryX, ivec2(ij.y, run * sizeX.z + (ij.x >> 7)), 0), ij.x) != 0u)
    {
      for (int k = k0; k < k1; ++k)
      {
        word |= aoBit(texelFetch(aoAxisX, ivec3(ij.y, k, ij.x >> 7), 0), ij.x) << uint(k - k0);
      }
    }
    if (aoAxes > 2 &&
      aoBit(texelFetch(aoSummaryY, ivec2(ij.x, run * sizeY.z + (ij.y >> 7)), 0), ij.y) != 0u)
    {
      for (int k = k0; k < k1; ++k)
      {
        word |= aoBit(texelFetch(aoAxisY, ivec3(k, ij.x, ij.y >> 7), 0), ij.y) << uint(k - k0);
      }
    }
    words[k0 >> 7][(k0 >> 5) & 3] |= word;
  }
//AO::Merge::Outputs
}
