// Surfaces inside the medium (SurfaceShading.h): the share of surface events, the BRDF's energy,
// the sides, the path tracer's lobes, the classifier's normal on structured fields, and the
// precomputed gradient (SurfaceGrid.h) the renderers read.
#include "Classifier.h"
#include "ReferenceRenderer.h"
#include "SurfaceGrid.h"
#include "SurfaceShading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace avs;

namespace
{
// Integral over the hemisphere about +z of Reflect's f cos for light from every direction: the
// directional albedo seen from `toViewer`, by the midpoint rule in (cos theta, phi).
SurfaceReflectance Albedo(const SurfaceShading& s, const Vec3& toViewer, int n = 400)
{
  SurfaceReflectance sum;
  const Vec3 normal{ 0, 0, 1 };
  for (int i = 0; i < n; ++i)
  {
    const double mu = (i + 0.5) / n;
    for (int j = 0; j < 2 * n; ++j)
    {
      const Vec3 l = SphericalDirection(normal, mu, Pi * (j + 0.5) / n);
      const SurfaceReflectance r = Reflect(s, normal, l, toViewer);
      sum.Diffuse += r.Diffuse;
      sum.Specular += r.Specular;
    }
  }
  const double weight = 2.0 * Pi / (2.0 * n * n); // d(mu) d(phi)
  sum.Diffuse *= weight;
  sum.Specular *= weight;
  return sum;
}
} // namespace

TEST(SurfaceShading, ProbabilityFollowsVTKsBlending)
{
  for (double alpha : { 0.0, 0.3, 1.0 })
  {
    // No gradient, no surface; blending 2: no surface; blending 0: the gradient alone.
    EXPECT_EQ(SurfaceProbability(0.0, alpha, 0.0), 0.0);
    EXPECT_EQ(SurfaceProbability(0.5, alpha, 2.0), 0.0);
    EXPECT_NEAR(
      SurfaceProbability(SurfaceGradientReference, alpha, 0.0), 1.0 - std::exp(-1.0), 1e-12);
    for (double b = 0.0; b <= 2.0; b += 0.25)
    {
      // Never more surface events than at blending 0 (VTK's weight B exp(-B g alpha) is not
      // monotonic in B below 1), more as the gradient grows.
      const double p = SurfaceProbability(0.1, alpha, b);
      EXPECT_LE(p, SurfaceProbability(0.1, alpha, 0.0) + 1e-12) << "b " << b;
      EXPECT_GE(SurfaceProbability(0.2, alpha, b), p - 1e-12);
      EXPECT_GE(p, 0.0);
      EXPECT_LE(p, 1.0);
    }
  }
  // Between 0 and 2, opacity makes a surface (VTK's weight exp(-B g alpha)).
  EXPECT_GT(SurfaceProbability(0.1, 0.9, 1.0), SurfaceProbability(0.1, 0.1, 1.0));
}

TEST(SurfaceShading, CoefficientsConserveEnergy)
{
  SurfaceShading s;
  s.Ambient = 0.5;
  s.Diffuse = 1.0;
  s.Specular = 0.5;
  s.SpecularPower = 1000.0;
  const SurfaceShading r = s.Resolved();
  EXPECT_NEAR(r.Ambient + r.Diffuse + r.Specular, 1.0, 1e-12);
  EXPECT_NEAR(r.Diffuse / r.Ambient, 2.0, 1e-12);
  EXPECT_EQ(r.SpecularPower, 128.0);
  SurfaceShading vtk; // VTK's defaults sum to 1 and stay
  EXPECT_EQ(vtk.Resolved().Diffuse, 0.7);
}

