#include "vtkOpenVDBImageReader.h"

#include "OpenVDBCheckedArchive.h"
#include "OpenVDBGridCopy.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenVDBImageReader);

namespace
{
// The largest downsampling factor chosen automatically (MaximumNumberOfVoxels).
constexpr int MaximumAutomaticDownsampling = 16;

struct GridInfo
{
  std::string Name, Class, ValueType;
  double VoxelSize[3] = { 0, 0, 0 };
  int Box[6] = { 0, -1, 0, -1, 0, -1 };
  std::size_t Entry = 0; ///< index in the file
};

const char* ClassName(openvdb::GridClass c)
{
  switch (c)
  {
    case openvdb::GRID_LEVEL_SET:
      return "level set";
    case openvdb::GRID_FOG_VOLUME:
      return "fog volume";
    case openvdb::GRID_STAGGERED:
      return "staggered";
    default:
      return "unknown";
  }
}

bool IsScalarType(const std::string& t)
{
  return t == "float" || t == "double" || t == "int32" || t == "bool" || t == "half";
}
bool IsVectorType(const std::string& t)
{
  return t == "vec3s" || t == "vec3d";
}
} // namespace

struct vtkOpenVDBImageReader::Internals
{
  std::vector<GridInfo> Grids;
  std::string ListedFile;
  openvdb::GridBase::Ptr Grid; ///< the selected grid, read in full (released after the copy)
  std::string GridKey;         ///< file + grid + options it was read with
  avs::OpenVDBLayout Out;
  std::string Error;
};

namespace
{
std::once_flag OpenVDBInitialised;
void InitialiseOpenVDB()
{
  std::call_once(OpenVDBInitialised, [] { openvdb::initialize(); });
}

} // namespace

vtkOpenVDBImageReader::vtkOpenVDBImageReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkOpenVDBImageReader::~vtkOpenVDBImageReader()
{
  this->SetFileName(nullptr);
  this->SetGridName(nullptr);
}

bool vtkOpenVDBImageReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  InitialiseOpenVDB();
  try
  {
    return !avs::OpenVDBCheckedArchive(fileName).GetEntries().empty();
  }
  catch (...)
  {
    return false;
  }
}

int vtkOpenVDBImageReader::GetNumberOfGrids()
{
  return static_cast<int>(this->Internal->Grids.size());
}

const char* vtkOpenVDBImageReader::GetGridName(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < static_cast<int>(g.size()) ? g[i].Name.c_str() : "";
}

const char* vtkOpenVDBImageReader::GetGridClass(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < static_cast<int>(g.size()) ? g[i].Class.c_str() : "";
}

const char* vtkOpenVDBImageReader::GetGridValueType(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < static_cast<int>(g.size()) ? g[i].ValueType.c_str() : "";
}

void vtkOpenVDBImageReader::GetGridVoxelSize(int i, double size[3])
{
  const auto& g = this->Internal->Grids;
  for (int a = 0; a < 3; ++a)
  {
    size[a] = i >= 0 && i < static_cast<int>(g.size()) ? g[i].VoxelSize[a] : 0.0;
  }
}

void vtkOpenVDBImageReader::GetGridBoundingBox(int i, int box[6])
{
  const auto& g = this->Internal->Grids;
  for (int a = 0; a < 6; ++a)
  {
    box[a] = i >= 0 && i < static_cast<int>(g.size()) ? g[i].Box[a] : (a % 2 ? -1 : 0);
  }
}

int vtkOpenVDBImageReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  auto& in = *this->Internal;
  in.Grids.clear();
  in.Grid.reset();
  in.GridKey.clear();
  in.Error.clear();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto fail = [&](const std::string& message)
  {
    in.Error = message;
    vtkErrorMacro("Cannot read '" << (this->FileName ? this->FileName : "") << "': " << message);
    int empty[6] = { 0, -1, 0, -1, 0, -1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1;
  };
  if (!this->FileName || !*this->FileName)
  {
    return fail("no file name set");
  }
  InitialiseOpenVDB();
  std::string chosen;
  try
  {
    // Every grid's descriptor, metadata and transform, checked against the file (a truncated
    // or corrupt file fails here or when the grid is read, never with a partial volume).
    avs::OpenVDBCheckedArchive archive(this->FileName);
    const auto& entries = archive.GetEntries();
    // Listed by name, as OpenVDB's io::File lists them.
    std::vector<std::size_t> order(entries.size());
    for (std::size_t i = 0; i < order.size(); ++i)
    {
      order[i] = i;
    }
    std::stable_sort(order.begin(),
      order.end(),
      [&](std::size_t a, std::size_t b)
      { return entries[a].Descriptor.gridName() < entries[b].Descriptor.gridName(); });
    for (std::size_t i : order)
    {
      const openvdb::GridBase& grid = *entries[i].Grid;
      GridInfo info;
      info.Name = grid.getName();
      info.Class = ClassName(grid.getGridClass());
      info.ValueType = grid.valueType();
      info.Entry = i;
      const openvdb::Vec3d v = grid.voxelSize();
      for (int a = 0; a < 3; ++a)
      {
        info.VoxelSize[a] = v[a];
      }
      if (auto lo = grid.getMetadata<openvdb::Vec3IMetadata>("file_bbox_min"))
      {
        if (auto hi = grid.getMetadata<openvdb::Vec3IMetadata>("file_bbox_max"))
        {
          for (int a = 0; a < 3; ++a)
          {
            info.Box[2 * a] = lo->value()[a];
            info.Box[2 * a + 1] = hi->value()[a];
          }
        }
      }
      in.Grids.push_back(info);
    }
    if (in.Grids.empty())
    {
      return fail("the file holds no grids");
    }
    const GridInfo* selected = nullptr;
    if (this->GridName && *this->GridName)
    {
      chosen = this->GridName;
      for (const auto& g : in.Grids)
      {
        if (!selected && (g.Name == chosen || entries[g.Entry].Descriptor.uniqueName() == chosen))
        {
          selected = &g;
        }
      }
      if (!selected)
      {
        std::ostringstream os;
        os << "no grid named '" << chosen << "' (the file has:";
        for (const auto& g : in.Grids)
        {
          os << " '" << g.Name << "'";
        }
        os << ")";
        return fail(os.str());
      }
    }
    else
    {
      auto density = std::find_if(
        in.Grids.begin(), in.Grids.end(), [](const GridInfo& g) { return g.Name == "density"; });
      auto scalar = std::find_if(in.Grids.begin(),
        in.Grids.end(),
        [](const GridInfo& g) { return IsScalarType(g.ValueType); });
      selected = density != in.Grids.end()
        ? &*density
        : (scalar != in.Grids.end() ? &*scalar : &in.Grids.front());
      chosen = selected->Name;
    }
    in.Grid = archive.ReadGrid(selected->Entry);
  }
  catch (const std::exception& e)
  {
    in.Grids.clear();
    in.Grid.reset();
    return fail(e.what());
  }
  catch (...)
  {
    in.Grids.clear();
    in.Grid.reset();
    return fail("not a readable OpenVDB file");
  }
  const std::string type = in.Grid->valueType();
  if (!IsScalarType(type) && !IsVectorType(type))
  {
    in.Grid.reset();
    return fail("unsupported value type '" + type + "' of grid '" + chosen + "'");
  }
  const openvdb::math::Transform& transform = in.Grid->transform();
  if (!transform.isLinear())
  {
    in.Grid.reset();
    return fail("grid '" + chosen +
      "' has a non-linear (e.g. frustum) transform, which image "
      "data cannot represent");
  }

  // The box: the grid's active voxels (leaves and tiles) or the user's box.
  avs::OpenVDBLayout L;
  if (this->UseBoundingBox)
  {
    const int* b = this->BoundingBox;
    if (b[1] < b[0] || b[3] < b[2] || b[5] < b[4])
    {
      in.Grid.reset();
      return fail("the bounding box is empty");
    }
    L.Box = openvdb::CoordBBox(openvdb::Coord(b[0], b[2], b[4]), openvdb::Coord(b[1], b[3], b[5]));
  }
  else
  {
    L.Box = in.Grid->evalActiveVoxelBoundingBox();
    if (L.Box.empty())
    {
      in.Grid.reset();
      return fail("grid '" + chosen + "' has no active voxels");
    }
  }
  // 64-bit: a box may span the whole 32-bit index range.
  const std::int64_t extent[3] = { static_cast<std::int64_t>(L.Box.max().x()) - L.Box.min().x() + 1,
    static_cast<std::int64_t>(L.Box.max().y()) - L.Box.min().y() + 1,
    static_cast<std::int64_t>(L.Box.max().z()) - L.Box.min().z() + 1 };
  const double voxels = static_cast<double>(extent[0]) * extent[1] * extent[2];
  const double maximum = static_cast<double>(this->MaximumNumberOfVoxels);
  // The output of factor f has ceil(extent / f) voxels per axis: their product (not the box's
  // volume over f^3, which it exceeds at the edges; found by the VDB fuzzer) must fit.
  auto tooMany = [&](std::int64_t f)
  {
    double n = 1.0;
    for (const std::int64_t e : extent)
    {
      n *= static_cast<double>((e + f - 1) / f);
    }
    return n > maximum;
  };
  const std::int64_t largest = std::max(MaximumAutomaticDownsampling, this->DownsamplingFactor);
  std::int64_t factor = this->DownsamplingFactor;
  if (tooMany(factor))
  {
    factor = std::max<std::int64_t>(factor, static_cast<std::int64_t>(std::cbrt(voxels / maximum)));
    while (factor <= largest && tooMany(factor))
    {
      ++factor;
    }
  }
  // Averaging reads every voxel of the box: more than 16^3 voxels per output voxel is refused
  // unless DownsamplingFactor asks for it.
  if (factor > largest)
  {
    std::ostringstream os;
    os << "grid '" << chosen << "' spans " << extent[0] << " x " << extent[1] << " x " << extent[2]
       << " voxels (" << (this->UseBoundingBox ? "the bounding box" : "its active voxels")
       << "): that needs blocks of " << factor << "^3 voxels averaged, more than "
       << MaximumAutomaticDownsampling << "^3; set a BoundingBox, a larger MaximumNumberOfVoxels "
       << "or DownsamplingFactor";
    in.Grid.reset();
    return fail(os.str());
  }
  L.Factor = static_cast<int>(factor);
  if (L.Factor > this->DownsamplingFactor)
  {
    vtkWarningMacro("Grid '" << chosen << "' has " << extent[0] << " x " << extent[1] << " x "
                             << extent[2] << " voxels, more than MaximumNumberOfVoxels ("
                             << this->MaximumNumberOfVoxels << "): averaging blocks of " << L.Factor
                             << "^3 voxels.");
  }
  for (int a = 0; a < 3; ++a)
  {
    const std::int64_t n = (extent[a] + L.Factor - 1) / L.Factor;
    if (n > std::numeric_limits<int>::max() / 2)
    {
      in.Grid.reset();
      return fail("grid '" + chosen + "' is too long along an axis for image data");
    }
    L.Dimensions[a] = static_cast<int>(n);
  }

  // Index -> world: columns of the linear map give spacing and direction.
  const openvdb::Vec3d o =
    transform.indexToWorld(openvdb::Vec3d(L.Box.min().x(), L.Box.min().y(), L.Box.min().z()));
  double axes[3][3];
  for (int a = 0; a < 3; ++a)
  {
    openvdb::Vec3d step(0.0);
    step[a] = 1.0;
    const openvdb::Vec3d p = transform.indexToWorld(
      openvdb::Vec3d(L.Box.min().x(), L.Box.min().y(), L.Box.min().z()) + step);
    const openvdb::Vec3d d = p - o;
    const double length = d.length();
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(o[a]))
    {
      in.Grid.reset();
      return fail("grid '" + chosen + "' has a degenerate transform");
    }
    L.Spacing[a] = length * L.Factor;
    for (int r = 0; r < 3; ++r)
    {
      axes[a][r] = d[r] / length;
    }
  }
  // Sheared (general affine) maps keep their axes in the direction matrix, which is then not
  // orthonormal; VTK's image data carries that, though volume mappers may refuse it.
  bool sheared = false;
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a + 1; b < 3; ++b)
    {
      const double dot =
        axes[a][0] * axes[b][0] + axes[a][1] * axes[b][1] + axes[a][2] * axes[b][2];
      sheared = sheared || std::abs(dot) > 1e-6;
    }
  }
  if (sheared)
  {
    vtkWarningMacro("Grid '" << chosen
                             << "' has a sheared transform: the image's direction "
                                "matrix is not orthonormal, which volume mappers "
                                "(these and VTK's) may refuse.");
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      L.Direction[3 * r + c] = axes[c][r];
    }
    // A block's value sits at the block's centre.
    double shift = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      shift += axes[c][r] * (L.Spacing[c] / L.Factor) * 0.5 * (L.Factor - 1);
    }
    L.Origin[r] = o[r] + shift;
  }
  in.Out = L;
  in.GridKey = chosen;

  int whole[6] = { 0, L.Dimensions[0] - 1, 0, L.Dimensions[1] - 1, 0, L.Dimensions[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole, 6);
  outInfo->Set(vtkDataObject::SPACING(), L.Spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), L.Origin, 3);
  outInfo->Set(vtkDataObject::DIRECTION(), L.Direction, 9);
  return 1;
}

int vtkOpenVDBImageReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  auto& in = *this->Internal;
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!in.Grid && in.Error.empty())
  {
    // Executed again without RequestInformation (a new update request): the grid was released
    // after the last copy, so it is read again.
    this->RequestInformation(nullptr, nullptr, outputVector);
  }
  if (!in.Grid)
  {
    return 1; // RequestInformation reported why
  }
  const avs::OpenVDBLayout& L = in.Out;
  const auto progress = [this](double v) { this->UpdateProgress(v); };
  output->SetExtent(0, L.Dimensions[0] - 1, 0, L.Dimensions[1] - 1, 0, L.Dimensions[2] - 1);
  output->SetSpacing(L.Spacing);
  output->SetOrigin(L.Origin);
  output->SetDirectionMatrix(L.Direction);
  const vtkIdType n = static_cast<vtkIdType>(L.Dimensions[0]) * L.Dimensions[1] * L.Dimensions[2];
  const std::string type = in.Grid->valueType();
  const bool averaged = L.Factor > 1;
  this->UpdateProgress(0.0);
  bool finite = true;
  try
  {
    vtkSmartPointer<vtkDataArray> array;
    auto scalar = [](auto v, double* out) { out[0] = static_cast<double>(v); };
    if (type == "float" || type == "half")
    {
      auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(in.Grid);
      if (this->LevelSetToFogVolume && grid->getGridClass() == openvdb::GRID_LEVEL_SET)
      {
        grid = grid->deepCopy();
        openvdb::tools::sdfToFogVolume(*grid);
      }
      auto a = vtkSmartPointer<vtkFloatArray>::New();
      a->SetNumberOfTuples(n);
      finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, progress);
      array = a;
    }
    else if (type == "double")
    {
      auto grid = openvdb::gridPtrCast<openvdb::DoubleGrid>(in.Grid);
      if (this->LevelSetToFogVolume && grid->getGridClass() == openvdb::GRID_LEVEL_SET)
      {
        grid = grid->deepCopy();
        openvdb::tools::sdfToFogVolume(*grid);
      }
      auto a = vtkSmartPointer<vtkDoubleArray>::New();
      a->SetNumberOfTuples(n);
      finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, progress);
      array = a;
    }
    else if (type == "int32")
    {
      auto grid = openvdb::gridPtrCast<openvdb::Int32Grid>(in.Grid);
      if (averaged)
      {
        auto a = vtkSmartPointer<vtkFloatArray>::New();
        a->SetNumberOfTuples(n);
        finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, progress);
        array = a;
      }
      else
      {
        auto a = vtkSmartPointer<vtkIntArray>::New();
        a->SetNumberOfTuples(n);
        finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, progress);
        array = a;
      }
    }
    else if (type == "bool")
    {
      auto grid = openvdb::gridPtrCast<openvdb::BoolGrid>(in.Grid);
      auto boolean = [](bool v, double* out) { out[0] = v ? 1.0 : 0.0; };
      if (averaged)
      {
        auto a = vtkSmartPointer<vtkFloatArray>::New();
        a->SetNumberOfTuples(n);
        finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, boolean, progress);
        array = a;
      }
      else
      {
        auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
        a->SetNumberOfTuples(n);
        finite = avs::CopyGrid(*grid, L, a->GetPointer(0), 1, boolean, progress);
        array = a;
      }
    }
    else // vec3s, vec3d
    {
      const int components = this->VectorMode == VECTOR_COMPONENTS ? 3 : 1;
      auto vector = [components](const auto& v, double* out)
      {
        if (components == 3)
        {
          out[0] = v[0];
          out[1] = v[1];
          out[2] = v[2];
        }
        else
        {
          out[0] = std::sqrt(static_cast<double>(v[0]) * v[0] + static_cast<double>(v[1]) * v[1] +
            static_cast<double>(v[2]) * v[2]);
        }
      };
      auto a = vtkSmartPointer<vtkFloatArray>::New();
      a->SetNumberOfComponents(components);
      a->SetNumberOfTuples(n);
      if (type == "vec3s")
      {
        finite = avs::CopyGrid(*openvdb::gridPtrCast<openvdb::Vec3SGrid>(in.Grid),
          L,
          a->GetPointer(0),
          components,
          vector,
          progress);
      }
      else
      {
        finite = avs::CopyGrid(*openvdb::gridPtrCast<openvdb::Vec3DGrid>(in.Grid),
          L,
          a->GetPointer(0),
          components,
          vector,
          progress);
      }
      array = a;
    }
    array->SetName(in.GridKey.c_str());
    if (finite)
    {
      output->GetPointData()->SetScalars(array);
    }
    else
    {
      output->Initialize();
      vtkErrorMacro("Cannot read '" << this->FileName << "': grid '" << in.GridKey
                                    << "' holds NaN or infinite values (a corrupt leaf buffer?)");
    }
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro(
      "Cannot read '" << this->FileName << "': grid '" << in.GridKey << "': " << e.what());
  }
  catch (...)
  {
    output->Initialize();
    vtkErrorMacro("Cannot read '" << this->FileName << "': grid '" << in.GridKey << "'.");
  }
  // The sparse grid goes once it is copied: the output holds the voxels, and a grid kept until
  // the reader's destruction can outlive OpenVDB's TBB allocator where the reader is destroyed
  // at process exit (ParaView's pvbatch destroys its proxies after the static destructors ran).
  in.Grid.reset();
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOpenVDBImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "GridName: " << (this->GridName ? this->GridName : "(default)") << "\n";
  os << indent
     << "VectorMode: " << (this->VectorMode == VECTOR_COMPONENTS ? "Components" : "Magnitude")
     << "\n";
  os << indent << "LevelSetToFogVolume: " << (this->LevelSetToFogVolume ? "On" : "Off") << "\n";
  os << indent << "UseBoundingBox: " << (this->UseBoundingBox ? "On" : "Off") << "\n";
  os << indent << "BoundingBox: (" << this->BoundingBox[0] << ", " << this->BoundingBox[1] << ", "
     << this->BoundingBox[2] << ", " << this->BoundingBox[3] << ", " << this->BoundingBox[4] << ", "
     << this->BoundingBox[5] << ")\n";
  os << indent << "MaximumNumberOfVoxels: " << this->MaximumNumberOfVoxels << "\n";
  os << indent << "DownsamplingFactor: " << this->DownsamplingFactor << "\n";
  os << indent << "NumberOfGrids: " << this->Internal->Grids.size() << "\n";
  for (const auto& g : this->Internal->Grids)
  {
    os << indent.GetNextIndent() << g.Name << ": " << g.Class << ", " << g.ValueType << ", voxel "
       << g.VoxelSize[0] << " x " << g.VoxelSize[1] << " x " << g.VoxelSize[2] << ", box ["
       << g.Box[0] << ", " << g.Box[1] << "] x [" << g.Box[2] << ", " << g.Box[3] << "] x ["
       << g.Box[4] << ", " << g.Box[5] << "]\n";
  }
}
