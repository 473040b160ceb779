//VTK::System::Dec
//AO::VolumeClass
// Ambient Occlusion Volumes (McGuire 2010), stage 3 of 3 (drawn into the AO map, one texel per
// AOScale x AOScale pixels, each evaluated at the pixel vtkAOVolumeInitFS chose): for each pixel covered by the volume
// of a triangle P, the occlusion P casts on the visible point x (normal n) of that pixel:
//
//   O_P(x) = 1/pi * Integral over the directions w that hit P of W(d(x, w)) <n, w> dw
//
// (ao-definition.md, per polygon; the blend combines them). Without the falloff it is the
// form factor of P clipped to the tangent plane, AOV eq. 1: the sum over P's edges of the
// projected areas of the spherical segments. The falloff is honoured exactly in distance,
// approximately in shape: with F(s) the form factor of P clipped to the ball of radius s about
// x, O_P = Integral W(t) dF(t) = W(dmax) F(dmax) + Integral from dmin to dmax of -W'(s) F(s) ds,
// evaluated by 3-point Gauss-Legendre quadrature; the ball's cut through P's plane (a disc) is
// replaced by the regular octagon of the same area. Binary falloff: O_P = F(R). A triangle
// small against R takes W at its centroid's distance: all of them in the draw of triangles
// whose longest edge is at most R/4 (AO_LARGE_TRIANGLES 0, a program without the quadrature),
// and in the other draw where dmax - dmin <= R/4 with all of the triangle within R.
flat in vec3 aoP0;
flat in vec3 aoP1;
flat in vec3 aoP2;
flat in float aoTwoSided;
uniform sampler2D aoDepth;      // declared for AO::Common, unused here
uniform sampler2D aoNormal;
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform sampler2D aoPoints; // per texel: lifted point x (view space), packed normal (< 0: none)
uniform float aoRadius;
uniform int aoBinary;
//VTK::Output::Dec

//AO::Common

const float aoPi = 3.14159265358979;

// The edge term of eq. 1 for the edge (a, b), vertices relative to the point.
float aoEdge(vec3 a, vec3 b, vec3 n)
{
  a = normalize(a);
  b = normalize(b);
  vec3 c = cross(a, b);
  float s = length(c);
  return s > 1e-12 ? atan(s, dot(a, b)) * dot(n, c) / s : 0.0;
}

// Narrow the parameter range [t0, t1] of the segment a + t (b - a) to where dot(m, y) <= c
// (an empty range ends with t1 < t0). Branch-free: no compaction, no indexed arrays.
void aoClipSegment(vec3 a, vec3 b, vec3 m, float c, inout float t0, inout float t1)
{
  float da = dot(m, a) - c;
  float db = dot(m, b) - c;
  float t = da / (da - db); // used only where the signs differ
  bool aOut = da > 0.0;
  bool bOut = db > 0.0;
  t0 = aOut && !bOut ? max(t0, t) : t0;
  t1 = bOut && !aOut ? min(t1, t) : t1;
  t1 = aOut && bOut ? -1.0 : t1;
}

// The edge term of the part of the segment (a, b) inside the range [t0, t1].
float aoClippedEdge(vec3 a, vec3 b, float t0, float t1, vec3 n)
{
  vec3 e = b - a;
  return t1 > t0 ? aoEdge(a + t0 * e, a + t1 * e, n) : 0.0;
}

