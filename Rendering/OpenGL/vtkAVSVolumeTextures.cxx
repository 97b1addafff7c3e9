#include "vtkAVSVolumeTextures.h"

#include "Classifier.h"
#include "SurfaceGrid.h"

#include "vtkAVSBricks.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSTextureMemory.h"
#include "vtkAVSTextureUpload.h"

#include "vtkAVSOpenGL.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

void vtkAVSVolumeTextures::SetWindow(vtkOpenGLRenderWindow* window)
{
  this->Window = window;
  this->Classification.SetWindow(window);
}

void vtkAVSVolumeTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Classification.ReleaseGraphicsResources(window);
  this->Surfaces.ReleaseGraphicsResources(window);
  this->SurfacesKey.clear();
  for (vtkTextureObject* t : { this->Scalars.Get(),
         this->AveragedExtinction.Get(),
         this->Occlusion.Get(),
         this->Occupancy.Get(),
         this->Table.Get(),
         this->LightVolumes[0].Get(),
         this->LightVolumes[1].Get(),
         this->Scratch[0].Get(),
         this->Scratch[1].Get() })
  {
    if (t && window)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->AveragedSlot = -1;
  this->PhiSlot = -1;
  this->ReleaseBricks(window);
  this->Bricks.Clear();
  this->Scalars = this->AveragedExtinction = this->Occlusion = this->Table = nullptr;
  this->Occupancy = nullptr;
  for (auto& t : this->LightVolumes)
  {
    t = nullptr;
  }
  for (auto& t : this->Scratch)
  {
    t = nullptr;
  }
  this->LightTextureDimensions = { 0, 0, 0 };
  this->PeakBytes = 0.0;
  this->SoftwareRenderer = -1; // asked again in the next context
  if (window == this->Window)
  {
    this->Window = nullptr;
  }
}

unsigned int vtkAVSVolumeTextures::LightVolumeFormat() const
{
  // Transmittances in [0, 1] keep 11 significant bits as half floats, and a 64-bit texel filters
  // at twice the rate of a 128-bit one on GPUs (measured on an H100: ambient scattering with 4
  // lights 1.96 instead of 2.53 EA frames). A software rasterizer converts each half-float texel
  // instead, so there 32-bit floats are faster.
  return this->IsSoftwareRenderer() ? GL_RGBA32F : GL_RGBA16F;
}

bool vtkAVSVolumeTextures::IsSoftwareRenderer() const
{
  if (this->SoftwareRenderer < 0)
  {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    this->SoftwareRenderer = name.find("llvmpipe") != std::string::npos ||
        name.find("softpipe") != std::string::npos || name.find("SwiftShader") != std::string::npos
      ? 1
      : 0;
  }
  return this->SoftwareRenderer == 1;
}

int vtkAVSVolumeTextures::MaximumTextureSize3D() const
{
  if (!this->Window)
  {
    return 0;
  }
  GLint size = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &size);
  // A smaller limit from the environment, so that a test on a small volume can take the
  // automatic split that a volume beyond the GPU's limit takes.
  const char* cap = std::getenv("AVS_MAXIMUM_3D_TEXTURE_SIZE");
  const int capped = cap ? std::atoi(cap) : 0;
  return capped > 0 ? std::min(static_cast<int>(size), capped) : static_cast<int>(size);
}

void vtkAVSVolumeTextures::ConfigureSampling(vtkTextureObject* t)
{
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetWrapR(vtkTextureObject::ClampToEdge);
  t->SetMinificationFilter(vtkTextureObject::Linear);
  t->SetMagnificationFilter(vtkTextureObject::Linear);
}

void vtkAVSVolumeTextures::SetVolumeFilter(vtkTextureObject* texture, bool nearest)
{
  if (texture)
  {
    const int filter = nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
    texture->SetMinificationFilter(filter);
    texture->SetMagnificationFilter(filter);
  }
}

