// The CPU reference ray caster: analytic slabs, empty volumes, the albedo-0 limit of ambient
// scattering, forward scattering towards the light, the direction matrix and the camera inside.
#include "ReferenceRenderer.h"

#include "Extinction.h"

#include "ShippedTable.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
// A homogeneous box [0, 10] x [0, 10] x [0, depth] with scalar 1.
VolumeScene Slab(double alpha, double unitDistance, double depth, const Vec3& color)
{
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { 11, 11, 11 };
  g.Spacing = { 1.0, 1.0, depth / 10.0 };
  scene.Scalars = Grid(g, 1.0f);
  scene.Transfer = TransferFunction::Constant(alpha, color);
  scene.UnitDistance = unitDistance;
  return scene;
}

Camera LookingDownZ(const Vec3& at, double from)
{
  Camera c;
  c.Position = at + Vec3{ 0, 0, from };
  c.FocalPoint = at;
  c.ViewUp = { 0, 1, 0 };
  c.Parallel = true;
  c.ParallelScale = 1.0;
  return c;
}

Image Render(const VolumeScene& scene,
  ScatteringParameters p,
  RenderMode mode,
  const Camera& camera,
  int size = 8)
{
  const ScatteringParameters resolved = p.Resolve(scene.Scalars.Geometry);
  PrecomputedVolumes volumes;
  std::string error;
  EXPECT_TRUE(Precompute(scene, resolved, &Shipped(), mode, volumes, &error)) << error;
  return RenderReference(scene, resolved, volumes, mode, camera, size, size);
}
} // namespace

TEST(ReferenceRenderer, HomogeneousSlabUnderEmissionAbsorption)
{
  const double alpha = 0.3, u = 2.0, depth = 5.0;
  const Vec3 color{ 0.2, 0.5, 0.9 };
  const VolumeScene scene = Slab(alpha, u, depth, color);
  ScatteringParameters p;
  p.TerminationTransmittance = 0.0;
  const Image image =
    Render(scene, p, RenderMode::EmissionAbsorption, LookingDownZ({ 5, 5, 0 }, 20));
  const double sigma = OpacityToExtinction(alpha, u);
  const double expected = 1.0 - std::exp(-sigma * depth);
  for (int y = 0; y < image.Height; ++y)
    for (int x = 0; x < image.Width; ++x)
    {
      const float* px = image.At(x, y);
      EXPECT_NEAR(px[3], expected, 1e-6);
      EXPECT_NEAR(px[0], color.x * expected, 1e-6);
      EXPECT_NEAR(px[2], color.z * expected, 1e-6);
    }
}

TEST(ReferenceRenderer, CellDataSpansHalfACellBeyondItsSamples)
{
  // Cell data (samples at the cell centres, GridGeometry::Border 0.5): the slab is a cell
  // thicker than its lattice, in every mode, and the light volumes and averaged extinction
  // (on the lattice) are read clamped in the border.
  const double alpha = 0.3, u = 2.0, depth = 5.0;
  VolumeScene scene = Slab(alpha, u, depth, { 1, 1, 1 });
  scene.Scalars.Geometry.Border = 0.5;
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { 1, 1, 1 }) };
  ScatteringParameters p;
  p.TerminationTransmittance = 0.0;
  const double sigma = OpacityToExtinction(alpha, u);
  const double expected = 1.0 - std::exp(-sigma * (depth + depth / 10.0));
  for (RenderMode mode :
    { RenderMode::EmissionAbsorption, RenderMode::AmbientOcclusion, RenderMode::AmbientScattering })
  {
    const Image image = Render(scene, p, mode, LookingDownZ({ 5, 5, 0 }, 20));
    EXPECT_NEAR(image.At(4, 4)[3], expected, 1e-6);
    EXPECT_GT(image.At(4, 4)[0], 0.0);
  }
}

TEST(ReferenceRenderer, CameraInsideTheVolumeSeesOnlyWhatIsInFront)
{
  const double alpha = 0.4, u = 1.0;
  const VolumeScene scene = Slab(alpha, u, 10.0, { 1, 1, 1 });
  ScatteringParameters p;
  p.TerminationTransmittance = 0.0;
  Camera c = LookingDownZ({ 5, 5, 0 }, 3.0); // at z = 3, looking towards -z
  const Image image = Render(scene, p, RenderMode::EmissionAbsorption, c, 4);
  EXPECT_NEAR(image.At(1, 1)[3], 1.0 - std::exp(-OpacityToExtinction(alpha, u) * 3.0), 1e-6);
}

