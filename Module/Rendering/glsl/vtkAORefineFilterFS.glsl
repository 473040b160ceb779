//VTK::System::Dec
// Denoising of Hybrid AO's refined pixels. The refinement traces the marked pixels at full
// resolution with the map's few rays; everywhere else the joint bilateral filter has averaged
// the map's samples, so unfiltered refined pixels would stand out as speckle (on curved or
// faceted surfaces, where many pixels are marked). This pass runs over the marked pixels only
// (listed, AO_LIST: the dense rectangle of vtkAOPixelList; in place: the marks as its depth
// attachment) and replaces each by the mean of the pixels in a
// (2 aoTaps + 1)^2 window (Wendland-weighted by distance) that lie on its own surface: their
// normals within 26 degrees of its own and their positions within (1 + d) pixel footprints of
// its tangent plane, d their distance in pixels, so that it never borrows another fin's,
// rib's or object's occlusion (the reason the pixel was marked). Those neighbours hold their
// refined A where they were refined too, their upsampled A elsewhere (equal weights measured
// best: Documentation/quality.md).
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform sampler2D aoFacet;   // the polygon's plane (vtkAOGBufferPass), for the normal's side
uniform sampler2D aoRefined; // full resolution: r = A (refined or upsampled), g = coverage
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoTaps;
//VTK::Output::Dec

//AO::Common

void main()
{
#ifdef AO_LIST
  // Over a list of pixels (vtkAOPixelList): fragment i of the dense rectangle filters entry i.
  int i = aoListEntry(texCoord);
  if (i < 0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 0.0, 0.0); // past the list's end: never scattered
    return;
  }
  ivec2 x = aoListPixel(i);
#else
  ivec2 x = min(ivec2(texCoord * vec2(aoFullSize)), aoFullSize - 1);
#endif
  float depth = texelFetch(aoDepth, x, 0).r;
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 0.0, 0.0); // not marked: never drawn
    return;
  }
  vec3 px = aoViewPosition(x, depth);
  vec3 nx = aoVisibleSide(aoViewNormal(x, px), texelFetch(aoFacet, x, 0), px);
  float footprint = aoPixelFootprint(px);
  float sum = 0.0;
  float weights = 0.0;
  for (int j = -aoTaps; j <= aoTaps; ++j)
  {
    for (int i = -aoTaps; i <= aoTaps; ++i)
    {
      ivec2 y = x + ivec2(i, j);
      if (any(lessThan(y, ivec2(0))) || any(greaterThanEqual(y, aoFullSize)))
      {
        continue;
      }
      float dy = texelFetch(aoDepth, y, 0).r;
      if (dy >= 1.0)
      {
        continue; // background
      }
      vec3 py = aoViewPosition(y, dy);
      vec3 ny = aoVisibleSide(aoViewNormal(y, py), texelFetch(aoFacet, y, 0), py);
      float d = length(vec2(i, j));
      float w = aoWendland(d, float(aoTaps) + 1.0) * aoWendland(1.0 - dot(nx, ny), 0.1) *
        aoWendland(abs(dot(nx, py - px)), footprint * (1.0 + d));
      sum += w * texelFetch(aoRefined, y, 0).r;
      weights += w;
    }
  }
  // The centre always counts (weight 1), so weights > 0.
  gl_FragData[0] = vec4(sum / weights, 1.0, 0.0, 0.0);
}
