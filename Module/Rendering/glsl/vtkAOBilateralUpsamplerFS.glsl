//VTK::System::Dec
// Joint bilateral upsampling of the AO map (HAO section 7, eq. 5-7), one axis of the
// separable approximation (eq. 8). The sum runs over the input samples on that axis within
// the m x m window; each sample stands for the full-resolution pixel it was taken at, so its
// position and normal are those of that pixel. The input carries them with A (see below), so
// a tap is a single fetch; the first pass writes the same layout for the second. Normals are
// compared on their polygon's visible side (aoVisibleSide), as the rays use them: where a
// coarse mesh's interpolated normal crosses its polygon's plane the contract turns it over,
// and a pixel on the turned side must not take the A of samples on the other.
//
// Compiled with AO_MARK, the second pass also writes the refinement marks of Hybrid AO into the
// depth attachment (0: the pixel needs its own full-resolution trace, 1: it does not), so that
// the tracer runs again for those pixels alone (the stencil pattern of mixed-resolution
// rendering, GPU Gems 3 ch. 23). This pass already has the pixel's position and normal, so the
// marks cost four fetches of the reduced map, not a full-screen pass of their own. A pixel is
// marked where the (up to) four map samples around it disagree by more than aoContrast in A
// (the occlusion changes within a texel: contacts, the floors of narrow gaps between fins),
// or where none of them lies on its own surface: normal within aoNormalCos and position within
// aoPlaneTolerance reduced texels of the pixel's tangent plane (silhouettes, creases, fins or
// ribs finer than a texel), where the filter could only borrow another surface's occlusion.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform sampler2D aoFacet;   // the polygon's plane (vtkAOGBufferPass), for the normal's side
uniform sampler2D aoInput;   // r = A, g = 1 where a sample exists, b = window depth of the
                             // pixel it stands for, a = its normal (aoPackNormal)
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoScale;         // full-resolution pixels per input texel along the filtered axis
uniform int aoHorizontal;    // 1: first pass (x), 0: second pass (y)
uniform int aoTaps;          // input texels each side of the centre
uniform float aoWindow;      // m, in full-resolution pixels
uniform float aoRadius;      // d_max, view units
#ifdef AO_MARK
uniform sampler2D aoMap;     // the reduced map (the first pass's input), for the marks
uniform float aoNormalCos;
uniform float aoPlaneTolerance;
uniform float aoContrast;
#endif
//VTK::Output::Dec

//AO::Common

#ifdef AO_MARK
// Whether the reduced map represents full-resolution pixel pix at p with normal n (above).
bool aoRepresented(ivec2 pix, vec3 p, vec3 n)
{
  ivec2 mapSize = textureSize(aoMap, 0);
  // The samples whose pixels bracket this one (sample of texel c: pixel c * scale + scale / 2).
  ivec2 base = (pix - ivec2(aoScale / 2) + ivec2(aoScale)) / aoScale - 1;
  vec4 s[4];
  float lo = 1.0, hi = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    s[k] = texelFetch(aoMap, clamp(base + ivec2(k & 1, k >> 1), ivec2(0), mapSize - 1), 0);
    if (s[k].g > 0.0 && s[k].b < 1.0)
    {
      lo = min(lo, s[k].r);
      hi = max(hi, s[k].r);
    }
  }
  if (hi - lo > aoContrast)
  {
    return false; // contrast first: it needs no geometry
  }
  float tolerance = aoPlaneTolerance * aoPixelFootprint(p) * float(aoScale);
  for (int k = 0; k < 4; ++k)
  {
    if (s[k].g <= 0.0 || s[k].b >= 1.0)
    {
      continue;
    }
    ivec2 c = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), mapSize - 1);
    ivec2 sp = min(c * aoScale + ivec2(aoScale / 2), aoFullSize - 1);
    if (dot(aoUnpackNormal(s[k].a), n) >= aoNormalCos &&
      abs(dot(n, aoViewPosition(sp, s[k].b) - p)) <= tolerance)
    {
      return true;
    }
  }
  return false;
}
#endif

