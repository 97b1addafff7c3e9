#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "Classifier.h"
#include "ReferenceRenderer.h"
#include "vtkAVSDataTranslator.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"

#include <string>
#include <vector>

// The data a vtkAVSVolumeMapper draws: the selected array and the mask converted and checked
// when they changed, with the array's values left in the array where they can be
// (vtkAVSDataTranslator::Volume::Deferred); what the GPU upload reads from it; and the host
// copies that only the CPU's precomputation makes.

vtkImageData* vtkAVSVolumeMapper::PrepareInput()
{
  auto& in = *this->Internal;
  std::string error;
  // The input, converted and checked when it changed.
  if (vtkAlgorithm* producer = this->GetInputAlgorithm())
  {
    producer->Update();
  }
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  if (!input)
  {
    if (vtkDataSet* other = this->GetInput())
    {
      vtkErrorMacro("Cannot render: no input image data (the input is a "
        << other->GetClassName()
        << "; these mappers take vtkImageData: resample it, e.g. with vtkResampleToImage).");
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
    in.ScalarsUploaded = false;
    ++in.DataVersion;
    in.PropertyObject = nullptr; // the scalar range may have changed
  }
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
      return nullptr;
    }
    in.MaskObject = mask;
    in.MaskTime = mask ? mask->GetMTime() : 0;
    ++in.DataVersion; // sigma_t depends on it
    in.PropertyObject = nullptr;
  }
  return input;
}

vtkAVSVolumeTextures::ScalarSource vtkAVSVolumeMapper::Internals::ScalarSource() const
{
  vtkAVSVolumeTextures::ScalarSource source;
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

void vtkAVSVolumeMapper::UpdateExtinction()
{
  auto& in = *this->Internal;
  if (in.ExtinctionKey[0] != in.DataVersion || in.ExtinctionKey[1] != in.OpacityVersion)
  {
    in.EnsureHostScalars();
    in.Extinction = avs::ExtinctionGrid(in.Scene);
    in.ExtinctionKey[0] = in.DataVersion;
    in.ExtinctionKey[1] = in.OpacityVersion;
  }
}
