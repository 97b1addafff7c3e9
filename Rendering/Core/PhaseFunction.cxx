#include "PhaseFunction.h"

#include <algorithm>
#include <cmath>

namespace avs
{

double ClampAnisotropy(double g)
{
  if (!(g == g))
  {
    return 0.0;
  }
  return std::clamp(g, -MaximumAnisotropy, MaximumAnisotropy);
}

double HenyeyGreenstein(double mu, double g)
{
  g = ClampAnisotropy(g);
  mu = std::clamp(mu, -1.0, 1.0);
  const double denom = 1.0 + g * g - 2.0 * g * mu; // >= (1 - |g|)^2 > 0
  return (1.0 - g * g) / (4.0 * Pi * denom * std::sqrt(denom));
}

double SampleHenyeyGreensteinCosine(double u, double g)
{
  g = ClampAnisotropy(g);
  u = std::clamp(u, 0.0, 1.0);
  if (std::abs(g) < 1e-3)
  {
    // Isotropic case: the inversion below divides by g.
    return 1.0 - 2.0 * u;
  }
  // Inversion of the cumulative distribution of mu. With u = 0 this gives mu = -1, with u = 1
  // it gives mu = +1 for either sign of g.
  const double sq = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
  const double mu = (1.0 + g * g - sq * sq) / (2.0 * g);
  return std::clamp(mu, -1.0, 1.0);
}

PhaseSample SampleHenyeyGreenstein(const Vec3& incoming, double g, double u1, double u2)
{
  PhaseSample s;
  s.Mu = SampleHenyeyGreensteinCosine(u1, g);
  s.Direction = SphericalDirection(incoming, s.Mu, 2.0 * Pi * u2);
  s.Pdf = HenyeyGreenstein(s.Mu, g);
  return s;
}

} // namespace avs
