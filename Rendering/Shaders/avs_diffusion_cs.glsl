#version 430
// The extended model's diffusion solve on the GPU (Core/DiffuseFluence.cxx is the CPU version,
// which the tests hold this one against; ARCHITECTURE.md, "Beyond the paper", has the model).
// The diffusion grid spans the data's lattice box; positions are in the data's local frame
// (lights too: the free irradiance depends only on distances and the cone). The stages:
//  stage 0, the cells of one level of the nested solve: per cell, D (0: vacuum) from the
//    averaged extinction, (0, D) into u_phi; each cell that is not vacuum is appended to the
//    list of its colour (the level's lists in u_cells from u_listBase: their indirect
//    dispatches and counts, then the lists);
//  stage 4, over a level's lists, before the light volumes are marched: the tiles of the light
//    grid that a light's reads r downstream (stage 3's Downstream) meet are flagged in
//    u_flags; stage 5 appends the flagged tiles to a list of tiles (vtkAVSTileList), the tiles
//    that the light-volume pass marches;
//  stage 3, over the lists, the source: q = sigma~t sum_j w_j E_j^free T_j b into u_source
//    (T_j at the cell, the light volume r downstream; b the share beyond the ball) (rgb) with
//    sigma_a (a), and phi started from the coarser level's, interpolated (0 on the coarsest);
//  stage 1, one SOR half-sweep over the list of colour u_colour (the cells with
//    (i + j + k) % 2 == u_colour):
//    phi <- (1 - w) phi + w (q + sum_f K_f phi_f) / (sigma_a + sum_f K_f + leaks), with the
//    harmonic-mean couplings of the CPU code and Marshak's leak towards vacuum and the border
//    (vacuum cells stay 0, as the CPU code leaves them; a half-sweep reads only the other
//    colour, so the lists' order does not matter);
//  stage 2, after the finest level: phi interpolated onto the light grid, with the averaged
//    extinction in alpha, into u_packed (what the ray caster reads), over the light grid's tiles
//    that the rays read (a list of tiles: Core/LightTiles.h, 8 x 8 x 1 points, a work group each).
// The ray caster defines AVS_NUMBER_OF_LIGHTS, AVS_POSITIONAL_LIGHTS and AVS_SPOT_LIGHTS for
// stage 3 (the others have no lights), and puts avs_lights.glsl (LightAt) before this text;
// AVS_DIFFUSION_STAGE is the stage, a program each, since a software rasterizer runs every
// branch of a shader (one program's sweeps would pay for the source's and the packing's fetches).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = 0) uniform image3D u_phi;    // rgb: phi, a: D (0: vacuum)
layout(rgba32f, binding = 1) uniform image3D u_source; // rgb: q, a: sigma_a
layout(rgba32f, binding = 2) uniform readonly image3D u_coarser; // the coarser level's phi
layout(rgba32f, binding = 3) uniform writeonly image3D u_packed; // stage 2: (phi, sigma~t)
// The cells that are not vacuum (packed x | y << 11 | z << 22): a level's from u_listBase,
// first the indirect dispatches of its two lists (work groups x, y, z), then their counts, then
// the lists, `u_listCapacity` entries each.
layout(std430, binding = 0) buffer avs_DiffusionCells
{
  uint u_cells[];
};
uniform int u_listBase;
uniform int u_listCapacity;
#if AVS_DIFFUSION_STAGE == 2 || AVS_DIFFUSION_STAGE == 5
// A list of tiles of the light grid (vtkAVSTileList): the count, its dispatch, the tiles.
layout(std430, binding = 1) buffer avs_Tiles
{
  uint u_tileCount;
  uint u_tileGroups[3];
  uint u_tiles[];
};
#endif
#if AVS_DIFFUSION_STAGE == 4 || AVS_DIFFUSION_STAGE == 5
// A flag per tile of the light grid, x fastest, then y, then z (the light grid's points).
layout(std430, binding = 2) buffer avs_TileFlags
{
  uint u_flags[];
};
uniform ivec3 u_tilesAlong;       // tiles along x and y, points along z
uniform int u_markPositional;     // 1: the light is at u_markLight, else it shines along it
uniform vec3 u_markLight;
#endif
uniform int u_hasCoarser;            // 0: the coarsest level (phi starts at 0)
uniform ivec3 u_coarserDimensions;
uniform int u_colour;
uniform ivec3 u_dimensions;      // diffusion grid
uniform vec3 u_spacing;          // its spacing (local frame)
uniform vec3 u_lightDimensions;  // light grid
uniform sampler3D u_averaged;    // averaged extinction on the light grid
uniform sampler3D u_lightVolumes0;
uniform sampler3D u_lightVolumes1;
uniform float u_albedo;
uniform float u_anisotropy;
uniform float u_sourceWeight[8]; // DiffusionSourceWeight of each light's tube law
uniform float u_relaxation;
uniform float u_ambientRadius;   // r
uniform float u_transportLimit;  // 1 / sigma' at most
uniform float u_vacuum;          // VacuumOpticalDepth / mean spacing

