#include "OpenVDBCheckedArchive.h"
#include "OpenVDBTreeCheck.h"

#include <openvdb/Metadata.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/openvdb.h>

#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>

namespace avs
{
namespace
{
// Longest type name (grid, metadata or map type) accepted; OpenVDB's are below 64 characters.
constexpr std::uint32_t MaximumTypeNameLength = 256;
// Smallest sizes of a grid descriptor (three empty strings, three offsets) and of a metadata
// entry (two empty strings and a size).
constexpr std::int64_t MinimumDescriptorBytes = 3 * 4 + 3 * 8;
constexpr std::int64_t MinimumMetadataBytes = 3 * 4;
// The 16-byte header of a blosc chunk: nbytes (uncompressed) at 4, cbytes (compressed) at 12.
constexpr std::uint32_t BloscHeaderBytes = 16;
constexpr std::uint32_t BloscPadBytes = 128; // OpenVDB pads small arrays to this

std::uint32_t LittleU32(const unsigned char* b)
{
  return static_cast<std::uint32_t>(b[0]) | (static_cast<std::uint32_t>(b[1]) << 8) |
    (static_cast<std::uint32_t>(b[2]) << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
}
} // namespace

OpenVDBCheckedArchive::OpenVDBCheckedArchive(const std::string& fileName)
  : FileName(fileName)
{
  openvdb::initialize();
  this->Stream.open(fileName, std::ios::binary);
  if (!this->Stream)
  {
    this->Fail("not a readable OpenVDB file (it cannot be opened)");
  }
  this->Stream.seekg(0, std::ios::end);
  this->Size = static_cast<std::int64_t>(this->Stream.tellg());
  this->Stream.seekg(0);
  if (this->Size < 8)
  {
    this->Fail("not a readable OpenVDB file (" + std::to_string(this->Size) + " bytes)");
  }
  // No value is ever taken from a failed read: every short read throws.
  this->Stream.exceptions(std::ios::failbit | std::ios::badbit);
  try
  {
    try
    {
      this->readHeader(this->Stream);
    }
    catch (const openvdb::Exception&)
    {
      this->Fail("not a readable OpenVDB file (no OpenVDB header)");
    }
    // Tag the stream as io::File::open does, so that OpenVDB's parsers know the versions.
    this->StreamMeta.reset(new openvdb::io::StreamMetadata);
    this->StreamMeta->setSeekable(true);
    openvdb::io::setStreamMetadataPtr(this->Stream, this->StreamMeta, /*transfer=*/false);
    this->setFormatVersion(this->Stream);
    this->setLibraryVersion(this->Stream);
    this->setDataCompression(this->Stream);

    this->ScanMetadata(this->Size, "the file's metadata"); // not needed: skipped
    const std::int32_t count = readGridCount(this->Stream);
    if (count < 0 || count > this->Remaining(this->Size) / MinimumDescriptorBytes)
    {
      this->Fail("corrupt header: it claims " + std::to_string(count) + " grids in " +
        std::to_string(this->Remaining(this->Size)) + " bytes");
    }
    for (std::int32_t i = 0; i < count; ++i)
    {
      Entry entry;
      this->CheckDescriptor(this->Position());
      entry.Descriptor.read(this->Stream);
      const openvdb::io::GridDescriptor& gd = entry.Descriptor;
      if (this->inputHasGridOffsets())
      {
        const std::int64_t here = this->Position();
        const std::string name = "grid '" + gd.gridName() + "'";
        if (gd.getEndPos() > this->Size)
        {
          this->Fail(name + " ends at byte " + std::to_string(gd.getEndPos()) +
            ", past the end of the file (" + std::to_string(this->Size) +
            " bytes): the file is truncated or its grid descriptor is corrupt");
        }
        if (gd.getGridPos() != here || gd.getBlockPos() < here || gd.getEndPos() < gd.getBlockPos())
        {
          this->Fail("corrupt descriptor of " + name + " (offsets " +
            std::to_string(gd.getGridPos()) + ", " + std::to_string(gd.getBlockPos()) + ", " +
            std::to_string(gd.getEndPos()) + " after byte " + std::to_string(here) + ")");
        }
        this->ReadGridHeader(entry);
        gd.seekToEnd(this->Stream);
      }
      else
      {
        // Written to a stream that could not seek: no offsets, the grids are read in turn.
        // Its header first (as for the others), then its tree walked to where it ends.
        const std::int64_t start = this->Position();
        this->ScanGridHeader(gd, this->Size);
        if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
        {
          entry.Compression = this->ReadU32(this->Size);
          this->Stream.seekg(start);
        }
        readGridCompression(this->Stream);
        openvdb::GridBase::Ptr header = openvdb::GridBase::createGrid(gd.gridType());
        header->readMeta(this->Stream);
        OpenVDBTreeLayout layout;
        layout.GridType = gd.gridType();
        layout.SaveFloatAsHalf = gd.saveFloatAsHalf();
        layout.Compression = entry.Compression;
        layout.FileVersion = this->fileVersion();
        if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING &&
          !gd.isInstance())
        {
          header->readTransform(this->Stream);
          if (IsCheckableOpenVDBTree(layout))
          {
            try
            {
              CheckOpenVDBTree(this->Stream, this->Position(), -1, this->Size, layout);
            }
            catch (const std::runtime_error& e)
            {
              this->Fail("grid '" + gd.gridName() + "': " + e.what());
            }
          }
        }
        this->Stream.clear();
        this->Stream.seekg(start);
        entry.Grid = openvdb::GridBase::createGrid(gd.gridType());
        entry.Grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
        Archive::readGrid(entry.Grid, gd, this->Stream);
      }
      this->Entries.push_back(entry);
    }
    if (!this->inputHasGridOffsets())
    {
      NamedGridMap grids;
      for (const auto& e : this->Entries)
      {
        grids[e.Descriptor.uniqueName()] = e.Grid;
      }
      for (const auto& e : this->Entries)
      {
        this->connectInstance(e.Descriptor, grids);
      }
    }
  }
  catch (const std::ios_base::failure&)
  {
    this->Fail("the file ends early at byte " + std::to_string(this->Size) +
      " (truncated, or a size in it is corrupt)");
  }
  catch (const openvdb::Exception& e)
  {
    this->Fail(std::string("corrupt or unsupported content (") + e.what() + ")");
  }
  catch (const std::bad_alloc&)
  {
    this->Fail("corrupt content (a size in it asks for more memory than there is)");
  }
}

openvdb::GridBase::Ptr OpenVDBCheckedArchive::ReadGrid(std::size_t index)
{
  if (index >= this->Entries.size())
  {
    this->Fail("no grid number " + std::to_string(index));
  }
  const Entry& entry = this->Entries[index];
  if (!this->inputHasGridOffsets())
  {
    return entry.Grid; // read in full when opened
  }
  const openvdb::io::GridDescriptor& gd = entry.Descriptor;
  this->Stream.clear();
  try
  {
    openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(gd.gridType());
    grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
    this->ReadTree(entry, grid);
    if (gd.isInstance())
    {
      const Entry* parent = nullptr;
      for (const auto& e : this->Entries)
      {
        if (e.Descriptor.uniqueName() == gd.instanceParentName() && !e.Descriptor.isInstance())
        {
          parent = &e;
        }
      }
      if (!parent)
      {
        this->Fail("grid '" + gd.gridName() + "' is an instance of a grid the file lacks");
      }
      openvdb::GridBase::Ptr source = openvdb::GridBase::createGrid(parent->Descriptor.gridType());
      source->setSaveFloatAsHalf(parent->Descriptor.saveFloatAsHalf());
      this->ReadTree(*parent, source);
      grid->setTree(source->baseTreePtr());
    }
    return grid;
  }
  catch (const std::ios_base::failure&)
  {
    this->Fail("the data of grid '" + gd.gridName() +
      "' runs past the end of the file (truncated, or a size in it is corrupt)");
  }
  catch (const openvdb::Exception& e)
  {
    this->Fail("corrupt data in grid '" + gd.gridName() + "' (" + e.what() + ")");
  }
  catch (const std::bad_alloc&)
  {
    this->Fail("corrupt data in grid '" + gd.gridName() +
      "' (a size in it asks for more memory than there is)");
  }
}

void OpenVDBCheckedArchive::ReadTree(const Entry& entry, openvdb::GridBase::Ptr grid)
{
  const openvdb::io::GridDescriptor& gd = entry.Descriptor;
  OpenVDBTreeLayout layout;
  layout.GridType = gd.gridType();
  layout.SaveFloatAsHalf = gd.saveFloatAsHalf();
  layout.Compression = entry.Compression;
  layout.FileVersion = this->fileVersion();
  if (!gd.isInstance() && entry.TreePosition >= 0 && IsCheckableOpenVDBTree(layout))
  {
    try
    {
      CheckOpenVDBTree(this->Stream, entry.TreePosition, gd.getBlockPos(), gd.getEndPos(), layout);
    }
    catch (const std::runtime_error& e)
    {
      this->Fail("grid '" + gd.gridName() + "': " + e.what());
    }
  }
  this->Stream.seekg(gd.getGridPos());
  Archive::readGrid(grid, gd, this->Stream);
  const std::int64_t end = this->Position();
  if (end != gd.getEndPos())
  {
    this->Fail("corrupt data in grid '" + gd.gridName() + "': it ends at byte " +
      std::to_string(end) + ", its descriptor says " + std::to_string(gd.getEndPos()) +
      " (a corrupt leaf mask, node flag or block size)");
  }
}

void OpenVDBCheckedArchive::ReadGridHeader(Entry& entry)
{
  const openvdb::io::GridDescriptor& gd = entry.Descriptor;
  this->ScanGridHeader(gd, gd.getEndPos());
  this->Stream.seekg(gd.getGridPos());
  openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(gd.gridType());
  grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
  // What io::File::readGridPartial reads for the metadata: compression, metadata, transform.
  if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
  {
    entry.Compression = this->ReadU32(gd.getEndPos());
    this->Stream.seekg(gd.getGridPos());
  }
  readGridCompression(this->Stream);
  grid->readMeta(this->Stream);
  if ((*grid)[openvdb::GridBase::META_FILE_DELAYED_LOAD])
  {
    grid->removeMeta(openvdb::GridBase::META_FILE_DELAYED_LOAD);
  }
  if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
  {
    grid->readTransform(this->Stream);
    entry.TreePosition = this->Position();
  }
  if (grid->getName().empty())
  {
    grid->setName(gd.gridName());
  }
  entry.Grid = grid;
}

void OpenVDBCheckedArchive::ScanGridHeader(const openvdb::io::GridDescriptor& gd, std::int64_t end)
{
  const std::int64_t start = this->Position();
  const std::string where = "the metadata of grid '" + gd.gridName() + "'";
  if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
  {
    this->ReadU32(end); // the grid's compression flags
  }
  this->ScanMetadata(end, where);
  if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
  {
    this->ReadShortString(end, "transform type"); // what Transform::read allocates
  }
  this->Stream.seekg(start);
}

void OpenVDBCheckedArchive::CheckDescriptor(std::int64_t start)
{
  // What GridDescriptor::read allocates: its strings.
  this->SkipString(this->Size, "grid name");
  this->ReadShortString(this->Size, "grid type");
  if (this->fileVersion() >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
  {
    this->SkipString(this->Size, "instance parent name");
  }
  if (this->Remaining(this->Size) < 3 * 8)
  {
    this->Fail("the file ends inside a grid descriptor (truncated)");
  }
  this->Stream.seekg(start);
}

void OpenVDBCheckedArchive::ScanMetadata(std::int64_t end, const std::string& where)
{
  const std::uint32_t count = this->ReadU32(end);
  if (count > this->Remaining(end) / MinimumMetadataBytes)
  {
    this->Fail("corrupt " + where + ": " + std::to_string(count) + " entries in " +
      std::to_string(this->Remaining(end)) + " bytes");
  }
  for (std::uint32_t i = 0; i < count; ++i)
  {
    this->SkipString(end, "metadata name");
    const std::string type = this->ReadShortString(end, "metadata type");
    const std::uint32_t numBytes = this->ReadLength(end, "metadata value");
    const std::int64_t value = this->Position();
    // MetaMap::readMeta reads registered types with their own reader (which reads its own
    // size, not numBytes) and anything else as numBytes raw bytes.
    if (openvdb::Metadata::isRegisteredType(type))
    {
      if (type == openvdb::io::DelayedLoadMetadata::staticTypeName())
      {
        this->CheckDelayedLoadMetadata(numBytes, value + numBytes, where);
      }
      else if (type != openvdb::StringMetadata::staticTypeName())
      {
        const openvdb::Index32 expected = openvdb::Metadata::createMetadata(type)->size();
        if (numBytes != expected)
        {
          this->Fail("corrupt " + where + ": a value of type '" + type + "' has " +
            std::to_string(numBytes) + " bytes instead of " + std::to_string(expected));
        }
      }
    }
    this->Stream.seekg(value + numBytes);
  }
}

void OpenVDBCheckedArchive::CheckDelayedLoadMetadata(std::uint32_t numBytes,
  std::int64_t end,
  const std::string& where)
{
  // DelayedLoadMetadata::readValue: u32 count; a mask of count bytes and the compressed sizes,
  // count 64-bit values, each raw or as a blosc chunk (u32 bytes first; ~0u: no sizes).
  if (numBytes == 0)
  {
    return;
  }
  const std::string what = "corrupt " + where + " (delayed-load data)";
  const std::uint32_t count = this->ReadU32(end);
  if (count > this->Size / 8) // a leaf takes far more than 8 bytes of the file
  {
    this->Fail(what + ": " + std::to_string(count) + " leaves in a file of " +
      std::to_string(this->Size) + " bytes");
  }
  auto array = [&](std::uint32_t elementBytes, bool optional)
  {
    const std::uint32_t bytes = this->ReadU32(end);
    if (optional && bytes == std::numeric_limits<std::uint32_t>::max())
    {
      return;
    }
    const std::int64_t raw = static_cast<std::int64_t>(count) * elementBytes;
    if (bytes == 0)
    {
      if (raw > this->Remaining(end))
      {
        this->Fail(what + ": " + std::to_string(raw) + " bytes of values do not fit");
      }
      this->Stream.seekg(this->Position() + raw);
      return;
    }
    if (bytes < BloscHeaderBytes || bytes > this->Remaining(end))
    {
      this->Fail(what + ": a compressed block of " + std::to_string(bytes) + " bytes");
    }
    unsigned char header[BloscHeaderBytes];
    const std::int64_t start = this->Position();
    this->Stream.read(reinterpret_cast<char*>(header), BloscHeaderBytes);
    const std::uint32_t nbytes = LittleU32(header + 4), cbytes = LittleU32(header + 12);
    const bool sizeOk = nbytes == raw || (nbytes == BloscPadBytes && raw <= BloscPadBytes);
    if (!sizeOk || cbytes > bytes)
    {
      this->Fail(what + ": a compressed block says " + std::to_string(nbytes) + " bytes (" +
        std::to_string(cbytes) + " compressed) where " + std::to_string(raw) + " (at most " +
        std::to_string(bytes) + ") are expected");
    }
    this->Stream.seekg(start + bytes);
  };
  array(sizeof(openvdb::io::DelayedLoadMetadata::MaskType), false);
  array(sizeof(openvdb::io::DelayedLoadMetadata::CompressedSizeType), true);
}

std::int64_t OpenVDBCheckedArchive::Position()
{
  return static_cast<std::int64_t>(this->Stream.tellg());
}

std::int64_t OpenVDBCheckedArchive::Remaining(std::int64_t end)
{
  return std::max<std::int64_t>(0, end - this->Position());
}

std::uint32_t OpenVDBCheckedArchive::ReadU32(std::int64_t end)
{
  if (this->Remaining(end) < 4)
  {
    this->Fail("the file ends early at byte " + std::to_string(this->Position()) +
      " (truncated, or a size in it is corrupt)");
  }
  unsigned char b[4];
  this->Stream.read(reinterpret_cast<char*>(b), 4);
  return LittleU32(b);
}

std::uint32_t OpenVDBCheckedArchive::ReadLength(std::int64_t end, const char* what)
{
  const std::int64_t at = this->Position();
  const std::uint32_t n = this->ReadU32(end);
  if (n > this->Remaining(end))
  {
    this->Fail(std::string("truncated or corrupt: the ") + what + " at byte " + std::to_string(at) +
      " claims " + std::to_string(n) + " bytes, " + std::to_string(this->Remaining(end)) +
      " remain");
  }
  return n;
}

void OpenVDBCheckedArchive::SkipString(std::int64_t end, const char* what)
{
  const std::uint32_t n = this->ReadLength(end, what);
  this->Stream.seekg(this->Position() + n);
}

std::string OpenVDBCheckedArchive::ReadShortString(std::int64_t end, const char* what)
{
  const std::int64_t at = this->Position();
  const std::uint32_t n = this->ReadLength(end, what);
  if (n > MaximumTypeNameLength)
  {
    this->Fail(std::string("corrupt: the ") + what + " at byte " + std::to_string(at) + " has " +
      std::to_string(n) + " characters");
  }
  std::string s(n, '\0');
  if (n > 0)
  {
    this->Stream.read(&s[0], n);
  }
  return s;
}

void OpenVDBCheckedArchive::Fail(const std::string& what) const
{
  throw std::runtime_error(what);
}

} // namespace avs
