// The display transform (Core/DisplayTransform.h): the exposure is a factor, the clamp curve
// leaves the radiance as it is, the shoulder is the identity below its start, continuous with
// a continuous slope there, increasing, below 1 everywhere (nothing can saturate), and keeps
// the ratios of the channels (hue and saturation); the auto-exposure meter follows the lights'
// luminance at the medium and nothing else.
#include "DisplayTransform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
using avs::DisplayTransform;
using avs::Vec3;

DisplayTransform Shoulder(double exposure = 1.0)
{
  DisplayTransform d;
  d.Exposure = exposure;
  d.Curve = avs::ToneMapping::Shoulder;
  return d;
}

double Luminance(const Vec3& e)
{
  return 0.2126 * e.x + 0.7152 * e.y + 0.0722 * e.z;
}
} // namespace

TEST(DisplayTransform, ClampIsTheExposureAlone)
{
  DisplayTransform d;
  EXPECT_TRUE(d.IsIdentity());
  const Vec3 x{ 0.3, 1.7, 12.0 };
  const Vec3 y = d.Apply(x);
  EXPECT_EQ(y.x, x.x);
  EXPECT_EQ(y.y, x.y);
  EXPECT_EQ(y.z, x.z);
  d.Exposure = 0.25;
  EXPECT_FALSE(d.IsIdentity());
  EXPECT_DOUBLE_EQ(d.Apply(x).z, 3.0);
}

TEST(DisplayTransform, ShoulderIsTheIdentityBelowItsStart)
{
  const double s = DisplayTransform::ShoulderStart;
  for (double m = 0.0; m <= s; m += s / 64)
  {
    EXPECT_DOUBLE_EQ(DisplayTransform::Shoulder(m), m);
  }
  const Vec3 dark{ 0.1, 0.2, s * 0.99 };
  const Vec3 out = Shoulder().Apply(dark);
  EXPECT_DOUBLE_EQ(out.z, dark.z);
}

TEST(DisplayTransform, ShoulderIsSmoothIncreasingAndBelowOne)
{
  const double s = DisplayTransform::ShoulderStart;
  const double h = 1e-6;
  // Value and slope continuous at the start (slope 1 on both sides).
  EXPECT_NEAR(DisplayTransform::Shoulder(s + h), s + h, 1e-9);
  EXPECT_NEAR((DisplayTransform::Shoulder(s + h) - DisplayTransform::Shoulder(s)) / h, 1.0, 1e-5);
  double previous = DisplayTransform::Shoulder(s);
  for (double m = s + 0.01; m < 1e6; m *= 1.05)
  {
    const double v = DisplayTransform::Shoulder(m);
    EXPECT_GT(v, previous) << m;
    EXPECT_LT(v, 1.0) << m;
    previous = v;
  }
  // ... and it does approach 1: highlights are compressed, not clipped below white.
  EXPECT_GT(DisplayTransform::Shoulder(1e6), 0.9999);
  // A radiance 8x the start still maps below 254.5 / 255 (no 8-bit saturation).
  EXPECT_LT(DisplayTransform::Shoulder(8.0 * s) * 255.0, 254.5);
}

TEST(DisplayTransform, ShoulderKeepsHueAndSaturation)
{
  // Bright saturated colours: the channels keep their ratios, none reaches 1.
  for (const Vec3& c : { Vec3{ 3.0, 1.2, 0.3 }, Vec3{ 0.2, 9.0, 4.0 }, Vec3{ 40.0, 40.0, 1.0 } })
  {
    const Vec3 out = Shoulder(0.5).Apply(c);
    EXPECT_LT(std::max({ out.x, out.y, out.z }), 1.0);
    EXPECT_NEAR(out.x / out.y, c.x / c.y, 1e-12);
    EXPECT_NEAR(out.z / out.y, c.z / c.y, 1e-12);
  }
  // A curve per channel would have whitened the orange (3, 1.2, 0.3): here it stays orange.
  const Vec3 orange = Shoulder().Apply({ 3.0, 1.2, 0.3 });
  EXPECT_NEAR(orange.y / orange.x, 0.4, 1e-12);
}

