#version 430
// The extended model's diffusion solve on the GPU (Core/DiffuseFluence.cxx is the CPU version,
// which the tests hold this one against; ARCHITECTURE.md, "Beyond the paper", has the model).
// The diffusion grid spans the data's lattice box; positions are in the data's local frame
// (lights too: the free irradiance depends only on distances and the cone). Three stages:
//  stage 0, the source of one level of the nested solve: per cell, q = sigma~t sum_j w_j
//    E_j^free T_j b into u_source (T_j at the cell, the light volume r downstream; b the share
//    beyond the ball) (rgb) with sigma_a (a), and (phi, D) into u_phi (D = 0: vacuum), from
//    the averaged extinction and the packed light volumes on the light grid; phi starts from the
//    coarser level's, interpolated (0 on the coarsest level and in vacuum);
//  stage 1, one SOR half-sweep (dispatched over half the x range): the cells with
//    (i + j + k) % 2 == u_colour relax
//    phi <- (1 - w) phi + w (q + sum_f K_f phi_f) / (sigma_a + sum_f K_f + leaks), with the
//    harmonic-mean couplings of the CPU code and Marshak's leak towards vacuum and the border;
//  stage 2, after the finest level: phi interpolated onto the light grid, with the averaged
//    extinction in alpha, into u_packed (what the ray caster reads).
// The ray caster defines AVS_NUMBER_OF_LIGHTS, AVS_POSITIONAL_LIGHTS and AVS_SPOT_LIGHTS, and
// puts avs_lights.glsl (LightAt) before this text; AVS_DIFFUSION_STAGE is the stage, a program
// each, since a software rasterizer runs every branch of a shader (one program's sweeps would
// pay for the source's and the packing's fetches).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = 0) uniform image3D u_phi;    // rgb: phi, a: D (0: vacuum)
layout(rgba32f, binding = 1) uniform image3D u_source; // rgb: q, a: sigma_a
layout(rgba32f, binding = 2) uniform readonly image3D u_coarser; // the coarser level's phi
layout(rgba32f, binding = 3) uniform writeonly image3D u_packed; // stage 2: (phi, sigma~t)
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

void Source(ivec3 cell)
{
  vec3 f = vec3(cell) / max(vec3(u_dimensions - 1), vec3(1.0));
  vec3 lc = (f * (u_lightDimensions - 1.0) + 0.5) / u_lightDimensions;
  float sigma = textureLod(u_averaged, lc, 0.0).r;
  vec3 x = vec3(cell) * u_spacing;
  vec3 e = vec3(0.0);
  if (sigma > 0.0)
  {
    // BeyondTheBall: the light's share beyond the ball, which the table A does not count.
    float reduced = (1.0 - u_albedo * u_anisotropy) * sigma;
    float kr = sqrt(3.0 * (1.0 - u_albedo) * sigma * max(reduced, 1.0 / u_transportLimit)) * u_ambientRadius;
    float beyond = (1.0 + kr) * exp(-kr);
    vec3 propagation, irradiance;
#define AVS_ADD_SOURCE(j) LightAt(j, x, propagation, irradiance); e += irradiance * (beyond * u_sourceWeight[j] * Downstream(j, x + u_ambientRadius * propagation));
    AVS_FOR_EACH_LIGHT(AVS_ADD_SOURCE)
  }
  imageStore(u_source, cell, vec4(sigma * e, (1.0 - u_albedo) * max(sigma, 0.0)));
  float d = Diffusivity(sigma);
  vec3 start = u_hasCoarser != 0 && d > 0.0 ? Coarser(f) : vec3(0.0);
  imageStore(u_phi, cell, vec4(start, d));
}

void Relax(ivec3 cell)
{
  vec4 here = imageLoad(u_phi, cell);
  float d = here.a;
  if (!(d > 0.0))
  {
    return;
  }
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

void main()
{
  ivec3 cell = ivec3(gl_GlobalInvocationID);
#if AVS_DIFFUSION_STAGE == 1
  // A half-sweep is dispatched over half the x range: invocation x relaxes the cell 2x or
  // 2x + 1 of this row whose colour is u_colour, so no invocation idles beside a busy one.
  cell.x = 2 * cell.x + ((cell.y + cell.z + u_colour) & 1);
#endif
  if (any(greaterThanEqual(cell, u_dimensions)))
  {
    return;
  }
#if AVS_DIFFUSION_STAGE == 0
  Source(cell);
#elif AVS_DIFFUSION_STAGE == 1
  Relax(cell);
#else
  Pack(cell);
#endif
}
