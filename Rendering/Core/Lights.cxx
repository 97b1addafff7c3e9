#include "Lights.h"

#include <algorithm>
#include <cmath>

namespace avs
{

Light Light::Directional(const Vec3& propagation, const Vec3& irradiance)
{
  Light l;
  l.Type = LightType::Directional;
  l.FocalPoint = { 0, 0, 0 };
  l.Position = -Normalize(propagation);
  l.Irradiance = irradiance;
  return l;
}

Light Light::Point(const Vec3& position, const Vec3& irradiance, const Vec3& attenuation)
{
  Light l;
  l.Type = LightType::Positional;
  l.Position = position;
  l.FocalPoint = position + Vec3{ 0, 0, -1 };
  l.Irradiance = irradiance;
  l.Attenuation = attenuation;
  return l;
}

Vec3 Light::PropagationDirection(const Vec3& x) const
{
  if (this->Type == LightType::Directional)
  {
    return Normalize(this->FocalPoint - this->Position);
  }
  const Vec3 d = Normalize(x - this->Position);
  // At the light's own position any direction will do; use the axis.
  return Length(d) > 0.0 ? d : Normalize(this->FocalPoint - this->Position);
}

Vec3 Light::FreeIrradiance(const Vec3& x) const
{
  if (this->Type == LightType::Directional)
  {
    return this->Irradiance;
  }
  const double dist = Length(x - this->Position);
  const double att =
    this->Attenuation.x + this->Attenuation.y * dist + this->Attenuation.z * dist * dist;
  double scale = att > 0.0 ? 1.0 / att : 0.0;
  if (this->IsSpot())
  {
    const Vec3 axis = Normalize(this->FocalPoint - this->Position);
    const double cosAngle = dist > 0.0 ? Dot(axis, (x - this->Position) * (1.0 / dist)) : 1.0;
    const double cosCone = std::cos(this->ConeAngle * Pi / 180.0);
    scale = cosAngle >= cosCone ? scale * std::pow(std::max(0.0, cosAngle), this->Exponent) : 0.0;
  }
  return this->Irradiance * scale;
}

bool CommonColour(const std::vector<Light>& lights, Vec3& colour)
{
  if (lights.empty())
  {
    return false;
  }
  const Vec3& first = lights.front().Irradiance;
  const double largest = std::max({ first.x, first.y, first.z });
  if (!(largest > 0.0) || std::min({ first.x, first.y, first.z }) < 0.0)
  {
    return false;
  }
  colour = first * (1.0 / largest);
  for (const Light& l : lights)
  {
    // Proportional to the first: no component negative, and parallel to a relative precision
    // that the float textures cannot tell apart.
    const Vec3& e = l.Irradiance;
    const double length = Length(e);
    if (std::min({ e.x, e.y, e.z }) < 0.0 || !(length > 0.0) ||
      Length(Cross(e, colour)) > 1e-6 * length * Length(colour))
    {
      return false;
    }
  }
  return true;
}

} // namespace avs
