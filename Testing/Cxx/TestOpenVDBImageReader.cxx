// vtkOpenVDBImageReader against VDB files written with OpenVDB at test time: known values,
// level sets, transforms (scale, rotation, translation; shear refused), active tiles, double,
// int32, bool and vector grids, half-float files, user boxes, the memory guard, and every error.
#include "TestErrorObserver.h"
#include "vtkOpenVDBImageReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace
{
std::string Path(const std::string& name)
{
  return std::string(::testing::TempDir()) + "/avs_vdb_" + name;
}

void Write(const std::string& path, const openvdb::GridPtrVec& grids)
{
  openvdb::io::File file(path);
  file.write(grids);
  file.close();
}

struct Reader
{
  vtkNew<vtkOpenVDBImageReader> R;
  vtkNew<TestErrorObserver> Errors;
  Reader(const std::string& path)
  {
    this->R->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    this->R->AddObserver(vtkCommand::WarningEvent, this->Errors);
    this->R->SetFileName(path.c_str());
  }
  vtkImageData* Read()
  {
    this->R->Update();
    return this->R->GetOutput();
  }
  double At(int i, int j, int k, int c = 0)
  {
    return this->R->GetOutput()->GetPointData()->GetScalars()->GetComponent(
      this->R->GetOutput()->ComputePointId(std::array<int, 3>{ i, j, k }.data()), c);
  }
};

class OpenVDBReader : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { openvdb::initialize(); }
};
} // namespace

TEST_F(OpenVDBReader, FogSphereWithKnownValuesTranslationAndScale)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto transform = openvdb::math::Transform::createLinearTransform(0.5);
  transform->postTranslate(openvdb::Vec3d(1, 2, 3));
  grid->setTransform(transform);
  auto acc = grid->getAccessor();
  for (int k = -8; k <= 2; ++k)
    for (int j = 4; j <= 20; ++j)
      for (int i = 3; i <= 17; ++i)
        if ((i - 10) * (i - 10) + (j - 12) * (j - 12) + (k + 3) * (k + 3) <= 25)
          acc.setValue(openvdb::Coord(i, j, k), 1.0f + 0.01f * i + 0.001f * j - 0.1f * k);
  Write(Path("fog.vdb"), { grid });

  Reader r(Path("fog.vdb"));
  vtkImageData* out = r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  int dims[3];
  out->GetDimensions(dims);
  // Active box of the sphere: i 5..15, j 7..17, k -8..2, inclusive.
  EXPECT_EQ(dims[0], 11);
  EXPECT_EQ(dims[1], 11);
  EXPECT_EQ(dims[2], 11);
  double spacing[3], origin[3];
  out->GetSpacing(spacing);
  out->GetOrigin(origin);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_DOUBLE_EQ(spacing[a], 0.5);
  }
  const openvdb::Vec3d world = grid->indexToWorld(openvdb::Vec3d(5, 7, -8));
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR(origin[a], world[a], 1e-12);
  }
  // Values at known voxels, and the background outside the sphere.
  EXPECT_FLOAT_EQ(r.At(10 - 5, 12 - 7, -3 + 8), 1.0f + 0.10f + 0.012f + 0.3f);
  EXPECT_FLOAT_EQ(r.At(15 - 5, 12 - 7, -3 + 8), 1.0f + 0.15f + 0.012f + 0.3f);
  EXPECT_FLOAT_EQ(r.At(0, 0, 0), 0.0f);
  EXPECT_EQ(out->GetPointData()->GetScalars()->GetDataType(), VTK_FLOAT);
  EXPECT_STREQ(r.R->GetGridClass(0), "fog volume");
  EXPECT_STREQ(r.R->GetGridName(0), "density");
}

