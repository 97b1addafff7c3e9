// The path-traced refinement's picture (Refinement.h): ambient scattering below 16 samples; the
// path tracer's mean where the ambient picture is biased and the mean is certain; the ambient
// picture kept where it is right; on structured scenes of smooth truth, smooth bias and noisy
// samples, never worse than the ambient picture or the mean alone, and converging to the truth.
#include "Random.h"
#include "Refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

using namespace avs;

namespace
{
double Gaussian(Random& random)
{
  const double u = std::max(random.Uniform(), 1e-300);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.14159265358979 * random.Uniform());
}

struct Scene
{
  int Width = 48, Height = 40;
  std::vector<float> Truth, Ambient;
};

// A smooth truth and an ambient picture off by a smooth bias of amplitude `bias`.
Scene MakeScene(double bias)
{
  Scene s;
  const std::size_t n = 4 * static_cast<std::size_t>(s.Width) * s.Height;
  s.Truth.resize(n);
  s.Ambient.resize(n);
  for (int y = 0; y < s.Height; ++y)
    for (int x = 0; x < s.Width; ++x)
      for (int c = 0; c < 4; ++c)
      {
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * s.Width + x) + c;
        // Radiance in the colour channels, a nearly opaque alpha (so that the variance's floor,
        // a mean of hits and misses, is below the samples' own).
        const double t = c < 3 ? 0.4 + 0.3 * std::sin(0.2 * x + c) * std::cos(0.15 * y)
                               : 0.9 + 0.05 * std::sin(0.1 * x) * std::cos(0.2 * y);
        s.Truth[i] = static_cast<float>(t);
        s.Ambient[i] = static_cast<float>(t + bias * std::sin(0.1 * x + 0.13 * y + c));
      }
  return s;
}

// The buffers after `n` samples of the truth plus noise of standard deviation `sigma`.
RefinementBuffers Sampled(const Scene& s, int n, double sigma, Random& random)
{
  RefinementBuffers b;
  b.Width = s.Width;
  b.Height = s.Height;
  b.Samples = n;
  b.Ambient = s.Ambient;
  b.Mean.assign(s.Truth.size(), 0.0f);
  b.MeanOfSquares.assign(s.Truth.size(), 0.0f);
  for (std::size_t i = 0; i < s.Truth.size(); ++i)
  {
    double sum = 0.0, squares = 0.0;
    for (int k = 0; k < n; ++k)
    {
      const double v = s.Truth[i] + sigma * Gaussian(random);
      sum += v;
      squares += v * v;
    }
    b.Mean[i] = static_cast<float>(n > 0 ? sum / n : 0.0);
    b.MeanOfSquares[i] = static_cast<float>(n > 0 ? squares / n : 0.0);
  }
  return b;
}

double MeanSquaredError(const std::vector<float>& a, const std::vector<float>& b)
{
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    e += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  }
  return e / static_cast<double>(a.size());
}
} // namespace

TEST(Refinement, BelowSixteenSamplesTheAmbientPictureIsShown)
{
  Random random(1);
  const Scene s = MakeScene(0.1);
  for (int n : { 0, 1, 2, 3, 8, 15 })
  {
    const RefinementBuffers b = Sampled(s, n, 0.2, random);
    EXPECT_EQ(RefinedPicture(b), s.Ambient) << n;
  }
}

TEST(Refinement, ACertainMeanReplacesABiasedPicture)
{
  Random random(2);
  const Scene s = MakeScene(0.1);
  // No noise and many samples: the mean is the truth, and certain.
  const RefinementBuffers b = Sampled(s, 4096, 0.0, random);
  EXPECT_LT(
    MeanSquaredError(RefinedPicture(b), s.Truth), 1e-3 * MeanSquaredError(s.Ambient, s.Truth));
}

