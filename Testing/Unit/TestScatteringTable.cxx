// The shipped scattering table: resolution, analytic limits, monotonicity, interpolation, and
// the loader's rejection of broken files.
#include "PhaseFunction.h"
#include "ScatteringTable.h"

#include "ShippedTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

using namespace avs;

namespace
{
std::string TempFile(const char* name)
{
  return std::string(::testing::TempDir()) + "/" + name;
}

void WriteBytes(const std::string& path, const std::vector<unsigned char>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

ScatteringTable SmallTable()
{
  ScatteringTableAxes ax;
  ax.NumberOfTheta = 5;
  ax.NumberOfTau = 4;
  ax.NumberOfAnisotropy = 3;
  ax.NumberOfAlbedo = 2;
  ScatteringTable t;
  t.Allocate(ax);
  for (std::size_t i = 0; i < t.A.size(); ++i)
  {
    t.A[i] = 0.01f * static_cast<float>(i);
    t.AError[i] = 0.001f;
  }
  for (std::size_t i = 0; i < t.F.size(); ++i)
  {
    t.F[i] = 0.5f;
    t.FError[i] = 0.01f;
  }
  t.Seed = 42;
  return t;
}
} // namespace

TEST(ScatteringTable, ShippedTableHasTheResolutionAlgorithmMdAsksFor)
{
  const auto& ax = Shipped().Axes;
  EXPECT_GE(ax.NumberOfTheta, 64);
  EXPECT_GE(ax.TauMaximum, 32.0);
  EXPECT_LE(ax.AnisotropyMinimum, -0.95);
  EXPECT_GE(ax.AnisotropyMaximum, 0.95);
  EXPECT_LE(
    (ax.AnisotropyMaximum - ax.AnisotropyMinimum) / (ax.NumberOfAnisotropy - 1), 0.1 + 1e-12);
  EXPECT_GE(ax.NumberOfAlbedo, 8);
  EXPECT_EQ(ax.Theta(0), 0.0);
  EXPECT_NEAR(ax.Theta(ax.NumberOfTheta - 1), Pi, 1e-12);
  // Denser near theta = 0 than near pi.
  EXPECT_LT(
    ax.Theta(1) - ax.Theta(0), ax.Theta(ax.NumberOfTheta - 1) - ax.Theta(ax.NumberOfTheta - 2));
  EXPECT_EQ(ax.Tau(0), 0.0);
  EXPECT_NEAR(ax.Tau(ax.NumberOfTau - 1), ax.TauMaximum, 1e-9);
}

TEST(ScatteringTable, ThinBallGivesSingleScatteringAtTheNodes)
{
  const auto& t = Shipped();
  const auto& ax = t.Axes;
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
    for (int l = 0; l < ax.NumberOfAlbedo; ++l)
      for (int i = 0; i < ax.NumberOfTheta; ++i)
      {
        const double expected =
          ax.Albedo(l) * HenyeyGreenstein(std::cos(ax.Theta(i)), ax.Anisotropy(k));
        EXPECT_NEAR(t.A[t.AIndex(i, 0, k, l)], expected, 1e-6 * (1 + expected));
        EXPECT_NEAR(t.InScattering(ax.Theta(i), 0.0, ax.Anisotropy(k), ax.Albedo(l)),
          expected,
          1e-5 * (1 + expected));
      }
  // Between theta nodes the interpolation stays close to the phase function.
  for (double theta : { 0.3, 1.0, 2.0, 3.0 })
  {
    const double expected = 0.5 * HenyeyGreenstein(std::cos(theta), 0.45);
    EXPECT_NEAR(t.InScattering(theta, 0.0, 0.45, 0.5), expected, 0.02 * expected);
  }
}

TEST(ScatteringTable, ForwardTransportLimits)
{
  const auto& t = Shipped();
  for (double g : { -0.95, -0.3, 0.0, 0.55, 0.95 })
  {
    EXPECT_DOUBLE_EQ(t.ForwardTransport(0.0, g, 0.7), 1.0);
    for (double tau : { 0.01, 0.37, 1.0, 4.2, 17.0, 31.0 })
    {
      // Albedo 0: only the direct beam crosses the ball, exactly, also between nodes.
      EXPECT_NEAR(
        t.ForwardTransport(tau, g, 0.0), std::exp(-2.0 * tau), 1e-6 * std::exp(-2.0 * tau))
        << "tau " << tau;
    }
  }
  const ScatteringSlice slice = t.Slice(0.2, 0.0);
  EXPECT_NEAR(slice.ForwardTransport(2.5), std::exp(-5.0), 1e-6 * std::exp(-5.0));
  EXPECT_DOUBLE_EQ(slice.ForwardTransport(0.0), 1.0);
}

TEST(ScatteringTable, ForwardTransportIsMonotone)
{
  const auto& t = Shipped();
  const auto& ax = t.Axes;
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
    for (int l = 0; l < ax.NumberOfAlbedo; ++l)
      for (int j = 1; j < ax.NumberOfTau; ++j)
      {
        // Non-increasing in tau, within the Monte-Carlo errors.
        const std::size_t a = t.FIndex(j - 1, k, l), b = t.FIndex(j, k, l);
        const double slack = 4.0 * std::hypot(t.FError[a], t.FError[b]) + 1e-7;
        EXPECT_LE(t.F[b], t.F[a] + slack)
          << "g " << ax.Anisotropy(k) << " albedo " << ax.Albedo(l) << " tau " << ax.Tau(j);
        // Non-decreasing in the albedo: exact, every albedo shares the same paths.
        if (l > 0)
        {
          EXPECT_GE(t.F[t.FIndex(j, k, l)], t.F[t.FIndex(j, k, l - 1)]);
        }
      }
  // Interpolated lookups are monotone in the albedo too.
  for (double albedo = 0.05; albedo < 1.0; albedo += 0.1)
  {
    EXPECT_GE(t.ForwardTransport(3.3, 0.4, albedo + 0.05), t.ForwardTransport(3.3, 0.4, albedo));
  }
}

TEST(ScatteringTable, InScatteringIsNonNegativeAndFinite)
{
  const auto& t = Shipped();
  for (std::size_t i = 0; i < t.A.size(); ++i)
  {
    ASSERT_GE(t.A[i], 0.0f);
    ASSERT_TRUE(std::isfinite(t.A[i]));
    ASSERT_GE(t.AError[i], 0.0f);
  }
  EXPECT_GT(t.InScattering(0.2, 1.0, 0.5, 0.9), 0.0);
}

// Found by the table fuzzer: std::clamp passes NaN on, and the int cast of the node index then
// read outside the table. A NaN coordinate now takes the first node.
TEST(ScatteringTable, NaNArgumentsTakeTheFirstNode)
{
  const auto& t = Shipped();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(t.InScattering(nan, 1.0, 0.5, 0.9), t.InScattering(0.0, 1.0, 0.5, 0.9));
  EXPECT_EQ(t.InScattering(0.2, nan, 0.5, 0.9), t.InScattering(0.2, 0.0, 0.5, 0.9));
  EXPECT_EQ(t.ForwardTransport(1.0, nan, 0.9), t.ForwardTransport(1.0, -0.95, 0.9));
  EXPECT_EQ(t.ForwardTransport(1.0, 0.5, nan), t.ForwardTransport(1.0, 0.5, 0.0));
  const ScatteringSlice slice = t.Slice(nan, nan);
  EXPECT_TRUE(std::isfinite(slice.InScattering(nan, nan)));
  EXPECT_TRUE(std::isfinite(slice.ForwardTransport(nan)));
}

TEST(ScatteringTable, SliceMatchesTheFullInterpolation)
{
  const auto& t = Shipped();
  for (double g : { -0.62, 0.0, 0.33, 0.95 })
    for (double albedo : { 0.0, 0.31, 0.9, 1.0 })
    {
      const ScatteringSlice s = t.Slice(g, albedo);
      for (double theta : { 0.0, 0.05, 0.8, 2.9 })
        for (double tau : { 0.0, 0.2, 3.0, 30.0 })
        {
          const double full = t.InScattering(theta, tau, g, albedo);
          EXPECT_NEAR(s.InScattering(theta, tau), full, 1e-5 * (1 + full));
          EXPECT_NEAR(s.InScatteringCos(std::cos(theta), tau), full, 1e-4 * (1 + full));
        }
      for (double tau : { 0.0, 0.2, 3.0, 30.0 })
      {
        const double f = t.ForwardTransport(tau, g, albedo);
        EXPECT_NEAR(s.ForwardTransport(tau), f, 1e-5 * f);
      }
    }
}

TEST(ScatteringTable, WriteReadRoundTrip)
{
  const ScatteringTable t = SmallTable();
  const std::string path = TempFile("roundtrip.avst");
  std::string error;
  ASSERT_TRUE(t.Write(path, &error)) << error;
  ScatteringTable u;
  ASSERT_TRUE(u.Read(path, &error)) << error;
  EXPECT_TRUE(u.Axes == t.Axes);
  EXPECT_EQ(u.A, t.A);
  EXPECT_EQ(u.F, t.F);
  EXPECT_EQ(u.AError, t.AError);
  EXPECT_EQ(u.Seed, 42u);
  EXPECT_EQ(u.Generator, ScatteringTable::GeneratorVersion);
}

TEST(ScatteringTable, LoaderRejectsBrokenFiles)
{
  const ScatteringTable good = SmallTable();
  const std::vector<unsigned char> bytes = good.Serialize();
  ScatteringTable t;
  std::string error;
  auto rejects = [&](const std::vector<unsigned char>& b, const std::string& expected)
  {
    error.clear();
    const bool ok = t.ReadFromMemory(b, &error);
    EXPECT_FALSE(ok);
    EXPECT_NE(error.find(expected), std::string::npos) << "message was: " << error;
  };
  ASSERT_TRUE(t.ReadFromMemory(bytes, &error)) << error;

  rejects({}, "too short");
  // Truncated anywhere: in the header (each says so), in the data, by one byte.
  for (std::size_t keep : { std::size_t(20), std::size_t(60), bytes.size() / 2, bytes.size() - 1 })
  {
    rejects(std::vector<unsigned char>(bytes.begin(), bytes.begin() + keep),
      keep < 100 ? "truncated header" : "truncated");
  }
  auto corrupted = bytes;
  corrupted[bytes.size() / 2] ^= 0x5a;
  rejects(corrupted, "checksum");
  auto badMagic = bytes;
  badMagic[0] = 'X';
  rejects(badMagic, "magic");
  // A later version with a valid checksum is still refused.
  auto newer = bytes;
  newer[8] = 99;
  const std::uint64_t sum = Fnv1a64(newer.data(), newer.size() - 8);
  for (int b = 0; b < 8; ++b)
  {
    newer[newer.size() - 8 + b] = static_cast<unsigned char>(sum >> (8 * b));
  }
  rejects(newer, "version");
  auto longer = bytes;
  longer.push_back(0);
  rejects(longer, "size mismatch");
  // The previously loaded table is kept after a failure.
  EXPECT_EQ(t.Axes.NumberOfTheta, 5);

  EXPECT_FALSE(t.Read(TempFile("does-not-exist.avst"), &error));
  EXPECT_NE(error.find("cannot open"), std::string::npos);
  WriteBytes(TempFile("empty.avst"), {});
  EXPECT_FALSE(t.Read(TempFile("empty.avst"), &error));
  EXPECT_NE(error.find("too short"), std::string::npos);
}
