#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "Classifier.h"
#include "Fingerprint.h"
#include "ReferenceRenderer.h"
#include "vtkAVSClipTranslator.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSPropertyTranslator.h"

#include "vtkAlgorithm.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

// The scene a vtkAVSVolumeMapper draws (Internals' scene fields): the selected array and the
// mask converted and checked when they changed, with the array's values left in the array where
// they can be (vtkAVSDataTranslator::Volume::Deferred); what the GPU upload reads from it; the
// host copies that only the CPU's precomputation makes; the property's classification and the
// clip region, with the versions that invalidate what is built from them.

namespace
{
// Slices per slab of the fingerprints: a change of a few slices rewrites a few slices.
constexpr int FingerprintSlices = 4;

// What the conversion of `array` depends on besides its values: the grid, the array's type,
// components and tuples, and whether it is cell data.
std::vector<double> ContentKeyOf(vtkImageData* input, vtkDataArray* array, bool cellData)
{
  std::vector<double> key;
  int extent[6];
  input->GetExtent(extent);
  key.insert(key.end(), extent, extent + 6);
  const double* spacing = input->GetSpacing();
  const double* origin = input->GetOrigin();
  key.insert(key.end(), spacing, spacing + 3);
  key.insert(key.end(), origin, origin + 3);
  const double* direction = input->GetDirectionMatrix()->GetData();
  key.insert(key.end(), direction, direction + 9);
  key.push_back(array->GetDataType());
  key.push_back(array->GetNumberOfComponents());
  key.push_back(static_cast<double>(array->GetNumberOfTuples()));
  key.push_back(cellData ? 1.0 : 0.0);
  return key;
}

// The fingerprints of the array's memory in slabs of FingerprintSlices slices along z (slices
// set to FingerprintSlices), or of the whole array where its tuples do not make whole slices
// (slices 0); none where the values are not in one block of memory.
std::vector<std::uint64_t> FingerprintsOf(vtkDataArray* array,
  const int extent[6],
  bool cellData,
  int& slices)
{
  slices = 0;
  if (!array->HasStandardMemoryLayout() || array->GetDataType() == VTK_BIT)
  {
    return {};
  }
  const std::size_t tuples = static_cast<std::size_t>(array->GetNumberOfTuples());
  const std::size_t tupleBytes =
    static_cast<std::size_t>(array->GetDataTypeSize()) * array->GetNumberOfComponents();
  const std::size_t bytes = tuples * tupleBytes;
  const std::size_t depth =
    static_cast<std::size_t>(std::max(1, extent[5] - extent[4] + (cellData ? 0 : 1)));
  std::size_t slab = bytes;
  if (tuples > 0 && tuples % depth == 0)
  {
    slices = FingerprintSlices;
    slab = tuples / depth * tupleBytes * FingerprintSlices;
  }
  return avs::SlabFingerprints(array->GetVoidPointer(0), bytes, slab);
}
} // namespace