// D of a cell of averaged extinction sigma; 0 for vacuum (sigma' h below VacuumOpticalDepth).
float Diffusivity(float sigma)
{
  float reduced = (1.0 - u_albedo * u_anisotropy) * max(sigma, 0.0);
  return reduced >= u_vacuum ? 1.0 / (3.0 * max(reduced, 1.0 / u_transportLimit)) : 0.0;
}

// The coarser level's phi, trilinear at the fraction f of the common box (ResampleTrilinear of
// the CPU code, with the index clamped into the lattice).
vec3 Coarser(vec3 f)
{
  ivec3 last = max(u_coarserDimensions - 1, ivec3(0));
  vec3 p = clamp(f * vec3(last), vec3(0.0), vec3(last));
  ivec3 i0 = min(ivec3(floor(p)), max(last - 1, ivec3(0)));
  vec3 t = p - vec3(i0);
  ivec3 i1 = min(i0 + 1, last);
  vec3 c00 = mix(imageLoad(u_coarser, i0).rgb, imageLoad(u_coarser, ivec3(i1.x, i0.y, i0.z)).rgb, t.x);
  vec3 c10 = mix(imageLoad(u_coarser, ivec3(i0.x, i1.y, i0.z)).rgb, imageLoad(u_coarser, ivec3(i1.x, i1.y, i0.z)).rgb, t.x);
  vec3 c01 = mix(imageLoad(u_coarser, ivec3(i0.x, i0.y, i1.z)).rgb, imageLoad(u_coarser, ivec3(i1.x, i0.y, i1.z)).rgb, t.x);
  vec3 c11 = mix(imageLoad(u_coarser, ivec3(i0.x, i1.y, i1.z)).rgb, imageLoad(u_coarser, i1).rgb, t.x);
  return mix(mix(c00, c10, t.y), mix(c01, c11, t.y), t.z);
}

// Light j's transmittance at x (local frame): the light volume holds T where the light enters
// the ball around a point, r before it, so T at x is its value r downstream, x + r p (clamped
// into the box, beyond which nothing attenuates).
float Downstream(int j, vec3 x)
{
  vec3 f = clamp(x / max(u_spacing * vec3(u_dimensions - 1), vec3(1e-30)), vec3(0.0), vec3(1.0));
  vec3 lc = (f * (u_lightDimensions - 1.0) + 0.5) / u_lightDimensions;
  return j < 4 ? textureLod(u_lightVolumes0, lc, 0.0)[clamp(j, 0, 3)]
               : textureLod(u_lightVolumes1, lc, 0.0)[clamp(j - 4, 0, 3)];
}

// Stage 0: the cell's D, and whether it is not vacuum.
bool Classify(ivec3 cell)
{
  vec3 f = vec3(cell) / max(vec3(u_dimensions - 1), vec3(1.0));
  vec3 lc = (f * (u_lightDimensions - 1.0) + 0.5) / u_lightDimensions;
  float d = Diffusivity(textureLod(u_averaged, lc, 0.0).r);
  imageStore(u_phi, cell, vec4(0.0, 0.0, 0.0, d));
  return d > 0.0;
}