bool vtkAVSVolumeTextures::UploadGrid(vtkSmartPointer<vtkTextureObject>& texture,
  const std::array<int, 3>& d,
  int components,
  const float* data,
  std::string& error,
  unsigned int internalFormat)
{
  if (!vtkAVSTextureUpload::UploadFloats(
        this->Window, texture, d, components, data, internalFormat, this->BudgetTextures(), error))
  {
    return false;
  }
  this->NotePeak();
  return true;
}

double vtkAVSVolumeTextures::HeldBytes() const
{
  double bytes = 0.0;
  for (vtkTextureObject* t : this->VolumeTextures())
  {
    bytes += vtkAVSTextureMemory::Bytes(t);
  }
  return bytes;
}

void vtkAVSVolumeTextures::NoteTemporary(vtkTextureObject* texture)
{
  this->PeakBytes =
    std::max(this->PeakBytes, this->HeldBytes() + vtkAVSTextureMemory::Bytes(texture));
}

void vtkAVSVolumeTextures::NotePeak()
{
  this->PeakBytes = std::max(this->PeakBytes, this->HeldBytes());
}

void vtkAVSVolumeTextures::ReleaseScratch()
{
  for (auto& t : this->Scratch)
  {
    if (t)
    {
      t->ReleaseGraphicsResources(this->Window);
    }
    t = nullptr;
  }
}

namespace
{
// Writes the slices [z0, z1) of the sub-box of `dimensions` voxels from `origin` (the whole
// volume, or a brick: vtkAVSBricks) of the scene's channels (the components, then the validity
// where the layout puts it beside them) into `texels` as T, x fastest, each value v stored as
// round(format.Encode(v)) for normalized texels and as v for floats. The values are the scene's
// grids, or, where a grid holds none (not converted on the host), what `source` reads, one row
// at a time.
template<typename T>
void PackBox(const avs::VolumeScene& scene,
  const vtkAVSVolumeTextures::ScalarSource& source,
  const vtkAVSClassification::Layout& layout,
  const vtkAVSTextureUpload::TexelFormat& format,
  const std::array<int, 3>& origin,
  const std::array<int, 3>& dimensions,
  int z0,
  int z1,
  T* texels)
{
  const std::array<int, 3>& d = scene.Scalars.Geometry.Dimensions;
  const int channels = layout.ScalarChannels();
  const bool normalized = format.IsNormalized();
  const double top = static_cast<double>(format.Scale);
  std::vector<float> read;
  for (int c = 0; c < channels; ++c)
  {
    const std::vector<float>& grid = c == layout.Components ? scene.Medium.Validity.Values
      : c == 0                                              ? scene.Scalars.Values
               : scene.Medium.Components[c - 1].Values.Values;
    T* out = texels + c;
    for (int z = z0; z < z1; ++z)
    {
      for (int y = 0; y < dimensions[1]; ++y)
      {
        const std::size_t row = (static_cast<std::size_t>(origin[2] + z) * d[1] + origin[1] + y) *
            static_cast<std::size_t>(d[0]) +
          origin[0];
        // The grid's row, or the row read from the source where the grid holds no values.
        const float* v = grid.empty() ? nullptr : grid.data() + row;
        if (!v)
        {
          read.resize(static_cast<std::size_t>(dimensions[0]));
          source.Read(c, row, row + dimensions[0], read.data());
          v = read.data();
        }
        for (int x = 0; x < dimensions[0]; ++x, out += channels)
        {
          *out = normalized ? static_cast<T>(std::lround(std::clamp(format.Encode(v[x]), 0.0, top)))
                            : static_cast<T>(v[x]);
        }
      }
    }
  }
}

// PackBox into `texels` of the format's host type.
// The slices of [0, depth) in `slices`.
int WrittenSlices(const std::array<int, 2>& slices, int depth)
{
  return std::max(0, std::min(slices[1], depth) - std::max(slices[0], 0));
}

void PackBoxAs(const avs::VolumeScene& scene,
  const vtkAVSVolumeTextures::ScalarSource& source,
  const vtkAVSClassification::Layout& layout,
  const vtkAVSTextureUpload::TexelFormat& format,
  const std::array<int, 3>& origin,
  const std::array<int, 3>& dimensions,
  int z0,
  int z1,
  void* texels)
{
  if (format.HostType == VTK_UNSIGNED_CHAR)
  {
    PackBox(scene,
      source,
      layout,
      format,
      origin,
      dimensions,
      z0,
      z1,
      static_cast<unsigned char*>(texels));
  }
  else if (format.HostType == VTK_UNSIGNED_SHORT)
  {
    PackBox(scene,
      source,
      layout,
      format,
      origin,
      dimensions,
      z0,
      z1,
      static_cast<unsigned short*>(texels));
  }
  else
  {
    PackBox(scene, source, layout, format, origin, dimensions, z0, z1, static_cast<float*>(texels));
  }
}
} // namespace