TEST(ReferenceRenderer, VolumeOfZerosRendersTheBackground)
{
  VolumeScene scene = Slab(0.5, 1.0, 10.0, { 1, 0, 0 });
  scene.Scalars = Grid(scene.Scalars.Geometry, 0.0f);
  scene.Transfer = TransferFunction::Ramp(0.0, 1.0, 0.8, { 1, 0, 0 }); // alpha(0) = 0
  scene.Background = { 0.1, 0.2, 0.3 };
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { 5, 5, 5 }) };
  for (RenderMode mode :
    { RenderMode::EmissionAbsorption, RenderMode::AmbientOcclusion, RenderMode::AmbientScattering })
  {
    const Image image = Render(scene, ScatteringParameters(), mode, LookingDownZ({ 5, 5, 5 }, 20));
    for (int y = 0; y < image.Height; ++y)
      for (int x = 0; x < image.Width; ++x)
      {
        const Vec3 c = image.Composited(x, y, scene.Background);
        EXPECT_DOUBLE_EQ(c.x, 0.1);
        EXPECT_DOUBLE_EQ(c.y, 0.2);
        EXPECT_DOUBLE_EQ(c.z, 0.3);
      }
  }
}

TEST(ReferenceRenderer, AmbientScatteringWithoutAlbedoOrEmissionIsBlack)
{
  const VolumeScene base = Slab(0.5, 1.0, 10.0, { 1, 1, 1 });
  VolumeScene scene = base;
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { 10, 10, 10 }),
    Light::Point({ 5, 5, 5 }, { 10, 10, 10 }) };
  ScatteringParameters p;
  p.Albedo = 0.0;
  p.EmissionWeight = 0.0;
  const Image black =
    Render(scene, p, RenderMode::AmbientScattering, LookingDownZ({ 5, 5, 5 }, 20));
  for (int y = 0; y < black.Height; ++y)
    for (int x = 0; x < black.Width; ++x)
    {
      EXPECT_EQ(black.At(x, y)[0], 0.0f);
      EXPECT_EQ(black.At(x, y)[1], 0.0f);
      EXPECT_GT(black.At(x, y)[3], 0.99f); // it still absorbs
    }
  // With albedo the same scene is lit; with emission only, it glows with (1 - albedo) sigma k_e.
  p.Albedo = 0.9;
  const Image lit = Render(scene, p, RenderMode::AmbientScattering, LookingDownZ({ 5, 5, 5 }, 20));
  EXPECT_GT(lit.At(4, 4)[0], 0.01f);
  p.Albedo = 0.0;
  p.EmissionWeight = 1.0;
  scene.Lights.clear();
  const Image glow = Render(scene, p, RenderMode::AmbientScattering, LookingDownZ({ 5, 5, 5 }, 20));
  // Eq. 8.7 is a left Riemann sum, L = sum T(t) sigma k_e c dt with T(t + dt) = T(t)
  // exp(-sigma dt): sigma dt / (1 - exp(-sigma dt)) times the opacity 1 - exp(-sigma d).
  // The automatic step is half the smallest spacing, 0.5 here.
  const double sigma = OpacityToExtinction(0.5, 1.0), dt = 0.5;
  EXPECT_NEAR(glow.At(4, 4)[0], sigma * dt / -std::expm1(-sigma * dt) * glow.At(4, 4)[3], 1e-5);
}

TEST(ReferenceRenderer, ForwardScatteringIsBrighterLookingIntoTheLight)
{
  // A thin homogeneous cube lit by a directional light propagating along -z.
  VolumeScene scene = Slab(0.2, 2.0, 10.0, { 1, 1, 1 });
  scene.Lights = { Light::Directional({ 0, 0, -1 }, { 10, 10, 10 }) };
  ScatteringParameters p;
  p.Anisotropy = 0.8;
  p.Albedo = 0.9;
  p.AmbientRadius = 1.0;
  // Looking into the light: camera below the cube looking up (+z).
  Camera into;
  into.Position = { 5, 5, -30 };
  into.FocalPoint = { 5, 5, 5 };
  into.Parallel = true;
  Camera away = LookingDownZ({ 5, 5, 5 }, 30); // above, looking down along the light
  const Image a = Render(scene, p, RenderMode::AmbientScattering, into);
  const Image b = Render(scene, p, RenderMode::AmbientScattering, away);
  EXPECT_GT(a.At(4, 4)[0], 1.5 * b.At(4, 4)[0]);
  // Backward scattering reverses it.
  p.Anisotropy = -0.8;
  const Image c = Render(scene, p, RenderMode::AmbientScattering, into);
  const Image d = Render(scene, p, RenderMode::AmbientScattering, away);
  EXPECT_LT(c.At(4, 4)[0], d.At(4, 4)[0]);
}

