//VTK::System::Dec
// Ambient Occlusion Volumes, before the volumes: the initial AO map. Each texel
// stands for one full-resolution pixel (aoOffset in its aoScale x aoScale block: the centre,
// as vtkAOVoxelTracer samples, or the accumulated frame's pixel of the block) and
// starts at A = 1 with that pixel's coverage, window depth and packed normal: the layout the
// bilateral upsampler and the compositor read. The volumes then subtract their occlusion
// from r only. A second target holds, per texel, the lifted point x = p + Bias n in view space
// and its packed normal (w < 0 on the background), so the volumes' fragments read x and n with
// one fetch; and the depth attachment gets the pixel's depth, so the rasterizer rejects a
// volume's fragments where the visible surface lies beyond the volume.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform sampler2D aoFacet; // the polygon's plane (vtkAOGBufferPass), for the normal's side
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoScale;
uniform ivec2 aoOffset; // the texel's pixel in its block
uniform float aoBias;
//VTK::Output::Dec

//AO::Common

void main()
{
  ivec2 lowSize = (aoFullSize + ivec2(aoScale - 1)) / aoScale;
  ivec2 lowPix = min(ivec2(texCoord * vec2(lowSize)), lowSize - 1);
  ivec2 pix = min(lowPix * aoScale + aoOffset, aoFullSize - 1);
  float depth = texelFetch(aoDepth, pix, 0).r;
  gl_FragDepth = depth;
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 1.0, 0.0);
    gl_FragData[1] = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  vec3 p = aoViewPosition(pix, depth);
  vec4 facet = texelFetch(aoFacet, pix, 0);
  vec3 n = aoVisibleSide(aoViewNormal(pix, p), facet, p);
  float code = aoPackNormal(n);
  gl_FragData[0] = vec4(1.0, 1.0, depth, code);
  // The volumes use the normal as packed, as the upsampler and compositor see it.
  gl_FragData[1] = vec4(p + aoBias * aoUnpackNormal(code), code);
}
