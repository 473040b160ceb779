//VTK::System::Dec
// Hybrid Ambient Occlusion, occlusion sampling (Reinboth et al. 2009, section 6, eq. 4):
// for each texel of the reduced-resolution AO map, march aoRays cosine-distributed rays in a
// fixed number of steps through the bitmask voxel grid. Directions and step offsets are
// jittered by a noise texture evaluated in world space, so the pattern sticks to surfaces.
//
// Empty-space skipping: every ray tests the same evenly spaced points as a plain march
// (aoSteps x aoSubSteps points), but the grid is read only where it can be occupied. A
// distance field over blocks of AO_BLOCK^3 cells (aoDistance, built by vtkAOVoxelTracer after
// each voxelization) gives, for the block holding a point, the chessboard distance k to the
// nearest block with an occupied cell: the cube of blocks within k - 1 is empty, so the march
// jumps to the first point beyond that cube. The points tested, and so the result, are the
// plain march's; the loop count drops from aoRays x points to a few per ray. All rays of a
// texel share one loop, so a ray that ends early hands over at once to the next (SIMD lanes
// wait for the longest total, not for the longest ray of each round).
//
// Cascades (clipmap): up to AO_LEVELS grids, finest first, cells doubling. A pixel marches
// through the finest grid whose focus cube holds the ball of radius R around it; the last grid
// covers the whole region. Level l's uniforms are element l of the *L arrays.
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal;
uniform sampler2D aoFacet;
// Grid l (AO_LEVELS of them, a program per count): texel (x, y, layer), each layer 128
// slices in 4 words; its distance field: per block of AO_BLOCK^3 cells, the L-inf distance in
// blocks to the nearest occupied block / 255 (0: occupied).
uniform usampler3D aoGrid0;
uniform sampler3D aoDistance0;
#if AO_LEVELS > 1
uniform usampler3D aoGrid1;
uniform sampler3D aoDistance1;
#endif
#if AO_LEVELS > 2
uniform usampler3D aoGrid2;
uniform sampler3D aoDistance2;
#endif
#if AO_LEVELS > 3
uniform usampler3D aoGrid3;
uniform sampler3D aoDistance3;
#endif
uniform sampler3D aoNoise;
uniform mat4 aoInvProjection;
uniform mat4 aoViewToWorld;
uniform mat4 aoViewToGridL[AO_LEVELS]; // rigid motion and uniform scale: view units -> cells
uniform vec3 aoGridSizeL[AO_LEVELS];   // cells along x, y and z (z = slices)
uniform vec3 aoCoarseSizeL[AO_LEVELS]; // blocks along x, y and z
uniform vec3 aoFocusLoL[AO_LEVELS];    // the focus cube, in cells
uniform vec3 aoFocusHiL[AO_LEVELS];
uniform float aoCellL[AO_LEVELS];      // cell edge, world units
uniform int aoSkipL[AO_LEVELS];        // 0: no distance field (grid too large): march all
uniform float aoRadius;      // world units
uniform float aoBias;        // world units
uniform ivec2 aoFullSize;
uniform int aoParallel;
uniform int aoScale;
uniform int aoRays;
uniform int aoSteps;
uniform int aoFalloff;       // 0: Wendland, 1: binary
uniform float aoSelfSlope;   // tangent of the elevation below which a hit near the tangent
                             // plane is still the surface itself (facets against the
                             // interpolated normal)
uniform float aoErosion;     // cells: occupied cells' exposed faces are moved in by this
                             // much (see aoMarch)
uniform float aoSinSpread;   // sine of the cone half-angle, Spread * pi / 2
uniform float aoNoiseScale;  // world units -> noise texels
uniform vec3 aoJitter;       // the accumulation frame's rotation of the noise (0: frame 0)

// The pixel's grid (set once in main).
int aoLevel = 0;
mat4 aoViewToGrid;
vec3 aoGridSize;
ivec3 aoCoarseSize;
int aoSkip = 0;
//VTK::Output::Dec

//AO::Common

