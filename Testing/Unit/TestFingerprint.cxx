// The slabs' fingerprints (Fingerprint.h): equal memory gives equal fingerprints whatever the
// slab size and the number of threads; any change of one byte, a swap of two words, or a shift
// of the contents changes exactly the slabs it touches; ChangedSlabs brackets them.
#include "Fingerprint.h"
#include "Random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <utility>

using namespace avs;

namespace
{
std::vector<unsigned char> RandomBytes(std::size_t n, std::uint64_t seed)
{
  Random rng(seed);
  std::vector<unsigned char> b(n);
  for (unsigned char& c : b)
  {
    c = static_cast<unsigned char>(rng.NextUInt() & 255u);
  }
  return b;
}
} // namespace

TEST(Fingerprint, EqualMemoryEqualFingerprints)
{
  const std::vector<unsigned char> a = RandomBytes(100003, 1);
  const std::vector<unsigned char> b = a; // another copy, another address
  for (std::size_t slab : { 1, 7, 32, 1000, 4096, 100003, 200000 })
  {
    const auto fa = SlabFingerprints(a.data(), a.size(), slab);
    EXPECT_EQ(fa, SlabFingerprints(b.data(), b.size(), slab)) << slab;
    EXPECT_EQ(fa.size(), (a.size() + slab - 1) / slab);
    EXPECT_TRUE(ChangedSlabs(fa, fa).Empty());
  }
}

TEST(Fingerprint, EveryByteCounts)
{
  // Each byte of a slab changed by each single bit: the slab's fingerprint changes, the others'
  // do not. (Also the tails: 1000 is not a multiple of the 32-byte blocks.)
  const std::size_t slab = 1000;
  std::vector<unsigned char> data = RandomBytes(3 * slab, 2);
  const auto before = SlabFingerprints(data.data(), data.size(), slab);
  std::set<std::uint64_t> seen(before.begin(), before.end());
  for (std::size_t i = slab; i < 2 * slab; i += 37)
  {
    for (int bit = 0; bit < 8; ++bit)
    {
      data[i] ^= static_cast<unsigned char>(1u << bit);
      const auto now = SlabFingerprints(data.data(), data.size(), slab);
      EXPECT_EQ(now[0], before[0]);
      EXPECT_NE(now[1], before[1]) << "byte " << i << " bit " << bit;
      EXPECT_EQ(now[2], before[2]);
      EXPECT_TRUE(seen.insert(now[1]).second) << "a repeated fingerprint";
      const SlabRange r = ChangedSlabs(before, now);
      EXPECT_EQ(r.First, 1u);
      EXPECT_EQ(r.Last, 2u);
      data[i] ^= static_cast<unsigned char>(1u << bit);
    }
  }
  EXPECT_EQ(SlabFingerprints(data.data(), data.size(), slab), before);
}

TEST(Fingerprint, OrderAndPositionCount)
{
  // Structured changes that sums or xors of the words would miss: two words swapped, the
  // contents shifted by a word, a zero slab against a slab of another length.
  std::vector<std::uint64_t> words(512);
  for (std::size_t i = 0; i < words.size(); ++i)
  {
    words[i] = i % 5; // few distinct values: swaps and shifts change little
  }
  const std::size_t bytes = words.size() * sizeof(std::uint64_t);
  const auto base = SlabFingerprints(words.data(), bytes, bytes);
  auto swapped = words;
  std::swap(swapped[10], swapped[11]);
  EXPECT_NE(SlabFingerprints(swapped.data(), bytes, bytes), base);
  auto shifted = words;
  std::rotate(shifted.begin(), shifted.begin() + 1, shifted.end());
  EXPECT_NE(SlabFingerprints(shifted.data(), bytes, bytes), base);
  const std::vector<unsigned char> zeros(64, 0);
  EXPECT_NE(SlabFingerprints(zeros.data(), 32, 32), SlabFingerprints(zeros.data(), 64, 64));
}

TEST(Fingerprint, ChangedSlabsBracketTheChanges)
{
  const std::vector<std::uint64_t> before = { 1, 2, 3, 4, 5, 6 };
  EXPECT_TRUE(ChangedSlabs(before, before).Empty());
  const SlabRange r = ChangedSlabs(before, { 1, 9, 3, 4, 9, 6 });
  EXPECT_EQ(r.First, 1u); // the slabs between two changed ones are in the range
  EXPECT_EQ(r.Last, 5u);
  const SlabRange all = ChangedSlabs(before, { 1, 2, 3 });
  EXPECT_EQ(all.First, 0u); // another count: everything
  EXPECT_EQ(all.Last, 3u);
  EXPECT_TRUE(ChangedSlabs({}, {}).Empty());
}

TEST(Fingerprint, ThreadCountDoesNotMatter)
{
  const std::vector<unsigned char> a = RandomBytes(1 << 20, 3);
  const auto many = SlabFingerprints(a.data(), a.size(), 4096);
  setenv("AVS_NUM_THREADS", "1", 1);
  const auto one = SlabFingerprints(a.data(), a.size(), 4096);
  unsetenv("AVS_NUM_THREADS");
  EXPECT_EQ(many, one);
}
