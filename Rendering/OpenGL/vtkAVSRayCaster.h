/**
 * @class   vtkAVSRayCaster
 * @brief   the GL resources and the ray-casting pass shared by the module's mappers (private)
 *
 * The frame of one render window: it holds the textures (vtkAVSVolumeTextures: scalars,
 * classification, averaged extinction, light volumes, ambient occlusion, the scattering-table
 * slice), the extended model's fluence (vtkAVSDiffuseVolume), the depth copy (vtkAVSDepthCopy),
 * the compute passes of the GPU precomputation (vtkAVSAveragedExtinctionPass,
 * vtkAVSLightVolumePass, vtkAVSOcclusionPass) and the full-screen ray-casting program
 * (vtkAVSShaderAssembly), and draws the pass composited over what the renderer drew. The mappers
 * decide what to upload and when; this class and those it holds only talk to OpenGL.
 */
#ifndef vtkAVSRayCaster_h
#define vtkAVSRayCaster_h

#include "ClipRegion.h"
#include "DisplayTransform.h"
#include "Grid.h"
#include "LightVolume.h"
#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "TransferFunction.h"
#include "vtkAVSAveragedExtinctionPass.h"
#include "vtkAVSDepthCopy.h"
#include "vtkAVSDiffuseVolume.h"
#include "vtkAVSImageSampler.h"
#include "vtkAVSLightVolumePass.h"
#include "vtkAVSOcclusionPass.h"
#include "vtkAVSRefinement.h"
#include "vtkAVSShaderOptions.h"
#include "vtkAVSVolumeTextures.h"
#include "vtkOpenGLRenderWindow.h" // for vtkWeakPointer<vtkOpenGLRenderWindow>
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkAbstractMapper;
class vtkMatrix4x4;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkAVSRayCaster
{
public:
  static constexpr int MaximumNumberOfLights = 8;
  /// Largest ring buffer of the ambient-scattering look-ahead (entries); beyond it the
  /// look-ahead sample is classified explicitly.
  static constexpr int MaximumRingSize = 512;
  /// Longest table tau axis for which directional lights keep a per-ray column of A (longer
  /// axes are read from the table texture per sample) and the GPU light-volume pass runs (it
  /// keeps log F in an array; longer axes make the mapper march the light volumes on the CPU).
  static constexpr int MaximumTauNodes = 64;

  vtkAVSRayCaster();
  ~vtkAVSRayCaster();
  vtkAVSRayCaster(const vtkAVSRayCaster&) = delete;
  vtkAVSRayCaster& operator=(const vtkAVSRayCaster&) = delete;

