  // Bitmask voxelization (Eisemann & Decoret 2006; HAO section 5): the fragment's depth
  // slice selects one bit of the 32-bit words along the voxel camera's view direction; the
  // framebuffer ORs it in (glLogicOp(GL_OR)).
  {
    int aoSlice = clamp(int(gl_FragCoord.z * float(aoVoxelSlices)), 0, aoVoxelSlices - 1);
    uint aoBit = 1u << uint(aoSlice & 31);
    int aoWord = aoSlice >> 5;
    //AO::Voxel::Outputs
  }
