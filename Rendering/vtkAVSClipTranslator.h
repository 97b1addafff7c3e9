/**
 * @class   vtkAVSClipTranslator
 * @brief   a volume's clipping planes and cropping as the core's clip region (private)
 *
 * VTK gives clipping planes (vtkAbstractMapper::ClippingPlanes) in world coordinates and
 * cropping (vtkVolumeMapper: Cropping, CroppingRegionPlanes, CroppingRegionFlags) in data
 * coordinates; the core (Core/ClipRegion.h) holds both in the data grid's index frame. The
 * planes go through the whole index -> world map, the vtkVolume's matrix included, so they stay
 * where they are in the world when the volume moves, scales or shears, as in
 * vtkGPUVolumeRayCastMapper. The cropping planes are positions along the image's own axes in
 * its data coordinates, origin + index x spacing (the direction matrix turns the cropping box
 * with the image); with the identity direction matrix these are VTK's data coordinates.
 */
#ifndef vtkAVSClipTranslator_h
#define vtkAVSClipTranslator_h

#include "ClipRegion.h"

#include <string>

class vtkImageData;
class vtkMatrix4x4;
class vtkPlaneCollection;

class vtkAVSClipTranslator
{
public:
  /// The region of `image` (converted to `grid` by vtkAVSDataTranslator::ToVolume) placed in
  /// the world by `dataToWorld` (the vtkVolume's matrix; nullptr: the identity). Returns false
  /// with a message for more than avs::ClipRegion::MaximumNumberOfPlanes planes, a plane with a
  /// zero or non-finite normal or a non-finite origin, or non-finite cropping planes.
  static bool ToClipRegion(vtkPlaneCollection* planes,
    bool cropping,
    const double croppingPlanes[6],
    int croppingRegionFlags,
    vtkImageData* image,
    const avs::GridGeometry& grid,
    vtkMatrix4x4* dataToWorld,
    avs::ClipRegion& region,
    std::string& error);
};

#endif
