#include "PieceAveraging.h"

#include "AveragedExtinction.h"
#include "GridFill.h"

#include <algorithm>
#include <cmath>

namespace avs
{

GridGeometry WholeGeometry(const GridGeometry& piece,
  const std::array<int, 3>& offset,
  const std::array<int, 3>& dimensions)
{
  GridGeometry whole = piece;
  whole.Dimensions = dimensions;
  const Vec3 shift{
    offset[0] * piece.Spacing.x, offset[1] * piece.Spacing.y, offset[2] * piece.Spacing.z
  };
  whole.Origin = piece.Origin - piece.LocalToWorldDirection(shift);
  return whole;
}

IndexBox PieceBox(const std::array<int, 3>& offset, const std::array<int, 3>& dimensions)
{
  return { offset[0],
    offset[0] + dimensions[0] - 1,
    offset[1],
    offset[1] + dimensions[1] - 1,
    offset[2],
    offset[2] + dimensions[2] - 1 };
}

bool BoxInside(const IndexBox& box, const std::array<int, 3>& dimensions)
{
  for (int a = 0; a < 3; ++a)
  {
    if (box[2 * a] < 0 || box[2 * a + 1] < box[2 * a] || box[2 * a + 1] >= dimensions[a])
    {
      return false;
    }
  }
  return true;
}

namespace
{
bool Contains(const IndexBox& box, int i, int j, int k)
{
  return i >= box[0] && i <= box[1] && j >= box[2] && j <= box[3] && k >= box[4] && k <= box[5];
}

bool Intersect(const IndexBox& a, const IndexBox& b)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (a[2 * axis + 1] < b[2 * axis] || b[2 * axis + 1] < a[2 * axis])
    {
      return false;
    }
  }
  return true;
}
} // namespace

Grid AverageExtinctionShare(const Grid& pieceSigmaT,
  const std::array<int, 3>& offset,
  const GridGeometry& whole,
  const std::vector<IndexBox>& earlier,
  double radius,
  const GridGeometry& target)
{
  const GridGeometry& piece = pieceSigmaT.Geometry;
  const IndexBox box = PieceBox(offset, piece.Dimensions);
  const std::array<int, 3> k = AveragingHalfWidths(radius, whole.Spacing);
  // The region: the piece widened by k + 1 samples (within the whole lattice). The box mean of
  // the piece's owned sigma_t (0 elsewhere) is exact on it, and zero on its outer layer wherever
  // that is not the whole lattice's face, so that the trilinear reads near its faces are exact
  // too; beyond it the mean is zero.
  std::array<int, 3> lower{}, dims{};
  for (int a = 0; a < 3; ++a)
  {
    lower[a] = std::max(0, box[2 * a] - k[a] - 1);
    const int upper = std::min(whole.Dimensions[a] - 1, box[2 * a + 1] + k[a] + 1);
    dims[a] = upper - lower[a] + 1;
  }
  GridGeometry regionGeometry = WholeGeometry(whole,
    { -lower[0], -lower[1], -lower[2] },
    dims); // the whole's origin moved forward to `lower`
  std::vector<IndexBox> others;
  for (const IndexBox& other : earlier)
  {
    if (Intersect(other, box))
    {
      others.push_back(other);
    }
  }
  Grid region(regionGeometry, 0.0f);
  for (int z = 0; z < piece.Dimensions[2]; ++z)
  {
    for (int y = 0; y < piece.Dimensions[1]; ++y)
    {
      for (int x = 0; x < piece.Dimensions[0]; ++x)
      {
        const int i = x + offset[0], j = y + offset[1], l = z + offset[2];
        const bool owned = std::none_of(others.begin(),
          others.end(),
          [&](const IndexBox& other) { return Contains(other, i, j, l); });
        if (owned)
        {
          region.At(i - lower[0], j - lower[1], l - lower[2]) = pieceSigmaT.At(x, y, z);
        }
      }
    }
  }
  const Grid mean = BoxMean(region, k);
  return FillGrid(target,
    [&](const Vec3& world, std::uint64_t&)
    { return mean.SampleIndex(regionGeometry.WorldToIndex(world), 0.0); });
}

Grid SampleAtPoints(const Grid& values, const GridGeometry& piece)
{
  const GridGeometry& source = values.Geometry;
  return FillGrid(piece,
    [&](const Vec3& world, std::uint64_t&)
    { return values.SampleIndex(source.WorldToIndex(world), 0.0); });
}

} // namespace avs