TEST(SurfaceShading, TheBRDFReflectsAtMostWhatArrives)
{
  SurfaceShading s;
  s.Diffuse = 0.6;
  s.Specular = 0.4;
  s.Ambient = 0.0;
  for (double p : { 1.0, 10.0, 60.0 })
  {
    s.SpecularPower = p;
    for (double viewerCos : { 1.0, 0.7, 0.2 })
    {
      const Vec3 v = SphericalDirection({ 0, 0, 1 }, viewerCos, 0.3);
      const SurfaceReflectance a = Albedo(s, v);
      EXPECT_NEAR(a.Diffuse, s.Diffuse, 2e-3) << "Lambert reflects k_d";
      EXPECT_LE(a.Specular, s.Specular * 1.01) << "power " << p << " viewer " << viewerCos;
      EXPECT_GT(a.Specular, 0.0);
    }
  }
}

TEST(SurfaceShading, SidesAndNormal)
{
  SurfaceShading s;
  const Vec3 n{ 0, 0, 1 };
  const Vec3 front{ 0, 0.6, 0.8 }, behind{ 0, 0.6, -0.8 };
  Vec3 facing;
  // Two-sided: lit and seen from behind, it reflects as from the front.
  EXPECT_TRUE(Facing(s, n, behind, facing));
  EXPECT_EQ(facing.z, -1.0);
  EXPECT_NEAR(Reflect(s, n, behind, behind).Diffuse, Reflect(s, n, front, front).Diffuse, 1e-12);
  // Lit from the other side than the viewer's: dark.
  EXPECT_EQ(Reflect(s, n, behind, front).Diffuse, 0.0);
  // One-sided: seen from behind, nothing.
  s.TwoSided = false;
  EXPECT_FALSE(Facing(s, n, behind, facing));
  EXPECT_EQ(Reflect(s, n, behind, behind).Diffuse, 0.0);
  EXPECT_GT(Reflect(s, n, front, front).Diffuse, 0.0);
  // The specular peak is in the mirror direction.
  const Vec3 mirror{ 0, -0.6, 0.8 };
  EXPECT_GT(Reflect(s, n, front, mirror).Specular, Reflect(s, n, front, front).Specular);
}

TEST(SurfaceShading, LobeSamplersHaveTheirMeanCosines)
{
  const Vec3 axis = Normalize(Vec3{ 0.3, -0.5, 0.8 });
  const int n = 200000;
  double cosine = 0.0, lobe = 0.0;
  const double power = 12.0;
  for (int i = 0; i < n; ++i)
  {
    // A stratified grid of (u1, u2).
    const double u1 = (i % 400 + 0.5) / 400.0, u2 = (i / 400 + 0.5) / (n / 400.0);
    cosine += Dot(SampleCosine(axis, u1, u2), axis);
    lobe += Dot(SamplePhongLobe(axis, power, u1, u2), axis);
  }
  EXPECT_NEAR(cosine / n, 2.0 / 3.0, 1e-3);                   // E[cos] for pdf cos / pi
  EXPECT_NEAR(lobe / n, (power + 1.0) / (power + 2.0), 1e-3); // for pdf ~ cos^p
}

TEST(SurfaceShading, ClassifierNormalPointsDownTheGradient)
{
  // s = 100 x over a lattice of spacing (0.5, 1, 2), range 0..1000 (the transfer function's):
  // the normal is -x, gamma = mean spacing * |grad s| / range.
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { 21, 5, 5 };
  g.Spacing = { 0.5, 1.0, 2.0 };
  scene.Scalars = Grid(g);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 21; ++i)
      {
        scene.Scalars.At(i, j, k) = static_cast<float>(100.0 * 0.5 * i);
      }
  scene.Transfer.Minimum = 0.0;
  scene.Transfer.Maximum = 1000.0;
  scene.Transfer.Opacity = { 0.5f, 0.5f };
  scene.Transfer.Color = { { 1, 1, 1 }, { 1, 1, 1 } };
  const Classifier classifier(scene);
  const Vec3 gradient = classifier.ShadingGradient({ 10, 2, 2 });
  EXPECT_NEAR(gradient.x, 0.05, 1e-6); // (s(11) - s(9)) / 2 / range, per index step
  EXPECT_NEAR(gradient.y, 0.0, 1e-9);
  const double mean = (0.5 + 1.0 + 2.0) / 3.0;
  EXPECT_NEAR(classifier.NormalisedGradient(gradient), mean * 100.0 / 1000.0, 1e-6);
  const SurfacePoint p = classifier.SurfaceAt({ 10, 2, 2 }, 1.0, 0.0);
  EXPECT_NEAR(p.Normal.x, -1.0, 1e-9);
  EXPECT_NEAR(p.Probability, 1.0 - std::exp(-mean * 0.1 / SurfaceGradientReference), 1e-6);
  EXPECT_EQ(classifier.SurfaceAt({ 10, 2, 2 }, 0.0, 0.0).Probability, 0.0); // no material
}

