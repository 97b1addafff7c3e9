/**
 * @class   vtkAVSDataTranslator
 * @brief   the array a volume mapper draws, converted into the core's grids (private)
 *
 * Finds the scalars as vtkGPUVolumeRayCastMapper finds them (vtkAbstractMapper::GetScalars with
 * the mapper's ScalarMode, ArrayAccessMode, ArrayId and ArrayName: point or cell scalars, point
 * or cell field data by name or index) and copies them, any scalar type, one float grid per
 * component, into the core's types. Point data samples the image's points; cell data samples
 * the cell centres, and the volume still spans the points (GridGeometry::Border = 0.5), which
 * is how VTK's mapper renders cell scalars. Every check of the input lives here, so the mappers
 * and the reference renderer reject the same bad input with the same messages.
 */
#ifndef vtkAVSDataTranslator_h
#define vtkAVSDataTranslator_h

#include "Grid.h"

#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkDataArray;
class vtkImageData;

class vtkAVSDataTranslator
{
public:
  /// Largest number of voxels the CPU code accepts (2^30).
  static constexpr double MaximumVoxels = 1073741824.0;
  /// Largest number of components (VTK's volume mappers take up to 4).
  static constexpr int MaximumComponents = 4;

  /// Which array to draw: vtkAbstractVolumeMapper's settings (VTK_SCALAR_MODE_*,
  /// VTK_GET_ARRAY_BY_ID or _BY_NAME, the index or the name).
  struct Selection
  {
    int ScalarMode = 0; // VTK_SCALAR_MODE_DEFAULT: point scalars, else cell scalars
    int ArrayAccessMode = 0;
    int ArrayId = -1;
    std::string ArrayName;
  };

  /// The selected array on the core's grids.
  struct Volume
  {
    /// One grid per component. Where a voxel has a NaN component, every component holds 0 there
    /// and Validity is 0 (NaN is empty space, ALGORITHM.md section 1); infinities are clamped
    /// into the component's finite range.
    std::vector<avs::Grid> Components;
    /// Finite range of each component (NaN and infinities ignored, as VTK's GetFiniteRange).
    std::vector<std::array<double, 2>> Ranges;
    /// Empty when every voxel is finite, else 1 at voxels without NaN and 0 at voxels with one.
    avs::Grid Validity;
    vtkIdType NaNVoxels = 0;       ///< voxels with a NaN component
    vtkIdType Infinities = 0;      ///< infinite values clamped
    bool CellData = false;         ///< samples at the cell centres
    int ScalarType = 0;            ///< the array's VTK type
    vtkDataArray* Array = nullptr; ///< the array that was converted (not owned)
    /// The component grids have their geometry but no values: ToVolume was asked not to copy
    /// (deferCopy) and the array allows it (no NaN, the standard memory layout). CopyValues
    /// reads the values from Array when they are needed, a slab at a time.
    bool Deferred = false;
  };

  /// The selected array of `image`, or nullptr with the reason in `error`. `cellData` says
  /// whether it is cell data.
  static vtkDataArray* Select(vtkImageData* image,
    const Selection& selection,
    bool& cellData,
    std::string& error);

  /// Checks `image` and converts the selected array. Returns false with a message in `error`
  /// for: no image, an empty image, no such array, a non-numeric array, more than 4 components,
  /// a volume less than 2 samples thick, non-finite or non-positive spacing, a non-finite origin,
  /// a direction matrix that is not orthonormal, too many voxels, a spacing outside
  /// [1e-30, 1e30] or a box beyond +-1e30 (single precision on the GPU), an image more than 2^23
  /// times as long as its smallest spacing (rays of over 2^24 samples), finite values beyond
  /// the single-precision range. `warning` is set (else left
  /// empty) when the data has NaN or infinite values: their counts, once per conversion.
  /// With `deferCopy` the values are not copied where they need not be (Volume::Deferred): a
  /// GPU mapper converts them while it uploads them, so that the process never holds a float
  /// copy of the whole volume.
  static bool ToVolume(vtkImageData* image,
    const Selection& selection,
    Volume& volume,
    std::string& error,
    std::string& warning,
    bool deferCopy = false);

  /// The values of component `c` of the tuples [begin, end) of `array` as floats in `out`,
  /// infinities clamped into `range` (the component's finite range), as ToVolume converts them.
  static void CopyValues(vtkDataArray* array,
    int c,
    const std::array<double, 2>& range,
    vtkIdType begin,
    vtkIdType end,
    float* out);
  /// Copies the values of a deferred volume into its component grids (Deferred becomes false).
  static void Materialize(Volume& volume);

  /// The mask of a volume (vtkGPUVolumeRayCastMapper::SetMaskInput): its point scalars, else
  /// its cell scalars, first component, on the volume's samples. VTK's mapper reads the mask
  /// with the volume's texture coordinates, so its samples must match the volume's in number
  /// (points for point data, cells for cell data); its own origin and spacing are not used.
  /// NaN mask values count as 0. Returns false with a message when it has no scalars or does
  /// not match.
  static bool ToMask(vtkImageData* mask,
    const avs::GridGeometry& volume,
    avs::Grid& out,
    std::string& error);

  /// The placement of `image`'s points (CellData false) or of its cell centres (true) as a core
  /// grid geometry, or false with a message in `error` (bad spacing, origin or direction).
  static bool ToGeometry(vtkImageData* image,
    bool cellData,
    avs::GridGeometry& geometry,
    std::string& error);
};

#endif
