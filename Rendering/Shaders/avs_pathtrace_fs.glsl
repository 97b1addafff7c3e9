//VTK::System::Dec
// The GPU path tracer of the path-traced refinement (vtkAmbientScatteringVolumeMapper::
// PathTracedRefinement; ARCHITECTURE.md, "Refinement at rest"): one sample per pixel of the
// unbiased estimator of Rendering/Core/PathTracer.cxx (its reference, which the tests compare
// with pixel by pixel) for the medium the ray caster draws: the same classification
// (avs_classify.glsl: components, masks, NaN voxels, gradient opacity), clipping and cropping
// (avs_clip.glsl) and lights (avs_lights.glsl: VTK's attenuation and spot cones). Delta tracking
// samples the free flights, ratio tracking the transmittance of next-event estimation to every
// light, over the majorants of the cells empty-space skipping uses (u_majorants: an upper bound of
// sigma_t per data unit for each cell of u_cellSize voxels, avs::Majorants); directions come from
// the Henyey-Greenstein phase function; the medium emits k_e (1 - albedo) sigma_t c; Russian
// roulette ends the paths. The camera ray ends at the depth of the opaque geometry drawn before.
// With surfaces inside the medium (AVS_SURFACE, avs_surface.glsl) a collision is a surface event
// with probability P_s: next-event estimation through k_a c times the phase function plus the
// BRDF, and the path goes on by the phase function (k_a), the diffuse lobe (k_d), the specular
// lobe (k_s) or ends, as avs::RenderPathTraced.
//
// Distances t run along world rays; sigma_t is per data unit (the vtkVolume's coordinates before
// its matrix), so a world step of length t crosses t * |d(index)/dt * spacing| data units, as the
// ray caster integrates.
//
// Output: target 0 gets (L, hit), target 1 (L^2, hit), added by the blending to the
// accumulation buffers: the running sums of the samples and of their squares.

//VTK::Output::Dec

in vec2 texCoord; // the pixel's centre in the viewport, [0, 1]^2

uniform mat4 u_ndcToWorld;
uniform mat4 u_worldToIndex;
uniform sampler2D u_depth;
uniform vec3 u_dimensions;
uniform vec3 u_spacing;
uniform float u_border;
uniform float u_albedo;
uniform float u_anisotropy;
uniform float u_emissionWeight;
uniform sampler3D u_majorants;
uniform vec3 u_majorantCells;
uniform float u_majorantCellSize;
uniform vec2 u_viewportSize;
uniform int u_sampleIndex; // which sample of the pixel this pass adds
uniform int u_seed;

const float PI = 3.14159265358979;
const float FAR = 1e30;
// Guards against a path that never ends (a GPU must not hang); far beyond what Russian roulette
// lets a path reach.
const int MAXIMUM_BOUNCES = 256;
const int MAXIMUM_TRACKING_STEPS = 8192;
const int ROULETTE_DEPTH = 4; // bounces before Russian roulette, as avs::PathTracerSettings

//AVS::Classify::Dec

//AVS::Lights::Dec

//AVS::Clip::Dec

//AVS::Surface::Dec