namespace
{
// s = a x + b y + c z (world units) on a lattice of spacing (0.5, 1, 2), transfer range 0..r.
VolumeScene Ramp(const Vec3& gradient, double range)
{
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { 9, 7, 6 };
  g.Spacing = { 0.5, 1.0, 2.0 };
  scene.Scalars = Grid(g);
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 9; ++i)
      {
        scene.Scalars.At(i, j, k) =
          static_cast<float>(gradient.x * 0.5 * i + gradient.y * 1.0 * j + gradient.z * 2.0 * k);
      }
  scene.Transfer.Minimum = 0.0;
  scene.Transfer.Maximum = range;
  scene.Transfer.Opacity = { 0.5f, 0.5f };
  scene.Transfer.Color = { { 1, 1, 1 }, { 1, 1, 1 } };
  return scene;
}
} // namespace

TEST(SurfaceGrid, BytesRoundTrip)
{
  EXPECT_EQ(SurfaceGrid::EncodeDirection(0.0), 128);
  EXPECT_EQ(SurfaceGrid::DecodeDirection(128), 0.0);
  EXPECT_EQ(SurfaceGrid::EncodeDirection(1.0), 255);
  EXPECT_EQ(SurfaceGrid::EncodeDirection(-1.0), 1);
  EXPECT_EQ(SurfaceGrid::EncodeDirection(7.0), 255); // clamped
  EXPECT_EQ(SurfaceGrid::EncodeEdge(1.0), 255);
  EXPECT_EQ(SurfaceGrid::EncodeEdge(-1.0), 0);
  for (int b = 1; b < 256; ++b)
  {
    EXPECT_EQ(SurfaceGrid::EncodeDirection(SurfaceGrid::DecodeDirection(b)), b);
    EXPECT_EQ(SurfaceGrid::EncodeEdge(SurfaceGrid::DecodeEdge(b)), b);
  }
}

TEST(SurfaceGrid, RampHasItsDirectionAndEdgeShare)
{
  // Inside, the central differences of a linear field are its gradient; at a face they are
  // one-sided, halved (VTK's clamp). The bytes hold e n (the edge share times the unit
  // direction), each component to within a byte; the edge share read back is its length.
  const Vec3 a{ 30.0, -20.0, 10.0 };
  const double range = 1000.0;
  const VolumeScene scene = Ramp(a, range);
  const SurfaceGrid grid = MakeSurfaceGrid(scene, 2);
  ASSERT_EQ(grid.Bytes(), 4u * 9 * 7 * 6);
  const double mean = (0.5 + 1.0 + 2.0) / 3.0;
  auto check = [&](const Vec3& index, const Vec3& g)
  {
    Vec3 direction;
    double edge;
    grid.Sample(index, false, direction, edge);
    const double e = SurfaceEdge(mean * Length(g) / range);
    ASSERT_GT(e, 0.2); // (a ramp whose direction the bytes resolve)
    const Vec3 scaled = g * (e / Length(g));
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(direction[c], scaled[c], 0.6 / 127.0) << "component " << c;
    }
    EXPECT_NEAR(edge, e, std::sqrt(3.0) * 0.6 / 127.0);
    EXPECT_DOUBLE_EQ(edge, Length(direction));
  };
  check({ 4, 3, 2 }, a);
  check({ 4.5, 3.25, 2.75 }, a); // interpolated between interior points
  check({ 0, 3, 2 }, { 0.5 * a.x, a.y, a.z });
  check({ 4, 6, 5 }, { a.x, 0.5 * a.y, 0.5 * a.z });
  // Outside the lattice: clamped to its faces, as a texture clamps to the edge.
  Vec3 inside, outside;
  double e1, e2;
  grid.Sample({ 0, 3, 2 }, false, inside, e1);
  grid.Sample({ -3, 3, 2 }, false, outside, e2);
  EXPECT_EQ(e1, e2);
  EXPECT_EQ(inside.x, outside.x);
}

