#include "SurfaceShading.h"

#include "Medium.h"

#include <algorithm>
#include <cmath>

namespace avs
{

SurfaceShading SurfaceShading::Resolved() const
{
  SurfaceShading s = *this;
  auto finite = [](double v, double fallback) { return std::isfinite(v) ? v : fallback; };
  s.Blending = std::clamp(finite(s.Blending, 0.0), 0.0, 2.0);
  s.Ambient = std::max(0.0, finite(s.Ambient, 0.0));
  s.Diffuse = std::max(0.0, finite(s.Diffuse, 0.0));
  s.Specular = std::max(0.0, finite(s.Specular, 0.0));
  s.SpecularPower = std::clamp(finite(s.SpecularPower, 1.0), 0.0, 128.0);
  const double sum = s.Ambient + s.Diffuse + s.Specular;
  if (sum > 1.0)
  {
    s.Ambient /= sum;
    s.Diffuse /= sum;
    s.Specular /= sum;
  }
  return s;
}

double SurfaceEdge(double gamma)
{
  return 1.0 - std::exp(-std::max(0.0, gamma) / SurfaceGradientReference);
}

double SurfaceProbabilityOfEdge(double edge, double alpha, double blending)
{
  const double e = std::clamp(edge, 0.0, 1.0);
  const double b = std::clamp(blending, 0.0, 2.0);
  if (b == 0.0)
  {
    return e;
  }
  // gamma / gamma_0, bounded where e rounds to 1 (a quantised edge share).
  const double g = -std::log(std::max(1.0 - e, 1e-6));
  const double decay = std::exp(-b * g * std::clamp(alpha, 0.0, 1.0));
  const double volumetric = b < 1.0 ? b * decay : (2.0 - b) * decay + (b - 1.0);
  return e * (1.0 - volumetric);
}

double SurfaceProbability(double gamma, double alpha, double blending)
{
  return SurfaceProbabilityOfEdge(SurfaceEdge(gamma), alpha, blending);
}

SurfaceReflectance Reflect(const SurfaceShading& s,
  const Vec3& normal,
  const Vec3& toLight,
  const Vec3& toViewer)
{
  SurfaceReflectance out;
  Vec3 n = normal;
  double nv = Dot(n, toViewer);
  if (nv < 0.0 && s.TwoSided)
  {
    n = -n;
    nv = -nv;
  }
  const double nl = Dot(n, toLight);
  if (!(nv > 0.0) || !(nl > 0.0))
  {
    return out;
  }
  out.Diffuse = s.Diffuse / Pi * nl;
  const Vec3 mirror = n * (2.0 * nl) - toLight;
  const double rv = std::max(0.0, Dot(mirror, toViewer));
  out.Specular =
    s.Specular * (s.SpecularPower + 2.0) / (2.0 * Pi) * std::pow(rv, s.SpecularPower) * nl;
  return out;
}

bool Facing(const SurfaceShading& s, const Vec3& normal, const Vec3& toViewer, Vec3& facing)
{
  const double nv = Dot(normal, toViewer);
  facing = nv < 0.0 && s.TwoSided ? -normal : normal;
  return s.TwoSided || nv > 0.0;
}

Vec3 SampleCosine(const Vec3& n, double u1, double u2)
{
  return SphericalDirection(n, std::sqrt(std::max(0.0, u1)), 2.0 * Pi * u2);
}

Vec3 SamplePhongLobe(const Vec3& mirror, double power, double u1, double u2)
{
  return SphericalDirection(
    mirror, std::pow(std::max(0.0, u1), 1.0 / (power + 1.0)), 2.0 * Pi * u2);
}

int ShadingComponent(const MediumOptions& medium)
{
  switch (medium.Mode)
  {
    case ComponentMode::DependentColorOpacity:
      return 1;
    case ComponentMode::DependentRGBA:
      return 3;
    default:
      return 0;
  }
}

} // namespace avs
