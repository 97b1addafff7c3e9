//VTK::System::Dec
// The picture of the path-traced refinement (Rendering/Core/Refinement.h, whose RefinedPicture
// this computes): the ambient-scattering picture A plus the residual r = M - A of the path
// tracer's running mean M in two bands, each weighed by its bias against its noise over a window
// of (2 R + 1)^2 pixels (clamped to the picture): the window's mean residual, and the pixel's
// difference from it; A below 16 samples. Then the display transform (avs_display.glsl),
// composited by the caller's blending (ONE, ONE_MINUS_SRC_ALPHA) as the ray caster's pass is.

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
  if (n >= 16.0) // avs::RefinementMinimumSamples
  {
    vec4 sum = vec4(0.0);
    float squares = 0.0, variance = 0.0, own = 0.0;
    for (int dy = -R; dy <= R; ++dy)
    {
      for (int dx = -R; dx <= R; ++dx)
      {
        ivec2 q = clamp(p + ivec2(dx, dy), ivec2(0), size - 1);
        vec4 m = texelFetch(u_sum, q, 0) / n;
        vec4 ambient = texelFetch(u_ambient, q, 0);
        vec4 r = m - ambient;
        sum += r;
        squares += dot(r, r);
        vec4 s = max(texelFetch(u_sumSquares, q, 0) / n - m * m, vec4(0.0)) / (n - 1.0);
        // At least the variance of a mean of hits and misses as likely as A says.
        float h = clamp(ambient.a, 0.0, 1.0);
        vec4 least = h > 0.0
          ? vec4(ambient.rgb * ambient.rgb * ((1.0 - h) / h), h * (1.0 - h)) / n
          : vec4(0.0);
        s = max(s, least);
        float v = s.r + s.g + s.b + s.a;
        variance += v;
        if (dx == 0 && dy == 0)
          own = v;
      }
    }
    float count = float((2 * R + 1) * (2 * R + 1));
    vec4 residual = sum / count; // the window's mean residual
    float smoothEnergy = dot(residual, residual);
    float v = variance / count;
    float smoothBias2 = max(smoothEnergy - 2.0 * v / count, 0.0);
    float smoothWeight =
      smoothBias2 + v / count > 0.0 ? smoothBias2 / (smoothBias2 + v / count) : 1.0;
    float detailBias2 = max(squares / count - smoothEnergy - 2.0 * v, 0.0);
    float noise = max(v, own);
    float detailWeight = detailBias2 + noise > 0.0 ? detailBias2 / (detailBias2 + noise) : 1.0;
    vec4 r = texelFetch(u_sum, p, 0) / n - a;
    result = a + smoothWeight * residual + detailWeight * (r - residual);
  }
  gl_FragData[0] = vec4(DisplayTransform(result.rgb), result.a);
}