TEST(SurfaceGrid, SlicesAndSceneAgreeAndFlatFieldsHaveNone)
{
  const VolumeScene scene = Ramp({ 5.0, 0.0, -2.0 }, 100.0);
  const SurfaceGrid whole = MakeSurfaceGrid(scene, 1);
  const GridGeometry& g = scene.Scalars.Geometry;
  const std::size_t slice = static_cast<std::size_t>(g.Dimensions[0]) * g.Dimensions[1];
  int reads = 0;
  const SurfaceGrid sliced = MakeSurfaceGrid(
    g.Dimensions,
    g.Spacing,
    1.0 / 100.0,
    [&](int k, float* out)
    {
      ++reads;
      std::copy_n(scene.Scalars.Values.data() + slice * k, slice, out);
    },
    3);
  EXPECT_EQ(sliced.Texels, whole.Texels);
  EXPECT_EQ(reads, g.Dimensions[2]); // each slice read once
  const VolumeScene level = Ramp({ 0.0, 0.0, 0.0 }, 100.0);
  const SurfaceGrid flat = MakeSurfaceGrid(level);
  for (std::size_t v = 0; v < flat.Texels.size(); v += 4)
  {
    ASSERT_EQ(flat.Texels[v], 128);
    ASSERT_EQ(flat.Texels[v + 3], 0);
  }
  Classifier classifier(level); // (which keeps a reference to the scene)
  classifier.SetSurfaceGrid(&flat);
  EXPECT_EQ(classifier.SurfaceAt({ 3, 3, 3 }, 1.0, 0.0).Probability, 0.0);
}

TEST(SurfaceGrid, ClassifierReadsTheGridLikeTheCentralDifferences)
{
  // With the grid set, SurfaceAt gives what the central differences give, to within the bytes,
  // at every blending; a volume turned by its direction matrix turns the normal with it.
  VolumeScene scene = Ramp({ 30.0, -20.0, 10.0 }, 1000.0);
  scene.Scalars.Geometry.Direction = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
  const SurfaceGrid grid = MakeSurfaceGrid(scene);
  const Classifier exact(scene);
  Classifier quantised(scene);
  quantised.SetSurfaceGrid(&grid);
  for (double blending : { 0.0, 0.5, 1.0, 1.5 })
  {
    for (const Vec3& index : { Vec3{ 4, 3, 2 }, Vec3{ 2.5, 4.75, 3.5 } })
    {
      const SurfacePoint e = exact.SurfaceAt(index, 0.7, blending);
      const SurfacePoint q = quantised.SurfaceAt(index, 0.7, blending);
      EXPECT_NEAR(q.Probability, e.Probability, 0.01) << "blending " << blending;
      EXPECT_GT(Dot(q.Normal, e.Normal), 0.9999);
    }
  }
  // The world normal: -grad s turned by the direction matrix (x -> y, y -> -x).
  const Vec3 n = quantised.SurfaceAt({ 4, 3, 2 }, 0.7, 0.0).Normal;
  const Vec3 local = Vec3{ 30.0, -20.0, 10.0 } * (-1.0 / Length(Vec3{ 30.0, -20.0, 10.0 }));
  EXPECT_NEAR(n.x, -local.y, 0.01);
  EXPECT_NEAR(n.y, local.x, 0.01);
  EXPECT_NEAR(n.z, local.z, 0.01);
}
