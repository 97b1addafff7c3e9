// Empty space in the light-volume pass (ARCHITECTURE.md, "Empty space"): the tiles of the light
// grid whose light volumes something reads. The rays read the light volumes only at samples with
// material (their group's light point, at most a light cell away, interpolated over one more), and
// the extended model's diffusion at its cells with averaged extinction (within the averaging box
// of material), r downstream. A node farther than that from every cell that the occupancy grid
// (OccupancyGrid.h) says may hold material is read by nothing: the GPU pass marches only the
// tiles that hold a nearer node, and leaves the others' texels as they were (finite: the textures
// start at 1).
#ifndef avs_LightTiles_h
#define avs_LightTiles_h

#include "Vec3.h"

#include <array>
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

/// The boxes within which a node of the light grid `lightDimensions` over the data's lattice
/// `dataDimensions` (spacing `dataSpacing`) is read from a voxel with material:
/// - the rays': two light cells (a light point within one of a sample, and the interpolation's)
///   and a voxel to spare, on every side;
/// - with `diffusion` (the extended model) the diffusion's, which reads the light volume r
///   downstream of each point with averaged extinction (within the averaging box's half width at
///   `radius` and a voxel of material, and a light cell between the nodes), interpolated over a
///   light cell, with a voxel to spare: for a light whose propagation direction is the same
///   everywhere (`direction`, in the data's local frame, non-zero: a directional light) that box
///   moved r upstream, else widened by r on every side.
std::vector<LightReachBox> LightReach(const std::array<int, 3>& dataDimensions,
  const Vec3& dataSpacing,
  const std::array<int, 3>& lightDimensions,
  double radius,
  bool diffusion,
  const Vec3& direction = Vec3{ 0.0, 0.0, 0.0 });

/// The tiles of the light grid `lightDimensions` over the lattice `dataDimensions` that hold a
/// node with an occupied cell in one of its boxes `reach` (LightReach): cells of `cellSize` voxels
/// per axis, `cells` of them (x fastest), occupied where `occupied` is above 0 (cell a owns the
/// indices [a B, (a + 1) B), the first one from minus infinity, the last one to infinity). Each
/// tile as its x and y tile indices and its z node, x | y << 10 | z << 20, in z, y, x order. Every
/// tile where `occupied` does not match `cells`.
std::vector<std::uint32_t> LightGridTiles(const std::vector<float>& occupied,
  const std::array<int, 3>& cells,
  int cellSize,
  const std::array<int, 3>& dataDimensions,
  const std::array<int, 3>& lightDimensions,
  const std::vector<LightReachBox>& reach);

/// Every tile of the light grid `lightDimensions`, in the same order and packing.
std::vector<std::uint32_t> AllLightTiles(const std::array<int, 3>& lightDimensions);

/// The tile's first node.
inline std::array<int, 3> LightTileOrigin(std::uint32_t tile)
{
  return { static_cast<int>(tile & 1023u) * LightTileSize,
    static_cast<int>((tile >> 10) & 1023u) * LightTileSize,
    static_cast<int>(tile >> 20) };
}

} // namespace avs

#endif
