#include "vtkAVSDataTranslator.h"

#include "vtkAbstractMapper.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace
{
constexpr double MinimumSpacing = 1e-30;
constexpr double MaximumCoordinate = 1e30;
constexpr double MaximumSamplesPerAxis = 1 << 23; // half-spacing samples: 2^24 per axis

template<typename T>
void CopyComponent(const T* in,
  vtkIdType begin,
  vtkIdType end,
  int components,
  int c,
  float lo,
  float hi,
  float* out)
{
  for (vtkIdType i = begin; i < end; ++i)
  {
    float v = static_cast<float>(in[i * components + c]);
    if constexpr (std::is_floating_point_v<T>)
    {
      v = std::isinf(v) ? (v > 0 ? hi : lo) : v;
    }
    *out++ = v;
  }
}

// Counts the tuples with a NaN component and the infinite values (as floats).
template<typename T>
void CountNonFinite(const T* in, vtkIdType n, int components, vtkIdType& nan, vtkIdType& inf)
{
  if constexpr (std::is_floating_point_v<T>)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      bool isNaN = false;
      for (int c = 0; c < components; ++c)
      {
        const float v = static_cast<float>(in[i * components + c]);
        isNaN = isNaN || std::isnan(v);
        inf += std::isinf(v) ? 1 : 0;
      }
      nan += isNaN ? 1 : 0;
    }
  }
  else
  {
    (void)in, (void)n, (void)components, (void)nan, (void)inf;
  }
}

const char* ModeName(int mode)
{
  switch (mode)
  {
    case VTK_SCALAR_MODE_USE_POINT_DATA:
      return "point scalars";
    case VTK_SCALAR_MODE_USE_CELL_DATA:
      return "cell scalars";
    case VTK_SCALAR_MODE_USE_POINT_FIELD_DATA:
      return "point data";
    case VTK_SCALAR_MODE_USE_CELL_FIELD_DATA:
      return "cell data";
    default:
      return "point scalars (nor cell scalars)";
  }
}
} // namespace

vtkDataArray* vtkAVSDataTranslator::Select(vtkImageData* image,
  const Selection& selection,
  bool& cellData,
  std::string& error)
{
  cellData = false;
  if (!image)
  {
    error = "no input image data";
    return nullptr;
  }
  if (image->GetNumberOfPoints() < 1)
  {
    error = "the input image is empty";
    return nullptr;
  }
  const int mode = selection.ScalarMode;
  if (mode == VTK_SCALAR_MODE_USE_FIELD_DATA || mode < VTK_SCALAR_MODE_DEFAULT ||
    mode > VTK_SCALAR_MODE_USE_FIELD_DATA)
  {
    error = "unsupported scalar mode " + std::to_string(mode) +
      " (volumes take point or cell data: default, point data, cell data, point field data, cell "
      "field data)";
    return nullptr;
  }
  const bool field =
    mode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA || mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  const bool byName = selection.ArrayAccessMode == VTK_GET_ARRAY_BY_NAME;
  int flag = 0;
  vtkAbstractArray* array = vtkAbstractMapper::GetAbstractScalars(
    image, mode, selection.ArrayAccessMode, selection.ArrayId, selection.ArrayName.c_str(), flag);
  cellData = flag == 1;
  std::ostringstream os;
  if (!array)
  {
    if (field && byName)
    {
      os << "no array named '" << selection.ArrayName << "' in the " << ModeName(mode);
    }
    else if (field)
    {
      os << "no array with index " << selection.ArrayId << " in the " << ModeName(mode)
         << " (select one with SelectScalarArray)";
    }
    else
    {
      os << "the input image has no " << ModeName(mode);
    }
    error = os.str();
    return nullptr;
  }
  vtkDataArray* data = vtkDataArray::SafeDownCast(array);
  if (!data)
  {
    os << "the selected array '" << (array->GetName() ? array->GetName() : "") << "' ("
       << array->GetClassName() << ") is not numeric";
    error = os.str();
    return nullptr;
  }
  return data;
}

