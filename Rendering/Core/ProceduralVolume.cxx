#include "ProceduralVolume.h"

#include "GridFill.h"
#include "Random.h"

#include <algorithm>
#include <cmath>

namespace avs
{

namespace
{
inline double LatticeValue(std::int64_t i, std::int64_t j, std::int64_t k, std::uint64_t seed)
{
  const std::uint64_t h = HashSeed(static_cast<std::uint64_t>(i) * 73856093ULL,
    static_cast<std::uint64_t>(j) * 19349663ULL,
    static_cast<std::uint64_t>(k) * 83492791ULL ^ seed);
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}
inline double Smooth(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
inline double SmoothStep(double a, double b, double x)
{
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

Grid MakeGrid(int n)
{
  GridGeometry g;
  n = std::max(2, n);
  g.Dimensions = { n, n, n };
  const double h = 2.0 / (n - 1);
  g.Spacing = { h, h, h };
  g.Origin = { -1, -1, -1 };
  return Grid(g);
}

template<typename Density>
Grid Fill(int n, Density density)
{
  return FillGrid(MakeGrid(n).Geometry,
    [&](const Vec3& p, std::uint64_t&) { return std::clamp(density(p), 0.0, 1.0); });
}
} // namespace

double ValueNoise(const Vec3& p, std::uint64_t seed)
{
  const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  const auto i = static_cast<std::int64_t>(fx);
  const auto j = static_cast<std::int64_t>(fy);
  const auto k = static_cast<std::int64_t>(fz);
  const double u = Smooth(p.x - fx), v = Smooth(p.y - fy), w = Smooth(p.z - fz);
  double c[2][2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int d = 0; d < 2; ++d)
        c[a][b][d] = LatticeValue(i + a, j + b, k + d, seed);
  const double x00 = c[0][0][0] + (c[1][0][0] - c[0][0][0]) * u;
  const double x10 = c[0][1][0] + (c[1][1][0] - c[0][1][0]) * u;
  const double x01 = c[0][0][1] + (c[1][0][1] - c[0][0][1]) * u;
  const double x11 = c[0][1][1] + (c[1][1][1] - c[0][1][1]) * u;
  const double y0 = x00 + (x10 - x00) * v;
  const double y1 = x01 + (x11 - x01) * v;
  return y0 + (y1 - y0) * w;
}

double FractalNoise(const Vec3& p, int octaves, std::uint64_t seed)
{
  double sum = 0.0, amplitude = 1.0, norm = 0.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o)
  {
    sum += amplitude * ValueNoise(p * frequency, seed + 1000003ULL * o);
    norm += amplitude;
    amplitude *= 0.5;
    frequency *= 2.03;
  }
  return sum / norm;
}

Grid MakeNebula(int n, std::uint64_t seed)
{
  return Fill(n,
    [seed](const Vec3& p)
    {
      // Domain warp for filaments.
      const Vec3 q = p * 2.5;
      const Vec3 warp{ FractalNoise(q + Vec3{ 3.1, 0, 0 }, 3, seed + 1),
        FractalNoise(q + Vec3{ 0, 5.7, 0 }, 3, seed + 2),
        FractalNoise(q + Vec3{ 0, 0, 9.3 }, 3, seed + 3) };
      const Vec3 pw = p + (warp - Vec3{ 0.5, 0.5, 0.5 }) * 0.35;
      const double r = Length(pw);
      const double shell = SmoothStep(0.22, 0.42, r) * (1.0 - SmoothStep(0.62, 0.92, r));
      const double turbulence = FractalNoise(pw * 4.0, 5, seed);
      const double detail = SmoothStep(0.35, 0.75, turbulence);
      return shell * detail * 1.4;
    });
}

Grid MakeCloud(int n, std::uint64_t seed)
{
  return Fill(n,
    [seed](const Vec3& p)
    {
      const Vec3 q{ p.x * 0.9, (p.y + 0.15) * 1.4, p.z * 0.9 };
      const double billows = FractalNoise(p * 3.0, 5, seed);
      const double r = Length(q) + 0.45 * (billows - 0.5);
      const double body = 1.0 - SmoothStep(0.55, 0.8, r);
      const double bottom = SmoothStep(-0.55, -0.35, p.y);
      return body * bottom * (0.6 + 0.8 * FractalNoise(p * 7.0, 3, seed + 5));
    });
}

} // namespace avs
