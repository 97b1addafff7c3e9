//AVS::Effect::Dec
// Ambient scattering (ALGORITHM.md section 6): emission (eq. 8.7) and the light that the ball of
// radius r around x' = x(t + r) scatters towards the camera (eqs. 8.8-8.9).
//
// Eq. 8.8 adds, for each t, the light from the ball around x(t + r) times T(t): the integral
// of T(s - r) S(s) over the points s = t + r. Here each sample s = x_i adds its own in-scattered
// light S (its classification is the one the ray made anyway) times the transmittance r before
// it, interpolated linearly between the samples k and k + 1 back (r = (k + f) steps), kept in a
// ring buffer of AVS_RING entries. Before the ray's start (the volume box, or the camera inside
// it) nothing attenuates, so samples in the first r of the ray take T = 1 r before them: eq. 8.8
// with the ray starting at the camera (ARCHITECTURE.md, "The look-ahead on the sample grid").
// The ray caster sizes the ring from r and the sample distance when it builds the program; for
// a radius too large for any ring it defines AVS_LOOKAHEAD_EXPLICIT instead, and the sample
// k + 1 steps ahead is classified explicitly: the same sum, slower. The CPU reference computes
// this sum. AVS_LIGHT_TEXTURES (0-2) says how many light-volume textures the lights need;
// AVS_EMISSION is defined when the emission term is not zero. The choices are compile-time
// because a software rasterizer runs every branch of a shader whatever its condition.
// AVS_LIGHTS_PER_PAIR, with AVS_LIGHT_GROUP G = 2 or 4 (ScatteringParameters::LightGroup: G
// steps span at most one cell of the light grid), reads the lights once per group of G samples
// of the unsplit ray, at the group's midpoint, for all of them (ARCHITECTURE.md, "The lights
// once per group of samples"); with the ring the ray caster then takes G samples per iteration
// (AVS_SAMPLE_PAIRS, AVS_SAMPLE_GROUP) and the group's snippet reads them. The CPU reference
// reads them at the same points.
#ifndef AVS_LOOKAHEAD_EXPLICIT
#define AVS_EFFECT_TERMINATION
#endif
// Light grid: tube transmittance of lights 0-3, then 4-7.
#if AVS_LIGHT_TEXTURES > 0
uniform sampler3D u_lightVolumes0;
#endif
#if AVS_LIGHT_TEXTURES > 1
uniform sampler3D u_lightVolumes1;
#endif
// The averaged sigma_t on the light grid (where the precomputation leaves it), read at the
// sample with the light volumes' coordinate (ARCHITECTURE.md, "Texel formats"): with 1-3 or 5-7
// lights from the copy in the free channel after the last light's, AVS_AVERAGED_SLOT (slot s:
// channel s % 4 of light texture s / 4), in the same fetch as the lights; in the extended model
// with phi, from the alpha of the diffuse fluence's texture or with lights of one colour from
// that slot too (below); else from its own texture, one fetch more.
#ifdef AVS_DIFFUSE
// The extended model (ARCHITECTURE.md, "Beyond the paper"): the diffuse fluence phi (RGB) of
// the diffusion solve (Core/DiffuseFluence.h), interpolated onto the light grid, with the
// averaged sigma_t in alpha; the ring's samples keep the phi their InScattered (with pairs: the
// pair's snippet) read. With lights of one colour c (1, 2, 5 or 6 of them), AVS_PHI_SLOT: phi /
// c as one number in the light textures' slot after the averaged extinction's
// (AVS_AVERAGED_SLOT), read in the lights' fetch (vtkAVSLightVolumePass::CopyFluence).
#ifdef AVS_PHI_SLOT
uniform vec3 u_phiColour;
#if AVS_PHI_SLOT < 4
#define AVS_PHI_TEXTURE u_lightVolumes0
#else
#define AVS_PHI_TEXTURE u_lightVolumes1
#endif
// (phi, sigma~t) at light-grid coordinate lc.
vec4 DiffuseAt(vec3 lc)
{
  vec4 t = textureLod(AVS_PHI_TEXTURE, lc, 0.0);
  return vec4(t[AVS_PHI_SLOT & 3] * u_phiColour, t[AVS_AVERAGED_SLOT & 3]);
}
#else
uniform sampler3D u_diffuse;
vec4 DiffuseAt(vec3 lc)
{
  return textureLod(u_diffuse, lc, 0.0);
}
#endif
vec3 g_phi = vec3(0.0);
float g_averaged = 0.0;
#ifdef AVS_DIFFUSE_ANISOTROPIC
// Anisotropic scattering (g != 0): phi's derivative along the ray weighs the flux J.w.
uniform float u_anisotropy;
uniform float u_reducedFloor; // 1 / the flux limiter's transport length
// The previous sample's (or pair's) phi and its index (-100: none), for phi's derivative along
// the ray.
vec3 g_phiBefore = vec3(0.0);
int g_phiBeforeIndex = -100;
#endif
#elif !defined(AVS_AVERAGED_SLOT)
uniform sampler3D u_averagedExtinction;
#endif
uniform vec3 u_lightVolumeDimensions;
// The light grid covers the whole image of which the volume is a piece (distributed rendering;
// the volume itself otherwise): the whole's samples and the piece's first sample in it.
uniform vec3 u_wholeDimensions;
uniform vec3 u_pieceOffset;
uniform sampler2D u_table;         // A(theta, tau) for the current g and albedo
uniform vec2 u_tableSize;          // theta nodes, tau nodes
uniform float u_tableTauMaximum;
uniform float u_albedo;
uniform float u_ambientRadius;
uniform float u_emissionWeight;
#ifdef AVS_DIFFUSE_ANISOTROPIC
// What the diffuse field scatters towards the camera (DiffuseFluence.h, ScatteredFluence):
// phi + g clamp(3 J.w, -phi, phi), J.w = D dphi/dt along the ray, dphi/dt = slope.
vec3 ScatteredFluenceOf(vec3 phi, float averaged, vec3 slope)
{
  float d3 = 1.0 / max((1.0 - u_albedo * u_anisotropy) * averaged, u_reducedFloor);
  vec3 positive = max(phi, vec3(0.0)); // the relaxation may overshoot below 0 at vacuum
  return positive + u_anisotropy * clamp(d3 * slope, -positive, positive);
}
// ... of the sample i, dphi/dt from the previous sample that read phi (0 if it was not i - 1).
vec3 ScatteredFluence(vec3 phi, float averaged, int i, float dt)
{
  vec3 slope = g_phiBeforeIndex == i - 1 ? (phi - g_phiBefore) / dt : vec3(0.0);
  g_phiBefore = phi;
  g_phiBeforeIndex = i;
  return ScatteredFluenceOf(phi, averaged, slope);
}
#elif defined(AVS_DIFFUSE)
// Isotropic scattering (g = 0, the default): the flux term vanishes, and what the diffuse
// field scatters towards the camera is phi (its positive part), with no derivative to track.
vec3 ScatteredFluence(vec3 phi, float averaged, int i, float dt)
{
  return max(phi, vec3(0.0));
}
#endif