bool vtkAVSVolumeTextures::UploadScalars(const avs::VolumeScene& scene,
  int scalarType,
  const ScalarSource& source,
  const std::array<int, 3>& partitions,
  const std::array<int, 3>& lookBack,
  std::string& error)
{
  const vtkAVSClassification::Layout layout = vtkAVSClassification::LayoutOf(scene);
  const int channels = layout.ScalarChannels();
  // NaN voxels: the validity goes with the components (or the components are multiplied by
  // it), so those volumes stay floats whatever their type.
  const vtkAVSTextureUpload::TexelFormat format =
    vtkAVSTextureUpload::TexelFormat::ForScalars(scalarType, channels, layout.Validity != 0);
  const std::array<int, 3>& dimensions = scene.Scalars.Geometry.Dimensions;
  // Bricks (vtkAVSBricks): per axis the partitions asked for, or more where the context's
  // 3D-texture limit needs more ((1, 1, 1): only those); one more voxel layer around the shared
  // one when a gradient opacity reads the neighbours, and those ambient scattering's look-back
  // reads before a brick's first sample (avs_as_effect.glsl).
  if (scene.Scalars.Values.empty() && !source.Read)
  {
    error = "the scalars are neither on the host nor readable";
    return false;
  }
  // The components' value range per cell, for empty-space skipping (UploadOccupancy): cells of
  // the default size, or larger where the cells along an axis would exceed the 3D-texture limit
  // (a volume that long is split into bricks; its grid stays whole).
  int cellSize = avs::ValueRangeGrid::DefaultCellSize;
  const int largest = std::max(1, this->MaximumTextureSize3D());
  for (int a = 0; a < 3; ++a)
  {
    cellSize = std::max(cellSize, (dimensions[a] + largest - 1) / largest);
  }
  this->ValueRanges = avs::ValueRangeGrid(
    dimensions,
    layout.Components,
    cellSize,
    [&scene, &source](int c, std::size_t begin, std::size_t end, float* out)
    {
      const std::vector<float>& grid =
        c == 0 ? scene.Scalars.Values : scene.Medium.Components[c - 1].Values.Values;
      if (grid.empty())
      {
        source.Read(c, begin, end, out);
      }
      else
      {
        std::copy(grid.begin() + begin, grid.begin() + end, out);
      }
    },
    scene.Medium.Validity.Values);
  ++this->ValueRangesVersion;
  std::array<int, 3> ghost;
  for (int a = 0; a < 3; ++a)
  {
    ghost[a] = (layout.Gradient != 0 ? 1 : 0) + std::max(0, lookBack[a]);
  }
  std::array<int, 3> split;
  if (!vtkAVSBricks::PartitionsFor(dimensions, this->MaximumTextureSize3D(), ghost, split, error))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    split[a] = std::max(split[a], partitions[a]);
  }
  vtkAVSBricks bricks;
  bricks.Split(dimensions, split, scene.Scalars.Geometry.Border, ghost);
  // The last upload's textures are re-filled where the data changed (source.ChangedSlices)
  // when their texels mean the same: the same layout and format, and the same bricks.
  const bool sameTexels = layout == this->ScalarLayout &&
    format.InternalFormat == this->ScalarFormat.InternalFormat &&
    format.HostType == this->ScalarFormat.HostType && format.Scale == this->ScalarFormat.Scale &&
    format.Shift == this->ScalarFormat.Shift;
  const bool sameBricks = sameTexels && bricks.SameSplit(this->Bricks) &&
    std::all_of(this->BrickTextures.begin(),
      this->BrickTextures.end(),
      [](const vtkSmartPointer<vtkTextureObject>& t) { return t != nullptr; });
  const std::array<int, 2> changed =
    sameTexels ? source.ChangedSlices : vtkAVSTextureUpload::AllSlices;
  this->UploadedVoxels = 0.0;
  if (!sameBricks)
  {
    this->ReleaseBricks(this->Window);
  }
  this->Bricks = bricks;
  if (this->Bricks.IsSplit())
  {
    if (!this->UploadBricks(scene,
          source,
          layout,
          format,
          sameBricks ? changed : vtkAVSTextureUpload::AllSlices,
          error))
    {
      this->ReleaseBricks(this->Window);
      return false;
    }
    this->ScalarLayout = layout;
    this->ScalarFormat = format;
    this->Classification.SetValueMap(format.Scale, format.Shift);
    return this->UploadOccupancy(scene, error);
  }
  const std::size_t slice = static_cast<std::size_t>(scene.Scalars.Geometry.Dimensions[0]) *
    scene.Scalars.Geometry.Dimensions[1];
  const std::size_t texel = static_cast<std::size_t>(channels) * format.HostBytes();
  const bool onHost = !scene.Scalars.Values.empty();
  const vtkAVSTextureUpload::SlabFill fill =
    [&scene, &source, &layout, &format, channels, slice, texel, onHost](
      int z0, int z1, void* texels) -> const void*
  {
    if (!onHost && source.Texels)
    {
      return static_cast<const char*>(source.Texels) + texel * slice * z0; // the array itself
    }
    if (onHost && !format.IsNormalized() && channels == 1)
    {
      return scene.Scalars.Values.data() + slice * z0; // the grid itself
    }
    PackBoxAs(scene,
      source,
      layout,
      format,
      { 0, 0, 0 },
      scene.Scalars.Geometry.Dimensions,
      z0,
      z1,
      texels);
    return texels;
  };
  const vtkTextureObject* before = this->Scalars;
  if (!vtkAVSTextureUpload::Upload(this->Window,
        this->Scalars,
        scene.Scalars.Geometry.Dimensions,
        channels,
        format,
        fill,
        this->BudgetTextures(),
        error,
        changed))
  {
    return false;
  }
  const bool kept = before && before == this->Scalars.Get(); // (else allocated and all written)
  this->UploadedVoxels = static_cast<double>(slice) *
    WrittenSlices(kept ? changed : vtkAVSTextureUpload::AllSlices, dimensions[2]);
  this->NotePeak();
  this->ScalarLayout = layout;
  this->ScalarFormat = format;
  this->Classification.SetValueMap(format.Scale, format.Shift);
  return this->UploadOccupancy(scene, error);
}

