// avs-bench: throughput of the VTK-free core, one line per figure:
//
//   bench <name> <value> <unit>
//
// Summed-area-table averaging at 128^3 and 256^3, light-volume tube marching for one
// directional and one point light, and scattering-table lookups. Timings are medians of several
// runs of the same work. The GPU figures come with the mappers (Documentation/Performance.md).
#include "AveragedExtinction.h"
#include "LightVolume.h"
#include "Parallel.h"
#include "ProceduralVolume.h"
#include "Random.h"
#include "ReferenceRenderer.h"
#include "ScatteringTable.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

template<typename F>
double MedianSeconds(int runs, F&& work)
{
  std::vector<double> t;
  for (int i = 0; i < runs; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    work();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

avs::Grid NebulaExtinction(int n)
{
  avs::VolumeScene scene;
  scene.Scalars = avs::MakeNebula(n);
  scene.Transfer = avs::TransferFunction::Ramp(0.0, 1.0, 0.8, { 1, 1, 1 });
  scene.UnitDistance = 2.0 / 64.0;
  return avs::ExtinctionGrid(scene);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string tableFile;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::printf("Usage: avs-bench [--table FILE]\n\nPrints 'bench <name> <value> <unit>' lines "
                  "for the core's precomputation and lookups.\n");
      return 0;
    }
    if (arg == "--table" && i + 1 < argc)
    {
      tableFile = argv[++i];
    }
  }
  if (tableFile.empty())
  {
    const char* env = std::getenv("AVS_SCATTERING_TABLE");
#ifdef AVS_SOURCE_TABLE_PATH
    tableFile = env && *env ? env : AVS_SOURCE_TABLE_PATH;
#else
    tableFile = env ? env : "";
#endif
  }
  avs::ScatteringTable table;
  std::string error;
  if (!table.Read(tableFile, &error))
  {
    std::fprintf(stderr, "avs-bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("# threads %d\n", avs::DefaultThreadCount());

  for (int n : { 128, 256 })
  {
    const avs::Grid sigma = NebulaExtinction(n);
    const double radius = 3.0 * sigma.Geometry.Spacing.x;
    const double seconds = MedianSeconds(5, [&] { avs::AverageExtinction(sigma, radius); });
    std::printf("bench sat_average_%d %.1f Mvoxel/s\n",
      n,
      static_cast<double>(sigma.Values.size()) / seconds * 1e-6);
  }

  {
    const int n = 128;
    const avs::Grid sigma = NebulaExtinction(n);
    const double radius = 2.0 * sigma.Geometry.Diagonal() / 128.0;
    const avs::Grid averaged = avs::AverageExtinction(sigma, radius);
    const avs::ScatteringSlice slice = table.Slice(0.3, 0.9);
    const avs::Light directional = avs::Light::Directional({ 1, 0.3, 0.2 }, { 1, 1, 1 });
    const avs::Light point = avs::Light::Point({ 0, 0, 0 }, { 1, 1, 1 });
    for (const auto& [name, light] : { std::make_pair("light_volume_directional", directional),
           std::make_pair("light_volume_point", point) })
    {
      avs::LightVolumeStatistics stats;
      const double seconds = MedianSeconds(3,
        [&]
        { avs::ComputeLightVolume(averaged, averaged.Geometry, light, slice, radius, &stats); });
      std::printf("bench %s_%d %.2f Mvoxel/s\n",
        name,
        n,
        static_cast<double>(averaged.Values.size()) / seconds * 1e-6);
      std::printf("bench %s_steps_%d %.1f Msteps/s\n",
        name,
        n,
        static_cast<double>(stats.Steps) / seconds * 1e-6);
    }
  }

  {
    const int count = 2000000;
    std::vector<double> theta(count), tau(count);
    avs::Random rng(3);
    for (int i = 0; i < count; ++i)
    {
      theta[i] = avs::Pi * rng.Uniform();
      tau[i] = 20.0 * rng.Uniform();
    }
    const avs::ScatteringSlice slice = table.Slice(0.3, 0.9);
    double sink = 0.0;
    const double sliceSeconds = MedianSeconds(5,
      [&]
      {
        for (int i = 0; i < count; ++i)
        {
          sink += slice.InScattering(theta[i], tau[i]);
        }
      });
    std::printf("bench table_slice_lookups %.1f Mlookup/s\n", count / sliceSeconds * 1e-6);
    const double fullSeconds = MedianSeconds(3,
      [&]
      {
        for (int i = 0; i < count; ++i)
        {
          sink += table.InScattering(theta[i], tau[i], 0.3, 0.9);
        }
      });
    std::printf("bench table_full_lookups %.1f Mlookup/s\n", count / fullSeconds * 1e-6);
    const double fSeconds = MedianSeconds(5,
      [&]
      {
        for (int i = 0; i < count; ++i)
        {
          sink += slice.ForwardTransport(tau[i]);
        }
      });
    std::printf("bench table_forward_lookups %.1f Mlookup/s\n", count / fSeconds * 1e-6);
    if (sink == 42.0)
    {
      std::printf("#\n");
    }
  }
  return 0;
}
