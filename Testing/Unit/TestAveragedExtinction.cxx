// Summed-area table and averaged extinction against brute-force double sums on structured
// fields (a thin spherical shell, a sphere, a constant), the work counter, and precision at 256^3.
#include "AveragedExtinction.h"
#include "Random.h"
#include "SummedAreaTable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace avs;

namespace
{
GridGeometry Geometry(int nx, int ny, int nz, Vec3 spacing = { 1, 1, 1 })
{
  GridGeometry g;
  g.Dimensions = { nx, ny, nz };
  g.Spacing = spacing;
  return g;
}

// A thin spherical shell: 1 within half a voxel of radius R around the centre, else 0.
Grid Shell(const GridGeometry& g, double radiusFraction = 0.35, double value = 3.0)
{
  Grid grid(g);
  const Vec3 c{
    0.5 * (g.Dimensions[0] - 1), 0.5 * (g.Dimensions[1] - 1), 0.5 * (g.Dimensions[2] - 1)
  };
  const double r = radiusFraction * std::min({ g.Dimensions[0], g.Dimensions[1], g.Dimensions[2] });
  for (int k = 0; k < g.Dimensions[2]; ++k)
    for (int j = 0; j < g.Dimensions[1]; ++j)
      for (int i = 0; i < g.Dimensions[0]; ++i)
      {
        const double d = Length(Vec3{ double(i), double(j), double(k) } - c);
        grid.At(i, j, k) = std::abs(d - r) < 0.5 ? static_cast<float>(value) : 0.0f;
      }
  return grid;
}

double BruteBoxSum(const Grid& g, std::array<int, 3> lo, std::array<int, 3> hi)
{
  double s = 0.0;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
      {
        if (i >= 0 && j >= 0 && k >= 0 && i < g.Geometry.Dimensions[0] &&
          j < g.Geometry.Dimensions[1] && k < g.Geometry.Dimensions[2])
        {
          s += g.At(i, j, k);
        }
      }
  return s;
}

double BruteMean(const Grid& g, int i, int j, int k, const std::array<int, 3>& w)
{
  const double count = (2.0 * w[0] + 1) * (2.0 * w[1] + 1) * (2.0 * w[2] + 1);
  return BruteBoxSum(g, { i - w[0], j - w[1], k - w[2] }, { i + w[0], j + w[1], k + w[2] }) / count;
}

void ExpectRelative(double value, double truth, double tolerance, const char* what)
{
  EXPECT_LE(std::abs(value - truth), tolerance * std::abs(truth) + 1e-30)
    << what << ": " << value << " vs " << truth;
}
} // namespace

TEST(SummedAreaTable, BoxSumsEqualBruteForceOnRandomBoxesTouchingEveryBorder)
{
  const Grid shell = Shell(Geometry(23, 17, 29));
  SummedAreaTable sat(shell.Values.data(), shell.Geometry.Dimensions);
  Random rng(5);
  const auto& n = shell.Geometry.Dimensions;
  for (int trial = 0; trial < 400; ++trial)
  {
    std::array<int, 3> lo, hi;
    for (int a = 0; a < 3; ++a)
    {
      // Every box touches a border on each axis (low, high or both), or reaches beyond it.
      const int kind = static_cast<int>(rng.Uniform() * 4);
      const int x = static_cast<int>(rng.Uniform() * n[a]);
      const int y = static_cast<int>(rng.Uniform() * n[a]);
      lo[a] = kind == 0 ? 0 : (kind == 1 ? std::min(x, y) : (kind == 2 ? 0 : -3));
      hi[a] =
        kind == 0 ? std::max(x, y) : (kind == 1 ? n[a] - 1 : (kind == 2 ? n[a] - 1 : n[a] + 2));
    }
    ExpectRelative(sat.BoxSum(lo, hi), BruteBoxSum(shell, lo, hi), 1e-12, "box sum");
  }
  EXPECT_EQ(sat.BoxSum({ 5, 5, 5 }, { 4, 9, 9 }), 0.0);     // empty box
  EXPECT_EQ(sat.BoxSum({ -9, -9, -9 }, { -1, 3, 3 }), 0.0); // entirely outside
}