  /// The window whose context holds the resources; a different window releases them first.
  void SetWindow(vtkOpenGLRenderWindow* window);
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window.Get(); }
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Largest 3D texture size of the context (0 without a context).
  int MaximumTextureSize3D() const;

  /// Texture uploads; return false and say why in `error` when the GPU refuses. The volume:
  /// its components (and the validity of NaN data) in one texture, in the texel format of the
  /// array's VTK type `scalarType` (vtkAVSTextureUpload), from the scene's grids or, where they
  /// hold no values, from `source`. Split into `partitions` bricks per axis ((1, 1, 1): only where
  /// the 3D-texture limit needs it), one texture each (vtkAVSBricks), drawn back to front;
  /// `lookBack` more voxel layers around each shared one for ambient scattering (LookBackVoxels).
  bool UploadScalars(const avs::VolumeScene& scene,
    int scalarType,
    const vtkAVSVolumeTextures::ScalarSource& source,
    const std::array<int, 3>& partitions,
    const std::array<int, 3>& lookBack,
    std::string& error);
  /// The voxels a brick's rays of ambient scattering read before its first sample: the
  /// look-ahead's r and one step back (the ring buffer starts there; avs_as_effect.glsl), at
  /// `spacing`.
  static std::array<int, 3> LookBackVoxels(double radius,
    double sampleDistance,
    const avs::Vec3& spacing);
  /// Bricks of the uploaded scalars (1: unsplit, 0: none uploaded) and whether there are more.
  int GetNumberOfBricks() const;
  bool IsBricked() const { return this->GetNumberOfBricks() > 1; }
  /// The GPU memory the context reports (GL_NVX_gpu_memory_info's dedicated video memory, or
  /// GL_ATI_meminfo's free texture memory), in bytes; 0 where it reports none.
  double ReportedGPUMemoryBytes();
  /// The classification's tables, mask and uniforms (vtkAVSClassification), after the scalars.
  bool UploadClassification(const avs::VolumeScene& scene, std::string& error);
  /// Surfaces inside the medium: the precomputed gradient (vtkAVSVolumeTextures::UploadSurfaces).
  bool UploadSurfaces(const avs::VolumeScene& scene,
    bool active,
    const vtkAVSVolumeTextures::ScalarSource& source,
    std::string& error);
  /// The CPU's ambient-scattering volumes: the averaged extinction on the light grid (which
  /// the ray caster samples with the light volumes' coordinate) ...
  bool UploadAveraged(const avs::Grid& averaged, std::string& error);
  /// ... and up to 8 light volumes on the same grid, four to an RGBA texture.
  bool UploadLightVolumes(const std::vector<avs::Grid>& lights, std::string& error);

  /// Ambient occlusion computed on the GPU into the occlusion texture, on the grid `dimensions`
  /// over the box of the data grid `geometry` (at most 256 directions), from sigma_t that the
  /// averaged-extinction program classifies from the uploaded scalars (0 outside `clip`) into a
  /// texture held for the pass alone. Returns false when the context cannot, with the reason.
  bool ComputeOcclusion(const avs::GridGeometry& geometry,
    const std::array<int, 3>& dimensions,
    double radius,
    int directions,
    const avs::ClipRegion& clip,
    std::string& error);

  /// The averaged extinction computed on the GPU from the uploaded scalars and transfer function
  /// (classification on the data's grid `dimensions`, then box sums along x, y, z with the half
  /// widths, each axis interpolated onto the light grid `lightDimensions` as it is summed) into
  /// the averaged texture (light grid), which the light-volume pass and the ray caster sample.
  /// sigma_t is 0 outside `clip` (in the data's index frame).
  bool ComputeAveragedExtinction(const std::array<int, 3>& dimensions,
    const std::array<int, 3>& lightDimensions,
    const std::array<int, 3>& halfWidths,
    const avs::ClipRegion& clip,
    std::string& error);

  /// Whether the context runs compute shaders (OpenGL 4.3), for the GPU precomputation.
  bool SupportsComputeShaders();
  /// Light volumes computed on the GPU: tube-marches light `index` (< 8, given in the data's
  /// frame) on `lightGrid` into its channel of the packed textures (allocated once per size).
  /// Needs the averaged extinction (ComputeAveragedExtinction on the same grid) and the table
  /// slice. `law` as avs::ComputeLightVolume's (TubeLaw::DirectBeam: the extended model's
  /// positional lights).
  bool ComputeLightVolume(int index,
    const avs::GridGeometry& lightGrid,
    const avs::Light& light,
    double radius,
    avs::TubeLaw law,
    std::string& error);
  /// Which tiles of `lightGrid` (over the uploaded scalars' box) the next ComputeLightVolume
  /// marches for `light` (in the data's frame): with `skipEmpty` (the mapper's
  /// EmptySpaceSkipping) those that the rays can read near the cells that the occupancy says
  /// may hold material (avs::LightGridTiles), and with `diffusion` those that the extended
  /// model's diffusion source reads from its cells that are not vacuum (vtkAVSDiffuseVolume::
  /// MarkTiles, on the GPU, from the averaged extinction of `averagedVersion`), else all of
  /// them. False with the reason when that fails.
  bool UpdateLightTiles(const avs::GridGeometry& lightGrid,
    const avs::Light& light,
    const avs::ScatteringParameters& resolved,
    bool diffusion,
    bool skipEmpty,
    int averagedVersion,
    std::string& error);
  /// The tiles of `lightGrid` that the rays read (with `skipEmpty`, those near the cells that
  /// the occupancy says may hold material; else all): where the extended model packs its
  /// fluence.
  std::vector<std::uint32_t> RayTiles(const avs::GridGeometry& lightGrid, bool skipEmpty) const;
  /// Counts the changes of the occupancy that UpdateLightTiles reads.
  int GetOccupancyVersion() const { return this->Textures.MajorantsVersion; }
  /// With 1-3 or 5-7 `lights`, copies the averaged extinction into the free channel after the
  /// last light's (compute shaders; vtkAVSLightVolumePass::CopyAveraged), which saves the rays
  /// a texture fetch per sample. Call after the light volumes are current; nothing happens when
  /// the copy is current, or when there is no free channel or no compute shader (the rays then
  /// read the averaged extinction's own texture). False on a GL error.
  bool PackAveraged(int lights, std::string& error);
  /// In the extended model with 1, 2, 5 or 6 `lights` of one colour (avs::CommonColour) and the
  /// averaged extinction packed (PackAveraged), copies the diffuse fluence as one number per
  /// point into the channel after the averaged extinction's
  /// (vtkAVSLightVolumePass::CopyFluence): the rays then read the lights, the averaged
  /// extinction and the fluence with one fetch. Call after the fluence is current; nothing
  /// happens where the copy is current or cannot be made (the rays then read the fluence's
  /// texture). False on a GL error.
  bool PackFluence(const std::vector<avs::Light>& lights, std::string& error);
  bool UploadOcclusion(const avs::Grid& occlusion, std::string& error);
  bool UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error);
  /// The extended model's diffuse fluence (vtkAVSDiffuseVolume), bound when the frame's
  /// parameters ask for the extended model.
  vtkAVSDiffuseVolume& GetDiffuseVolume() { return this->Diffuse; }
  /// What the GPU diffusion solve reads: the averaged extinction and the packed light volumes
  /// on the light grid (null where absent).
  vtkTextureObject* GetAveragedExtinctionTexture() const;
  vtkTextureObject* GetLightVolumeTexture(int t) const;
  /// Bytes of the volume's 3D textures (vtkAVSVolumeTextures::VolumeTextures), as the GPU
  /// memory budget counts them.
  double VolumeTextureBytes() const;
  /// The most they held at once since the last release (during a precomputation).
  double PeakVolumeTextureBytes() const;

  struct Frame
  {
    avs::RenderMode Mode = avs::RenderMode::EmissionAbsorption;
    avs::ScatteringParameters Parameters; ///< resolved
    vtkMatrix4x4* WorldToIndex = nullptr; ///< row-major, VTK convention
    std::array<int, 3> Dimensions{ 1, 1, 1 };
    avs::Vec3 Spacing{ 1, 1, 1 };     ///< data units per index step (the grid's spacing)
    double Border = 0.0;              ///< the box beyond the samples, in voxels (cell data: 0.5)
    avs::ClipRegion Clip;             ///< clipping planes and cropping, index frame
    vtkAVSShaderOptions::Blend Blend; ///< emission-absorption only
    std::array<int, 3> LightVolumeDimensions{ 1, 1, 1 };
    /// Ambient scattering reads the lights once per group of this many samples, 1, 2 or 4
    /// (avs::ScatteringParameters::LightGroup).
    int LightGroup = 1;
    /// The light grid covers the whole image of which the volume is a piece (distributed
    /// rendering): its samples and the piece's first sample in it.
    std::array<int, 3> WholeDimensions{ 1, 1, 1 };
    std::array<int, 3> PieceOffset{ 0, 0, 0 };
    std::array<int, 3> OcclusionDimensions{ 1, 1, 1 };
    std::vector<avs::Light> Lights; ///< world space
    bool Jitter = true;
    /// The volume and its mapper, for the render passes attached to the volume (SSAO's draw
    /// buffers); with PeelingFront the volume goes into vtkDualDepthPeelingPass's front target
    /// (vtkAVSRenderPasses).
    vtkProp* Prop = nullptr;
    vtkAbstractMapper* Mapper = nullptr;
    bool PeelingFront = false;
    /// Pixels per ray along each axis (vtkAVSImageSampler); 1: one ray per pixel.
    double ImageSampleDistance = 1.0;
    /// What the framebuffer receives of the volume's linear radiance: the exposure (metered
    /// where auto exposure is on) and the tone curve (avs_display.glsl), applied once, where
    /// the ray ends or, for a pass through the image sampler's target, as it is composited.
    avs::DisplayTransform Display;
    /// Leap over the empty cells (avs_skip.glsl) where the frame allows it: the composite
    /// blend, and for ambient scattering the ring's look-ahead.
    bool SkipEmptySpace = true;
    /// Ambient scattering's path-traced refinement (vtkAVSRefinement): on, whether this frame
    /// may add samples (a still frame; the ray caster also wants one ray per pixel), what must
    /// not change for the samples to add up (the mapper's key, exact, and its geometry: camera,
    /// matrices and lights, to a millionth; the viewport's size is added here) and the samples
    /// per pixel at which it stops.
    struct RefinementSettings
    {
      bool Enabled = false;
      bool Still = false;
      std::vector<double> Key;
      std::vector<double> Geometry;
      int MaximumSamples = 1024;
    } Refinement;
  };

  /// Draws the volume into the current viewport (the renderer's, or a render pass's). Returns
  /// false when the program cannot be built (nothing drawn) or OpenGL reported an error.
  bool Render(vtkRenderer* renderer, const Frame& frame, std::string& error);
  /// Whether the last Render leapt over empty cells, and the share of the volume's cells that
  /// are empty for the current transfer functions (vtkAVSVolumeTextures::Occupancy).
  bool GetLastSkippedEmptySpace() const { return this->LastSkipped; }
  double GetEmptyCellFraction() const { return this->Textures.EmptyCellFraction; }
  /// The voxels the last scalar upload wrote (ghost layers of bricks included).
  double GetUploadedVoxels() const { return this->Textures.UploadedVoxels; }
  /// Rays the last Render cast along x and y.
  const std::array<int, 2>& GetLastPassSize() const { return this->LastPassSize; }
  /// The path-traced refinement's state (samples, buffers).
  vtkAVSRefinement& GetRefinement() { return this->Refinement; }
  /// Whether the last Render showed the refined picture.
  bool GetLastRefined() const { return this->LastRefined; }

