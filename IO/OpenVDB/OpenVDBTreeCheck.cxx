#include "OpenVDBTreeCheck.h"

#include <openvdb/io/Compression.h>
#include <openvdb/version.h>

#include <zlib.h>

#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace avs
{
namespace
{
namespace io = openvdb::io;

struct ValueLayout
{
  std::uint32_t Raw = 0;    ///< sizeof(ValueType): root values, inactive values
  std::uint32_t Stored = 0; ///< one value in a node's value array (half floats: smaller)
  bool Bool = false;        ///< LeafNode<bool>: buffers are bit masks
};

bool ValueLayoutOf(const OpenVDBTreeLayout& layout, ValueLayout& v)
{
  const std::string prefix = "Tree_", suffix = "_5_4_3";
  const std::string& t = layout.GridType;
  if (t.size() <= prefix.size() + suffix.size() || t.compare(0, prefix.size(), prefix) != 0 ||
    t.compare(t.size() - suffix.size(), suffix.size(), suffix) != 0)
  {
    return false;
  }
  const std::string value = t.substr(prefix.size(), t.size() - prefix.size() - suffix.size());
  // name, sizeof(T), its half-float size (0: not a real type, never stored as half)
  static const std::map<std::string, std::pair<std::uint32_t, std::uint32_t>> sizes = {
    { "float", { 4, 2 } },
    { "double", { 8, 2 } },
    { "int32", { 4, 0 } },
    { "int64", { 8, 0 } },
    { "vec3s", { 12, 6 } },
    { "vec3d", { 24, 6 } },
    { "vec3i", { 12, 0 } },
    { "bool", { 1, 0 } }
  };
  const auto it = sizes.find(value);
  if (it == sizes.end())
  {
    return false;
  }
  v.Raw = it->second.first;
  v.Stored = layout.SaveFloatAsHalf && it->second.second ? it->second.second : v.Raw;
  v.Bool = value == "bool";
  return true;
}

// Reads the framing of [begin, end) of a stream, every read checked against end.
class Walker
{
public:
  Walker(std::istream& is,
    std::int64_t begin,
    std::int64_t block,
    std::int64_t end,
    const OpenVDBTreeLayout& layout,
    const ValueLayout& value)
    : Stream(is)
    , BuffersBegin(block)
    , End(end)
    , Position(begin)
    , Layout(layout)
    , Value(value)
  {
    this->Stream.seekg(begin);
  }

  std::int64_t Tree()
  {
    this->Skip(4, "buffer count");
    // Root (file format 213 and later): background, tile and child counts, tiles, children.
    this->Skip(this->Value.Raw, "background value");
    const std::uint32_t tiles = this->U32("tile count");
    const std::uint32_t children = this->U32("child count");
    const std::uint64_t tileBytes = 12 + this->Value.Raw + 1;
    if (tiles * tileBytes + children * 12ull > static_cast<std::uint64_t>(this->Remaining()))
    {
      this->Fail("the root claims " + std::to_string(tiles) + " tiles and " +
        std::to_string(children) + " children");
    }
    for (std::uint32_t i = 0; i < tiles; ++i)
    {
      this->Skip(12 + this->Value.Raw, "root tile");
      const std::uint8_t active = this->Bytes<std::uint8_t>("root tile flag");
      if (active > 1)
      {
        this->Fail("a root tile's active flag is " + std::to_string(active));
      }
    }
    // The root keeps its children in a map by origin: the buffers follow in that order.
    std::map<std::tuple<std::int32_t, std::int32_t, std::int32_t>, std::vector<std::uint16_t>>
      leavesOf;
    for (std::uint32_t i = 0; i < children; ++i)
    {
      const auto x = static_cast<std::int32_t>(this->U32("child origin"));
      const auto y = static_cast<std::int32_t>(this->U32("child origin"));
      const auto z = static_cast<std::int32_t>(this->U32("child origin"));
      const std::int32_t alignment = (1 << 12) - 1; // a root child spans 4096^3 voxels
      if ((x & alignment) || (y & alignment) || (z & alignment))
      {
        this->Fail("a root child at a misaligned origin");
      }
      const auto origin = std::make_tuple(x, y, z);
      if (leavesOf.count(origin))
      {
        this->Fail("two root children at the same origin");
      }
      this->Internal(5, leavesOf[origin]);
    }
    if (this->BuffersBegin >= 0 && this->Position != this->BuffersBegin)
    {
      this->Fail("the topology ends at byte " + std::to_string(this->Position) +
        ", the descriptor's buffers begin at " + std::to_string(this->BuffersBegin));
    }
    for (const auto& child : leavesOf)
    {
      for (std::uint16_t active : child.second)
      {
        if (this->Value.Bool)
        {
          // Value mask, origin (version 217 on: then the value bits).
          this->Skip(64 + 12 + 64, "bool leaf buffer");
        }
        else
        {
          this->Skip(64, "leaf value mask"); // OpenVDB seeks over this copy
          this->Values(512, active, 64);
        }
      }
    }
    if (this->BuffersBegin >= 0 && this->Position != this->End)
    {
      this->Fail("the tree ends at byte " + std::to_string(this->Position) +
        ", its descriptor says " + std::to_string(this->End));
    }
    return this->Position;
  }

private:
  // An internal node of 2^(3 log2) entries: child mask, value mask, values, children.
  void Internal(int log2, std::vector<std::uint16_t>& leaves)
  {
    const std::uint32_t entries = 1u << (3 * log2);
    const std::uint32_t maskBytes = entries / 8;
    std::vector<unsigned char> childMask(maskBytes), valueMask(maskBytes);
    this->Read(childMask.data(), maskBytes, "child mask");
    this->Read(valueMask.data(), maskBytes, "value mask");
    this->Values(entries, Count(valueMask), maskBytes);
    for (std::uint32_t i = 0; i < entries; ++i)
    {
      if (childMask[i / 8] & (1u << (i % 8)))
      {
        if (log2 == 5)
        {
          this->Internal(4, leaves);
        }
        else
        {
          unsigned char mask[64];
          this->Read(mask, 64, "leaf value mask");
          leaves.push_back(static_cast<std::uint16_t>(Count(mask, 64)));
        }
      }
    }
  }

  // io::readCompressedValues for `count` values of which `active` are on in the node's value
  // mask, whose selection mask has `maskBytes` bytes.
  void Values(std::uint32_t count, std::uint32_t active, std::uint32_t maskBytes)
  {
    const std::uint8_t flag = this->Bytes<std::uint8_t>("node flag");
    if (flag > io::NO_MASK_AND_ALL_VALS)
    {
      this->Fail("a node's compression flag is " + std::to_string(flag));
    }
    if (flag == io::NO_MASK_AND_ONE_INACTIVE_VAL || flag == io::MASK_AND_ONE_INACTIVE_VAL ||
      flag == io::MASK_AND_TWO_INACTIVE_VALS)
    {
      this->Skip(
        this->Value.Raw * (flag == io::MASK_AND_TWO_INACTIVE_VALS ? 2 : 1), "inactive values");
    }
    if (flag == io::MASK_AND_NO_INACTIVE_VALS || flag == io::MASK_AND_ONE_INACTIVE_VAL ||
      flag == io::MASK_AND_TWO_INACTIVE_VALS)
    {
      this->Skip(maskBytes, "selection mask");
    }
    const bool maskCompressed = this->Layout.Compression & io::COMPRESS_ACTIVE_MASK;
    const std::uint32_t n = maskCompressed && flag != io::NO_MASK_AND_ALL_VALS ? active : count;
    const bool half = this->Value.Stored != this->Value.Raw;
    if (half && n == 0)
    {
      return; // OpenVDB's half reader reads nothing for no values
    }
    const std::int64_t bytes = static_cast<std::int64_t>(n) * this->Value.Stored;
    if (this->Layout.Compression & (io::COMPRESS_BLOSC | io::COMPRESS_ZIP))
    {
      this->Block(bytes, this->Layout.Compression & io::COMPRESS_BLOSC);
    }
    else
    {
      this->Skip(bytes, "values");
    }
  }

  // io::unzipFromStream / io::bloscFromStream: a 64-bit size, then the block (stored as it is
  // when the size is negative).
  void Block(std::int64_t bytes, bool blosc)
  {
    std::int64_t size = 0;
    this->Read(&size, 8, "block size");
    if (size <= 0)
    {
      if (size != -bytes)
      {
        this->Fail("an uncompressed block of " + std::to_string(-size) + " bytes where " +
          std::to_string(bytes) + " belong");
      }
      this->Skip(bytes, "values");
      return;
    }
    if (size > this->Remaining())
    {
      this->Fail("a compressed block of " + std::to_string(size) + " bytes with " +
        std::to_string(this->Remaining()) + " left in the grid");
    }
    if (blosc)
    {
      // Blosc reads as much of the block as its header says: that must lie inside it.
      unsigned char header[16];
      if (size < 16)
      {
        this->Fail("a blosc block of " + std::to_string(size) + " bytes");
      }
      this->Read(header, 16, "blosc header");
      auto u32 = [&](int at)
      {
        return static_cast<std::uint32_t>(header[at]) |
          (static_cast<std::uint32_t>(header[at + 1]) << 8) |
          (static_cast<std::uint32_t>(header[at + 2]) << 16) |
          (static_cast<std::uint32_t>(header[at + 3]) << 24);
      };
      if (u32(4) != bytes || u32(12) > size)
      {
        this->Fail("a blosc block of " + std::to_string(size) + " bytes says " +
          std::to_string(u32(4)) + " bytes (" + std::to_string(u32(12)) + " compressed) where " +
          std::to_string(bytes) + " belong");
      }
      size -= 16;
      this->Skip(size, "compressed block");
      return;
    }
    // OpenVDB accepts a zlib block that inflates to the right size even when zlib reports an
    // error (a damaged stream or checksum): inflate it here and insist on zlib's Z_OK.
    std::vector<unsigned char> block(static_cast<std::size_t>(size));
    this->Read(block.data(), size, "compressed block");
    this->Inflated.resize(static_cast<std::size_t>(bytes) + 1);
    uLongf produced = static_cast<uLongf>(this->Inflated.size());
    const int status =
      uncompress(this->Inflated.data(), &produced, block.data(), static_cast<uLong>(size));
    if (status != Z_OK || produced != static_cast<uLongf>(bytes))
    {
      this->Fail("a zlib block that does not inflate (zlib status " + std::to_string(status) +
        ", " + std::to_string(produced) + " of " + std::to_string(bytes) + " bytes)");
    }
  }

  static std::uint32_t Count(const std::vector<unsigned char>& mask)
  {
    return Count(mask.data(), mask.size());
  }
  static std::uint32_t Count(const unsigned char* mask, std::size_t n)
  {
    std::uint32_t c = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      c += static_cast<std::uint32_t>(__builtin_popcount(mask[i]));
    }
    return c;
  }

  std::int64_t Remaining() const { return this->End - this->Position; }

  void Need(std::int64_t n, const char* what)
  {
    if (n < 0 || n > this->Remaining())
    {
      this->Fail(std::string("the ") + what + " at byte " + std::to_string(this->Position) +
        " runs past the grid's end (" + std::to_string(this->End) + ")");
    }
  }
  void Read(void* p, std::int64_t n, const char* what)
  {
    this->Need(n, what);
    this->Stream.read(static_cast<char*>(p), n);
    this->Position += n;
  }
  void Skip(std::int64_t n, const char* what)
  {
    this->Need(n, what);
    this->Position += n;
    this->Stream.seekg(this->Position);
  }
  template<typename T>
  T Bytes(const char* what)
  {
    T v{};
    this->Read(&v, sizeof(T), what);
    return v;
  }
  std::uint32_t U32(const char* what) { return this->Bytes<std::uint32_t>(what); }

  [[noreturn]] void Fail(const std::string& what) const
  {
    throw std::runtime_error("corrupt tree: " + what);
  }

  std::istream& Stream;
  std::int64_t BuffersBegin;
  std::int64_t End;
  std::int64_t Position;
  const OpenVDBTreeLayout& Layout;
  ValueLayout Value;
  std::vector<unsigned char> Inflated; ///< scratch for the zlib check
};
} // namespace

bool IsCheckableOpenVDBTree(const OpenVDBTreeLayout& layout)
{
  ValueLayout v;
  return layout.FileVersion >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION &&
    ValueLayoutOf(layout, v);
}

std::int64_t CheckOpenVDBTree(std::istream& is,
  std::int64_t begin,
  std::int64_t block,
  std::int64_t end,
  const OpenVDBTreeLayout& layout)
{
  ValueLayout v;
  if (!IsCheckableOpenVDBTree(layout) || !ValueLayoutOf(layout, v))
  {
    throw std::runtime_error("no tree check for grids of type '" + layout.GridType + "'");
  }
  return Walker(is, begin, block, end, layout, v).Tree();
}

} // namespace avs
