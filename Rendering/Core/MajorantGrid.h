// A coarse grid of extinction majorants (ALGORITHM.md section 8): for each cell of B^3 voxels, an
// upper bound of sigma_t anywhere inside it. sigma_t(x) is the transfer function applied to the
// trilinearly interpolated scalar, so inside a cell it takes values of the transfer function
// between the smallest and the largest scalar at the cell's corner voxels; the majorant is the
// largest sigma_t of the transfer function over that scalar interval (exact for the sampled,
// linearly interpolated table; Classifier::Bound, which also bounds several components, gradient
// opacity, NaN voxels and masks). Delta and ratio tracking walk the cells with a DDA.
#ifndef avs_MajorantGrid_h
#define avs_MajorantGrid_h

#include "Classifier.h"
#include "ClipRegion.h"
#include "Grid.h"
#include "TransferFunction.h"

#include <array>
#include <vector>

namespace avs
{

class MajorantGrid
{
public:
  /// Majorants of sigma_t for `scalars` with `tf` and unit distance `u`, cells of `cellSize`
  /// voxels per axis (cellSize >= the whole grid gives one global majorant). Cells wholly
  /// outside `clip` (when given) get 0.
  MajorantGrid(const Grid& scalars,
    const TransferFunction& tf,
    double unitDistance,
    int cellSize,
    const ClipRegion* clip = nullptr);
  /// Majorants of what `classifier` classifies on the lattice `geometry` (components,
  /// gradient opacity, NaN voxels and masks included: Classifier::Bound); cells wholly outside
  /// `clip` (when given) get 0.
  MajorantGrid(const Classifier& classifier,
    const GridGeometry& geometry,
    int cellSize,
    const ClipRegion* clip = nullptr);

  int CellSize() const { return this->Size; }
  const std::array<int, 3>& Cells() const { return this->Count; }
  /// Majorant of the cell holding continuous index p (clamped into the grid).
  double At(const Vec3& index) const;
  double Cell(int i, int j, int k) const
  {
    return this->Values[(static_cast<std::size_t>(k) * this->Count[1] + j) * this->Count[0] + i];
  }
  double Maximum() const { return this->Largest; }

private:
  int Size;
  std::array<int, 3> Count;
  std::vector<double> Values;
  double Largest = 0.0;
};

} // namespace avs

#endif
