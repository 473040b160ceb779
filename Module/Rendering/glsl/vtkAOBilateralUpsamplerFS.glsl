//VTK::System::Dec
// Joint bilateral upsampling of the AO map (HAO section 7, eq. 5-7), one axis of the
// separable approximation (eq. 8). The sum runs over the input samples on that axis within
// the m x m window; each sample stands for the full-resolution pixel it was taken at, so its
// position and normal are those of that pixel. The input carries them with A (see below), so
// a tap is a single fetch; the first pass writes the same layout for the second.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
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
//VTK::Output::Dec

//AO::Common

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
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 1.0, 0.0);
    return;
  }
  vec3 px = aoViewPosition(x, depth);
  vec3 nx = aoViewNormal(x, px);
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
