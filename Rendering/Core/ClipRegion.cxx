#include "ClipRegion.h"

#include "Parallel.h"

#include <algorithm>
#include <cmath>

namespace avs
{

namespace
{
constexpr double Unbounded = 1e30;

// The cropping interval (0, 1, 2) of coordinate p between the planes lo and hi, as VTK's
// shader computes it: below lo, in [lo, hi), from hi on.
inline int Interval(double p, double lo, double hi)
{
  return p < lo ? 0 : (p < hi ? 1 : 2);
}
} // namespace

int ClipRegion::Region(const Vec3& index) const
{
  const auto& c = this->CroppingPlanes;
  return Interval(index.x, c[0], c[1]) + 3 * Interval(index.y, c[2], c[3]) +
    9 * Interval(index.z, c[4], c[5]);
}

bool ClipRegion::IsInside(const Vec3& index) const
{
  for (const IndexPlane& p : this->Planes)
  {
    if (p.Evaluate(index) < 0.0)
    {
      return false;
    }
  }
  return !this->Cropping || ((this->CroppingRegionFlags >> this->Region(index)) & 1) != 0;
}

bool ClipRegion::KeptBox(Vec3& low, Vec3& high) const
{
  low = { -Unbounded, -Unbounded, -Unbounded };
  high = { Unbounded, Unbounded, Unbounded };
  if (!this->Cropping)
  {
    return true;
  }
  const auto& c = this->CroppingPlanes;
  low = { Unbounded, Unbounded, Unbounded };
  high = { -Unbounded, -Unbounded, -Unbounded };
  bool any = false;
  for (int r = 0; r < 27; ++r)
  {
    if (!((this->CroppingRegionFlags >> r) & 1))
    {
      continue;
    }
    any = true;
    const int cell[3] = { r % 3, (r / 3) % 3, r / 9 };
    for (int a = 0; a < 3; ++a)
    {
      const double lo = cell[a] == 0 ? -Unbounded : c[2 * a + cell[a] - 1];
      const double hi = cell[a] == 2 ? Unbounded : c[2 * a + cell[a]];
      low[a] = std::min(low[a], lo);
      high[a] = std::max(high[a], hi);
    }
  }
  return any;
}

bool ClipRegion::ClipRay(const Vec3& o, const Vec3& d, double& t0, double& t1) const
{
  for (const IndexPlane& p : this->Planes)
  {
    // f(t) = a + b t >= 0.
    const double a = p.Evaluate(o);
    const double b = Dot(p.Normal, d);
    if (b > 0.0)
    {
      t0 = std::max(t0, -a / b);
    }
    else if (b < 0.0)
    {
      t1 = std::min(t1, -a / b);
    }
    else if (a < 0.0)
    {
      return false;
    }
  }
  if (this->Cropping)
  {
    Vec3 low, high;
    if (!this->KeptBox(low, high))
    {
      return false;
    }
    for (int a = 0; a < 3; ++a)
    {
      if (d[a] != 0.0)
      {
        const double u = (low[a] - o[a]) / d[a], v = (high[a] - o[a]) / d[a];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
      }
      else if (o[a] < low[a] || o[a] > high[a])
      {
        return false;
      }
    }
  }
  return t1 > t0;
}

bool ClipRegion::BoxOutside(const Vec3& low, const Vec3& high) const
{
  for (const IndexPlane& p : this->Planes)
  {
    // The corner of the box farthest along the normal.
    const Vec3 best{ p.Normal.x > 0 ? high.x : low.x,
      p.Normal.y > 0 ? high.y : low.y,
      p.Normal.z > 0 ? high.z : low.z };
    if (p.Evaluate(best) < 0.0)
    {
      return true;
    }
  }
  if (!this->Cropping)
  {
    return false;
  }
  Vec3 keptLow, keptHigh;
  if (!this->KeptBox(keptLow, keptHigh))
  {
    return true;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (high[a] < keptLow[a] || low[a] > keptHigh[a])
    {
      return true;
    }
  }
  // Inside one region: that region decides.
  const int r0 = this->Region(low), r1 = this->Region(high);
  return r0 == r1 && !((this->CroppingRegionFlags >> r0) & 1);
}

IndexPlane PlaneToIndex(const Vec3& origin, const Vec3& normal, const std::array<double, 12>& m)
{
  // dot(n, A i + b - o) = dot(A^T n, i) + dot(n, b - o).
  const Vec3 n = Normalize(normal);
  IndexPlane p;
  p.Normal = { m[0] * n.x + m[4] * n.y + m[8] * n.z,
    m[1] * n.x + m[5] * n.y + m[9] * n.z,
    m[2] * n.x + m[6] * n.y + m[10] * n.z };
  p.Offset = Dot(n, Vec3{ m[3], m[7], m[11] } - origin);
  return p;
}

std::array<double, 12> IndexToWorldMap(const GridGeometry& g)
{
  std::array<double, 12> m{};
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[4 * r + c] = g.Direction[3 * r + c] * g.Spacing[c];
    }
    m[4 * r + 3] = g.Origin[r];
  }
  return m;
}

void ClearOutside(const ClipRegion& region, Grid& values)
{
  if (!region.Clips())
  {
    return;
  }
  const auto& d = values.Geometry.Dimensions;
  ParallelFor(d[2],
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t k = b; k < e; ++k)
        for (int j = 0; j < d[1]; ++j)
          for (int i = 0; i < d[0]; ++i)
          {
            if (!region.IsInside(
                  { static_cast<double>(i), static_cast<double>(j), static_cast<double>(k) }))
            {
              values.At(i, j, static_cast<int>(k)) = 0.0f;
            }
          }
    });
}

} // namespace avs
