// Surfaces inside the medium: the GPU twin of Rendering/Core/SurfaceShading.h, which defines
// every term (the CPU reference, ReferenceRenderer.cxx, computes the same sums). Defined with
// AVS_SURFACE (ShadeOn, VolumetricScatteringBlending below 2): a sample with extinction returns
// VolumetricShare() of its volumetric light (the ball's in-scattering, the extended model's
// diffuse light) and reflects the lights' direct light with the BRDF (SurfaceReflected), P_s and
// the normal from the gradient of component AVS_SURFACE_COMPONENT (SurfaceAt: VTK's central
// differences, one voxel on either side); the extended model's diffuse field it returns with
// DiffuseFieldColor. Inserted into ambient scattering's declarations.
#ifdef AVS_SURFACE
uniform float u_surfaceBlending;     // B in [0, 2]
uniform vec4 u_surfaceCoefficients;  // k_a, k_d, k_s, p (resolved: k_a + k_d + k_s <= 1)
uniform int u_surfaceTwoSided;       // the renderer's TwoSidedLighting
uniform float u_surfaceInverseRange; // 1 / the shading component's range
uniform float u_surfaceInverseReference; // 1 / gamma_0
uniform mat3 u_gradientToWorld;      // the transpose of d index / d world
float g_surfaceShare = 0.0;          // P_s of the last SurfaceAt
vec3 g_surfaceNormal = vec3(0.0);    // its normal, world space
bool g_surfaceFacing = false;        // whether it reflects towards the camera (SurfaceShading.h)
// The light values LightSum read last (its tube transmittances and averaged sigma_t).
vec4 g_surfaceTubes0 = vec4(1.0);
vec4 g_surfaceTubes1 = vec4(1.0);
float g_surfaceAveraged = 0.0;

float SurfaceProbability(float gamma, float alpha)
{
  float g = max(gamma, 0.0) * u_surfaceInverseReference;
  float b = u_surfaceBlending;
  float decay = exp(-b * g * clamp(alpha, 0.0, 1.0));
  float volumetric = b < 1.0 ? b * decay : (2.0 - b) * decay + (b - 1.0);
  return (1.0 - exp(-g)) * (1.0 - volumetric);
}

// P_s and the normal of the sample at volume texture coordinate `coordinate` with sigma_t
// `sigma`, into g_surfaceShare and g_surfaceNormal.
void SurfaceAt(vec3 coordinate, float sigma)
{
  vec3 g = vec3(0.0);
  for (int a = 0; a < 3; ++a)
  {
    vec3 e = vec3(0.0);
    e[a] = u_voxelStep[a];
    vec4 p = textureLod(AVS_VOLUME_TEXTURE, coordinate + e, 0.0);
    vec4 m = textureLod(AVS_VOLUME_TEXTURE, coordinate - e, 0.0);
    g[a] = 0.5 *
      (Components(p, Validity(p, coordinate + e))[AVS_SURFACE_COMPONENT] -
        Components(m, Validity(m, coordinate - e))[AVS_SURFACE_COMPONENT]) *
      u_surfaceInverseRange;
  }
  vec3 world = u_gradientToWorld * g;
  float len = length(world);
  float gamma = 2.0 * length(g * u_gradientScale);
  float alpha = 1.0 - exp(-sigma * u_unitDistance[0]);
  g_surfaceShare = len > 0.0 ? SurfaceProbability(gamma, alpha) : 0.0;
  g_surfaceNormal = len > 0.0 ? world * (-1.0 / len) : vec3(0.0);
  g_surfaceFacing = u_surfaceTwoSided == 1 || dot(g_surfaceNormal, -direction) > 0.0;
}

// What the last SurfaceAt's sample returns of the volumetric light: 1 - P_s (1 - k_a).
float VolumetricShare()
{
  return 1.0 - g_surfaceShare * (1.0 - u_surfaceCoefficients.x);
}

// The colour with which the last SurfaceAt's sample (colour `color`) returns the extended
// model's diffuse field, near isotropic: the medium with c, a surface with k_a c (its ambient
// share) plus, where it faces the camera, the BRDF's integral over the field, k_d c + k_s.
vec3 DiffuseFieldColor(vec3 color)
{
  vec4 k = u_surfaceCoefficients;
  float facing = g_surfaceFacing ? 1.0 : 0.0;
  return color * (1.0 - g_surfaceShare * (1.0 - k.x - facing * k.y)) +
    g_surfaceShare * facing * k.z;
}

// The BRDF times the cosine at the light: (diffuse, specular) for light from `toLight` seen
// from `toViewer`; 0 on the dark side.
vec2 SurfaceReflectance(vec3 n, vec3 toLight, vec3 toViewer)
{
  float nv = dot(n, toViewer);
  if (nv < 0.0 && u_surfaceTwoSided == 1)
  {
    n = -n;
    nv = -nv;
  }
  float nl = dot(n, toLight);
  if (!(nv > 0.0) || !(nl > 0.0))
  {
    return vec2(0.0);
  }
  vec3 mirror = n * (2.0 * nl) - toLight;
  float rv = max(0.0, dot(mirror, toViewer));
  float p = u_surfaceCoefficients.w;
  return vec2(u_surfaceCoefficients.y / PI * nl,
    u_surfaceCoefficients.z * (p + 2.0) / (2.0 * PI) * exp2(p * log2(max(rv, 1e-30))) * nl);
}

// Light j's (a constant) direct light that the last SurfaceAt's sample (colour `color`)
// reflects towards the camera, the light at `world` with the tube transmittance LightSum read
// there, `ball` the transmittance through the ball at the averaged sigma_t.
vec3 SurfaceLight(int j, vec3 world, vec3 direction, vec3 color, float ball)
{
  vec3 propagation, irradiance;
  LightAt(j, world, propagation, irradiance);
  vec2 r = SurfaceReflectance(g_surfaceNormal, -propagation, -direction);
  return irradiance * (color * r.x + r.y) * (Tube(j, g_surfaceTubes0, g_surfaceTubes1) * ball);
}

// The direct light the last SurfaceAt's sample (sigma_t `sigma`) reflects per unit of T (1 -
// e^(-sigma dt)): albedo P_s sum_j E_j T_j e^(-l sigma~) f cos, l = min(r, 1 / sigma) / 2, the
// lights as LightSum read them last.
vec3 SurfaceReflected(vec3 world, vec3 direction, vec3 color, float sigma)
{
  float ball = exp(-0.5 * min(u_ambientRadius, 1.0 / sigma) * g_surfaceAveraged);
  vec3 reflected = vec3(0.0);
#define AVS_REFLECT_LIGHT(j) reflected += SurfaceLight(j, world, direction, color, ball);
  AVS_FOR_EACH_LIGHT(AVS_REFLECT_LIGHT)
  return reflected * (u_albedo * g_surfaceShare);
}
#endif