// The words of texel t of the pixel's grid (branches, not selects: one fetch per call).
uvec4 aoFetchGrid(ivec3 t)
{
#if AO_LEVELS > 3
  if (aoLevel == 3)
  {
    return texelFetch(aoGrid3, t, 0);
  }
#endif
#if AO_LEVELS > 2
  if (aoLevel == 2)
  {
    return texelFetch(aoGrid2, t, 0);
  }
#endif
#if AO_LEVELS > 1
  if (aoLevel == 1)
  {
    return texelFetch(aoGrid1, t, 0);
  }
#endif
  return texelFetch(aoGrid0, t, 0);
}

// The distance field of the pixel's grid at block b.
float aoFetchDistance(ivec3 b)
{
#if AO_LEVELS > 3
  if (aoLevel == 3)
  {
    return texelFetch(aoDistance3, b, 0).r;
  }
#endif
#if AO_LEVELS > 2
  if (aoLevel == 2)
  {
    return texelFetch(aoDistance2, b, 0).r;
  }
#endif
#if AO_LEVELS > 1
  if (aoLevel == 1)
  {
    return texelFetch(aoDistance1, b, 0).r;
  }
#endif
  return texelFetch(aoDistance0, b, 0).r;
}

uint aoWord(uvec4 words, int i)
{
  return i == 0 ? words.x : (i == 1 ? words.y : (i == 2 ? words.z : words.w));
}

// The words of the grid texel holding cell c (the column of 128 slices around it); zero
// outside the grid.
uvec4 aoColumn(ivec3 c)
{
  if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(aoGridSize))))
  {
    return uvec4(0u);
  }
  return aoFetchGrid(ivec3(c.xy, c.z >> 7));
}

// Whether slice z of its grid texel's words w is occupied.
bool aoBit(uvec4 w, int z)
{
  return ((aoWord(w, (z >> 5) & 3) >> uint(z & 31)) & 1u) != 0u;
}

// Whether slice z of column words w (fetched for slice z0) is occupied. Slices outside the
// grid are empty; a slice in the next texel, which w does not hold, counts as occupied (so no
// face is moved in there, see aoMarch).
bool aoSlice(uvec4 w, int z0, int z)
{
  if (z < 0 || z >= int(aoGridSize.z))
  {
    return false;
  }
  if ((z >> 7) != (z0 >> 7))
  {
    return true;
  }
  return aoBit(w, z);
}

bool aoOccupied(vec3 q)
{
  ivec3 c = ivec3(floor(q));
  return aoBit(aoColumn(c), c.z);
}

// Chessboard distance, in blocks, from block b to the nearest occupied block: 0 if b holds an
// occupied cell; otherwise every block closer than that is empty. 1 outside the grid.
float aoBlockDistance(ivec3 b)
{
  if (aoSkip == 0)
  {
    return 0.0;
  }
  if (any(lessThan(b, ivec3(0))) || any(greaterThanEqual(b, aoCoarseSize)))
  {
    return 1.0;
  }
  return floor(aoFetchDistance(b) * 255.0 + 0.5);
}

// The finest grid whose focus cube holds the ball of radius R (plus a cell) around view
// point p; the last grid otherwise.
void aoChooseLevel(vec3 p)
{
  aoLevel = AO_LEVELS - 1;
  for (int l = 0; l + 1 < AO_LEVELS; ++l)
  {
    vec3 q = (aoViewToGridL[l] * vec4(p, 1.0)).xyz;
    float margin = aoRadius / aoCellL[l] + 1.0;
    if (all(greaterThanEqual(q - margin, aoFocusLoL[l])) &&
      all(lessThanEqual(q + margin, aoFocusHiL[l])))
    {
      aoLevel = l;
      break;
    }
  }
  aoViewToGrid = aoViewToGridL[aoLevel];
  aoGridSize = aoGridSizeL[aoLevel];
  aoCoarseSize = ivec3(aoCoarseSizeL[aoLevel]);
  aoSkip = aoSkipL[aoLevel];
}