int g_lag = 0;            // k = floor(r / dt)
float g_lagFraction = 0.0; // f = r / dt - k
// Per-ray constants of the lookups (index -> light-volume texture coordinate, table coordinates).
// (Set by the per-ray code; the initial values only tell the compiler so: Mesa 26 warns of
// globals read in functions without them.)
vec3 g_lightScale = vec3(0.0), g_lightOffset = vec3(0.0);
vec2 g_tableScale = vec2(0.0), g_tableOffset = vec2(0.0);
float g_tauScale = 0.0;
float g_thetaCoordinate[8]; // per ray, for directional lights (their theta is constant on a ray)
#ifdef AVS_TABLE_COLUMN
// Per ray, for directional lights: A(theta_j; tau) at the table's AVS_TABLE_COLUMN tau nodes,
// interpolated in theta once. Interpolating this column in tau then gives the table's bilinear
// value at (theta_j, tau) with two reads instead of a 2D texture fetch per light and sample.
// An array per light (ColumnAt picks it for the constant j): read at an index known only per
// sample, one array of all the lights' columns cost a software rasterizer about 0.2 EA frames
// more with four lights.
#define AVS_COLUMN_ARRAY(j) float g_column##j[AVS_TABLE_COLUMN];
AVS_FOR_EACH_LIGHT(AVS_COLUMN_ARRAY)
#endif
#ifndef AVS_LOOKAHEAD_EXPLICIT
float g_ring[AVS_RING]; // T at the last AVS_RING samples; AVS_RING is a power of two > k + 1
#ifdef AVS_BRICKED
// Samples before the ray's first whose T the ring holds (a brick's look-back, below), and T
// before the unsplit ray's start relative to this ray's (1 where they are the same).
int g_prefix = 0;
float g_before = 1.0;
#else
// An unsplit ray: constants, so that the look-ahead costs what it did before bricking.
#define g_prefix 0
#define g_before 1.0
#endif
#endif

// The table's theta coordinate, sqrt(theta / pi) (denser near theta = 0).
float ThetaCoordinate(float cosTheta)
{
  return sqrt(acos(clamp(cosTheta, -1.0, 1.0)) * (1.0 / PI));
}

// A(theta; tau) from the table slice at theta coordinate u and tau coordinate v (see
// ThetaCoordinate and TableTauCoordinate).
float InScattering(float u, float v)
{
  return textureLod(u_table, vec2(u, v) * g_tableScale + g_tableOffset, 0.0).r;
}

#ifdef AVS_TABLE_COLUMN
// Fills light j's column for the theta coordinate u.
void FillColumn(int j, float u)
{
  float x = u * (u_tableSize.x - 1.0);
  int i = min(int(x), int(u_tableSize.x) - 2);
  float f = x - float(i);
  for (int n = 0; n < AVS_TABLE_COLUMN; ++n)
  {
    float a =
      mix(texelFetch(u_table, ivec2(i, n), 0).r, texelFetch(u_table, ivec2(i + 1, n), 0).r, f);
    // (j a constant: one of these stores.)
#define AVS_COLUMN_STORE(k) if (j == k) g_column##k[n] = a;
    AVS_FOR_EACH_LIGHT(AVS_COLUMN_STORE)
  }
}