void vtkAVSVolumeTextures::ReleaseBricks(vtkWindow* window)
{
  for (auto& t : this->BrickTextures)
  {
    if (t && window)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->BrickTextures.clear();
}

bool vtkAVSVolumeTextures::UploadBricks(const avs::VolumeScene& scene,
  const ScalarSource& source,
  const vtkAVSClassification::Layout& layout,
  const vtkAVSTextureUpload::TexelFormat& format,
  const std::array<int, 2>& changed,
  std::string& error)
{
  // The unsplit texture goes first, so that the budget counts the bricks alone.
  if (this->Scalars)
  {
    this->Scalars->ReleaseGraphicsResources(this->Window);
    this->Scalars = nullptr;
  }
  const int channels = layout.ScalarChannels();
  const std::vector<vtkAVSBricks::Brick>& bricks = this->Bricks.GetBricks();
  this->BrickTextures.resize(bricks.size());
  for (std::size_t b = 0; b < bricks.size(); ++b)
  {
    const vtkAVSBricks::Brick& brick = bricks[b];
    // A kept brick's slices that changed, in its texture's frame (none: left alone).
    const bool kept = this->BrickTextures[b] != nullptr;
    const std::array<int, 2> slices = kept
      ? std::array<int, 2>{ std::max(0, changed[0] - brick.Origin[2]),
          std::min(brick.Dimensions[2], changed[1] - brick.Origin[2]) }
      : vtkAVSTextureUpload::AllSlices;
    if (slices[0] >= slices[1])
    {
      continue;
    }
    const vtkTextureObject* before = this->BrickTextures[b];
    const vtkAVSTextureUpload::SlabFill fill = [&scene, &source, &layout, &format, &brick](
                                                 int z0, int z1, void* texels) -> const void*
    {
      PackBoxAs(scene, source, layout, format, brick.Origin, brick.Dimensions, z0, z1, texels);
      return texels;
    };
    if (!vtkAVSTextureUpload::Upload(this->Window,
          this->BrickTextures[b],
          brick.Dimensions,
          channels,
          format,
          fill,
          this->BudgetTextures(),
          error,
          slices))
    {
      error = "brick " + std::to_string(b + 1) + " of " + std::to_string(bricks.size()) + " (" +
        std::to_string(brick.Dimensions[0]) + " x " + std::to_string(brick.Dimensions[1]) + " x " +
        std::to_string(brick.Dimensions[2]) + " voxels): " + error;
      return false;
    }
    const bool refilled = before && before == this->BrickTextures[b].Get();
    this->UploadedVoxels += static_cast<double>(brick.Dimensions[0]) * brick.Dimensions[1] *
      WrittenSlices(refilled ? slices : vtkAVSTextureUpload::AllSlices, brick.Dimensions[2]);
    this->NotePeak();
  }
  return true;
}

bool vtkAVSVolumeTextures::UploadClassification(const avs::VolumeScene& scene, std::string& error)
{
  this->Classification.SetWindow(this->Window);
  std::vector<vtkTextureObject*> held = this->BudgetTextures();
  held.resize(held.size() - this->Classification.VolumeTextures().size()); // counted by it
  if (!this->Classification.Upload(scene, held, this->Bricks, error))
  {
    return false;
  }
  this->Classification.SetValueMap(this->ScalarFormat.Scale, this->ScalarFormat.Shift);
  this->NotePeak(); // the mask and validity textures count too
  return this->UploadOccupancy(scene, error);
}

bool vtkAVSVolumeTextures::UploadSurfaces(const avs::VolumeScene& scene,
  bool active,
  const ScalarSource& source,
  std::string& error)
{
  if (!active)
  {
    this->Surfaces.ReleaseGraphicsResources(this->Window);
    this->SurfacesKey.clear();
    this->SurfacesPacked = false;
    return true;
  }
  const avs::Classifier classifier(scene);
  const int c = classifier.ShadingComponentIndex();
  // On a software rasterizer, whose gradient texels are 16-bit anyway, the scalars beside the
  // gradient in 16 bits over their range, where they are one channel the classification reads
  // alone (vtkAVSSurfaceTexture::Upload): a fetch per pair of samples less, no more memory. (A
  // GPU keeps RGBA8, 4 bytes per voxel, and the fetch.)
  const vtkAVSClassification::Layout& layout = this->ScalarLayout;
  std::vector<std::uint16_t> packed;
  // (AVS_SURFACES_PACKED=0 in the environment turns it off, for the tests.)
  const char* packing = std::getenv("AVS_SURFACES_PACKED");
  const bool pack = this->IsSoftwareRenderer() && (!packing || std::atoi(packing) != 0) && c == 0 &&
    layout.ScalarAlone() && !this->Bricks.IsSplit();
  std::vector<double> key{ static_cast<double>(this->ValueRangesVersion),
    static_cast<double>(c),
    classifier.ShadingInverseRange(),
    static_cast<double>(this->Bricks.GetNumberOfBricks()),
    pack ? 1.0 : 0.0 };
  if (this->Surfaces.IsUploaded() && key == this->SurfacesKey)
  {
    return true; // made from the same scalars and range
  }
  avs::SurfaceGrid grid;
  const avs::GridGeometry& g = scene.Scalars.Geometry;
  if (!scene.Scalars.Values.empty() || !source.Read)
  {
    grid = avs::MakeSurfaceGrid(scene);
  }
  else
  {
    // Slice by slice from the array (the validity, where there is one, is on the host).
    const std::size_t slice = static_cast<std::size_t>(g.Dimensions[0]) * g.Dimensions[1];
    const std::vector<float>& validity = scene.Medium.Validity.Values;
    const avs::SurfaceSliceReader read = [&](int k, float* out)
    {
      const std::size_t first = slice * static_cast<std::size_t>(k);
      source.Read(c, first, first + slice, out);
      avs::DivideByValidity(validity, first, slice, out);
    };
    grid = avs::MakeSurfaceGrid(g.Dimensions, g.Spacing, classifier.ShadingInverseRange(), read);
  }
  if (grid.Empty())
  {
    this->Surfaces.ReleaseGraphicsResources(this->Window);
    this->SurfacesKey.clear();
    this->SurfacesPacked = false;
    error = "the surfaces' gradient has no scalars to be made from";
    return false;
  }
  if (pack)
  {
    packed = this->PackScalars(scene, source);
  }
  std::vector<vtkTextureObject*> held = this->BudgetTextures();
  const std::vector<vtkTextureObject*> own = this->Surfaces.VolumeTextures();
  held.erase(
    std::remove_if(held.begin(),
      held.end(),
      [&own](vtkTextureObject* t) { return std::find(own.begin(), own.end(), t) != own.end(); }),
    held.end());
  this->SurfacesPacked = !packed.empty();
  if (!this->Surfaces.Upload(this->Window,
        grid,
        this->Bricks,
        held,
        this->IsSoftwareRenderer(),
        packed.empty() ? nullptr : &packed,
        error))
  {
    this->SurfacesPacked = false;
    this->SurfacesKey.clear();
    return false;
  }
  this->SurfacesKey = std::move(key);
  this->NotePeak();
  return true;
}

std::vector<std::uint16_t> vtkAVSVolumeTextures::PackScalars(const avs::VolumeScene& scene,
  const ScalarSource& source)
{
  // The range from the value ranges UploadScalars took of the same scalars (cells whose points
  // are all NaN have Low > High).
  const avs::GridGeometry& g = scene.Scalars.Geometry;
  const avs::ValueRangeGrid& ranges = this->ValueRanges;
  if (ranges.Empty() || ranges.Dimensions() != g.Dimensions)
  {
    return {};
  }
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (std::size_t cell = 0; cell < ranges.NumberOfCells(); ++cell)
  {
    if (ranges.Low(cell, 0) <= ranges.High(cell, 0))
    {
      lo = std::min(lo, ranges.Low(cell, 0));
      hi = std::max(hi, ranges.High(cell, 0));
    }
  }
  if (!(lo <= hi))
  {
    lo = hi = 0.0f;
  }
  const double range = static_cast<double>(hi) - lo;
  const double scale = range > 0.0 ? 65535.0 / range : 0.0;
  // Slice by slice, from the scene's values or, where it holds none, through `source`.
  const std::size_t slice = static_cast<std::size_t>(g.Dimensions[0]) * g.Dimensions[1];
  const std::size_t count = slice * static_cast<std::size_t>(std::max(0, g.Dimensions[2]));
  const bool onHost = scene.Scalars.Values.size() == count;
  if (!onHost && !source.Read)
  {
    return {};
  }
  std::vector<float> read(onHost ? 0 : slice);
  std::vector<std::uint16_t> packed(count, 0);
  for (std::size_t first = 0; first < count; first += slice)
  {
    const float* values = scene.Scalars.Values.data() + first;
    if (!onHost)
    {
      source.Read(0, first, first + slice, read.data());
      values = read.data();
    }
    for (std::size_t i = 0; i < slice; ++i)
    {
      const double v = values[i];
      packed[first + i] = std::isfinite(v)
        ? static_cast<std::uint16_t>(std::clamp(std::floor((v - lo) * scale + 0.5), 0.0, 65535.0))
        : 0;
    }
  }
  this->SurfacesPackedScale = range;
  this->SurfacesPackedShift = lo;
  return packed;
}

bool vtkAVSVolumeTextures::UploadOccupancy(const avs::VolumeScene& scene, std::string& error)
{
  if (this->ValueRanges.Empty() ||
    this->ValueRanges.Dimensions() != scene.Scalars.Geometry.Dimensions)
  {
    return true; // no scalars yet: UploadScalars comes back here
  }
  std::vector<double> key = avs::ExtinctionKey(scene);
  if (this->Occupancy && this->OccupancyRangesVersion == this->ValueRangesVersion &&
    this->OccupancyKey == key)
  {
    return true; // built from the same ranges and opacity
  }
  this->MajorantValues = avs::Majorants(this->ValueRanges, avs::Classifier(scene));
  ++this->MajorantsVersion;
  std::vector<unsigned char> occupied(this->MajorantValues.size(), 0);
  for (std::size_t c = 0; c < occupied.size(); ++c)
  {
    occupied[c] = this->MajorantValues[c] > 0.0f ? 1 : 0;
  }
  this->EmptyCellFraction = avs::EmptyFraction(occupied);
  for (unsigned char& o : occupied)
  {
    o = o ? 255 : 0;
  }
  vtkAVSTextureUpload::TexelFormat format;
  format.InternalFormat = GL_R8;
  format.HostType = VTK_UNSIGNED_CHAR;
  format.Scale = 255.0f;
  const std::array<int, 3>& cells = this->ValueRanges.Cells();
  const std::size_t slice = static_cast<std::size_t>(cells[0]) * cells[1];
  if (!vtkAVSTextureUpload::Upload(
        this->Window,
        this->Occupancy,
        cells,
        1,
        format,
        [&occupied, slice](int z0, int, void*) -> const void*
        { return occupied.data() + slice * z0; },
        this->BudgetTextures(),
        error))
  {
    return false;
  }
  SetVolumeFilter(this->Occupancy, true); // one texel per cell (read with texelFetch)
  this->OccupancyRangesVersion = this->ValueRangesVersion;
  this->OccupancyKey = std::move(key);
  this->NotePeak();
  return true;
}

std::vector<vtkTextureObject*> vtkAVSVolumeTextures::BudgetTextures() const
{
  std::vector<vtkTextureObject*> held = this->VolumeTextures();
  if (this->OtherTextures)
  {
    const std::vector<vtkTextureObject*> others = this->OtherTextures();
    held.insert(held.begin(), others.begin(), others.end()); // the classification's stay last
  }
  return held;
}

std::vector<vtkTextureObject*> vtkAVSVolumeTextures::VolumeTextures() const
{
  std::vector<vtkTextureObject*> held = { this->Scalars,
    this->AveragedExtinction,
    this->Occlusion,
    this->Occupancy,
    this->LightVolumes[0],
    this->LightVolumes[1],
    this->Scratch[0],
    this->Scratch[1] };
  for (vtkTextureObject* t : this->BrickTextures)
  {
    held.push_back(t);
  }
  for (vtkTextureObject* t : this->Surfaces.VolumeTextures())
  {
    held.push_back(t);
  }
  for (vtkTextureObject* t : this->Classification.VolumeTextures())
  {
    held.push_back(t); // last: UploadClassification leaves them to the classification
  }
  return held;
}

bool vtkAVSVolumeTextures::UploadOcclusion(const avs::Grid& occlusion, std::string& error)
{
  return this->UploadGrid(
    this->Occlusion, occlusion.Geometry.Dimensions, 1, occlusion.Values.data(), error);
}

bool vtkAVSVolumeTextures::EnsureLightTextures(const std::array<int, 3>& dimensions,
  int count,
  std::string& error)
{
  if (dimensions != this->LightTextureDimensions)
  {
    this->AveragedSlot = -1;
    this->PhiSlot = -1;
    for (auto& t : this->LightVolumes)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
      t = nullptr;
    }
    this->LightTextureDimensions = dimensions;
  }
  std::vector<float> ones;
  for (int t = 0; t < count && t < NumberOfLightTextures; ++t)
  {
    if (!this->LightVolumes[t])
    {
      ones.resize(
        4 * static_cast<std::size_t>(dimensions[0]) * dimensions[1] * dimensions[2], 1.0f);
      if (!this->UploadGrid(
            this->LightVolumes[t], dimensions, 4, ones.data(), error, this->LightVolumeFormat()))
      {
        this->LightTextureDimensions = { 0, 0, 0 };
        return false;
      }
    }
  }
  return true;
}