#if AVS_DIFFUSION_STAGE == 3
// Stage 3: a cell that is not vacuum: its source, and phi from the coarser level's.
void Source(ivec3 cell)
{
  vec3 f = vec3(cell) / max(vec3(u_dimensions - 1), vec3(1.0));
  vec3 lc = (f * (u_lightDimensions - 1.0) + 0.5) / u_lightDimensions;
  float sigma = textureLod(u_averaged, lc, 0.0).r;
  vec3 x = vec3(cell) * u_spacing;
  vec3 e = vec3(0.0);
  // (sigma > 0: the cell is not vacuum.) BeyondTheBall: the light's share beyond the ball, which
  // the table A does not count.
  float reduced = (1.0 - u_albedo * u_anisotropy) * sigma;
  float kr = sqrt(3.0 * (1.0 - u_albedo) * sigma * max(reduced, 1.0 / u_transportLimit)) * u_ambientRadius;
  float beyond = (1.0 + kr) * exp(-kr);
  vec3 propagation, irradiance;
#define AVS_ADD_SOURCE(j) LightAt(j, x, propagation, irradiance); e += irradiance * (beyond * u_sourceWeight[j] * Downstream(j, x + u_ambientRadius * propagation));
  AVS_FOR_EACH_LIGHT(AVS_ADD_SOURCE)
  imageStore(u_source, cell, vec4(sigma * e, (1.0 - u_albedo) * max(sigma, 0.0)));
  vec3 start = u_hasCoarser != 0 ? Coarser(f) : vec3(0.0);
  imageStore(u_phi, cell, vec4(start, Diffusivity(sigma)));
}
#endif

#if AVS_DIFFUSION_STAGE == 4
// Stage 4: flags the tiles of the light grid that the cell's read of the light r downstream
// meets (the light grid's points interpolated there, and one more either side where the point is
// within rounding of one).
void Mark(ivec3 cell)
{
  vec3 x = vec3(cell) * u_spacing;
  vec3 propagation = u_markLight;
  if (u_markPositional != 0)
  {
    vec3 d = x - u_markLight;
    float dist = length(d);
    propagation = dist > 0.0 ? d / dist : vec3(0.0);
  }
  vec3 y = x + u_ambientRadius * propagation;
  vec3 f = clamp(y / max(u_spacing * vec3(u_dimensions - 1), vec3(1e-30)), vec3(0.0), vec3(1.0));
  vec3 p = f * (u_lightDimensions - 1.0);
  ivec3 last = ivec3(u_lightDimensions) - 1;
  ivec3 lo = clamp(ivec3(floor(p - 1e-3)), ivec3(0), last);
  ivec3 hi = clamp(ivec3(floor(p + 1e-3)) + 1, ivec3(0), last);
  if (u_markPositional != 0 && !(length(x - u_markLight) > 0.0))
  {
    // At the light itself (a direction of the spot's axis): anywhere within r.
    vec3 scale = (u_lightDimensions - 1.0) / max(u_spacing * vec3(u_dimensions - 1), vec3(1e-30));
    lo = clamp(ivec3(floor((x - u_ambientRadius) * scale - 1e-3)), ivec3(0), last);
    hi = clamp(ivec3(ceil((x + u_ambientRadius) * scale + 1e-3)), ivec3(0), last);
  }
  for (int z = lo.z; z <= hi.z; ++z)
    for (int ty = lo.y / 8; ty <= hi.y / 8; ++ty)
      for (int tx = lo.x / 8; tx <= hi.x / 8; ++tx)
        u_flags[(z * u_tilesAlong.y + ty) * u_tilesAlong.x + tx] = 1u;
}
#endif

void Relax(ivec3 cell)
{
  vec4 here = imageLoad(u_phi, cell);
  float d = here.a;
  vec4 source = imageLoad(u_source, cell);
  float diagonal = source.a;
  vec3 sum = source.rgb;
  for (int f = 0; f < 6; ++f)
  {
    int axis = f / 2;
    ivec3 m = cell;
    m[axis] += (f % 2) == 1 ? 1 : -1;
    float h = u_spacing[axis];
    bool inside = m[axis] >= 0 && m[axis] < u_dimensions[axis];
    vec4 there = inside ? imageLoad(u_phi, m) : vec4(0.0);
    float dn = there.a;
    if (dn > 0.0)
    {
      float k = 2.0 * d * dn / (d + dn) / (h * h);
      diagonal += k;
      sum += k * there.rgb;
    }
    else
    {
      diagonal += d / (2.0 * d + 0.5 * h) / h;
    }
  }
  vec3 phi = mix(here.rgb, sum / diagonal, u_relaxation);
  imageStore(u_phi, cell, vec4(phi, here.a));
}

// Stage 2: phi of the finest level (bound as u_coarser) at a point of the light grid (u_dimensions),
// with the averaged extinction there, for the ray caster's one fetch of both.
void Pack(ivec3 cell)
{
  vec3 f = vec3(cell) / max(vec3(u_dimensions - 1), vec3(1.0));
  imageStore(u_packed, cell, vec4(Coarser(f), texelFetch(u_averaged, cell, 0).r));
}

