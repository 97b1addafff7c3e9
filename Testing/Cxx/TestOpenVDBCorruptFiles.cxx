// vtkOpenVDBImageReader on truncated and corrupt files: each is refused with an error that
// names the file and what is wrong, and an empty output (never a partial volume); the
// untouched file still loads. OpenVDB's io::File does not check its stream, so before the
// checked archive a file cut anywhere after its header loaded as a full grid with chopped data.
#include "TestErrorObserver.h"
#include "vtkOpenVDBImageReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using Bytes = std::vector<char>;

std::string Path(const std::string& name)
{
  return std::string(::testing::TempDir()) + "/avs_corrupt_" + name;
}

Bytes Load(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void Save(const std::string& path, const Bytes& bytes, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(size));
}

// A cloud of 48^3 voxels with values that vary everywhere (so that no leaf is uniform). Its
// class stays "unknown": OpenVDB writes fog volumes and level sets without zip compression
// whatever the file asks for.
openvdb::FloatGrid::Ptr Cloud()
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  auto acc = grid->getAccessor();
  for (int k = 0; k < 48; ++k)
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i)
      {
        const double r =
          std::sqrt((i - 24.0) * (i - 24.0) + (j - 24.0) * (j - 24.0) + (k - 24.0) * (k - 24.0));
        if (r < 22.0)
        {
          acc.setValue(openvdb::Coord(i, j, k), static_cast<float>(1.0 + std::sin(0.3 * i + j)));
        }
      }
  return grid;
}

std::string Write(const std::string& name, std::uint32_t compression)
{
  const std::string path = Path(name);
  openvdb::io::File file(path);
  file.setCompression(compression);
  file.write({ Cloud() });
  file.close();
  return path;
}

// Where the first grid's descriptor says its parts lie (read with OpenVDB's own parsers).
struct Offsets : openvdb::io::Archive
{
  std::int64_t DescriptorEnd = 0, Grid = 0, Block = 0, End = 0;
  explicit Offsets(const std::string& path)
  {
    std::ifstream is(path, std::ios::binary);
    this->readHeader(is);
    auto meta = std::make_shared<openvdb::io::StreamMetadata>();
    openvdb::io::setStreamMetadataPtr(is, meta, false);
    this->setFormatVersion(is);
    this->setLibraryVersion(is);
    this->setDataCompression(is);
    openvdb::MetaMap().readMeta(is);
    readGridCount(is);
    openvdb::io::GridDescriptor gd;
    gd.read(is);
    this->DescriptorEnd = static_cast<std::int64_t>(is.tellg());
    this->Grid = gd.getGridPos();
    this->Block = gd.getBlockPos();
    this->End = gd.getEndPos();
  }
};

struct Result
{
  vtkIdType Points = 0;
  int Errors = 0;
  std::string Message;
};

Result Read(const std::string& path)
{
  vtkNew<vtkOpenVDBImageReader> reader;
  vtkNew<TestErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* out = reader->GetOutput();
  Result r;
  r.Points = out->GetPointData()->GetScalars() ? out->GetNumberOfPoints() : 0;
  r.Errors = errors->Errors;
  r.Message = errors->LastError;
  return r;
}

void ExpectRefused(const std::string& path, const std::string& what, const std::string& context)
{
  const Result r = Read(path);
  EXPECT_EQ(r.Points, 0) << context;
  EXPECT_GE(r.Errors, 1) << context;
  EXPECT_NE(r.Message.find(path), std::string::npos) << context << ": " << r.Message;
  EXPECT_NE(r.Message.find(what), std::string::npos) << context << ": " << r.Message;
}

class OpenVDBCorruptFiles : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { openvdb::initialize(); }
};
} // namespace

