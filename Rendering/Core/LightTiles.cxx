#include "LightTiles.h"

#include "AveragedExtinction.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace avs
{

namespace
{
std::uint32_t Pack(int tx, int ty, int z)
{
  return static_cast<std::uint32_t>(tx) | (static_cast<std::uint32_t>(ty) << 10) |
    (static_cast<std::uint32_t>(z) << 20);
}

int TilesAlong(int nodes)
{
  return (nodes + LightTileSize - 1) / LightTileSize;
}

// The data index of light node i on an axis of n data points and l light nodes.
double NodeIndex(int i, int n, int l)
{
  return l > 1 ? static_cast<double>(i) * (n - 1) / (l - 1) : 0.0;
}
} // namespace

std::vector<LightReachBox> LightReach(const std::array<int, 3>& dataDimensions,
  const Vec3& dataSpacing,
  const std::array<int, 3>& lightDimensions,
  double radius,
  bool diffusion,
  const Vec3& direction)
{
  const std::array<int, 3> half = AveragingHalfWidths(radius, dataSpacing);
  const double spacing[3] = { dataSpacing.x, dataSpacing.y, dataSpacing.z };
  const double norm = Length(direction);
  const double along[3] = { norm > 0.0 ? direction.x / norm : 0.0,
    norm > 0.0 ? direction.y / norm : 0.0,
    norm > 0.0 ? direction.z / norm : 0.0 };
  LightReachBox rays, source;
  for (int a = 0; a < 3; ++a)
  {
    const double cell = lightDimensions[a] > 1
      ? static_cast<double>(dataDimensions[a] - 1) / (lightDimensions[a] - 1)
      : static_cast<double>(dataDimensions[a]);
    rays.Low[a] = rays.High[a] = 2.0 * cell + 1.0;
    // Material within `around` of a point the diffusion's source reads r downstream of.
    const double around = half[a] + 1.0 + cell + cell + 1.0;
    const double r = radius / spacing[a];
    if (norm > 0.0)
    {
      // The node is r along the direction from such a point: the material r upstream of it.
      source.Low[a] = around + r * along[a];
      source.High[a] = around - r * along[a];
    }
    else
    {
      source.Low[a] = source.High[a] = around + r;
    }
  }
  std::vector<LightReachBox> boxes{ rays };
  if (diffusion)
  {
    boxes.push_back(source);
  }
  return boxes;
}

std::vector<std::uint32_t> AllLightTiles(const std::array<int, 3>& l)
{
  std::vector<std::uint32_t> tiles;
  tiles.reserve(static_cast<std::size_t>(TilesAlong(l[0])) * TilesAlong(l[1]) * l[2]);
  for (int z = 0; z < l[2]; ++z)
    for (int ty = 0; ty < TilesAlong(l[1]); ++ty)
      for (int tx = 0; tx < TilesAlong(l[0]); ++tx)
        tiles.push_back(Pack(tx, ty, z));
  return tiles;
}

std::vector<std::uint32_t> LightGridTiles(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  int cellSize,
  const std::array<int, 3>& d,
  const std::array<int, 3>& l,
  const std::vector<LightReachBox>& reach)
{
  const std::size_t count = static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
  if (occupied.size() != count || count == 0 || cellSize < 1)
  {
    return AllLightTiles(l);
  }
  // Occupied cells counted over boxes: a prefix sum of (cells + 1)^3 entries.
  const std::size_t sx = cells[0] + 1, sy = cells[1] + 1;
  std::vector<std::uint32_t> sum(sx * sy * (cells[2] + 1), 0);
  auto at = [&](int i, int j, int k) -> std::uint32_t&
  { return sum[(static_cast<std::size_t>(k) * sy + j) * sx + i]; };
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
      {
        const std::size_t c = (static_cast<std::size_t>(k) * cells[1] + j) * cells[0] + i;
        at(i + 1, j + 1, k + 1) = (occupied[c] > 0.0f ? 1u : 0u) + at(i, j + 1, k + 1) +
          at(i + 1, j, k + 1) + at(i + 1, j + 1, k) - at(i, j, k + 1) - at(i, j + 1, k) -
          at(i + 1, j, k) + at(i, j, k);
      }
  // The cells [lo, hi] along axis a whose owned indices meet [p0 - low, p1 + high].
  auto range = [&](int a, double p0, double p1, const LightReachBox& box, int& lo, int& hi)
  {
    lo = std::clamp(static_cast<int>(std::floor((p0 - box.Low[a]) / cellSize)), 0, cells[a] - 1);
    hi = std::clamp(static_cast<int>(std::floor((p1 + box.High[a]) / cellSize)), 0, cells[a] - 1);
  };
  auto occupiedIn = [&](const std::array<int, 3>& lo, const std::array<int, 3>& hi)
  {
    return at(hi[0] + 1, hi[1] + 1, hi[2] + 1) - at(lo[0], hi[1] + 1, hi[2] + 1) -
      at(hi[0] + 1, lo[1], hi[2] + 1) - at(hi[0] + 1, hi[1] + 1, lo[2]) +
      at(lo[0], lo[1], hi[2] + 1) + at(lo[0], hi[1] + 1, lo[2]) + at(hi[0] + 1, lo[1], lo[2]) -
      at(lo[0], lo[1], lo[2]);
  };
  std::vector<std::uint32_t> tiles;
  for (int z = 0; z < l[2]; ++z)
  {
    const double pz = NodeIndex(z, d[2], l[2]);
    for (int ty = 0; ty < TilesAlong(l[1]); ++ty)
    {
      const double py0 = NodeIndex(ty * LightTileSize, d[1], l[1]);
      const double py1 = NodeIndex(std::min(l[1], (ty + 1) * LightTileSize) - 1, d[1], l[1]);
      for (int tx = 0; tx < TilesAlong(l[0]); ++tx)
      {
        const double px0 = NodeIndex(tx * LightTileSize, d[0], l[0]);
        const double px1 = NodeIndex(std::min(l[0], (tx + 1) * LightTileSize) - 1, d[0], l[0]);
        bool read = false;
        for (std::size_t b = 0; b < reach.size() && !read; ++b)
        {
          std::array<int, 3> lo, hi;
          range(0, px0, px1, reach[b], lo[0], hi[0]);
          range(1, py0, py1, reach[b], lo[1], hi[1]);
          range(2, pz, pz, reach[b], lo[2], hi[2]);
          // (Clamped: the first and the last cells reach beyond the lattice, as the occupancy
          // grid's reach the box's border; a box beyond it meets them, which only marches more.)
          read = occupiedIn(lo, hi) > 0;
        }
        if (read)
        {
          tiles.push_back(Pack(tx, ty, z));
        }
      }
    }
  }
  return tiles;
}

} // namespace avs