// Node n of light j's column (j a constant in the unrolled loops, so this folds to one array).
float ColumnAt(int j, int n)
{
#define AVS_COLUMN_READ(k) if (j == k) return g_column##k[n];
  AVS_FOR_EACH_LIGHT(AVS_COLUMN_READ)
  return g_column0[n];
}

// A(theta_j; tau) of directional light j from its column at tau coordinate v.
float ColumnInScattering(int j, float v)
{
  float x = v * float(AVS_TABLE_COLUMN - 1);
  int n = min(int(x), AVS_TABLE_COLUMN - 2);
  float f = x - float(n);
  return mix(ColumnAt(j, n), ColumnAt(j, n + 1), f);
}
#endif

float TableTauCoordinate(float tau)
{
  return log(1.0 + clamp(tau, 0.0, u_tableTauMaximum)) * g_tauScale;
}

// Light j's tube transmittance in the packed light-volume textures (lights 0-3, 4-7). j is a
// constant in the unrolled loops, so this folds to one component.
float Tube(int j, vec4 tubes0, vec4 tubes1)
{
  return j < 4 ? tubes0[clamp(j, 0, 3)] : tubes1[clamp(j - 4, 0, 3)];
}

// Surfaces inside the medium (avs_surface.glsl, with AVS_SURFACE), and the lights' direct light
// a surface sample reflects.
//AVS::Surface::Dec
#ifdef AVS_SURFACE
#if defined(AVS_LIGHTS_PER_PAIR) && !defined(AVS_LOOKAHEAD_EXPLICIT) && \
  !defined(AVS_SURFACE_BLENDED)
// Surfaces at blending 0 with the lights read per pair of samples (AVS_SAMPLE_PAIRS): P_s
// depends on the gradient alone, read once per pair, so what the pair's samples return of each
// light is weighed by it once, in the pair's snippet.
#define AVS_SURFACE_PER_PAIR
#endif
// The light values LightSum read last (its tube transmittances and averaged sigma_t).
vec4 g_surfaceTubes0 = vec4(1.0);
vec4 g_surfaceTubes1 = vec4(1.0);
float g_surfaceAveraged = 0.0;
// The lights' direct light a surface reflects at the last SurfaceLights, per unit of T (1 -
// e^(-sigma dt)) and of P_s: albedo e^(-l sigma~) sum_j E_j T_j f_d cos (to be multiplied by
// the colour) and albedo e^(-l sigma~) sum_j E_j T_j f_s cos, l sigma~ = min(r sigma~, 1) / 2
// (SurfaceShading.h); with AVS_SURFACE_PER_PAIR times the pair's P_s too.
vec3 g_surfaceDiffuse = vec3(0.0);
vec3 g_surfaceSpecular = vec3(0.0);

// (r.v)^p for r.v >= 0: with AVS_SURFACE_SPECULAR_POWER (an integer p, at most 128) by
// squaring, straight-line code the compiler folds for the constant p (the bits of p choose the
// factors; the squares nothing uses go).
float SpecularLobe(float rv)
{
#ifdef AVS_SURFACE_SPECULAR_POWER
  const int p = AVS_SURFACE_SPECULAR_POWER;
  float b1 = rv, b2 = b1 * b1, b4 = b2 * b2, b8 = b4 * b4, b16 = b8 * b8, b32 = b16 * b16;
  float b64 = b32 * b32, b128 = b64 * b64;
  return ((p & 1) != 0 ? b1 : 1.0) * ((p & 2) != 0 ? b2 : 1.0) * ((p & 4) != 0 ? b4 : 1.0) *
    ((p & 8) != 0 ? b8 : 1.0) * ((p & 16) != 0 ? b16 : 1.0) * ((p & 32) != 0 ? b32 : 1.0) *
    ((p & 64) != 0 ? b64 : 1.0) * ((p & 128) != 0 ? b128 : 1.0);
#else
  return exp2(u_surfaceCoefficients.w * log2(max(rv, 1e-30)));
#endif
}

// Light j's (a constant) share of them, the light at `world` with the tube transmittance
// LightSum read there: E_j T_j (n.l) and E_j T_j (n.l) max(0, r.v)^p, with n the normal turned
// to the viewer `v` and r.v = 2 (n.l)(n.v) - l.v (SurfaceReflectance's terms, the BRDF's
// constants applied once for all lights in SurfaceLights).
void SurfaceLight(int j,
  vec3 world,
  vec3 n,
  float nv,
  vec3 v,
  inout vec3 diffuse,
  inout vec3 specular)
{
  vec3 propagation, irradiance;
  LightAt(j, world, propagation, irradiance);
  float nl = max(-dot(n, propagation), 0.0);
  float rv = max(2.0 * nl * nv + dot(propagation, v), 0.0);
  vec3 arriving = irradiance * (Tube(j, g_surfaceTubes0, g_surfaceTubes1) * nl);
  diffuse += arriving;
  specular += arriving * SpecularLobe(rv);
}

