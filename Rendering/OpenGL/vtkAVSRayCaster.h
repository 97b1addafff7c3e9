/**
 * @class   vtkAVSRayCaster
 * @brief   the GL resources and the ray-casting pass shared by the module's mappers (private)
 *
 * Holds the textures (scalars, transfer function, averaged extinction, light volumes, ambient
 * occlusion, the scattering-table slice, the depth copy) and the full-screen ray-casting program
 * of one render window, and draws the pass composited over what the renderer drew. The mappers
 * decide what to upload and when; this class only talks to OpenGL.
 */
#ifndef vtkAVSRayCaster_h
#define vtkAVSRayCaster_h

#include "ClipRegion.h"
#include "Grid.h"
#include "LightVolume.h"
#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "TransferFunction.h"
#include "vtkAVSClassification.h"
#include "vtkAVSDiffuseVolume.h"
#include "vtkAVSShaderOptions.h"

#include "vtkAVSImageSampler.h"
#include "vtkOpenGLRenderWindow.h" // for vtkWeakPointer<vtkOpenGLRenderWindow>
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkAbstractMapper;
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
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
  /// Packed light-volume textures: up to 8 lights, 4 channels each.
  static constexpr int NumberOfLightTextures = 2;
  /// How many of them `lights` lights need.
  static int LightTexturesFor(int lights) { return (lights + 3) / 4; }

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
  /// its components (and the validity of NaN data) in one texture
  /// (vtkAVSClassification::PackScalars).
  bool UploadScalars(const avs::VolumeScene& scene, std::string& error);
  /// The classification's tables, mask and uniforms (vtkAVSClassification), after the scalars.
  bool UploadClassification(const avs::VolumeScene& scene, std::string& error);
  /// The CPU's ambient-scattering volumes as the ray caster fetches them: the volume's
  /// channels beside the averaged extinction interpolated at the voxels (both on the data's
  /// grid, one texture when they fit into four channels, else the averaged extinction in a
  /// texture of its own) ...
  bool UploadScalarsAveraged(const avs::VolumeScene& scene,
    const avs::Grid& averagedAtVoxels,
    std::string& error);
  /// ... and up to 8 light volumes on one (the light) grid, four to an RGBA texture.
  bool UploadLightVolumes(const std::vector<avs::Grid>& lights, std::string& error);

  /// Ambient occlusion computed on the GPU from the extinction grid into the occlusion texture,
  /// on the grid `dimensions` over the same box (at most 256 directions). Returns false when the
  /// context cannot, with the reason.
  bool ComputeOcclusion(const avs::Grid& extinction,
    const std::array<int, 3>& dimensions,
    double radius,
    int directions,
    std::string& error);

  /// The averaged extinction computed on the GPU from the uploaded scalars and transfer function
  /// (classification on the data's grid `dimensions`, then box sums along x, y, z with the half
  /// widths, each axis interpolated onto the light grid `lightDimensions` as it is summed) into
  /// the averaged texture (light grid), then interpolated back at the voxels beside the scalars
  /// into the ray caster's two-channel volume texture.
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
  bool UploadOcclusion(const avs::Grid& occlusion, std::string& error);
  bool UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error);
  /// The extended model's diffuse fluence (vtkAVSDiffuseVolume), bound when the frame's
  /// parameters ask for the extended model.
  vtkAVSDiffuseVolume& GetDiffuseVolume() { return this->Diffuse; }
  /// What the GPU diffusion solve reads: the averaged extinction and the packed light volumes
  /// on the light grid (null where absent).
  vtkTextureObject* GetAveragedExtinctionTexture() const;
  vtkTextureObject* GetLightVolumeTexture(int t) const;

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
  };

  /// Draws the volume into the current viewport (the renderer's, or a render pass's). Returns
  /// false when the program cannot be built (nothing drawn) or OpenGL reported an error.
  bool Render(vtkRenderer* renderer, const Frame& frame, std::string& error);
  /// Rays the last Render cast along x and y.
  const std::array<int, 2>& GetLastPassSize() const { return this->LastPassSize; }