void main()
{
  ivec2 hi = aoFullSize - 1;
  ivec2 inSize = textureSize(aoInput, 0);
  ivec2 outSize = aoHorizontal != 0 ? ivec2(aoFullSize.x, inSize.y) : aoFullSize;
  ivec2 o = min(ivec2(texCoord * vec2(outSize)), outSize - 1);
  // The full-resolution pixel this output texel stands for, and the input texel holding it.
  ivec2 x = aoHorizontal != 0 ? ivec2(o.x, min(o.y * aoScale + aoScale / 2, hi.y)) : o;
  ivec2 c = aoHorizontal != 0 ? ivec2(min(x.x / aoScale, inSize.x - 1), o.y)
                              : ivec2(o.x, min(x.y / aoScale, inSize.y - 1));
  ivec2 axis = aoHorizontal != 0 ? ivec2(1, 0) : ivec2(0, 1);

  float depth = texelFetch(aoDepth, x, 0).r;
  vec2 hc = texelFetch(aoInput, c, 0).rg;
#ifdef AO_MARK
  gl_FragDepth = 1.0; // not marked
#endif
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 1.0, 0.0);
    return;
  }
  vec3 px = aoViewPosition(x, depth);
  // On its polygon's visible side, as the map's samples carry theirs (aoSampleAt).
  vec3 nx = aoVisibleSide(aoViewNormal(x, px), texelFetch(aoFacet, x, 0), px);
#ifdef AO_MARK
  if (!aoRepresented(x, px, nx))
  {
    gl_FragDepth = 0.0;
  }
#endif
  // Only the first pass's output is filtered again (and needs its normal); the second's is
  // read for A and coverage only.
  float outNormal = aoHorizontal != 0 ? aoPackNormal(nx) : 0.0;

  // Where every sample in the window has (nearly) the same A, so has any weighted mean of
  // them: skip the weights (most of a frame is open or evenly occluded surface). The result
  // differs from the full sum by less than the spread tested, 1/1024.
  float lo = 2.0;
  float top = -1.0;
  for (int i = -aoTaps; i <= aoTaps; ++i)
  {
    ivec2 ci = clamp(c + axis * i, ivec2(0), inSize - 1);
    vec4 h = texelFetch(aoInput, ci, 0);
    if (h.g > 0.0 && h.b < 1.0)
    {
      lo = min(lo, h.r);
      top = max(top, h.r);
    }
  }
  if (top - lo <= 1.0 / 1024.0)
  {
    gl_FragData[0] = vec4(top >= 0.0 ? 0.5 * (lo + top) : (hc.g > 0.0 ? hc.r : 1.0), 1.0, depth,
      outNormal);
    return;
  }

  float sum = 0.0;
  float weights = 0.0;
  for (int i = -aoTaps; i <= aoTaps; ++i)
  {
    ivec2 ci = c + axis * i;
    if (any(lessThan(ci, ivec2(0))) || any(greaterThanEqual(ci, inSize)))
    {
      continue;
    }
    vec4 h = texelFetch(aoInput, ci, 0);
    if (h.g <= 0.0 || h.b >= 1.0)
    {
      continue;
    }
    ivec2 y = aoHorizontal != 0 ? ivec2(min(ci.x * aoScale + aoScale / 2, hi.x), x.y)
                                : ivec2(x.x, min(ci.y * aoScale + aoScale / 2, hi.y));
    vec3 py = aoViewPosition(y, h.b);
    vec3 ny = aoUnpackNormal(h.a);
    float wd = aoWendland(length(vec2(x - y)), aoWindow);            // eq. 6
    float wn = aoWendland(1.0 - dot(nx, ny), 2.0);                   // eq. 7, normals
    float wp = aoWendland(length(px - py), aoRadius);                // eq. 7, positions
    float wh = hc.g > 0.0 ? aoWendland(abs(hc.r - h.r), 1.0) : 1.0;  // eq. 7, AO values
    float w = wd * wn * wp * wh;
    sum += w * h.r;
    weights += w;
  }
  float a = weights > 1e-6 ? sum / weights : (hc.g > 0.0 ? hc.r : 1.0);
  gl_FragData[0] = vec4(a, 1.0, depth, outNormal);
}
