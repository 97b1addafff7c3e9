// The core's classification (Classifier): NaN voxels are empty space and fade over one voxel;
// VTK's gradient and gradient opacity; nearest interpolation; dependent and independent
// components; binary and label-map masks; the majorant bound holds for all of them; the
// extinction key ignores colour; the path tracer sees NaN voxels as empty.
#include "Classifier.h"
#include "Extinction.h"
#include "MajorantGrid.h"
#include "PathTracer.h"
#include "Random.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
// A 6 x 4 x 4 grid, spacing (2, 1, 1), values f(i, j, k).
template<typename F>
Grid Field(F f)
{
  GridGeometry g;
  g.Dimensions = { 6, 4, 4 };
  g.Spacing = { 2.0, 1.0, 1.0 };
  Grid grid(g);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 6; ++i)
        grid.At(i, j, k) = static_cast<float>(f(i, j, k));
  return grid;
}

// Opacity rising linearly over [0, 10], colour (s / 10, 1 - s / 10, 0.5).
TransferFunction Ramp(double alpha = 0.6)
{
  TransferFunction tf;
  tf.Minimum = 0.0;
  tf.Maximum = 10.0;
  for (int i = 0; i < 101; ++i)
  {
    const float s = i / 100.0f;
    tf.Opacity.push_back(static_cast<float>(alpha * s));
    tf.Color.push_back({ s, 1.0f - s, 0.5f });
  }
  return tf;
}

VolumeScene Scene()
{
  VolumeScene scene;
  scene.Scalars = Field([](int i, int j, int k) { return 1.0 + i + 0.5 * j + 0.25 * k; });
  scene.Transfer = Ramp();
  scene.UnitDistance = 0.5;
  return scene;
}

double Sigma(const TransferFunction& tf, double s, double u)
{
  return OpacityToExtinction(tf.OpacityAt(s), u);
}

// The bound of the whole lattice holds at random points of the box.
void ExpectBoundHolds(const VolumeScene& scene)
{
  const Classifier c(scene);
  const auto& n = scene.Scalars.Geometry.Dimensions;
  const double bound = c.Bound({ 0, 0, 0 }, { n[0] - 1, n[1] - 1, n[2] - 1 });
  Random rng(11);
  for (int i = 0; i < 2000; ++i)
  {
    const Vec3 p{
      rng.Uniform() * (n[0] - 1), rng.Uniform() * (n[1] - 1), rng.Uniform() * (n[2] - 1)
    };
    EXPECT_LE(c.AtIndex(p).SigmaT, bound * (1 + 1e-9) + 1e-12);
  }
}
} // namespace

TEST(Classifier, OneComponentIsTheTransferFunction)
{
  const VolumeScene scene = Scene();
  const Classifier c(scene);
  const Vec3 p{ 2.3, 1.5, 0.5 };
  const double s = scene.Scalars.SampleIndex(p);
  EXPECT_NEAR(c.AtIndex(p).SigmaT, Sigma(scene.Transfer, s, 0.5), 1e-9);
  EXPECT_NEAR(c.AtIndex(p).Color.x, scene.Transfer.ColorAt(s).x, 1e-9);
  EXPECT_EQ(c.AtIndex({ -0.1, 1, 1 }).SigmaT, 0.0); // outside the box
  EXPECT_NEAR(c.AtVoxel(3, 2, 1).SigmaT, c.AtIndex({ 3, 2, 1 }).SigmaT, 1e-12);
  ExpectBoundHolds(scene);
}

TEST(Classifier, NaNVoxelsAreEmptyAndFadeOverOneVoxel)
{
  VolumeScene scene = Scene();
  // Voxel (2, 1, 1) was NaN: value 0 and validity 0.
  scene.Medium.Validity = Grid(scene.Scalars.Geometry, 1.0f);
  scene.Medium.Validity.At(2, 1, 1) = 0.0f;
  const double valid = scene.Scalars.At(3, 1, 1);
  scene.Scalars.At(2, 1, 1) = 0.0f;
  const Classifier c(scene);
  EXPECT_EQ(c.AtVoxel(2, 1, 1).SigmaT, 0.0);
  EXPECT_EQ(c.AtIndex({ 2, 1, 1 }).SigmaT, 0.0);
  // Halfway to the valid neighbour: that neighbour's value, half its extinction.
  EXPECT_NEAR(c.AtIndex({ 2.5, 1, 1 }).SigmaT, 0.5 * Sigma(scene.Transfer, valid, 0.5), 1e-6);
  EXPECT_NEAR(c.AtIndex({ 2.5, 1, 1 }).Color.x, scene.Transfer.ColorAt(valid).x, 1e-6);
  // Far from it, unchanged.
  EXPECT_NEAR(c.AtIndex({ 4.5, 2.5, 2.5 }).SigmaT,
    Sigma(scene.Transfer, scene.Scalars.SampleIndex({ 4.5, 2.5, 2.5 }), 0.5),
    1e-9);
  ExpectBoundHolds(scene);
}

