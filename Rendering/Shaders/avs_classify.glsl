// Colour and extinction of a scalar (ALGORITHM.md section 1): the colour transfer function's
// colour and sigma_t = -ln(1 - min(alpha, 1 - 1e-6)) / u, with the transfer function sampled over
// u_scalarRange in a 1D texture of u_transferSize texels. Shared by the ray caster and the
// averaged-extinction pass, which insert it at //AVS::Classify::Dec. InitClassify() sets the
// affine maps scalar -> normalised value -> texture coordinate once (per ray in the ray caster);
// Classify(s) is then one texture fetch.
uniform sampler1D u_transfer; // rgb colour, a opacity over u_scalarRange
uniform vec2 u_scalarRange;
uniform float u_transferSize;
uniform float u_unitDistance;

vec2 g_transferScale, g_transferOffset;

void InitClassify()
{
  g_transferScale =
    vec2(1.0 / (u_scalarRange.y - u_scalarRange.x), (u_transferSize - 1.0) / u_transferSize);
  g_transferOffset = vec2(-u_scalarRange.x * g_transferScale.x, 0.5 / u_transferSize);
}

// (colour, sigma_t) of the scalar s.
vec4 Classify(float s)
{
  float c = clamp(s * g_transferScale.x + g_transferOffset.x, 0.0, 1.0);
  vec4 rgba = textureLod(u_transfer, c * g_transferScale.y + g_transferOffset.y, 0.0);
  float alpha = min(rgba.a, 1.0 - 1e-6);
  return vec4(rgba.rgb, alpha > 0.0 ? -log(1.0 - alpha) / u_unitDistance : 0.0);
}
