#include "ImageSampleDistance.h"

#include <algorithm>
#include <cmath>

namespace avs
{

double ChooseImageSampleDistance(const FrameBudget& b)
{
  const double lo = b.Minimum;
  const double hi = std::max(b.Minimum, b.Maximum);
  const double previous = std::clamp(b.Previous > 0.0 ? b.Previous : 1.0, lo, hi);
  if (!(b.SecondsPerRay > 0.0) || !(b.AllocatedSeconds > 0.0) || !(b.Pixels > 0.0) ||
    !std::isfinite(b.SecondsPerRay) || !std::isfinite(b.AllocatedSeconds))
  {
    return previous;
  }
  // The distance whose frame takes the allotted time: P s / d^2 = t.
  const double fit = std::sqrt(b.Pixels * b.SecondsPerRay / b.AllocatedSeconds);
  // Over budget: coarser at once. Under: refine halfway, in the resolution factor 1 / d.
  const double d = fit >= previous ? fit : 2.0 / (1.0 / std::max(fit, 1e-12) + 1.0 / previous);
  const double stepped = ImageSampleDistanceStep * std::ceil(d / ImageSampleDistanceStep - 1e-9);
  return std::clamp(stepped, lo, hi);
}

int SampledSize(int pixels, double distance)
{
  if (!(distance > 0.0) || !std::isfinite(distance))
  {
    return std::max(1, pixels);
  }
  return std::max(1, static_cast<int>(std::ceil(pixels / distance - 1e-9)));
}

} // namespace avs
