/**
 * @class   vtkAVSVolumeTextures
 * @brief   the ray caster's textures of one render window and their uploads (private)
 *
 * Holds every texture vtkAVSRayCaster draws with or its compute passes write: the scalars (in
 * their texel format, vtkAVSTextureUpload), the classification (vtkAVSClassification), the
 * averaged extinction on the light grid, the packed light volumes, the ambient-occlusion
 * volume, the scattering-table slice and the averaged-extinction pass's intermediate grids.
 * Each 3D allocation goes through vtkAVSTextureUpload, which checks the context's 3D-texture
 * limit and the GPU memory budget (vtkAVSTextureMemory) first. The compute passes
 * (vtkAVSAveragedExtinctionPass, vtkAVSLightVolumePass, vtkAVSOcclusionPass) read and write the
 * members directly; the ray caster binds them for its frame.
 */
#ifndef vtkAVSVolumeTextures_h
#define vtkAVSVolumeTextures_h

#include "Grid.h"
#include "OccupancyGrid.h"
#include "ReferenceRenderer.h"
#include "ScatteringTable.h"
#include "vtkAVSBricks.h"
#include "vtkAVSClassification.h"
#include "vtkAVSSurfaceTexture.h"
#include "vtkAVSTextureUpload.h"

#include "vtkOpenGLRenderWindow.h" // for vtkWeakPointer<vtkOpenGLRenderWindow>
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkSmartPointer<vtkTextureObject>
#include "vtkWeakPointer.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkWindow;

class vtkAVSVolumeTextures
{
public:
  /// Packed light-volume textures: up to 8 lights, 4 channels each.
  static constexpr int NumberOfLightTextures = 2;
  /// How many of them `lights` lights need.
  static int LightTexturesFor(int lights) { return (lights + 3) / 4; }

  vtkAVSVolumeTextures() = default;
  vtkAVSVolumeTextures(const vtkAVSVolumeTextures&) = delete;
  vtkAVSVolumeTextures& operator=(const vtkAVSVolumeTextures&) = delete;

  /// The window whose context the textures are made in (the ray caster's).
  void SetWindow(vtkOpenGLRenderWindow* window);
  /// Releases every texture (in the current context, which the caller made `window`'s).
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Largest 3D texture size of the context (0 without a context), or AVS_MAXIMUM_3D_TEXTURE_SIZE
  /// from the environment where that is smaller (tests: the automatic split on a small volume).
  int MaximumTextureSize3D() const;
  /// Whether the context's renderer runs on the CPU (llvmpipe and the like), asked once per
  /// context.
  bool IsSoftwareRenderer() const;
  /// The light volumes' GL internal format: half floats on a GPU, floats on a software
  /// rasterizer.
  unsigned int LightVolumeFormat() const;

  /// A 3D float texture of `components` channels (data may be null: allocated, undefined, and
  /// storage of the same size reused), in the GL internal format `internalFormat` (0: 32-bit
  /// floats), through vtkAVSTextureUpload with this volume's textures as the budget's.
  /// Returns false and says why in `error` when the GPU refuses.
  bool UploadGrid(vtkSmartPointer<vtkTextureObject>& texture,
    const std::array<int, 3>& dimensions,
    int components,
    const float* data,
    std::string& error,
    unsigned int internalFormat = 0);
  /// The first `count` packed light-volume textures on the light grid `dimensions`, allocated
  /// (filled with ones) where missing or of another size.
  bool EnsureLightTextures(const std::array<int, 3>& dimensions, int count, std::string& error);

  /// Where the scalars' values come from when the scene's grids hold none (a GPU mapper does
  /// not keep a float copy of the volume on the host, vtkAVSDataTranslator::Volume::Deferred).
  struct ScalarSource
  {
    /// Writes the values [begin, end) (voxel ids) of channel c (0: the scalars, then the other
    /// components) as floats into `out`.
    std::function<void(int c, std::size_t begin, std::size_t end, float* out)> Read;
    /// Where the texels already lie, interleaved as the texture stores them (the array's own
    /// memory when its type is the texel type: unsigned 8 or 16 bits, or floats without
    /// infinities), or null.
    const void* Texels = nullptr;
    /// The slices [first, last) of the data that differ from the last upload's (what a new time
    /// step changed, vtkAVSVolumeMapper's fingerprints): where the textures of that upload
    /// can be kept (same size, format and layout, the same bricks), only those slices are
    /// written again, and only the bricks that hold some of them.
    std::array<int, 2> ChangedSlices = vtkAVSTextureUpload::AllSlices;
  };