// Random numbers: a permutation of 32-bit integers (a PCG output step), one stream per pixel and
// sample.
uint g_state = 0u;
uint Permute(uint v)
{
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
// Uniform in [0, 1).
float Uniform()
{
  g_state = Permute(g_state);
  return float(g_state >> 8u) * (1.0 / 16777216.0);
}

float HenyeyGreenstein(float mu, float g)
{
  float d = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}

// A direction whose cosine with `w` follows Henyey-Greenstein (avs::SampleHenyeyGreenstein).
vec3 SampleHenyeyGreenstein(vec3 w, float g)
{
  float u = Uniform();
  float mu;
  if (abs(g) < 1e-3)
  {
    mu = 1.0 - 2.0 * u;
  }
  else
  {
    float sq = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    mu = (1.0 + g * g - sq * sq) / (2.0 * g);
  }
  mu = clamp(mu, -1.0, 1.0);
  float s = sqrt(max(0.0, 1.0 - mu * mu));
  float phi = 2.0 * PI * Uniform();
  vec3 a = abs(w.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 b1 = normalize(cross(w, a));
  vec3 b2 = cross(w, b1);
  return normalize(mu * w + s * (cos(phi) * b1 + sin(phi) * b2));
}

// Colour (rgb) and sigma_t per data unit (a) of the medium at a continuous index: nothing outside
// the volume's box or where clipping planes or cropping remove it.
vec4 MediumAt(vec3 index)
{
  if (any(lessThan(index, vec3(-u_border))) ||
    any(greaterThan(index, u_dimensions - 1.0 + u_border)))
  {
    return vec4(0.0);
  }
  vec3 coordinate = (index + 0.5) / u_dimensions;
  vec4 here = Classify(textureLod(AVS_VOLUME_TEXTURE, coordinate, 0.0), coordinate);
#ifdef AVS_CLIPPING
  here.a *= ClipInside(index, true);
#endif
  return here;
}

// The world ray origin + t direction in the index frame, the data units per world unit along it,
// and the part [t0, t1] of [0, tMaximum] inside the volume's box; false where it misses.
bool IndexRay(vec3 origin,
  vec3 direction,
  float tMaximum,
  out vec3 io,
  out vec3 id,
  out float dataPerWorld,
  out float t0,
  out float t1)
{
  io = (u_worldToIndex * vec4(origin, 1.0)).xyz;
  id = (u_worldToIndex * vec4(direction, 0.0)).xyz;
  dataPerWorld = length(id * u_spacing);
  vec3 lo = (-u_border - io) / id;
  vec3 hi = (u_dimensions - 1.0 + u_border - io) / id;
  vec3 tmin = min(lo, hi);
  vec3 tmax = max(lo, hi);
  t0 = max(max(max(tmin.x, tmin.y), tmin.z), 0.0);
  t1 = min(min(min(tmax.x, tmax.y), tmax.z), tMaximum);
  return t1 > t0;
}

// The majorant cell around index(t) (nudged along the ray): returns the distance where the ray
// leaves it (at most t1) and its majorant per world unit in `majorant`. The first and last cells
// reach to the box's faces, as in the CPU's walk.
float CellExit(vec3 io, vec3 id, float t, float t1, float dataPerWorld, out float majorant)
{
  float B = u_majorantCellSize;
  vec3 p = io + (t + 1e-5 * (1.0 + abs(t))) * id;
  vec3 cell = clamp(floor(p / B), vec3(0.0), u_majorantCells - 1.0);
  vec3 lower = mix(cell * B, vec3(-u_border), equal(cell, vec3(0.0)));
  vec3 upper = (cell + 1.0) * B;
  upper = mix(upper,
    max(upper, u_dimensions - 1.0 + u_border),
    equal(cell, u_majorantCells - 1.0));
  float exit = t1;
  for (int a = 0; a < 3; ++a)
  {
    if (id[a] > 0.0)
      exit = min(exit, (upper[a] - io[a]) / id[a]);
    else if (id[a] < 0.0)
      exit = min(exit, (lower[a] - io[a]) / id[a]);
  }
  majorant = texelFetch(u_majorants, ivec3(cell), 0).r * dataPerWorld;
  // Always forward: a float step that rounds to nothing would never leave the cell.
  return max(exit, t + 1e-6 * (1.0 + abs(t)));
}

// Delta tracking: the distance of a real collision along the world ray before tMaximum (and the
// medium there), or -1 when the ray leaves without one.
float SampleCollision(vec3 origin, vec3 direction, float tMaximum, out vec4 medium)
{
  medium = vec4(0.0);
  vec3 io, id;
  float dataPerWorld, t0, t1;
  if (!IndexRay(origin, direction, tMaximum, io, id, dataPerWorld, t0, t1))
    return -1.0;
  float t = t0;
  for (int k = 0; k < MAXIMUM_TRACKING_STEPS && t < t1; ++k)
  {
    float majorant;
    float exit = CellExit(io, id, t, t1, dataPerWorld, majorant);
    if (!(majorant > 0.0))
    {
      t = exit;
      continue;
    }
    float step = -log(1.0 - Uniform()) / majorant;
    if (t + step >= exit)
    {
      t = exit; // memoryless: sample afresh in the next cell
      continue;
    }
    t += step;
    medium = MediumAt(io + t * id);
    if (Uniform() * majorant < medium.a * dataPerWorld)
      return t;
  }
  return -1.0;
}

// Ratio tracking with Russian roulette: an unbiased estimate of the transmittance along the world
// ray up to tMaximum.
float Transmittance(vec3 origin, vec3 direction, float tMaximum)
{
  vec3 io, id;
  float dataPerWorld, t0, t1;
  if (!IndexRay(origin, direction, tMaximum, io, id, dataPerWorld, t0, t1))
    return 1.0;
  float T = 1.0;
  float t = t0;
  for (int k = 0; k < MAXIMUM_TRACKING_STEPS && t < t1; ++k)
  {
    float majorant;
    float exit = CellExit(io, id, t, t1, dataPerWorld, majorant);
    if (!(majorant > 0.0))
    {
      t = exit;
      continue;
    }
    float step = -log(1.0 - Uniform()) / majorant;
    if (t + step >= exit)
    {
      t = exit;
      continue;
    }
    t += step;
    float sigma = MediumAt(io + t * id).a * dataPerWorld;
    T *= max(0.0, 1.0 - sigma / majorant);
    if (T < 0.05)
    {
      if (Uniform() >= 0.5)
        return 0.0;
      T *= 2.0;
    }
    if (!(T > 0.0))
      return 0.0;
  }
  return T;
}

#ifdef AVS_POSITIONAL_LIGHTS
// The light j (a constant where AVS_FOR_EACH_LIGHT expands it) sends to x, ratio-tracked through
// the medium, and its propagation direction there.
vec3 ArrivingLight(int j, vec3 x, out vec3 propagation)
{
  vec3 irradiance;
  LightAt(j, x, propagation, irradiance);
  if (!(max(max(irradiance.r, irradiance.g), irradiance.b) > 0.0))
    return vec3(0.0);
  float distance = LightIsPositional(j) ? length(u_lightPosition[j] - x) : FAR;
  float T = Transmittance(x, -propagation, distance);
  return T > 0.0 ? irradiance * T : vec3(0.0);
}

// Next-event estimation towards light j: the light light j sends from x towards -w (the path's
// direction reversed), per unit of the scattering albedo.
vec3 NextEvent(int j, vec3 x, vec3 w)
{
  vec3 propagation;
  vec3 arriving = ArrivingLight(j, x, propagation);
  return arriving * HenyeyGreenstein(dot(propagation, -w), u_anisotropy);
}
#define AVS_NEXT_EVENT(j) light += NextEvent(j, x, w);
#ifdef AVS_SURFACE
// Next-event estimation towards light j at a surface event (the last SurfaceAt's): k_a of a
// phase-function event plus the BRDF, with the albedo (chromatic for all but the specular part).
vec3 SurfaceNextEvent(int j, vec3 x, vec3 w, vec3 albedo)
{
  vec3 propagation;
  vec3 arriving = ArrivingLight(j, x, propagation);
  float phase = HenyeyGreenstein(dot(propagation, -w), u_anisotropy);
  vec2 r = SurfaceReflectance(g_surfaceNormal, -propagation, -w);
  return arriving * (albedo * (u_surfaceCoefficients.x * phase + r.x) + u_albedo * r.y);
}
#define AVS_SURFACE_NEXT_EVENT(j) light += SurfaceNextEvent(j, x, w, albedo);
#endif
#endif

void main()
{
  g_state = Permute(uint(gl_FragCoord.x) +
    Permute(uint(gl_FragCoord.y) + Permute(uint(u_sampleIndex) + Permute(uint(u_seed)))));

  // A camera ray through a random point of the pixel.
  vec2 jitter = (vec2(Uniform(), Uniform()) - 0.5) / u_viewportSize;
  vec2 ndc = (texCoord + jitter) * 2.0 - 1.0;
  vec4 nearPoint = u_ndcToWorld * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = u_ndcToWorld * vec4(ndc, 1.0, 1.0);
  vec3 x = nearPoint.xyz / nearPoint.w;
  vec3 w = normalize(farPoint.xyz / farPoint.w - x);
  // Opaque geometry drawn before ends the camera ray.
  float limit = FAR;
  float depth = texture(u_depth, texCoord).r;
  if (depth < 1.0)
  {
    vec4 p = u_ndcToWorld * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    limit = dot(p.xyz / p.w - x, w);
  }

  vec3 L = vec3(0.0);
  vec3 beta = vec3(1.0);
  float hit = 0.0;
  for (int bounce = 0; bounce < MAXIMUM_BOUNCES; ++bounce)
  {
    vec4 medium;
    float t = SampleCollision(x, w, limit, medium);
    if (t < 0.0)
      break; // the environment is black; the background is composited as the ray caster's
    if (bounce == 0)
      hit = 1.0;
    x += t * w;
    // Emission: sigma_a L_e / sigma_t at a real collision.
    L += beta * medium.rgb * ((1.0 - u_albedo) * u_emissionWeight);
    vec3 albedo = medium.rgb * u_albedo; // chromatic single-scattering albedo
    if (!(max(max(albedo.r, albedo.g), albedo.b) > 0.0))
      break;
    vec3 light = vec3(0.0);
#ifdef AVS_SURFACE
    // A surface event with probability P_s (avs_surface.glsl).
    vec3 index = (u_worldToIndex * vec4(x, 1.0)).xyz;
    SurfaceAt((index + 0.5) / u_dimensions, medium.a, -w);
    bool surface = g_surfaceShare > 0.0 && Uniform() < g_surfaceShare;
    if (surface)
    {
#ifdef AVS_POSITIONAL_LIGHTS
      AVS_FOR_EACH_LIGHT(AVS_SURFACE_NEXT_EVENT)
#endif
      L += beta * light;
      // Go on by the lobe chosen with the coefficients' weights (each one's f cos / pdf over
      // its probability: albedo c for the phase function and the diffuse lobe, the albedo
      // times (p + 2) / (p + 1) cos for the specular one).
      vec4 k = u_surfaceCoefficients;
      vec3 v = -w;
      vec3 n = dot(g_surfaceNormal, v) < 0.0 && u_surfaceTwoSided == 1 ? -g_surfaceNormal
                                                                       : g_surfaceNormal;
      float u = Uniform();
      if (u < k.x)
      {
        beta *= albedo;
        w = SampleHenyeyGreenstein(w, u_anisotropy);
      }
      else if (g_surfaceFacing && u < k.x + k.y)
      {
        beta *= albedo;
        w = SampleCosine(n, Uniform(), Uniform());
      }
      else if (g_surfaceFacing && u < k.x + k.y + k.z)
      {
        vec3 mirror = normalize(n * (2.0 * dot(n, v)) - v);
        vec3 d = SamplePhongLobe(mirror, k.w, Uniform(), Uniform());
        float cosine = dot(n, d);
        if (!(cosine > 0.0))
          break;
        beta *= u_albedo * (k.w + 2.0) / (k.w + 1.0) * cosine;
        w = d;
      }
      else
      {
        break; // absorbed
      }
    }
    else
#endif
    {
      // A phase-function event.
#ifdef AVS_POSITIONAL_LIGHTS
      AVS_FOR_EACH_LIGHT(AVS_NEXT_EVENT)
#endif
      L += beta * albedo * light;
      beta *= albedo;
      w = SampleHenyeyGreenstein(w, u_anisotropy);
    }
    limit = FAR;
    if (bounce >= ROULETTE_DEPTH)
    {
      float q = min(1.0, max(max(beta.r, beta.g), beta.b));
      if (Uniform() >= q)
        break;
      beta /= q;
    }
  }
  // A sample that went wrong in floating point would spoil the running sums for good.
  if (any(isnan(L)) || any(isinf(L)))
    L = vec3(0.0);
  gl_FragData[0] = vec4(L, hit);
  gl_FragData[1] = vec4(L * L, hit);
}
