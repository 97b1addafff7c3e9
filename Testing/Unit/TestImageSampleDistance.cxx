// The image sample distance chosen from the allotted frame time: still frames at the minimum,
// over-budget frames coarser at once, refinement by halves, steps of 0.5, the clamps, and that
// a simulated interaction settles on the finest distance that fits the budget.
#include "ImageSampleDistance.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
FrameBudget Budget(double allocated, double secondsPerRay, double previous)
{
  FrameBudget b;
  b.AllocatedSeconds = allocated;
  b.SecondsPerRay = secondsPerRay;
  b.Pixels = 512.0 * 512.0;
  b.Previous = previous;
  return b;
}
// Seconds per ray for which a full-resolution 512^2 frame takes `seconds`.
double PerRay(double seconds)
{
  return seconds / (512.0 * 512.0);
}
} // namespace

TEST(ImageSampleDistance, StillFramesRenderAtTheMinimum)
{
  // VTK's still frames get 1 / (0.0001 renderers) seconds.
  for (double previous : { 1.0, 2.5, 4.0, 10.0 })
  {
    EXPECT_EQ(ChooseImageSampleDistance(Budget(10000.0, PerRay(3.0), previous)), 1.0);
  }
  FrameBudget b = Budget(10000.0, PerRay(3.0), 6.0);
  b.Minimum = 2.0;
  EXPECT_EQ(ChooseImageSampleDistance(b), 2.0);
}

TEST(ImageSampleDistance, OverBudgetGoesCoarserAtOnce)
{
  // A 1 s frame in 1/15 s: sqrt(15) = 3.87 pixels per ray, rounded up to 4.
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, PerRay(1.0), 1.0)), 4.0);
  // 4 s in 1/15 s: 7.75 -> 8.
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, PerRay(4.0), 2.0)), 8.0);
}

TEST(ImageSampleDistance, UnderBudgetRefinesByHalves)
{
  // A full-resolution frame fits exactly (fit 1), previous 4: factor (1 + 1/4) / 2, distance
  // 1.6, stepped to 2; then (1 + 1/2) / 2 -> 1.33 -> 1.5; then (1 + 1/1.5) / 2 -> 1.2 -> 1.5:
  // within one step of the fit, where it stays.
  const double fits = PerRay(1.0 / 15.0);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, fits, 4.0)), 2.0);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, fits, 2.0)), 1.5);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, fits, 1.5)), 1.5);
  // Well under budget (a tenth of it), from 2: (3.16 + 0.5) / 2 -> 0.55 -> 1.
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, fits / 10.0, 2.0)), 1.0);
}

TEST(ImageSampleDistance, StepsAndClamps)
{
  for (double seconds : { 0.3, 0.7, 1.3, 2.9, 5.0, 11.0 })
  {
    const double d = ChooseImageSampleDistance(Budget(1.0 / 15.0, PerRay(seconds), 1.0));
    EXPECT_EQ(std::fmod(d, ImageSampleDistanceStep), 0.0) << d;
    EXPECT_GE(d, 1.0);
    EXPECT_LE(d, 10.0);
  }
  // 100 s in 1/15 s would need 39 pixels per ray: the maximum.
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, PerRay(100.0), 1.0)), 10.0);
  FrameBudget b = Budget(1.0 / 15.0, PerRay(100.0), 1.0);
  b.Maximum = 3.0;
  EXPECT_EQ(ChooseImageSampleDistance(b), 3.0);
  // A minimum above the maximum wins (no undefined clamp).
  b.Minimum = 5.0;
  EXPECT_EQ(ChooseImageSampleDistance(b), 5.0);
  // Supersampling: a minimum below 1 lets still frames cast more rays than pixels.
  b = Budget(10000.0, PerRay(1.0), 1.0);
  b.Minimum = 0.5;
  EXPECT_EQ(ChooseImageSampleDistance(b), 0.5);
}

TEST(ImageSampleDistance, WithoutMeasurementKeepsThePrevious)
{
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, 0.0, 3.0)), 3.0);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(0.0, PerRay(1.0), 3.0)), 3.0);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, NAN, 3.0)), 3.0);
  EXPECT_EQ(ChooseImageSampleDistance(Budget(1.0 / 15.0, 0.0, 20.0)), 10.0); // clamped
}

TEST(ImageSampleDistance, SimulatedInteractionSettlesWithinBudget)
{
  // A frame costs a fixed 5 ms plus its rays, 1.2 s at full resolution; each frame measures the
  // seconds per ray of the one before, as the mapper does. Coming from a still frame (which
  // measured 1.2 s), the interaction settles at once on the finest distance that fits (4.5; 4
  // would take 80 ms). Coming from the coarsest distance, it refines to within one step of it.
  const double fixed = 0.005, perRay = PerRay(1.2), allocated = 1.0 / 15.0;
  auto cost = [&](double d) { return fixed + std::pow(std::ceil(512.0 / d), 2) * perRay; };
  for (double start : { 1.0, 10.0 })
  {
    double d = start, measured = perRay;
    for (int frame = 0; frame < 12; ++frame)
    {
      d = ChooseImageSampleDistance(Budget(allocated, measured, d));
      measured = cost(d) / std::pow(std::ceil(512.0 / d), 2);
    }
    EXPECT_LE(cost(d), allocated) << "from " << start;
    EXPECT_GT(cost(d - (start == 1.0 ? 1.0 : 2.0) * ImageSampleDistanceStep), allocated)
      << "from " << start << ": " << d;
  }
  EXPECT_GT(cost(4.0), allocated);
}

TEST(ImageSampleDistance, SampledSize)
{
  EXPECT_EQ(SampledSize(512, 1.0), 512);
  EXPECT_EQ(SampledSize(512, 2.0), 256);
  EXPECT_EQ(SampledSize(512, 3.0), 171);
  EXPECT_EQ(SampledSize(120, 3.0), 40);
  EXPECT_EQ(SampledSize(512, 0.5), 1024);
  EXPECT_EQ(SampledSize(5, 10.0), 1);
  EXPECT_EQ(SampledSize(7, 0.0), 7);
}
