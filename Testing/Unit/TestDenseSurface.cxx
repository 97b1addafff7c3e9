// No bands on dense, surface-like media: ambient scattering of a dense fog sphere (a level set
// turned fog volume, opacity 0.9 per voxel) under one directional light has no more
// high-frequency energy along its lit surface than the path tracer's picture of it. Tube marching
// counted from where the light enters the box put zebra bands of period 2r along the light on
// such surfaces (ARCHITECTURE.md, "Light volumes"): relative high-frequency energy 2.3e-3, the
// truth's 0 within its noise; the tube counted from the receiving point leaves 1.9e-4, the
// voxel-scale structure of the trilinearly interpolated fog.
#include "PathTracer.h"
#include "ReferenceRenderer.h"

#include "HighFrequencyEnergy.h"
#include "ShippedTable.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace avs;

namespace
{
constexpr int Size = 128;

// A sphere of radius 0.6 in [-1, 1]^3 as OpenVDB's sdfToFogVolume makes it from a level set:
// 0 outside, rising linearly to 1 over `band` inside.
VolumeScene DenseFogSphere(int n)
{
  VolumeScene scene;
  GridGeometry g;
  g.Dimensions = { n, n, n };
  g.Origin = { -1, -1, -1 };
  const double h = 2.0 / (n - 1), band = 0.05;
  g.Spacing = { h, h, h };
  scene.Scalars = Grid(g);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double sdf = Length(g.IndexToWorld({ double(i), double(j), double(k) })) - 0.6;
        scene.Scalars.At(i, j, k) = static_cast<float>(std::clamp(-sdf / band, 0.0, 1.0));
      }
  // Peak opacity 0.9 per voxel.
  scene.Transfer = TransferFunction::Ramp(0.0, 1.0, 0.9, { 1, 1, 1 }, 1024);
  scene.UnitDistance = h;
  scene.Lights.push_back(Light::Directional({ 1.0, -0.4, -0.5 }, { 10, 10, 10 }));
  return scene;
}

Camera Front()
{
  Camera c;
  c.Position = { 0, 0, 5 };
  c.FocalPoint = { 0, 0, 0 };
  c.Parallel = true;
  c.ParallelScale = 0.7;
  return c;
}

Picture Luminance(const Image& image)
{
  Picture out{ image.Width, image.Height, std::vector<double>(Size * Size) };
  for (int i = 0; i < Size * Size; ++i)
  {
    const float* p = &image.Pixels[4 * i];
    out.Values[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
  return out;
}
} // namespace

TEST(DenseSurface, NoMoreHighFrequencyAlongTheLitSurfaceThanThePathTracer)
{
  const VolumeScene scene = DenseFogSphere(96);
  ScatteringParameters p;
  p.Albedo = 0.9;
  const ScatteringParameters resolved = p.Resolve(scene.Scalars.Geometry);
  PrecomputedVolumes volumes;
  std::string error;
  ASSERT_TRUE(
    Precompute(scene, resolved, &Shipped(), RenderMode::AmbientScattering, volumes, &error))
    << error;
  const Image as =
    RenderReference(scene, resolved, volumes, RenderMode::AmbientScattering, Front(), Size, Size);
  // The truth twice, with different seeds: the high-frequency energy of their half difference is
  // that of the noise in their mean, which is subtracted.
  PathTracerSettings settings;
  settings.SamplesPerPixel = 128;
  settings.Seed = 1;
  const Image truthA = RenderPathTraced(scene, resolved, settings, Front(), Size, Size);
  settings.Seed = 2;
  const Image truthB = RenderPathTraced(scene, resolved, settings, Front(), Size, Size);

  // The lit surface, opaque within the blur's reach. The bands' period 2r is 10 pixels.
  const double s = 2.0;
  const Picture ambient = Luminance(as);
  std::vector<bool> opaque(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    opaque[i] = as.Pixels[4 * i + 3] > 0.99f;
  }
  const std::vector<bool> mask =
    LitRegion(ambient, opaque, static_cast<int>(std::ceil(3.0 * s)) + 2);
  const auto pixels = std::count(mask.begin(), mask.end(), true);
  ASSERT_GT(pixels, 3000);

  const Picture a = Luminance(truthA), b = Luminance(truthB);
  Picture mean = a, half = a;
  for (int i = 0; i < Size * Size; ++i)
  {
    mean.Values[i] = 0.5 * (a.Values[i] + b.Values[i]);
    half.Values[i] = 0.5 * (a.Values[i] - b.Values[i]);
  }
  // Relative to each picture's own energy there.
  const double noise = HighFrequencyEnergy(half, mask, s) / Energy(mean, mask);
  const double truth = HighFrequencyEnergy(mean, mask, s) / Energy(mean, mask) - noise;
  const double measured = HighFrequencyEnergy(ambient, mask, s) / Energy(ambient, mask);
  std::cout << "relative high-frequency energy on the lit surface (" << pixels
            << " pixels): ambient scattering " << measured << ", path tracer " << truth
            << " (its noise " << noise << " subtracted)\n";
  // The truth's picture of a sphere is smooth.
  EXPECT_LT(std::abs(truth), 2e-4);
  // Ambient scattering may keep the voxel-scale structure of the fog it reads at each sample,
  // 1.4 % RMS of the radiance; the bands were 4.8 %.
  EXPECT_LT(measured - truth, 5e-4);
}
