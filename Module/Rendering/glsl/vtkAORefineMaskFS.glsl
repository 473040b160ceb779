//VTK::System::Dec
// Refinement mask of Hybrid Ambient Occlusion: marks (depth 0) the full-resolution pixels that
// the reduced AO map cannot represent, so that the tracer runs again for them alone (the
// stencil pattern of mixed-resolution rendering, GPU Gems 3 ch. 23). A pixel is represented
// when one of the (up to) four AO-map samples around it lies on its own surface: its normal
// within aoNormalCos and its position within aoPlaneTolerance pixel footprints of the pixel's
// tangent plane. Elsewhere (silhouettes, creases, fins or ribs finer than a texel) the joint
// bilateral filter could only borrow the occlusion of another surface. A pixel is also marked
// where those samples' A differ by more than aoContrast: the occlusion changes within a texel
// (contacts, the floors of narrow gaps between fins), and interpolation would blur or alias it.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform sampler2D aoMap;     // the reduced map: r = A, g = coverage, b = depth, a = normal
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoScale;
uniform float aoNormalCos;
uniform float aoPlaneTolerance;
uniform float aoContrast;
//VTK::Output::Dec

//AO::Common

void main()
{
  ivec2 pix = min(ivec2(texCoord * vec2(aoFullSize)), aoFullSize - 1);
  float depth = texelFetch(aoDepth, pix, 0).r;
  gl_FragDepth = 1.0;
  if (depth >= 1.0)
  {
    return;
  }
  vec3 p = aoViewPosition(pix, depth);
  vec3 n = aoViewNormal(pix, p);
  // One pixel's width at p's depth, in view units.
  ivec2 side = ivec2(pix.x > 0 ? -1 : 1, 0);
  float footprint = length(aoViewPosition(pix + side, depth) - p);
  float tolerance = aoPlaneTolerance * footprint * float(aoScale);
  ivec2 mapSize = textureSize(aoMap, 0);
  // The samples whose pixels bracket this one (sample of texel c: pixel c * scale + scale / 2).
  ivec2 base = (pix - ivec2(aoScale / 2) + ivec2(aoScale)) / aoScale - 1;
  bool matched = false;
  float lo = 1.0, hi = 0.0;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      ivec2 c = clamp(base + ivec2(i, j), ivec2(0), mapSize - 1);
      vec4 s = texelFetch(aoMap, c, 0);
      if (s.g <= 0.0 || s.b >= 1.0)
      {
        continue;
      }
      ivec2 sp = min(c * aoScale + ivec2(aoScale / 2), aoFullSize - 1);
      vec3 ps = aoViewPosition(sp, s.b);
      vec3 ns = aoUnpackNormal(s.a);
      matched = matched || (dot(ns, n) >= aoNormalCos && abs(dot(n, ps - p)) <= tolerance);
      lo = min(lo, s.r);
      hi = max(hi, s.r);
    }
  }
  gl_FragDepth = matched && hi - lo <= aoContrast ? 1.0 : 0.0;
}