// F(s): the form factor of the convex polygon v0..v3 (counter-clockwise about `plane`; v3 = v0
// for a triangle) cut to the ball of radius s about the origin. The ball meets P's plane in a
// disc (centre `foot`, radius sqrt(s^2 - h^2)), replaced by the regular octagon of the same
// area with edge normals along t1 rotated by multiples of 45 degrees. The cut's boundary is
// the polygon's edges clipped to the octagon plus the octagon's edges clipped to the polygon,
// all counter-clockwise, so eq. 1 sums over those 12 segments.
float aoBallFormFactor(vec3 v0, vec3 v1, vec3 v2, vec3 v3, vec3 n, vec3 plane, vec3 foot,
  float h, vec3 t1, vec3 t2, float s)
{
  float rho2 = s * s - h * h;
  if (rho2 <= 0.0)
  {
    return 0.0;
  }
  // Apothem of the regular octagon with the disc's area: rho * sqrt(pi / (8 tan(pi/8))); its
  // circumradius is apothem / cos(pi/8).
  float apothem = sqrt(rho2) * 0.973682;
  float circumradius = apothem * 1.0823922;
  vec3 pv[4] = vec3[4](v0, v1, v2, v3);
  vec3 edgeNormal[8];
  vec3 corner[8];
  for (int j = 0; j < 8; ++j)
  {
    float angle = float(j) * (aoPi / 4.0);
    edgeNormal[j] = cos(angle) * t1 + sin(angle) * t2;
    float between = angle + aoPi / 8.0; // the corner between edges j and j + 1
    corner[j] = foot + circumradius * (cos(between) * t1 + sin(between) * t2);
  }
  float sum = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    vec3 a = pv[i];
    vec3 b = pv[i == 3 ? 0 : i + 1];
    float lo = 0.0;
    float hi = 1.0;
    for (int j = 0; j < 8; ++j)
    {
      aoClipSegment(a, b, edgeNormal[j], apothem + dot(edgeNormal[j], foot), lo, hi);
    }
    sum += aoClippedEdge(a, b, lo, hi, n);
  }
  for (int j = 0; j < 8; ++j)
  {
    vec3 a = corner[j == 0 ? 7 : j - 1];
    vec3 b = corner[j];
    float lo = 0.0;
    float hi = 1.0;
    for (int i = 0; i < 4; ++i)
    {
      // Inside the polygon: dot(cross(E, plane), y - v_i) <= 0 for each edge E = v_i+1 - v_i
      // (a degenerate edge, v3 = v0, gives m = 0 and clips nothing).
      vec3 m = cross(pv[i == 3 ? 0 : i + 1] - pv[i], plane);
      aoClipSegment(a, b, m, dot(m, pv[i]), lo, hi);
    }
    sum += aoClippedEdge(a, b, lo, hi, n);
  }
  // Either winding: both faces occlude (one-sided triangles were rejected before).
  return abs(sum) / (2.0 * aoPi);
}

// -dW/dt of the Wendland kernel (HAO eq. 3): 20 x (1 - x)^3 / R with x = t / R.
float aoWendlandDensity(float t, float r)
{
  float x = clamp(t / r, 0.0, 1.0);
  float a = 1.0 - x;
  return 20.0 * x * a * a * a / r;
}

// Clip edge (a, b) against dot(n, y) >= 0, appending to the (at most 4) vertices v0..v3.
void aoAppend(inout vec3 v0, inout vec3 v1, inout vec3 v2, inout vec3 v3, inout int k, vec3 y)
{
  if (k == 0) v0 = y;
  else if (k == 1) v1 = y;
  else if (k == 2) v2 = y;
  else v3 = y;
  k = min(k + 1, 4);
}

// Step 1: clip the triangle q0 q1 q2 (relative to the point x; s0..s2 their heights over the
// tangent plane) to the half-space in front of the tangent plane: 3 or 4 vertices v0..v3, or
// 0 when the triangle cannot occlude (@p reached false).
int aoClipToTangentPlane(bool reached, vec3 q0, vec3 q1, vec3 q2, float s0, float s1, float s2,
  out vec3 v0, out vec3 v1, out vec3 v2, out vec3 v3)
{
  v0 = q0;
  v1 = q1;
  v2 = q2;
  v3 = q0;
  int count = 0;
  if (reached)
  {
    vec3 q[3] = vec3[3](q0, q1, q2);
    float sd[3] = float[3](s0, s1, s2);
    for (int i = 0; i < 3; ++i)
    {
      int j = i == 2 ? 0 : i + 1;
      if (sd[i] >= 0.0)
      {
        aoAppend(v0, v1, v2, v3, count, q[i]);
      }
      if ((sd[i] >= 0.0) != (sd[j] >= 0.0))
      {
        aoAppend(v0, v1, v2, v3, count, mix(q[i], q[j], sd[i] / (sd[i] - sd[j])));
      }
    }
  }
  if (count == 3)
  {
    v3 = v0; // a degenerate fourth edge adds nothing
  }
  return count < 3 ? 0 : count;
}

