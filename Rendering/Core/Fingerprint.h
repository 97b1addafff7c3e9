// What a new time step did not change: 64-bit fingerprints of the data's memory in slabs of
// slices, so that a mapper given new data can tell which slices differ from the data it
// uploaded (none: a static series, or a step that repeats; a few: a simulation that changes a
// region) and upload those alone. Two slabs with equal fingerprints are taken to be equal: for
// contents that differ, the chance that they agree is about 2^-64 per slab.
#ifndef avs_Fingerprint_h
#define avs_Fingerprint_h

#include <cstddef>
#include <cstdint>
#include <vector>

namespace avs
{

/// The fingerprints of the slabs of `bytes` bytes at `data`: `slabBytes` each (the last one
/// what is left), computed in parallel.
std::vector<std::uint64_t> SlabFingerprints(const void* data,
  std::size_t bytes,
  std::size_t slabBytes);

/// The slabs [first, last) whose fingerprints differ between `before` and `now` ({0, 0}: none);
/// all of `now`'s when the counts differ.
struct SlabRange
{
  std::size_t First = 0;
  std::size_t Last = 0;
  bool Empty() const { return this->First >= this->Last; }
};
SlabRange ChangedSlabs(const std::vector<std::uint64_t>& before,
  const std::vector<std::uint64_t>& now);

} // namespace avs

#endif
