#version 430
// Tube marching of one light into one channel of a packed light-volume texture
// (ALGORITHM.md section 5; the CPU version is Rendering/Core/LightVolume.cxx, which the tests
// hold this pass against). Each point x gets the tube transmittance where the light enters the
// ball of radius r around x, at distance max(D - r, 0) from x0 (LightVolume.h says why). All
// positions are in the data's local frame: the volume box is [0, u_extent], axis-aligned. The
// averaged extinction is on the target (light) grid.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// AVS_LIGHT_FORMAT (defined by the ray caster): the light-volume textures' format.
layout(AVS_LIGHT_FORMAT, binding = 0) uniform image3D u_target; // four channels, this light's
uniform int u_channel;
uniform ivec3 u_targetDimensions;
uniform vec3 u_targetSpacing;

uniform sampler3D u_averaged;   // averaged extinction on the target grid (texel centres = points)
uniform vec3 u_extent;

// log(F(tau) exp(2 tau)) on the table's tau nodes (at most AVS_MAXIMUM_TAU_NODES, which the
// ray caster defines): read from an array rather than a texture, a software rasterizer's
// texture fetch costing as much as the rest of a step.
uniform float u_logGain[AVS_MAXIMUM_TAU_NODES];
uniform int u_tauNodes;
uniform float u_tauMaximum;
uniform float u_radius;
// 0: each ball passes on F (the paper's tube); 1: the direct light alone, exp(-2 tau) per ball
// (the extended model's positional lights; TubeLaw in LightVolume.h).
uniform int u_directBeam;

// A program per kind of pass (a software rasterizer runs every branch of a shader): tube
// marching from a directional light, from a positional one (AVS_LIGHT_VOLUME_POSITIONAL), or,
// with AVS_LIGHT_VOLUME_COPY, no tube marching: the averaged extinction itself is copied into
// channel u_channel, where the ray caster reads it beside the lights' (the free channel of the
// last light texture); with AVS_LIGHT_VOLUME_COPY_FLUENCE the extended model's diffuse fluence
// of lights of one colour c, as the one number phi.c / c.c (u_fluenceWeights = c / c.c), into
// the channel after that.
#ifdef AVS_LIGHT_VOLUME_COPY_FLUENCE
#define AVS_LIGHT_VOLUME_COPY
uniform sampler3D u_fluence; // (phi, sigma~t) on the target grid (vtkAVSDiffuseVolume)
uniform vec3 u_fluenceWeights;
#endif
#ifndef AVS_LIGHT_VOLUME_COPY
// Tube marching goes over the tiles of the target that something reads (Core/LightTiles.h:
// 8 x 8 x 1 points, the work group), one work group each: x | y << 10 (tile indices) | z << 20
// (vtkAVSTileList: the count and the indirect dispatch before them).
layout(std430, binding = 0) readonly buffer avs_LightTiles
{
  uint u_tileCount;
  uint u_tileGroups[3];
  uint u_tiles[];
};
#endif
uniform vec3 u_light;           // propagation direction (directional) or position (positional)

float g_tauScale = 0.0;         // (tau nodes - 1) / log(1 + tau maximum), set in main
vec3 g_coordinateScale;         // local -> texture coordinate: local * scale + offset
vec3 g_coordinateOffset;

// The averaged extinction at a local point inside the box.
float AveragedInside(vec3 local)
{
  return textureLod(u_averaged, local * g_coordinateScale + g_coordinateOffset, 0.0).r;
}

// The same anywhere: 0 outside the box (empty space).
float Averaged(vec3 local)
{
  vec3 index = local / u_targetSpacing;
  vec3 dims = vec3(u_targetDimensions);
  if (any(lessThan(index, vec3(-1e-6))) || any(greaterThan(index, dims - 1.0 + 1e-6)))
  {
    return 0.0;
  }
  return AveragedInside(local);
}

// log F(tau): the factors of a tube are summed as logarithms, one exp at the end.
float LogForwardTransport(float tau)
{
  if (!(tau > 0.0))
  {
    return 0.0;
  }
  if (u_directBeam != 0)
  {
    return -2.0 * tau;
  }
  // Linear in log(1 + tau) between the nodes, as ScatteringSlice::ForwardTransport.
  float x = log(1.0 + min(tau, u_tauMaximum)) * g_tauScale;
  int n = clamp(int(x), 0, u_tauNodes - 2);
  float f = clamp(x - float(n), 0.0, 1.0);
  return -2.0 * tau + mix(u_logGain[n], u_logGain[n + 1], f);
}