// The direct light a surface reflects at a sample's light point `world` (where LightSum read
// the light values last), with the last SurfaceGradientAt's normal: SurfaceReflectance summed
// over the lights, times the albedo and e^(-l sigma~).
void SurfaceLights(vec3 world, vec3 direction)
{
  vec3 v = -direction;
  vec3 n = g_surfaceNormal;
  float nv = dot(n, v);
  if (nv < 0.0 && u_surfaceTwoSided == 1)
  {
    n = -n;
    nv = -nv;
  }
  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
#define AVS_SURFACE_LIGHT(j) SurfaceLight(j, world, n, nv, v, diffuse, specular);
  AVS_FOR_EACH_LIGHT(AVS_SURFACE_LIGHT)
  // Nothing where the viewer is behind the surface (one-sided).
  float shadow =
    nv > 0.0 ? u_albedo * exp(-0.5 * min(u_ambientRadius * g_surfaceAveraged, 1.0)) : 0.0;
  vec4 k = u_surfaceCoefficients;
  g_surfaceDiffuse = diffuse * (shadow * k.y / PI);
  g_surfaceSpecular = specular * (shadow * k.z * (k.w + 2.0) / (2.0 * PI));
}

// The direct light a sample (colour `color`, P_s from SurfaceShareFor) reflects per unit of T
// (1 - e^(-sigma dt)): P_s (c D + S) of SurfaceLights.
vec3 SurfaceReflected(vec3 color)
{
#ifdef AVS_SURFACE_PER_PAIR
  return color * g_surfaceDiffuse + g_surfaceSpecular; // P_s in them
#else
  return (color * g_surfaceDiffuse + g_surfaceSpecular) * g_surfaceShare;
#endif
}
#endif

// E_j(x') A(theta_j; tau) of light j (a constant) at x'; `tube` is the light volume there (the
// tube transmittance where the light enters the ball around x', Core/LightVolume.h), v the
// table coordinate of tau.
vec3 LightInScattering(int j, vec3 world, vec3 direction, float tube, float v)
{
  vec3 propagation, irradiance;
  LightAt(j, world, propagation, irradiance);
#ifdef AVS_TABLE_COLUMN
  if (!LightIsPositional(j))
  {
    return irradiance * (tube * ColumnInScattering(j, v));
  }
#endif
  float u =
    LightIsPositional(j) ? ThetaCoordinate(dot(propagation, -direction)) : g_thetaCoordinate[j];
  return irradiance * (tube * InScattering(u, v));
}

// sum_j E_j(x) A(theta_j; r sigma~_t(x)) at the continuous voxel index x (world position
// `world`) for a ray along `direction`; the extended model also leaves phi and sigma~_t there in
// g_phi and g_averaged.
vec3 LightSum(vec3 index, vec3 world, vec3 direction)
{
  // The averaged sigma_t and the tube transmittances of all lights at x' (light grid), four
  // lights to a texture fetch.
  vec3 lc = index * g_lightScale + g_lightOffset;
#if AVS_LIGHT_TEXTURES > 0
  vec4 tubes0 = textureLod(u_lightVolumes0, lc, 0.0);
#else
  vec4 tubes0 = vec4(1.0);
#endif
#if AVS_LIGHT_TEXTURES > 1
  vec4 tubes1 = textureLod(u_lightVolumes1, lc, 0.0);
#else
  vec4 tubes1 = vec4(1.0);
#endif
#if defined(AVS_DIFFUSE) && !defined(AVS_PHI_SLOT)
  vec4 diffuse = DiffuseAt(lc);
  float averaged = diffuse.a;
  g_phi = diffuse.rgb;
#elif defined(AVS_AVERAGED_SLOT)
  float averaged = AVS_AVERAGED_SLOT < 4 ? tubes0[AVS_AVERAGED_SLOT & 3] : tubes1[AVS_AVERAGED_SLOT & 3];
#else
  float averaged = textureLod(u_averagedExtinction, lc, 0.0).r;
#endif
#ifdef AVS_PHI_SLOT
  // (In the lights' fetch too, beside the averaged extinction.)
  g_phi = Tube(AVS_PHI_SLOT, tubes0, tubes1) * u_phiColour;
#endif
#ifdef AVS_DIFFUSE
  g_averaged = averaged;
#endif
#ifdef AVS_SURFACE
  g_surfaceTubes0 = tubes0;
  g_surfaceTubes1 = tubes1;
  g_surfaceAveraged = averaged;
#endif
  float v = TableTauCoordinate(u_ambientRadius * averaged);
  vec3 inscatter = vec3(0.0);
#define AVS_ADD_LIGHT(j) inscatter += LightInScattering(j, world, direction, Tube(j, tubes0, tubes1), v);
  AVS_FOR_EACH_LIGHT(AVS_ADD_LIGHT)
  return inscatter;
}

// The ray parameter at which sample s (of this ray; brickFirst + s of the unsplit one) reads its
// lights: with AVS_LIGHTS_PER_PAIR the midpoint of its group of the unsplit ray's samples
// (G m to G m + G - 1), else the sample itself.
int g_parity = 0; // the unsplit ray's index of sample 0, modulo G
#ifdef AVS_LIGHTS_PER_PAIR
// The first sample of sample s's group (of this ray).
int GroupFirst(int s)
{
  return s - ((s + g_parity) & (AVS_LIGHT_GROUP - 1));
}
#endif
float LightT(int s)
{
#ifdef AVS_LIGHTS_PER_PAIR
  return t0 + (float(GroupFirst(s)) + 0.5 * float(AVS_LIGHT_GROUP - 1) + offset) * dtWorld;
#else
  return t0 + (float(s) + offset) * dtWorld;
#endif
}

