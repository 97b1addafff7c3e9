#include "vtkAVSClipTranslator.h"

#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"

#include <array>
#include <cmath>
#include <sstream>

bool vtkAVSClipTranslator::ToClipRegion(vtkPlaneCollection* planes,
  bool cropping,
  const double croppingPlanes[6],
  int croppingRegionFlags,
  vtkImageData* image,
  const avs::GridGeometry& grid,
  vtkMatrix4x4* dataToWorld,
  avs::ClipRegion& region,
  std::string& error)
{
  region = avs::ClipRegion();
  // index -> world: world = V (origin + D diag(spacing) index), V the volume's matrix.
  const std::array<double, 12> indexToData = avs::IndexToWorldMap(grid);
  std::array<double, 12> indexToWorld = indexToData;
  if (dataToWorld)
  {
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        double sum = c == 3 ? dataToWorld->GetElement(r, 3) : 0.0;
        for (int k = 0; k < 3; ++k)
        {
          sum += dataToWorld->GetElement(r, k) * indexToData[4 * k + c];
        }
        indexToWorld[4 * r + c] = sum;
      }
    }
  }
  const int count = planes ? planes->GetNumberOfItems() : 0;
  if (count > avs::ClipRegion::MaximumNumberOfPlanes)
  {
    std::ostringstream os;
    os << count << " clipping planes (at most " << avs::ClipRegion::MaximumNumberOfPlanes
       << " are supported, as by vtkGPUVolumeRayCastMapper)";
    error = os.str();
    return false;
  }
  for (int p = 0; p < count; ++p)
  {
    vtkPlane* plane = planes->GetItem(p);
    if (!plane)
    {
      continue;
    }
    double o[3], n[3];
    plane->GetOrigin(o);
    plane->GetNormal(n);
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!std::isfinite(length) || !(length > 0.0) || !std::isfinite(o[0]) || !std::isfinite(o[1]) ||
      !std::isfinite(o[2]))
    {
      std::ostringstream os;
      os << "clipping plane " << p << " has a zero or non-finite normal or a non-finite origin";
      error = os.str();
      return false;
    }
    region.Planes.push_back(
      avs::PlaneToIndex({ o[0], o[1], o[2] }, { n[0], n[1], n[2] }, indexToWorld));
  }
  if (cropping && image)
  {
    double origin[3], spacing[3];
    int extent[6];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    image->GetExtent(extent);
    for (int i = 0; i < 6; ++i)
    {
      const int a = i / 2;
      if (!std::isfinite(croppingPlanes[i]))
      {
        error = "the cropping region planes are not finite";
        return false;
      }
      // Data coordinate x = origin + (extent start + index) spacing along axis a.
      // The grid's index 0 is the first point, or the first cell's centre for cell data
      // (half a voxel on).
      region.CroppingPlanes[i] = (croppingPlanes[i] - origin[a]) / spacing[a] - extent[2 * a] -
        (grid.Border > 0.0 ? 0.5 : 0.0);
    }
    region.Cropping = true;
    region.CroppingRegionFlags = croppingRegionFlags;
  }
  return true;
}
