// avs-preintegrate: generates the preintegrated scattering table (ALGORITHM.md section 4).
//
//   avs-preintegrate [options] OUTPUT.avst
//
// Run with --help for the options. The shipped table Data/scattering_table.avst was made with
// the defaults (Documentation/ScatteringTable.md has the command and how long it took).
#include "Parallel.h"
#include "Preintegrator.h"
#include "ScatteringTable.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{

void PrintHelp(const avs::PreintegrationSettings& d)
{
  std::printf(
    "Usage: avs-preintegrate [options] OUTPUT\n"
    "\n"
    "Generates the preintegrated ambient-scattering table: the in-scattering table\n"
    "A(theta; tau, g, albedo) and the forward transport factor F(tau, g, albedo) of a homogeneous\n"
    "ball lit by a directional light, by Monte-Carlo backward path tracing with next-event\n"
    "estimation (ALGORITHM.md section 4). Writes a versioned binary file with a checksum, which\n"
    "vtkAmbientScatteringTable and the mappers load.\n"
    "\n"
    "Options (defaults in brackets):\n"
    "  --theta N          theta nodes on [0, pi], quadratic spacing (denser near 0) [%d]\n"
    "  --tau N            optical-radius nodes on [0, tau-max], uniform in log(1 + tau) [%d]\n"
    "  --tau-max X        largest optical radius r * sigma_t [%g]\n"
    "  --g N              anisotropy nodes on [-0.95, 0.95] [%d]\n"
    "  --albedo N         albedo nodes on [0, 1] [%d]\n"
    "  --seed S           random seed; the same seed gives the same file [%llu]\n"
    "  --batch N          paths per batch and cell [%llu]\n"
    "  --min-paths N      paths per cell before the error is checked [%llu]\n"
    "  --max-paths N      path budget per cell for A [%llu]\n"
    "  --max-paths-f N    path budget per cell for F [%llu]\n"
    "  --target-error X   stop a cell when every significant entry has a relative standard\n"
    "                     error below X [%g]\n"
    "  --threshold X      an entry is significant when it is at least X times the largest value\n"
    "                     of A (or of F) in the table [%g]\n"
    "  --threads N        worker threads (0: all cores, or AVS_NUM_THREADS) [0]\n"
    "  --refine TABLE     start from an earlier table with the same axes: copy its cells whose\n"
    "                     significant entries all meet --target-error, compute the others again\n"
    "                     with these options (e.g. a larger --max-paths-f); OUTPUT may be TABLE\n"
    "  --checkpoint S     write OUTPUT every S seconds while running (0: only at the end); a\n"
    "                     run cut short resumes with --refine OUTPUT [%g]\n"
    "  --quiet            no progress display\n"
    "  --help             this text\n"
    "\n"
    "The progress display goes to standard error. At the end the program reports the largest\n"
    "relative standard error of the significant entries of A and F, and the time taken.\n",
    d.Axes.NumberOfTheta,
    d.Axes.NumberOfTau,
    d.Axes.TauMaximum,
    d.Axes.NumberOfAnisotropy,
    d.Axes.NumberOfAlbedo,
    static_cast<unsigned long long>(d.Seed),
    static_cast<unsigned long long>(d.BatchSize),
    static_cast<unsigned long long>(d.MinimumPaths),
    static_cast<unsigned long long>(d.MaximumPaths),
    static_cast<unsigned long long>(d.MaximumPathsF),
    d.TargetRelativeError,
    d.SignificanceThreshold,
    d.CheckpointSeconds);
}

bool ParseNumber(const char* text, double& out)
{
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end && *end == '\0' && end != text;
}

} // namespace

