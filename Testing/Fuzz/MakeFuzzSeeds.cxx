// Writes the seed corpora of the fuzz targets (Testing/Fuzz/Corpus/<target>): valid inputs of
// each kind, small enough for many runs a second. The files in the repository were made with
//   build/bin/MakeFuzzSeeds Testing/Fuzz/Corpus
// and a ctest checks that every seed is still accepted (a seed that is refused finds nothing).
#include "ScatteringTable.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;

void Save(const fs::path& path, const std::vector<unsigned char>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Tables: small axes, plausible values (A > 0, F between exp(-2 tau) and 1).
void Tables(const fs::path& dir)
{
  const int axes[][4] = { { 2, 2, 1, 2 }, { 3, 4, 2, 3 }, { 5, 3, 3, 2 } };
  int n = 0;
  for (const auto& a : axes)
  {
    avs::ScatteringTableAxes ax;
    ax.NumberOfTheta = a[0];
    ax.NumberOfTau = a[1];
    ax.NumberOfAnisotropy = a[2];
    ax.NumberOfAlbedo = a[3];
    ax.TauMaximum = 8.0 + n;
    ax.AnisotropyMinimum = a[2] == 1 ? 0.0 : -0.9;
    ax.AnisotropyMaximum = a[2] == 1 ? 0.0 : 0.9;
    avs::ScatteringTable t;
    t.Allocate(ax);
    for (std::size_t i = 0; i < t.A.size(); ++i)
    {
      t.A[i] = 0.05f + 0.01f * static_cast<float>(i % 17);
      t.AError[i] = 1e-4f;
    }
    for (int l = 0; l < ax.NumberOfAlbedo; ++l)
      for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
        for (int j = 0; j < ax.NumberOfTau; ++j)
        {
          const double tau = ax.Tau(j);
          t.F[t.FIndex(j, k, l)] =
            static_cast<float>(std::exp(-2.0 * tau) * (1.0 + ax.Albedo(l) * tau));
          t.FError[t.FIndex(j, k, l)] = 1e-5f;
        }
    t.Seed = 7;
    std::vector<unsigned char> bytes = t.Serialize();
    for (unsigned char mode : { 0, 1 })
    {
      std::vector<unsigned char> seed{ mode };
      seed.insert(seed.end(), bytes.begin(), bytes.end());
      Save(dir / ("table_" + std::to_string(n) + "_mode" + std::to_string(mode) + ".bin"), seed);
    }
    ++n;
  }
}

void WriteVDB(const fs::path& path, const openvdb::GridPtrVec& grids, std::uint32_t compression)
{
  openvdb::io::File file(path.string());
  file.setCompression(compression);
  file.write(grids);
  file.close();
}

openvdb::FloatGrid::Ptr Fog(float value, int radius)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto acc = grid->getAccessor();
  for (int k = -radius; k <= radius; ++k)
    for (int j = -radius; j <= radius; ++j)
      for (int i = -radius; i <= radius; ++i)
        if (i * i + j * j + k * k <= radius * radius)
          acc.setValue(openvdb::Coord(i + 4, j + 5, k + 6), value + 0.01f * (i + j));
  return grid;
}

void VDBs(const fs::path& dir)
{
  using openvdb::io::COMPRESS_ACTIVE_MASK;
  using openvdb::io::COMPRESS_BLOSC;
  using openvdb::io::COMPRESS_NONE;
  using openvdb::io::COMPRESS_ZIP;
  WriteVDB(dir / "fog_blosc.vdb", { Fog(1.0f, 3) }, COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK);
  {
    // OpenVDB writes fog volumes and level sets without zip: a grid of no class gets it.
    auto zipped = Fog(0.5f, 3);
    zipped->setGridClass(openvdb::GRID_UNKNOWN);
    WriteVDB(dir / "fog_zip.vdb", { zipped }, COMPRESS_ZIP | COMPRESS_ACTIVE_MASK);
  }
  WriteVDB(dir / "fog_none.vdb", { Fog(2.0f, 2) }, COMPRESS_NONE);
  WriteVDB(dir / "fog_mask.vdb", { Fog(2.0f, 2) }, COMPRESS_ACTIVE_MASK);
  {
    auto half = Fog(1.5f, 3);
    half->setSaveFloatAsHalf(true);
    half->setGridClass(openvdb::GRID_UNKNOWN);
    WriteVDB(dir / "fog_half.vdb", { half }, COMPRESS_ZIP | COMPRESS_ACTIVE_MASK);
  }
  {
    auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
      3.0f, openvdb::Vec3f(0, 0, 0), 1.0f, 2.0f);
    sphere->setName("surface");
    WriteVDB(dir / "levelset.vdb", { sphere }, COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK);
  }
  {
    auto tiles = openvdb::FloatGrid::create(0.25f);
    tiles->setName("density");
    tiles->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(15)), 1.0f, true);
    tiles->tree().setValue(openvdb::Coord(3, 20, 1), 3.0f);
    auto t = openvdb::math::Transform::createLinearTransform(0.5);
    t->postRotate(0.3, openvdb::math::Z_AXIS);
    t->postTranslate(openvdb::Vec3d(1, -2, 3));
    tiles->setTransform(t);
    WriteVDB(dir / "tiles_rotated.vdb", { tiles }, COMPRESS_ZIP | COMPRESS_ACTIVE_MASK);
  }
  {
    auto ids = openvdb::Int32Grid::create(0);
    ids->setName("ids");
    auto mask = openvdb::BoolGrid::create(false);
    mask->setName("mask");
    auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0));
    velocity->setName("velocity");
    auto dbl = openvdb::DoubleGrid::create(0.0);
    dbl->setName("temperature");
    for (int i = 0; i < 6; ++i)
    {
      ids->tree().setValue(openvdb::Coord(i, 2 * i, 1), i * 7);
      mask->tree().setValue(openvdb::Coord(i, 1, i), true);
      velocity->tree().setValue(openvdb::Coord(1, i, 2), openvdb::Vec3s(i, -1, 0.5f));
      dbl->tree().setValue(openvdb::Coord(i, i, i), 0.1 * i);
    }
    WriteVDB(
      dir / "many_grids.vdb", { ids, mask, velocity, dbl }, COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK);
  }
  {
    auto fog = Fog(1.0f, 2);
    openvdb::GridBase::Ptr copy = fog->copyGrid(); // shares the tree: written as an instance
    copy->setName("instance");
    WriteVDB(dir / "instance.vdb", { fog, copy }, COMPRESS_ZIP | COMPRESS_ACTIVE_MASK);
  }
  {
    // Written to a stream that cannot seek: no grid offsets.
    std::ofstream out(dir / "stream_no_offsets.vdb", std::ios::binary);
    openvdb::io::Stream(out).write(openvdb::GridPtrVec{ Fog(1.0f, 2) });
  }
}