// Entry and exit of the ray o + t d with the box; false when it misses.
bool Box(vec3 o, vec3 d, out float t0, out float t1)
{
  t0 = -1e30;
  t1 = 1e30;
  for (int a = 0; a < 3; ++a)
  {
    if (abs(d[a]) < 1e-30)
    {
      if (o[a] < 0.0 || o[a] > u_extent[a])
        return false;
      continue;
    }
    float ta = -o[a] / d[a];
    float tb = (u_extent[a] - o[a]) / d[a];
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
    if (t0 > t1)
      return false;
  }
  return true;
}

void main()
{
#ifdef AVS_LIGHT_VOLUME_COPY
  ivec3 voxel = ivec3(gl_GlobalInvocationID);
#else
  uint t = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
  if (t >= u_tileCount)
  {
    return;
  }
  uint tile = u_tiles[t];
  ivec3 voxel = ivec3(int(tile & 1023u) * 8, int((tile >> 10) & 1023u) * 8, int(tile >> 20)) +
    ivec3(gl_LocalInvocationID.xy, 0);
#endif
  if (any(greaterThanEqual(voxel, u_targetDimensions)))
  {
    return;
  }
#ifdef AVS_LIGHT_VOLUME_COPY
  vec4 texel = imageLoad(u_target, voxel);
#ifdef AVS_LIGHT_VOLUME_COPY_FLUENCE
  texel[u_channel] = dot(texelFetch(u_fluence, voxel, 0).rgb, u_fluenceWeights);
#else
  texel[u_channel] = texelFetch(u_averaged, voxel, 0).r;
#endif
  imageStore(u_target, voxel, texel);
#else
  vec3 x = vec3(voxel) * u_targetSpacing;
  vec3 x0 = x;
  float t0, t1;
#ifndef AVS_LIGHT_VOLUME_POSITIONAL
  if (Box(x, -u_light, t0, t1))
  {
    x0 = x - u_light * max(0.0, t1);
  }
#else
  {
    vec3 p = u_light;
    float eps = 1e-9 * (1.0 + length(u_extent));
    bool inside = all(greaterThanEqual(p, vec3(-eps))) && all(lessThanEqual(p, u_extent + eps));
    float dist = length(x - p);
    if (inside)
    {
      x0 = p;
    }
    else if (dist > 0.0 && Box(p, (x - p) / dist, t0, t1))
    {
      x0 = p + (x - p) / dist * clamp(t0, 0.0, dist);
    }
  }
#endif
  float D = length(x - x0);
  float T = 1.0;
  if (D > 0.0)
  {
    vec3 d = (x - x0) / D;
    // The ball's entry point is D - r from x0 along the path.
    float ratio = max(D - u_radius, 0.0) / (2.0 * u_radius);
    int n = int(floor(ratio));
    float eta = ratio - float(n);
    g_tauScale = float(u_tauNodes - 1) / log(1.0 + u_tauMaximum);
    vec3 dims = vec3(u_targetDimensions);
    g_coordinateScale = 1.0 / (u_targetSpacing * dims);
    g_coordinateOffset = 0.5 / dims;
    // The tube is anchored at the ball's entry point e = x0 + (D - r) d (LightVolume.cxx says
    // why): n whole balls centred at e - (2 i + 1) r d, i < n, which lie on the segment
    // x0 -> e, inside the box; the rest, 2 r eta long, as a ball centred at x0 + eta r d,
    // weighted as eq. 8.5 weights its last ball (the box test keeps it against rounding).
    vec3 step = d * (2.0 * u_radius);
    vec3 m = x0 + d * (D - 2.0 * u_radius);
    float logT = 0.0;
    for (int i = 0; i < n; ++i)
    {
      logT += LogForwardTransport(u_radius * AveragedInside(m));
      m -= step;
    }
    float rest = exp(LogForwardTransport(u_radius * Averaged(x0 + d * (eta * u_radius))));
    T = exp(logT) * ((1.0 - eta) + eta * rest);
  }
  vec4 value = imageLoad(u_target, voxel);
  value[u_channel] = T;
  imageStore(u_target, voxel, value);
#endif
}