// The reader releases the sparse grid after the copy; a new execution without
// RequestInformation (here: the output's data released) reads it again, to the same values.
TEST_F(OpenVDBReader, ExecutesAgainAfterTheGridWasReleased)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  auto acc = grid->getAccessor();
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 4; ++i)
        acc.setValue(openvdb::Coord(i, j, k), 0.5f + 0.1f * i + 0.01f * j + 0.001f * k);
  Write(Path("again.vdb"), { grid });

  Reader r(Path("again.vdb"));
  vtkImageData* out = r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  ASSERT_EQ(out->GetNumberOfPoints(), 4 * 5 * 6);
  const double before = r.At(3, 2, 5);
  out->ReleaseData(); // the next update runs RequestData alone (the reader is not modified)
  ASSERT_EQ(out->GetNumberOfPoints(), 0);
  out = r.Read();
  EXPECT_EQ(r.Errors->Errors, 0);
  ASSERT_EQ(out->GetNumberOfPoints(), 4 * 5 * 6);
  EXPECT_FLOAT_EQ(r.At(3, 2, 5), before);
  EXPECT_FLOAT_EQ(r.At(3, 2, 5), 0.5f + 0.3f + 0.02f + 0.005f);
}

TEST_F(OpenVDBReader, LevelSetAsDistanceOrFogVolume)
{
  auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
    2.0f, openvdb::Vec3f(0, 0, 0), 0.1f, 3.0f);
  sphere->setName("ls");
  Write(Path("ls.vdb"), { sphere });
  Reader r(Path("ls.vdb"));
  vtkImageData* out = r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  EXPECT_STREQ(r.R->GetGridClass(0), "level set");
  int dims[3];
  out->GetDimensions(dims);
  const int c = dims[0] / 2;
  // Inside the narrow band: the (negative) background; near the surface: the distance.
  EXPECT_NEAR(r.At(c, c, c), -sphere->background(), 1e-6);
  r.R->LevelSetToFogVolumeOn();
  r.Read();
  EXPECT_NEAR(r.At(c, c, c), 1.0, 1e-6);
  EXPECT_NEAR(r.At(0, c, c), 0.0, 1e-6);
}

TEST_F(OpenVDBReader, RotatedAndAnisotropicallyScaledGrid)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
  m.preScale(openvdb::Vec3d(0.5, 1.0, 2.0));
  m.postRotate(openvdb::math::Z_AXIS, 0.5235987755982988); // 30 degrees
  m.postTranslate(openvdb::Vec3d(4, 5, 6));
  grid->setTransform(openvdb::math::Transform::createLinearTransform(m));
  grid->tree().setValue(openvdb::Coord(1, 2, 3), 7.0f);
  grid->tree().setValue(openvdb::Coord(6, 8, 9), 3.0f);
  Write(Path("rotated.vdb"), { grid });
  Reader r(Path("rotated.vdb"));
  vtkImageData* out = r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  double spacing[3];
  out->GetSpacing(spacing);
  EXPECT_NEAR(spacing[0], 0.5, 1e-12);
  EXPECT_NEAR(spacing[1], 1.0, 1e-12);
  EXPECT_NEAR(spacing[2], 2.0, 1e-12);
  // Both set voxels land where OpenVDB puts them in world space.
  for (const auto& [ijk, value] :
    { std::make_pair(openvdb::Coord(1, 2, 3), 7.0), std::make_pair(openvdb::Coord(6, 8, 9), 3.0) })
  {
    const openvdb::Vec3d expected = grid->indexToWorld(ijk);
    double p[3];
    const double index[3] = { double(ijk.x() - 1), double(ijk.y() - 2), double(ijk.z() - 3) };
    out->TransformContinuousIndexToPhysicalPoint(index, p);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(p[a], expected[a], 1e-9);
    }
    EXPECT_FLOAT_EQ(r.At(ijk.x() - 1, ijk.y() - 2, ijk.z() - 3), value);
  }
  EXPECT_NEAR(out->GetDirectionMatrix()->GetElement(0, 0), std::cos(0.5235987755982988), 1e-12);
  EXPECT_NEAR(out->GetDirectionMatrix()->GetElement(1, 0), std::sin(0.5235987755982988), 1e-12);
}

