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

#include "Grid.h"
#include "Lights.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "TransferFunction.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
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
  /// axes are read from the table texture per sample).
  static constexpr int MaximumColumnNodes = 64;

  vtkAVSRayCaster();
  ~vtkAVSRayCaster();
  vtkAVSRayCaster(const vtkAVSRayCaster&) = delete;
  vtkAVSRayCaster& operator=(const vtkAVSRayCaster&) = delete;

  /// The window whose context holds the resources; a different window releases them first.
  void SetWindow(vtkOpenGLRenderWindow* window);
  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }
  void ReleaseGraphicsResources(vtkWindow* window);

  /// Largest 3D texture size of the context (0 without a context).
  int MaximumTextureSize3D() const;

  /// Texture uploads; return false and say why in `error` when the GPU refuses.
  bool UploadScalars(const avs::Grid& scalars, std::string& error);
  bool UploadTransferFunction(const avs::TransferFunction& tf, std::string& error);
  /// The CPU's averaged extinction, stored beside the scalars (two channels: scalar, averaged)
  /// as the ambient-scattering ray caster fetches them; both on the data's grid.
  bool UploadAveragedExtinction(const avs::Grid& scalars,
    const avs::Grid& averaged,
    std::string& error);
  /// Up to 8 light volumes on one grid, packed four to an RGBA texture.
  bool UploadLightVolumes(const std::vector<avs::Grid>& volumes, std::string& error);

  /// Ambient occlusion computed on the GPU from the extinction grid into the occlusion texture
  /// (at most 256 directions). Returns false when the context cannot, with the reason.
  bool ComputeOcclusion(const avs::Grid& extinction,
    double radius,
    int directions,
    std::string& error);

  /// The averaged extinction computed on the GPU from the uploaded scalars and transfer function
  /// (classification, then box sums along x, y, z with the half widths) into the averaged
  /// texture. `dimensions` are the data's.
  bool ComputeAveragedExtinction(const std::array<int, 3>& dimensions,
    double unitDistance,
    const std::array<int, 3>& halfWidths,
    std::string& error);

  /// Whether the context runs compute shaders (OpenGL 4.3), for the GPU precomputation.
  bool SupportsComputeShaders();
  /// Light volumes computed on the GPU: allocates the two packed textures on `lightGrid` (once
  /// per size), then tube-marches light `index` (< 8, given in the data's frame) into its
  /// channel. Needs the averaged extinction and the table slice uploaded.
  bool ComputeLightVolume(int index,
    const avs::GridGeometry& dataGrid,
    const avs::GridGeometry& lightGrid,
    const avs::Light& light,
    double radius,
    std::string& error);
  bool UploadOcclusion(const avs::Grid& occlusion, std::string& error);
  bool UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error);

  struct Frame
  {
    avs::RenderMode Mode = avs::RenderMode::EmissionAbsorption;
    avs::ScatteringParameters Parameters; ///< resolved
    vtkMatrix4x4* WorldToIndex = nullptr; ///< row-major, VTK convention
    std::array<int, 3> Dimensions{ 1, 1, 1 };
    std::array<int, 3> LightVolumeDimensions{ 1, 1, 1 };
    double UnitDistance = 1.0;
    std::vector<avs::Light> Lights; ///< world space
    bool Jitter = true;
  };

  /// Draws the volume into the renderer's viewport. Returns false (and draws nothing) when the
  /// program cannot be built.
  bool Render(vtkRenderer* renderer, const Frame& frame, std::string& error);

private:
  bool UploadScalarGrid(vtkSmartPointer<vtkTextureObject>& texture,
    const avs::Grid& grid,
    int components,
    const float* data,
    std::string& error);
  bool EnsureProgram(avs::RenderMode mode, const std::string& defines);
  /// Whether lights 0 and 1 can travel in the volume texture's .ba (compute shaders, light
  /// volumes on the data's grid); if so, copies them there unless already done.
  bool PackLightVolumes(const Frame& frame);
  /// Copies the depth of the viewport into Depth (multisampled framebuffers are resolved).
  void CaptureDepth(int x, int y, int width, int height);
  unsigned int BuildComputeProgram(const char* source, const char* what);

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkTextureObject> Scalars, Transfer, Averaged, Occlusion, Table, Depth, LogGain;
  vtkSmartPointer<vtkTextureObject> LightVolumes[2];
  /// The averaged extinction alone (one channel), which the light-volume pass samples: a
  /// quarter of the bytes per fetch of the ray caster's four-channel volume texture (Averaged).
  vtkSmartPointer<vtkTextureObject> AveragedExtinction;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFramebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  int QuadMode = -1;
  std::string QuadDefines;
  int DepthFormat = 0;
  unsigned int ComputeProgram = 0;   ///< GL name of the light-volume compute program
  unsigned int OcclusionProgram = 0; ///< GL name of the ambient-occlusion compute program
  unsigned int AverageProgram = 0;   ///< GL name of the averaged-extinction compute program
  unsigned int PackProgram = 0;      ///< GL name of the light-packing compute program
  bool LightsPacked = false;         ///< lights 0 and 1 are in Averaged's .ba
  int ComputeSupport = -1;           ///< -1 unknown, 0 no, 1 yes
  std::array<int, 3> ComputedDimensions{ 0, 0, 0 };
  float TauNodes = 2.0f;
  bool DepthWarningGiven = false;
  float TransferSize = 1.0f;
  float ScalarRange[2] = { 0.0f, 1.0f };
  float TableSize[2] = { 1.0f, 1.0f };
  float TableTauMaximum = 1.0f;
};

#endif
