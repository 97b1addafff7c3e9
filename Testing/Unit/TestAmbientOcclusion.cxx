// Local ambient occlusion: direction set, empty space, a homogeneous medium's analytic value,
// occlusion grows with density and depth.
#include "AmbientOcclusion.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

TEST(AmbientOcclusion, DirectionsAreUnitAndWellSpread)
{
  const auto dirs = SphereDirections(32);
  ASSERT_EQ(dirs.size(), 32u);
  Vec3 mean{ 0, 0, 0 };
  double closest = 2.0;
  for (std::size_t a = 0; a < dirs.size(); ++a)
  {
    EXPECT_NEAR(Length(dirs[a]), 1.0, 1e-12);
    mean = mean + dirs[a];
    for (std::size_t b = a + 1; b < dirs.size(); ++b)
    {
      closest = std::min(closest, Length(dirs[a] - dirs[b]));
    }
  }
  EXPECT_LT(Length(mean) / 32.0, 0.05);
  EXPECT_GT(closest, 0.3); // no two directions bunch up
}

TEST(AmbientOcclusion, EmptySpaceIsUnoccluded)
{
  GridGeometry g;
  g.Dimensions = { 10, 10, 10 };
  const Grid ao = ComputeAmbientOcclusion(Grid(g, 0.0f), g, 3.0, 14);
  for (float v : ao.Values)
  {
    ASSERT_FLOAT_EQ(v, 1.0f);
  }
}

TEST(AmbientOcclusion, HomogeneousInteriorMatchesTheAnalyticValue)
{
  GridGeometry g;
  g.Dimensions = { 21, 21, 21 };
  const double sigma = 0.2, radius = 4.0;
  const Grid ao = ComputeAmbientOcclusion(Grid(g, static_cast<float>(sigma)), g, radius, 32);
  // Far from the border every direction sees sigma * R.
  EXPECT_NEAR(ao.At(10, 10, 10), std::exp(-sigma * radius), 1e-5);
  // At a face half the directions leave the volume early: less occluded.
  EXPECT_GT(ao.At(0, 10, 10), ao.At(10, 10, 10) + 0.1);
  // At a corner even less.
  EXPECT_GT(ao.At(0, 0, 0), ao.At(0, 10, 10));
}

TEST(AmbientOcclusion, DenserMediumOccludesMore)
{
  GridGeometry g;
  g.Dimensions = { 15, 15, 15 };
  OcclusionStatistics stats;
  const Grid thin = ComputeAmbientOcclusion(Grid(g, 0.05f), g, 3.0, 20, 0.5, &stats);
  const Grid dense = ComputeAmbientOcclusion(Grid(g, 0.5f), g, 3.0, 20, 0.5);
  EXPECT_GT(thin.At(7, 7, 7), dense.At(7, 7, 7));
  // 20 directions, 6 midpoint samples each, per voxel.
  EXPECT_EQ(stats.Samples, 15ull * 15 * 15 * 20 * 6);
}
