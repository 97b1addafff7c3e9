// Henyey–Greenstein: normalisation, sampler against pdf (chi-square), mean cosine, robustness.
#include "PhaseFunction.h"
#include "Random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace avs;

namespace
{
// 2 pi * integral over mu in [a, b] of p_g(mu), by composite Simpson.
double IntegrateMu(double g, double a, double b, int n = 20000)
{
  const double h = (b - a) / n;
  double s = HenyeyGreenstein(a, g) + HenyeyGreenstein(b, g);
  for (int i = 1; i < n; ++i)
  {
    s += (i % 2 ? 4.0 : 2.0) * HenyeyGreenstein(a + i * h, g);
  }
  return 2.0 * Pi * s * h / 3.0;
}
const double Anisotropies[] = { -0.9, -0.5, 0.0, 0.5, 0.9 };
} // namespace

TEST(PhaseFunction, IntegratesToOneOverTheSphere)
{
  for (double g : Anisotropies)
  {
    EXPECT_NEAR(IntegrateMu(g, -1.0, 1.0), 1.0, 1e-6) << "g = " << g;
  }
}

TEST(PhaseFunction, ConventionForwardPeakForPositiveG)
{
  // mu = 1 is "straight on": positive g scatters forwards.
  EXPECT_GT(HenyeyGreenstein(1.0, 0.8), HenyeyGreenstein(-1.0, 0.8));
  EXPECT_LT(HenyeyGreenstein(1.0, -0.8), HenyeyGreenstein(-1.0, -0.8));
  EXPECT_NEAR(HenyeyGreenstein(0.3, 0.0), 1.0 / (4.0 * Pi), 1e-15);
}

TEST(PhaseFunction, SamplerHistogramMatchesPdfChiSquare)
{
  const int bins = 40;
  const int n = 400000;
  for (double g : Anisotropies)
  {
    Random rng(12345);
    std::vector<int> count(bins, 0);
    for (int i = 0; i < n; ++i)
    {
      const double mu = SampleHenyeyGreensteinCosine(rng.Uniform(), g);
      const int b = std::min(bins - 1, static_cast<int>((mu + 1.0) * 0.5 * bins));
      ++count[b];
    }
    double chi2 = 0.0;
    int dof = 0;
    for (int b = 0; b < bins; ++b)
    {
      const double lo = -1.0 + 2.0 * b / bins, hi = -1.0 + 2.0 * (b + 1) / bins;
      const double expected = n * IntegrateMu(g, lo, hi, 200);
      if (expected < 5.0)
      {
        continue;
      }
      chi2 += (count[b] - expected) * (count[b] - expected) / expected;
      ++dof;
    }
    // 99.9 % quantile of chi-square with ~39 degrees of freedom is about 72.
    EXPECT_LT(chi2, 72.0) << "g = " << g << ", dof " << dof;
  }
}

TEST(PhaseFunction, MeanCosineEqualsG)
{
  const int n = 400000;
  for (double g : Anisotropies)
  {
    Random rng(777);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i)
    {
      const double mu = SampleHenyeyGreensteinCosine(rng.Uniform(), g);
      sum += mu;
      sum2 += mu * mu;
    }
    const double mean = sum / n;
    const double se = std::sqrt((sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, g, 5.0 * se + 1e-4) << "g = " << g;
  }
}

TEST(PhaseFunction, SampledDirectionsFollowTheIncomingDirection)
{
  Random rng(99);
  const Vec3 incoming = Normalize(Vec3{ 0.3, -0.5, 0.8 });
  double sum = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i)
  {
    const PhaseSample s = SampleHenyeyGreenstein(incoming, 0.7, rng.Uniform(), rng.Uniform());
    ASSERT_NEAR(Length(s.Direction), 1.0, 1e-9);
    ASSERT_NEAR(Dot(s.Direction, incoming), s.Mu, 1e-9);
    ASSERT_DOUBLE_EQ(s.Pdf, HenyeyGreenstein(s.Mu, 0.7));
    ASSERT_DOUBLE_EQ(HenyeyGreensteinPdf(s.Mu, 0.7), s.Pdf);
    sum += Dot(s.Direction, incoming);
  }
  EXPECT_NEAR(sum / n, 0.7, 0.005);
}

TEST(PhaseFunction, NoNaNAtTheLimits)
{
  const double eps = std::nextafter(1.0, 0.0);
  for (double g : { -0.95, 0.95, -1.0, 1.0, -5.0, 5.0, 1e-9, -1e-9 })
  {
    for (double u : { 0.0, 1e-300, 0.5, eps, 1.0 })
    {
      const double mu = SampleHenyeyGreensteinCosine(u, g);
      EXPECT_TRUE(std::isfinite(mu)) << g << " " << u;
      EXPECT_GE(mu, -1.0);
      EXPECT_LE(mu, 1.0);
      const double p = HenyeyGreenstein(mu, g);
      EXPECT_TRUE(std::isfinite(p));
      EXPECT_GT(p, 0.0);
    }
  }
  // |g| beyond 0.95 is clamped to 0.95.
  EXPECT_DOUBLE_EQ(HenyeyGreenstein(1.0, 5.0), HenyeyGreenstein(1.0, 0.95));
  EXPECT_DOUBLE_EQ(ClampAnisotropy(std::nan("")), 0.0);
}
