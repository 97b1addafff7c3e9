#include "Grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

Vec3 GridGeometry::WorldToLocalDirection(const Vec3& d) const
{
  const auto& m = this->Direction;
  // D is orthonormal: its inverse is its transpose.
  return { m[0] * d.x + m[3] * d.y + m[6] * d.z,
    m[1] * d.x + m[4] * d.y + m[7] * d.z,
    m[2] * d.x + m[5] * d.y + m[8] * d.z };
}

Vec3 GridGeometry::LocalToWorldDirection(const Vec3& d) const
{
  const auto& m = this->Direction;
  return { m[0] * d.x + m[1] * d.y + m[2] * d.z,
    m[3] * d.x + m[4] * d.y + m[5] * d.z,
    m[6] * d.x + m[7] * d.y + m[8] * d.z };
}

Vec3 GridGeometry::WorldToIndex(const Vec3& world) const
{
  const Vec3 l = this->WorldToLocal(world);
  return { l.x / this->Spacing.x, l.y / this->Spacing.y, l.z / this->Spacing.z };
}

Vec3 GridGeometry::IndexToWorld(const Vec3& index) const
{
  return this->LocalToWorld(
    { index.x * this->Spacing.x, index.y * this->Spacing.y, index.z * this->Spacing.z });
}

GridGeometry GridGeometry::Resampled(const std::array<int, 3>& dims) const
{
  GridGeometry g = *this;
  g.Border = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    g.Dimensions[a] = std::max(1, dims[a]);
    const double length = (this->Dimensions[a] - 1) * this->Spacing[a];
    g.Spacing[a] = g.Dimensions[a] > 1 ? length / (g.Dimensions[a] - 1) : this->Spacing[a];
  }
  return g;
}

GridGeometry GridGeometry::Capped(int maximum) const
{
  const auto& n = this->Dimensions;
  const int largest = std::max({ n[0], n[1], n[2] });
  std::array<int, 3> capped = n;
  if (largest > maximum && maximum >= 2)
  {
    for (int a = 0; a < 3; ++a)
    {
      capped[a] =
        std::max(2, static_cast<int>(std::lround(static_cast<double>(n[a]) * maximum / largest)));
      capped[a] = std::min(capped[a], n[a]);
    }
  }
  return this->Resampled(capped);
}

namespace
{
// The continuous index p clamped into the lattice, or false when p lies outside the box (the
// lattice widened by `border`, with a tolerance for rounding at its faces).
inline bool ClampIntoLattice(const Vec3& p, const std::array<int, 3>& n, double border, Vec3& c)
{
  for (int a = 0; a < 3; ++a)
  {
    const double hi = n[a] - 1;
    if (!(p[a] >= -border - 1e-9 && p[a] <= hi + border + 1e-9))
    {
      return false;
    }
    c[a] = std::clamp(p[a], 0.0, hi);
  }
  return true;
}
} // namespace

double Grid::SampleIndex(const Vec3& p, double outside) const
{
  Vec3 c;
  if (!ClampIntoLattice(p, this->Geometry.Dimensions, this->Geometry.Border, c))
  {
    return outside;
  }
  return this->SampleClamped(c);
}

double Grid::NearestIndex(const Vec3& p, double outside) const
{
  Vec3 c;
  const auto& n = this->Geometry.Dimensions;
  if (!ClampIntoLattice(p, n, this->Geometry.Border, c))
  {
    return outside;
  }
  int i[3];
  for (int a = 0; a < 3; ++a)
  {
    i[a] = std::min(static_cast<int>(std::floor(c[a] + 0.5)), n[a] - 1);
  }
  return this->At(i[0], i[1], i[2]);
}

double Grid::SampleClamped(const Vec3& p) const
{
  const auto& n = this->Geometry.Dimensions;
  double f[3];
  int i0[3];
  for (int a = 0; a < 3; ++a)
  {
    const double cc = std::clamp(p[a], 0.0, static_cast<double>(n[a] - 1));
    int i = static_cast<int>(std::floor(cc));
    if (i >= n[a] - 1)
    {
      i = std::max(0, n[a] - 2);
    }
    i0[a] = i;
    f[a] = n[a] > 1 ? cc - i : 0.0;
  }
  const int i1x = std::min(i0[0] + 1, n[0] - 1);
  const int i1y = std::min(i0[1] + 1, n[1] - 1);
  const int i1z = std::min(i0[2] + 1, n[2] - 1);
  const double c000 = this->At(i0[0], i0[1], i0[2]);
  const double c100 = this->At(i1x, i0[1], i0[2]);
  const double c010 = this->At(i0[0], i1y, i0[2]);
  const double c110 = this->At(i1x, i1y, i0[2]);
  const double c001 = this->At(i0[0], i0[1], i1z);
  const double c101 = this->At(i1x, i0[1], i1z);
  const double c011 = this->At(i0[0], i1y, i1z);
  const double c111 = this->At(i1x, i1y, i1z);
  const double c00 = c000 + (c100 - c000) * f[0];
  const double c10 = c010 + (c110 - c010) * f[0];
  const double c01 = c001 + (c101 - c001) * f[0];
  const double c11 = c011 + (c111 - c011) * f[0];
  const double c0 = c00 + (c10 - c00) * f[1];
  const double c1 = c01 + (c11 - c01) * f[1];
  return c0 + (c1 - c0) * f[2];
}

bool IntersectBox(const Vec3& extent, const Vec3& o, const Vec3& d, double& t0, double& t1)
{
  t0 = -std::numeric_limits<double>::infinity();
  t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (std::abs(d[a]) < 1e-300)
    {
      if (o[a] < 0.0 || o[a] > extent[a])
      {
        return false;
      }
      continue;
    }
    double ta = (0.0 - o[a]) / d[a];
    double tb = (extent[a] - o[a]) / d[a];
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1)
    {
      return false;
    }
  }
  return true;
}

bool IntersectVolumeBox(const GridGeometry& g, const Vec3& o, const Vec3& d, double& t0, double& t1)
{
  const Vec3 lower = g.BoxLower();
  return IntersectBox(g.BoxUpper() - lower, o - lower, d, t0, t1);
}

} // namespace avs
