// A minimal parallel-for over std::thread. Work is split into contiguous chunks handed out
// through an atomic counter, so results never depend on the number of threads as long as each
// index writes only its own output.
#ifndef avs_Parallel_h
#define avs_Parallel_h

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <thread>
#include <vector>

namespace avs
{

/// Threads to use: AVS_NUM_THREADS if set and positive, else the hardware concurrency.
inline int DefaultThreadCount()
{
  if (const char* env = std::getenv("AVS_NUM_THREADS"))
  {
    const int n = std::atoi(env);
    if (n > 0)
    {
      return n;
    }
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Calls body(begin, end) on chunks of [0, count) from `threads` threads (0: the default).
template<typename Body>
void ParallelFor(std::int64_t count, Body&& body, int threads = 0, std::int64_t grain = 1)
{
  if (count <= 0)
  {
    return;
  }
  if (threads <= 0)
  {
    threads = DefaultThreadCount();
  }
  grain = std::max<std::int64_t>(1, grain);
  const std::int64_t chunks = (count + grain - 1) / grain;
  threads = static_cast<int>(std::min<std::int64_t>(threads, chunks));
  std::atomic<std::int64_t> next{ 0 };
  auto worker = [&]()
  {
    for (;;)
    {
      const std::int64_t c = next.fetch_add(1);
      if (c >= chunks)
      {
        return;
      }
      const std::int64_t b = c * grain;
      body(b, std::min(count, b + grain));
    }
  };
  if (threads <= 1)
  {
    worker();
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(worker);
  }
  worker();
  for (auto& t : pool)
  {
    t.join();
  }
}

} // namespace avs

#endif
