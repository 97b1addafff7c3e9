#include "AmbientOcclusion.h"

#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

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
  Grid out(target, 1.0f);
  const auto& dims = target.Dimensions;
  std::atomic<std::uint64_t> samples{ 0 };
  std::atomic<int> slicesDone{ 0 };
  const std::thread::id caller = std::this_thread::get_id();
  ParallelFor(dims[2],
    [&](std::int64_t b, std::int64_t e)
    {
      std::uint64_t local = 0;
      for (std::int64_t k = b; k < e; ++k)
      {
        for (int j = 0; j < dims[1]; ++j)
        {
          for (int i = 0; i < dims[0]; ++i)
          {
            const Vec3 world = target.IndexToWorld(
              { static_cast<double>(i), static_cast<double>(j), static_cast<double>(k) });
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
            local += offsets.size();
            out.At(i, j, static_cast<int>(k)) = static_cast<float>(sum / dirs.size());
          }
        }
        const int done = ++slicesDone;
        if (progress && std::this_thread::get_id() == caller)
        {
          progress(static_cast<double>(done) / dims[2]);
        }
      }
      samples += local;
    });
  if (statistics)
  {
    statistics->Samples = samples.load();
  }
  return out;
}

} // namespace avs