private:
  /// A 3D float texture of `components` channels (data may be null: allocated, undefined), in
  /// the GL internal format `internalFormat` (0: 32-bit floats).
  bool UploadScalarGrid(vtkSmartPointer<vtkTextureObject>& texture,
    const std::array<int, 3>& dimensions,
    int components,
    const float* data,
    std::string& error,
    unsigned int internalFormat = 0);
  bool EnsureProgram(avs::RenderMode mode, const std::string& defines);
  /// The filter of a volume texture: the nearest voxel or trilinear (the interpolation type).
  static void SetVolumeFilter(vtkTextureObject* texture, bool nearest);
  /// The light volumes' GL internal format: half floats on a GPU, floats on a software
  /// rasterizer.
  unsigned int LightVolumeFormat() const;
  /// Whether the context's renderer runs on the CPU (llvmpipe and the like), asked once per
  /// context.
  bool IsSoftwareRenderer() const;
  /// The first `count` packed light-volume textures on the light grid `dimensions`, allocated
  /// (filled with ones) where missing or of another size.
  bool EnsureLightTextures(const std::array<int, 3>& dimensions, int count, std::string& error);
  /// Copies the depth of the read framebuffer's rectangle at (x, y) into Depth, by a blit into a
  /// texture of the same depth format (multisampled framebuffers are resolved).
  void CaptureDepth(int x, int y, int width, int height);
  unsigned int BuildComputeProgram(const char* source, const char* what);
  /// Every 3D texture held for the volume (the GPU memory budget counts them).
  std::vector<vtkTextureObject*> VolumeTextures() const;
  /// The averaged-extinction program for these defines (rebuilt when they change).
  unsigned int BuildAverageProgram(const std::string& defines);

  /// Weak: the window may be deleted before the mapper (a volume removed from its renderer is
  /// not told), and its context took its resources with it.
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  vtkSmartPointer<vtkTextureObject> Scalars, Occlusion, Table, Depth;
  vtkAVSClassification Classification;
  vtkAVSDiffuseVolume Diffuse; ///< the extended model's fluence
  /// The layout the scalars were uploaded with (vtkAVSClassification::Layout).
  vtkAVSClassification::Layout ScalarLayout;
  std::vector<float> LogGain; ///< log(F(tau) exp(2 tau)) on the table's tau nodes
  /// Data grid, for ambient scattering: the volume's channels and then the averaged sigma_t at
  /// the voxel (AveragedChannel) or, when they do not fit into four channels, the averaged
  /// sigma_t alone (AveragedChannel -1).
  vtkSmartPointer<vtkTextureObject> ScalarsAveraged;
  int AveragedChannel = 1;
  /// Which channel of ScalarsAveraged holds the averaged extinction for a layout (-1: it is
  /// alone in it), and its channel count.
  static int AveragedChannelFor(const vtkAVSClassification::Layout& layout);
  static int AveragedComponentsFor(const vtkAVSClassification::Layout& layout);
  /// Classification and packing defines of the averaged-extinction program it was built with.
  std::string AverageDefines;
  /// Packed on the light grid: (T0-T3), (T4-T7).
  vtkSmartPointer<vtkTextureObject> LightVolumes[NumberOfLightTextures];
  /// The averaged extinction on the light grid, which the light-volume pass samples.
  vtkSmartPointer<vtkTextureObject> AveragedExtinction;
  /// The averaged-extinction pass's intermediate grids (sigma_t on the data grid, then reduced
  /// along x and along y), kept between rebuilds: allocating them again costs more than the
  /// pass on a software rasterizer.
  vtkSmartPointer<vtkTextureObject> Scratch[3];
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFramebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkAVSImageSampler ImageSampler; ///< the pass at image sample distances other than 1
  std::array<int, 2> LastPassSize{ 0, 0 };
  int QuadMode = -1;
  std::string QuadDefines;
  int DepthFormat = 0;
  unsigned int ComputeProgram = 0;   ///< GL name of the light-volume compute program
  unsigned int OcclusionProgram = 0; ///< GL name of the ambient-occlusion compute program
  unsigned int AverageProgram = 0;   ///< GL name of the averaged-extinction compute program
  int ComputeSupport = -1;           ///< -1 unknown, 0 no, 1 yes
  mutable int SoftwareRenderer = -1; ///< -1 unknown, 0 no, 1 yes (IsSoftwareRenderer)
  std::array<int, 3> LightTextureDimensions{ 0, 0, 0 };
  bool DepthWarningGiven = false;
  float TableSize[2] = { 1.0f, 1.0f };
  float TableTauMaximum = 1.0f;
};

#endif