// What the rays of one AO sample share, in cells of its grid (aoChooseLevel): where they start,
// the frame (t, b, ng) their directions are drawn in, the noise xi, the point spacing dt, and
// the bands within which an occupied cell is the sample's own surface (see aoRaysAt).
struct aoSampleRays
{
  vec3 pg, ng, nf, t, b, xi, origin, blockOrigin;
  float radiusCells, band, facetBand, facetLift, dt;
  int points;
  bool exact;
};

// The rays of the sample at pixel pix, view point p, normal n on the visible side of the
// polygon whose plane is facet (aoSampleAt; chooses the grid).
aoSampleRays aoRaysAt(ivec2 pix, vec3 p, vec3 n, vec4 facet)
{
  aoSampleRays r;
  aoChooseLevel(p);
  r.radiusCells = aoRadius / aoCellL[aoLevel];
  float biasCells = aoBias / aoCellL[aoLevel];
  // Each step tests one point per cell along its segment, so a one-cell-thick surface is not
  // stepped over however many cells the radius spans; the distance field skips the empty ones.
  int subSteps = clamp(int(ceil(r.radiusCells / float(aoSteps))), 1, 64);

  r.exact = facet.w > 0.5;
  r.pg = (aoViewToGrid * vec4(p, 1.0)).xyz;
  r.ng = normalize(mat3(aoViewToGrid) * n);
  vec3 pw = (aoViewToWorld * vec4(p, 1.0)).xyz;
  // Each frame of a progressive accumulation rotates the pixel's noise by the next point of a
  // low-discrepancy sequence (Cranley-Patterson): every frame stays unbiased, and their mean
  // samples the pixel's rays, azimuths and step offsets evenly.
  r.xi = fract(texture(aoNoise, pw * aoNoiseScale).xyz + aoJitter);

  r.t = normalize(
    abs(r.ng.x) < 0.57 ? cross(r.ng, vec3(1.0, 0.0, 0.0)) : cross(r.ng, vec3(0.0, 1.0, 0.0)));
  r.b = cross(r.ng, r.t);
  // Rays start at p + Bias n (the definition's offset; 0 by default). The surface's own
  // voxels are told apart from other surfaces' by where they lie, not by how far the ray has
  // gone: a flat surface's cells (the cells its plane passes through) have their centres
  // within h0 = (|n.x| + |n.y| + |n.z|) / 2 cells of its tangent plane, so an occupied cell
  // whose centre lies no higher than h0 above the tangent plane at p, plus a slope of
  // aoSelfSlope per cell of distance (facets of a curved surface against its interpolated
  // normal), is the surface itself and is passed through. A touching neighbour's cells rise
  // above that band within a few cells of the contact and occlude; the face's own staircase
  // never does, whatever the ray's angle and whatever the bias.
  // Where the mapper's interpolated normals lean away from the facets (coarse iso-surfaces,
  // gradient normals, smoothed CAD edges) the polygon seen at p is what the rays meet first.
  // With its exact plane (the G-buffer's facet attachment, r.exact) a ray that goes below that
  // plane crosses the polygon itself, as the true integral's rays do (aoBelowFacet), and the
  // rays above it are told the surface's own cells by that plane's band alone: the interpolated
  // plane's band would count the facet's own staircase as an occluder wherever the facet rises
  // above it (iso: RMSE 0.060 -> 0.047). Where the mapper gave no position (the facet rebuilt
  // from the depths, which may take the next polygon's at a crease) a cell within the band of
  // the rebuilt plane is the surface too, unless it rises above the interpolated plane by more
  // than 3.5 times the slope, and no ray is counted below it.
  r.nf = normalize(mat3(aoViewToGrid) * (r.exact ? facet.xyz : aoFacetNormal(pix, p)));
  r.nf = dot(r.nf, r.ng) < 0.0 ? -r.nf : r.nf;
  r.facetLift = biasCells * dot(r.ng, r.nf);
  r.origin = r.pg + r.ng * biasCells;
  r.band = 0.5 * (abs(r.ng.x) + abs(r.ng.y) + abs(r.ng.z)) + 0.02;
  r.facetBand = 0.5 * (abs(r.nf.x) + abs(r.nf.y) + abs(r.nf.z)) + 0.02;
  // aoSteps steps of Radius / aoSteps; each step tests the cells along its segment (at most
  // subSteps of them), so a one-cell-thick surface is not stepped over when the radius
  // spans many cells. Point m of a ray is at distance (m + xi.z) * dt, m < aoSteps * aoSubSteps.
  r.points = aoSteps * subSteps;
  r.dt = r.radiusCells / float(r.points);
  r.blockOrigin = r.origin / AO_BLOCK;
  return r;
}

