#include "Fingerprint.h"

#include "Parallel.h"

#include <algorithm>
#include <cstring>

namespace
{
constexpr std::uint64_t Prime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t Prime2 = 0xC2B2AE3D27D4EB4Full;

std::uint64_t RotateLeft(std::uint64_t x, int r)
{
  return (x << r) | (x >> (64 - r));
}

// One word into a lane: multiply, rotate, multiply (each bit of the word reaches every bit of
// the lane, and the order of the words matters).
std::uint64_t Round(std::uint64_t lane, std::uint64_t word)
{
  lane += word * Prime2;
  lane = RotateLeft(lane, 31);
  return lane * Prime1;
}

// The final avalanche: every input bit changes about half of the output bits.
std::uint64_t Mix(std::uint64_t h)
{
  h ^= h >> 33;
  h *= Prime2;
  h ^= h >> 29;
  h *= Prime1;
  h ^= h >> 32;
  return h;
}

std::uint64_t Fingerprint(const unsigned char* p, std::size_t n)
{
  // Four independent lanes over 32-byte blocks (the multiplications of one block overlap).
  std::uint64_t lanes[4] = { Prime1 + Prime2, Prime2, 0, 0 - Prime1 };
  std::size_t i = 0;
  for (; i + 32 <= n; i += 32)
  {
    for (int k = 0; k < 4; ++k)
    {
      std::uint64_t w;
      std::memcpy(&w, p + i + 8 * k, 8);
      lanes[k] = Round(lanes[k], w);
    }
  }
  std::uint64_t h = RotateLeft(lanes[0], 1) + RotateLeft(lanes[1], 7) + RotateLeft(lanes[2], 12) +
    RotateLeft(lanes[3], 18);
  for (; i + 8 <= n; i += 8)
  {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = Round(h, w);
  }
  for (; i < n; ++i)
  {
    h = Round(h, p[i]);
  }
  return Mix(h ^ static_cast<std::uint64_t>(n));
}
} // namespace

namespace avs
{

std::vector<std::uint64_t> SlabFingerprints(const void* data,
  std::size_t bytes,
  std::size_t slabBytes)
{
  slabBytes = std::max<std::size_t>(1, slabBytes);
  const std::size_t slabs = (bytes + slabBytes - 1) / slabBytes;
  std::vector<std::uint64_t> out(slabs);
  const unsigned char* p = static_cast<const unsigned char*>(data);
  ParallelFor(static_cast<std::int64_t>(slabs),
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t s = begin; s < end; ++s)
      {
        const std::size_t from = static_cast<std::size_t>(s) * slabBytes;
        out[s] = Fingerprint(p + from, std::min(slabBytes, bytes - from));
      }
    });
  return out;
}

SlabRange ChangedSlabs(const std::vector<std::uint64_t>& before,
  const std::vector<std::uint64_t>& now)
{
  SlabRange r;
  if (before.size() != now.size())
  {
    r.Last = now.size();
    return r;
  }
  std::size_t first = 0;
  while (first < now.size() && before[first] == now[first])
  {
    ++first;
  }
  if (first == now.size())
  {
    return r;
  }
  std::size_t last = now.size();
  while (last > first && before[last - 1] == now[last - 1])
  {
    --last;
  }
  r.First = first;
  r.Last = last;
  return r;
}

} // namespace avs