#ifdef AVS_SURFACE
// The surfaces' texel of sample s (of this ray; brickFirst + s of the unsplit one): with
// AVS_LIGHTS_PER_PAIR the mean of its group's two middle samples' (the unsplit ray's
// G m + G / 2 - 1 and G m + G / 2; the ray's last sample for one beyond it), else its own, as
// the CPU reference reads them (Classifier::SurfaceAtMean). (With AVS_SURFACE_PACKED the
// group's own fetches serve instead.)
vec4 SurfaceTexelOf(int s)
{
#ifdef AVS_LIGHTS_PER_PAIR
#ifdef AVS_BRICKED
  int last = raySteps - 1 - brickFirst; // the unsplit ray's last sample, of this ray
#else
  int last = raySteps - 1;
#endif
  int middle = GroupFirst(s) + AVS_LIGHT_GROUP / 2;
  float ta = t0 + (float(min(middle - 1, last)) + offset) * dtWorld;
  float tb = t0 + (float(min(middle, last)) + offset) * dtWorld;
  vec4 a = textureLod(u_surfaces, VolumeCoordinate(io + ta * id), 0.0);
  vec4 b = textureLod(u_surfaces, VolumeCoordinate(io + tb * id), 0.0);
  return 0.5 * (a + b);
#else
  float t = t0 + (float(s) + offset) * dtWorld;
  return textureLod(u_surfaces, VolumeCoordinate(io + t * id), 0.0);
#endif
}
#endif

// sigma_t(x') c(x') sum_j E_j A(theta_j; r sigma~_t) for `classified` = (c, sigma_t) at x', the
// lights read at the ray parameter tl (LightT).
vec3 InScattered(vec4 classified, float tl)
{
  return classified.a * classified.rgb * LightSum(io + tl * id, origin + tl * direction, direction);
}

#ifdef AVS_LIGHTS_PER_PAIR
#ifndef AVS_LOOKAHEAD_EXPLICIT
#define AVS_SAMPLE_PAIRS
#define AVS_SAMPLE_GROUP AVS_LIGHT_GROUP
#endif
vec3 g_pairLight = vec3(0.0); // the current pair's light sum (AVS_SAMPLE_PAIRS)
#ifdef AVS_DIFFUSE
// And what its diffuse field scatters towards the camera, times albedo / (4 pi).
vec3 g_pairFluence = vec3(0.0);
#ifdef AVS_SURFACE_PER_PAIR
// (Per pair, to be multiplied by the colour: weighed by the pair's surface, with the lights'
// direct light it reflects; and what needs no colour.)
vec3 g_pairFluenceWhite = vec3(0.0);
#endif
#endif
#endif

#ifndef AVS_LOOKAHEAD_EXPLICIT
bool EffectContinues(float T, int i)
{
  // Sample i still receives light while the transmittance k + 1 samples back is above the
  // threshold.
  return i <= g_lag - g_prefix ||
    g_ring[(i - g_lag - 1 + AVS_RING) & (AVS_RING - 1)] >= u_termination;
}
#endif

#ifndef AVS_LOOKAHEAD_EXPLICIT
// Empty-space skipping (avs_skip.glsl; not with the explicit look-ahead, whose sample i adds the
// light of sample i + k + 1): the samples [from, to) were empty and leapt over, T held over
// them, and the ring keeps it for those it reads again: k + 1 and k + 2 back from `to` on, and
// with groups of G samples from the group of `to`, which starts up to G - 1 before it, on
// (whose samples the ray takes again), down to k + G back from `to`.
#define AVS_EFFECT_LEAP
#ifdef AVS_SAMPLE_PAIRS
#define AVS_LEAP_KEEPS (AVS_SAMPLE_GROUP > 2 ? AVS_SAMPLE_GROUP : 2)
#else
#define AVS_LEAP_KEEPS 2
#endif
void EffectLeap(int from, int to)
{
  for (int s = max(from, to - g_lag - AVS_LEAP_KEEPS); s < to; ++s)
  {
    g_ring[s & (AVS_RING - 1)] = T;
  }
}
#endif
//AVS::Effect::Init
  g_lag = int(floor(u_ambientRadius / dt));
  g_lagFraction = u_ambientRadius / dt - float(g_lag);
  // lc = ((index + offset) / (whole dims - 1) * (light dims - 1) + 0.5) / light dims; table
  // texel centres.
  g_lightScale =
    (u_lightVolumeDimensions - 1.0) / ((u_wholeDimensions - 1.0) * u_lightVolumeDimensions);
  g_lightOffset = u_pieceOffset * g_lightScale + 0.5 / u_lightVolumeDimensions;
  g_tableScale = (u_tableSize - 1.0) / u_tableSize;
  g_tableOffset = 0.5 / u_tableSize;
  g_tauScale = 1.0 / log(1.0 + u_tableTauMaximum);
#ifdef AVS_DIFFUSE_ANISOTROPIC
  // None yet: per ray (a fragment may cast several: the image sample distance).
  g_phiBeforeIndex = -100;