// Whether the cell holding q, at distance tm along a ray of r, belongs to another surface than
// the sample's own (the bands of aoRaysAt).
bool aoOtherSurface(aoSampleRays r, vec3 q, float tm)
{
  vec3 cq = floor(q) + 0.5 - r.pg;
  float height = dot(r.ng, cq) - r.band;
  bool aboveFacet = dot(r.nf, cq) > r.facetBand + aoSelfSlope * tm;
  return r.exact ? aboveFacet
                 : height > aoSelfSlope * tm && (aboveFacet || height > 3.5 * aoSelfSlope * tm);
}

// Starts ray number ray of the sample and counts it: m, its first point; d, its direction; per
// block unit on each axis, the distance along it in points, invDb, and the offset of the block
// face it leaves through, side. A stratified cosine-weighted set in the cone (a Fibonacci
// spiral), Cranley-Patterson rotated by the noise: unbiased for every noise value, low
// discrepancy for each pixel. Ray i has u = fract((i + 1/2) / aoRays + xi.x) and azimuth
// 2 pi (i g + xi.y), g the golden ratio's fraction: the azimuth's cosine and sine (in and out)
// advance by a fixed rotation per ray. (aoRaysAt gives at least one point per ray.)
void aoStartRay(aoSampleRays r, inout int ray, out int m, inout vec2 azimuth, out vec3 d,
  out vec3 db, out vec3 invDb, out vec3 side)
{
  const float golden = 0.618033989;
  const vec2 turn = vec2(cos(6.28318531 * golden), sin(6.28318531 * golden));
  float u = fract((float(ray) + 0.5) / float(aoRays) + r.xi.x);
  float s = sqrt(u) * aoSinSpread;
  float c = sqrt(max(0.0, 1.0 - s * s));
  d = (azimuth.x * s) * r.t + (azimuth.y * s) * r.b + c * r.ng;
  azimuth = vec2(azimuth.x * turn.x - azimuth.y * turn.y, azimuth.y * turn.x + azimuth.x * turn.y);
  db = d / AO_BLOCK;
  invDb = 1.0 / (r.dt * max(abs(db), vec3(1e-12)));
  side = step(0.0, d);
  m = 0;
  ++ray;
}

// Whether ray direction d of r goes below the plane of the polygon at p (exact planes only):
// then it crosses that polygon, facetLift / (-d . nf) cells from its start (0 unless Bias > 0),
// and its weight there is added to occlusion; the ray is done either way.
bool aoBelowFacet(aoSampleRays r, vec3 d, inout float occlusion)
{
  float down = -dot(d, r.nf);
  if (!r.exact || down <= 0.0)
  {
    return false;
  }
  float t = r.facetLift / down;
  occlusion += t >= r.radiusCells ? 0.0 : (aoFalloff == 0 ? aoWendland(t, r.radiusCells) : 1.0);
  return true;
}

// The next point to test from point m (at tm) of a ray: m itself where its block may hold an
// occupied cell; else the cube of blocks within free - 1 of its block is empty, and the first
// point beyond that cube.
int aoSkipTo(aoSampleRays r, int m, float tm, vec3 db, vec3 invDb, vec3 side)
{
  vec3 qb = r.blockOrigin + db * tm;
  vec3 block = floor(qb);
  float free = aoBlockDistance(ivec3(block));
  if (free <= 0.0)
  {
    return m;
  }
  vec3 exitPoints = abs(block + side * free - (1.0 - side) * (free - 1.0) - qb) * invDb;
  float skip = min(exitPoints.x, min(exitPoints.y, exitPoints.z));
  return max(m + 1, int(ceil(float(m) + skip)));
}