TEST_F(OpenVDBReader, GeneralAffineMapGoesIntoTheDirectionMatrix)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
  m(1, 0) = 0.5; // shear: index y moves world x
  m.preScale(openvdb::Vec3d(0.5, 2.0, 1.0));
  m.postTranslate(openvdb::Vec3d(1, 2, 3));
  grid->setTransform(openvdb::math::Transform::createLinearTransform(m));
  grid->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  grid->tree().setValue(openvdb::Coord(4, 3, 2), 2.0f);
  Write(Path("shear.vdb"), { grid });
  Reader r(Path("shear.vdb"));
  vtkImageData* out = r.Read();
  EXPECT_EQ(r.Errors->Errors, 0);
  EXPECT_EQ(r.Errors->Warnings, 1); // not orthonormal
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  // Every voxel lands where OpenVDB puts it.
  for (const openvdb::Coord ijk :
    { openvdb::Coord(0, 0, 0), openvdb::Coord(4, 3, 2), openvdb::Coord(1, 3, 0) })
  {
    const openvdb::Vec3d expected = grid->indexToWorld(ijk);
    const double index[3] = { double(ijk.x()), double(ijk.y()), double(ijk.z()) };
    double p[3];
    out->TransformContinuousIndexToPhysicalPoint(index, p);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(p[a], expected[a], 1e-9);
    }
  }
  EXPECT_FLOAT_EQ(r.At(4, 3, 2), 2.0f);
}

TEST_F(OpenVDBReader, NonLinearTransformIsRefused)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  const openvdb::BBoxd box(openvdb::Vec3d(0, 0, 0), openvdb::Vec3d(10, 10, 10));
  grid->setTransform(openvdb::math::Transform::createFrustumTransform(box, 0.5, 2.0, 0.1));
  grid->tree().setValue(openvdb::Coord(1, 1, 1), 1.0f);
  Write(Path("frustum.vdb"), { grid });
  Reader r(Path("frustum.vdb"));
  EXPECT_EQ(r.Read()->GetNumberOfPoints(), 0);
  EXPECT_EQ(r.Errors->Errors, 1);
  EXPECT_NE(r.Errors->LastError.find("non-linear"), std::string::npos);
}

TEST_F(OpenVDBReader, ActiveTilesAndTheBackgroundValue)
{
  auto grid = openvdb::FloatGrid::create(0.25f);
  grid->setName("density");
  // A tile at level 2 (128^3 voxels; level 1 tiles are leaf-sized) and one leaf voxel far from it.
  grid->tree().addTile(2, openvdb::Coord(0, 0, 0), 2.0f, true);
  grid->tree().setValue(openvdb::Coord(200, 5, 5), 9.0f);
  Write(Path("tiles.vdb"), { grid });
  Reader r(Path("tiles.vdb"));
  r.R->SetMaximumNumberOfVoxels(vtkIdType(1) << 30);
  vtkImageData* out = r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  int dims[3];
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 201); // 0..200 inclusive
  EXPECT_EQ(dims[1], 128);
  EXPECT_EQ(dims[2], 128);
  EXPECT_FLOAT_EQ(r.At(64, 64, 64), 2.0f);     // inside the tile
  EXPECT_FLOAT_EQ(r.At(127, 127, 127), 2.0f);  // its last voxel
  EXPECT_FLOAT_EQ(r.At(200, 5, 5), 9.0f);      // the leaf voxel
  EXPECT_FLOAT_EQ(r.At(150, 100, 100), 0.25f); // not stored: the background
}

