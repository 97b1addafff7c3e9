// The averaged extinction of a volume split into pieces (PieceAveraging.h): the pieces' shares
// sum to the whole volume's averaged extinction on its light grid, for point-data pieces that
// share a face, for pieces with ghost layers, for a turned grid, and for cell-data pieces; a
// piece that is the whole gives the whole's average; counting the shared samples twice (no
// ownership) is visibly wrong.
#include "AveragedExtinction.h"
#include "PieceAveraging.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
// A structured sigma_t: blobs of three sizes and a slab, so that the averages vary strongly
// across the piece boundaries.
Grid Field(const GridGeometry& g)
{
  Grid grid(g);
  for (int k = 0; k < g.Dimensions[2]; ++k)
    for (int j = 0; j < g.Dimensions[1]; ++j)
      for (int i = 0; i < g.Dimensions[0]; ++i)
      {
        const double x = double(i) / (g.Dimensions[0] - 1), y = double(j) / (g.Dimensions[1] - 1),
                     z = double(k) / (g.Dimensions[2] - 1);
        double v = 4.0 * std::exp(-40.0 * ((x - 0.5) * (x - 0.5) + (y - 0.4) * (y - 0.4)));
        v += 2.0 * std::exp(-200.0 * ((x - 0.3) * (x - 0.3) + (z - 0.6) * (z - 0.6)));
        v += (y > 0.7 && y < 0.8) ? 1.5 : 0.0;
        v += 0.5 * std::sin(17.0 * x + 11.0 * y + 7.0 * z) + 0.5;
        grid.At(i, j, k) = static_cast<float>(v);
      }
  return grid;
}

// The part of `whole` in the box (whole-lattice samples, inclusive), on its own grid.
Grid Cut(const Grid& whole, const IndexBox& box)
{
  const std::array<int, 3> offset{ box[0], box[2], box[4] };
  const std::array<int, 3> dims{ box[1] - box[0] + 1, box[3] - box[2] + 1, box[5] - box[4] + 1 };
  GridGeometry g = whole.Geometry;
  g.Dimensions = dims;
  const Vec3 shift{ offset[0] * g.Spacing.x, offset[1] * g.Spacing.y, offset[2] * g.Spacing.z };
  g.Origin = g.Origin + g.LocalToWorldDirection(shift);
  Grid piece(g);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        piece.At(i, j, k) = whole.At(i + offset[0], j + offset[1], k + offset[2]);
  return piece;
}

// Sum of the shares of the pieces (in rank order), and the largest difference from the whole's
// averaged extinction relative to its largest value. `owned` false: every piece counts all its
// samples.
double SplitError(const Grid& whole,
  const std::vector<IndexBox>& boxes,
  double radius,
  int lightMaximum,
  bool owned = true)
{
  const GridGeometry target = whole.Geometry.Capped(lightMaximum);
  const Grid expected = AverageExtinctionOn(whole, radius, target);
  Grid sum(target, 0.0f);
  std::vector<IndexBox> earlier;
  for (const IndexBox& box : boxes)
  {
    const Grid piece = Cut(whole, box);
    const std::array<int, 3> offset{ box[0], box[2], box[4] };
    // The piece's own geometry gives the whole's back.
    const GridGeometry g = WholeGeometry(piece.Geometry, offset, whole.Geometry.Dimensions);
    EXPECT_NEAR(Length(g.Origin - whole.Geometry.Origin), 0.0, 1e-9);
    const Grid share = AverageExtinctionShare(
      piece, offset, g, owned ? earlier : std::vector<IndexBox>{}, radius, target);
    for (std::size_t i = 0; i < sum.Values.size(); ++i)
      sum.Values[i] += share.Values[i];
    earlier.push_back(box);
  }
  double largest = 0.0, error = 0.0;
  for (std::size_t i = 0; i < sum.Values.size(); ++i)
  {
    largest = std::max(largest, double(std::abs(expected.Values[i])));
    error = std::max(error, double(std::abs(sum.Values[i] - expected.Values[i])));
  }
  return error / largest;
}

GridGeometry Geometry(int nx, int ny, int nz)
{
  GridGeometry g;
  g.Dimensions = { nx, ny, nz };
  g.Origin = { -3.0, 1.5, 0.25 };
  g.Spacing = { 0.5, 0.75, 0.6 };
  return g;
}
} // namespace