vtkImageData* vtkAVSVolumeMapper::PrepareInput()
{
  auto& in = *this->Internal;
  std::string error;
  // The input, converted and checked when it changed.
  if (vtkAlgorithm* producer = this->GetInputAlgorithm())
  {
    producer->Update();
  }
  vtkImageData* input = in.CompositeInput.Resolve(this->GetInputDataObject(0, 0), error);
  if (!input)
  {
    vtkDataObject* given = this->GetInputDataObject(0, 0);
    if (!error.empty())
    {
      // (A vtkMultiBlockDataSet, vtkPartitionedDataSet, ... whose leaves are not pieces of one
      // image.)
      vtkErrorMacro("Cannot render the " << given->GetClassName() << ": " << error << ".");
    }
    else if (vtkDataSet::SafeDownCast(given))
    {
      vtkErrorMacro("Cannot render: no input image data (the input is a "
        << given->GetClassName()
        << "; these mappers take vtkImageData: resample it, e.g. with vtkResampleToImage).");
    }
    else if (vtkCompositeDataSet::SafeDownCast(given))
    {
      // (vtkOverlappingAMR, vtkNonOverlappingAMR: composites that are not trees.)
      vtkErrorMacro("Cannot render: the input is a "
        << given->GetClassName()
        << ", a composite dataset that is not a tree of image blocks; these mappers take a "
           "vtkImageData or a vtkMultiBlockDataSet, vtkPartitionedDataSet or "
           "vtkPartitionedDataSetCollection of vtkImageData pieces of one grid (resample it "
           "onto one grid, e.g. with vtkResampleToImage).");
    }
    else
    {
      vtkErrorMacro("Cannot render: no input image data.");
    }
    return nullptr;
  }
  // The array to draw, as vtkGPUVolumeRayCastMapper selects it.
  vtkAVSDataTranslator::Selection selection;
  selection.ScalarMode = this->ScalarMode;
  selection.ArrayAccessMode = this->ArrayAccessMode;
  selection.ArrayId = this->ArrayId;
  selection.ArrayName = this->ArrayName ? this->ArrayName : "";
  bool cellData = false;
  vtkDataArray* array = vtkAVSDataTranslator::Select(input, selection, cellData, error);
  auto forget = [&in]()
  {
    in.DataObject = nullptr;
    in.Scene = avs::VolumeScene();
    in.SourceArray = nullptr;
    in.Fingerprints.clear();
    in.ContentKey.clear();
  };
  if (!array)
  {
    forget();
    vtkErrorMacro("Cannot render: " << error);
    return nullptr;
  }
  const bool sameSelection = selection.ScalarMode == in.Selection.ScalarMode &&
    selection.ArrayAccessMode == in.Selection.ArrayAccessMode &&
    selection.ArrayId == in.Selection.ArrayId && selection.ArrayName == in.Selection.ArrayName;
  if (input != in.DataObject || input->GetMTime() != in.DataTime || array != in.ArrayObject ||
    array->GetMTime() != in.ArrayTime || !sameSelection ||
    (in.Scene.Scalars.Values.empty() && !in.SourceArray))
  {
    // New data, or the same data modified: its contents against the converted data's.
    std::vector<double> key = ContentKeyOf(input, array, cellData);
    int slices = 0;
    int extent[6];
    input->GetExtent(extent);
    std::vector<std::uint64_t> prints = FingerprintsOf(array, extent, cellData, slices);
    const bool converted = !(in.Scene.Scalars.Values.empty() && !in.SourceArray);
    if (converted && sameSelection && !prints.empty() && key == in.ContentKey &&
      prints == in.Fingerprints)
    {
      // The values of the converted data (a static series, a step shown again): nothing is
      // converted, uploaded or rebuilt. The new array takes the old one's place.
      in.DataObject = input;
      in.DataTime = input->GetMTime();
      in.ArrayObject = array;
      in.ArrayTime = array->GetMTime();
      if (in.SourceArray)
      {
        in.SourceArray = array;
      }
      return this->PrepareMask() ? input : nullptr;
    }
    // The values stay in the array where they can (Volume::Deferred): the upload converts them
    // slab by slab, and only the CPU's precomputation copies them (EnsureHostScalars).
    vtkAVSDataTranslator::Volume data;
    std::string warning;
    in.SourceArray = nullptr;
    if (!vtkAVSDataTranslator::ToVolume(input, selection, data, error, warning, true))
    {
      forget();
      vtkErrorMacro("Cannot render: " << error);
      return nullptr;
    }
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning << ".");
    }
    in.Scene = avs::VolumeScene();
    in.Scene.Scalars = std::move(data.Components[0]);
    for (std::size_t c = 1; c < data.Components.size(); ++c)
    {
      in.Scene.Medium.Components.emplace_back();
      in.Scene.Medium.Components.back().Values = std::move(data.Components[c]);
    }
    in.Scene.Medium.Validity = std::move(data.Validity);
    in.SourceArray = data.Deferred ? data.Array : nullptr;
    in.ScalarInfinities = data.Infinities;
    in.Ranges = data.Ranges;
    in.ScalarType = data.ScalarType;
    in.DataObject = input;
    in.DataTime = input->GetMTime();
    in.ArrayObject = array;
    in.ArrayTime = array->GetMTime();
    in.Selection = selection;
    ++in.ScalarsVersion;
    in.ContentKey = std::move(key);
    in.Fingerprints = std::move(prints);
    in.FingerprintSlices = slices;
    ++in.DataVersion;
    in.PropertyObject = nullptr; // the scalar range may have changed
  }
  return this->PrepareMask() ? input : nullptr;
}