#if AVS_DIFFUSION_STAGE == 0 || AVS_DIFFUSION_STAGE == 5
shared uint s_count[2];
shared uint s_base[2];
#endif

void main()
{
#if AVS_DIFFUSION_STAGE == 0
  // Each work group counts its cells of either colour, takes their places in the lists with one
  // atomic each, and raises that list's dispatch to cover them.
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (gl_LocalInvocationIndex < 2u)
  {
    s_count[gl_LocalInvocationIndex] = 0u;
  }
  barrier();
  int colour = (cell.x + cell.y + cell.z) & 1;
  bool listed = all(lessThan(cell, u_dimensions)) && Classify(cell);
  uint place = listed ? atomicAdd(s_count[colour], 1u) : 0u;
  barrier();
  if (gl_LocalInvocationIndex < 2u)
  {
    uint c = gl_LocalInvocationIndex;
    uint count = s_count[c];
    s_base[c] = count > 0u ? atomicAdd(u_cells[uint(u_listBase) + 6u + c], count) : 0u;
    if (count > 0u)
    {
      // Work groups of 64 cells, x then y, 65535 a row at most.
      uint groups = (s_base[c] + count + 63u) / 64u;
      atomicMax(u_cells[uint(u_listBase) + 3u * c], min(groups, 65535u));
      atomicMax(u_cells[uint(u_listBase) + 3u * c + 1u], (groups + 65534u) / 65535u);
    }
  }
  barrier();
  if (listed)
  {
    u_cells[uint(u_listBase + 8 + colour * u_listCapacity) + s_base[colour] + place] =
      uint(cell.x) | (uint(cell.y) << 11) | (uint(cell.z) << 22);
  }
#elif AVS_DIFFUSION_STAGE == 5
  // The flagged tiles appended, a work group's with one atomic; the dispatch raised to cover
  // them (x then y, 65535 a row at most).
  uint t = (gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x) * 64u +
    gl_LocalInvocationIndex;
  uint total = uint(u_tilesAlong.x * u_tilesAlong.y * u_tilesAlong.z);
  if (gl_LocalInvocationIndex == 0u)
  {
    s_count[0] = 0u;
  }
  barrier();
  bool flagged = t < total && u_flags[min(t, total - 1u)] != 0u;
  uint place = flagged ? atomicAdd(s_count[0], 1u) : 0u;
  barrier();
  if (gl_LocalInvocationIndex == 0u)
  {
    uint count = s_count[0];
    s_base[0] = count > 0u ? atomicAdd(u_tileCount, count) : 0u;
    if (count > 0u)
    {
      uint end = s_base[0] + count;
      atomicMax(u_tileGroups[0], min(end, 65535u));
      atomicMax(u_tileGroups[1], (end + 65534u) / 65535u);
    }
  }
  barrier();
  if (flagged)
  {
    uint plane = uint(u_tilesAlong.x * u_tilesAlong.y);
    uint z = t / plane;
    uint ty = (t - z * plane) / uint(u_tilesAlong.x);
    uint tx = t - z * plane - ty * uint(u_tilesAlong.x);
    u_tiles[s_base[0] + place] = tx | (ty << 10) | (z << 20);
  }
#elif AVS_DIFFUSION_STAGE == 2
  uint t = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
  if (t >= u_tileCount)
  {
    return;
  }
  uint tile = u_tiles[t];
  ivec3 cell = ivec3(int(tile & 1023u) * 8, int((tile >> 10) & 1023u) * 8, int(tile >> 20)) +
    ivec3(gl_LocalInvocationID.xy, 0);
  if (any(greaterThanEqual(cell, u_dimensions)))
  {
    return;
  }
  Pack(cell);
#else
  // Stages 1, 3 and 4 go over the list of colour u_colour, 64 cells a work group.
  uint i = (gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x) * 64u +
    gl_LocalInvocationIndex;
  if (i >= u_cells[uint(u_listBase) + 6u + uint(u_colour)])
  {
    return;
  }
  uint entry = u_cells[uint(u_listBase + 8 + u_colour * u_listCapacity) + i];
  ivec3 cell = ivec3(int(entry & 2047u), int((entry >> 11) & 2047u), int(entry >> 22));
#if AVS_DIFFUSION_STAGE == 1
  Relax(cell);
#elif AVS_DIFFUSION_STAGE == 3
  Source(cell);
#else
  Mark(cell);
#endif
#endif
}
