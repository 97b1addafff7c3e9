// Writes a procedural cloud (Rendering/Core/ProceduralVolume: MakeCloud, 64^3) as an OpenVDB fog
// volume named "density", rotated 20 degrees about y and translated, for the tests that render
// imported VDB grids.
#include "ProceduralVolume.h"

#include <openvdb/openvdb.h>

#include <cstdio>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: MakeTestCloudVDB OUTPUT.vdb\n");
    return 1;
  }
  openvdb::initialize();
  const int n = 64;
  const avs::Grid cloud = avs::MakeCloud(n);
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("density");
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
  m.preScale(openvdb::Vec3d(2.0 / (n - 1)));
  m.postRotate(openvdb::math::Y_AXIS, 0.3490658503988659);
  m.postTranslate(openvdb::Vec3d(-1.0, -1.0, -1.0));
  grid->setTransform(openvdb::math::Transform::createLinearTransform(m));
  auto acc = grid->getAccessor();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const float v = cloud.At(i, j, k);
        if (v > 0.0f)
        {
          acc.setValue(openvdb::Coord(i, j, k), v);
        }
      }
  openvdb::io::File file(argv[1]);
  file.write({ grid });
  file.close();
  std::printf("%s\n", argv[1]);
  return 0;
}