bool vtkAVSVolumeMapper::PrepareMask()
{
  auto& in = *this->Internal;
  std::string error;
  // The mask, on the volume's samples.
  vtkImageData* mask = this->MaskInput;
  if (mask != in.MaskObject || (mask && mask->GetMTime() != in.MaskTime) ||
    (mask && in.Scene.Medium.MaskValues.Values.empty()))
  {
    in.Scene.Medium.MaskValues = avs::Grid();
    in.MaskObject = nullptr;
    if (mask &&
      !vtkAVSDataTranslator::ToMask(
        mask, in.Scene.Scalars.Geometry, in.Scene.Medium.MaskValues, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.MaskObject = mask;
    in.MaskTime = mask ? mask->GetMTime() : 0;
    ++in.DataVersion; // sigma_t depends on it
    in.PropertyObject = nullptr;
  }
  return true;
}

vtkAVSVolumeTextures::ScalarSource vtkAVSVolumeMapper::Internals::ScalarSource() const
{
  vtkAVSVolumeTextures::ScalarSource source;
  // What changed since the upload whose textures are kept (all where the slabs are not slices,
  // or the texels depend on the range).
  if (this->FingerprintSlices > 0 && !this->UploadedFingerprints.empty() &&
    this->UploadedContentKey == this->ContentKey && !this->UploadedRangeDependent &&
    !this->RangeDependent())
  {
    const avs::SlabRange r = avs::ChangedSlabs(this->UploadedFingerprints, this->Fingerprints);
    source.ChangedSlices = { static_cast<int>(r.First) * this->FingerprintSlices,
      static_cast<int>(r.Last) * this->FingerprintSlices };
  }
  vtkDataArray* array = this->SourceArray;
  if (!array || !this->Scene.Scalars.Values.empty())
  {
    return source; // the scene's grids hold the values
  }
  const std::vector<std::array<double, 2>> ranges = this->Ranges;
  source.Read = [array, ranges](int c, std::size_t begin, std::size_t end, float* out)
  {
    vtkAVSDataTranslator::CopyValues(
      array, c, ranges[c], static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end), out);
  };
  // The array's own memory where its values are the texels: unsigned 8 and 16 bits (R8, R16 and
  // their multi-channel forms hold the tuples as they are), floats without infinities.
  const int type = array->GetDataType();
  if (array->HasStandardMemoryLayout() &&
    (type == VTK_UNSIGNED_CHAR || type == VTK_UNSIGNED_SHORT ||
      (type == VTK_FLOAT && this->ScalarInfinities == 0)) &&
    this->Scene.Medium.Validity.Values.empty())
  {
    source.Texels = array->GetVoidPointer(0);
  }
  return source;
}

void vtkAVSVolumeMapper::Internals::EnsureHostScalars()
{
  if (!this->SourceArray || !this->Scene.Scalars.Values.empty())
  {
    return;
  }
  const std::size_t n = this->Scene.Scalars.Geometry.NumberOfPoints();
  for (std::size_t c = 0; c <= this->Scene.Medium.Components.size(); ++c)
  {
    avs::Grid& grid = c == 0 ? this->Scene.Scalars : this->Scene.Medium.Components[c - 1].Values;
    grid.Values.resize(n);
    vtkAVSDataTranslator::CopyValues(this->SourceArray,
      static_cast<int>(c),
      this->Ranges[c],
      0,
      static_cast<vtkIdType>(n),
      grid.Values.data());
  }
}

const avs::Grid& vtkAVSVolumeMapper::UpdateExtinction()
{
  auto& in = *this->Internal;
  if (in.ExtinctionKey[0] != in.DataVersion || in.ExtinctionKey[1] != in.OpacityVersion)
  {
    in.EnsureHostScalars();
    in.Extinction = avs::ExtinctionGrid(in.Scene);
    in.ExtinctionKey[0] = in.DataVersion;
    in.ExtinctionKey[1] = in.OpacityVersion;
  }
  return in.Extinction;
}

bool vtkAVSVolumeMapper::PrepareProperty(vtkVolumeProperty* property)
{
  auto& in = *this->Internal;
  if (property == in.PropertyObject && property->GetMTime() == in.PropertyTime &&
    this->GetMTime() == in.ClassificationTime)
  {
    return true;
  }
  std::string error, warning;
  avs::MediumOptions& medium = in.Scene.Medium;
  medium.Mask = medium.MaskValues.Values.empty()
    ? avs::MaskType::None
    : (this->MaskType == BinaryMaskType ? avs::MaskType::Binary : avs::MaskType::LabelMap);
  medium.MaskBlendFactor = this->MaskBlendFactor;
  if (!vtkAVSPropertyTranslator::ToMedium(property,
        in.Ranges,
        in.ScalarType,
        medium.Mask == avs::MaskType::LabelMap,
        in.Scene,
        error,
        warning))
  {
    in.PropertyObject = nullptr;
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  this->WarnAboutShading(property);
  in.PropertyObject = property;
  in.PropertyTime = property->GetMTime();
  in.ClassificationTime = this->GetMTime();
  ++in.TransferVersion;
  // Extinction depends on the opacity alone: a change of colour alone rebuilds nothing.
  std::vector<double> inputs = avs::ExtinctionKey(in.Scene);
  if (inputs != in.ExtinctionInputs)
  {
    in.ExtinctionInputs = std::move(inputs);
    ++in.OpacityVersion;
  }
  return true;
}

bool vtkAVSVolumeMapper::PrepareClip(vtkImageData* input, vtkMatrix4x4* dataToWorld)
{
  auto& in = *this->Internal;
  std::string error;
  // Clipping planes (world) and cropping (data coordinates) in the index frame.
  avs::ClipRegion clip;
  if (!vtkAVSClipTranslator::ToClipRegion(this->ClippingPlanes,
        this->Cropping != 0,
        this->CroppingRegionPlanes,
        this->CroppingRegionFlags,
        input,
        in.Scene.Scalars.Geometry,
        dataToWorld,
        clip,
        error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  // The clip region is in the scene (its index frame); a change bumps OpacityVersion, since
  // sigma_t depends on it (everything built from sigma_t is rebuilt).
  if (clip != in.Scene.Clip)
  {
    in.Scene.Clip = clip;
    ++in.OpacityVersion;
  }
  return true;
}
