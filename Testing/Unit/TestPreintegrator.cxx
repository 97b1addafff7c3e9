// The Monte-Carlo generator: determinism, agreement between seeds within the reported errors,
// the thin-ball limit, and agreement of the shipped table with a fresh low-count run.
#include "PhaseFunction.h"
#include "Preintegrator.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace avs;

namespace
{
PreintegrationSettings Small(std::uint64_t seed)
{
  PreintegrationSettings s;
  s.Axes.NumberOfTheta = 12;
  s.Axes.NumberOfTau = 5;
  s.Axes.TauMaximum = 8.0;
  s.Axes.NumberOfAnisotropy = 3;
  s.Axes.AnisotropyMinimum = -0.6;
  s.Axes.AnisotropyMaximum = 0.6;
  s.Axes.NumberOfAlbedo = 3;
  s.Seed = seed;
  s.BatchSize = 1024;
  s.MinimumPaths = 2048;
  s.MaximumPaths = 2048;
  s.MaximumPathsF = 2048;
  return s;
}

// |a - b| within k combined standard errors (plus a small absolute slack).
void ExpectAgree(double a, double sa, double b, double sb, double k, const std::string& what)
{
  EXPECT_LE(std::abs(a - b), k * std::hypot(sa, sb) + 1e-6 * (std::abs(a) + std::abs(b)) + 1e-9)
    << what << ": " << a << " +- " << sa << " vs " << b << " +- " << sb;
}
} // namespace

TEST(Preintegrator, SameSeedSameTableWhateverTheThreads)
{
  PreintegrationSettings s1 = Small(3);
  s1.Threads = 1;
  PreintegrationSettings s2 = Small(3);
  s2.Threads = 2;
  const ScatteringTable a = Preintegrate(s1);
  const ScatteringTable b = Preintegrate(s2);
  EXPECT_EQ(a.A, b.A);
  EXPECT_EQ(a.F, b.F);
  EXPECT_EQ(a.AError, b.AError);
}

TEST(Preintegrator, TwoSeedsAgreeWithinTheirErrors)
{
  const ScatteringTable a = Preintegrate(Small(1));
  const ScatteringTable b = Preintegrate(Small(2));
  ASSERT_NE(a.A, b.A);
  for (std::size_t i = 0; i < a.A.size(); ++i)
  {
    ExpectAgree(a.A[i], a.AError[i], b.A[i], b.AError[i], 5.0, "A[" + std::to_string(i) + "]");
  }
  for (std::size_t i = 0; i < a.F.size(); ++i)
  {
    ExpectAgree(a.F[i], a.FError[i], b.F[i], b.FError[i], 5.0, "F[" + std::to_string(i) + "]");
  }
  EXPECT_EQ(a.PathsA[a.CellIndex(1, 0)], 2048u);
}

TEST(Preintegrator, ThinBallIsSingleScatteringAndOpaqueBallBlocksTheBeam)
{
  PreintegrationSettings s = Small(9);
  // tau nodes 0, 5e-5, 1e-4, ...: thin enough that double scattering, which for |g| = 0.6
  // exceeds weak single back-scattering by a factor ~ 10 tau / p(pi), stays below 0.1 %.
  s.Axes.TauMaximum = 0.0002;
  s.Axes.NumberOfAlbedo = 2;
  const ScatteringTable t = Preintegrate(s);
  const auto& ax = t.Axes;
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
    for (int i = 0; i < ax.NumberOfTheta; ++i)
    {
      const double single = HenyeyGreenstein(std::cos(ax.Theta(i)), ax.Anisotropy(k));
      const double a = t.A[t.AIndex(i, 1, k, 1)];
      // Attenuation inside the ball and higher orders are O(tau).
      EXPECT_NEAR(a, single, 0.01 * single + 5 * t.AError[t.AIndex(i, 1, k, 1)]);
      EXPECT_EQ(t.A[t.AIndex(i, 1, k, 0)], 0.0f); // albedo 0: no scattering
    }
  for (int j = 0; j < ax.NumberOfTau; ++j)
  {
    EXPECT_FLOAT_EQ(t.F[t.FIndex(j, 1, 0)], static_cast<float>(std::exp(-2.0 * ax.Tau(j))));
  }
}

