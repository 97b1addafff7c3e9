// The tiles of the light grid that the light-volume pass marches (Core/LightTiles.h): every tile
// holding a node within the reach of an occupied cell, and no other, against a node-by-node
// check on structured occupancies (none, all, one cell in a corner and in the middle, a random
// scatter, a ball), on grids coarser than the data, as fine, and not a multiple of the tile, with
// symmetric and moved boxes; the rays' reach. (The extended model's diffusion flags its tiles on
// the GPU: Cxx.TestEmptySpaceSkipping's dense slab.)
#include "LightTiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <set>

using namespace avs;

namespace
{
// The tiles with a node that has an occupied cell's owned indices in its box, node by node (the
// first cell from minus infinity, the last to infinity).
std::set<std::uint32_t> Expected(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  int size,
  const std::array<int, 3>& d,
  const std::array<int, 3>& l,
  const LightReachBox& box)
{
  std::set<std::uint32_t> tiles;
  auto index = [&](int a, int i)
  { return l[a] > 1 ? static_cast<double>(i) * (d[a] - 1) / (l[a] - 1) : 0.0; };
  // Whether [p - low, p + high] meets the owned indices of cell c along axis a.
  auto meets = [&](int a, double p, int c, const LightReachBox& box)
  {
    const double lo = c == 0 ? -1e30 : c * size;
    const double hi = c == cells[a] - 1 ? 1e30 : (c + 1) * size;
    return p + box.High[a] >= lo && p - box.Low[a] < hi;
  };
  for (int z = 0; z < l[2]; ++z)
    for (int y = 0; y < l[1]; ++y)
      for (int x = 0; x < l[0]; ++x)
      {
        bool read = false;
        for (int k = 0; k < cells[2] && !read; ++k)
          for (int j = 0; j < cells[1] && !read; ++j)
            for (int i = 0; i < cells[0] && !read; ++i)
            {
              const std::size_t c = (static_cast<std::size_t>(k) * cells[1] + j) * cells[0] + i;
              read = occupied[c] > 0.0f && meets(0, index(0, x), i, box) &&
                meets(1, index(1, y), j, box) && meets(2, index(2, z), k, box);
            }
        if (read)
        {
          tiles.insert(static_cast<std::uint32_t>(x / LightTileSize) |
            (static_cast<std::uint32_t>(y / LightTileSize) << 10) |
            (static_cast<std::uint32_t>(z) << 20));
        }
      }
  return tiles;
}

void Check(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  const std::array<int, 3>& d,
  const std::array<int, 3>& l,
  const LightReachBox& reach)
{
  const std::vector<std::uint32_t> tiles = LightGridTiles(occupied, cells, 8, d, l, reach);
  const std::set<std::uint32_t> got(tiles.begin(), tiles.end());
  EXPECT_EQ(got.size(), tiles.size()); // no tile twice
  EXPECT_EQ(got, Expected(occupied, cells, 8, d, l, reach));
  for (std::uint32_t t : tiles)
  {
    const std::array<int, 3> origin = LightTileOrigin(t);
    EXPECT_TRUE(origin[0] < l[0] && origin[1] < l[1] && origin[2] < l[2]);
  }
}

LightReachBox Symmetric(double x, double y, double z)
{
  LightReachBox box;
  box.Low = box.High = { x, y, z };
  return box;
}
} // namespace

TEST(LightTiles, AllTilesCoverTheGridOnce)
{
  const std::array<int, 3> l{ 20, 9, 3 };
  const std::vector<std::uint32_t> tiles = AllLightTiles(l);
  EXPECT_EQ(tiles.size(), 3u * 2u * 3u);
  std::set<std::array<int, 3>> origins;
  for (std::uint32_t t : tiles)
  {
    origins.insert(LightTileOrigin(t));
  }
  EXPECT_EQ(origins.size(), tiles.size());
  EXPECT_EQ(origins.count({ 16, 8, 2 }), 1u);
  // Their counts, and each one's place in that order.
  EXPECT_EQ(LightTileCounts(l), (std::array<int, 3>{ 3, 2, 3 }));
  EXPECT_EQ(NumberOfLightTiles(l), tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i)
  {
    EXPECT_EQ(LightTileIndex(tiles[i], LightTileCounts(l)), i);
  }
}

