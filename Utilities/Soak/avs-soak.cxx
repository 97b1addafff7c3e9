// avs-soak: renders many frames with random but valid changes in two windows and checks that
// nothing accumulates (./avs soak; a short run is a test).
//
//   avs-soak [--frames N (2000)] [--rounds R (4)] [--seed S (1)] [--inject-leak]
//   avs-soak --time-series [--steps N (200)]   (SoakTimeSeries.h)
//
// Every frame changes, at random, the camera (also inside the volume and in parallel
// projection), the lights (count, kind: directional, point, spot, headlight, camera light;
// pose), the transfer function, the mapper's parameters, the mapper kind (a new mapper), the
// window size and the input (a larger, a smaller and a turned volume), in two windows; bad
// input at fixed frames (an empty image, an image without scalars, a missing scattering table) must
// give an error and no frame, and the next valid frame must render again. The frames before each
// checkpoint (every 50) change nothing and must rebuild nothing.
//
// The N frames are R rounds of the same N / R frames: the scene is reset (new mappers) and the
// generator reseeded at each round, so every round asks for exactly the same work. A steady
// state means that the rounds agree: the same uploads, rebuilds, frames and errors in every
// round (the counters), and from the third round on no more GL objects at any checkpoint than
// the second round had there, and a resident memory peak at most 32 MiB above the second
// round's. (The first round is the warm-up: VTK's shader cache keeps every program variant it
// compiles, so the first round's counts grow with the variants it meets.) Under
// AddressSanitizer the memory is not compared (its quarantine keeps freed memory, so the
// resident size grows by design); LeakSanitizer checks for leaks at exit instead.
//
// --inject-leak makes the soak leak on purpose from the third round on (a GL texture and 1 MiB
// every frame): the run must then fail, which shows that the checks see a leak (a test).
#include "SoakCensus.h"
#include "SoakScene.h"
#include "SoakTimeSeries.h"

#include "vtkAVSOpenGL.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
#if defined(__SANITIZE_ADDRESS__)
constexpr bool AddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool AddressSanitizer = true;
#else
constexpr bool AddressSanitizer = false;
#endif
#else
constexpr bool AddressSanitizer = false;
#endif
} // namespace

int main(int argc, char** argv)
{
  int frames = 2000, rounds = 4, steps = 200;
  unsigned long seed = 1;
  bool injectLeak = false, timeSeries = false;
  std::vector<std::vector<char>> leaked;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc)
      frames = std::atoi(argv[++i]);
    else if (a == "--rounds" && i + 1 < argc)
      rounds = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc)
      seed = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--inject-leak")
      injectLeak = true;
    else if (a == "--time-series")
      timeSeries = true;
    else if (a == "--steps" && i + 1 < argc)
      steps = std::atoi(argv[++i]);
    else
    {
      std::printf("usage: avs-soak [--frames N] [--rounds R] [--seed S] [--inject-leak]\n"
                  "       avs-soak --time-series [--steps N]\n");
      return a == "--help" ? 0 : 2;
    }
  }
  if (timeSeries)
  {
    return RunTimeSeriesSoak(steps, AddressSanitizer) ? 0 : 1;
  }
  if (rounds < 3 || frames < 50 * rounds)
  {
    std::fprintf(stderr, "avs-soak: at least 3 rounds of at least 50 frames\n");
    return 2;
  }
  const int perRound = frames / rounds;
  const double memoryTolerance = 32.0; // MiB

  SoakScene scene;
  const std::size_t windows = scene.Windows().size();
  // Per round: counters per window, census per window and checkpoint, peak memory.
  std::vector<std::vector<SoakCounters>> counters(rounds, std::vector<SoakCounters>(windows));
  std::vector<std::vector<std::vector<GLCensus>>> census(
    rounds, std::vector<std::vector<GLCensus>>(windows));
  std::vector<double> peak(rounds, 0.0);
  bool ok = true;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < rounds && ok; ++r)
  {
    scene.Reset(seed);
    for (int f = 0; f < perRound; ++f)
    {
      std::string failure;
      if (!scene.Step(f, failure))
      {
        std::printf("FAIL round %d: %s\n", r + 1, failure.c_str());
        ok = false;
        break;
      }
      if (injectLeak && r >= 2)
      {
        scene.Windows()[0].RenderWindow->MakeCurrent();
        unsigned int name = 0;
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, name);
        glBindTexture(GL_TEXTURE_2D, 0);
        leaked.emplace_back(1 << 20, 'x');
      }
      if (SoakScene::IsCheckpoint(f))
      {
        for (std::size_t w = 0; w < windows; ++w)
        {
          census[r][w].push_back(CountGLObjects(scene.Windows()[w].RenderWindow));
        }
        peak[r] = std::max(peak[r], ResidentMegabytes());
      }
      if ((f + 1) % 100 == 0)
      {
        const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf(
          "round %d frame %d: %.0f s, %.0f MiB resident\n", r + 1, f + 1, s, ResidentMegabytes());
        std::fflush(stdout);
      }
    }
    for (std::size_t w = 0; w < windows; ++w)
    {
      counters[r][w] = scene.Windows()[w].Total;
    }
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The rounds against the first.
  for (int r = 0; r < rounds && ok; ++r)
  {
    std::printf("round %d: peak resident memory %.1f MiB\n", r + 1, peak[r]);
    for (std::size_t w = 0; w < windows; ++w)
    {
      const auto& c = census[r][w];
      std::printf("  window %zu: %s\n", w, counters[r][w].ToString().c_str());
      if (!c.empty())
      {
        std::printf(
          "  window %zu GL objects at the last checkpoint: %s\n", w, c.back().ToString().c_str());
      }
      if (r > 0 && !(counters[r][w] == counters[0][w]))
      {
        std::printf("FAIL round %d, window %zu: the counters differ from round 1\n", r + 1, w);
        ok = false;
      }
      for (std::size_t k = 0; r > 1 && k < c.size() && k < census[1][w].size(); ++k)
      {
        if (!c[k].NotAbove(census[1][w][k]))
        {
          std::printf("FAIL round %d, window %zu, checkpoint %zu: %s, more than round 2's %s\n",
            r + 1,
            w,
            k,
            c[k].ToString().c_str(),
            census[1][w][k].ToString().c_str());
          ok = false;
        }
      }
    }
    if (r > 1 && AddressSanitizer)
    {
      std::printf("round %d: resident memory not checked under AddressSanitizer (its quarantine "
                  "keeps freed memory; LeakSanitizer checks for leaks at exit)\n",
        r + 1);
    }
    else if (r > 1 && peak[r] > peak[1] + memoryTolerance)
    {
      std::printf("FAIL round %d: resident memory peaked at %.1f MiB, round 2 at %.1f MiB\n",
        r + 1,
        peak[r],
        peak[1]);
      ok = false;
    }
  }
  std::printf("%s: %d frames in %d rounds, 2 windows, %.0f s (%.1f frames/s)\n",
    ok ? "PASS" : "FAIL",
    ok ? frames : 0,
    rounds,
    seconds,
    frames / std::max(seconds, 1e-9));
  return ok ? 0 : 1;
}