TEST_F(OpenVDBReader, ManyGridsTypesAndVectors)
{
  auto density = openvdb::DoubleGrid::create(0.0);
  density->setName("density");
  density->tree().setValue(openvdb::Coord(0, 0, 0), 0.123456789012345);
  density->tree().setValue(openvdb::Coord(3, 1, 2), 2.5);
  auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
  velocity->setName("velocity");
  velocity->tree().setValue(openvdb::Coord(0, 0, 0), openvdb::Vec3s(3, 4, 12));
  velocity->tree().setValue(openvdb::Coord(1, 1, 1), openvdb::Vec3s(1, 0, 0));
  auto ids = openvdb::Int32Grid::create(-1);
  ids->setName("ids");
  ids->tree().setValue(openvdb::Coord(2, 2, 2), 42);
  ids->tree().setValue(openvdb::Coord(0, 0, 0), 7);
  auto mask = openvdb::BoolGrid::create(false);
  mask->setName("mask");
  mask->tree().setValue(openvdb::Coord(0, 0, 0), true);
  mask->tree().setValue(openvdb::Coord(1, 0, 0), false);
  mask->tree().setValueOn(openvdb::Coord(1, 0, 0));
  Write(Path("many.vdb"), { velocity, ids, density, mask });

  Reader r(Path("many.vdb"));
  r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  ASSERT_EQ(r.R->GetNumberOfGrids(), 4);
  // OpenVDB lists the grids by name.
  EXPECT_STREQ(r.R->GetGridName(0), "density");
  EXPECT_STREQ(r.R->GetGridValueType(0), "double");
  EXPECT_STREQ(r.R->GetGridName(1), "ids");
  EXPECT_STREQ(r.R->GetGridName(2), "mask");
  EXPECT_STREQ(r.R->GetGridValueType(2), "bool");
  EXPECT_STREQ(r.R->GetGridName(3), "velocity");
  EXPECT_STREQ(r.R->GetGridValueType(3), "vec3s");
  // The default is "density", a double grid kept as double.
  EXPECT_EQ(r.R->GetOutput()->GetPointData()->GetScalars()->GetDataType(), VTK_DOUBLE);
  EXPECT_DOUBLE_EQ(r.At(0, 0, 0), 0.123456789012345);
  EXPECT_DOUBLE_EQ(r.At(3, 1, 2), 2.5);

  r.R->SetGridName("velocity");
  r.Read();
  EXPECT_EQ(r.R->GetOutput()->GetPointData()->GetScalars()->GetNumberOfComponents(), 1);
  EXPECT_FLOAT_EQ(r.At(0, 0, 0), 13.0f); // |(3, 4, 12)|
  r.R->SetVectorMode(vtkOpenVDBImageReader::VECTOR_COMPONENTS);
  r.Read();
  EXPECT_EQ(r.R->GetOutput()->GetPointData()->GetScalars()->GetNumberOfComponents(), 3);
  EXPECT_FLOAT_EQ(r.At(0, 0, 0, 2), 12.0f);
  EXPECT_FLOAT_EQ(r.At(1, 1, 1, 0), 1.0f);

  r.R->SetGridName("ids");
  r.Read();
  EXPECT_EQ(r.R->GetOutput()->GetPointData()->GetScalars()->GetDataType(), VTK_INT);
  EXPECT_EQ(r.At(2, 2, 2), 42);
  EXPECT_EQ(r.At(1, 1, 1), -1); // background
  r.R->SetGridName("mask");
  r.Read();
  EXPECT_EQ(r.R->GetOutput()->GetPointData()->GetScalars()->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(r.At(0, 0, 0), 1);
  EXPECT_EQ(r.At(1, 0, 0), 0);
  EXPECT_EQ(r.Errors->Errors, 0);
}

TEST_F(OpenVDBReader, HalfFloatFile)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setSaveFloatAsHalf(true);
  for (int i = 0; i < 10; ++i)
  {
    grid->tree().setValue(openvdb::Coord(i, 0, 0), 0.1f * i + 0.013f);
  }
  Write(Path("half.vdb"), { grid });
  Reader r(Path("half.vdb"));
  r.Read();
  ASSERT_EQ(r.Errors->Errors, 0);
  for (int i = 0; i < 10; ++i)
  {
    const double expected = 0.1 * i + 0.013;
    EXPECT_NEAR(r.At(i, 0, 0), expected, 1e-3 * expected + 1e-4);
  }
}