bool vtkAVSDataTranslator::ToGeometry(vtkImageData* image,
  bool cellData,
  avs::GridGeometry& g,
  std::string& error)
{
  int dims[3];
  image->GetDimensions(dims);
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(spacing[a]) || !(spacing[a] > 0.0))
    {
      std::ostringstream os;
      os << "invalid spacing (" << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
         << "): it must be finite and positive";
      error = os.str();
      return false;
    }
    if (!std::isfinite(origin[a]))
    {
      error = "the image origin is not finite";
      return false;
    }
  }
  // Geometry the renderers can compute with (the GPU in single precision): spacing within
  // [1e-30, 1e30], the box within +-1e30, and rays of at most 2^24 samples of half the smallest
  // spacing (the casts of step counts to int are undefined beyond that, and no ray needs it).
  {
    int e[6];
    image->GetExtent(e);
    double lo = spacing[0], length = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      lo = std::min(lo, spacing[a]);
      const double reach = std::max(std::abs(static_cast<double>(e[2 * a])),
                             std::abs(static_cast<double>(e[2 * a + 1]))) *
        spacing[a];
      length = std::max(length, (dims[a] - 1) * spacing[a]);
      if (!(spacing[a] >= MinimumSpacing && spacing[a] <= MaximumCoordinate) ||
        !(std::abs(origin[a]) + reach <= MaximumCoordinate))
      {
        std::ostringstream os;
        os << "the image's geometry (spacing " << spacing[0] << ", " << spacing[1] << ", "
           << spacing[2] << ", origin " << origin[0] << ", " << origin[1] << ", " << origin[2]
           << ") is outside [1e-30, 1e30]";
        error = os.str();
        return false;
      }
    }
    if (!(length / lo <= MaximumSamplesPerAxis))
    {
      std::ostringstream os;
      os << "the image is more than " << MaximumSamplesPerAxis
         << " times as long as its smallest spacing (spacing " << spacing[0] << ", " << spacing[1]
         << ", " << spacing[2] << "): rays would take too many samples";
      error = os.str();
      return false;
    }
  }
  const double* d = image->GetDirectionMatrix()->GetData();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        dot += d[3 * k + r] * d[3 * k + c];
      }
      if (!std::isfinite(dot) || std::abs(dot - (r == c ? 1.0 : 0.0)) > 1e-6)
      {
        error = "the image's direction matrix is not orthonormal";
        return false;
      }
    }
  }
  // VTK 9.1 image data has a direction matrix: world = origin + D (ijk * spacing), where ijk
  // runs over the extent. The core's grid starts at index 0, so its origin is the world
  // position of the first sample: the extent's first point, or the first cell's centre.
  int extent[6];
  image->GetExtent(extent);
  const double shift = cellData ? 0.5 : 0.0;
  const double first[3] = { (extent[0] + shift) * spacing[0],
    (extent[2] + shift) * spacing[1],
    (extent[4] + shift) * spacing[2] };
  g = avs::GridGeometry();
  for (int a = 0; a < 3; ++a)
  {
    g.Dimensions[a] = cellData ? dims[a] - 1 : dims[a];
    g.Spacing[a] = spacing[a];
  }
  g.Origin = { origin[0] + d[0] * first[0] + d[1] * first[1] + d[2] * first[2],
    origin[1] + d[3] * first[0] + d[4] * first[1] + d[5] * first[2],
    origin[2] + d[6] * first[0] + d[7] * first[1] + d[8] * first[2] };
  for (int i = 0; i < 9; ++i)
  {
    g.Direction[i] = d[i];
  }
  g.Border = cellData ? 0.5 : 0.0;
  return true;
}

