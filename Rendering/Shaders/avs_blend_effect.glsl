//AVS::Effect::Dec
// vtkVolumeMapper's blend modes other than composite, for the emission-absorption mapper, as
// vtkGPUVolumeRayCastMapper (VTK 9.1) computes them unshaded. AVS_BLEND is VTK's number:
// 1 maximum intensity: the largest scalar on the ray through the transfer functions, colour c
//   and opacity alpha (not opacity-corrected), premultiplied: (alpha c, alpha);
// 2 minimum intensity: the same with the smallest scalar;
// 3 average intensity: the mean of alpha(s) s' over the samples whose scalar lies in
//   AverageIPScalarRange, s' the scalar normalised over the data's range, as an opaque grey
//   (none: nothing drawn);
// 4 additive: the sum of alpha(s) s' dt / u over the samples (the opacity scaled by the step
//   over the unit distance), clamped to 1, an opaque grey;
// 5 isosurface: where the ray crosses one of the AVS_ISO_COUNT sorted contour values between
//   two samples, the value's colour and opacity alpha are composited front to back, at most one
//   crossing per step.
// Samples in cropped-away regions are skipped (AVS_KEPT); clipping planes have shortened the
// ray. alpha is recovered from Classify's sigma_t: alpha = 1 - exp(-sigma_t u).
#define AVS_EFFECT_KEEPS_TRANSMITTANCE
#if AVS_BLEND != 5
#define AVS_EFFECT_TERMINATION
#define AVS_EFFECT_OUTPUT
#endif
uniform vec2 u_blendRange;   // the data's scalar range
uniform vec2 u_averageRange; // AverageIPScalarRange
#if AVS_BLEND == 5
uniform float u_isoValues[AVS_ISO_COUNT];
int g_isoIndex = -1; // the contour interval of the previous sample; -1 before the first
#endif
float g_value = 0.0; // the extreme scalar (1, 2) or the sum (3, 4)
int g_count = 0;   // samples averaged (3)

// Colour and opacity (as the transfer function gives it) of scalar s.
vec4 TransferAt(float s)
{
  vec4 c = ClassifyValue(s);
  return vec4(c.rgb, 1.0 - exp(-c.a * u_unitDistance[0]));
}

float Normalised(float s)
{
  return (s - u_blendRange.x) / (u_blendRange.y - u_blendRange.x);
}

#if AVS_BLEND == 5
// Contour value n of the list with -inf and +inf around it (n = 0 .. AVS_ISO_COUNT + 1).
float Contour(int n)
{
  return n <= 0 ? -1e20 : (n > AVS_ISO_COUNT ? 1e20 : u_isoValues[n - 1]);
}
#else
bool EffectContinues(float T, int i)
{
  return true; // the whole ray: these modes do not attenuate
}

vec4 EffectOutput(vec3 L, float T)
{
#if AVS_BLEND == 1 || AVS_BLEND == 2
  vec4 c = TransferAt(g_value);
  return vec4(c.rgb * c.a, c.a);
#elif AVS_BLEND == 3
  if (g_count == 0)
  {
    discard;
  }
  return vec4(vec3(clamp(g_value / float(g_count), 0.0, 1.0)), 1.0);
#else
  return vec4(vec3(clamp(g_value, 0.0, 1.0)), 1.0);
#endif
}
#endif
//AVS::Effect::Init
  // VTK starts the maximum at the range's minimum and the minimum at its maximum.
  g_value = AVS_BLEND == 1 ? u_blendRange.x : (AVS_BLEND == 2 ? u_blendRange.y : 0.0);
  g_count = 0;
#if AVS_BLEND == 5
  g_isoIndex = -1;
#endif
//AVS::Effect::Sample
    // One component (the mapper refuses more); NaN voxels (validity 0) and samples a binary
    // mask removes are skipped, as VTK skips them.
    float valid = Validity(voxel, coordinate);
    if (AVS_KEPT(index) && valid > 0.0 && MaskKeeps(coordinate))
    {
      float s = Components(voxel, valid).x;
#if AVS_BLEND == 1
      g_value = max(g_value, s);
#elif AVS_BLEND == 2
      g_value = min(g_value, s);
#elif AVS_BLEND == 3
      if (s >= u_averageRange.x && s <= u_averageRange.y)
      {
        g_value += TransferAt(s).a * Normalised(s);
        ++g_count;
      }
#elif AVS_BLEND == 4
      g_value += TransferAt(s).a * (dt / u_unitDistance[0]) * Normalised(s);
#else
      if (g_isoIndex < 0)
      {
        // The first sample: the interval [Contour(n), Contour(n + 1)) it lies in.
        int n = AVS_ISO_COUNT / 2;
        while (s > Contour(n))
          ++n;
        while (s < Contour(n))
          --n;
        g_isoIndex = n;
      }
      else
      {
        int n = clamp(g_isoIndex, 0, AVS_ISO_COUNT);
        float crossed = 0.0;
        bool cross = false;
        if (s < Contour(n))
        {
          crossed = Contour(n);
          --n;
          cross = true;
        }
        if (s > Contour(n + 1))
        {
          crossed = Contour(n + 1);
          ++n;
          cross = true;
        }
        g_isoIndex = n;
        if (cross && T >= u_termination)
        {
          vec4 c = TransferAt(crossed);
          L += T * c.a * c.rgb;
          T *= 1.0 - c.a;
        }
      }
#endif
    }
