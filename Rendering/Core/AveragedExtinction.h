// Averaged extinction (ALGORITHM.md section 3): the mean of sigma_t over the ball of radius r
// around each voxel, approximated by the mean over the axis-aligned cube of the same volume,
// half side h = r (pi / 6)^(1/3).
//
// The cube is taken in the grid's own (index) axes, so it turns with the image's direction
// matrix. In voxels its half widths are k_a = round(h / spacing_a); the mean is the sum over the
// (2 k_a + 1) voxels per axis divided by their full count: voxels outside the volume count as 0,
// so the average fades towards empty space at the border.
//
// The box sums are a summed-area table evaluated per line: for an axis-aligned box the 8-corner
// inclusion–exclusion of a 3D table factorises into three 1D prefix-sum differences, one per
// axis. Each pass keeps a double prefix sum of one line, so the work is a fixed number of
// additions per voxel whatever r is, the memory is one float grid, and no digits are lost on
// large volumes.
#ifndef avs_AveragedExtinction_h
#define avs_AveragedExtinction_h

#include "Grid.h"

#include <array>
#include <cstdint>
#include <functional>

namespace avs
{

/// (pi / 6)^(1/3): half side of the cube with the volume of the unit ball.
constexpr double CubeHalfSidePerRadius = 0.80599597700823482;

/// Half widths in voxels of the averaging cube for radius r on a grid with the given spacing.
std::array<int, 3> AveragingHalfWidths(double radius, const Vec3& spacing);

struct AveragingStatistics
{
  std::uint64_t Operations = 0; ///< additions and subtractions performed
};

/// Averaged extinction on the grid of `sigmaT` (same geometry). Multi-threaded.
/// `progress` (optional) receives values in [0, 1].
Grid AverageExtinction(const Grid& sigmaT,
  double radius,
  AveragingStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {});

/// The averaged extinction stored on `target`, a grid covering the same box (coarser, e.g. the
/// light volumes' grid; ALGORITHM.md section 3 allows it): the average on the grid of `sigmaT`,
/// interpolated trilinearly at the points of `target`. The GPU computes the same values
/// separably, interpolating each axis's box sums between voxels as it reduces that axis.
Grid AverageExtinctionOn(const Grid& sigmaT,
  double radius,
  const GridGeometry& target,
  AveragingStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {});

/// `values` interpolated trilinearly at the points of `target` (same box); a copy when the
/// dimensions agree.
Grid ResampleTrilinear(const Grid& values, const GridGeometry& target);

/// Mean over an arbitrary half-width box (the building block of AverageExtinction).
Grid BoxMean(const Grid& values,
  const std::array<int, 3>& halfWidths,
  AveragingStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {});

} // namespace avs

#endif