TEST(DisplayTransform, ExposureComesBeforeTheCurve)
{
  const Vec3 c{ 2.0, 1.0, 0.5 };
  const Vec3 a = Shoulder(0.5).Apply(c);
  const Vec3 b = Shoulder(1.0).Apply(c * 0.5);
  EXPECT_DOUBLE_EQ(a.x, b.x);
  EXPECT_DOUBLE_EQ(a.z, b.z);
}

TEST(AutoExposure, OneWhiteLightOfIntensityOneMetersOne)
{
  const Vec3 low{ -1, -1, -1 }, high{ 1, 1, 1 };
  const Vec3 white = Vec3{ 1, 1, 1 } * (4.0 * avs::Pi);
  const avs::Light sun = avs::Light::Directional({ 0, 0, -1 }, white);
  EXPECT_NEAR(avs::AutoExposureFactor({ sun }, low, high), 1.0, 1e-12);
  // Its direction does not matter (a headlight turning with the camera meters the same).
  for (const Vec3& d : { Vec3{ 1, 0, 0 }, Vec3{ 0.3, -0.8, 0.5 }, Vec3{ -1, -1, -1 } })
  {
    EXPECT_NEAR(
      avs::AutoExposureFactor({ avs::Light::Directional(d, white) }, low, high), 1.0, 1e-12);
  }
  // Intensity 40, or two of them, meter 1/40 and 1/2; colour by its luminance.
  EXPECT_NEAR(
    avs::AutoExposureFactor({ avs::Light::Directional({ 0, 0, -1 }, white * 40.0) }, low, high),
    1.0 / 40.0,
    1e-12);
  EXPECT_NEAR(avs::AutoExposureFactor({ sun, sun }, low, high), 0.5, 1e-12);
  const Vec3 warm = Vec3{ 1.0, 0.5, 0.2 } * (4.0 * avs::Pi);
  EXPECT_NEAR(avs::AutoExposureFactor({ avs::Light::Directional({ 0, 0, -1 }, warm) }, low, high),
    1.0 / Luminance({ 1.0, 0.5, 0.2 }),
    1e-12);
  // No light: 1.
  EXPECT_EQ(avs::AutoExposureFactor({}, low, high), 1.0);
}

TEST(AutoExposure, PositionalLightsMeterTheirFalloffOverTheBox)
{
  const Vec3 white = Vec3{ 1, 1, 1 } * (4.0 * avs::Pi);
  // No attenuation: as a directional light.
  EXPECT_NEAR(
    avs::AutoExposureFactor({ avs::Light::Point({ 0, 0, 5 }, white) }, { -1, -1, -1 }, { 1, 1, 1 }),
    1.0,
    1e-12);
  // Quadratic falloff: farther away, less light received, a larger factor; the mean over the box
  // is what the box receives (the light at its centre, a0 = 0: one point is infinite and left out).
  const avs::Light near = avs::Light::Point({ 0, 0, 3 }, white, { 0, 0, 1 });
  const avs::Light far = avs::Light::Point({ 0, 0, 6 }, white, { 0, 0, 1 });
  const double a = avs::AutoExposureFactor({ near }, { -1, -1, -1 }, { 1, 1, 1 });
  const double b = avs::AutoExposureFactor({ far }, { -1, -1, -1 }, { 1, 1, 1 });
  EXPECT_GT(b, 3.0 * a);
  const double inside = avs::AutoExposureFactor(
    { avs::Light::Point({ 0, 0, 0 }, white, { 0, 0, 1 }) }, { -1, -1, -1 }, { 1, 1, 1 });
  EXPECT_TRUE(std::isfinite(inside));
  EXPECT_GT(inside, 0.0);
}
