// Surfaces inside the medium: the GPU twin of Rendering/Core/SurfaceShading.h, which defines
// every term (the CPU reference, ReferenceRenderer.cxx, and the CPU path tracer compute the same).
// Defined with AVS_SURFACE (ShadeOn, VolumetricScatteringBlending below 2): P_s and the normal
// from the precomputed gradient of the shading component (u_surfaces, avs::SurfaceGrid: one
// RGBA8 fetch, SurfaceGradientAt), what a sample returns of the volumetric light
// (VolumetricShare) and of the extended model's diffuse field (DiffuseFieldColor), the BRDF
// (SurfaceReflectance) and its lobes (SampleCosine, SamplePhongLobe). Shared by ambient
// scattering's ray casting (avs_as_effect.glsl, which adds the lights' direct light,
// SurfaceReflected) and the path tracer (avs_pathtrace_fs.glsl, its surface events), after
// their classification and lights. P_s is the edge share alone at blending 0; with
// AVS_SURFACE_BLENDED (above 0) it depends on the sample's opacity too.
#ifdef AVS_SURFACE
uniform sampler3D u_surfaces;        // RGB: 128 + 127 e n (bytes), n the unit local gradient
uniform float u_surfaceBlending;     // B in [0, 2]
uniform vec4 u_surfaceCoefficients;  // k_a, k_d, k_s, p (resolved: k_a + k_d + k_s <= 1)
uniform int u_surfaceTwoSided;       // the renderer's TwoSidedLighting
uniform mat3 u_surfaceToWorld;       // local gradient -> world gradient
float g_surfaceShare = 0.0;          // P_s of the last SurfaceAt
float g_surfaceEdge = 0.0;           // the edge share e of the last SurfaceGradientAt
vec3 g_surfaceNormal = vec3(0.0);    // its normal, world space
bool g_surfaceFacing = false;        // whether it reflects towards the camera (SurfaceShading.h)

#ifdef AVS_SURFACE_BLENDED
// P_s from the edge share e and the opacity alpha (avs::SurfaceProbabilityOfEdge).
float SurfaceProbability(float edge, float alpha)
{
  float g = -log(max(1.0 - edge, 1e-6));
  float b = u_surfaceBlending;
  float decay = exp(-b * g * clamp(alpha, 0.0, 1.0));
  float volumetric = b < 1.0 ? b * decay : (2.0 - b) * decay + (b - 1.0);
  return edge * (1.0 - volumetric);
}
#endif

#ifdef AVS_SURFACE_PACKED
// The texture holds the scalars in A too (vtkAVSSurfaceTexture), so that a sample's one fetch
// (ClassifySample) brings its gradient: the scalars' texel value of a texel t.
uniform float u_packedScale;
uniform float u_packedShift;
vec4 PackedScalar(vec4 t)
{
  return vec4(t.a * u_packedScale + u_packedShift);
}
#endif

// The gradient of a texel `t` of u_surfaces: the edge share, the normal and whether the surface
// reflects towards `toViewer`, into g_surfaceEdge, g_surfaceNormal, g_surfaceFacing.
void SurfaceGradientFrom(vec4 t, vec3 toViewer)
{
  vec3 local = t.xyz * (255.0 / 127.0) - 128.0 / 127.0;
  vec3 world = u_surfaceToWorld * local;
  // (Where the gradient vanishes around, e is 0 and the normal nothing.)
  g_surfaceEdge = min(1.0, length(local));
  g_surfaceNormal = world * -inversesqrt(max(dot(world, world), 1e-30));
  g_surfaceFacing = u_surfaceTwoSided == 1 || dot(g_surfaceNormal, toViewer) > 0.0;
}

// The same at volume texture coordinate `coordinate`.
void SurfaceGradientAt(vec3 coordinate, vec3 toViewer)
{
  SurfaceGradientFrom(textureLod(u_surfaces, coordinate, 0.0), toViewer);
}

// P_s of a sample with sigma_t `sigma` at the last SurfaceGradientAt's gradient, into
// g_surfaceShare (0 where the gradient vanishes).
void SurfaceShareFor(float sigma)
{
#ifdef AVS_SURFACE_BLENDED
  g_surfaceShare = SurfaceProbability(g_surfaceEdge, 1.0 - exp(-sigma * u_unitDistance[0]));
#else
  g_surfaceShare = g_surfaceEdge;
#endif
}

// Both, for a sample at `coordinate`.
void SurfaceAt(vec3 coordinate, float sigma, vec3 toViewer)
{
  SurfaceGradientAt(coordinate, toViewer);
  SurfaceShareFor(sigma);
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

// A direction at polar cosine `cosTheta` and azimuth `phi` about the unit vector `axis`.
vec3 AboutAxis(vec3 axis, float cosTheta, float phi)
{
  vec3 a = abs(axis.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 b1 = normalize(cross(axis, a));
  vec3 b2 = cross(axis, b1);
  float s = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
  return normalize(cosTheta * axis + s * (cos(phi) * b1 + sin(phi) * b2));
}
// Cosine-weighted about n (pdf cos / pi) and within the Phong lobe of power p about `mirror`
// (pdf (p + 1) / (2 pi) cos^p), from two uniform numbers (avs::SampleCosine, SamplePhongLobe).
vec3 SampleCosine(vec3 n, float u1, float u2)
{
  return AboutAxis(n, sqrt(u1), 2.0 * PI * u2);
}
vec3 SamplePhongLobe(vec3 mirror, float p, float u1, float u2)
{
  return AboutAxis(mirror, exp2(log2(max(u1, 1e-30)) / (p + 1.0)), 2.0 * PI * u2);
}
#endif