// The occlusion of one sample: the falloff-weighted count of its rays that hit, out of aoRays.
// One loop over all the points of all the rays: a ray that ends early (a hit, or skipped empty
// space) hands over to the next at once, so neighbouring texels, which run in lock step on SIMD
// hardware, wait for the longest total rather than for the longest of each ray.
//
// Thin walls (aoErosion). A surface anywhere in a cell fills the whole cell, so a thin wall is a
// cell thick and the gap between two walls a cell narrower than it is, on average. The rays
// test the occupied cells with their exposed faces moved in by aoErosion cells (a quarter of a
// cell halves the bias: the surface lies, on average, at the cell's centre). A face stays where
// the neighbour across it is occupied, and so does a cell's edge or corner region where the
// diagonal neighbour there is occupied: a slanted surface's cells may touch along edges or at
// corners only, and the surface goes on through them. The thinned walls are 1 - 2 aoErosion
// cells thick; where the points are further apart than that, a point of another surface's
// occupied cell that lies outside the thinned wall is followed by one more test half a spacing
// away: after it if it lies on the side the ray enters the cell's faces through, else before.
//
// The loop fetches one grid texel per iteration whatever it does (marching, or gathering the
// neighbours of a point: the texels of the columns beside its cell, each of which also holds
// the slices above and below), so that lanes gathering neighbours cost the others iterations,
// not extra fetches in every iteration (llvmpipe runs both sides of every branch).
#if AO_ERODE
float aoMarch(aoSampleRays r)
{
  bool probe = r.dt > 1.0 - 2.0 * aoErosion;
  float spacing = probe ? 0.5 * r.dt : r.dt;
  vec2 azimuth = vec2(cos(6.28318531 * r.xi.y), sin(6.28318531 * r.xi.y));
  float occlusion = 0.0;
  int ray = 0;
  int m = r.points;
  vec3 d = r.ng, db = r.ng, invDb = r.ng, side = r.ng;
  // Testing the point at tc (in another surface's occupied cell) and then, if need be, the one
  // half a spacing before (k = 0) or after (k = 2) it (k = 1: tc itself). j: the column being
  // read for the tested point's cell (0: its own, 1: the one beside it along x, 2: along y,
  // 3: along both); toward: the neighbour steps towards the point along the axes whose outer
  // band holds it; faces: every face neighbour towards it occupied so far; diagonal: an edge
  // or corner neighbour towards it occupied.
  bool testing = false;
  float tc = 0.0;
  int k = 1;
  int j = 0;
  ivec3 cell = ivec3(0);
  ivec3 toward = ivec3(0);
  bool faces = true;
  bool diagonal = false;
  while (true)
  {
    if (!testing && m >= r.points)
    {
      if (ray >= aoRays)
      {
        break;
      }
      aoStartRay(r, ray, m, azimuth, d, db, invDb, side);
      if (aoBelowFacet(r, d, occlusion))
      {
        m = r.points;
        continue;
      }
    }
    // The point this iteration looks at, and the cell whose column it fetches.
    float tm = testing ? tc + float(k - 1) * spacing : (float(m) + r.xi.z) * r.dt;
    vec3 q = r.origin + d * tm;
    ivec3 here = ivec3(floor(q));
    ivec3 fetch = here;
    if (testing && j > 0)
    {
      fetch = cell + ivec3(j == 2 ? 0 : toward.x, j == 1 ? 0 : toward.y, 0);
    }
    if (!testing)
    {
      int next = aoSkipTo(r, m, tm, db, invDb, side);
      if (next != m)
      {
        m = next;
        continue;
      }
    }
    uvec4 w = aoColumn(fetch);
    // The slice of the tested cell in this column, and the one beyond it towards the point (the
    // same two bits whatever the column: every iteration runs the same code).
    bool own = !testing || j == 0;
    vec3 f = q - (vec3(here) + 0.5); // in [-1/2, 1/2)
    ivec3 towardHere = ivec3(sign(f) * step(0.5 - aoErosion, abs(f)));
    int z = own ? here.z : cell.z;
    int tz = own ? towardHere.z : toward.z;
    bool level = aoBit(w, z);
    bool beyond = tz != 0 && aoSlice(w, z, z + tz);
    bool decided = false; // the tested point's verdict is in
    bool hit = false;
    if (own)
    {
      bool occupied = level && aoOtherSurface(r, q, tm);
      if (!testing)
      {
        if (!occupied)
        {
          ++m;
          continue;
        }
        testing = true;
        tc = tm;
        k = 1;
      }
      else if (!occupied)
      {
        decided = true;
      }
      if (!decided)
      {
        cell = here;
        toward = towardHere;
        faces = tz == 0 || beyond;
        diagonal = false;
      }
    }
    else
    {
      // Column 1 or 2: a face neighbour (level) and an edge one (beyond); column 3: an edge
      // neighbour and a corner one.
      faces = faces && (j == 3 || level);
      diagonal = diagonal || beyond || (j == 3 && level);
    }
    if (testing && !decided)
    {
      // The next column this point needs, or its verdict.
      int next = j < 1 && toward.x != 0 ? 1 : (j < 2 && toward.y != 0 ? 2 : 4);
      next = next == 4 && j < 3 && toward.x != 0 && toward.y != 0 ? 3 : next;
      if (next < 4)
      {
        j = next;
        continue;
      }
      hit = faces || diagonal;
    }
    if (hit)
    {
      // The thinned wall was entered between the previous point tested and this one: on
      // average half a spacing before. The surface lies, on average, at the cell's centre,
      // aoErosion beyond the thinned wall's face (Wendland RMSE: fins 0.0397 -> 0.0362).
      float distance = max(tm - 0.5 * spacing + aoErosion, 0.0);
      occlusion += aoFalloff == 0 ? aoWendland(distance, r.radiusCells) : 1.0;
      testing = false;
      m = r.points;
    }
    else if (testing)
    {
      // After tc itself, the point half a spacing towards the thinned wall: before tc if tc
      // lies in the bands the ray leaves its cell through, else after it. Then back to marching.
      j = 0;
      if (k == 1 && probe)
      {
        k = dot(vec3(toward), d) > 0.0 ? 0 : 2;
        testing = k == 0 ? tc > spacing : tc + spacing < r.radiusCells;
      }
      else
      {
        testing = false;
      }
      if (!testing)
      {
        ++m;
      }
    }
  }
  return occlusion;
}
#else
// Without the thinned walls: a point in another surface's occupied cell is a hit.
float aoMarch(aoSampleRays r)
{
  vec2 azimuth = vec2(cos(6.28318531 * r.xi.y), sin(6.28318531 * r.xi.y));
  float occlusion = 0.0;
  int ray = 0;
  int m = r.points;
  vec3 d = r.ng, db = r.ng, invDb = r.ng, side = r.ng;
  while (true)
  {
    if (m >= r.points)
    {
      if (ray >= aoRays)
      {
        break;
      }
      aoStartRay(r, ray, m, azimuth, d, db, invDb, side);
      if (aoBelowFacet(r, d, occlusion))
      {
        m = r.points;
        continue;
      }
    }
    float tm = (float(m) + r.xi.z) * r.dt;
    int next = aoSkipTo(r, m, tm, db, invDb, side);
    if (next != m)
    {
      m = next;
    }
    else
    {
      vec3 q = r.origin + d * tm;
      if (aoOccupied(q) && aoOtherSurface(r, q, tm))
      {
        // The surface was crossed between the previous point and this one: on average half a
        // point spacing before tm (the falloff would otherwise see every hit dt/2 too far).
        occlusion += aoFalloff == 0 ? aoWendland(max(tm - 0.5 * r.dt, 0.0), r.radiusCells) : 1.0;
        m = r.points;
      }
      else
      {
        ++m;
      }
    }
  }
  return occlusion;
}
#endif

