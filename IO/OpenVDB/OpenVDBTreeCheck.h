// Walks the serialised tree of one grid (topology and leaf buffers) as OpenVDB 10 will read
// it, checking every count and block size before OpenVDB sees them (private to
// vtkOpenVDBImageReader's checked archive).
//
// OpenVDB trusts these sizes: an uncompressed block is read into the node's buffer for as many
// bytes as the file says before the size is compared with the buffer's (a heap overflow on a
// corrupt file), a blosc block's own header says how much of it blosc reads, a root tile's
// "active" byte is loaded as a bool, a root child that appears twice leaks the first, and a
// zlib block that inflates to the right length passes even when zlib reports it damaged. The
// walk reads the framing (masks, flags, sizes), inflates zlib blocks to check them and seeks
// over the rest. Blosc blocks carry no checksum: damage inside one that still decodes to the
// right length cannot be told from data. It covers the standard 5-4-3 trees of file format 222 and
// later (the versions of OpenVDB 3.0 on); older files are left to OpenVDB and the archive's other
// checks.
#ifndef avs_OpenVDBTreeCheck_h
#define avs_OpenVDBTreeCheck_h

#include <cstdint>
#include <istream>
#include <string>

namespace avs
{

struct OpenVDBTreeLayout
{
  std::string GridType;          ///< e.g. "Tree_float_5_4_3" (the descriptor's, without _HalfFloat)
  bool SaveFloatAsHalf = false;  ///< the descriptor's half-float flag
  std::uint32_t Compression = 0; ///< the grid's compression flags (io::COMPRESS_*)
  std::uint32_t FileVersion = 0;
};

/// Walks the tree that starts at `begin` (after the grid's transform), whose buffers must begin
/// at `block` and end exactly at `end` (the descriptor's offsets); with `block` < 0 (a file
/// without offsets) `end` only bounds it. Returns where the tree ends. Throws
/// std::runtime_error with what is wrong; leaves the stream anywhere.
std::int64_t CheckOpenVDBTree(std::istream& is,
  std::int64_t begin,
  std::int64_t block,
  std::int64_t end,
  const OpenVDBTreeLayout& layout);

/// Whether CheckOpenVDBTree knows the tree of this grid type and file version.
bool IsCheckableOpenVDBTree(const OpenVDBTreeLayout& layout);

} // namespace avs

#endif
