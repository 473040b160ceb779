//VTK::System::Dec
// Hybrid Ambient Occlusion, occlusion sampling (Reinboth et al. 2009, section 6, eq. 4):
// for each texel of the reduced-resolution AO map, march aoRays cosine-distributed rays in a
// fixed number of steps through the bitmask voxel grid. Directions and step offsets are
// jittered by a noise texture evaluated in world space, so the pattern sticks to surfaces.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform usampler3D aoGrid;   // texel (x, y, layer); each layer holds 128 slices in 4 words
uniform sampler3D aoNoise;
uniform mat4 aoInvProjection;
uniform mat4 aoViewToGrid;   // rigid motion and uniform scale: view units -> grid cells
uniform mat4 aoViewToWorld;
uniform vec3 aoGridSize;     // cells along x, y and z (z = slices)
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoScale;
uniform int aoRays;
uniform int aoSteps;
uniform int aoSubSteps;
uniform int aoFalloff;       // 0: Wendland, 1: binary
uniform float aoRadiusCells;
uniform float aoBiasCells;
uniform float aoSinSpread;   // sine of the cone half-angle, Spread * pi / 2
uniform float aoNoiseScale;  // world units -> noise texels
//VTK::Output::Dec

//AO::Common

bool aoOccupied(vec3 q)
{
  ivec3 c = ivec3(floor(q));
  if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(aoGridSize))))
  {
    return false;
  }
  uvec4 words = texelFetch(aoGrid, ivec3(c.xy, c.z >> 7), 0);
  int w = (c.z >> 5) & 3;
  uint bits = w == 0 ? words.x : (w == 1 ? words.y : (w == 2 ? words.z : words.w));
  return ((bits >> uint(c.z & 31)) & 1u) != 0u;
}

void main()
{
  ivec2 lowSize = (aoFullSize + ivec2(aoScale - 1)) / aoScale;
  ivec2 lowPix = min(ivec2(texCoord * vec2(lowSize)), lowSize - 1);
  ivec2 pix = min(lowPix * aoScale + ivec2(aoScale / 2), aoFullSize - 1);
  float depth = texelFetch(aoDepth, pix, 0).r;
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 p = aoViewPosition(pix, depth);
  vec3 n = aoViewNormal(pix, p);

  vec3 pg = (aoViewToGrid * vec4(p, 1.0)).xyz;
  vec3 ng = normalize(mat3(aoViewToGrid) * n);
  vec3 pw = (aoViewToWorld * vec4(p, 1.0)).xyz;
  vec3 xi = texture(aoNoise, pw * aoNoiseScale).xyz;

  vec3 t = normalize(abs(ng.x) < 0.57 ? cross(ng, vec3(1.0, 0.0, 0.0)) : cross(ng, vec3(0.0, 1.0, 0.0)));
  vec3 b = cross(ng, t);
  // The origin leaves the surface's own voxels by the bias along n (no self-occlusion). Near
  // other surfaces, closer than the bias, that lift would cross them or end inside them, so
  // n is walked in half cells first (up to twice the bias) and two cases are told apart:
  // - an empty run followed by occupied cells (a narrow gap): start in the middle of the run;
  // - occupied all the way (the foot of a thick wall, a crease): start at the bias, and count
  //   only occupancy beyond it, so rays leaving the corner are free and rays into the wall are
  //   blocked (A near 1/2, as for the exact crease) rather than every ray hitting at once.
  // Within about a cell of contact the voxels cannot tell another surface from the point's
  // own: a surface touching the point closer than that is not seen (see the documentation).
  float lift = aoBiasCells;
  float tMin = 0.0;
  float firstEmpty = -1.0;
  for (float sb = 0.5; sb <= 2.0 * aoBiasCells; sb += 0.5)
  {
    bool occupied = aoOccupied(pg + ng * sb);
    if (!occupied && firstEmpty < 0.0)
    {
      firstEmpty = sb;
    }
    else if (occupied && firstEmpty >= 0.0 && firstEmpty <= aoBiasCells)
    {
      lift = 0.5 * (firstEmpty + sb - 0.5);
      break;
    }
  }
  if (firstEmpty < 0.0)
  {
    tMin = aoBiasCells;
  }
  vec3 origin = pg + ng * lift;
  float stepLength = aoRadiusCells / float(aoSteps);

  float occlusion = 0.0;
  for (int i = 0; i < aoRays; ++i)
  {
    // A stratified cosine-weighted set in the cone (a Fibonacci spiral), Cranley-Patterson
    // rotated by the noise: unbiased for every noise value, low discrepancy for each pixel.
    float u = fract((float(i) + 0.5) / float(aoRays) + xi.x);
    float phi = 6.28318531 * fract(float(i) * 0.618033989 + xi.y);
    float s = sqrt(u) * aoSinSpread;
    float c = sqrt(max(0.0, 1.0 - s * s));
    vec3 d = (cos(phi) * s) * t + (sin(phi) * s) * b + c * ng;
    // aoSteps steps of Radius / aoSteps; each step tests the cells along its segment (at
    // most aoSubSteps of them), so a one-cell-thick surface is not stepped over when the
    // radius spans many cells.
    bool hit = false;
    for (int k = 0; k < aoSteps && !hit; ++k)
    {
      for (int j = 0; j < aoSubSteps; ++j)
      {
        float tk = (float(k) + (float(j) + xi.z) / float(aoSubSteps)) * stepLength;
        if (tk >= tMin && aoOccupied(origin + d * tk))
        {
          occlusion += aoFalloff == 0 ? aoWendland(tk, aoRadiusCells) : 1.0;
          hit = true;
          break;
        }
      }
    }
  }
  gl_FragData[0] = vec4(1.0 - occlusion / float(aoRays), 1.0, 0.0, 1.0);
}