bool vtkAVSDataTranslator::ToVolume(vtkImageData* image,
  const Selection& selection,
  Volume& volume,
  std::string& error,
  std::string& warning,
  bool deferCopy)
{
  volume = Volume();
  warning.clear();
  if (!image)
  {
    error = "no input image data";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || image->GetNumberOfPoints() < 1)
  {
    error = "the input image is empty";
    return false;
  }
  if (static_cast<double>(dims[0]) * dims[1] * dims[2] > MaximumVoxels)
  {
    error = "the input image is too large (more than 2^30 voxels)";
    return false;
  }
  bool cellData = false;
  vtkDataArray* scalars = Select(image, selection, cellData, error);
  if (!scalars)
  {
    return false;
  }
  const int needed = cellData ? 3 : 2; // points per axis: 2 samples (points or cells)
  if (dims[0] < needed || dims[1] < needed || dims[2] < needed)
  {
    std::ostringstream os;
    os << "the input image is not a volume (dimensions " << dims[0] << " x " << dims[1] << " x "
       << dims[2] << "; at least 2 " << (cellData ? "cells" : "points") << " per axis are needed)";
    error = os.str();
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > MaximumComponents)
  {
    std::ostringstream os;
    os << "unsupported number of scalar components: " << components << " (1 to "
       << MaximumComponents << " are supported)";
    error = os.str();
    return false;
  }
  const vtkIdType n = cellData ? image->GetNumberOfCells() : image->GetNumberOfPoints();
  if (scalars->GetNumberOfTuples() != n)
  {
    error = cellData ? "the cell scalars do not match the image's number of cells"
                     : "the point scalars do not match the image's number of points";
    return false;
  }
  avs::GridGeometry geometry;
  if (!ToGeometry(image, cellData, geometry, error))
  {
    return false;
  }
  volume.CellData = cellData;
  volume.Array = scalars;
  volume.ScalarType = scalars->GetDataType();
  for (int c = 0; c < components; ++c)
  {
    double range[2];
    scalars->GetFiniteRange(range, c);
    if (!(range[0] <= range[1]) || !std::isfinite(range[0]) || !std::isfinite(range[1]))
    {
      range[0] = range[1] = 0.0; // no finite value at all
    }
    // The renderers compute in single precision: finite values beyond its range would become
    // infinities there (found by the translator fuzzer: a double of 1e300).
    constexpr double largest = std::numeric_limits<float>::max();
    if (range[0] < -largest || range[1] > largest)
    {
      std::ostringstream os;
      os << "component " << c << " has values beyond the single-precision range (its finite range "
         << range[0] << " to " << range[1] << "; at most +-" << largest
         << " is supported): rescale the data";
      error = os.str();
      volume = Volume();
      return false;
    }
    volume.Ranges.push_back({ range[0], range[1] });
  }
  // NaN and infinities, counted on the array itself (as floats, which the renderers use).
  const bool standard = scalars->HasStandardMemoryLayout() != 0;
  vtkIdType nanTuples = 0;
  if (standard)
  {
    switch (scalars->GetDataType())
    {
      vtkTemplateMacro(CountNonFinite(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)),
        n,
        components,
        nanTuples,
        volume.Infinities));
      default:
        break; // bits: integers, no NaN
    }
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      bool isNaN = false;
      for (int c = 0; c < components; ++c)
      {
        const float v = static_cast<float>(scalars->GetComponent(i, c));
        isNaN = isNaN || std::isnan(v);
        volume.Infinities += std::isinf(v) ? 1 : 0;
      }
      nanTuples += isNaN ? 1 : 0;
    }
  }
  for (int c = 0; c < components; ++c)
  {
    volume.Components.emplace_back();
    volume.Components.back().Geometry = geometry;
  }
  volume.Deferred = true;
  if (!deferCopy || !standard || nanTuples > 0)
  {
    Materialize(volume);
  }
  // NaN voxels are empty space: every component 0 and validity 0 there.
  if (nanTuples > 0)
  {
    volume.Validity = avs::Grid(geometry, 1.0f);
    for (vtkIdType i = 0; i < n; ++i)
    {
      bool isNaN = false;
      for (const auto& grid : volume.Components)
      {
        isNaN = isNaN || std::isnan(grid.Values[i]);
      }
      if (isNaN)
      {
        volume.Validity.Values[i] = 0.0f;
        for (auto& grid : volume.Components)
        {
          grid.Values[i] = 0.0f;
        }
        ++volume.NaNVoxels;
      }
    }
  }
  if (volume.NaNVoxels || volume.Infinities)
  {
    std::ostringstream os;
    os << "the scalars '" << (scalars->GetName() ? scalars->GetName() : "") << "' have ";
    if (volume.NaNVoxels)
    {
      os << volume.NaNVoxels << " of " << n << " " << (cellData ? "cells" : "points")
         << " with NaN (rendered as empty space)";
    }
    if (volume.NaNVoxels && volume.Infinities)
    {
      os << " and ";
    }
    if (volume.Infinities)
    {
      os << volume.Infinities << " infinite values (clamped to the finite range)";
    }
    warning = os.str();
  }
  return true;
}

