#include "AmbientOcclusion.h"

#include "GridFill.h"

#include <algorithm>
#include <cmath>

namespace avs
{

std::vector<Vec3> SphereDirections(int count)
{
  std::vector<Vec3> dirs;
  count = std::max(1, count);
  const double golden = Pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k)
  {
    const double z = 1.0 - (2.0 * k + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * k;
    dirs.push_back({ r * std::cos(phi), r * std::sin(phi), z });
  }
  return dirs;
}

Grid ComputeAmbientOcclusion(const Grid& sigmaT,
  const GridGeometry& target,
  double radius,
  int directions,
  double step,
  OcclusionStatistics* statistics,
  const std::function<void(double)>& progress)
{
  const GridGeometry& source = sigmaT.Geometry;
  if (!(step > 0.0))
  {
    step = 0.5 * std::min({ source.Spacing.x, source.Spacing.y, source.Spacing.z });
  }
  const int n = std::max(1, static_cast<int>(std::ceil(radius / step)));
  const double h = radius / n;
  // Directions in the source grid's local frame; the index offsets of each sample along them.
  std::vector<Vec3> offsets;
  const auto dirs = SphereDirections(directions);
  for (const Vec3& v : dirs)
  {
    const Vec3 l = source.WorldToLocalDirection(v);
    for (int s = 0; s < n; ++s)
    {
      const double t = (s + 0.5) * h;
      offsets.push_back(
        { l.x * t / source.Spacing.x, l.y * t / source.Spacing.y, l.z * t / source.Spacing.z });
    }
  }
  std::uint64_t samples = 0;
  Grid out = FillGrid(
    target,
    [&](const Vec3& world, std::uint64_t& work)
    {
      const Vec3 base = source.WorldToIndex(world);
      double sum = 0.0;
      std::size_t o = 0;
      for (std::size_t d = 0; d < dirs.size(); ++d)
      {
        double optical = 0.0;
        for (int s = 0; s < n; ++s, ++o)
        {
          optical += sigmaT.SampleIndex(base + offsets[o], 0.0);
        }
        sum += std::exp(-optical * h);
      }
      work += offsets.size();
      return sum / dirs.size();
    },
    &samples,
    progress);
  if (statistics)
  {
    statistics->Samples = samples;
  }
  return out;
}

} // namespace avs
