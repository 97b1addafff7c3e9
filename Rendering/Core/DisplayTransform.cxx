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
  return s + (1.0 - s) * (1.0 - 1.0 / (1.0 + u)); // u / (1 + u), finite for an infinite u
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

double AutoExposureFactor(const std::vector<Light>& lights,
  const GridGeometry& grid,
  const double* dataToWorld)
{
  const Vec3 lo = grid.BoxLower(), hi = grid.BoxUpper();
  Vec3 low{ 1e300, 1e300, 1e300 }, high{ -1e300, -1e300, -1e300 };
  for (int c = 0; c < 8; ++c)
  {
    Vec3 p = grid.LocalToWorld({ c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z });
    if (dataToWorld)
    {
      const double* m = dataToWorld;
      const double w = m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15];
      p = { (m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3]) / w,
        (m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7]) / w,
        (m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]) / w };
    }
    low = { std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z) };
    high = { std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z) };
  }
  return AutoExposureFactor(lights, low, high);
}

} // namespace avs