#endif
#if defined(AVS_BRICKED) && defined(AVS_LIGHTS_PER_PAIR)
  g_parity = brickFirst & (AVS_LIGHT_GROUP - 1);
#endif
#if defined(AVS_SAMPLE_PAIRS) && defined(AVS_DIFFUSE_ANISOTROPIC) && defined(AVS_BRICKED)
  // A brick's first group takes dphi/dt from the unsplit ray's group before it (in the bricks
  // in front), as the unsplit ray does.
  if (brickFirst - g_parity >= AVS_LIGHT_GROUP)
  {
    float tb = LightT(-g_parity) - float(AVS_LIGHT_GROUP) * dtWorld;
    g_phiBefore = DiffuseAt((io + tb * id) * g_lightScale + g_lightOffset).rgb;
    g_phiBeforeIndex = -g_parity - AVS_LIGHT_GROUP;
  }
#endif
#define AVS_THETA_COORDINATE(j) g_thetaCoordinate[j] = ThetaCoordinate(dot(u_lightAxis[j], -direction));
  AVS_FOR_EACH_LIGHT(AVS_THETA_COORDINATE)
#ifdef AVS_TABLE_COLUMN
#define AVS_FILL_COLUMN(j) if (!LightIsPositional(j)) FillColumn(j, g_thetaCoordinate[j]);
  AVS_FOR_EACH_LIGHT(AVS_FILL_COLUMN)
#endif
#if defined(AVS_BRICKED) && !defined(AVS_LOOKAHEAD_EXPLICIT)
  // A brick's pass (ARCHITECTURE.md, "Bricking"): the unsplit ray's k + 1 samples before this
  // brick's first (those of the bricks in front, whose voxels the brick's texture holds as its
  // look-back layers) fill the ring with T relative to the brick's start, T(-j) = 1 / (the
  // transmittance of the samples -j .. -1), as the unsplit ray holds them relative to its own.
  // Composited under the bricks in front, whose transmittance is T at this brick's start, the
  // in-scattered light of the brick's first k samples is the unsplit ray's. Capped at
  // 1 / u_termination (where the unsplit ray would have ended before).
  g_prefix = min(g_lag + 1, brickFirst);
  {
    float behind = 1.0;
    for (int j = 1; j <= g_prefix; ++j)
    {
      vec3 back = io + (t0 + (offset - float(j)) * dtWorld) * id;
      vec3 backCoordinate = VolumeCoordinate(back);
      vec4 s0 = Classify(textureLod(AVS_VOLUME_TEXTURE, backCoordinate, 0.0), backCoordinate);
      AVS_CROP(s0, back);
      behind = min(behind / exp(-s0.a * dt), 1.0 / max(u_termination, 1e-6));
      g_ring[(AVS_RING - j) & (AVS_RING - 1)] = behind;
    }
    // Where the look-back reached the unsplit ray's start (brickFirst < k + 1), T before it is
    // 1, relative to this brick's start the last value.
    g_before = behind;
  }
#endif
//AVS::Effect::Pair
#ifdef AVS_SAMPLE_PAIRS
    if (g_pairMaterial)
    {
      // The lights of the group's samples, read once at their midpoint (not for a group
      // without material: none of its samples would add them).
      float tp = LightT(max(pair, 0));
      g_pairLight = LightSum(io + tp * id, origin + tp * direction, direction);
#ifdef AVS_SURFACE
      // Surfaces: the group's gradient (the mean of its middle samples' texels) and reflected
      // light (at its lights).
#ifdef AVS_SURFACE_PACKED
      // (From the group's own fetches, not bricked: pair >= 0, and the samples beyond the ray's
      // end are its last.)
#if AVS_SAMPLE_GROUP == 4
      SurfaceGradientFrom(0.5 * (voxelB + voxelC), -direction);
#else
      SurfaceGradientFrom(0.5 * (voxelA + voxelB), -direction);
#endif
#else
      SurfaceGradientFrom(SurfaceTexelOf(pair), -direction);
#endif
      SurfaceLights(origin + tp * direction, direction);
#endif
#ifdef AVS_DIFFUSE_ANISOTROPIC
      // dphi/dt from the group before (G steps back; 0 at the unsplit ray's first group), its
      // phi read here where that group had no material or was leapt over.
      bool before = g_phiBeforeIndex == pair - AVS_SAMPLE_GROUP;
#ifdef AVS_BRICKED
      bool exists = brickFirst + pair >= AVS_SAMPLE_GROUP;
#else
      bool exists = pair >= AVS_SAMPLE_GROUP;
#endif
      if (!before && exists)
      {
        float tb = LightT(max(pair, 0)) - float(AVS_SAMPLE_GROUP) * dtWorld;
        g_phiBefore = DiffuseAt((io + tb * id) * g_lightScale + g_lightOffset).rgb;
        before = true;
      }
      vec3 slope = before ? (g_phi - g_phiBefore) / (float(AVS_SAMPLE_GROUP) * dt) : vec3(0.0);
      g_phiBefore = g_phi;
      g_phiBeforeIndex = pair;
      g_pairFluence = ScatteredFluenceOf(g_phi, g_averaged, slope) * (u_albedo / (4.0 * PI));
#elif defined(AVS_DIFFUSE)
      g_pairFluence = max(g_phi, vec3(0.0)) * (u_albedo / (4.0 * PI));
#endif
#ifdef AVS_SURFACE_PER_PAIR
      // The pair's P_s weighs what both its samples return: of the lights' in-scattering
      // (VolumetricShare), of their direct light (SurfaceReflected) and of the diffuse field
      // (DiffuseFieldColor = c a + w).
      SurfaceShareFor(0.0);
      g_pairLight *= VolumetricShare();
      g_surfaceDiffuse *= g_surfaceShare;
      g_surfaceSpecular *= g_surfaceShare;
#ifdef AVS_DIFFUSE
      vec4 k = u_surfaceCoefficients;
      float facing = g_surfaceFacing ? 1.0 : 0.0;
      // With the lights' direct light the pair's surface reflects (SurfaceReflected), which
      // its samples weigh alike: one term per sample for both.
      g_pairFluenceWhite = g_pairFluence * (g_surfaceShare * facing * k.z) + g_surfaceSpecular;
      g_pairFluence =
        g_pairFluence * (1.0 - g_surfaceShare * (1.0 - k.x - facing * k.y)) + g_surfaceDiffuse;
#endif
#endif
    }
