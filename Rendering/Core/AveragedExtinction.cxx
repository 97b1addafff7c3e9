#include "AveragedExtinction.h"

#include "GridFill.h"
#include "Parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

namespace avs
{

std::array<int, 3> AveragingHalfWidths(double radius, const Vec3& spacing)
{
  std::array<int, 3> k{ 0, 0, 0 };
  const double h = std::max(0.0, radius) * CubeHalfSidePerRadius;
  for (int a = 0; a < 3; ++a)
  {
    const double s = std::abs(spacing[a]);
    const double w = s > 0.0 ? std::round(h / s) : 0.0;
    k[a] = static_cast<int>(std::min(w, 1e6));
  }
  return k;
}

namespace
{
// Box sum of half width k along one axis of `data`, written into `out` (may not alias).
void BoxPass(const std::vector<float>& data,
  std::vector<float>& out,
  const std::array<int, 3>& dims,
  int axis,
  int k,
  std::atomic<std::uint64_t>& operations)
{
  const std::size_t stride = axis == 0
    ? 1
    : (axis == 1 ? static_cast<std::size_t>(dims[0]) : static_cast<std::size_t>(dims[0]) * dims[1]);
  const int n = dims[axis];
  // The lines of this axis: indexed by the other two coordinates.
  const int o1 = axis == 0 ? dims[1] : dims[0];
  const int o2 = axis == 2 ? dims[1] : dims[2];
  ParallelFor(
    static_cast<std::int64_t>(o1) * o2,
    [&](std::int64_t b, std::int64_t e)
    {
      std::vector<double> prefix(n + 1);
      std::uint64_t ops = 0;
      for (std::int64_t line = b; line < e; ++line)
      {
        const int a = static_cast<int>(line % o1);
        const int c = static_cast<int>(line / o1);
        std::size_t base;
        if (axis == 0)
          base = (static_cast<std::size_t>(c) * dims[1] + a) * dims[0];
        else if (axis == 1)
          base = static_cast<std::size_t>(c) * dims[0] * dims[1] + a;
        else
          base = static_cast<std::size_t>(c) * dims[0] + a;
        prefix[0] = 0.0;
        for (int i = 0; i < n; ++i)
        {
          prefix[i + 1] = prefix[i] + data[base + i * stride];
        }
        for (int i = 0; i < n; ++i)
        {
          const int lo = std::max(0, i - k);
          const int hi = std::min(n, i + k + 1);
          out[base + i * stride] = static_cast<float>(prefix[hi] - prefix[lo]);
        }
        ops += 2ull * n;
      }
      operations += ops;
    },
    0,
    64);
}
} // namespace

Grid BoxMean(const Grid& values,
  const std::array<int, 3>& halfWidths,
  AveragingStatistics* statistics,
  const std::function<void(double)>& progress)
{
  const auto& dims = values.Geometry.Dimensions;
  std::atomic<std::uint64_t> operations{ 0 };
  std::vector<float> a = values.Values;
  std::vector<float> b(a.size());
  for (int axis = 0; axis < 3; ++axis)
  {
    BoxPass(a, b, dims, axis, halfWidths[axis], operations);
    std::swap(a, b);
    if (progress)
    {
      progress((axis + 1) / 3.0);
    }
  }
  const double count =
    (2.0 * halfWidths[0] + 1.0) * (2.0 * halfWidths[1] + 1.0) * (2.0 * halfWidths[2] + 1.0);
  const float inv = static_cast<float>(1.0 / count);
  Grid out(values.Geometry);
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    out.Values[i] = a[i] * inv;
  }
  operations += a.size();
  if (statistics)
  {
    statistics->Operations = operations.load();
  }
  return out;
}

Grid AverageExtinction(const Grid& sigmaT,
  double radius,
  AveragingStatistics* statistics,
  const std::function<void(double)>& progress)
{
  return BoxMean(
    sigmaT, AveragingHalfWidths(radius, sigmaT.Geometry.Spacing), statistics, progress);
}

Grid ResampleTrilinear(const Grid& values, const GridGeometry& target)
{
  if (target.Dimensions == values.Geometry.Dimensions)
  {
    return values;
  }
  const GridGeometry& source = values.Geometry;
  return FillGrid(target,
    [&](const Vec3& world, std::uint64_t&)
    { return values.SampleIndex(source.WorldToIndex(world), 0.0); });
}

Grid AverageExtinctionOn(const Grid& sigmaT,
  double radius,
  const GridGeometry& target,
  AveragingStatistics* statistics,
  const std::function<void(double)>& progress)
{
  return ResampleTrilinear(AverageExtinction(sigmaT, radius, statistics, progress), target);
}

} // namespace avs
