//VTK::System::Dec
// The picture of the path-traced refinement (Rendering/Core/Refinement.h, whose RefinedPicture
// this computes): the ambient-scattering picture A moved towards the path tracer's running mean M
// by w = b^2 / (b^2 + v), the squared bias b^2 = max(D - 2 v, 0) and the variance v of M averaged
// over a window of (2 R + 1)^2 pixels (clamped to the picture); A below four samples. Then the
// display transform (avs_display.glsl), composited by the caller's blending (ONE,
// ONE_MINUS_SRC_ALPHA) as the ray caster's pass is.

//VTK::Output::Dec

in vec2 texCoord; // position in the viewport, [0, 1]^2

uniform sampler2D u_ambient;    // A: premultiplied linear radiance, alpha = 1 - transmittance
uniform sampler2D u_sum;        // the sum of the samples (L, hit)
uniform sampler2D u_sumSquares; // the sum of their squares (L^2, hit)
uniform float u_samples;        // n

const int R = 2; // avs::RefinementWindowRadius

//AVS::Display::Dec

void main()
{
  ivec2 size = textureSize(u_sum, 0);
  ivec2 p = clamp(ivec2(texCoord * vec2(size)), ivec2(0), size - 1);
  vec4 a = texelFetch(u_ambient, p, 0);
  vec4 result = a;
  float n = u_samples;
  if (n >= 4.0) // avs::RefinementMinimumSamples
  {
    float difference = 0.0, variance = 0.0;
    for (int dy = -R; dy <= R; ++dy)
    {
      for (int dx = -R; dx <= R; ++dx)
      {
        ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), size - 1);
        vec4 m = texelFetch(u_sum, q, 0) / n;
        vec4 d = m - texelFetch(u_ambient, q, 0);
        difference += dot(d, d);
        vec4 s = max(texelFetch(u_sumSquares, q, 0) / n - m * m, vec4(0.0)) / (n - 1.0);
        variance += s.r + s.g + s.b + s.a;
      }
    }
    float count = float((2 * R + 1) * (2 * R + 1));
    difference /= count;
    variance /= count;
    float bias2 = max(difference - 2.0 * variance, 0.0);
    float w = bias2 + variance > 0.0 ? bias2 / (bias2 + variance) : 1.0;
    result = a + w * (texelFetch(u_sum, p, 0) / n - a);
  }
  gl_FragData[0] = vec4(DisplayTransform(result.rgb), result.a);
}