private:
  /// A still frame of the refinement (vtkAVSRayCasterRefine.cxx): the ambient picture taken
  /// where there is none (`drawPass` with the ray-casting program, current), one path-traced
  /// sample added below the maximum, and the refined picture shown over the viewport. False
  /// having drawn nothing when this frame is not refined (reduced, or no ambient picture can be
  /// taken), with `error` set when OpenGL failed.
  bool Refine(vtkRenderer* renderer,
    const Frame& frame,
    vtkShaderProgram* program,
    const std::function<void()>& drawPass,
    int x,
    int y,
    int width,
    int height,
    std::string& error);

  /// The ray-casting program for `mode` and these defines (built again when they change).
  bool EnsureProgram(avs::RenderMode mode, const std::string& defines);

  /// Weak: the window may be deleted before the mapper (a volume removed from its renderer is
  /// not told), and its context took its resources with it.
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkAVSVolumeTextures Textures;
  vtkAVSDiffuseVolume Diffuse; ///< the extended model's fluence

  vtkAVSDepthCopy Depth; ///< where the rays end at opaque geometry
  bool LastSkipped = false;
  vtkAVSAveragedExtinctionPass AveragedExtinctionPass;
  vtkAVSLightVolumePass LightVolumePass;
  vtkAVSOcclusionPass OcclusionPass;
  int ComputeSupport = -1;      ///< -1 unknown, 0 no, 1 yes
  double ReportedMemory = -1.0; ///< ReportedGPUMemoryBytes; -1 not asked in this context
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  int QuadMode = -1;
  std::string QuadDefines;
  vtkAVSImageSampler ImageSampler; ///< the pass at image sample distances other than 1
  vtkAVSRefinement Refinement;     ///< ambient scattering's path-traced refinement
  bool LastRefined = false;
  bool RefinementRefused = false; ///< warned that the refinement's buffers were refused
  std::array<int, 2> LastPassSize{ 0, 0 };
};

#endif