// A back face kept by a depth tie (the rasterizer's) where a closed mesh's front and back faces
// meet at a silhouette edge: its normal, turned towards the camera by the mapper, points into
// the object, so nearly every ray is blocked (single black pixels on the outlines of coarse
// spheres and boxes; the true integral sees the front face there). A pixel on a back face (the
// G-buffer's plane faces away from the camera, vtkAOGBufferPass) takes the normal and plane of
// the 4-neighbour on a front face whose plane passes closest to it, within a pixel footprint.
// A back face with no front face at its depth beside it (an open surface seen from behind, an
// inconsistently wound patch) keeps its own. The pixel stays where it is: only the direction
// its rays leave in, and the plane that tells its own cells, change.
void aoFrontFaceAt(ivec2 pix, vec3 p, inout vec3 n, inout vec4 facet)
{
  if (facet.w < 0.5 || dot(facet.xyz, aoToEye(p)) >= 0.0)
  {
    return;
  }
  float best = aoPixelFootprint(p);
  vec3 bestN = n;
  vec4 bestFacet = facet;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 d = ivec2(k == 0 ? 1 : (k == 1 ? -1 : 0), k == 2 ? 1 : (k == 3 ? -1 : 0));
    ivec2 q = clamp(pix + d, ivec2(0), aoFullSize - 1);
    float dq = texelFetch(aoDepth, q, 0).r;
    vec4 fq = texelFetch(aoFacet, q, 0);
    if (dq < 1.0 && fq.w > 0.5)
    {
      vec3 pq = aoViewPosition(q, dq);
      float distance = abs(dot(fq.xyz, p - pq));
      if (dot(fq.xyz, aoToEye(pq)) > 0.0 && distance <= best)
      {
        best = distance;
        bestN = aoViewNormal(q, pq);
        bestFacet = fq;
      }
    }
  }
  n = bestN;
  facet = bestFacet;
}