TEST_F(OpenVDBCorruptFiles, CutAtTenPositionsFromTheHeaderToTheLastByte)
{
  using namespace openvdb::io;
  for (std::uint32_t compression : { std::uint32_t(COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK),
         std::uint32_t(COMPRESS_ZIP | COMPRESS_ACTIVE_MASK),
         std::uint32_t(COMPRESS_NONE) })
  {
    const std::string good = Write("good" + std::to_string(compression) + ".vdb", compression);
    const Result intact = Read(good);
    ASSERT_EQ(intact.Errors, 0) << intact.Message;
    ASSERT_GT(intact.Points, 1000);
    const Bytes bytes = Load(good);
    const Offsets o(good);
    // From just after the magic number (inside the header) through the descriptor, the
    // topology and the leaf buffers to one byte short of the end.
    const std::int64_t first = 8, last = static_cast<std::int64_t>(bytes.size()) - 1;
    for (int k = 0; k < 10; ++k)
    {
      const std::int64_t cut = first + (last - first) * k / 9;
      const std::string path = Path("cut.vdb");
      Save(path, bytes, static_cast<std::size_t>(cut));
      ExpectRefused(path,
        "truncated",
        "compression " + std::to_string(compression) + ", cut at " + std::to_string(cut) + " of " +
          std::to_string(bytes.size()) + " (buffers from " + std::to_string(o.Block) + ")");
    }
    // The untouched file still loads, with the same voxels.
    EXPECT_EQ(Read(good).Points, intact.Points);
  }
}

TEST_F(OpenVDBCorruptFiles, SharedSmokeFileCutAsTheIssueDid)
{
  const std::string smoke = AVS_SHARED_DATA "/openvdb_smoke1.vdb";
  const Bytes bytes = Load(smoke);
  if (bytes.empty())
  {
    GTEST_SKIP() << smoke << " is not there";
  }
  const Result intact = Read(smoke);
  ASSERT_EQ(intact.Errors, 0);
  EXPECT_EQ(intact.Points, 111 * 222 * 112);
  for (double fraction : { 0.10, 0.33, 0.50, 0.90, 0.99 })
  {
    const std::string path = Path("smoke_cut.vdb");
    Save(path, bytes, static_cast<std::size_t>(fraction * bytes.size()));
    ExpectRefused(path, "truncated", "smoke file cut at " + std::to_string(fraction));
  }
}

TEST_F(OpenVDBCorruptFiles, DescriptorPointingPastTheEndOrShortOfIt)
{
  const std::string good = Write("descriptor.vdb", openvdb::io::COMPRESS_ZIP);
  const Bytes bytes = Load(good);
  const Offsets o(good);
  ASSERT_EQ(o.DescriptorEnd, o.Grid);
  // The descriptor ends with three 64-bit offsets: grid, block and end position.
  for (std::int64_t end : { o.End + 1000, o.End - 100 })
  {
    Bytes patched = bytes;
    std::memcpy(&patched[static_cast<std::size_t>(o.DescriptorEnd - 8)], &end, 8);
    const std::string path = Path("patched.vdb");
    Save(path, patched, patched.size());
    ExpectRefused(path,
      end > o.End ? "past the end of the file" : "corrupt",
      "end position " + std::to_string(end) + " instead of " + std::to_string(o.End));
  }
}

