// The path tracer: its majorants bound the extinction, the grid of them changes nothing but the
// work, the albedo-0 image is the analytic transmittance, a white medium conserves energy, the
// error falls like 1/sqrt(spp), and a seed gives the same image whatever the threads.
#include "MajorantGrid.h"
#include "PathTracer.h"
#include "Random.h"

#include "Extinction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace avs;

namespace
{
// A thin spherical shell of scalar 1 in an n^3 grid over [0, n-1], with a transfer function
// whose opacity peaks in the middle of the scalar range (not monotone).
VolumeScene Shell(int n)
{
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { n, n, n };
  scene.Scalars = Grid(g);
  const double c = 0.5 * (n - 1), r = 0.35 * n;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double d = Length(Vec3{ i - c, j - c, k - c });
        scene.Scalars.At(i, j, k) = static_cast<float>(std::max(0.0, 1.0 - std::abs(d - r) / 1.5));
      }
  scene.Transfer.Minimum = 0.0;
  scene.Transfer.Maximum = 1.0;
  for (int i = 0; i < 64; ++i)
  {
    const double s = i / 63.0;
    scene.Transfer.Opacity.push_back(
      static_cast<float>(0.9 * std::exp(-30.0 * (s - 0.5) * (s - 0.5))));
    scene.Transfer.Color.push_back({ 1.0f, 0.8f, 0.6f });
  }
  scene.UnitDistance = 1.0;
  return scene;
}

// A homogeneous cube [0, L]^3 of extinction sigma and colour 1.
VolumeScene Cube(int n, double length, double sigma)
{
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { n, n, n };
  const double h = length / (n - 1);
  g.Spacing = { h, h, h };
  scene.Scalars = Grid(g, 1.0f);
  scene.Transfer = TransferFunction::Constant(ExtinctionToOpacity(sigma, 1.0), { 1, 1, 1 });
  scene.UnitDistance = 1.0;
  return scene;
}

Camera Orthographic(const Vec3& centre, const Vec3& towards, double halfSize)
{
  Camera c;
  c.FocalPoint = centre;
  c.Position = centre - towards * 10.0;
  c.ViewUp = std::abs(towards.y) < 0.9 ? Vec3{ 0, 1, 0 } : Vec3{ 1, 0, 0 };
  c.Parallel = true;
  c.ParallelScale = halfSize;
  return c;
}

double Mean(const Image& image, int channel)
{
  double s = 0.0;
  for (int y = 0; y < image.Height; ++y)
    for (int x = 0; x < image.Width; ++x)
      s += image.At(x, y)[channel];
  return s / (static_cast<double>(image.Width) * image.Height);
}
} // namespace

TEST(PathTracer, MajorantBoundsTheExtinctionEverywhere)
{
  const VolumeScene scene = Shell(24);
  for (int cell : { 1, 4, 8, 100 })
  {
    const MajorantGrid majorants(scene.Scalars, scene.Transfer, 1.0, cell);
    const VolumeTracker tracker(scene, majorants);
    Random rng(cell);
    int tight = 0;
    for (int i = 0; i < 20000; ++i)
    {
      const Vec3 p{ 23 * rng.Uniform(), 23 * rng.Uniform(), 23 * rng.Uniform() };
      const double sigma = tracker.Extinction(p);
      const double bound = majorants.At(p);
      ASSERT_LE(sigma, bound * (1 + 1e-9) + 1e-12) << "cell " << cell;
      tight += sigma > 0.5 * bound;
    }
    EXPECT_LE(majorants.Maximum(), OpacityToExtinction(0.9, 1.0) + 1e-9);
    if (cell == 4)
    {
      EXPECT_GT(tight, 100); // the bound is not vacuous
    }
  }
}