bool vtkAVSVolumeTextures::UploadAveraged(const avs::Grid& averaged, std::string& error)
{
  ++this->AveragedWrites;
  return this->UploadGrid(
    this->AveragedExtinction, averaged.Geometry.Dimensions, 1, averaged.Values.data(), error);
}

bool vtkAVSVolumeTextures::UploadLightVolumes(const std::vector<avs::Grid>& lights,
  std::string& error)
{
  if (lights.empty())
  {
    return true;
  }
  const avs::Grid& first = lights.front();
  const std::size_t n = first.Values.size();
  for (const avs::Grid& light : lights)
  {
    if (light.Values.size() != n)
    {
      error = "the light volumes are not on one grid";
      return false;
    }
  }
  const int textures = LightTexturesFor(static_cast<int>(lights.size()));
  this->AveragedSlot = -1; // every channel is written below
  this->PhiSlot = -1;
  for (int t = 0; t < NumberOfLightTextures; ++t)
  {
    if (t >= textures)
    {
      // Not needed now; released so that no texture of another size is left behind.
      if (this->LightVolumes[t])
      {
        this->LightVolumes[t]->ReleaseGraphicsResources(this->Window);
        this->LightVolumes[t] = nullptr;
      }
      continue;
    }
    std::vector<float> packed(4 * n, 1.0f);
    for (int c = 0; c < 4; ++c)
    {
      const std::size_t j = static_cast<std::size_t>(4 * t + c);
      if (j < lights.size())
      {
        for (std::size_t i = 0; i < n; ++i)
        {
          packed[4 * i + c] = lights[j].Values[i];
        }
      }
    }
    if (!this->UploadGrid(this->LightVolumes[t],
          first.Geometry.Dimensions,
          4,
          packed.data(),
          error,
          this->LightVolumeFormat()))
    {
      return false;
    }
  }
  this->LightTextureDimensions = first.Geometry.Dimensions;
  return true;
}

bool vtkAVSVolumeTextures::UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error)
{
  if (this->Table)
  {
    this->Table->ReleaseGraphicsResources(this->Window);
  }
  this->Table = vtkSmartPointer<vtkTextureObject>::New();
  this->Table->SetContext(this->Window);
  ConfigureSampling(this->Table);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (!this->Table->Create2DFromRaw(static_cast<unsigned int>(slice.Axes.NumberOfTheta),
        static_cast<unsigned int>(slice.Axes.NumberOfTau),
        1,
        VTK_FLOAT,
        const_cast<float*>(slice.A.data())))
  {
    error = "the GPU could not allocate the scattering-table texture";
    this->Table = nullptr;
    return false;
  }
  this->LogGain = slice.LogGain; // a uniform array of the light-volume pass
  this->TableSize[0] = static_cast<float>(slice.Axes.NumberOfTheta);
  this->TableSize[1] = static_cast<float>(slice.Axes.NumberOfTau);
  this->TableTauMaximum = static_cast<float>(slice.Axes.TauMaximum);
  return true;
}