int main(int argc, char* argv[])
{
  avs::PreintegrationSettings settings;
  std::string output;
  std::string refineFile;
  bool quiet = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      PrintHelp(settings);
      return 0;
    }
    if (arg == "--quiet")
    {
      quiet = true;
      continue;
    }
    if (arg == "--refine")
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "avs-preintegrate: option --refine needs a table file\n");
        return 2;
      }
      refineFile = argv[++i];
      continue;
    }
    if (arg.rfind("--", 0) == 0)
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "avs-preintegrate: option %s needs a value\n", arg.c_str());
        return 2;
      }
      double v = 0;
      if (!ParseNumber(argv[++i], v) || v < 0)
      {
        std::fprintf(stderr, "avs-preintegrate: bad value '%s' for %s\n", argv[i], arg.c_str());
        return 2;
      }
      if (arg == "--theta")
        settings.Axes.NumberOfTheta = static_cast<int>(v);
      else if (arg == "--tau")
        settings.Axes.NumberOfTau = static_cast<int>(v);
      else if (arg == "--tau-max")
        settings.Axes.TauMaximum = v;
      else if (arg == "--g")
        settings.Axes.NumberOfAnisotropy = static_cast<int>(v);
      else if (arg == "--albedo")
        settings.Axes.NumberOfAlbedo = static_cast<int>(v);
      else if (arg == "--seed")
        settings.Seed = static_cast<std::uint64_t>(v);
      else if (arg == "--batch")
        settings.BatchSize = static_cast<std::uint64_t>(v);
      else if (arg == "--min-paths")
        settings.MinimumPaths = static_cast<std::uint64_t>(v);
      else if (arg == "--max-paths")
        settings.MaximumPaths = static_cast<std::uint64_t>(v);
      else if (arg == "--max-paths-f")
        settings.MaximumPathsF = static_cast<std::uint64_t>(v);
      else if (arg == "--target-error")
        settings.TargetRelativeError = v;
      else if (arg == "--threshold")
        settings.SignificanceThreshold = v;
      else if (arg == "--checkpoint")
        settings.CheckpointSeconds = v;
      else if (arg == "--threads")
        settings.Threads = static_cast<int>(v);
      else
      {
        std::fprintf(stderr, "avs-preintegrate: unknown option %s (see --help)\n", arg.c_str());
        return 2;
      }
      continue;
    }
    if (!output.empty())
    {
      std::fprintf(stderr, "avs-preintegrate: more than one output file given\n");
      return 2;
    }
    output = arg;
  }
  if (output.empty())
  {
    std::fprintf(stderr, "avs-preintegrate: no output file (see --help)\n");
    return 2;
  }
  const std::string problem = settings.Axes.Validate();
  if (!problem.empty())
  {
    std::fprintf(stderr, "avs-preintegrate: %s\n", problem.c_str());
    return 2;
  }
  if (settings.BatchSize == 0 || settings.MaximumPaths < settings.BatchSize ||
    settings.MaximumPathsF < settings.BatchSize)
  {
    std::fprintf(
      stderr, "avs-preintegrate: --batch must be positive and <= --max-paths, --max-paths-f\n");
    return 2;
  }

  avs::ScatteringTable earlier;
  if (!refineFile.empty())
  {
    std::string error;
    if (!earlier.Read(refineFile, &error))
    {
      std::fprintf(stderr, "avs-preintegrate: cannot refine: %s\n", error.c_str());
      return 1;
    }
    if (!(earlier.Axes == settings.Axes))
    {
      std::fprintf(stderr,
        "avs-preintegrate: cannot refine %s: its axes differ from the requested ones\n",
        refineFile.c_str());
      return 2;
    }
    settings.Refine = &earlier;
  }

  const auto start = std::chrono::steady_clock::now();
  bool progressOpen = false; // a progress line not yet ended by a newline
  if (!quiet)
  {
    settings.Progress = [start, &progressOpen](std::size_t done, std::size_t all)
    {
      const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double eta = done > 0 ? elapsed * (static_cast<double>(all) / done - 1.0) : 0.0;
      std::fprintf(stderr,
        "\r[avs-preintegrate] %zu/%zu cells (%3.0f%%), %.0f s elapsed, ~%.0f s left ",
        done,
        all,
        100.0 * done / all,
        elapsed,
        eta);
      progressOpen = done != all;
      if (done == all)
      {
        std::fprintf(stderr, "\n");
      }
      std::fflush(stderr);
    };
  }
  if (settings.CheckpointSeconds > 0.0)
  {
    settings.Checkpoint = [output, quiet](const avs::ScatteringTable& partial)
    {
      std::string error;
      if (!partial.Write(output, &error))
      {
        std::fprintf(stderr, "\navs-preintegrate: checkpoint failed: %s\n", error.c_str());
      }
      else if (!quiet)
      {
        std::fprintf(stderr, "\n[avs-preintegrate] checkpoint written to %s\n", output.c_str());
      }
    };
  }
  avs::PreintegrationStatistics stats;
  const avs::ScatteringTable table = avs::Preintegrate(settings, &stats);
  if (progressOpen)
  {
    std::fprintf(stderr, "\n"); // the progress stopped short of the last cell
  }
  std::string error;
  if (!table.Write(output, &error))
  {
    std::fprintf(stderr, "avs-preintegrate: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s\n", output.c_str());
  std::printf("axes: theta %d, tau %d (max %g), g %d, albedo %d\n",
    settings.Axes.NumberOfTheta,
    settings.Axes.NumberOfTau,
    settings.Axes.TauMaximum,
    settings.Axes.NumberOfAnisotropy,
    settings.Axes.NumberOfAlbedo);
  if (settings.Refine)
  {
    std::printf("refined %s: %zu cells computed again, the others copied\n",
      refineFile.c_str(),
      stats.CellsComputed);
  }
  std::printf("paths: %llu for A, %llu for F, %llu vertices; %zu cells stopped at --max-paths\n",
    static_cast<unsigned long long>(stats.PathsA),
    static_cast<unsigned long long>(stats.PathsF),
    static_cast<unsigned long long>(stats.Vertices),
    stats.CellsAtPathLimit);
  std::printf("largest relative standard error of significant entries (>= %g of the table's "
              "largest value): "
              "A %.4f, F %.4f\n",
    settings.SignificanceThreshold,
    table.MaximumRelativeErrorA(settings.SignificanceThreshold),
    table.MaximumRelativeErrorF(settings.SignificanceThreshold));
  std::printf("time: %.1f s on %d threads%s\n",
    table.GenerationSeconds,
    settings.Threads > 0 ? settings.Threads : avs::DefaultThreadCount(),
    settings.Refine ? " (including the earlier table's)" : "");
  return 0;
}
