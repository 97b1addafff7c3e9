// Tube-marched light volumes: the albedo-0 limit is a shadow ray with step 2r, a light volume
// holds the tube transmittance where the light enters the ball around each point, empty space
// lets everything through, a slab casts its shadow, point lights inside and outside the box, the
// light behind a dense surface does not depend on the empty space before it (no bands); the
// extended model's positional lights take the direct beam, a shadow ray whatever the albedo.
#include "AveragedExtinction.h"
#include "LightVolume.h"
#include "ScatteringTable.h"

#include "ShippedTable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace avs;

namespace
{
GridGeometry Box(int n, double spacing = 1.0)
{
  GridGeometry g;
  g.Dimensions = { n, n, n };
  g.Spacing = { spacing, spacing, spacing };
  return g;
}

// A thin shell of extinction (structured input).
Grid ShellExtinction(const GridGeometry& g, double sigma)
{
  Grid grid(g);
  const double c = 0.5 * (g.Dimensions[0] - 1);
  for (int k = 0; k < g.Dimensions[2]; ++k)
    for (int j = 0; j < g.Dimensions[1]; ++j)
      for (int i = 0; i < g.Dimensions[0]; ++i)
      {
        const double d = Length(Vec3{ i - c, j - c, k - c });
        grid.At(i, j, k) =
          std::abs(d - 0.3 * g.Dimensions[0]) < 1.5 ? static_cast<float>(sigma) : 0.0f;
      }
  return grid;
}

// Independent shadow ray over the averaged extinction with step 2r, written from ALGORITHM.md
// section 5 with exp(-2 tau) in place of F, the tube counted back from x (LightVolume.h): n
// whole steps centred at x - (2i + 1) r d, the rest (2 r eta) centred at x0 + eta r d.
double ShadowRay(const Grid& averaged, const Vec3& x0, const Vec3& x, double r)
{
  const double D = Length(x - x0);
  if (D == 0.0)
  {
    return 1.0;
  }
  const Vec3 d = (x - x0) * (1.0 / D);
  const int n = static_cast<int>(std::floor(D / (2 * r)));
  const double eta = D / (2 * r) - n;
  double opticalDepth = 0.0;
  for (int i = 0; i < n; ++i)
  {
    opticalDepth += 2.0 * r * averaged.SampleWorld(x - d * ((2 * i + 1) * r));
  }
  const double rest = std::exp(-2.0 * r * averaged.SampleWorld(x0 + d * (eta * r)));
  return std::exp(-opticalDepth) * ((1 - eta) + eta * rest);
}

// The point r before x on the straight path x0 -> x (x0 when x is nearer than r).
Vec3 BallEntry(const Vec3& x0, const Vec3& x, double r)
{
  const double D = Length(x - x0);
  return D > r ? x0 + (x - x0) * ((D - r) / D) : x0;
}
} // namespace

TEST(LightVolume, AlbedoZeroIsAShadowRayWithStepTwoR)
{
  const GridGeometry g = Box(24);
  const Grid averaged = AverageExtinction(ShellExtinction(g, 0.4), 2.0);
  const ScatteringSlice slice = Shipped().Slice(0.5, 0.0);
  const double r = 1.3;
  // Directional light propagating along +x (enters at x = 0).
  const Light sun = Light::Directional({ 1, 0, 0 }, { 1, 1, 1 });
  const Grid lv = ComputeLightVolume(averaged, g, sun, slice, r);
  // Point light inside the box.
  const Vec3 p{ 11.5, 10.2, 12.7 };
  const Light lamp = Light::Point(p, { 1, 1, 1 });
  const Grid lp = ComputeLightVolume(averaged, g, lamp, slice, r);
  for (int k = 0; k < 24; k += 3)
    for (int j = 0; j < 24; j += 2)
      for (int i = 0; i < 24; ++i)
      {
        const Vec3 x{ double(i), double(j), double(k) };
        const Vec3 x0{ 0.0, x.y, x.z };
        // At the point itself (T of ALGORITHM section 5) ...
        EXPECT_NEAR(
          TubeTransmittance(averaged, sun, slice, r, x), ShadowRay(averaged, x0, x, r), 1e-6);
        EXPECT_NEAR(
          TubeTransmittance(averaged, lamp, slice, r, x), ShadowRay(averaged, p, x, r), 1e-6);
        // ... and, in the light volume, where the light enters the ball of radius r around it.
        EXPECT_NEAR(lv.At(i, j, k), ShadowRay(averaged, x0, BallEntry(x0, x, r), r), 1e-6);
        EXPECT_NEAR(lp.At(i, j, k), ShadowRay(averaged, p, BallEntry(p, x, r), r), 1e-6);
      }
}