TEST(Preintegrator, ShippedTableAgreesWithAFreshLowCountRun)
{
  ScatteringTable shipped;
  std::string error;
  ASSERT_TRUE(shipped.Read(AVS_SOURCE_TABLE_PATH, &error)) << error;
  PreintegrationSettings s;
  s.Axes = shipped.Axes;
  s.Seed = 424242;
  s.BatchSize = 1024;
  s.MinimumPaths = 2048;
  s.MaximumPaths = 2048;
  s.MaximumPathsF = 2048;
  // A few cells across the table: thin, medium and thick balls; backward, isotropic, forward.
  const int nTau = shipped.Axes.NumberOfTau, nG = shipped.Axes.NumberOfAnisotropy;
  s.Cells = { { nTau / 6, nG / 4 }, { nTau / 2, nG / 2 }, { (5 * nTau) / 6, (3 * nG) / 4 } };
  const ScatteringTable fresh = Preintegrate(s);
  for (const auto& [j, k] : s.Cells)
  {
    for (int l = 0; l < shipped.Axes.NumberOfAlbedo; ++l)
    {
      for (int i = 0; i < shipped.Axes.NumberOfTheta; ++i)
      {
        const std::size_t e = shipped.AIndex(i, j, k, l);
        ExpectAgree(shipped.A[e],
          shipped.AError[e],
          fresh.A[e],
          fresh.AError[e],
          5.0,
          "A cell " + std::to_string(j) + "," + std::to_string(k));
      }
      const std::size_t f = shipped.FIndex(j, k, l);
      ExpectAgree(shipped.F[f], shipped.FError[f], fresh.F[f], fresh.FError[f], 5.0, "F");
    }
  }
}

TEST(Preintegrator, RefiningRecomputesOnlyTheCellsThatMissTheTarget)
{
  PreintegrationSettings first = Small(5);
  first.TargetRelativeError = 0.03;
  const ScatteringTable earlier = Preintegrate(first);

  PreintegrationSettings more = first;
  more.MaximumPaths = 8192;
  more.MaximumPathsF = 8192;
  PreintegrationStatistics stats;
  more.Refine = &earlier;
  const ScatteringTable refined = Preintegrate(more, &stats);
  more.Refine = nullptr;
  const ScatteringTable single = Preintegrate(more);

  const auto& ax = earlier.Axes;
  std::size_t kept = 0, redone = 0;
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
  {
    for (int j = 0; j < ax.NumberOfTau; ++j)
    {
      const bool meets = CellMeetsTarget(earlier, j, k, first.SignificanceThreshold, 0.03);
      (meets ? kept : redone) += 1;
      const std::size_t c = earlier.CellIndex(j, k);
      EXPECT_EQ(refined.PathsF[c], meets ? earlier.PathsF[c] : single.PathsF[c]);
      for (int l = 0; l < ax.NumberOfAlbedo; ++l)
      {
        const std::size_t f = earlier.FIndex(j, k, l);
        // Refining gives what one run with the larger budget gives, cell for cell.
        EXPECT_EQ(refined.F[f], single.F[f]);
        EXPECT_EQ(refined.FError[f], single.FError[f]);
        for (int i = 0; i < ax.NumberOfTheta; ++i)
        {
          const std::size_t e = earlier.AIndex(i, j, k, l);
          EXPECT_EQ(refined.A[e], single.A[e]);
          if (meets)
          {
            EXPECT_EQ(refined.A[e], earlier.A[e]);
          }
        }
      }
    }
  }
  // Both kinds of cell occur, and only the redone ones were traced.
  EXPECT_GT(kept, 0u);
  EXPECT_GT(redone, 0u);
  EXPECT_EQ(stats.CellsComputed, redone + ax.NumberOfAnisotropy); // plus the analytic tau = 0
  EXPECT_LT(refined.MaximumRelativeErrorF(), earlier.MaximumRelativeErrorF());

  // A table with other axes is not used.
  PreintegrationSettings other = Small(5);
  other.Axes.NumberOfTheta = 10;
  other.Refine = &earlier;
  PreintegrationStatistics otherStats;
  Preintegrate(other, &otherStats);
  EXPECT_EQ(otherStats.CellsComputed,
    static_cast<std::size_t>(other.Axes.NumberOfTau * other.Axes.NumberOfAnisotropy));
}

TEST(Preintegrator, ACheckpointResumesToTheSameTable)
{
  PreintegrationSettings s = Small(6);
  s.Threads = 1;
  s.TargetRelativeError = 0.2; // finished cells meet it, so resuming skips them
  const ScatteringTable whole = Preintegrate(s);

  // Checkpoints after every cell; keep the third one as a run cut short.
  PreintegrationSettings cut = s;
  cut.CheckpointSeconds = 0.0;
  std::vector<ScatteringTable> checkpoints;
  cut.Checkpoint = [&](const ScatteringTable& t) { checkpoints.push_back(t); };
  Preintegrate(cut);
  ASSERT_GE(checkpoints.size(), 3u);
  const ScatteringTable& partial = checkpoints[2];
  // Loadable: unfinished cells have F = 1 and no paths.
  std::string error;
  ScatteringTable reread;
  ASSERT_TRUE(reread.ReadFromMemory(partial.Serialize(), &error)) << error;

  PreintegrationSettings resume = s;
  resume.Refine = &partial;
  PreintegrationStatistics stats;
  const ScatteringTable resumed = Preintegrate(resume, &stats);
  EXPECT_LT(
    stats.CellsComputed, static_cast<std::size_t>(s.Axes.NumberOfTau * s.Axes.NumberOfAnisotropy));
  EXPECT_EQ(resumed.A, whole.A);
  EXPECT_EQ(resumed.F, whole.F);
  EXPECT_EQ(resumed.FError, whole.FError);
}
