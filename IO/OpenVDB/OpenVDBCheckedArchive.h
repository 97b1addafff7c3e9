// An OpenVDB file read through checks (private to vtkOpenVDBImageReader).
//
// OpenVDB's io::File does not check its input stream: a file cut short, or one whose sizes or
// offsets are corrupt, reads past the end of the file, and the values it then "reads" go into
// the grid without an error (a truncated file loads as a full grid with chopped data). Some
// size fields (string lengths, metadata sizes) are also allocated before they are read, so a
// corrupt one asks for gigabytes. This archive reads the same format through OpenVDB's own
// parsers, with checks around them:
//
// - the stream throws on every short read (no value is ever taken from a failed read);
// - every grid descriptor's offsets must be ordered and lie inside the file (a file cut
//   anywhere after its header fails here, before any voxel is read);
// - string lengths, metadata sizes and the counts of OpenVDB's delayed-load metadata are
//   checked against the bytes that remain before OpenVDB allocates them;
// - a grid read must end exactly where its descriptor says it ends (a corrupt leaf mask, node
//   flag or chunk size desynchronises the stream and is caught here);
// - the tree itself (topology and leaf buffers) is walked first, every count, flag and block
//   size checked, before OpenVDB reads it (OpenVDBTreeCheck.h says what OpenVDB trusts);
// - it never loads lazily: the trees are read in full from a plain stream.
//
// Every failure throws std::runtime_error with what is wrong; OpenVDB's own exceptions (zlib
// or blosc blocks that do not decompress, unknown types) are rethrown the same way.
#ifndef avs_OpenVDBCheckedArchive_h
#define avs_OpenVDBCheckedArchive_h

#include <openvdb/Grid.h>
#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/io/io.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace avs
{

class OpenVDBCheckedArchive : public openvdb::io::Archive
{
public:
  struct Entry
  {
    openvdb::io::GridDescriptor Descriptor;
    /// The grid's metadata and transform (no tree, except in files without grid offsets,
    /// which are read in full when opened).
    openvdb::GridBase::Ptr Grid;
    std::int64_t TreePosition = -1; ///< where the tree begins (after the transform)
    std::uint32_t Compression = 0;  ///< the grid's compression flags
  };

  /// Opens `fileName` and checks its header and every grid descriptor; reads each grid's
  /// metadata and transform. Throws std::runtime_error. Calls openvdb::initialize() first if
  /// needed (it is idempotent).
  explicit OpenVDBCheckedArchive(const std::string& fileName);

  /// The grids in the order the file holds them.
  const std::vector<Entry>& GetEntries() const { return this->Entries; }

  /// Reads entry `index` in full (an instance: with its parent's tree). Throws
  /// std::runtime_error.
  openvdb::GridBase::Ptr ReadGrid(std::size_t index);

  /// The file's size in bytes.
  std::int64_t GetFileSize() const { return this->Size; }

private:
  std::int64_t Position();
  std::int64_t Remaining(std::int64_t end);
  /// Reads a little-endian 32-bit value that must end before `end`.
  std::uint32_t ReadU32(std::int64_t end);
  /// Reads a 32-bit length and checks that `end` leaves room for that many bytes.
  std::uint32_t ReadLength(std::int64_t end, const char* what);
  void SkipString(std::int64_t end, const char* what);
  std::string ReadShortString(std::int64_t end, const char* what);
  /// Walks a MetaMap as MetaMap::readMeta will read it, checking every size; leaves the stream
  /// after it.
  void ScanMetadata(std::int64_t end, const std::string& where);
  void CheckDelayedLoadMetadata(std::uint32_t numBytes, std::int64_t end, const std::string& where);
  /// Checks the strings of the descriptor at `start` and returns there.
  void CheckDescriptor(std::int64_t start);
  /// Checks the grid's compression flags, metadata and transform type that follow, and
  /// returns to where it started.
  void ScanGridHeader(const openvdb::io::GridDescriptor& gd, std::int64_t end);
  void ReadGridHeader(Entry& entry);
  /// Walks the entry's tree (OpenVDBTreeCheck) and reads it into `grid`.
  void ReadTree(const Entry& entry, openvdb::GridBase::Ptr grid);
  [[noreturn]] void Fail(const std::string& what) const;

  std::string FileName;
  std::ifstream Stream;
  std::int64_t Size = 0;
  openvdb::io::StreamMetadata::Ptr StreamMeta; ///< the stream's tags (it does not own them)
  std::vector<Entry> Entries;
};

} // namespace avs

#endif