// Translator inputs, in the order FuzzSceneTranslator reads them: flags, dimensions and
// extent starts, spacing, origin, [direction], scalar kind, values; then 24 bytes of settings.
void Images(const fs::path& dir)
{
  struct Seed
  {
    const char* Name;
    std::uint8_t Flags;
    std::uint8_t Dims[3];
    std::int16_t Start[3];
    std::vector<std::uint8_t> Direction;
    std::uint8_t Kind;
  };
  const Seed seeds[] = { { "uchar_identity", 0x00, { 6, 5, 4 }, { 0, 0, 0 }, {}, 2 },
    { "float_rotated", 0x04, { 5, 5, 5 }, { -3, 2, 7 }, { 200, 40, 90, 10 }, 11 },
    { "short_permuted", 0x08, { 4, 7, 3 }, { 10, -5, 0 }, { 0x2b }, 3 },
    { "double_offset", 0x00, { 8, 3, 6 }, { 100, 100, -100 }, {}, 12 },
    { "int_identity", 0x00, { 3, 3, 3 }, { 0, 0, 0 }, {}, 5 } };
  int mode = 0;
  for (const Seed& s : seeds)
  {
    std::vector<std::uint8_t> b{ s.Flags };
    for (int a = 0; a < 3; ++a)
    {
      b.push_back(s.Dims[a]);
      b.push_back(0); // Range reads 16 bits
      b.push_back(static_cast<std::uint8_t>(s.Start[a] & 0xff));
      b.push_back(static_cast<std::uint8_t>((s.Start[a] >> 8) & 0xff));
    }
    for (int a = 0; a < 3; ++a)
    {
      b.push_back(static_cast<std::uint8_t>(60 + 40 * a));  // spacing
      b.push_back(static_cast<std::uint8_t>(100 + 20 * a)); // origin
    }
    b.insert(b.end(), s.Direction.begin(), s.Direction.end());
    b.push_back(s.Kind);
    const int points = s.Dims[0] * s.Dims[1] * s.Dims[2];
    for (int i = 0; i < points; ++i)
    {
      // A blob-like pattern of small values, written as the scalar type's bytes (floats for
      // float and double, little-endian integers for the rest).
      const int v = (i * 37) % 97 < 40 ? 3 : 60 + (i % 50);
      unsigned char bytes[8] = {};
      std::size_t n = 1;
      if (s.Kind == 11)
      {
        const float f = static_cast<float>(v);
        std::memcpy(bytes, &f, n = 4);
      }
      else if (s.Kind == 12)
      {
        const double d = v;
        std::memcpy(bytes, &d, n = 8);
      }
      else
      {
        bytes[0] = static_cast<unsigned char>(v);
        n =
          s.Kind == 3 || s.Kind == 4 ? 2 : (s.Kind == 5 || s.Kind == 6 ? 4 : (s.Kind < 3 ? 1 : 8));
      }
      b.insert(b.end(), bytes, bytes + n);
    }
    // Two nodes (position, red, green, opacity), unit distance, camera azimuth, elevation and
    // distance, parallel projection, render mode; zeros after.
    const std::uint8_t settings[24] = { 2,
      0,
      0,
      40,
      200,
      80,
      0,
      160,
      255,
      230,
      200,
      100,
      40,
      150,
      120,
      static_cast<std::uint8_t>(mode % 2),
      static_cast<std::uint8_t>(mode % 3) };
    ++mode;
    b.insert(b.end(), settings, settings + 24);
    Save(dir / (std::string(s.Name) + ".bin"), b);
  }
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s CORPUS_FOLDER\n", argv[0]);
    return 2;
  }
  openvdb::initialize();
  const fs::path root(argv[1]);
  for (const char* target : { "table", "vdb", "translator" })
  {
    fs::create_directories(root / target);
  }
  Tables(root / "table");
  VDBs(root / "vdb");
  Images(root / "translator");
  std::printf("seeds written to %s\n", root.c_str());
  return 0;
}