TEST(PieceAveraging, PointDataPiecesSharingAFaceSumToTheWhole)
{
  const Grid whole = Field(Geometry(41, 33, 29));
  // Two pieces along x sharing the plane i = 20 (as VTK splits point data).
  EXPECT_LT(
    SplitError(whole, { { 0, 20, 0, 32, 0, 28 }, { 20, 40, 0, 32, 0, 28 } }, 3.0, 16), 1e-5);
  // Eight pieces, every axis split, a light grid as fine as the data.
  std::vector<IndexBox> eight;
  for (int c = 0; c < 8; ++c)
  {
    eight.push_back({ c & 1 ? 17 : 0,
      c & 1 ? 40 : 17,
      c & 2 ? 12 : 0,
      c & 2 ? 32 : 12,
      c & 4 ? 20 : 0,
      c & 4 ? 28 : 20 });
  }
  EXPECT_LT(SplitError(whole, eight, 2.0, 64), 1e-5);
}

TEST(PieceAveraging, GhostLayersAreCountedOnce)
{
  const Grid whole = Field(Geometry(36, 30, 40));
  // Three slabs along z overlapping by three samples.
  EXPECT_LT(SplitError(whole,
              { { 0, 35, 0, 29, 0, 15 }, { 0, 35, 0, 29, 13, 28 }, { 0, 35, 0, 29, 26, 39 } },
              4.0,
              20),
    1e-5);
  // Counting the overlap twice is wrong by far more than rounding.
  EXPECT_GT(
    SplitError(whole, { { 0, 35, 0, 29, 0, 15 }, { 0, 35, 0, 29, 13, 28 } }, 4.0, 20, false), 1e-2);
}

TEST(PieceAveraging, TurnedGridAndCellData)
{
  GridGeometry g = Geometry(30, 26, 22);
  // A rotation about z by 30 degrees.
  const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
  g.Direction = { c, -s, 0, s, c, 0, 0, 0, 1 };
  g.Border = 0.5; // cell data: the pieces' cells do not overlap
  const Grid whole = Field(g);
  EXPECT_LT(
    SplitError(whole, { { 0, 11, 0, 25, 0, 21 }, { 12, 29, 0, 25, 0, 21 } }, 2.5, 12), 1e-5);
}

TEST(PieceAveraging, OnePieceIsTheWhole)
{
  const Grid whole = Field(Geometry(24, 20, 18));
  EXPECT_LT(SplitError(whole, { { 0, 23, 0, 19, 0, 17 } }, 3.0, 10), 1e-6);
  // A piece far from a target point's box contributes nothing there, and the share is not
  // zero everywhere.
  const GridGeometry target = whole.Geometry.Capped(24);
  const Grid share = AverageExtinctionShare(
    Cut(whole, { 0, 5, 0, 19, 0, 17 }), { 0, 0, 0 }, whole.Geometry, {}, 1.0, target);
  EXPECT_GT(share.At(2, 10, 9), 0.1f);
  EXPECT_EQ(share.At(23, 10, 9), 0.0f);
}

TEST(PieceAveraging, SamplesAtThePieceAndBoxes)
{
  const Grid whole = Field(Geometry(20, 16, 12));
  const GridGeometry target = whole.Geometry.Capped(8);
  const Grid coarse = AverageExtinctionOn(whole, 2.0, target);
  const Grid piece = Cut(whole, { 6, 13, 2, 15, 0, 11 });
  const Grid atPiece = SampleAtPoints(coarse, piece.Geometry);
  const Grid atWhole = ResampleTrilinear(coarse, whole.Geometry);
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 14; ++j)
      for (int i = 0; i < 8; ++i)
        ASSERT_NEAR(atPiece.At(i, j, k), atWhole.At(i + 6, j + 2, k), 1e-5);
  EXPECT_TRUE(BoxInside(PieceBox({ 6, 2, 0 }, { 8, 14, 12 }), { 20, 16, 12 }));
  EXPECT_FALSE(BoxInside(PieceBox({ 6, 4, 0 }, { 8, 14, 12 }), { 20, 16, 12 }));
  EXPECT_FALSE(BoxInside({ 3, 2, 0, 1, 0, 1 }, { 20, 16, 12 }));
}