TEST(ReferenceRenderer, DirectionMatrixTurnsTheVolumeWithTheCamera)
{
  // A structured volume (a ramp along x) rendered as is, and rotated 90 degrees about z with the
  // camera rotated alike, gives the same picture.
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { 12, 8, 6 };
  g.Spacing = { 0.5, 1.0, 1.5 };
  g.Origin = { 1, 2, 3 };
  scene.Scalars = Grid(g);
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 12; ++i)
        scene.Scalars.At(i, j, k) = static_cast<float>(i * j % 7) / 6.0f;
  scene.Transfer = TransferFunction::Ramp(0.0, 1.0, 0.6, { 0.9, 0.6, 0.3 });
  scene.Lights = { Light::Directional({ 0.3, -0.2, -1 }, { 3, 3, 3 }) };
  Camera camera;
  camera.Position = { 4, 6, 30 };
  camera.FocalPoint = { 4, 5.5, 6 };
  camera.ViewUp = { 0, 1, 0 };
  camera.ViewAngle = 25;
  VolumeScene turned = scene;
  turned.Scalars.Geometry.Direction = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
  auto rotate = [&](const Vec3& v)
  {
    const Vec3 d = v - g.Origin;
    return g.Origin + Vec3{ -d.y, d.x, d.z };
  };
  Camera turnedCamera = camera;
  turnedCamera.Position = rotate(camera.Position);
  turnedCamera.FocalPoint = rotate(camera.FocalPoint);
  turnedCamera.ViewUp = { -1, 0, 0 };
  turned.Lights = { Light::Directional({ 0.2, 0.3, -1 }, { 3, 3, 3 }) };
  for (RenderMode mode : { RenderMode::EmissionAbsorption, RenderMode::AmbientScattering })
  {
    const Image a = Render(scene, ScatteringParameters(), mode, camera, 16);
    const Image b = Render(turned, ScatteringParameters(), mode, turnedCamera, 16);
    double maxDiff = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < a.Pixels.size(); ++i)
    {
      maxDiff = std::max(maxDiff, static_cast<double>(std::abs(a.Pixels[i] - b.Pixels[i])));
      sum += a.Pixels[i];
    }
    EXPECT_GT(sum, 1.0);
    EXPECT_LT(maxDiff, 2e-3);
  }
}

TEST(ReferenceRenderer, PrecomputeRejectsAVolumeWithoutScalars)
{
  VolumeScene scene;
  PrecomputedVolumes volumes;
  std::string error;
  EXPECT_FALSE(Precompute(scene,
    ScatteringParameters().Resolve(scene.Scalars.Geometry),
    &Shipped(),
    RenderMode::EmissionAbsorption,
    volumes,
    &error));
  EXPECT_NE(error.find("no scalars"), std::string::npos);
  VolumeScene slab = Slab(0.5, 1.0, 5.0, { 1, 1, 1 });
  EXPECT_FALSE(Precompute(slab,
    ScatteringParameters().Resolve(slab.Scalars.Geometry),
    nullptr,
    RenderMode::AmbientScattering,
    volumes,
    &error));
  EXPECT_NE(error.find("table"), std::string::npos);
}

TEST(ReferenceRenderer, LightsPerPairWhenTwoStepsSpanAtMostOneLightCell)
{
  GridGeometry light;
  light.Dimensions = { 40, 40, 40 };
  light.Spacing = { 0.05, 0.05, 0.06 };
  EXPECT_GT(ScatteringParameters::LightGroup(0.02, light), 1);
  EXPECT_GT(ScatteringParameters::LightGroup(0.025, light), 1); // two steps: one cell
  EXPECT_EQ(ScatteringParameters::LightGroup(0.03, light), 1);
  EXPECT_EQ(ScatteringParameters::LightGroup(0.0, light), 1);
  // The automatic step on the data's own grid: always in pairs.
  const GridGeometry data = light;
  EXPECT_GT(ScatteringParameters::LightGroup(
              ScatteringParameters().Resolve(data).SampleDistance, data.Capped(128)),
    1);
  EXPECT_GT(ScatteringParameters::LightGroup(
              ScatteringParameters().Resolve(data).SampleDistance, data.Capped(16)),
    1);
}

TEST(ReferenceRenderer, LightGroupOfFourWhenFourStepsSpanAtMostOneLightCell)
{
  GridGeometry light;
  light.Dimensions = { 40, 40, 40 };
  light.Spacing = { 0.05, 0.05, 0.06 };
  EXPECT_EQ(ScatteringParameters::LightGroup(0.01, light), 4);
  EXPECT_EQ(ScatteringParameters::LightGroup(0.0125, light), 4); // four steps: one cell
  EXPECT_EQ(ScatteringParameters::LightGroup(0.013, light), 2);
  EXPECT_EQ(ScatteringParameters::LightGroup(0.025, light), 2);
  EXPECT_EQ(ScatteringParameters::LightGroup(0.03, light), 1);
  EXPECT_EQ(ScatteringParameters::LightGroup(0.0, light), 1);
  // The automatic step (half a voxel): in fours where the light grid is at most half the
  // data's per axis (a 256^3 volume on the default 128^3 light grid), in pairs on the data's
  // own grid.
  GridGeometry data;
  data.Dimensions = { 256, 256, 256 };
  data.Spacing = { 1.0, 1.0, 1.0 };
  const double step = ScatteringParameters().Resolve(data).SampleDistance;
  EXPECT_EQ(ScatteringParameters::LightGroup(step, data.Capped(128)), 4);
  EXPECT_EQ(ScatteringParameters::LightGroup(step, data.Capped(129)), 2);
  EXPECT_EQ(ScatteringParameters::LightGroup(step, data), 2);
}
