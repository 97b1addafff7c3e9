// The averaged extinction of a volume split into pieces (distributed rendering: ARCHITECTURE.md,
// "Distributed rendering"). Each piece computes its share of the whole volume's averaged
// extinction on the whole volume's light grid; the shares of all pieces sum to
// AverageExtinctionOn of the whole volume, because the box mean and the trilinear interpolation
// are linear in sigma_t and every sample of the whole lattice belongs to exactly one piece.
// Summed over the ranks (an all-reduce), the shares give every rank the global averaged
// extinction without any rank holding more of the data's resolution than its own piece and a
// margin of the averaging box's half width around it.
#ifndef avs_PieceAveraging_h
#define avs_PieceAveraging_h

#include "Grid.h"

#include <array>
#include <vector>

namespace avs
{

/// A box of samples of the whole lattice, inclusive: {i0, i1, j0, j1, k0, k1}.
using IndexBox = std::array<int, 6>;

/// The whole grid of which `piece` is the part whose first sample is the whole's `offset`: the
/// same spacing, direction and border, `dimensions` samples, and the origin moved back.
GridGeometry WholeGeometry(const GridGeometry& piece,
  const std::array<int, 3>& offset,
  const std::array<int, 3>& dimensions);

/// The samples of the whole lattice that the piece at `offset` with `dimensions` covers.
IndexBox PieceBox(const std::array<int, 3>& offset, const std::array<int, 3>& dimensions);

/// Whether `box` lies inside a lattice of `dimensions` samples and is not empty.
bool BoxInside(const IndexBox& box, const std::array<int, 3>& dimensions);

/// The piece's share of the whole volume's averaged extinction for radius r, on `target` (a grid
/// over the whole lattice's box, e.g. whole.Capped(m)). `pieceSigmaT` is sigma_t on the piece's
/// own grid, whose first sample is `offset` in `whole`. A sample the piece shares with another
/// piece (the common face of point data, ghost layers) belongs to the piece of lowest rank:
/// `earlier` lists the boxes of the pieces of lower rank, and the piece leaves the samples inside
/// any of them to those. The share is zero at target points whose box does not reach the piece.
Grid AverageExtinctionShare(const Grid& pieceSigmaT,
  const std::array<int, 3>& offset,
  const GridGeometry& whole,
  const std::vector<IndexBox>& earlier,
  double radius,
  const GridGeometry& target);

/// `values` (a grid over the whole lattice's box) interpolated trilinearly at the points of
/// `piece` (always sampled, even when the dimensions happen to agree).
Grid SampleAtPoints(const Grid& values, const GridGeometry& piece);

} // namespace avs

#endif
