  // Bitmask voxelization (Eisemann & Decoret 2006; HAO section 5): the fragment's depth
  // slice selects one bit of the 32-bit words along the voxel camera's view direction; the
  // framebuffer ORs it in (glLogicOp(GL_OR)).
  {
    // Conservative along the slices: a slanted polygon sets every slice its pixel spans, so
    // its voxels form a closed surface rather than a dotted one (at most 32 slices).
    float aoDepth = gl_FragCoord.z * float(aoVoxelSlices);
    float aoHalfSpan = 0.5 * fwidth(aoDepth);
    int aoFirst = clamp(int(aoDepth - aoHalfSpan), 0, aoVoxelSlices - 1);
    int aoLast = clamp(int(aoDepth + aoHalfSpan), aoFirst, min(aoFirst + 31, aoVoxelSlices - 1));
    uvec4 aoWords[8];
    for (int w = 0; w < 8; ++w)
    {
      aoWords[w] = uvec4(0u);
    }
    for (int aoSlice = aoFirst; aoSlice <= aoLast; ++aoSlice)
    {
      int aoWord = aoSlice >> 5;
      aoWords[aoWord >> 2][aoWord & 3] |= 1u << uint(aoSlice & 31);
    }
    //AO::Voxel::Outputs
  }