TEST(LightTiles, NodesWithinReachOfOccupiedCells)
{
  const std::array<int, 3> d{ 64, 40, 24 };
  const std::array<int, 3> cells{ 8, 5, 3 };
  const std::size_t n = 8 * 5 * 3;
  // A symmetric box, and one moved along a direction beside it (LightGridTiles takes any box).
  LightReachBox moved = Symmetric(4.0, 6.0, 2.0);
  moved.Low = { 4.0 + 9.0, 6.0 - 3.0, 2.0 + 5.0 };
  moved.High = { 4.0 - 9.0, 6.0 + 3.0, 2.0 - 5.0 };
  for (const LightReachBox& reach : { Symmetric(5.0, 3.0, 9.5), moved })
    for (const std::array<int, 3>& l : { std::array<int, 3>{ 32, 20, 12 },
           std::array<int, 3>{ 64, 40, 24 },
           std::array<int, 3>{ 21, 13, 5 } })
    {
      // None, all, a corner cell, a middle cell.
      Check(std::vector<float>(n, 0.0f), cells, d, l, reach);
      EXPECT_TRUE(LightGridTiles(std::vector<float>(n, 0.0f), cells, 8, d, l, reach).empty());
      Check(std::vector<float>(n, 1.0f), cells, d, l, reach);
      EXPECT_EQ(LightGridTiles(std::vector<float>(n, 1.0f), cells, 8, d, l, reach).size(),
        AllLightTiles(l).size());
      std::vector<float> corner(n, 0.0f);
      corner[n - 1] = 1.0f;
      Check(corner, cells, d, l, reach);
      std::vector<float> middle(n, 0.0f);
      middle[(1 * 5 + 2) * 8 + 4] = 2.5f;
      Check(middle, cells, d, l, reach);
      // A random scatter, a tenth of the cells.
      std::mt19937 random(7);
      std::vector<float> scatter(n, 0.0f);
      for (float& v : scatter)
      {
        v = random() % 10 == 0 ? 1.0f : 0.0f;
      }
      Check(scatter, cells, d, l, reach);
    }
  // Occupancy of another size: every tile.
  const std::array<int, 3> l{ 32, 20, 12 };
  EXPECT_EQ(LightGridTiles(std::vector<float>(5, 0.0f), cells, 8, d, l, moved).size(),
    AllLightTiles(l).size());
}

TEST(LightTiles, ReachOfTheRays)
{
  const std::array<int, 3> d{ 256, 256, 65 };
  const std::array<int, 3> l{ 128, 128, 65 };
  // Two light cells and a voxel on every side.
  const LightReachBox rays = RayReach(d, l);
  EXPECT_NEAR(rays.Low[0], 2.0 * 255.0 / 127.0 + 1.0, 1e-12);
  EXPECT_NEAR(rays.Low[2], 3.0, 1e-12);
  EXPECT_EQ(rays.High, rays.Low);
  // On a ball of material: some tiles, most of the grid left out.
  const std::array<int, 3> cube{ 256, 256, 256 }, grid{ 128, 128, 128 };
  const std::array<int, 3> cells{ 32, 32, 32 };
  std::vector<float> ball(32 * 32 * 32, 0.0f);
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
      {
        const double x = i - 15.5, y = j - 15.5, z = k - 15.5;
        ball[(static_cast<std::size_t>(k) * 32 + j) * 32 + i] =
          x * x + y * y + z * z < 64 ? 1.0f : 0.0f;
      }
  const std::vector<std::uint32_t> tiles =
    LightGridTiles(ball, cells, 8, cube, grid, RayReach(cube, grid));
  EXPECT_GT(tiles.size(), 0u);
  EXPECT_LT(tiles.size(), AllLightTiles(grid).size() / 4);
}
