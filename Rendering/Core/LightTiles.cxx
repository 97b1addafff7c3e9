#include "LightTiles.h"

#include "SummedAreaTable.h"

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

// The data index of light node i on an axis of n data points and l light nodes.
double NodeIndex(int i, int n, int l)
{
  return l > 1 ? static_cast<double>(i) * (n - 1) / (l - 1) : 0.0;
}
} // namespace

LightReachBox RayReach(const std::array<int, 3>& dataDimensions,
  const std::array<int, 3>& lightDimensions)
{
  LightReachBox rays;
  for (int a = 0; a < 3; ++a)
  {
    const double cell = lightDimensions[a] > 1
      ? static_cast<double>(dataDimensions[a] - 1) / (lightDimensions[a] - 1)
      : static_cast<double>(dataDimensions[a]);
    rays.Low[a] = rays.High[a] = 2.0 * cell + 1.0;
  }
  return rays;
}

std::array<int, 3> LightTileCounts(const std::array<int, 3>& l)
{
  return {
    (l[0] + LightTileSize - 1) / LightTileSize, (l[1] + LightTileSize - 1) / LightTileSize, l[2]
  };
}

std::size_t NumberOfLightTiles(const std::array<int, 3>& l)
{
  const std::array<int, 3> t = LightTileCounts(l);
  return static_cast<std::size_t>(t[0]) * t[1] * t[2];
}

std::vector<std::uint32_t> AllLightTiles(const std::array<int, 3>& l)
{
  const std::array<int, 3> t = LightTileCounts(l);
  std::vector<std::uint32_t> tiles;
  tiles.reserve(NumberOfLightTiles(l));
  for (int z = 0; z < t[2]; ++z)
    for (int ty = 0; ty < t[1]; ++ty)
      for (int tx = 0; tx < t[0]; ++tx)
        tiles.push_back(Pack(tx, ty, z));
  return tiles;
}

std::vector<std::uint32_t> LightGridTiles(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  int cellSize,
  const std::array<int, 3>& d,
  const std::array<int, 3>& l,
  const LightReachBox& reach)
{
  const std::size_t count = static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
  if (occupied.size() != count || count == 0 || cellSize < 1)
  {
    return AllLightTiles(l);
  }
  // Occupied cells counted over boxes of cells.
  std::vector<float> ones(count);
  std::transform(
    occupied.begin(), occupied.end(), ones.begin(), [](float v) { return v > 0.0f ? 1.0f : 0.0f; });
  const SummedAreaTable sum(ones.data(), cells);
  // The cells [lo, hi] along axis a whose owned indices meet [p0 - low, p1 + high].
  auto range = [&](int a, double p0, double p1, int& lo, int& hi)
  {
    lo = std::clamp(static_cast<int>(std::floor((p0 - reach.Low[a]) / cellSize)), 0, cells[a] - 1);
    hi = std::clamp(static_cast<int>(std::floor((p1 + reach.High[a]) / cellSize)), 0, cells[a] - 1);
  };
  const std::array<int, 3> t = LightTileCounts(l);
  std::vector<std::uint32_t> tiles;
  for (int z = 0; z < t[2]; ++z)
  {
    const double pz = NodeIndex(z, d[2], l[2]);
    for (int ty = 0; ty < t[1]; ++ty)
    {
      const double py0 = NodeIndex(ty * LightTileSize, d[1], l[1]);
      const double py1 = NodeIndex(std::min(l[1], (ty + 1) * LightTileSize) - 1, d[1], l[1]);
      for (int tx = 0; tx < t[0]; ++tx)
      {
        const double px0 = NodeIndex(tx * LightTileSize, d[0], l[0]);
        const double px1 = NodeIndex(std::min(l[0], (tx + 1) * LightTileSize) - 1, d[0], l[0]);
        std::array<int, 3> lo, hi;
        range(0, px0, px1, lo[0], hi[0]);
        range(1, py0, py1, lo[1], hi[1]);
        range(2, pz, pz, lo[2], hi[2]);
        // (Clamped: the first and the last cells reach beyond the lattice, as the occupancy
        // grid's reach the box's border; a box beyond it meets them, which only marches more.)
        if (sum.BoxSum(lo, hi) > 0.5)
        {
          tiles.push_back(Pack(tx, ty, z));
        }
      }
    }
  }
  return tiles;
}

} // namespace avs
