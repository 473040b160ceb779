//VTK::System::Dec
// Multi-axis voxelization: the grids rendered along the grid's x and y axes, transposed into
// the grid's own layout (texel (x, y, z / 128), bits along z) and ORed in by the logic op.
// Along x the pixels are (y, z) and the bits x; along y the pixels are (z, x) and the bits y.
// Each grid's column summary (vtkAOBitmaskVoxelizer::SummarizeAxis) skips the columns it leaves
// empty.
in vec2 texCoord;
uniform usampler3D aoAxisX;
uniform usampler3D aoAxisY;
uniform usampler2D aoSummaryX; // (y, x / 128): the x bits any slice of the x grid holds
uniform usampler2D aoSummaryY; // (x, y / 128): the y bits any slice of the y grid holds
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
  // Only the columns a polygon of that axis occupies (most are empty).
  if (aoBit(texelFetch(aoSummaryX, ivec2(ij.y, ij.x >> 7), 0), ij.x) != 0u)
  {
    for (int k = 0; k < size.z; ++k)
    {
      uint bit = aoBit(texelFetch(aoAxisX, ivec3(ij.y, k, ij.x >> 7), 0), ij.x);
      words[k >> 7][(k >> 5) & 3] |= bit << uint(k & 31);
    }
  }
  if (aoAxes > 2 && aoBit(texelFetch(aoSummaryY, ivec2(ij.x, ij.y >> 7), 0), ij.y) != 0u)
  {
    for (int k = 0; k < size.z; ++k)
    {
      uint bit = aoBit(texelFetch(aoAxisY, ivec3(k, ij.x, ij.y >> 7), 0), ij.y);
      words[k >> 7][(k >> 5) & 3] |= bit << uint(k & 31);
    }
  }
//AO::Merge::Outputs
}
