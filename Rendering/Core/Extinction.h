// Opacity to extinction (ALGORITHM.md section 1): a slab of thickness u (VTK's
// ScalarOpacityUnitDistance) has opacity alpha, as in VTK's own mappers.
#ifndef avs_Extinction_h
#define avs_Extinction_h

#include <algorithm>
#include <cmath>

namespace avs
{

/// Largest opacity used before the logarithm; keeps sigma_t finite for alpha = 1.
constexpr double MaximumOpacity = 1.0 - 1e-6;

/// sigma_t = -ln(1 - min(alpha, 1 - 1e-6)) / u for a unit distance u > 0. Negative or NaN
/// opacities count as 0.
inline double OpacityToExtinction(double alpha, double unitDistance)
{
  if (!(alpha > 0.0) || !(unitDistance > 0.0))
  {
    return 0.0;
  }
  return -std::log1p(-std::min(alpha, MaximumOpacity)) / unitDistance;
}

/// The inverse: the opacity of a slab of thickness `distance` with extinction sigma_t,
/// 1 - exp(-sigma_t d). With distance = u this returns the transfer function's alpha.
inline double ExtinctionToOpacity(double sigmaT, double distance)
{
  return -std::expm1(-std::max(0.0, sigmaT) * std::max(0.0, distance));
}

} // namespace avs

#endif