TEST(PathTracer, MajorantGridKeepsTheEstimateAndCutsNullCollisions)
{
  VolumeScene scene = Shell(24);
  scene.Lights = { Light::Directional({ 0.3, -1, -0.4 }, { 3, 3, 3 }) };
  ScatteringParameters p;
  p.Albedo = 0.8;
  p.Anisotropy = 0.3;
  const Camera camera = Orthographic({ 11.5, 11.5, 11.5 }, Normalize(Vec3{ 0.2, 0.1, -1 }), 13.0);
  PathTracerSettings fine, global;
  fine.SamplesPerPixel = global.SamplesPerPixel = 64;
  fine.MajorantCellSize = 2;
  global.MajorantCellSize = 1000; // one majorant for the whole volume
  PathTracerStatistics fineStats, globalStats;
  const Image a =
    RenderPathTraced(scene, p.Resolve(scene.Scalars.Geometry), fine, camera, 16, 16, &fineStats);
  const Image b = RenderPathTraced(
    scene, p.Resolve(scene.Scalars.Geometry), global, camera, 16, 16, &globalStats);
  for (int ch = 0; ch < 4; ++ch)
  {
    const double ma = Mean(a, ch), mb = Mean(b, ch);
    EXPECT_NEAR(ma, mb, 0.05 * std::max(ma, mb) + 1e-4) << "channel " << ch;
  }
  EXPECT_GT(Mean(a, 0), 0.01);
  std::cout << "tentative collisions: grid " << fineStats.NullCollisions << ", global "
            << globalStats.NullCollisions << "\n";
  EXPECT_LT(fineStats.NullCollisions * 2, globalStats.NullCollisions);
}

TEST(PathTracer, AlbedoZeroGivesTheAnalyticTransmittance)
{
  const double sigma = 0.15, length = 10.0;
  VolumeScene scene = Cube(11, length, sigma);
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { 5, 5, 5 }) };
  ScatteringParameters p;
  p.Albedo = 0.0;
  PathTracerSettings s;
  s.SamplesPerPixel = 256;
  const Camera camera = Orthographic({ 5, 5, 5 }, { 0, 0, -1 }, 4.0);
  const Image image = RenderPathTraced(scene, p.Resolve(scene.Scalars.Geometry), s, camera, 8, 8);
  const double expected = 1.0 - std::exp(-sigma * length);
  const double se = std::sqrt(expected * (1 - expected) / (64.0 * 256.0));
  EXPECT_NEAR(Mean(image, 3), expected, 4 * se);
  EXPECT_EQ(Mean(image, 0), 0.0); // nothing scatters, nothing glows
  // Ratio tracking alone, on a structured volume against a dense quadrature.
  const VolumeScene shell = Shell(24);
  const MajorantGrid majorants(shell.Scalars, shell.Transfer, 1.0, 4);
  const VolumeTracker tracker(shell, majorants);
  const Vec3 origin{ 2.0, 11.3, 10.7 };
  const Vec3 direction = Normalize(Vec3{ 1.0, 0.05, 0.02 });
  double optical = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    optical += tracker.Extinction(origin + direction * ((i + 0.5) * 20.0 / 20000)) * (20.0 / 20000);
  }
  Random rng(5);
  PathTracerStatistics stats;
  double sum = 0.0, sum2 = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i)
  {
    const double T = tracker.Transmittance(origin, direction, 20.0, rng, stats);
    sum += T;
    sum2 += T * T;
  }
  const double mean = sum / n, err = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, std::exp(-optical), 4 * err + 1e-4);
  EXPECT_LT(std::exp(-optical), 0.9); // the segment crosses the shell
}

TEST(PathTracer, CellDataBorderIsPartOfTheVolume)
{
  // Cell data: samples at the cell centres, the box half a cell wider on every side; the border
  // holds the medium of the nearest face, so the cube is L + h thick.
  const double sigma = 0.15, length = 10.0;
  VolumeScene scene = Cube(11, length, sigma);
  scene.Scalars.Geometry.Border = 0.5;
  const double h = scene.Scalars.Geometry.Spacing.x;
  const MajorantGrid majorants(scene.Scalars, scene.Transfer, 1.0, 4);
  const VolumeTracker tracker(scene, majorants);
  Random rng(3);
  PathTracerStatistics stats;
  double sum = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i)
  {
    // Through the border of the x faces, near the box's edge in y and z too.
    sum +=
      tracker.Transmittance({ -5.0, -0.4 * h, length + 0.3 * h }, { 1, 0, 0 }, 30.0, rng, stats);
  }
  EXPECT_NEAR(sum / n, std::exp(-sigma * (length + h)), 0.01);
  EXPECT_EQ(tracker.Extinction({ -0.45 * h, 0.0, 0.0 }), tracker.Extinction({ 0.0, 0.0, 0.0 }));
  EXPECT_EQ(tracker.Extinction({ -0.55 * h, 0.0, 0.0 }), 0.0);
}