#endif
//AVS::Effect::Sample
#if defined(AVS_DIFFUSE) && defined(AVS_LOOKAHEAD_EXPLICIT)
    // The extended model's diffuse light at the sample itself: albedo c phi / (4 pi) per unit
    // optical depth, integrated exactly over the step (T (1 - exp(-sigma_t dt))). (With the
    // ring, below, from the fetch of the sample's own InScattered.)
    if (here.a > 0.0 && T >= u_termination)
    {
      float tl = LightT(i);
      vec4 diffuse = DiffuseAt((io + tl * id) * g_lightScale + g_lightOffset);
#if defined(AVS_LIGHTS_PER_PAIR) && defined(AVS_DIFFUSE_ANISOTROPIC)
      // dphi/dt from the group before, G steps back (none before the unsplit ray's first).
      vec3 before = DiffuseAt(
        (io + (tl - float(AVS_LIGHT_GROUP) * dtWorld) * id) * g_lightScale + g_lightOffset).rgb;
#ifdef AVS_BRICKED
      bool afterFirstPair = brickFirst + i >= AVS_LIGHT_GROUP; // the unsplit ray's index
#else
      bool afterFirstPair = i >= AVS_LIGHT_GROUP;
#endif
      vec3 slope =
        afterFirstPair ? (diffuse.rgb - before) / (float(AVS_LIGHT_GROUP) * dt) : vec3(0.0);
      vec3 phi = ScatteredFluenceOf(diffuse.rgb, diffuse.a, slope);
#else
      vec3 phi = ScatteredFluence(diffuse.rgb, diffuse.a, i, dt);
#endif
#ifdef AVS_SURFACE
      // Surfaces reflect the diffuse field too (avs_surface.glsl), the gradient SurfaceTexelOf's.
      SurfaceGradientFrom(SurfaceTexelOf(i), -direction);
      SurfaceShareFor(here.a);
      L += T * (1.0 - extinction) * u_albedo * (1.0 / (4.0 * PI)) * DiffuseFieldColor(here.rgb) *
        phi;
#else
      L += T * (1.0 - extinction) * u_albedo * (1.0 / (4.0 * PI)) * here.rgb * phi;
#endif
    }
#endif
#if defined(AVS_SURFACE) && defined(AVS_LOOKAHEAD_EXPLICIT)
    // Surfaces: the direct light the sample reflects, its lights and gradient read at its light
    // point.
    if (here.a > 0.0 && T >= u_termination)
    {
      float ts = LightT(i);
      LightSum(io + ts * id, origin + ts * direction, direction); // (for its light values)
      SurfaceGradientFrom(SurfaceTexelOf(i), -direction);
      SurfaceLights(origin + ts * direction, direction);
      SurfaceShareFor(here.a);
      L += T * (1.0 - extinction) * SurfaceReflected(here.rgb);
    }
#endif
#ifdef AVS_EMISSION
    if (T >= u_termination)
    {
      L += T * (1.0 - u_albedo) * here.a * u_emissionWeight * dt * here.rgb;
    }
