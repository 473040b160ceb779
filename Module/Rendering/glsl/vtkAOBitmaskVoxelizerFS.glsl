  // Bitmask voxelization (Eisemann & Decoret 2006; HAO section 5): the fragment's depth
  // slice selects one bit of the 32-bit words along the voxel camera's view direction; the
  // framebuffer ORs it in (glLogicOp(GL_OR)).
  {
    // Conservative along the slices: a slanted polygon sets every slice its pixel spans, so
    // its voxels form a closed surface rather than a dotted one. The span comes from the
    // depth derivatives, which extrapolate the polygon's plane across the whole pixel: for
    // polygons seen almost edge-on that plane leaves the polygon by many slices and would
    // grow spikes out of the surface (stray voxels that occlude what is near them). The span
    // is therefore bounded to slopes of 3 slices per pixel (72 degrees from face-on); steeper
    // polygons are rare under the rotated voxel camera and are covered by their neighbours.
    float aoDepth = gl_FragCoord.z * float(aoVoxelSlices);
    vec2 aoSlope = abs(vec2(dFdx(aoDepth), dFdy(aoDepth)));
    float aoHalfSpan = min(0.5 * (aoSlope.x + aoSlope.y), 1.5);
    // With several voxelization axes, a polygon is left to the axis it faces more.
    if (any(greaterThan(aoSlope, aoSlopeLimit)))
    {
      discard;
    }
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
