// A 3D summed-area table in double precision (ALGORITHM.md section 3): O(N) to build, O(1) box
// sums by 8-corner inclusion–exclusion. Entry (i, j, k) holds the sum over [0, i) x [0, j) x
// [0, k), so the table has (n + 1) entries per axis and the empty prefix is 0. The sign of each
// corner alternates with the number of lower ("0") corner indices it uses.
#ifndef avs_SummedAreaTable_h
#define avs_SummedAreaTable_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace avs
{

class SummedAreaTable
{
public:
  /// Builds the table of `values` (x fastest) with dimensions `dims`.
  SummedAreaTable(const float* values, const std::array<int, 3>& dims);

  /// Sum over the inclusive index box [lo, hi], clipped to the grid; voxels outside count as 0.
  /// An empty box (after clipping) sums to 0.
  double BoxSum(std::array<int, 3> lo, std::array<int, 3> hi) const;

  /// Additions performed by the build (the work counter the tests use).
  std::uint64_t BuildOperations() const { return this->Operations; }

private:
  double At(int i, int j, int k) const
  {
    return this
      ->Table[(static_cast<std::size_t>(k) * (this->Dims[1] + 1) + j) * (this->Dims[0] + 1) + i];
  }
  std::array<int, 3> Dims;
  std::vector<double> Table;
  std::uint64_t Operations = 0;
};

} // namespace avs

#endif
