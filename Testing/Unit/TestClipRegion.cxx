// The clip region (clipping planes and cropping in the index frame): VTK's region numbering and
// presets, the ray interval against a brute-force per-point test, planes carried exactly
// through affine maps, the conservative box test, and the renderers: the CPU reference and the
// path tracer see nothing of the clipped half of a homogeneous cube (analytic transmittance),
// the extinction grid and the averaged extinction are 0 there, the majorants still bound.
#include "AveragedExtinction.h"
#include "ClipRegion.h"
#include "Extinction.h"
#include "MajorantGrid.h"
#include "PathTracer.h"
#include "Random.h"
#include "ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
ClipRegion Cropped(int flags)
{
  ClipRegion r;
  r.Cropping = true;
  r.CroppingPlanes = { 3, 6, 3, 6, 3, 6 };
  r.CroppingRegionFlags = flags;
  return r;
}

Vec3 RandomPoint(Random& rng, double lo, double hi)
{
  return {
    lo + (hi - lo) * rng.Uniform(), lo + (hi - lo) * rng.Uniform(), lo + (hi - lo) * rng.Uniform()
  };
}

ClipRegion RandomRegion(Random& rng, int planes, bool cropping)
{
  ClipRegion r;
  for (int p = 0; p < planes; ++p)
  {
    IndexPlane plane;
    plane.Normal = RandomPoint(rng, -1, 1);
    plane.Offset = -Dot(plane.Normal, RandomPoint(rng, 2, 7));
    r.Planes.push_back(plane);
  }
  if (cropping)
  {
    r.Cropping = true;
    for (int a = 0; a < 3; ++a)
    {
      const double u = 1 + 7 * rng.Uniform(), v = 1 + 7 * rng.Uniform();
      r.CroppingPlanes[2 * a] = std::min(u, v);
      r.CroppingPlanes[2 * a + 1] = std::max(u, v);
    }
    r.CroppingRegionFlags = static_cast<int>(rng.Uniform() * 0x7ffffff);
  }
  return r;
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
} // namespace

TEST(ClipRegion, RegionsAreNumberedAsVTKs)
{
  // Region a + 3 b + 9 c; 0x2000 (bit 13) is the middle one.
  const ClipRegion sub = Cropped(ClipRegion::SubVolume);
  EXPECT_EQ(sub.Region({ 4, 4, 4 }), 13);
  EXPECT_EQ(sub.Region({ 1, 1, 1 }), 0);
  EXPECT_EQ(sub.Region({ 7, 1, 1 }), 2);
  EXPECT_EQ(sub.Region({ 1, 7, 1 }), 6);
  EXPECT_EQ(sub.Region({ 1, 1, 7 }), 18);
  EXPECT_EQ(sub.Region({ 3, 6, 8 }), 1 + 6 + 18); // on a plane: the interval above it
  EXPECT_TRUE(sub.IsInside({ 4, 5, 3 }));
  EXPECT_FALSE(sub.IsInside({ 4, 5, 2 }));
  // VTK's cross (0x0417410): the middle and its six face neighbours.
  const ClipRegion cross = Cropped(0x0417410);
  Random rng(3);
  for (int i = 0; i < 2000; ++i)
  {
    const Vec3 p = RandomPoint(rng, 0, 9);
    int outside = 0;
    for (int a = 0; a < 3; ++a)
    {
      outside += p[a] < 3 || p[a] >= 6;
    }
    EXPECT_EQ(cross.IsInside(p), outside <= 1);
    // The inverted cross (0x7be8bef) keeps the rest.
    EXPECT_NE(Cropped(0x7be8bef).IsInside(p), cross.IsInside(p));
  }
}

TEST(ClipRegion, RayIntervalHoldsEveryKeptPoint)
{
  Random rng(7);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int planes = trial % 7;
    const ClipRegion region = RandomRegion(rng, planes, trial % 3 != 0);
    const Vec3 o = RandomPoint(rng, -5, 14);
    const Vec3 d = Normalize(RandomPoint(rng, -1, 1));
    double t0 = -30, t1 = 30;
    const bool any = region.ClipRay(o, d, t0, t1);
    for (int s = 0; s <= 600; ++s)
    {
      const double t = -30 + 60.0 * s / 600;
      const bool inside = region.IsInside(o + d * t);
      if (inside)
      {
        ASSERT_TRUE(any) << "trial " << trial;
        ASSERT_GE(t, t0 - 1e-9);
        ASSERT_LE(t, t1 + 1e-9);
      }
      if (!region.Cropping && any && t > t0 + 1e-9 && t < t1 - 1e-9)
      {
        ASSERT_TRUE(inside) << "planes alone: the interval is exactly the kept part";
      }
    }
  }
}

