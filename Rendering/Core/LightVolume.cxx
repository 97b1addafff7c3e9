#include "LightVolume.h"

#include "GridFill.h"

#include <algorithm>
#include <cmath>

namespace avs
{

namespace
{
inline double SampleLocal(const Grid& g, const Vec3& local)
{
  const Vec3& s = g.Geometry.Spacing;
  return g.SampleIndex({ local.x / s.x, local.y / s.y, local.z / s.z }, 0.0);
}

// Start of the light path towards local point o, in the local frame of `geometry`.
// Returns false when the light cannot reach o (no path inside the box).
bool LightPathStart(const GridGeometry& geometry, const Light& light, const Vec3& o, Vec3& x0)
{
  const Vec3 extent = geometry.LocalExtent();
  double t0, t1;
  if (light.Type == LightType::Directional)
  {
    const Vec3 d = geometry.WorldToLocalDirection(light.PropagationDirection(o));
    if (!IntersectBox(extent, o, -d, t0, t1))
    {
      x0 = o;
      return true;
    }
    x0 = o - d * std::max(0.0, t1);
    return true;
  }
  const Vec3 p = geometry.WorldToLocal(light.Position);
  const double eps = 1e-9 * (1.0 + Length(extent));
  const bool inside = p.x >= -eps && p.y >= -eps && p.z >= -eps && p.x <= extent.x + eps &&
    p.y <= extent.y + eps && p.z <= extent.z + eps;
  if (inside)
  {
    x0 = p;
    return true;
  }
  const double dist = Length(o - p);
  if (!(dist > 0.0))
  {
    x0 = o;
    return true;
  }
  const Vec3 u = (o - p) * (1.0 / dist);
  if (!IntersectBox(extent, p, u, t0, t1))
  {
    x0 = o;
    return true;
  }
  x0 = p + u * std::clamp(t0, 0.0, dist);
  return true;
}

// T at x from x0 (seed eq. 8.5), with the tube anchored at x: n = floor(D / 2r) whole balls
// centred at x - (2i + 1) r d, i < n, and the remaining length 2 r eta at the light's end,
// between x0 and x0 + 2 r eta, as one ball centred at x0 + eta r d, weighted as eq. 8.5
// weights the last ball: T = prod F_i ((1 - eta) + eta F_rest). Anchored at x0 instead (balls
// at x0 + (2i + 1) r d), the balls' phase against a dense surface would change with the
// surface's distance from x0, and T just behind it with (that distance mod 2r): bands of
// period 2r along the light (ARCHITECTURE.md, "Light volumes").
double March(const Grid& averaged,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& x0,
  const Vec3& x,
  std::uint64_t& steps,
  TubeLaw law)
{
  auto factor = [&](double tau)
  { return law == TubeLaw::DirectBeam ? std::exp(-2.0 * tau) : slice.ForwardTransport(tau); };
  const double distance = Length(x - x0);
  if (!(distance > 0.0))
  {
    return 1.0;
  }
  const Vec3 d = (x - x0) * (1.0 / distance);
  const double ratio = distance / (2.0 * radius);
  const auto n = static_cast<std::int64_t>(std::floor(ratio));
  const double eta = ratio - static_cast<double>(n);
  double t = 1.0;
  for (std::int64_t i = 0; i < n; ++i)
  {
    const Vec3 m = x - d * ((2.0 * i + 1.0) * radius);
    t *= factor(radius * SampleLocal(averaged, m));
  }
  const Vec3 rest = x0 + d * (eta * radius);
  const double f = factor(radius * SampleLocal(averaged, rest));
  steps += static_cast<std::uint64_t>(n) + 1;
  return t * ((1.0 - eta) + eta * f);
}
} // namespace

TubeLaw TubeLawFor(bool extended, LightType type)
{
  return extended && type == LightType::Positional ? TubeLaw::DirectBeam : TubeLaw::Forward;
}

std::array<int, 3> LightVolumeDimensions(const std::array<int, 3>& dims, int maximum)
{
  GridGeometry g;
  g.Dimensions = dims;
  return g.Capped(maximum).Dimensions;
}

namespace
{
// T at the point `shortenBy` before `world` on the light path towards it (x0 at the least).
double TransmittanceBefore(const Grid& averaged,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& world,
  double shortenBy,
  std::uint64_t* steps,
  TubeLaw law)
{
  const GridGeometry& geometry = averaged.Geometry;
  const Vec3 o = geometry.WorldToLocal(world);
  Vec3 x0;
  LightPathStart(geometry, light, o, x0);
  const double distance = Length(o - x0);
  const Vec3 end = distance > shortenBy ? x0 + (o - x0) * ((distance - shortenBy) / distance) : x0;
  std::uint64_t count = 0;
  const double t = March(averaged, slice, radius, x0, end, count, law);
  if (steps)
  {
    *steps += count;
  }
  return t;
}
} // namespace

double TubeTransmittance(const Grid& averaged,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& world,
  std::uint64_t* steps,
  TubeLaw law)
{
  return TransmittanceBefore(averaged, light, slice, radius, world, 0.0, steps, law);
}

double BallEntryTransmittance(const Grid& averaged,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& world,
  std::uint64_t* steps,
  TubeLaw law)
{
  return TransmittanceBefore(averaged, light, slice, radius, world, radius, steps, law);
}

Grid ComputeLightVolume(const Grid& averaged,
  const GridGeometry& target,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  LightVolumeStatistics* statistics,
  const std::function<void(double)>& progress,
  TubeLaw law)
{
  std::uint64_t steps = 0;
  Grid out = FillGrid(
    target,
    [&](const Vec3& world, std::uint64_t& work)
    { return BallEntryTransmittance(averaged, light, slice, radius, world, &work, law); },
    &steps,
    progress);
  if (statistics)
  {
    statistics->Steps = steps;
  }
  return out;
}

} // namespace avs
