// Opacity to extinction: a slab of thickness u has opacity alpha (VTK's convention).
#include "Extinction.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

TEST(Extinction, SlabOfUnitThicknessHasTheTransferFunctionOpacity)
{
  for (double u : { 0.01, 0.5, 1.0, 7.0 })
  {
    for (double alpha : { 0.0, 1e-6, 0.1, 0.5, 0.9, 0.999 })
    {
      const double sigma = OpacityToExtinction(alpha, u);
      EXPECT_NEAR(ExtinctionToOpacity(sigma, u), alpha, 1e-12) << alpha << " " << u;
      // Two slabs of thickness u: 1 - (1 - alpha)^2 (VTK's opacity correction).
      EXPECT_NEAR(ExtinctionToOpacity(sigma, 2 * u), 1 - (1 - alpha) * (1 - alpha), 1e-12);
    }
  }
}

TEST(Extinction, ScalesInverselyWithUnitDistance)
{
  EXPECT_NEAR(OpacityToExtinction(0.5, 2.0), 0.5 * OpacityToExtinction(0.5, 1.0), 1e-15);
  EXPECT_NEAR(OpacityToExtinction(0.5, 1.0), std::log(2.0), 1e-15);
}

TEST(Extinction, OpaqueAndInvalidValuesStayFinite)
{
  EXPECT_NEAR(OpacityToExtinction(1.0, 1.0), -std::log(1e-6), 1e-6);
  EXPECT_TRUE(std::isfinite(OpacityToExtinction(2.0, 1.0)));
  EXPECT_EQ(OpacityToExtinction(-0.5, 1.0), 0.0);
  EXPECT_EQ(OpacityToExtinction(std::nan(""), 1.0), 0.0);
  EXPECT_EQ(OpacityToExtinction(0.5, 0.0), 0.0);
  EXPECT_EQ(OpacityToExtinction(0.5, -1.0), 0.0);
}
