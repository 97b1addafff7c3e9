// The display transform (ALGORITHM.md section 1, "Display"): what turns the linear radiance a
// ray integrates into what an 8-bit framebuffer shows. Exposure first (a factor), then a tone
// curve, applied once where the ray's integral ends, before the volume is composited over what
// the renderer drew. The GLSL twin is Rendering/Shaders/avs_display.glsl; the CPU reference
// (vtkVolumeReferenceRenderer) applies this one, so the two are compared pixel by pixel.
//
// Tone curves:
//   Clamp     the radiance times the exposure, as it is (the framebuffer clamps at 1).
//   Shoulder  linear up to ShoulderStart, then a rational shoulder that approaches 1 and never
//             reaches it: s + (1 - s) u / (1 + u), u = (m - s) / (1 - s), with the same value and
//             slope as the line at s. It is applied to m = max(R, G, B), and the colour is scaled
//             by curve(m) / m: the ratios of the channels, hence hue and saturation, stay as
//             they are, and no channel ever clips (ARCHITECTURE.md says why this curve).
//
// The radiance is premultiplied (what the volume adds to the pixel, L in L + T x background),
// and the curve applies to it, not to the background behind the volume.
#ifndef avs_DisplayTransform_h
#define avs_DisplayTransform_h

#include "Grid.h"
#include "Lights.h"
#include "Vec3.h"

#include <vector>

namespace avs
{

enum class ToneMapping
{
  Clamp,   ///< none: radiance x exposure, clamped by the framebuffer
  Shoulder ///< linear to ShoulderStart, then a hue-preserving shoulder towards 1
};

struct DisplayTransform
{
  double Exposure = 1.0; ///< factor on the linear radiance (>= 0)
  ToneMapping Curve = ToneMapping::Clamp;

  /// Where the shoulder leaves the line (of max(R, G, B), after the exposure).
  static constexpr double ShoulderStart = 0.8;

  /// The shoulder on one value m >= 0 (identity below ShoulderStart, < 1 everywhere).
  static double Shoulder(double m);
  /// The premultiplied radiance `radiance` as the display receives it (before compositing).
  Vec3 Apply(const Vec3& radiance) const;
  /// Whether Apply is the identity.
  bool IsIdentity() const { return this->Exposure == 1.0 && this->Curve == ToneMapping::Clamp; }
};

/// Auto exposure: the factor that makes the light the medium receives, unshadowed, look like one
/// white light of intensity 1 in VTK's units (irradiance 4 pi): 4 pi over the mean luminance
/// (Rec. 709 weights) of the lights' summed free irradiance (Light::FreeIrradiance: falloff and
/// cone included) over the points of a 5 x 5 x 5 lattice spanning the box [low, high]. It does
/// not depend on the camera, nor on the shadows, so a directional light that turns with the
/// camera (a headlight, a light kit) meters the same in every view. 1 without light.
double AutoExposureFactor(const std::vector<Light>& lights, const Vec3& low, const Vec3& high);
/// The same over the world box of `grid`'s volume (its box, border included), placed by
/// `dataToWorld` (a 4 x 4 row-major matrix, VTK's convention; null: the identity).
double AutoExposureFactor(const std::vector<Light>& lights,
  const GridGeometry& grid,
  const double* dataToWorld = nullptr);

} // namespace avs

#endif
