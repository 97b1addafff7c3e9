// Filling a grid voxel by voxel in parallel, the loop that light volumes, ambient occlusion and
// the procedural volumes share.
#ifndef avs_GridFill_h
#define avs_GridFill_h

#include "Grid.h"
#include "Parallel.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

namespace avs
{

/// A grid on `target` whose voxel values are value(world position, work counter), computed in
/// parallel over z slices. The work counts are summed into *work (if given). Progress goes to
/// `progress` from the calling thread only, because VTK observers are not thread-safe.
template<typename Value>
Grid FillGrid(const GridGeometry& target,
  Value&& value,
  std::uint64_t* work = nullptr,
  const std::function<void(double)>& progress = {})
{
  Grid out(target, 0.0f);
  const auto& dims = target.Dimensions;
  std::atomic<std::uint64_t> total{ 0 };
  std::atomic<int> slicesDone{ 0 };
  const std::thread::id caller = std::this_thread::get_id();
  ParallelFor(dims[2],
    [&](std::int64_t b, std::int64_t e)
    {
      std::uint64_t local = 0;
      for (std::int64_t k = b; k < e; ++k)
      {
        for (int j = 0; j < dims[1]; ++j)
        {
          for (int i = 0; i < dims[0]; ++i)
          {
            const Vec3 world = target.IndexToWorld(
              { static_cast<double>(i), static_cast<double>(j), static_cast<double>(k) });
            out.At(i, j, static_cast<int>(k)) = static_cast<float>(value(world, local));
          }
        }
        const int done = ++slicesDone;
        if (progress && std::this_thread::get_id() == caller)
        {
          progress(static_cast<double>(done) / dims[2]);
        }
      }
      total += local;
    });
  if (work)
  {
    *work = total.load();
  }
  return out;
}

} // namespace avs

#endif
