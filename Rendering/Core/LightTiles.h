// Empty space in the light-volume pass (ARCHITECTURE.md, "Empty space"): the tiles of the light
// grid whose light volumes the rays read. They read the light volumes only at samples with
// material (their group's light point, at most a light cell away, interpolated over one more): a
// node farther than that from every cell that the occupancy grid (OccupancyGrid.h) says may hold
// material is read by no ray. The GPU pass marches only the tiles that hold a nearer node (and,
// for the extended model, those that its diffusion reads, flagged on the GPU from its cells that
// are not vacuum: vtkAVSDiffuseVolume::MarkTiles), and leaves the others' texels as they were
// (finite: the textures start at 1).
#ifndef avs_LightTiles_h
#define avs_LightTiles_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace avs
{

/// Light-grid nodes per tile along x and y (a tile is TileSize x TileSize x 1 nodes: the GPU
/// pass's work group).
constexpr int LightTileSize = 8;

/// A box of data indices around a node, [p - Low, p + High] per axis (voxels): a node is read
/// where an occupied cell meets one of its boxes.
struct LightReachBox
{
  std::array<double, 3> Low{ 0.0, 0.0, 0.0 };
  std::array<double, 3> High{ 0.0, 0.0, 0.0 };
};

/// The box within which a node of the light grid `lightDimensions` over the data's lattice
/// `dataDimensions` is read by the rays from a voxel with material: two light cells (a light
/// point within one of a sample, and the interpolation's) and a voxel to spare, on every side.
LightReachBox RayReach(const std::array<int, 3>& dataDimensions,
  const std::array<int, 3>& lightDimensions);

/// The tiles of the light grid `lightDimensions` over the lattice `dataDimensions` that hold a
/// node with an occupied cell in its box `reach` (RayReach): cells of `cellSize` voxels
/// per axis, `cells` of them (x fastest), occupied where `occupied` is above 0 (cell a owns the
/// indices [a B, (a + 1) B), the first one from minus infinity, the last one to infinity). Each
/// tile as its x and y tile indices and its z node, x | y << 10 | z << 20, in z, y, x order. Every
/// tile where `occupied` does not match `cells`.
std::vector<std::uint32_t> LightGridTiles(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  int cellSize,
  const std::array<int, 3>& dataDimensions,
  const std::array<int, 3>& lightDimensions,
  const LightReachBox& reach);

/// Every tile of the light grid `lightDimensions`, in the same order and packing.
std::vector<std::uint32_t> AllLightTiles(const std::array<int, 3>& lightDimensions);

/// The tiles of the light grid `lightDimensions` along x and along y, and its nodes along z.
std::array<int, 3> LightTileCounts(const std::array<int, 3>& lightDimensions);

/// How many tiles the light grid `lightDimensions` has.
std::size_t NumberOfLightTiles(const std::array<int, 3>& lightDimensions);

/// The tile's place in AllLightTiles' order on a grid of `counts` tiles (LightTileCounts).
inline std::size_t LightTileIndex(std::uint32_t tile, const std::array<int, 3>& counts)
{
  return (static_cast<std::size_t>(tile >> 20) * counts[1] + ((tile >> 10) & 1023u)) * counts[0] +
    (tile & 1023u);
}

/// The tile's first node.
inline std::array<int, 3> LightTileOrigin(std::uint32_t tile)
{
  return { static_cast<int>(tile & 1023u) * LightTileSize,
    static_cast<int>((tile >> 10) & 1023u) * LightTileSize,
    static_cast<int>(tile >> 20) };
}

} // namespace avs

#endif
