/**
 * @class   vtkAVSBricks
 * @brief   how the scalar volume is split into bricks, and the order they are drawn in (private)
 *
 * A volume larger than one 3D texture (GL_MAX_3D_TEXTURE_SIZE on an axis), or split on request
 * (vtkAVSVolumeMapper::SetPartitions), is cut along each index axis into near-equal ranges of
 * voxels. Brick k along an axis owns the continuous indices [c_k, c_{k+1}) between integer cut
 * planes c_k (the outer bricks reach out to the volume's box, the border of cell data included),
 * and its texture holds the voxels [c_k - g, c_{k+1} + g] (clamped to the volume): the layer at
 * c_{k+1} is shared with the next brick, so that trilinear interpolation (and the nearest voxel)
 * at every owned sample reads the same voxels as in the unsplit texture; g more layers on
 * either side hold what a pass reads beyond its owned box: 1 for a gradient opacity (central
 * differences, one voxel away), and for ambient scattering the voxels of the look-ahead's
 * priming before a brick's first sample (vtkAVSRayCaster::LookBackVoxels). The ray caster draws the
 * bricks back to front (BackToFront), each ray clipped to the brick's owned box, samples at the
 * unsplit ray's positions (ARCHITECTURE.md, "Bricking"). No OpenGL here.
 */
#ifndef vtkAVSBricks_h
#define vtkAVSBricks_h

#include "Grid.h"

#include <array>
#include <string>
#include <vector>

class vtkAVSBricks
{
public:
  struct Brick
  {
    std::array<int, 3> Cell{ 0, 0, 0 };       ///< its place in the grid of bricks
    std::array<int, 3> Origin{ 0, 0, 0 };     ///< the first voxel of its texture
    std::array<int, 3> Dimensions{ 1, 1, 1 }; ///< the voxels of its texture
    std::array<double, 3> Low{ 0, 0, 0 };     ///< the owned box [Low, High), continuous index
    std::array<double, 3> High{ 0, 0, 0 };
  };

  /// Splits a volume of `dimensions` voxels into `partitions` bricks per axis (each clamped to
  /// [1, dimensions - 1], 1 on a one-voxel axis), with `ghost[a]` extra voxel layers on either
  /// side of each shared one along axis a, the outer boxes reaching `border` voxels beyond the
  /// samples.
  void Split(const std::array<int, 3>& dimensions,
    const std::array<int, 3>& partitions,
    double border,
    const std::array<int, 3>& ghost);

  /// The fewest partitions per axis for which every brick's texture (ghost layers included) has
  /// at most `maximumSize` voxels per axis; false (with the reason) where none has.
  static bool PartitionsFor(const std::array<int, 3>& dimensions,
    int maximumSize,
    const std::array<int, 3>& ghost,
    std::array<int, 3>& partitions,
    std::string& error);

  /// The voxels of `grid` in the box of `dimensions` from `origin` (a brick's texture).
  static avs::Grid Crop(const avs::Grid& grid,
    const std::array<int, 3>& origin,
    const std::array<int, 3>& dimensions);

  /// Whether `other` has the same bricks (the same voxels in each texture).
  bool SameSplit(const vtkAVSBricks& other) const;

  const std::vector<Brick>& GetBricks() const { return this->Bricks; }
  const std::array<int, 3>& GetPartitions() const { return this->Partitions; }
  int GetNumberOfBricks() const { return static_cast<int>(this->Bricks.size()); }
  bool IsSplit() const { return this->Bricks.size() > 1; }
  void Clear();

  /// The bricks' indices in back-to-front order for an eye at `eye` (continuous index frame;
  /// for a parallel projection a point far behind the volume along the view direction): the
  /// key sum_a |cell_a - eye's cell_a| (the eye's cell clamped to the grid) increases along
  /// every ray from the eye, so drawing in decreasing key composites every ray back to front.
  std::vector<int> BackToFront(const std::array<double, 3>& eye) const;

private:
  std::vector<Brick> Bricks;
  std::array<int, 3> Partitions{ 1, 1, 1 };
  /// The cut planes c_0 .. c_n per axis (voxel indices).
  std::array<std::vector<int>, 3> Cuts;
};

#endif
