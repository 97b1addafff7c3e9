#include "DiffuseFluence.h"

#include "AveragedExtinction.h"
#include "GridFill.h"
#include "Parallel.h"

#include <algorithm>
#include <cmath>

namespace avs
{

GridGeometry DiffusionGeometry(const GridGeometry& data, int maximum)
{
  return data.Capped(std::max(2, maximum));
}

double DiffusionSourceWeight(TubeLaw law, double albedo, double anisotropy)
{
  return law == TubeLaw::DirectBeam ? albedo : albedo * (1.0 - anisotropy);
}

double BeyondTheBall(double sigma, const DiffusionSettings& s)
{
  const double reduced = (1.0 - s.Albedo * s.Anisotropy) * std::max(0.0, sigma);
  const double absorbing = (1.0 - s.Albedo) * std::max(0.0, sigma);
  const double limited = std::max(reduced, 1.0 / std::max(1e-30, s.TransportLengthLimit));
  const double x = std::sqrt(3.0 * absorbing * limited) * std::max(0.0, s.AmbientRadius);
  return (1.0 + x) * std::exp(-x);
}

std::array<Grid, 3> DiffusionSource(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const GridGeometry& target,
  const DiffusionSettings& settings)
{
  std::vector<double> weights;
  for (const Light& light : lights)
  {
    const TubeLaw law = TubeLawFor(true, light.Type);
    weights.push_back(DiffusionSourceWeight(law, settings.Albedo, settings.Anisotropy));
  }
  const double r = std::max(0.0, settings.AmbientRadius);
  std::array<Grid, 3> q{ Grid(target), Grid(target), Grid(target) };
  const auto& n = target.Dimensions;
  ParallelFor(n[2],
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t k = b; k < e; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
          {
            const Vec3 world = target.IndexToWorld(
              { static_cast<double>(i), static_cast<double>(j), static_cast<double>(k) });
            const double sigma = averaged.SampleWorld(world);
            Vec3 e{ 0, 0, 0 };
            if (sigma > 0.0)
            {
              const double beyond = BeyondTheBall(sigma, settings);
              for (std::size_t l = 0; l < lights.size() && l < lightVolumes.size(); ++l)
              {
                // T at x: the light volume holds T where the light enters the ball around a
                // point, r before it, so T at x is its value r downstream (clamped into the
                // box, beyond which nothing attenuates).
                const Grid& tube = lightVolumes[l];
                const Vec3 downstream = world + lights[l].PropagationDirection(world) * r;
                e = e +
                  lights[l].FreeIrradiance(world) *
                    (beyond * weights[l] *
                      tube.SampleClamped(tube.Geometry.WorldToIndex(downstream)));
              }
            }
            const std::size_t index = target.Index(i, j, static_cast<int>(k));
            for (int c = 0; c < 3; ++c)
            {
              q[c].Values[index] = static_cast<float>(sigma * e[c]);
            }
          }
    });
  return q;
}

namespace
{
// The discrete operator of one cell: the diagonal and the couplings to its six neighbours
// (0 where the neighbour is vacuum or outside the grid; their Marshak leak is in the diagonal).
struct Cell
{
  double Diagonal = 0.0;              ///< 0: a vacuum cell (phi = 0)
  double K[6] = { 0, 0, 0, 0, 0, 0 }; ///< -x, +x, -y, +y, -z, +z
};

std::vector<Cell> Operator(const Grid& averaged, const DiffusionSettings& s)
{
  const GridGeometry& g = averaged.Geometry;
  const auto& n = g.Dimensions;
  const double reduced = 1.0 - s.Albedo * s.Anisotropy; // sigma' / sigma~t
  const double absorbing = 1.0 - s.Albedo;              // sigma_a / sigma~t
  // D per cell, 0 for vacuum; the transport mean free path 1 / sigma' at most
  // TransportLengthLimit (a flux limiter: diffusion has no meaning beyond it).
  const double floor = 1.0 / std::max(1e-30, s.TransportLengthLimit);
  const double meanSpacing = (g.Spacing.x + g.Spacing.y + g.Spacing.z) / 3.0;
  std::vector<double> d(g.NumberOfPoints(), 0.0);
  for (std::size_t c = 0; c < d.size(); ++c)
  {
    const double sigma = reduced * std::max(0.0, static_cast<double>(averaged.Values[c]));
    d[c] = sigma * meanSpacing >= VacuumOpticalDepth ? 1.0 / (3.0 * std::max(sigma, floor)) : 0.0;
  }
  std::vector<Cell> cells(d.size());
  ParallelFor(n[2],
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t kk = b; kk < e; ++kk)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
          {
            const int k = static_cast<int>(kk);
            const std::size_t c = g.Index(i, j, k);
            if (!(d[c] > 0.0))
            {
              continue;
            }
            Cell& cell = cells[c];
            cell.Diagonal = absorbing * std::max(0.0, static_cast<double>(averaged.Values[c]));
            const int idx[3] = { i, j, k };
            for (int f = 0; f < 6; ++f)
            {
              const int axis = f / 2;
              const int step = (f % 2) ? 1 : -1;
              int m[3] = { idx[0], idx[1], idx[2] };
              m[axis] += step;
              const double h = g.Spacing[axis];
              const bool inside = m[axis] >= 0 && m[axis] < n[axis];
              const double dn = inside ? d[g.Index(m[0], m[1], m[2])] : 0.0;
              if (dn > 0.0)
              {
                cell.K[f] = 2.0 * d[c] * dn / (d[c] + dn) / (h * h);
                cell.Diagonal += cell.K[f];
              }
              else
              {
                // Marshak: phi = 2 D dphi/dn at the face, phi = 0 beyond it.
                cell.Diagonal += d[c] / (2.0 * d[c] + 0.5 * h) / h;
              }
            }
          }
    });
  return cells;
}
} // namespace