TEST_F(OpenVDBCorruptFiles, CorruptLeafBuffers)
{
  using namespace openvdb::io;
  // Uncompressed values overwritten with 0xff bytes (NaN floats).
  {
    const std::string good = Write("raw.vdb", COMPRESS_NONE);
    Bytes bytes = Load(good);
    const Offsets o(good);
    // Each leaf's buffer: its value mask (64 bytes), a flag byte, 512 floats. The values of a
    // leaf in the middle of the cloud become NaN.
    const std::int64_t leafBytes = 64 + 1 + 4 * 512;
    ASSERT_EQ((o.End - o.Block) % leafBytes, 0);
    const std::int64_t leaves = (o.End - o.Block) / leafBytes;
    const std::size_t at = static_cast<std::size_t>(o.Block + leafBytes * (leaves / 2) + 65);
    std::memset(&bytes[at], 0xff, 4 * 512);
    const std::string path = Path("raw_corrupt.vdb");
    Save(path, bytes, bytes.size());
    ExpectRefused(path, "NaN or infinite values", "raw leaf values overwritten");
  }
  // The value mask of the last leaf in the topology flipped: the leaf then claims other
  // active values, and the stream loses step with the descriptor. (The copy of each mask in
  // the buffers is skipped when reading, so that copy holds nothing that could go wrong.)
  {
    const std::string good = Write("mask.vdb", COMPRESS_ACTIVE_MASK);
    Bytes bytes = Load(good);
    const Offsets o(good);
    for (int i = 1; i <= 16; ++i)
    {
      bytes[static_cast<std::size_t>(o.Block - i)] ^= static_cast<char>(0x5a);
    }
    const std::string path = Path("mask_corrupt.vdb");
    Save(path, bytes, bytes.size());
    ExpectRefused(path, "corrupt", "last leaf mask of the topology flipped");
  }
}

// The leaf buffers of a file written with COMPRESS_ACTIVE_MASK and zip or blosc: per leaf the
// value mask (64 bytes, skipped when reading), a flag byte (0 for this cloud: inactive values
// are the background), a 64-bit block size and the block: compressed, or stored as it is when
// that is shorter (a negative size). The compressed blocks are returned.
std::vector<std::pair<std::size_t, std::size_t>> CompressedBlocks(const Bytes& bytes,
  const Offsets& o)
{
  std::vector<std::pair<std::size_t, std::size_t>> blocks;
  std::size_t at = static_cast<std::size_t>(o.Block);
  while (at < static_cast<std::size_t>(o.End))
  {
    std::int64_t size;
    std::memcpy(&size, &bytes[at + 65], 8);
    if (bytes[at + 64] != 0 || size == 0)
    {
      ADD_FAILURE() << "unexpected leaf layout at " << at;
      break;
    }
    const std::size_t length = static_cast<std::size_t>(size > 0 ? size : -size);
    if (size > 0)
    {
      blocks.emplace_back(at + 73, length);
    }
    at += 73 + length;
  }
  EXPECT_EQ(at, static_cast<std::size_t>(o.End));
  return blocks;
}

TEST_F(OpenVDBCorruptFiles, DamagedCompressedBlocks)
{
  using namespace openvdb::io;
  for (std::uint32_t compression : { std::uint32_t(COMPRESS_ZIP | COMPRESS_ACTIVE_MASK),
         std::uint32_t(COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK) })
  {
    const bool zip = compression & COMPRESS_ZIP;
    const std::string good = Write("packed" + std::to_string(compression) + ".vdb", compression);
    const Bytes original = Load(good);
    const Offsets o(good);
    const auto blocks = CompressedBlocks(original, o);
    ASSERT_GT(blocks.size(), 20u);
    for (std::size_t b : { std::size_t(0), blocks.size() / 2, blocks.size() - 1 })
    {
      const auto [start, size] = blocks[b];
      // The block's size field, its first bytes (zlib's header; blosc's header: version, flags,
      // sizes) and, for zip, bytes in its middle (zlib checks the stream and its Adler-32).
      std::vector<std::pair<std::size_t, int>> damages = { { start - 8, 8 }, { start, 12 } };
      if (zip)
      {
        damages.push_back({ start + size / 2, 4 });
      }
      for (const auto& [at, length] : damages)
      {
        Bytes bytes = original;
        for (int i = 0; i < length; ++i)
        {
          bytes[at + i] = static_cast<char>(bytes[at + i] ^ 0xa5);
        }
        const std::string path = Path("packed_corrupt.vdb");
        Save(path, bytes, bytes.size());
        ExpectRefused(path,
          "corrupt",
          std::string(zip ? "zip" : "blosc") + " block " + std::to_string(b) + ", " +
            std::to_string(length) + " bytes at " + std::to_string(at) + " (block at " +
            std::to_string(start) + ", " + std::to_string(size) + " bytes)");
      }
    }
  }
}
