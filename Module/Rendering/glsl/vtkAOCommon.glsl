// Shared by every full-screen stage of the ambient-occlusion passes: the falloff kernel of
// shared/design/ao-definition.md and the G-buffer reconstruction of p and n.
// Expects: uniform sampler2D aoDepth, aoNormal; uniform mat4 aoInvProjection;
//          uniform ivec2 aoFullSize; uniform int aoParallel;

// Wendland's compactly supported kernel (HAO eq. 3): 1 at t = 0, 0 for t >= h.
float aoWendland(float t, float h)
{
  float x = clamp(t / h, 0.0, 1.0);
  float a = 1.0 - x;
  return a * a * a * a * (4.0 * x + 1.0);
}

// Full-resolution pixel + window depth -> view-space position (exact inverse projection).
vec3 aoViewPosition(ivec2 pix, float depth)
{
  vec2 ndc = (vec2(pix) + 0.5) / vec2(aoFullSize) * 2.0 - 1.0;
  vec4 v = aoInvProjection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  return v.xyz / v.w;
}

// One pixel's width at view point p, in view units (the x spacing of the inverse projection:
// exact for perspective, off-axis and parallel projections).
float aoPixelFootprint(vec3 p)
{
  return 2.0 * aoInvProjection[0][0] / float(aoFullSize.x) * (aoParallel != 0 ? 1.0 : abs(p.z));
}

// The normal of the polygon seen at a pixel (unnormalized, either orientation), rebuilt from
// the neighbouring depths, taking on each axis the side with the smaller depth step so that
// silhouettes do not bend it.
vec3 aoFacetNormal(ivec2 pix, vec3 p)
{
  ivec2 hi = aoFullSize - 1;
  ivec2 px0 = clamp(pix - ivec2(1, 0), ivec2(0), hi);
  ivec2 px1 = clamp(pix + ivec2(1, 0), ivec2(0), hi);
  ivec2 py0 = clamp(pix - ivec2(0, 1), ivec2(0), hi);
  ivec2 py1 = clamp(pix + ivec2(0, 1), ivec2(0), hi);
  vec3 ax0 = p - aoViewPosition(px0, texelFetch(aoDepth, px0, 0).r);
  vec3 ax1 = aoViewPosition(px1, texelFetch(aoDepth, px1, 0).r) - p;
  vec3 ay0 = p - aoViewPosition(py0, texelFetch(aoDepth, py0, 0).r);
  vec3 ay1 = aoViewPosition(py1, texelFetch(aoDepth, py1, 0).r) - p;
  vec3 dx = abs(ax0.z) < abs(ax1.z) ? ax0 : ax1;
  vec3 dy = abs(ay0.z) < abs(ay1.z) ? ay0 : ay1;
  vec3 n = cross(dx, dy);
  return dot(n, n) < 1e-20 ? vec3(0.0, 0.0, 1.0) : n;
}

// The direction from view point p towards the eye.
vec3 aoToEye(vec3 p)
{
  return aoParallel != 0 ? vec3(0.0, 0.0, 1.0) : -p;
}

// View-space normal at a pixel, flipped to face the viewer (ao-definition: "which n").
// vtkAOGBufferPass completes the attachment where a mapper wrote no normal (the polygon's,
// from the depths: vtkAONormalResolveFS), so that no stage rebuilds one: on llvmpipe, which
// runs both sides of every branch, that rebuild (four depth fetches and unprojections) cost
// every pixel of every stage. What may still hold none (a degenerate normal from the data) faces
// the viewer.
vec3 aoViewNormal(ivec2 pix, vec3 p)
{
  vec4 stored = texelFetch(aoNormal, pix, 0);
  vec3 n = stored.w < 0.5 || dot(stored.xyz, stored.xyz) < 1e-8 ? aoToEye(p) : stored.xyz;
  n = normalize(n);
  return dot(n, aoToEye(p)) < 0.0 ? -n : n;
}

// Normal n at view point p on the visible side of the polygon seen there, whose plane the
// G-buffer's facet attachment holds (facet.w > 0.5; without it n as it is): where a smooth
// mesh's interpolated normal leans away from the viewer on a polygon that faces it
// (silhouettes, coarse iso-surfaces) n is kept, not flipped into the object; a normal that
// points into the polygon's hidden side (normals inconsistent with the winding) is turned.
// ao-definition.md "which n", as the reference orients it.
vec3 aoVisibleSide(vec3 n, vec4 facet, vec3 p)
{
  return facet.w > 0.5 && dot(n, facet.xyz) * dot(aoToEye(p), facet.xyz) < 0.0 ? -n : n;
}

// A unit normal in one float: octahedral map quantized to 12 bits per axis, stored as the
// integer 4096 qx + qy (< 2^24, so exact in a 32-bit float; no bit casts needed in GLSL 1.50).
float aoPackNormal(vec3 n)
{
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0)
  {
    e = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  vec2 q = floor(clamp(e * 0.5 + 0.5, 0.0, 1.0) * 4095.0 + 0.5);
  return q.x * 4096.0 + q.y;
}

vec3 aoUnpackNormal(float code)
{
  float qx = floor(code / 4096.0);
  vec2 e = vec2(qx, code - qx * 4096.0) / 4095.0 * 2.0 - 1.0;
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  return normalize(n);
}

#ifdef AO_LIST
// A list of pixels (vtkAOPixelList): fragment i of a dense rectangle aoListWidth wide and
// aoListRows high (the quad's viewport) stands for entry i, so that every SIMD lane works on a
// listed pixel.
uniform samplerBuffer aoList; // xy: the entry's pixel
uniform int aoListCount;
uniform int aoListWidth;
uniform int aoListRows;

// The entry of the fragment at tc (the quad's texCoord), -1 past the list's end.
int aoListEntry(vec2 tc)
{
  ivec2 dims = ivec2(aoListWidth, aoListRows);
  ivec2 f = min(ivec2(tc * vec2(dims)), dims - 1);
  int i = f.y * aoListWidth + f.x;
  return i < aoListCount ? i : -1;
}

ivec2 aoListPixel(int i)
{
  return ivec2(texelFetch(aoList, i).xy);
}
#endif