TEST(Classifier, GradientIsVTKsCentralDifference)
{
  VolumeScene scene = Scene(); // s = 1 + i + 0.5 j + 0.25 k, spacing (2, 1, 1)
  const Classifier c(scene);
  const double mean = 4.0 / 3.0;
  // g_a = (s(x + e_a) - s(x - e_a)) / 2 * mean / h_a: (1 * mean / 2, 0.5 * mean, 0.25 * mean).
  const double expected = mean * std::sqrt(0.25 + 0.25 + 0.0625);
  EXPECT_NEAR(c.GradientMagnitudes({ 2.5, 1.5, 1.5 })[0], expected, 1e-9);
  // At a face the far sample is clamped: half the difference along x.
  const double face = mean * std::sqrt(0.0625 + 0.25 + 0.0625);
  EXPECT_NEAR(c.GradientMagnitudes({ 0.0, 1.5, 1.5 })[0], face, 1e-9);
  // Gradient opacity multiplies the extinction (a rising table over [0, 2]).
  const Vec3 p{ 2.5, 1.5, 1.5 };
  const double plain = c.AtIndex(p).SigmaT;
  scene.Medium.GradientOpacity.Minimum = 0.0;
  scene.Medium.GradientOpacity.Maximum = 2.0;
  scene.Medium.GradientOpacity.Opacity = { 0.2f, 0.4f, 0.6f, 0.8f, 1.0f };
  const Classifier withGradient(scene);
  const double factor = scene.Medium.GradientOpacity.OpacityAt(expected);
  EXPECT_NEAR(withGradient.AtIndex(p).SigmaT, factor * plain, 1e-9);
  EXPECT_LT(factor, 0.9);
  ExpectBoundHolds(scene);
}

TEST(Classifier, NearestTakesTheNearestVoxel)
{
  VolumeScene scene = Scene();
  scene.Medium.Sampling = Interpolation::Nearest;
  const Classifier c(scene);
  EXPECT_NEAR(c.AtIndex({ 2.4, 1.2, 0.6 }).SigmaT, c.AtVoxel(2, 1, 1).SigmaT, 1e-12);
  EXPECT_NEAR(c.AtIndex({ 2.6, 0.8, 1.4 }).SigmaT, c.AtVoxel(3, 1, 1).SigmaT, 1e-12);
  ExpectBoundHolds(scene);
}

TEST(Classifier, DependentComponents)
{
  VolumeScene scene = Scene();
  MediumComponent opacity;
  opacity.Values = Field([](int i, int, int) { return 10.0 - i; });
  opacity.Transfer = Ramp(0.9);
  opacity.UnitDistance = 0.25;
  scene.Medium.Components.push_back(opacity);
  scene.Medium.Mode = ComponentMode::DependentColorOpacity;
  const Classifier c(scene);
  const Vec3 p{ 1.5, 2.0, 1.0 };
  const double s0 = scene.Scalars.SampleIndex(p), s1 = opacity.Values.SampleIndex(p);
  EXPECT_NEAR(c.AtIndex(p).Color.y, scene.Transfer.ColorAt(s0).y, 1e-9);
  EXPECT_NEAR(c.AtIndex(p).SigmaT, Sigma(opacity.Transfer, s1, 0.25), 1e-9);
  ExpectBoundHolds(scene);
  // RGBA: colour straight from components 0-2 over their ranges, opacity from 3.
  scene.Medium.Components.clear();
  for (int k = 0; k < 3; ++k)
  {
    MediumComponent m;
    m.Values = Field([k](int i, int j, int) { return k == 2 ? 10.0 - i : 2.0 * j + k; });
    m.Transfer = Ramp(0.9);
    m.UnitDistance = 0.25;
    scene.Medium.Components.push_back(m);
  }
  scene.Medium.Mode = ComponentMode::DependentRGBA;
  const Classifier rgba(scene);
  EXPECT_NEAR(rgba.AtIndex(p).Color.x, scene.Scalars.SampleIndex(p) / 10.0, 1e-9);
  EXPECT_NEAR(
    rgba.AtIndex(p).Color.y, scene.Medium.Components[0].Values.SampleIndex(p) / 10.0, 1e-9);
  EXPECT_NEAR(rgba.AtIndex(p).SigmaT,
    Sigma(
      scene.Medium.Components[2].Transfer, scene.Medium.Components[2].Values.SampleIndex(p), 0.25),
    1e-9);
  ExpectBoundHolds(scene);
}

TEST(Classifier, IndependentComponentsAddTheirExtinctions)
{
  VolumeScene scene = Scene();
  scene.Medium.Mode = ComponentMode::Independent;
  scene.Medium.Weight = 0.5;
  MediumComponent second;
  second.Values = Field([](int i, int, int) { return 10.0 - i; });
  second.Transfer = Ramp(0.3);
  for (auto& color : second.Transfer.Color)
  {
    color = { 0.0f, 0.0f, 1.0f };
  }
  second.UnitDistance = 2.0;
  second.Weight = 0.8;
  scene.Medium.Components.push_back(second);
  const Classifier c(scene);
  const Vec3 p{ 3.2, 0.5, 2.5 };
  const double s0 = scene.Scalars.SampleIndex(p), s1 = second.Values.SampleIndex(p);
  const double a = 0.5 * Sigma(scene.Transfer, s0, 0.5), b = 0.8 * Sigma(second.Transfer, s1, 2.0);
  const Classified r = c.AtIndex(p);
  EXPECT_NEAR(r.SigmaT, a + b, 1e-9);
  EXPECT_NEAR(r.Color.z, (a * 0.5 + b * 1.0) / (a + b), 1e-9);
  EXPECT_NEAR(r.Color.x, a * scene.Transfer.ColorAt(s0).x / (a + b), 1e-9);
  ExpectBoundHolds(scene);
}