// The AO sample at full-resolution pixel pix: R = A; G = 1 (a sample exists); B, A = its window
// depth and normal, so that the bilateral filter reads each of its taps with one fetch. The
// background's sample where the pixel shows no geometry.
vec4 aoSampleAt(ivec2 pix)
{
  float depth = texelFetch(aoDepth, pix, 0).r;
  if (depth >= 1.0)
  {
    return vec4(1.0, 0.0, 1.0, 0.0);
  }
  vec3 p = aoViewPosition(pix, depth);
  // The normal on its polygon's visible side: flipped to face the viewer, at a silhouette of a
  // smooth mesh it would turn the rays into the object (A near 0 on small objects: dark dots
  // along their outlines). The rays start around it (aoRaysAt), and the filter and the
  // refinement marks compare it with the full-resolution pixels' own, so that a pixel whose
  // interpolated normal the contract turns over is not given its neighbours' unturned A.
  vec4 facet = texelFetch(aoFacet, pix, 0);
  vec3 n = aoViewNormal(pix, p);
  aoFrontFaceAt(pix, p, n, facet);
  n = aoVisibleSide(n, facet, p);
  float occlusion = aoMarch(aoRaysAt(pix, p, n, facet));
  return vec4(1.0 - occlusion / float(aoRays), 1.0, depth, aoPackNormal(n));
}

#ifdef AO_LIST
// Refinement over a list of pixels (vtkAOPixelList, aoListEntry in AO::Common).
void main()
{
  int i = aoListEntry(texCoord);
  // Past the list's end: never scattered.
  gl_FragData[0] = i < 0 ? vec4(1.0, 0.0, 1.0, 0.0) : aoSampleAt(aoListPixel(i));
}
#else
void main()
{
  ivec2 lowSize = (aoFullSize + ivec2(aoScale - 1)) / aoScale;
  ivec2 lowPix = min(ivec2(texCoord * vec2(lowSize)), lowSize - 1);
  gl_FragData[0] = aoSampleAt(min(lowPix * aoScale + ivec2(aoScale / 2), aoFullSize - 1));
}
#endif
