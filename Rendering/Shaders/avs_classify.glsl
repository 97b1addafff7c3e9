// Colour and extinction of the volume at a sample (ALGORITHM.md section 1), the GPU twin of
// Rendering/Core/Classifier.cxx (which says what every case means): sigma_t =
// -ln(1 - min(alpha, 1 - 1e-6)) / u per component, with the components, dependent or
// independent, gradient opacity, NaN voxels and masks chosen at compile time:
//   AVS_COMPONENTS        1-4
//   AVS_MODE              0 one component, 1 dependent colour + opacity, 2 dependent RGBA,
//                         3 independent components (the extinctions add)
//   AVS_VALIDITY          0 no NaN voxels; 1 the validity is the channel after the components;
//                         2 it is in u_validity (4 components)
//   AVS_GRADIENT          bit c: component c's extinction takes its gradient opacity
//   AVS_MASK              0 none, 1 binary, 2 label map
// The volume texture (AVS_VOLUME_TEXTURE, default u_scalars) holds the components, multiplied
// by the validity. The tables are rows of u_transfer (RGBA, u_transferSize.x columns): row c
// is component c's colour and opacity, row AVS_COMPONENTS + c its gradient opacity (in .a),
// row 2 AVS_COMPONENTS + L - 1 label L's colour and opacity; u_rowMap[row] maps a value to the
// texture's x coordinate over the row's range, with texel centres on the table's nodes (labels
// use row 0's; the texture's clamp to the edge clamps beyond the range), and u_rowY[row] is its
// layer. Shared by the ray caster and the
// averaged-extinction pass, which insert it at //AVS::Classify::Dec. Classify(raw, coordinate)
// takes the volume texel `raw` fetched at texture coordinate `coordinate`. The texel's channels
// are data values once mapped by u_valueScale and u_valueShift (DataValues): 8- and 16-bit
// scalars are stored normalized (vtkAVSTextureUpload.h), and the map is affine, so mapping the
// interpolated texel equals interpolating the data values, as the CPU reference does.
#ifndef AVS_VOLUME_TEXTURE
#define AVS_VOLUME_TEXTURE u_scalars
#endif
uniform sampler3D AVS_VOLUME_TEXTURE;
uniform sampler1DArray u_transfer; // one layer per row
uniform vec2 u_transferSize; // columns, rows
uniform vec2 u_rowMap[8];    // value -> x texture coordinate: value * x + y
uniform float u_rowY[8];     // the row's layer
uniform vec2 u_colorMap[3];  // dependent RGBA: component -> colour in [0, 1] (before clamping)
uniform float u_unitDistance[4];
uniform float u_weight[4];
uniform vec3 u_gradientScale; // mean spacing / (2 spacing) per index axis
uniform vec3 u_voxelStep;     // one voxel in texture coordinates per axis
uniform vec4 u_valueScale;    // texel -> data value per channel: texel * scale + shift
uniform vec4 u_valueShift;
#if AVS_VALIDITY == 2
uniform sampler3D u_validity;
#endif
#if AVS_MASK > 0
uniform sampler3D u_mask; // nearest
uniform float u_maskBlend;
uniform float u_labels; // labels with their own row
#endif

// Row `row` (a compile-time constant where it is called) of the tables at `value`.
vec4 Row(float value, int row)
{
  return textureLod(u_transfer, vec2(value * u_rowMap[row].x + u_rowMap[row].y, u_rowY[row]), 0.0);
}

float Extinction(float alpha, float unitDistance)
{
  alpha = min(alpha, 1.0 - 1e-6);
  return alpha > 0.0 ? -log(1.0 - alpha) / unitDistance : 0.0;
}

// The validity of a texel fetched at `coordinate`.
float Validity(vec4 raw, vec3 coordinate)
{
#if AVS_VALIDITY == 1
  return raw[AVS_COMPONENTS];
#elif AVS_VALIDITY == 2
  return textureLod(u_validity, coordinate, 0.0).r;
#else
  return 1.0;
#endif
}

// The data values of a volume texel (the validity's channel, with float texels, unchanged).
vec4 DataValues(vec4 raw)
{
  return raw * u_valueScale + u_valueShift;
}

// The components of a texel as data values, divided by its validity.
vec4 Components(vec4 raw, float valid)
{
#if AVS_VALIDITY > 0
  return valid > 0.0 ? DataValues(raw) / valid : vec4(0.0);
#else
  return DataValues(raw);
#endif
}