TEST(Classifier, Masks)
{
  VolumeScene scene = Scene();
  scene.Medium.Mask = MaskType::Binary;
  scene.Medium.MaskValues = Field([](int i, int, int) { return i < 3 ? 1.0 : 0.0; });
  const Classifier binary(scene);
  EXPECT_GT(binary.AtIndex({ 2.4, 1, 1 }).SigmaT, 0.0);
  EXPECT_EQ(binary.AtIndex({ 2.6, 1, 1 }).SigmaT, 0.0); // the nearest mask voxel is 0
  ExpectBoundHolds(scene);
  // Label map: label 1 (i < 3) takes label 1's functions, label 2 (i >= 3) has none: component
  // 0's. Blend 1: the label's medium; 0.5: the mixture.
  scene.Medium.Mask = MaskType::LabelMap;
  scene.Medium.MaskValues = Field([](int i, int, int) { return i < 3 ? 1.0 : 2.0; });
  TransferFunction red = Ramp(0.95);
  for (auto& color : red.Color)
  {
    color = { 1.0f, 0.0f, 0.0f };
  }
  scene.Medium.Labels = { red };
  const Vec3 p{ 1.5, 1.5, 1.5 }, q{ 4.5, 1.5, 1.5 };
  const double s = scene.Scalars.SampleIndex(p);
  const Classifier full(scene);
  EXPECT_NEAR(full.AtIndex(p).SigmaT, Sigma(red, s, 0.5), 1e-9);
  EXPECT_NEAR(full.AtIndex(p).Color.x, 1.0, 1e-12);
  EXPECT_NEAR(
    full.AtIndex(q).SigmaT, Sigma(scene.Transfer, scene.Scalars.SampleIndex(q), 0.5), 1e-9);
  ExpectBoundHolds(scene);
  scene.Medium.MaskBlendFactor = 0.5;
  const Classifier half(scene);
  const double s0 = Sigma(scene.Transfer, s, 0.5), sl = Sigma(red, s, 0.5);
  EXPECT_NEAR(half.AtIndex(p).SigmaT, 0.5 * (s0 + sl), 1e-9);
  EXPECT_NEAR(half.AtIndex(p).Color.x, (s0 * scene.Transfer.ColorAt(s).x + sl) / (s0 + sl), 1e-9);
  scene.Medium.MaskBlendFactor = 0.0;
  const Classifier none(scene);
  EXPECT_NEAR(none.AtIndex(p).SigmaT, s0, 1e-9);
}

TEST(Classifier, ExtinctionKeyIgnoresColour)
{
  VolumeScene scene = Scene();
  const auto key = ExtinctionKey(scene);
  scene.Transfer.Color[3] = { 0.1f, 0.2f, 0.3f };
  EXPECT_EQ(ExtinctionKey(scene), key);
  scene.Transfer.Opacity[3] = 0.9f;
  EXPECT_NE(ExtinctionKey(scene), key);
  scene = Scene();
  scene.Medium.Sampling = Interpolation::Nearest;
  EXPECT_NE(ExtinctionKey(scene), key);
}

TEST(Classifier, PathTracerSeesNaNVoxelsAsEmpty)
{
  // A dense 11^3 cube whose half x > 5 is NaN: a ray through that half alone is unattenuated,
  // one through the other half is not; the majorants bound the medium.
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { 11, 11, 11 };
  scene.Scalars = Grid(g, 1.0f);
  scene.Transfer = TransferFunction::Constant(0.5, { 1, 1, 1 });
  scene.Medium.Validity = Grid(g, 1.0f);
  for (int k = 0; k < 11; ++k)
    for (int j = 0; j < 11; ++j)
      for (int i = 6; i < 11; ++i)
      {
        scene.Medium.Validity.At(i, j, k) = 0.0f;
        scene.Scalars.At(i, j, k) = 0.0f;
      }
  const MajorantGrid majorants(Classifier(scene), g, 4);
  const VolumeTracker tracker(scene, majorants);
  Random rng(7);
  PathTracerStatistics stats;
  double empty = 0.0, dense = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    empty += tracker.Transmittance({ 8.0, 5.0, -1.0 }, { 0, 0, 1 }, 20.0, rng, stats);
    dense += tracker.Transmittance({ 2.0, 5.0, -1.0 }, { 0, 0, 1 }, 20.0, rng, stats);
  }
  EXPECT_NEAR(empty / 2000, 1.0, 1e-12);
  EXPECT_NEAR(dense / 2000, std::exp(-OpacityToExtinction(0.5, 1.0) * 10.0), 0.01);
}