TEST(SummedAreaTable, SignsOfTheEightCornersAlternate)
{
  // A single non-zero voxel: each box containing it sums to its value, others to 0.
  Grid g(Geometry(6, 6, 6));
  g.At(2, 3, 4) = 1.0f;
  SummedAreaTable sat(g.Values.data(), g.Geometry.Dimensions);
  EXPECT_DOUBLE_EQ(sat.BoxSum({ 2, 3, 4 }, { 2, 3, 4 }), 1.0);
  EXPECT_DOUBLE_EQ(sat.BoxSum({ 0, 0, 0 }, { 5, 5, 5 }), 1.0);
  EXPECT_DOUBLE_EQ(sat.BoxSum({ 3, 0, 0 }, { 5, 5, 5 }), 0.0);
  EXPECT_DOUBLE_EQ(sat.BoxSum({ 0, 4, 0 }, { 5, 5, 5 }), 0.0);
  EXPECT_DOUBLE_EQ(sat.BoxSum({ 0, 0, 0 }, { 5, 5, 3 }), 0.0);
}

TEST(AveragedExtinction, HalfWidthsFollowTheEqualVolumeCube)
{
  EXPECT_NEAR(std::pow(CubeHalfSidePerRadius, 3) * 8.0, 4.0 / 3.0 * Pi, 1e-12);
  const auto w = AveragingHalfWidths(10.0, { 1.0, 2.0, 0.5 });
  EXPECT_EQ(w[0], 8);  // round(8.06)
  EXPECT_EQ(w[1], 4);  // round(4.03)
  EXPECT_EQ(w[2], 16); // round(16.12)
  EXPECT_EQ(AveragingHalfWidths(0.0, { 1, 1, 1 })[0], 0);
}

TEST(AveragedExtinction, EqualsBruteForceMeanOnAThinShell)
{
  const Grid shell = Shell(Geometry(36, 30, 33, { 1.0, 1.5, 0.8 }));
  for (double radius : { 1.0, 3.0, 6.5 })
  {
    const Grid avg = AverageExtinction(shell, radius);
    const auto w = AveragingHalfWidths(radius, shell.Geometry.Spacing);
    for (int k = 0; k < 33; ++k)
      for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 36; ++i)
        {
          ExpectRelative(avg.At(i, j, k), BruteMean(shell, i, j, k, w), 1e-5, "shell mean");
        }
  }
}

TEST(AveragedExtinction, EqualsSummedAreaTableMeanOnASphere)
{
  GridGeometry g = Geometry(40, 40, 40);
  Grid sphere(g);
  for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
        sphere.At(i, j, k) = Length(Vec3{ i - 19.5, j - 19.5, k - 19.5 }) < 12.0 ? 2.5f : 0.0f;
  SummedAreaTable sat(sphere.Values.data(), g.Dimensions);
  const std::array<int, 3> w{ 4, 4, 4 };
  const Grid avg = BoxMean(sphere, w);
  for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
      {
        const double truth = sat.BoxSum({ i - 4, j - 4, k - 4 }, { i + 4, j + 4, k + 4 }) / 729.0;
        ExpectRelative(avg.At(i, j, k), truth, 1e-5, "sphere mean");
      }
}

TEST(AveragedExtinction, FadesTowardsEmptySpaceAtTheBorder)
{
  Grid ones(Geometry(20, 20, 20), 1.0f);
  const Grid avg = BoxMean(ones, { 2, 2, 2 });
  EXPECT_NEAR(avg.At(10, 10, 10), 1.0, 1e-7);
  EXPECT_NEAR(avg.At(0, 10, 10), 3.0 / 5.0, 1e-7);
  EXPECT_NEAR(avg.At(0, 0, 0), 27.0 / 125.0, 1e-7);
  EXPECT_NEAR(avg.At(19, 1, 10), (3.0 / 5.0) * (4.0 / 5.0), 1e-7);
}

TEST(AveragedExtinction, WorkDoesNotGrowWithTheRadius)
{
  const Grid shell = Shell(Geometry(48, 40, 44));
  AveragingStatistics small, large;
  AverageExtinction(shell, 1.0, &small);
  AverageExtinction(shell, 15.0, &large);
  EXPECT_GT(small.Operations, 0u);
  EXPECT_EQ(small.Operations, large.Operations);
  // A fixed number of operations per voxel: 2 per axis pass and 1 for the division.
  EXPECT_EQ(small.Operations, 7ull * 48 * 40 * 44);
  // The brute-force mean would cost (2k + 1)^3 reads per voxel: 25^3 here.
  EXPECT_LT(large.Operations, 48ull * 40 * 44 * 25 * 25 * 25 / 1000);
}