  /// The uploads of vtkAVSRayCaster (documented there).
  /// The scalars in the texel format of their VTK type `scalarType`
  /// (vtkAVSTextureUpload::TexelFormat::ForScalars), converted slab by slab from the scene's
  /// grids or, where they are empty, from `source`; split into `partitions` bricks per axis
  /// ((1, 1, 1): the fewest the 3D-texture limit allows), one texture each (BrickTextures,
  /// Scalars then null), when that is more than one, with `lookBack` more voxel layers around
  /// each shared one (ambient scattering's look-ahead).
  bool UploadScalars(const avs::VolumeScene& scene,
    int scalarType,
    const ScalarSource& source,
    const std::array<int, 3>& partitions,
    const std::array<int, 3>& lookBack,
    std::string& error);
  bool UploadClassification(const avs::VolumeScene& scene, std::string& error);
  /// The occupancy of the scene's cells (avs::Occupancy) for its transfer functions, from the
  /// value ranges UploadScalars took, as an 8-bit texture (Occupancy); done by UploadScalars
  /// and UploadClassification, each time the ranges or the opacity changed.
  bool UploadOccupancy(const avs::VolumeScene& scene, std::string& error);
  /// Surfaces inside the medium (ShadeOn): the gradient of the scene's shading component
  /// (avs::SurfaceGrid), made from the scene's grids or, where they hold no values, from
  /// `source`, and uploaded whole or per brick (Surfaces) when the scalars, the component or its
  /// range changed since the last; released when `active` is false.
  bool UploadSurfaces(const avs::VolumeScene& scene,
    bool active,
    const ScalarSource& source,
    std::string& error);
  /// The scalars (one component) as 16-bit normalized integers over their finite range, which
  /// SurfacesPackedScale and SurfacesPackedShift then map back; 0 at NaN.
  std::vector<std::uint16_t> PackScalars(const avs::VolumeScene& scene, const ScalarSource& source);
  bool UploadAveraged(const avs::Grid& averaged, std::string& error);
  bool UploadLightVolumes(const std::vector<avs::Grid>& lights, std::string& error);
  bool UploadOcclusion(const avs::Grid& occlusion, std::string& error);
  bool UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error);

  /// Every 3D texture held for the volume (the GPU memory budget counts them), the
  /// classification's last.
  std::vector<vtkTextureObject*> VolumeTextures() const;
  /// Other 3D textures of the volume, outside this class (the extended model's fluence), which
  /// the GPU memory budget counts beside VolumeTextures when they allocate (set by
  /// vtkAVSRayCaster).
  std::function<std::vector<vtkTextureObject*>()> OtherTextures;
  /// VolumeTextures with OtherTextures before them: what an allocation is admitted beside.
  std::vector<vtkTextureObject*> BudgetTextures() const;
  /// Bytes of the volume textures held now (vtkAVSTextureMemory::Bytes), and the most they
  /// held at once since the last release (the precomputation's scratch grids included).
  double HeldBytes() const;
  double GetPeakBytes() const { return this->PeakBytes; }
  /// Counts a texture held for one pass (not a member) into the peak, beside those held.
  void NoteTemporary(vtkTextureObject* texture);
  /// Releases the averaged-extinction pass's intermediate grids (after the pass).
  void ReleaseScratch();
  /// The filter of a volume texture: the nearest voxel or trilinear (the interpolation type).
  static void SetVolumeFilter(vtkTextureObject* texture, bool nearest);
  /// Clamped to the edge, linear: how every texture of the ray caster is sampled.
  static void ConfigureSampling(vtkTextureObject* texture);

  /// Weak: the window may be deleted before the mapper, and its context took its resources.
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkSmartPointer<vtkTextureObject> Scalars, Occlusion, Table;
  /// Empty-space skipping (avs_skip.glsl): each component's value range per cell of the
  /// scalars (taken at their upload), and the occupancy of the cells, one 8-bit texel each
  /// (255: a sample there may have material), with the share of empty cells.
  avs::ValueRangeGrid ValueRanges;
  vtkSmartPointer<vtkTextureObject> Occupancy;
  double EmptyCellFraction = 0.0;
  /// The cells' majorants of sigma_t (avs::Majorants), from which the occupancy is taken, kept
  /// for the path-traced refinement (vtkAVSRefinement uploads them when MajorantsVersion
  /// changes).
  std::vector<float> MajorantValues;
  int MajorantsVersion = 0;
  /// The voxels (texels of the bricks, ghost layers included) the last UploadScalars wrote.
  double UploadedVoxels = 0.0;
  /// What Occupancy was built from: the ranges (counted at each UploadScalars) and the opacity
  /// (avs::ExtinctionKey), so that a colour change or a second call rebuilds nothing.
  int ValueRangesVersion = 0;
  int OccupancyRangesVersion = -1;
  std::vector<double> OccupancyKey;
  /// The bricks of a split volume (vtkAVSBricks; one unsplit brick otherwise) and, when split,
  /// their scalar textures (in the order of Bricks.GetBricks()).
  vtkAVSBricks Bricks;
  std::vector<vtkSmartPointer<vtkTextureObject>> BrickTextures;
  vtkAVSClassification Classification;
  /// The surfaces' gradient (UploadSurfaces) and what it was made from.
  vtkAVSSurfaceTexture Surfaces;
  std::vector<double> SurfacesKey;
  /// Whether the surfaces' texture holds the scalars in A (one channel, no gradient opacity or
  /// validity, not split into bricks; vtkAVSSurfaceTexture::Upload), and how: a scalar is
  /// A * SurfacesPackedScale + SurfacesPackedShift, A normalized.
  bool SurfacesPacked = false;
  double SurfacesPackedScale = 1.0;
  double SurfacesPackedShift = 0.0;
  /// The layout the scalars were uploaded with (vtkAVSClassification::Layout), and their texel
  /// format (its Scale and Shift map the texels back to data values in the shaders).
  vtkAVSClassification::Layout ScalarLayout;
  vtkAVSTextureUpload::TexelFormat ScalarFormat;
  /// Packed on the light grid: (T0-T3), (T4-T7).
  vtkSmartPointer<vtkTextureObject> LightVolumes[NumberOfLightTextures];
  std::array<int, 3> LightTextureDimensions{ 0, 0, 0 };
  /// Whether `texture` has the light textures' dimensions (so that a pass can copy it into one
  /// of their channels texel for texel).
  bool IsOnLightGrid(vtkTextureObject* texture) const
  {
    return texture && this->LightTextureDimensions[0] == int(texture->GetWidth()) &&
      this->LightTextureDimensions[1] == int(texture->GetHeight()) &&
      this->LightTextureDimensions[2] == int(texture->GetDepth());
  }
  /// The averaged extinction on the light grid, which the light-volume pass and the ray caster
  /// sample.
  vtkSmartPointer<vtkTextureObject> AveragedExtinction;
  /// How often AveragedExtinction was written (uploaded or computed).
  int AveragedWrites = 0;
  /// The slot of the packed light textures (light slots 0-7: channel slot % 4 of texture
  /// slot / 4) that holds a copy of the averaged extinction (vtkAVSLightVolumePass::CopyAveraged),
  /// -1 for none; the copy is current while AveragedSlotWrites == AveragedWrites.
  int AveragedSlot = -1;
  int AveragedSlotWrites = -1;
  /// Whether slot `slot` holds the current averaged extinction.
  bool HasAveragedIn(int slot) const
  {
    return slot >= 0 && this->AveragedSlot == slot &&
      this->AveragedSlotWrites == this->AveragedWrites;
  }
  /// The slot that holds the extended model's diffuse fluence as one number per point (its
  /// lights of one colour, vtkAVSLightVolumePass::CopyFluence), -1 for none; the copy is of the
  /// fluence written PhiSlotWrites-th (vtkAVSDiffuseVolume::GetWrites).
  int PhiSlot = -1;
  int PhiSlotWrites = -1;
  /// Whether slot `slot` holds the fluence of write `writes`.
  bool HasFluenceIn(int slot, int writes) const
  {
    return slot >= 0 && this->PhiSlot == slot && this->PhiSlotWrites == writes;
  }
  /// The averaged-extinction pass's intermediate grids (sigma_t summed along x, then along y,
  /// each shrunk to the light grid on its axis), released after the pass (ReleaseScratch).
  vtkSmartPointer<vtkTextureObject> Scratch[2];
  /// The table slice: log(F(tau) exp(2 tau)) on its tau nodes (the light-volume pass's uniform
  /// array), its size (theta, tau) and its longest tau.
  std::vector<float> LogGain;
  float TableSize[2] = { 1.0f, 1.0f };
  float TableTauMaximum = 1.0f;

private:
  void NotePeak();
  void ReleaseBricks(vtkWindow* window);
  bool UploadBricks(const avs::VolumeScene& scene,
    const ScalarSource& source,
    const vtkAVSClassification::Layout& layout,
    const vtkAVSTextureUpload::TexelFormat& format,
    const std::array<int, 2>& changed,
    std::string& error);
  double PeakBytes = 0.0;
  mutable int SoftwareRenderer = -1; ///< -1 unknown, 0 no, 1 yes (IsSoftwareRenderer)
};

#endif