TEST(ClipRegion, PlanesFollowAffineMapsExactly)
{
  Random rng(11);
  for (int trial = 0; trial < 50; ++trial)
  {
    std::array<double, 12> m{};
    for (double& v : m)
    {
      v = 2 * rng.Uniform() - 1;
    }
    m[0] += 2;
    m[5] += 2;
    m[10] += 2; // well conditioned
    const Vec3 origin = RandomPoint(rng, -1, 1), normal = RandomPoint(rng, -1, 1);
    const IndexPlane plane = PlaneToIndex(origin, normal, m);
    for (int i = 0; i < 100; ++i)
    {
      const Vec3 index = RandomPoint(rng, -5, 5);
      const Vec3 world{ m[0] * index.x + m[1] * index.y + m[2] * index.z + m[3],
        m[4] * index.x + m[5] * index.y + m[6] * index.z + m[7],
        m[8] * index.x + m[9] * index.y + m[10] * index.z + m[11] };
      EXPECT_NEAR(plane.Evaluate(index), Dot(Normalize(normal), world - origin), 1e-9);
    }
  }
}

TEST(ClipRegion, BoxOutsideIsConservative)
{
  Random rng(5);
  int outsideBoxes = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    const ClipRegion region = RandomRegion(rng, trial % 4, trial % 2 == 0);
    const Vec3 low = RandomPoint(rng, 0, 8);
    const Vec3 high = low + Vec3{ 1, 1, 1 } * (0.5 + rng.Uniform());
    if (!region.BoxOutside(low, high))
    {
      continue;
    }
    ++outsideBoxes;
    for (int i = 0; i < 200; ++i)
    {
      const Vec3 p{ low.x + (high.x - low.x) * rng.Uniform(),
        low.y + (high.y - low.y) * rng.Uniform(),
        low.z + (high.z - low.z) * rng.Uniform() };
      ASSERT_FALSE(region.IsInside(p)) << "trial " << trial;
    }
  }
  EXPECT_GT(outsideBoxes, 40); // the test is not vacuous
}

TEST(ClipRegion, ReferenceAndPathTracerSeeHalfTheCube)
{
  // A cube of side 10 cut at x = 4 (kept: x <= 4), looked at along -x: the transmittance is
  // exp(-4 sigma) instead of exp(-10 sigma).
  const double sigma = 0.2, length = 10.0;
  VolumeScene scene = Cube(11, length, sigma);
  scene.Clip.Planes.push_back(
    PlaneToIndex({ 4, 0, 0 }, { -1, 0, 0 }, IndexToWorldMap(scene.Scalars.Geometry)));
  Camera camera;
  camera.Position = { 30, 5, 5 };
  camera.FocalPoint = { 5, 5, 5 };
  camera.Parallel = true;
  camera.ParallelScale = 3;
  ScatteringParameters p;
  p.Albedo = 0.0;
  const ScatteringParameters resolved = p.Resolve(scene.Scalars.Geometry);
  const double expected = 1.0 - std::exp(-4 * sigma);

  PrecomputedVolumes volumes;
  ASSERT_TRUE(Precompute(scene, resolved, nullptr, RenderMode::EmissionAbsorption, volumes));
  const Image ea =
    RenderReference(scene, resolved, volumes, RenderMode::EmissionAbsorption, camera, 8, 8);
  EXPECT_NEAR(ea.At(4, 4)[3], expected, 1e-6);

  PathTracerSettings settings;
  settings.SamplesPerPixel = 4000;
  const Image traced = RenderPathTraced(scene, resolved, settings, camera, 2, 2);
  EXPECT_NEAR(traced.At(1, 1)[3], expected, 0.03);

  // The extinction grid and its average are 0 beyond the cut; the majorants still bound.
  const Grid sigmaT = ExtinctionGrid(scene);
  EXPECT_EQ(sigmaT.At(8, 5, 5), 0.0f);
  EXPECT_NEAR(sigmaT.At(2, 5, 5), sigma, 1e-6);
  const Grid averaged = AverageExtinction(sigmaT, 2.0);
  EXPECT_EQ(averaged.At(9, 5, 5), 0.0f);
  EXPECT_GT(averaged.At(2, 5, 5), 0.0f);
  const MajorantGrid majorants(scene.Scalars, scene.Transfer, 1.0, 2, &scene.Clip);
  const VolumeTracker tracker(scene, majorants);
  EXPECT_EQ(majorants.Cell(4, 2, 2), 0.0); // voxels 8-10: wholly cut away
  Random rng(1);
  for (int i = 0; i < 5000; ++i)
  {
    const Vec3 x = RandomPoint(rng, 0, length);
    ASSERT_LE(tracker.Extinction(x), majorants.At(scene.Scalars.Geometry.WorldToIndex(x)) + 1e-12);
    ASSERT_EQ(tracker.Extinction(x) > 0.0, x.x <= 4.0);
  }
}
