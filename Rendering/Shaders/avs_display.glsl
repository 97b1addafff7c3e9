// The display transform (Rendering/Core/DisplayTransform.h, whose Apply this computes): the
// premultiplied linear radiance L times the exposure, then the tone curve: 0 Clamp (none: the
// framebuffer clamps), 1 Shoulder (linear to s = u_shoulderStart, then s + (1 - s) u / (1 + u),
// u = (m - s) / (1 - s), on m = max(R, G, B), the colour scaled by curve(m) / m so that hue and
// saturation stay and no channel reaches 1).
uniform float u_exposure;
uniform int u_toneMapping;
uniform float u_shoulderStart; // avs::DisplayTransform::ShoulderStart

vec3 DisplayTransform(vec3 radiance)
{
  vec3 x = radiance * u_exposure;
  float m = max(max(x.r, x.g), x.b);
  if (u_toneMapping == 1 && m > u_shoulderStart)
  {
    float u = (m - u_shoulderStart) / (1.0 - u_shoulderStart);
    // u / (1 + u), written to stay finite for an infinite u (a half float that overflowed)
    float curve = u_shoulderStart + (1.0 - u_shoulderStart) * (1.0 - 1.0 / (1.0 + u));
    x *= curve / m;
  }
  return x;
}