TEST(PathTracer, WhiteMediumConservesEnergy)
{
  // A homogeneous cube, albedo 1, white, lit along -z: all light that enters leaves, scattered
  // (integrated over orthographic views from a sphere of directions) or straight through.
  const double sigma = 0.2, length = 6.0, E = 1.0;
  VolumeScene scene = Cube(13, length, sigma);
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { E, E, E }) };
  ScatteringParameters p;
  p.Albedo = 1.0;
  p.Anisotropy = 0.3;
  PathTracerSettings s;
  s.SamplesPerPixel = 4;
  const int views = 96, pixels = 24;
  const double half = 0.5 * std::sqrt(3.0) * length + 0.1; // covers the cube from any side
  double scattered = 0.0;
  const double golden = Pi * (3.0 - std::sqrt(5.0));
  for (int v = 0; v < views; ++v)
  {
    const double z = 1.0 - (2.0 * v + 1.0) / views;
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 towards{ r * std::cos(golden * v), r * std::sin(golden * v), z };
    s.Seed = 100 + v;
    const Image image = RenderPathTraced(scene,
      p.Resolve(scene.Scalars.Geometry),
      s,
      Orthographic({ 3, 3, 3 }, towards, half),
      pixels,
      pixels);
    const double area = (2 * half) * (2 * half) / (pixels * pixels);
    double power = 0.0;
    for (int y = 0; y < pixels; ++y)
      for (int x = 0; x < pixels; ++x)
        power += image.At(x, y)[0] * area;
    scattered += power * 4.0 * Pi / views;
  }
  const double incoming = E * length * length;
  const double direct = incoming * std::exp(-sigma * length);
  std::cout << "energy out / in: " << (scattered + direct) / incoming << "\n";
  EXPECT_NEAR((scattered + direct) / incoming, 1.0, 0.04) << "scattered " << scattered;
  EXPECT_GT(scattered, 0.5 * incoming);
}

TEST(PathTracer, ErrorFallsLikeOneOverSqrtSpp)
{
  VolumeScene scene = Shell(20);
  scene.Lights = { Light::Point({ 9.5, 9.5, 9.5 }, { 20, 20, 20 }, { 1, 0, 0.01 }) };
  ScatteringParameters p;
  p.Albedo = 0.9;
  const ScatteringParameters rp = p.Resolve(scene.Scalars.Geometry);
  const Camera camera = Orthographic({ 9.5, 9.5, 9.5 }, { 0, 0, -1 }, 10.0);
  PathTracerSettings s;
  s.SamplesPerPixel = 1024;
  s.Seed = 99;
  const Image reference = RenderPathTraced(scene, rp, s, camera, 8, 8);
  double rmse[2];
  int k = 0;
  for (int spp : { 16, 64 })
  {
    double e = 0.0;
    for (int seed = 0; seed < 4; ++seed)
    {
      s.SamplesPerPixel = spp;
      s.Seed = 1000 + seed;
      const Image image = RenderPathTraced(scene, rp, s, camera, 8, 8);
      for (std::size_t i = 0; i < image.Pixels.size(); i += 4)
      {
        const double d = image.Pixels[i] - reference.Pixels[i];
        e += d * d;
      }
    }
    rmse[k++] = std::sqrt(e / (4 * 64));
  }
  // 4x the samples: half the error (the reference's own noise is 1/8 of the 16-spp error).
  EXPECT_NEAR(rmse[0] / rmse[1], 2.0, 0.6) << rmse[0] << " " << rmse[1];
}

TEST(PathTracer, SameSeedSameImageWhateverTheThreads)
{
  VolumeScene scene = Shell(16);
  scene.Lights = { Light::Directional({ 1, -1, 0 }, { 2, 2, 2 }) };
  ScatteringParameters p;
  PathTracerSettings s;
  s.SamplesPerPixel = 8;
  const Camera camera = Orthographic({ 7.5, 7.5, 7.5 }, { 0, 0, -1 }, 8.0);
  setenv("AVS_NUM_THREADS", "1", 1);
  const Image a = RenderPathTraced(scene, p.Resolve(scene.Scalars.Geometry), s, camera, 8, 8);
  setenv("AVS_NUM_THREADS", "2", 1);
  const Image b = RenderPathTraced(scene, p.Resolve(scene.Scalars.Geometry), s, camera, 8, 8);
  unsetenv("AVS_NUM_THREADS");
  EXPECT_EQ(a.Pixels, b.Pixels);
}