TEST(AveragedExtinction, PrecisionAt256CubedOnConstantAndShellFields)
{
  const int n = 256;
  const GridGeometry g = Geometry(n, n, n);
  {
    const float value = 0.37f;
    Grid constant(g, value);
    const std::array<int, 3> w{ 6, 6, 6 };
    const Grid avg = BoxMean(constant, w);
    // Interior: exactly the value; border: the value times the share of the box inside.
    ExpectRelative(avg.At(128, 128, 128), value, 1e-6, "interior");
    ExpectRelative(avg.At(255, 255, 255), value * std::pow(7.0 / 13.0, 3), 1e-6, "corner");
    ExpectRelative(avg.At(3, 128, 250), value * (10.0 / 13.0) * (12.0 / 13.0), 1e-6, "edge");
    for (int k = 6; k < n - 6; k += 37)
      for (int j = 6; j < n - 6; j += 41)
        for (int i = 6; i < n - 6; i += 43)
          ExpectRelative(avg.At(i, j, k), value, 1e-6, "interior sweep");
  }
  {
    const Grid shell = Shell(g, 0.4, 1.0);
    const double radius = 5.0;
    const Grid avg = AverageExtinction(shell, radius);
    const auto w = AveragingHalfWidths(radius, g.Spacing);
    Random rng(2024);
    int nonZero = 0;
    for (int trial = 0; trial < 600; ++trial)
    {
      int i, j, k;
      if (trial < 8)
      {
        i = (trial & 1) ? n - 1 : 0;
        j = (trial & 2) ? n - 1 : 0;
        k = (trial & 4) ? n - 1 : 0;
      }
      else
      {
        // Points near the shell, where the mean is non-trivial.
        const Vec3 dir =
          Normalize(Vec3{ rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 0.5 });
        const double r = 0.4 * n + (rng.Uniform() - 0.5) * 12.0;
        i = std::clamp(static_cast<int>(127.5 + dir.x * r), 0, n - 1);
        j = std::clamp(static_cast<int>(127.5 + dir.y * r), 0, n - 1);
        k = std::clamp(static_cast<int>(127.5 + dir.z * r), 0, n - 1);
      }
      const double truth = BruteMean(shell, i, j, k, w);
      nonZero += truth > 0.0;
      ExpectRelative(avg.At(i, j, k), truth, 1e-5, "shell 256^3");
    }
    EXPECT_GT(nonZero, 400);
  }
}

// On a coarser grid over the same box (the light grid), the average is the data-grid average
// interpolated trilinearly: exact where a coarse point falls on a voxel, between the averages
// of the voxels around it elsewhere, and the plain average when the grids agree.
TEST(AveragedExtinction, OnACoarserGridInterpolatesTheDataGridAverage)
{
  const Grid shell = Shell(Geometry(33, 25, 29, { 1.0, 1.5, 0.8 }));
  const double radius = 2.5;
  const Grid full = AverageExtinction(shell, radius);
  EXPECT_EQ(AverageExtinctionOn(shell, radius, shell.Geometry).Values, full.Values);

  // 33 -> 17 and 25 -> 13 put every coarse point on a voxel (index 2i); 29 -> 11 does not.
  const GridGeometry coarse = shell.Geometry.Resampled({ 17, 13, 11 });
  const Grid averaged = AverageExtinctionOn(shell, radius, coarse);
  ASSERT_EQ(averaged.Geometry.Dimensions, coarse.Dimensions);
  for (int k = 0; k < 11; ++k)
    for (int j = 0; j < 13; ++j)
      for (int i = 0; i < 17; ++i)
      {
        // Along z the coarse point k sits at voxel 2.8 k: between 2.8 k's two neighbours.
        const double z = 2.8 * k;
        const int k0 = std::min(static_cast<int>(z), 27);
        const double f = z - k0;
        const double expected =
          (1 - f) * full.At(2 * i, 2 * j, k0) + f * full.At(2 * i, 2 * j, k0 + 1);
        ExpectRelative(averaged.At(i, j, k), expected, 1e-5, "coarse average");
      }
}
