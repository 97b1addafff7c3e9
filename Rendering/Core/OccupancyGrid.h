// Empty-space skipping (ARCHITECTURE.md, "Empty space"): a coarse grid that says, for cells of
// B^3 voxels, whether any sample a ray takes inside the cell can have sigma_t > 0. The GPU ray
// caster leaps over the cells that cannot, to the first sample of its own grid beyond them, so
// that the samples it takes, and the picture, are those of a ray that marched through.
//
// A cell owns the continuous indices [a B, (a + 1) B) on each axis (the first and the last cells
// reach the box's border beyond the lattice). A sample there interpolates the lattice points
// [a B - 1, (a + 1) B + 1] at most (one voxel to spare on either side, for the rounding of the
// ray's positions on the GPU). Two steps:
//  - ValueRangeGrid, once per change of the data: each component's smallest and largest value
//    over those lattice points (NaN voxels left out);
//  - Occupancy, once per change of the opacity: the classifier's bound of sigma_t over those
//    ranges (Classifier::BoundOfValues, every transfer-function row the sample may read, each
//    range widened by one table node for the GPU's rounding of the table coordinate), 1 where
//    it is above 0.
// Both are conservative: gradient opacity, a binary mask, clipping and cropping only lower
// sigma_t, so a cell they empty is still marched (the ray's clipping shortens it anyway).
#ifndef avs_OccupancyGrid_h
#define avs_OccupancyGrid_h

#include "Classifier.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace avs
{

class ValueRangeGrid
{
public:
  /// The cell size the mappers use (voxels per axis): measured on the benchmark's scenes
  /// (avs-bench-mappers), against 4 and 16.
  static constexpr int DefaultCellSize = 8;

  /// Writes component c's values of the voxel ids [begin, end) (one row of the lattice) as
  /// floats into `out`.
  using RowReader = std::function<void(int c, std::size_t begin, std::size_t end, float* out)>;

  ValueRangeGrid() = default;
  /// The ranges of `components` (1-4) components on a lattice of `dimensions`, cells of
  /// `cellSize` voxels per axis; `read` gives the values (called from several threads, one row
  /// at a time), `validity` (empty: every voxel is finite) is 0 at NaN voxels.
  ValueRangeGrid(const std::array<int, 3>& dimensions,
    int components,
    int cellSize,
    const RowReader& read,
    const std::vector<float>& validity);

  /// Cells per axis: ceil(n / B).
  const std::array<int, 3>& Cells() const { return this->Count; }
  int CellSize() const { return this->Size; }
  int Components() const { return this->ComponentCount; }
  const std::array<int, 3>& Dimensions() const { return this->Lattice; }
  std::size_t NumberOfCells() const
  {
    return static_cast<std::size_t>(this->Count[0]) * this->Count[1] * this->Count[2];
  }
  /// Component c's smallest and largest value in cell `cell` (x fastest); Low > High where the
  /// cell's lattice points are all NaN.
  float Low(std::size_t cell, int c) const { return this->Lows[cell * 4 + c]; }
  float High(std::size_t cell, int c) const { return this->Highs[cell * 4 + c]; }
  bool Empty() const { return this->Lows.empty(); }

private:
  std::array<int, 3> Lattice{ 0, 0, 0 };
  std::array<int, 3> Count{ 0, 0, 0 };
  int Size = DefaultCellSize;
  int ComponentCount = 1;
  std::vector<float> Lows, Highs; ///< 4 per cell
};

/// 1 for each cell of `ranges` where a sample may have sigma_t > 0 under `classifier`'s transfer
/// functions, 0 where none can (x fastest).
std::vector<unsigned char> Occupancy(const ValueRangeGrid& ranges, const Classifier& classifier);

/// For each cell of `ranges` the classifier's bound of sigma_t (per data unit) over its ranges,
/// as Occupancy takes it (0 where no sample can have material): the majorants of the GPU path
/// tracer's delta and ratio tracking (avs_pathtrace_fs.glsl), on the cells empty-space skipping
/// uses.
std::vector<float> Majorants(const ValueRangeGrid& ranges, const Classifier& classifier);

/// The share of cells that are 0 in `occupancy`.
double EmptyFraction(const std::vector<unsigned char>& occupancy);

} // namespace avs

#endif