#endif
#ifndef AVS_LOOKAHEAD_EXPLICIT
    g_ring[i & (AVS_RING - 1)] = T;
    // T at the samples k and k + 1 back; 1 before the ray's start (g_before: a brick's).
    float newer =
      i >= g_lag - g_prefix ? g_ring[(i - g_lag + AVS_RING) & (AVS_RING - 1)] : g_before;
    float older =
      i > g_lag - g_prefix ? g_ring[(i - g_lag - 1 + AVS_RING) & (AVS_RING - 1)] : g_before;
    if (here.a > 0.0 && older >= u_termination)
    {
      float lagged = mix(newer, older, g_lagFraction);
#if defined(AVS_SURFACE) && !defined(AVS_SURFACE_PER_PAIR)
      // Surfaces: the share of the volumetric light the sample returns, the gradient its pair's
      // (from the pair's snippet) or its own (here). (Per pair: in g_pairLight already.)
#if defined(AVS_SURFACE_PACKED) && !defined(AVS_SAMPLE_PAIRS)
      SurfaceGradientFrom(voxel, -direction); // (the sample's texel)
#elif !defined(AVS_SAMPLE_PAIRS)
      SurfaceGradientAt(coordinate, -direction);
#endif
      SurfaceShareFor(here.a);
      lagged *= VolumetricShare();
#endif
#if defined(AVS_SAMPLE_PAIRS) && defined(AVS_DIFFUSE) && \
  (!defined(AVS_SURFACE) || defined(AVS_SURFACE_PER_PAIR))
      // With the diffuse field's light at the sample itself (T <= older: every sample that
      // adds it passed the test above; T (1 - e^(-sigma dt)) where T is above the threshold),
      // both times the colour: one term. (Surfaces per pair: with what the pair's surface
      // reflects of the lights' direct light and of the diffuse field, weighed in the pair's
      // snippet, which needs no colour.)
      float diffuseWeight = T >= u_termination ? T * (1.0 - extinction) : 0.0;
      L += here.rgb * (lagged * dt * here.a * g_pairLight + diffuseWeight * g_pairFluence);
#ifdef AVS_SURFACE_PER_PAIR
      L += diffuseWeight * g_pairFluenceWhite;
#endif
#elif defined(AVS_SAMPLE_PAIRS)
      L += lagged * dt * here.a * here.rgb * g_pairLight;
#else
      L += lagged * dt * InScattered(here, t);
#if defined(AVS_SURFACE)
      SurfaceLights(origin + t * direction, direction); // with the lights just read
#endif
#endif
#if defined(AVS_DIFFUSE) && \
  !(defined(AVS_SAMPLE_PAIRS) && (!defined(AVS_SURFACE) || defined(AVS_SURFACE_PER_PAIR)))
      // The extended model's diffuse light at the sample itself (T <= older: every sample
      // that adds it passed the test above), phi from the pair's snippet or from the
      // InScattered just now, times albedo / (4 pi). (Pairs without surfaces or with surfaces
      // per pair: above.)
      if (T >= u_termination)
      {
#ifdef AVS_SAMPLE_PAIRS
        vec3 scattered = g_pairFluence;
#else
        vec3 scattered = ScatteredFluence(g_phi, g_averaged, i, dt) * (u_albedo / (4.0 * PI));
#endif
#if defined(AVS_SURFACE)
        // Surfaces reflect the diffuse field too (avs_surface.glsl).
        L += T * (1.0 - extinction) * DiffuseFieldColor(here.rgb) * scattered;
#else
        L += T * (1.0 - extinction) * here.rgb * scattered;
#endif
      }
#endif
#if defined(AVS_SURFACE) && !(defined(AVS_SURFACE_PER_PAIR) && defined(AVS_DIFFUSE))
      // Surfaces: the direct light the sample reflects, with the light values its in-scattering
      // (or its pair's) read. (Per pair in the extended model: with the diffuse field, above.)
      if (T >= u_termination)
      {
        L += T * (1.0 - extinction) * SurfaceReflected(here.rgb);
      }
#endif
    }
#else
    if (i == 0)
    {
      // The samples 0 to k, within r of the ray's start, which no sample reaches k + 1 steps
      // back: T = 1 r before them.
      for (int j = 0; j <= g_lag && j < steps; ++j)
      {
        float tj = t + float(j) * dtWorld;
        vec3 first = io + tj * id;
        vec3 firstCoordinate = VolumeCoordinate(first);
        vec4 firstVoxel = textureLod(AVS_VOLUME_TEXTURE, firstCoordinate, 0.0);
        vec4 s1 = Classify(firstVoxel, firstCoordinate);
        AVS_CROP(s1, first);
        if (s1.a > 0.0)
        {
#ifdef AVS_SURFACE
          SurfaceGradientFrom(SurfaceTexelOf(j), -direction);
          SurfaceShareFor(s1.a);
          L += dt * VolumetricShare() * InScattered(s1, LightT(j));
#else
          L += dt * InScattered(s1, LightT(j));
#endif
        }
      }
    }
    if (i + g_lag + 1 < steps)
    {
      // The sample k + 1 steps on, weighted by T interpolated r before it.
      float lagged = T * mix(extinction, 1.0, g_lagFraction);
      float ta = t + float(g_lag + 1) * dtWorld;
      vec3 ahead = io + ta * id;
      vec3 aheadCoordinate = VolumeCoordinate(ahead);
      vec4 aheadVoxel = textureLod(AVS_VOLUME_TEXTURE, aheadCoordinate, 0.0);
      vec4 s2 = Classify(aheadVoxel, aheadCoordinate);
      AVS_CROP(s2, ahead);
      if (s2.a > 0.0)
      {
#ifdef AVS_SURFACE
        SurfaceGradientFrom(SurfaceTexelOf(i + g_lag + 1), -direction);
        SurfaceShareFor(s2.a);
        lagged *= VolumetricShare();
#endif
        L += lagged * dt * InScattered(s2, LightT(i + g_lag + 1));
      }
    }
#endif
