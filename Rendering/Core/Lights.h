// Lights as VTK defines them (ALGORITHM.md section 1), in world space.
//
//   directional: propagation d = normalize(focal point - position), irradiance E
//   positional:  E / (a0 + a1 dist + a2 dist^2)   (VTK's attenuation values)
//   spot:        a positional light with cone half-angle < 90 degrees: zero outside the cone,
//                times cos(angle to the axis)^exponent inside, as VTK's OpenGL shaders do
//
// E is in VTK light units when the light comes from a vtkLight (vtkAVSSceneTranslator::ToLights):
// E = 4 pi x intensity x colour x LightScale.
#ifndef avs_Lights_h
#define avs_Lights_h

#include "Vec3.h"

#include <vector>

namespace avs
{

enum class LightType
{
  Directional,
  Positional
};

struct Light
{
  LightType Type = LightType::Directional;
  Vec3 Position{ 0, 0, 1 };
  Vec3 FocalPoint{ 0, 0, 0 };
  Vec3 Irradiance{ 1, 1, 1 };  ///< E: 4 pi x intensity x colour x LightScale for a vtkLight
  Vec3 Attenuation{ 1, 0, 0 }; ///< a0, a1, a2 (positional lights)
  double ConeAngle = 180.0;    ///< half-angle in degrees; >= 90 means no cone (point light)
  double Exponent = 1.0;       ///< spot exponent

  static Light Directional(const Vec3& propagation, const Vec3& irradiance);
  static Light Point(const Vec3& position,
    const Vec3& irradiance,
    const Vec3& attenuation = { 1, 0, 0 });

  bool IsSpot() const { return this->Type == LightType::Positional && this->ConeAngle < 90.0; }

  /// Propagation direction of this light's light at x (unit).
  Vec3 PropagationDirection(const Vec3& x) const;
  /// Unoccluded irradiance at x: falloff and cone included, no volume attenuation.
  Vec3 FreeIrradiance(const Vec3& x) const;
};

/// Whether the lights' irradiances share one colour: each a positive multiple of one RGB
/// vector (none black, no component negative). Then what is linear in the lights' light, as
/// the extended model's diffuse fluence, is that colour times one number per point; `colour`
/// gets the first light's irradiance over its largest component.
bool CommonColour(const std::vector<Light>& lights, Vec3& colour);

} // namespace avs

#endif