#if AVS_GRADIENT != 0
// VTK's central difference s(x + e_a) - s(x - e_a) of the components along index axis a at
// `coordinate` (one voxel on either side; the texture clamps at the faces): what gradient
// opacity is made of. (The surfaces' normal comes from the same differences, taken on the host:
// avs::SurfaceGrid.)
vec4 CentralDifference(vec3 coordinate, int a)
{
  vec3 e = vec3(0.0);
  e[a] = u_voxelStep[a];
  vec4 p = textureLod(AVS_VOLUME_TEXTURE, coordinate + e, 0.0);
  vec4 m = textureLod(AVS_VOLUME_TEXTURE, coordinate - e, 0.0);
  return Components(p, Validity(p, coordinate + e)) - Components(m, Validity(m, coordinate - e));
}

// The components' gradient magnitudes at `coordinate`.
vec4 GradientMagnitudes(vec3 coordinate)
{
  vec4 squared = vec4(0.0);
  for (int a = 0; a < 3; ++a)
  {
    vec4 g = CentralDifference(coordinate, a) * u_gradientScale[a];
    squared += g * g;
  }
  return sqrt(squared);
}
#endif

// sigma_t of component c from its opacity, with its gradient opacity.
float ComponentExtinction(int c, float alpha, vec4 gradient)
{
  float sigma = Extinction(alpha, u_unitDistance[c]);
#if AVS_GRADIENT != 0
  if (((AVS_GRADIENT >> c) & 1) != 0)
  {
    sigma *= clamp(Row(gradient[c], AVS_COMPONENTS + c).a, 0.0, 1.0);
  }
#endif
  return sigma;
}

// Whether a binary mask keeps the sample at `coordinate` (true without one, and for label maps,
// which the blend modes other than composite do not use).
bool MaskKeeps(vec3 coordinate)
{
#if AVS_MASK == 1
  return textureLod(u_mask, coordinate, 0.0).r > 0.0;
#else
  return true;
#endif
}

// (colour, sigma_t) of the value s of a single component through its own tables alone (no
// gradient opacity, validity or mask): the blend modes other than composite classify the
// extreme or crossed value this way, as vtkGPUVolumeRayCastMapper does.
vec4 ClassifyValue(float s)
{
  vec4 t = Row(s, 0);
  return vec4(t.rgb, Extinction(t.a, u_unitDistance[0]));
}

// (colour, sigma_t) of the sample whose volume texel `raw` was fetched at `coordinate`.
vec4 Classify(vec4 raw, vec3 coordinate)
{
  float valid = Validity(raw, coordinate);
  vec4 s = Components(raw, valid);
#if AVS_GRADIENT != 0
  vec4 gradient = GradientMagnitudes(coordinate);
#else
  vec4 gradient = vec4(0.0);
#endif
  vec3 color;
  float sigma;
#if AVS_MODE == 0
  vec4 t = Row(s.x, 0);
  color = t.rgb;
  sigma = ComponentExtinction(0, t.a, gradient);
#elif AVS_MODE == 1
  color = Row(s.x, 0).rgb;
  sigma = ComponentExtinction(1, Row(s.y, 1).a, gradient);
#elif AVS_MODE == 2
  color = clamp(s.rgb * vec3(u_colorMap[0].x, u_colorMap[1].x, u_colorMap[2].x) +
      vec3(u_colorMap[0].y, u_colorMap[1].y, u_colorMap[2].y),
    0.0,
    1.0);
  sigma = ComponentExtinction(3, Row(s.w, 3).a, gradient);
#else
  vec3 weighted = vec3(0.0);
  sigma = 0.0;
  for (int c = 0; c < AVS_COMPONENTS; ++c)
  {
    vec4 t = Row(s[c], c);
    float sc = u_weight[c] * ComponentExtinction(c, t.a, gradient);
    sigma += sc;
    weighted += sc * t.rgb;
  }
  color = sigma > 0.0 ? weighted / sigma : vec3(0.0);
#endif
#if AVS_MASK > 0
  float mask = textureLod(u_mask, coordinate, 0.0).r;
#if AVS_MASK == 1
  if (!(mask > 0.0))
  {
    sigma = 0.0;
  }
#else
  float label = floor(mask + 0.5);
  if (label >= 1.0 && u_maskBlend > 0.0)
  {
    float row = label <= u_labels ? 2.0 * float(AVS_COMPONENTS) + label - 1.0 : 0.0;
    vec4 l = textureLod(u_transfer, vec2(s.x * u_rowMap[0].x + u_rowMap[0].y, row), 0.0);
    float sigmaL = Extinction(l.a, u_unitDistance[0]);
    float mixed = (1.0 - u_maskBlend) * sigma + u_maskBlend * sigmaL;
    color = mixed > 0.0
      ? (color * ((1.0 - u_maskBlend) * sigma) + l.rgb * (u_maskBlend * sigmaL)) / mixed
      : vec3(0.0);
    sigma = mixed;
  }
#endif
#endif
  return vec4(color, valid > 0.0 ? sigma * valid : 0.0);
}
