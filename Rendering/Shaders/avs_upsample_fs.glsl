//VTK::System::Dec
// Composites the ray-casting pass rendered at another image sample distance over the
// framebuffer: the premultiplied colour and opacity interpolated bilinearly at the pixel's
// place in the viewport (the pass's rays sit at the centres of its own texels over the same
// viewport), blended by the caller with ONE, ONE_MINUS_SRC_ALPHA as the full-resolution pass is.
// The pass holds linear radiance (the sum of a split volume's bricks): the display transform
// (avs_display.glsl) is applied here.

//VTK::Output::Dec

in vec2 texCoord; // position in the viewport, [0, 1]^2 (from the quad's vertex shader)

uniform sampler2D u_sampled; // the pass: premultiplied colour, alpha = 1 - transmittance

//AVS::Display::Dec

void main()
{
  vec4 sampled = texture(u_sampled, texCoord);
  gl_FragData[0] = vec4(DisplayTransform(sampled.rgb), sampled.a);
}