void vtkAVSDataTranslator::CopyValues(vtkDataArray* array,
  int c,
  const std::array<double, 2>& range,
  vtkIdType begin,
  vtkIdType end,
  float* out)
{
  const int components = array->GetNumberOfComponents();
  const float lo = static_cast<float>(range[0]), hi = static_cast<float>(range[1]);
  // (vtkTemplateMacro has no case for bit arrays, which GetComponent reads.)
  if (array->HasStandardMemoryLayout() && array->GetDataType() != VTK_BIT)
  {
    switch (array->GetDataType())
    {
      vtkTemplateMacro(CopyComponent(static_cast<const VTK_TT*>(array->GetVoidPointer(0)),
        begin,
        end,
        components,
        c,
        lo,
        hi,
        out));
      default:
        break;
    }
    return;
  }
  for (vtkIdType i = begin; i < end; ++i)
  {
    const float v = static_cast<float>(array->GetComponent(i, c));
    *out++ = std::isinf(v) ? (v > 0 ? hi : lo) : v;
  }
}

void vtkAVSDataTranslator::Materialize(Volume& volume)
{
  if (!volume.Deferred)
  {
    return;
  }
  for (std::size_t c = 0; c < volume.Components.size(); ++c)
  {
    avs::Grid& grid = volume.Components[c];
    grid.Values.assign(grid.Geometry.NumberOfPoints(), 0.0f);
    CopyValues(volume.Array,
      static_cast<int>(c),
      volume.Ranges[c],
      0,
      static_cast<vtkIdType>(grid.Values.size()),
      grid.Values.data());
  }
  volume.Deferred = false;
}

bool vtkAVSDataTranslator::ToMask(vtkImageData* mask,
  const avs::GridGeometry& volume,
  avs::Grid& out,
  std::string& error)
{
  out = avs::Grid();
  bool cellData = false;
  vtkDataArray* scalars = Select(mask, Selection(), cellData, error);
  if (!scalars)
  {
    error = "the mask: " + error;
    return false;
  }
  int dims[3];
  mask->GetDimensions(dims);
  const int shift = cellData ? 1 : 0;
  const int n[3] = { dims[0] - shift, dims[1] - shift, dims[2] - shift };
  const auto& v = volume.Dimensions;
  if (n[0] != v[0] || n[1] != v[1] || n[2] != v[2] ||
    scalars->GetNumberOfTuples() != static_cast<vtkIdType>(volume.NumberOfPoints()))
  {
    std::ostringstream os;
    os << "the mask's " << (cellData ? "cells" : "points") << " (" << n[0] << " x " << n[1] << " x "
       << n[2] << ") do not match the volume's samples (" << v[0] << " x " << v[1] << " x " << v[2]
       << ")";
    error = os.str();
    return false;
  }
  out = avs::Grid(volume);
  // The mask's values as they are (an infinite range clamps nothing).
  const double unbounded = std::numeric_limits<double>::infinity();
  CopyValues(
    scalars, 0, { -unbounded, unbounded }, 0, scalars->GetNumberOfTuples(), out.Values.data());
  for (float& value : out.Values)
  {
    if (std::isnan(value))
    {
      value = 0.0f;
    }
  }
  return true;
}