TEST(Refinement, SamplesThatMissedARareEventDoNotEraseTheAmbientPicture)
{
  // A thin wisp in one pixel: A says 5 % of its paths meet it; its 16 paths all missed (no
  // variance to show), as they do 44 % of the time.
  RefinementBuffers b;
  b.Width = 9;
  b.Height = 7;
  b.Samples = 16;
  const std::size_t n = 4 * static_cast<std::size_t>(b.Width) * b.Height;
  b.Ambient.assign(n, 0.0f);
  b.Mean.assign(n, 0.0f);
  b.MeanOfSquares.assign(n, 0.0f);
  const std::size_t wisp = 4 * (3 * static_cast<std::size_t>(b.Width) + 4);
  const float thin[4] = { 0.02f, 0.03f, 0.04f, 0.05f };
  std::copy(thin, thin + 4, b.Ambient.begin() + static_cast<std::ptrdiff_t>(wisp));
  EXPECT_EQ(RefinedPicture(b), b.Ambient);
  // After 4096 misses the wisp is not there: the picture follows the samples.
  b.Samples = 4096;
  EXPECT_LT(RefinedPicture(b)[wisp + 3], 0.01f);
}

TEST(Refinement, TheWeightsAreInZeroOneAndScaleFree)
{
  Random random(3);
  const Scene s = MakeScene(0.05);
  RefinementBuffers b = Sampled(s, 8, 0.3, random);
  RefinementBuffers scaled = b;
  for (std::size_t i = 0; i < b.Mean.size(); ++i)
  {
    scaled.Ambient[i] *= 4.0f;
    scaled.Mean[i] *= 4.0f;
    scaled.MeanOfSquares[i] *= 16.0f;
  }
  for (int y = 0; y < b.Height; y += 3)
    for (int x = 0; x < b.Width; x += 3)
    {
      const RefinementBands w = RefinementWeights(b, x, y);
      const RefinementBands v = RefinementWeights(scaled, x, y);
      for (const double weight : { w.Smooth, w.Detail })
      {
        EXPECT_GE(weight, 0.0);
        EXPECT_LE(weight, 1.0);
      }
      EXPECT_NEAR(v.Smooth, w.Smooth, 1e-5);
      EXPECT_NEAR(v.Detail, w.Detail, 1e-5);
    }
  // A picture of one pixel: the window is clamped to it.
  RefinementBuffers one;
  one.Width = one.Height = 1;
  one.Samples = 1 << 20;
  one.Ambient = { 0.5f, 0.5f, 0.5f, 1.0f };
  one.Mean = { 0.7f, 0.7f, 0.7f, 1.0f };
  one.MeanOfSquares = { 0.49f, 0.49f, 0.49f, 1.0f }; // no variance
  EXPECT_NEAR(RefinedPicture(one)[0], 0.7f, 1e-6);
}

TEST(Refinement, NeverWorseThanEitherAndConvergesToTheTruth)
{
  Random random(4);
  for (const double bias : { 0.0, 0.01, 0.05, 0.2 })
  {
    const Scene s = MakeScene(bias);
    const double ambient = MeanSquaredError(s.Ambient, s.Truth);
    double last = 1e30;
    for (const int n : { 16, 32, 64, 256 })
    {
      const RefinementBuffers b = Sampled(s, n, 0.5, random);
      const double mean = MeanSquaredError(b.Mean, s.Truth);
      const double picture = MeanSquaredError(RefinedPicture(b), s.Truth);
      // (A margin for the weights' own noise: where A is right, the smooth band still lets in
      // a little of its noise, v / 25, in a few windows.)
      EXPECT_LE(picture, 1.1 * ambient + 0.01 * mean) << "bias " << bias << ", " << n << " samples";
      EXPECT_LE(picture, 1.1 * mean) << "bias " << bias << ", " << n << " samples";
      if (bias > 0.0)
      {
        EXPECT_LT(picture, 1.05 * last) << "bias " << bias << ", " << n << " samples";
      }
      last = picture;
    }
    if (bias == 0.0)
    {
      EXPECT_LT(last, 0.01 * 0.25 / 256) << "a right ambient picture is kept";
    }
  }
  // Where the samples are less noisy than the bias is large, the picture follows the mean.
  const Scene s = MakeScene(0.2);
  const RefinementBuffers b = Sampled(s, 256, 0.2, random);
  EXPECT_LT(
    MeanSquaredError(RefinedPicture(b), s.Truth), 0.01 * MeanSquaredError(s.Ambient, s.Truth));
}
