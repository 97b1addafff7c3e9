// The clip translator (vtkAVSClipTranslator, private) places clipping planes and cropping in the
// index frame of the grid the data translator made: for point data the grid's index 0 is the
// extent's first point, for cell data the first cell's centre, half a voxel on. A cropping
// plane at a data coordinate and a clipping plane through a world point must land on the same
// physical place for both; were cell data placed like point data, the cell grid would be cut
// half a voxel off.
#include "ClipRegion.h"
#include "vtkAVSClipTranslator.h"
#include "vtkAVSDataTranslator.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkVolumeMapper.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
int failures = 0;
#define AVS_CHECK(x)                                                                               \
  do                                                                                               \
  {                                                                                                \
    if (!(x))                                                                                      \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #x "\n";                      \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (false)

bool Near(double a, double b)
{
  return std::abs(a - b) < 1e-9;
}
} // namespace

int main(int, char*[])
{
  // 11 points (10 cells) per axis from extent 2, origin (1, 2, 3), spacing (0.5, 1, 2).
  vtkNew<vtkImageData> image;
  image->SetExtent(2, 12, 2, 12, 2, 12);
  image->SetOrigin(1, 2, 3);
  image->SetSpacing(0.5, 1, 2);
  vtkNew<vtkFloatArray> points, cells;
  points->SetNumberOfTuples(image->GetNumberOfPoints());
  points->Fill(1.0);
  cells->SetNumberOfTuples(image->GetNumberOfCells());
  cells->Fill(1.0);
  image->GetPointData()->SetScalars(points);
  image->GetCellData()->SetScalars(cells);

  const double spacing[3] = { 0.5, 1, 2 }, origin[3] = { 1, 2, 3 };
  // Cropping planes at data x = origin + (extent start + 3) spacing and (extent start + 7.5)
  // spacing: point indices 3 and 7.5, cell-centre indices 2.5 and 7.
  double planes[6];
  for (int a = 0; a < 3; ++a)
  {
    planes[2 * a] = origin[a] + (2 + 3.0) * spacing[a];
    planes[2 * a + 1] = origin[a] + (2 + 7.5) * spacing[a];
  }
  for (bool cellData : { false, true })
  {
    avs::GridGeometry grid;
    std::string error;
    AVS_CHECK(vtkAVSDataTranslator::ToGeometry(image, cellData, grid, error));
    AVS_CHECK(grid.Dimensions[0] == (cellData ? 10 : 11));
    // A clipping plane x >= data x at point index 4 (world = data: no volume matrix).
    vtkNew<vtkPlaneCollection> clipping;
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(origin[0] + (2 + 4.0) * spacing[0], 0, 0);
    plane->SetNormal(1, 0, 0);
    clipping->AddItem(plane);
    avs::ClipRegion region;
    AVS_CHECK(vtkAVSClipTranslator::ToClipRegion(
      clipping, true, planes, VTK_CROP_SUBVOLUME, image, grid, nullptr, region, error));
    const double shift = cellData ? 0.5 : 0.0;
    for (int a = 0; a < 3; ++a)
    {
      std::cout << (cellData ? "cell" : "point") << " data, axis " << a << ": cropping at "
                << region.CroppingPlanes[2 * a] << ", " << region.CroppingPlanes[2 * a + 1] << "\n";
      AVS_CHECK(Near(region.CroppingPlanes[2 * a], 3.0 - shift));
      AVS_CHECK(Near(region.CroppingPlanes[2 * a + 1], 7.5 - shift));
    }
    // Just inside and just outside the clipping plane at point index 4 (cell index 3.5), in
    // the middle of the kept cropping region along y and z.
    const avs::Vec3 inside{ 4.01 - shift, 5.0, 5.0 }, outside{ 3.99 - shift, 5.0, 5.0 };
    AVS_CHECK(region.IsInside(inside));
    AVS_CHECK(!region.IsInside(outside));
    // Beyond the high cropping plane: gone.
    AVS_CHECK(!region.IsInside(avs::Vec3{ 7.51 - shift, 5.0, 5.0 }));
    AVS_CHECK(region.IsInside(avs::Vec3{ 7.49 - shift, 5.0, 5.0 }));
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