std::array<Grid, 3> SolveDiffusion(const Grid& averaged,
  const std::array<Grid, 3>& source,
  const DiffusionSettings& s,
  double* residual,
  const std::array<Grid, 3>* initial)
{
  const GridGeometry& g = averaged.Geometry;
  const auto& n = g.Dimensions;
  const std::vector<Cell> cells = Operator(averaged, s);
  const std::ptrdiff_t stride[6] = { -1,
    1,
    -static_cast<std::ptrdiff_t>(n[0]),
    n[0],
    -static_cast<std::ptrdiff_t>(n[0]) * n[1],
    static_cast<std::ptrdiff_t>(n[0]) * n[1] };
  const double omega = std::clamp(s.Relaxation, 0.05, 1.95);
  std::array<Grid, 3> phi{ Grid(g), Grid(g), Grid(g) };
  if (initial)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::vector<float>& from = (*initial)[c].Values;
      for (std::size_t index = 0; index < cells.size() && index < from.size(); ++index)
      {
        phi[c].Values[index] = cells[index].Diagonal > 0.0 ? from[index] : 0.0f;
      }
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    const std::vector<float>& q = source[c].Values;
    std::vector<float>& p = phi[c].Values;
    for (int it = 0; it < s.Iterations; ++it)
    {
      for (int colour = 0; colour < 2; ++colour)
      {
        ParallelFor(n[2],
          [&](std::int64_t b, std::int64_t e)
          {
            for (std::int64_t k = b; k < e; ++k)
              for (int j = 0; j < n[1]; ++j)
                for (int i = (static_cast<int>(k) + j + colour) % 2; i < n[0]; i += 2)
                {
                  const std::size_t index = g.Index(i, j, static_cast<int>(k));
                  const Cell& cell = cells[index];
                  if (!(cell.Diagonal > 0.0))
                  {
                    continue;
                  }
                  double sum = q[index];
                  for (int f = 0; f < 6; ++f)
                  {
                    if (cell.K[f] > 0.0)
                    {
                      sum += cell.K[f] * p[static_cast<std::ptrdiff_t>(index) + stride[f]];
                    }
                  }
                  p[index] =
                    static_cast<float>((1.0 - omega) * p[index] + omega * sum / cell.Diagonal);
                }
          });
      }
    }
  }
  if (residual)
  {
    double r = 0.0, norm = 0.0;
    const std::vector<float>& q = source[0].Values;
    const std::vector<float>& p = phi[0].Values;
    for (std::size_t index = 0; index < cells.size(); ++index)
    {
      const Cell& cell = cells[index];
      if (!(cell.Diagonal > 0.0))
      {
        continue;
      }
      double a = cell.Diagonal * p[index];
      for (int f = 0; f < 6; ++f)
      {
        if (cell.K[f] > 0.0)
        {
          a -= cell.K[f] * p[static_cast<std::ptrdiff_t>(index) + stride[f]];
        }
      }
      r += std::abs(q[index] - a);
      norm += std::abs(q[index]);
    }
    *residual = norm > 0.0 ? r / norm : 0.0;
  }
  return phi;
}

std::vector<GridGeometry> DiffusionLevels(const GridGeometry& finest)
{
  std::vector<GridGeometry> levels{ finest };
  for (;;)
  {
    const auto& n = levels.back().Dimensions;
    if (std::max({ n[0], n[1], n[2] }) <= NestedCoarsestDimension)
    {
      return levels;
    }
    std::array<int, 3> coarser = n;
    for (int a = 0; a < 3; ++a)
    {
      coarser[a] = n[a] > 2 ? (n[a] + 1) / 2 : n[a];
    }
    levels.push_back(levels.back().Resampled(coarser));
  }
}

std::array<Grid, 3> ComputeDiffusion(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const GridGeometry& target,
  const DiffusionSettings& settings,
  double* residual)
{
  const std::vector<GridGeometry> levels = DiffusionLevels(target);
  std::array<Grid, 3> phi;
  for (std::size_t l = levels.size(); l-- > 0;)
  {
    const GridGeometry& g = levels[l];
    DiffusionSettings level = settings;
    level.Iterations = l == 0 ? settings.Iterations : settings.CoarseIterations;
    const Grid sigma = ResampleTrilinear(averaged, g);
    const std::array<Grid, 3> q = DiffusionSource(averaged, lights, lightVolumes, g, settings);
    if (l + 1 == levels.size())
    {
      phi = SolveDiffusion(sigma, q, level, l == 0 ? residual : nullptr);
      continue;
    }
    // The coarser level's phi, trilinear at this level's points (its box is the same).
    std::array<Grid, 3> start;
    for (int c = 0; c < 3; ++c)
    {
      start[c] = ResampleTrilinear(phi[c], g);
    }
    phi = SolveDiffusion(sigma, q, level, l == 0 ? residual : nullptr, &start);
  }
  return phi;
}

} // namespace avs
