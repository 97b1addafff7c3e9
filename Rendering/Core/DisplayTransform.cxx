#include "DisplayTransform.h"

#include <algorithm>
#include <cmath>

namespace avs
{

double DisplayTransform::Shoulder(double m)
{
  constexpr double s = ShoulderStart;
  if (!(m > s))
  {
    return std::max(m, 0.0);
  }
  const double u = (m - s) / (1.0 - s);
  return s + (1.0 - s) * u / (1.0 + u);
}

Vec3 DisplayTransform::Apply(const Vec3& radiance) const
{
  const Vec3 x = radiance * std::max(this->Exposure, 0.0);
  if (this->Curve == ToneMapping::Clamp)
  {
    return x;
  }
  const double m = std::max({ x.x, x.y, x.z });
  return m > ShoulderStart ? x * (Shoulder(m) / m) : x;
}

double AutoExposureFactor(const std::vector<Light>& lights, const Vec3& low, const Vec3& high)
{
  constexpr int n = 5;
  double sum = 0.0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const Vec3 f{ i / (n - 1.0), j / (n - 1.0), k / (n - 1.0) };
        const Vec3 x{ low.x + f.x * (high.x - low.x),
          low.y + f.y * (high.y - low.y),
          low.z + f.z * (high.z - low.z) };
        for (const Light& light : lights)
        {
          const Vec3 e = light.FreeIrradiance(x);
          const double y = 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
          sum += std::isfinite(y) ? std::max(y, 0.0) : 0.0;
        }
      }
    }
  }
  const double mean = sum / (n * n * n);
  constexpr double unit = 4.0 * Pi; // one white light of intensity 1
  return mean > 0.0 && std::isfinite(mean) ? unit / mean : 1.0;
}

} // namespace avs