// Step 2: the distance from x (the origin) to the nearest point of the clipped polygon
// v0..v3, which lies in the plane of unit normal @p plane at signed offset @p planeOffset.
float aoNearestDistance(vec3 v0, vec3 v1, vec3 v2, vec3 v3, vec3 plane, float planeOffset)
{
  vec3 foot = planeOffset * plane;
  vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v3 - v2, e3 = v0 - v3;
  bool inside = dot(cross(e0, foot - v0), plane) >= 0.0 && dot(cross(e1, foot - v1), plane) >= 0.0 &&
    dot(cross(e2, foot - v2), plane) >= 0.0 && dot(cross(e3, foot - v3), plane) >= 0.0;
  vec3 c0 = v0 + clamp(-dot(v0, e0) / max(dot(e0, e0), 1e-30), 0.0, 1.0) * e0;
  vec3 c1 = v1 + clamp(-dot(v1, e1) / max(dot(e1, e1), 1e-30), 0.0, 1.0) * e1;
  vec3 c2 = v2 + clamp(-dot(v2, e2) / max(dot(e2, e2), 1e-30), 0.0, 1.0) * e2;
  vec3 c3 = v3 + clamp(-dot(v3, e3) / max(dot(e3, e3), 1e-30), 0.0, 1.0) * e3;
  return inside ? abs(planeOffset)
                : sqrt(min(min(dot(c0, c0), dot(c1, c1)), min(dot(c2, c2), dot(c3, c3))));
}