TEST(LightVolume, HoldsTheTransmittanceWhereTheLightEntersTheBall)
{
  // A slab in front of the points, lit along +z, with scattering (F above exp(-2 tau)).
  const GridGeometry g = Box(20);
  Grid ext(g);
  for (int k = 3; k <= 8; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
        ext.At(i, j, k) = 0.3f;
  const double r = 1.5;
  const Grid averaged = AverageExtinction(ext, r);
  const ScatteringSlice slice = Shipped().Slice(0.6, 0.9);
  const Light sun = Light::Directional({ 0, 0, 1 }, { 1, 1, 1 });
  const Grid lv = ComputeLightVolume(averaged, g, sun, slice, r);
  for (int k = 0; k < 20; ++k)
  {
    const double entry = std::max(0.0, k - r);
    EXPECT_NEAR(
      lv.At(10, 10, k), TubeTransmittance(averaged, sun, slice, r, { 10, 10, entry }), 1e-6);
    EXPECT_NEAR(lv.At(10, 10, k),
      BallEntryTransmittance(averaged, sun, slice, r, { 10.0, 10.0, double(k) }),
      1e-6);
  }
  // Inside and behind the slab, the ball's light is what reaches its near side, more than what
  // reaches its centre.
  EXPECT_GT(lv.At(10, 10, 8), TubeTransmittance(averaged, sun, slice, r, { 10, 10, 8 }) + 0.01);
  // Points within r of where the light enters the box are unshadowed.
  EXPECT_NEAR(lv.At(10, 10, 1), 1.0, 1e-9);
}

TEST(LightVolume, LightBehindADenseSurfaceDoesNotDependOnTheEmptySpaceBeforeIt)
{
  // A dense fog sphere (a level set turned fog volume: 0 outside, rising to 1 over 2 voxels
  // inside; sigma_t up to 2.3, opacity 0.9 per voxel) with 4 empty voxels before it, and the
  // same with 1 or 2 empty voxels more on the side the light comes from. Empty space passes all
  // light, so the light volume at the same point of the medium must not change. A tube counted
  // from where the light enters the box (balls at x0 + (2i + 1) r d) moves its balls against the
  // surface with that distance mod 2r, and T behind the surface with them: zebra bands of
  // period 2r on dense surfaces.
  const double r = 1.3, sigma = 2.3;
  const ScatteringSlice slice = Shipped().Slice(0.0, 0.9);
  auto lightVolume = [&](int pad, const Light& light)
  {
    GridGeometry g;
    g.Dimensions = { 28 + pad, 28, 28 };
    Grid ext(g);
    for (int k = 0; k < 28; ++k)
      for (int j = 0; j < 28; ++j)
        for (int i = 0; i < 28; ++i)
        {
          const double depth = 9.5 - Length(Vec3{ i - 13.5, j - 13.5, k - 13.5 });
          ext.At(i + pad, j, k) = static_cast<float>(sigma * std::clamp(depth / 2.0, 0.0, 1.0));
        }
    return ComputeLightVolume(AverageExtinction(ext, r), g, light, slice, r);
  };
  const Light sun = Light::Directional({ 1, 0.3, -0.2 }, { 1, 1, 1 });
  const Light lamp = Light::Point({ -30, 12, 15 }, { 1, 1, 1 });
  for (const Light& light : { sun, lamp })
  {
    const Grid reference = lightVolume(0, light);
    for (int pad : { 1, 2 })
    {
      // The point light moves with the medium (a directional light's position and focal point
      // would both have to).
      Light moved = light;
      moved.Position = moved.Position + Vec3{ double(pad), 0, 0 };
      moved.FocalPoint = moved.FocalPoint + Vec3{ double(pad), 0, 0 };
      const Grid padded = lightVolume(pad, moved);
      double largest = 0.0;
      for (int k = 0; k < 28; ++k)
        for (int j = 0; j < 28; ++j)
          for (int i = 0; i < 28; ++i)
          {
            largest =
              std::max(largest, std::abs(double(padded.At(i + pad, j, k)) - reference.At(i, j, k)));
          }
      EXPECT_LT(largest, 1e-5) << (light.Type == LightType::Directional ? "sun" : "lamp") << ", "
                               << pad << " voxels more before the medium";
    }
  }
}

TEST(LightVolume, EmptyVolumeLetsEverythingThrough)
{
  const GridGeometry g = Box(12);
  const Grid empty(g, 0.0f);
  const ScatteringSlice slice = Shipped().Slice(0.3, 0.8);
  for (const Light& light : { Light::Directional({ 0.3, -1, 0.2 }, { 1, 1, 1 }),
         Light::Point({ 5, 6, 4 }, { 1, 1, 1 }),
         Light::Point({ -40, 3, 2 }, { 1, 1, 1 }) })
  {
    const Grid lv = ComputeLightVolume(empty, g, light, slice, 0.7);
    for (float v : lv.Values)
    {
      ASSERT_FLOAT_EQ(v, 1.0f);
    }
  }
}

TEST(LightVolume, SlabOccluderCastsTheExpectedShadow)
{
  // Light propagating along +z through a slab 8 <= z <= 13 covering 4 <= x <= 27.
  const int n = 32;
  const GridGeometry g = Box(n);
  const double sigma = 0.15, r = 1.0;
  Grid ext(g);
  for (int k = 8; k <= 13; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 4; i <= 27; ++i)
        ext.At(i, j, k) = static_cast<float>(sigma);
  const Grid averaged = AverageExtinction(ext, r);
  const ScatteringSlice slice = Shipped().Slice(0.0, 0.0);
  const Grid lv =
    ComputeLightVolume(averaged, g, Light::Directional({ 0, 0, 1 }, { 1, 1, 1 }), slice, r);
  // In front of the slab: lit. Behind it: attenuated by the slab's optical depth (6 voxels
  // of sigma; the averaging keeps the integral through the slab). Beside it: lit.
  EXPECT_NEAR(lv.At(16, 16, 4), 1.0, 1e-6);
  EXPECT_NEAR(lv.At(16, 16, 24), std::exp(-sigma * 6.0), 0.03);
  EXPECT_NEAR(lv.At(1, 16, 24), 1.0, 0.02);
  // The shadow does not recover behind the slab, and it is monotone along the light.
  for (int k = 1; k < n; ++k)
  {
    EXPECT_LE(lv.At(16, 16, k), lv.At(16, 16, k - 1) + 1e-6);
  }
  // Scattering (albedo 1, forward g) lets more light through than pure absorption.
  const Grid scattered = ComputeLightVolume(
    averaged, g, Light::Directional({ 0, 0, 1 }, { 1, 1, 1 }), Shipped().Slice(0.8, 1.0), r);
  EXPECT_GT(scattered.At(16, 16, 24), lv.At(16, 16, 24) + 0.05);
  EXPECT_LE(scattered.At(16, 16, 24), 1.0 + 1e-6);
}

TEST(LightVolume, PointLightInsideAndOutsideTheBox)
{
  const GridGeometry g = Box(24);
  const Grid averaged = AverageExtinction(ShellExtinction(g, 0.5), 1.0);
  const ScatteringSlice slice = Shipped().Slice(0.0, 0.5);
  // Inside, at the centre of the shell: symmetric, lit at the light, dark outside the shell.
  const Light inside = Light::Point({ 11.5, 11.5, 11.5 }, { 1, 1, 1 });
  const Grid li = ComputeLightVolume(averaged, g, inside, slice, 1.0);
  EXPECT_NEAR(li.At(11, 11, 11), 1.0, 0.02);
  EXPECT_NEAR(li.At(2, 11, 11), li.At(21, 11, 11), 1e-4);
  EXPECT_NEAR(li.At(11, 2, 11), li.At(11, 21, 11), 1e-4);
  EXPECT_LT(li.At(1, 11, 11), 0.6 * li.At(11, 11, 11));
  // Outside, far away along -z: the same as a directional light along +z.
  const Light far = Light::Point({ 11.5, 11.5, -1.0e5 }, { 1, 1, 1 });
  const Grid lf = ComputeLightVolume(averaged, g, far, slice, 1.0);
  const Grid ld =
    ComputeLightVolume(averaged, g, Light::Directional({ 0, 0, 1 }, { 1, 1, 1 }), slice, 1.0);
  for (int k = 0; k < 24; k += 4)
    for (int j = 4; j < 20; j += 3)
      for (int i = 4; i < 20; i += 3)
        EXPECT_NEAR(lf.At(i, j, k), ld.At(i, j, k), 2e-3);
  // A point light outside on the side starts its path where it enters the box: voxels on the
  // face towards the light are unshadowed.
  const Light side = Light::Point({ -10, 11.5, 11.5 }, { 1, 1, 1 });
  const Grid ls = ComputeLightVolume(averaged, g, side, slice, 1.0);
  EXPECT_NEAR(ls.At(0, 11, 11), 1.0, 1e-6);
}

TEST(LightVolume, WorkFollowsDistanceOverTwoR)
{
  const GridGeometry g = Box(20);
  const Grid averaged = AverageExtinction(ShellExtinction(g, 0.3), 1.0);
  const ScatteringSlice slice = Shipped().Slice(0.0, 0.9);
  const Light sun = Light::Directional({ 1, 0, 0 }, { 1, 1, 1 });
  LightVolumeStatistics small, large;
  ComputeLightVolume(averaged, g, sun, slice, 0.5, &small);
  ComputeLightVolume(averaged, g, sun, slice, 2.0, &large);
  // Along x, voxel i is i units from where the light enters the box, and its ball's entry point
  // i - r: floor((i - r) / 2r) + 1 balls each; voxels within r of the box face need none.
  std::uint64_t expected = 0;
  for (int i = 1; i < 20; ++i)
  {
    expected += static_cast<std::uint64_t>(std::floor((i - 0.5) / 1.0)) + 1;
  }
  EXPECT_EQ(small.Steps, expected * 400);
  EXPECT_LT(large.Steps * 3, small.Steps);
}

TEST(LightVolume, DimensionsAreCappedKeepingTheAspect)
{
  const auto d = LightVolumeDimensions({ 512, 256, 100 }, 256);
  EXPECT_EQ(d[0], 256);
  EXPECT_EQ(d[1], 128);
  EXPECT_EQ(d[2], 50);
  const auto same = LightVolumeDimensions({ 64, 32, 16 }, 256);
  EXPECT_EQ(same[0], 64);
  EXPECT_EQ(same[2], 16);
}

TEST(LightVolume, TheDirectBeamIsAShadowRayWhateverTheAlbedo)
{
  // The extended model's positional lights (TubeLaw::DirectBeam): exp(-2 tau) per ball, the
  // albedo-0 shadow ray, whatever F of the slice's g and albedo is.
  const GridGeometry g = Box(24);
  const Grid averaged = AverageExtinction(ShellExtinction(g, 0.4), 2.0);
  const ScatteringSlice slice = Shipped().Slice(0.6, 0.95);
  const double r = 1.3;
  const Vec3 p{ 11.5, 10.2, 12.7 };
  const Light lamp = Light::Point(p, { 1, 1, 1 });
  const Grid beam =
    ComputeLightVolume(averaged, g, lamp, slice, r, nullptr, {}, TubeLaw::DirectBeam);
  const Grid forward = ComputeLightVolume(averaged, g, lamp, slice, r);
  double brighter = 0.0;
  for (int k = 0; k < 24; k += 3)
    for (int j = 0; j < 24; j += 2)
      for (int i = 0; i < 24; ++i)
      {
        const Vec3 x{ double(i), double(j), double(k) };
        EXPECT_NEAR(beam.At(i, j, k), ShadowRay(averaged, p, BallEntry(p, x, r), r), 1e-6);
        EXPECT_NEAR(TubeTransmittance(averaged, lamp, slice, r, x, nullptr, TubeLaw::DirectBeam),
          ShadowRay(averaged, p, x, r),
          1e-6);
        brighter = std::max(brighter, double(forward.At(i, j, k) - beam.At(i, j, k)));
      }
  // F carries the forward-scattered light too: behind the shell the paper's tube is brighter.
  EXPECT_GT(brighter, 0.05);
  // The law: the paper's tube everywhere in the paper's model and for directional lights.
  EXPECT_EQ(TubeLawFor(false, LightType::Positional), TubeLaw::Forward);
  EXPECT_EQ(TubeLawFor(true, LightType::Directional), TubeLaw::Forward);
  EXPECT_EQ(TubeLawFor(true, LightType::Positional), TubeLaw::DirectBeam);
}
