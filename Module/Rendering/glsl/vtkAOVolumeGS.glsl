//VTK::System::Dec
//AO::VolumeClass
// Ambient Occlusion Volumes (McGuire 2010), stage 2 of 3: the ambient occlusion volume of a
// triangle P. A point farther than the radius R from P gets no occlusion from it, so the box
// that holds P's in-plane bounding rectangle dilated by R, extruded by R along P's normal (and
// against it for two-sided triangles), contains every pixel P can darken. Only the box's
// faces turned away from the eye are emitted: each covered pixel is shaded once, where its
// ray leaves the box, and the depth test (GL_GREATER against the pixels' depths) rejects
// before shading the pixels whose visible surface lies beyond the box. When the box crosses
// the near plane (the eye inside or close to it) or the far plane, those faces would be
// clipped away with pixels still inside: the triangle falls back to a screen-aligned quad on
// the far plane (which passes the depth test wherever there is a surface) over the box's part
// in front of the near plane; the fragment shader rejects the pixels out of reach.
layout(triangles) in;
layout(triangle_strip, max_vertices = 20) out; // up to 5 faces turned away

in vec3 aoVertexVC[];
in float aoTwoSidedVS[];
uniform mat4 aoProjection;
uniform float aoRadius;
uniform int aoParallel;

flat out vec3 aoP0;
flat out vec3 aoP1;
flat out vec3 aoP2;
flat out float aoTwoSided;

void aoEmit(vec4 clip)
{
  aoP0 = aoVertexVC[0];
  aoP1 = aoVertexVC[1];
  aoP2 = aoVertexVC[2];
  aoTwoSided = aoTwoSidedVS[0];
  gl_Position = clip;
  EmitVertex();
}

// The screen rectangle [lo, hi] (NDC, clamped to the screen) on the far plane, which passes
// the depth test wherever there is a surface.
void aoEmitRectangle(vec2 lo, vec2 hi)
{
  lo = max(lo, vec2(-1.0));
  hi = min(hi, vec2(1.0));
  if (any(greaterThanEqual(lo, hi)))
  {
    return;
  }
  aoEmit(vec4(lo.x, lo.y, 1.0, 1.0));
  aoEmit(vec4(hi.x, lo.y, 1.0, 1.0));
  aoEmit(vec4(lo.x, hi.y, 1.0, 1.0));
  aoEmit(vec4(hi.x, hi.y, 1.0, 1.0));
  EndPrimitive();
}

void main()
{
  vec3 p0 = aoVertexVC[0];
  vec3 e1 = aoVertexVC[1] - p0;
  vec3 e2 = aoVertexVC[2] - p0;
  vec3 normal = cross(e1, e2);
  float area2 = length(normal);
  if (!(area2 > 0.0))
  {
    return; // degenerate: no area, no occlusion
  }
  normal /= area2;
  vec3 e3 = e2 - e1;
  vec3 longest = dot(e1, e1) >= dot(e2, e2) ? e1 : e2;
  longest = dot(longest, longest) >= dot(e3, e3) ? longest : e3;
  // Two draws, one per class (see vtkAOVolumeFS): triangles whose longest edge is at most R/4,
  // then the others.
  bool small = dot(longest, longest) <= 0.0625 * aoRadius * aoRadius;
#if AO_LARGE_TRIANGLES
  if (small)
#else
  if (!small)
#endif
  {
    return;
  }
  vec3 u = normalize(longest);
  vec3 v = cross(normal, u);
  float r = aoRadius;
  vec2 lo = min(vec2(0.0), min(vec2(dot(e1, u), dot(e1, v)), vec2(dot(e2, u), dot(e2, v)))) - r;
  vec2 hi = max(vec2(0.0), max(vec2(dot(e1, u), dot(e1, v)), vec2(dot(e2, u), dot(e2, v)))) + r;
  float below = aoTwoSidedVS[0] > 0.5 ? -r : 0.0;

  vec3 corner[8];
  vec4 clip[8];
  int inFront = 0;
  int beyondFar = 0;
  for (int i = 0; i < 8; ++i)
  {
    corner[i] = p0 + u * ((i & 1) != 0 ? hi.x : lo.x) + v * ((i & 2) != 0 ? hi.y : lo.y) +
      normal * ((i & 4) != 0 ? r : below);
    clip[i] = aoProjection * vec4(corner[i], 1.0);
    inFront += (clip[i].w > 0.0 && clip[i].z >= -clip[i].w) ? 1 : 0;
    beyondFar += clip[i].z > clip[i].w ? 1 : 0;
  }
  if (inFront == 0 || beyondFar == 8)
  {
    return; // wholly behind the near plane or beyond the far one: no visible pixel is inside
  }
  if (inFront == 8 && beyondFar > 0)
  {
    // Back faces beyond the far plane would be clipped away with the pixels they cover: the
    // screen rectangle bounding the box instead, on the far plane.
    vec2 lo2 = vec2(1.0);
    vec2 hi2 = vec2(-1.0);
    for (int i = 0; i < 8; ++i)
    {
      lo2 = min(lo2, clip[i].xy / clip[i].w);
      hi2 = max(hi2, clip[i].xy / clip[i].w);
    }
    aoEmitRectangle(lo2, hi2);
    return;
  }
  if (inFront < 8)
  {
    // The screen rectangle bounding the part of the box in front of the near plane: its
    // corners there, and where its 12 edges cross the plane (z = -w in clip space).
    vec2 lo2 = vec2(1.0);
    vec2 hi2 = vec2(-1.0);
    for (int i = 0; i < 8; ++i)
    {
      float fi = clip[i].z + clip[i].w;
      if (fi >= 0.0 && clip[i].w > 0.0)
      {
        vec2 ndc = clip[i].xy / clip[i].w;
        lo2 = min(lo2, ndc);
        hi2 = max(hi2, ndc);
      }
      for (int axis = 0; axis < 3; ++axis)
      {
        int j = i | (1 << axis);
        float fj = clip[j].z + clip[j].w;
        if (j != i && (fi >= 0.0) != (fj >= 0.0))
        {
          vec4 c = mix(clip[i], clip[j], fi / (fi - fj));
          vec2 ndc = c.w > 1e-20 ? c.xy / c.w : vec2(0.0);
          // On the near plane w > 0 unless the camera is parallel-projected beyond it.
          lo2 = c.w > 1e-20 ? min(lo2, ndc) : vec2(-1.0);
          hi2 = c.w > 1e-20 ? max(hi2, ndc) : vec2(1.0);
        }
      }
    }
    aoEmitRectangle(lo2, hi2);
    return;
  }
  // Faces as (axis bit, side); corners of a face in strip order.
  for (int axis = 0; axis < 3; ++axis)
  {
    int bit = 1 << axis;
    int b1 = axis == 0 ? 2 : 1;
    int b2 = axis == 2 ? 2 : 4;
    vec3 outward = axis == 0 ? u : (axis == 1 ? v : normal);
    for (int side = 0; side < 2; ++side)
    {
      int base = side != 0 ? bit : 0;
      vec3 m = side != 0 ? outward : -outward;
      vec3 center = 0.5 * (corner[base] + corner[base + b1 + b2]);
      bool away = aoParallel != 0 ? m.z < 0.0 : dot(m, center) > 0.0;
      if (away)
      {
        aoEmit(clip[base]);
        aoEmit(clip[base + b1]);
        aoEmit(clip[base + b2]);
        aoEmit(clip[base + b1 + b2]);
        EndPrimitive();
      }
    }
  }
}
