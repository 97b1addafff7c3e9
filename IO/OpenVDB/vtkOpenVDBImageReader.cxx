#include "vtkOpenVDBImageReader.h"

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

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenVDBImageReader);

namespace
{
struct GridInfo
{
  std::string Name, Class, ValueType;
  double VoxelSize[3] = { 0, 0, 0 };
  int Box[6] = { 0, -1, 0, -1, 0, -1 };
};

/// Where the output sits and how it is sampled.
struct Layout
{
  openvdb::CoordBBox Box; ///< inclusive index box read from the grid
  int Factor = 1;         ///< downsampling factor
  int Dimensions[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
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
  openvdb::GridBase::Ptr Grid; ///< the selected grid, read in full
  std::string GridKey;         ///< file + grid + options it was read with
  Layout Out;
  std::string Error;
};

namespace
{
std::once_flag OpenVDBInitialised;
void InitialiseOpenVDB()
{
  std::call_once(OpenVDBInitialised, [] { openvdb::initialize(); });
}

// The copy of a typed grid's box into the output array, slab by slab, averaging f^3 blocks.
// `Out` is the VTK array's value type; `components` 1 or 3; `convert` maps a grid value to
// `components` output values.
template<typename GridT, typename Out, typename Convert>
void CopyGrid(const GridT& grid,
  const Layout& L,
  Out* out,
  int components,
  Convert convert,
  vtkOpenVDBImageReader* self)
{
  using ValueT = typename GridT::ValueType;
  const openvdb::Coord lo = L.Box.min();
  const openvdb::Coord hi = L.Box.max();
  const int f = L.Factor;
  const int nx = L.Dimensions[0], ny = L.Dimensions[1], nz = L.Dimensions[2];
  const int sx = hi.x() - lo.x() + 1, sy = hi.y() - lo.y() + 1;
  // A plain array: std::vector<bool> has no data().
  std::unique_ptr<ValueT[]> slab(new ValueT[static_cast<std::size_t>(sx) * sy * f]);
  std::vector<double> sum(static_cast<std::size_t>(nx) * ny * components);
  std::vector<int> count(static_cast<std::size_t>(nx) * ny);
  double values[3];
  for (int kz = 0; kz < nz; ++kz)
  {
    const int z0 = lo.z() + kz * f;
    const int z1 = std::min(hi.z(), z0 + f - 1);
    const openvdb::CoordBBox slabBox(
      openvdb::Coord(lo.x(), lo.y(), z0), openvdb::Coord(hi.x(), hi.y(), z1));
    openvdb::tools::Dense<ValueT, openvdb::tools::LayoutXYZ> dense(slabBox, slab.get());
    openvdb::tools::copyToDense(grid, dense); // multi-threaded
    const std::size_t planeOut = static_cast<std::size_t>(nx) * ny;
    if (f == 1)
    {
      for (std::size_t p = 0; p < planeOut; ++p)
      {
        convert(slab[p], values);
        for (int c = 0; c < components; ++c)
        {
          out[(kz * planeOut + p) * components + c] = static_cast<Out>(values[c]);
        }
      }
    }
    else
    {
      std::fill(sum.begin(), sum.end(), 0.0);
      std::fill(count.begin(), count.end(), 0);
      const int depth = z1 - z0 + 1;
      for (int z = 0; z < depth; ++z)
        for (int y = 0; y < sy; ++y)
          for (int x = 0; x < sx; ++x)
          {
            convert(slab[(static_cast<std::size_t>(z) * sy + y) * sx + x], values);
            const std::size_t o = static_cast<std::size_t>(y / f) * nx + x / f;
            for (int c = 0; c < components; ++c)
            {
              sum[o * components + c] += values[c];
            }
            ++count[o];
          }
      for (std::size_t p = 0; p < planeOut; ++p)
      {
        for (int c = 0; c < components; ++c)
        {
          out[(kz * planeOut + p) * components + c] =
            static_cast<Out>(count[p] ? sum[p * components + c] / count[p] : 0.0);
        }
      }
    }
    self->UpdateProgress(static_cast<double>(kz + 1) / nz);
  }
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
    openvdb::io::File file(fileName);
    file.open(false);
    const bool any = file.beginName() != file.endName();
    file.close();
    return any;
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
    openvdb::io::File file(this->FileName);
    file.open(false);
    openvdb::GridPtrVecPtr metas = file.readAllGridMetadata();
    for (const auto& grid : *metas)
    {
      GridInfo info;
      info.Name = grid->getName();
      info.Class = ClassName(grid->getGridClass());
      info.ValueType = grid->valueType();
      if (grid->saveFloatAsHalf() && info.ValueType == "float")
      {
        info.ValueType = "float"; // stored as half, read as float
      }
      const openvdb::Vec3d v = grid->voxelSize();
      for (int a = 0; a < 3; ++a)
      {
        info.VoxelSize[a] = v[a];
      }
      if (auto lo = grid->getMetadata<openvdb::Vec3IMetadata>("file_bbox_min"))
      {
        if (auto hi = grid->getMetadata<openvdb::Vec3IMetadata>("file_bbox_max"))
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
      file.close();
      return fail("the file holds no grids");
    }
    if (this->GridName && *this->GridName)
    {
      chosen = this->GridName;
      if (std::none_of(
            in.Grids.begin(), in.Grids.end(), [&](const GridInfo& g) { return g.Name == chosen; }))
      {
        std::ostringstream os;
        os << "no grid named '" << chosen << "' (the file has:";
        for (const auto& g : in.Grids)
        {
          os << " '" << g.Name << "'";
        }
        os << ")";
        file.close();
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
      chosen = density != in.Grids.end()
        ? density->Name
        : (scalar != in.Grids.end() ? scalar->Name : in.Grids.front().Name);
    }
    in.Grid = file.readGrid(chosen);
    file.close();
  }
  catch (const std::exception& e)
  {
    return fail(std::string("not a readable OpenVDB file (") + e.what() + ")");
  }
  catch (...)
  {
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
  Layout L;
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
  const openvdb::Coord extent = L.Box.dim();
  const double voxels = static_cast<double>(extent.x()) * extent.y() * extent.z();
  L.Factor = this->DownsamplingFactor;
  while (voxels / std::pow(static_cast<double>(L.Factor), 3) >
    static_cast<double>(this->MaximumNumberOfVoxels))
  {
    ++L.Factor;
  }
  if (L.Factor > this->DownsamplingFactor)
  {
    vtkWarningMacro("Grid '" << chosen << "' has " << extent.x() << " x " << extent.y() << " x "
                             << extent.z() << " voxels, more than MaximumNumberOfVoxels ("
                             << this->MaximumNumberOfVoxels << "): averaging blocks of " << L.Factor
                             << "^3 voxels.");
  }
  for (int a = 0; a < 3; ++a)
  {
    L.Dimensions[a] = (extent[a] + L.Factor - 1) / L.Factor;
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
    if (!(length > 0.0) || !std::isfinite(length))
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
  if (!in.Grid)
  {
    return 1; // RequestInformation reported why
  }
  const Layout& L = in.Out;
  output->SetExtent(0, L.Dimensions[0] - 1, 0, L.Dimensions[1] - 1, 0, L.Dimensions[2] - 1);
  output->SetSpacing(L.Spacing);
  output->SetOrigin(L.Origin);
  output->SetDirectionMatrix(L.Direction);
  const vtkIdType n = static_cast<vtkIdType>(L.Dimensions[0]) * L.Dimensions[1] * L.Dimensions[2];
  const std::string type = in.Grid->valueType();
  const bool averaged = L.Factor > 1;
  this->UpdateProgress(0.0);
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
      CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, this);
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
      CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, this);
      array = a;
    }
    else if (type == "int32")
    {
      auto grid = openvdb::gridPtrCast<openvdb::Int32Grid>(in.Grid);
      if (averaged)
      {
        auto a = vtkSmartPointer<vtkFloatArray>::New();
        a->SetNumberOfTuples(n);
        CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, this);
        array = a;
      }
      else
      {
        auto a = vtkSmartPointer<vtkIntArray>::New();
        a->SetNumberOfTuples(n);
        CopyGrid(*grid, L, a->GetPointer(0), 1, scalar, this);
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
        CopyGrid(*grid, L, a->GetPointer(0), 1, boolean, this);
        array = a;
      }
      else
      {
        auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
        a->SetNumberOfTuples(n);
        CopyGrid(*grid, L, a->GetPointer(0), 1, boolean, this);
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
        CopyGrid(*openvdb::gridPtrCast<openvdb::Vec3SGrid>(in.Grid),
          L,
          a->GetPointer(0),
          components,
          vector,
          this);
      }
      else
      {
        CopyGrid(*openvdb::gridPtrCast<openvdb::Vec3DGrid>(in.Grid),
          L,
          a->GetPointer(0),
          components,
          vector,
          this);
      }
      array = a;
    }
    array->SetName(in.GridKey.c_str());
    output->GetPointData()->SetScalars(array);
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro("Cannot read grid '" << in.GridKey << "': " << e.what());
  }
  catch (...)
  {
    output->Initialize();
    vtkErrorMacro("Cannot read grid '" << in.GridKey << "'.");
  }
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