TEST_F(OpenVDBReader, UserBoxAndDownsamplingByAveraging)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i)
        grid->tree().setValue(openvdb::Coord(i, j, k), static_cast<float>(i + 10 * j + 100 * k));
  Write(Path("ramp.vdb"), { grid });
  Reader r(Path("ramp.vdb"));
  // A user box reaching outside the active voxels: background there.
  r.R->UseBoundingBoxOn();
  r.R->SetBoundingBox(-2, 9, 0, 7, 3, 3);
  vtkImageData* out = r.Read();
  int dims[3];
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 12);
  EXPECT_EQ(dims[1], 8);
  EXPECT_EQ(dims[2], 1);
  EXPECT_FLOAT_EQ(r.At(0, 0, 0), 0.0f);
  EXPECT_FLOAT_EQ(r.At(2 + 5, 4, 0), 5.0f + 40.0f + 300.0f);
  r.R->UseBoundingBoxOff();
  // The memory guard: at most 64 voxels -> blocks of 2^3 averaged, with a warning.
  r.R->SetMaximumNumberOfVoxels(64);
  r.Errors->Clear();
  out = r.Read();
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4);
  EXPECT_EQ(dims[2], 4);
  EXPECT_EQ(r.Errors->Warnings, 1);
  // Block (1, 2, 3) averages i in {2, 3}, j in {4, 5}, k in {6, 7}.
  EXPECT_FLOAT_EQ(r.At(1, 2, 3), 2.5f + 45.0f + 650.0f);
  double spacing[3], origin[3];
  out->GetSpacing(spacing);
  out->GetOrigin(origin);
  EXPECT_DOUBLE_EQ(spacing[0], 2.0);
  EXPECT_DOUBLE_EQ(origin[0], 0.5); // the first block's centre
  // An explicit factor.
  r.R->SetMaximumNumberOfVoxels(1000000);
  r.R->SetDownsamplingFactor(4);
  out = r.Read();
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_FLOAT_EQ(r.At(0, 0, 0), 1.5f + 15.0f + 150.0f);
}

TEST_F(OpenVDBReader, ErrorsGiveAnEmptyOutputAndAMessage)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  for (int i = 0; i < 600; ++i)
  {
    grid->tree().setValue(openvdb::Coord(i % 30, i / 30, 0), 1.0f);
  }
  Write(Path("good.vdb"), { grid });
  std::ifstream in(Path("good.vdb"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  {
    std::ofstream out(Path("truncated.vdb"), std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  {
    std::ofstream out(Path("random.vdb"), std::ios::binary);
    for (int i = 0; i < 5000; ++i)
    {
      out.put(static_cast<char>((i * 2654435761u) >> 24));
    }
  }
  {
    std::ofstream out(Path("empty.vdb"), std::ios::binary);
  }
  const std::pair<std::string, std::string> cases[] = { { Path("missing.vdb"), "not a readable" },
    { Path("random.vdb"), "not a readable" },
    { Path("empty.vdb"), "not a readable" },
    { Path("truncated.vdb"), "" } };
  for (const auto& [path, text] : cases)
  {
    Reader r(path);
    vtkImageData* out = r.Read();
    EXPECT_EQ(out->GetNumberOfPoints(), 0) << path;
    EXPECT_GE(r.Errors->Errors, 1) << path;
    EXPECT_NE(r.Errors->LastError.find(text), std::string::npos)
      << path << ": " << r.Errors->LastError;
  }
  Reader r(Path("good.vdb"));
  r.R->SetGridName("temperature");
  EXPECT_EQ(r.Read()->GetNumberOfPoints(), 0);
  EXPECT_NE(r.Errors->LastError.find("no grid named 'temperature'"), std::string::npos);
  EXPECT_FALSE(vtkOpenVDBImageReader::CanReadFile(Path("random.vdb").c_str()));
  EXPECT_TRUE(vtkOpenVDBImageReader::CanReadFile(Path("good.vdb").c_str()));
}

// Found by the VDB fuzzer: the factor was chosen from the box's volume over f^3, but the output
// has ceil(extent / f) voxels per axis, whose product exceeded MaximumNumberOfVoxels (4212 for
// 4096 on a box of 128 x 128 x 768).
TEST_F(OpenVDBReader, MemoryGuardCountsTheOutputVoxels)
{
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  grid->tree().setValue(openvdb::Coord(127, 127, 767), 1.0f);
  Write(Path("elongated.vdb"), { grid });
  Reader r(Path("elongated.vdb"));
  r.R->SetMaximumNumberOfVoxels(4096);
  vtkImageData* out = r.Read();
  EXPECT_EQ(r.Errors->Errors, 0);
  EXPECT_GT(out->GetNumberOfPoints(), 0);
  EXPECT_LE(out->GetNumberOfPoints(), 4096);
}