#if AO_LARGE_TRIANGLES
// Step 3 for a triangle that is large against R: its form factor @p full weighted by the
// falloff integrated over the distances [dmin, min(dmax, R)] (the partial form factors of the
// polygon clipped to balls, aoBallFormFactor), or by W at its centroid's distance @p d where
// it is small seen from x.
float aoLargeTriangleOcclusion(vec3 v0, vec3 v1, vec3 v2, vec3 v3, vec3 n, vec3 plane,
  float planeOffset, float full, float d, float dmin, float dmax, float r)
{
  vec3 foot = planeOffset * plane;
  float h = abs(planeOffset);
  // Seen from far enough, even a large triangle is small against R; otherwise the quadrature.
  bool small = dmax - dmin <= 0.25 * r && dmax <= r;
  float occlusion = 0.0;
  float lo = dmin;
  float hi = min(dmax, r);
  int nodes = 0;
  if (small)
  {
    occlusion = (aoBinary != 0 ? 1.0 : aoWendland(d, r)) * full;
  }
  else if (aoBinary != 0)
  {
    occlusion = dmax <= r ? full : 0.0;
    nodes = dmax <= r ? 0 : 1; // F(R)
  }
  else
  {
    occlusion = dmax < r ? aoWendland(dmax, r) * full : 0.0;
    nodes = 3;
  }

  // A fixed in-plane frame (the same for every triangle of one plane), for the octagon.
  vec3 ap = abs(plane);
  vec3 axis = ap.x <= ap.y && ap.x <= ap.z ? vec3(1.0, 0.0, 0.0)
                                           : (ap.y <= ap.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
  vec3 t1 = normalize(cross(plane, axis));
  vec3 t2 = cross(plane, t1);
  float mid = 0.5 * (hi + lo);
  float halfWidth = 0.5 * (hi - lo);
  for (int k = 0; k < nodes; ++k)
  {
    if (aoBinary != 0)
    {
      occlusion += aoBallFormFactor(v0, v1, v2, v3, n, plane, foot, h, t1, t2, r);
    }
    else
    {
      // 3-point Gauss-Legendre on [dmin, min(dmax, R)].
      float offset = float(k - 1) * 0.774596669 * halfWidth;
      float weight = k == 1 ? 0.888888889 : 0.555555556;
      occlusion += halfWidth * weight * aoWendlandDensity(mid + offset, r) *
        aoBallFormFactor(v0, v1, v2, v3, n, plane, foot, h, t1, t2, mid + offset);
    }
  }
  return occlusion;
}
#endif

void main()
{
  // Rejections clear `count` instead of leaving early, and no array is indexed by a value
  // known only at run time: a SIMD rasterizer (llvmpipe, measured) runs every branch under a
  // mask, also after a discard, runs a loop's body at least once whatever its trip count, and
  // lowers dynamically indexed temporaries to select ladders.
  // The lifted point x = p + Bias n (as the reference starts its rays) and its normal, written
  // by vtkAOVolumeInitFS for the pixel this texel stands for; everything is relative to x.
  vec4 point = texelFetch(aoPoints, ivec2(gl_FragCoord.xy), 0);
  vec3 x = point.xyz;
  vec3 n = aoUnpackNormal(max(point.w, 0.0));
  vec3 q0 = aoP0 - x;
  vec3 q1 = aoP1 - x;
  vec3 q2 = aoP2 - x;
  vec3 plane = normalize(cross(q1 - q0, q2 - q0));
  float planeOffset = dot(plane, q0); // x lies on P's front side when this is < 0
  float r = aoRadius;
  float s0 = dot(n, q0), s1 = dot(n, q1), s2 = dot(n, q2);
  bool reached = point.w >= 0.0 && abs(planeOffset) < r &&
    // behind a one-sided (closed-surface) triangle
    !(aoTwoSided < 0.5 && planeOffset > 0.0) &&
    // wholly behind the tangent plane
    max(max(s0, s1), s2) > 0.0;
  vec3 v0, v1, v2, v3;
  int count = aoClipToTangentPlane(reached, q0, q1, q2, s0, s1, s2, v0, v1, v2, v3);

  // Nearest and farthest points of the clipped polygon.
  float dmin = aoNearestDistance(v0, v1, v2, v3, plane, planeOffset);
  float dmax = max(max(length(v0), length(v1)), max(length(v2), length(v3)));
  count = dmin < r ? count : 0;
  if (count == 0)
  {
    discard;
  }

  // Form factor of the clipped polygon, eq. 1 (either winding: both faces occlude; one-sided
  // triangles were rejected above).
  float full = abs(aoEdge(v0, v1, n) + aoEdge(v1, v2, n) + aoEdge(v2, v3, n) + aoEdge(v3, v0, n)) /
    (2.0 * aoPi);
  float d = length((v0 + v1 + v2 + (count == 4 ? v3 : vec3(0.0))) / float(count));
#if AO_LARGE_TRIANGLES
  float occlusion =
    aoLargeTriangleOcclusion(v0, v1, v2, v3, n, plane, planeOffset, full, d, dmin, dmax, r);
#else
  // This draw's triangles are small against R (longest edge <= R/4, the geometry shader's
  // class): W varies almost linearly over one, so its value at the centroid's distance stands
  // for its mean. A llvmpipe-style SIMD rasterizer runs every loop body at least once whatever
  // its trip count, so keeping the quadrature out of this program is what makes it cheap.
  float occlusion = (aoBinary != 0 ? (d < r ? 1.0 : 0.0) : aoWendland(d, r)) * full;
#endif
  // Removed from the map by the blend: subtracted (GL_FUNC_REVERSE_SUBTRACT; the target ends up
  // holding 1 - sum of O_P, which the compositor clamps to [0, 1]) or multiplied in as
  // 1 - O_P (GL_ONE_MINUS_SRC_COLOR, unclamped in a float target: O_P must not exceed 1).
  gl_FragData[0] = vec4(clamp(occlusion, 0.0, 1.0), 0.0, 0.0, 0.0);
}
