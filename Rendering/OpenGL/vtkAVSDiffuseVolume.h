/**
 * @class   vtkAVSDiffuseVolume
 * @brief   the extended model's diffuse fluence on the GPU (private)
 *
 * Holds the RGB fluence phi of the extended model (Core/DiffuseFluence.h), interpolated onto
 * the light grid and packed with the averaged extinction as one RGBA texture (phi, sigma~t):
 * uploaded from the core's CPU solve or computed on the GPU by the same solve
 * (avs_diffusion_cs.glsl, OpenGL 4.3: over the cells that are not vacuum, listed on the GPU,
 * which also flag the light grid's tiles that the solve reads for the light-volume pass), and
 * bound for the ray-casting program
 * (avs_as_effect.glsl, AVS_DIFFUSE: u_diffuse), which reads both with one fetch. Kept apart from
 * vtkAVSRayCaster, which only owns one and calls Bind / Unbind / ReleaseGraphicsResources.
 */
#ifndef vtkAVSDiffuseVolume_h
#define vtkAVSDiffuseVolume_h

#include "Grid.h"
#include "Lights.h"
#include "ScatteringParameters.h"
#include "vtkAVSTileList.h"

#include "vtkSmartPointer.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkAVSDiffuseVolume
{
public:
  vtkAVSDiffuseVolume();
  ~vtkAVSDiffuseVolume();
  vtkAVSDiffuseVolume(const vtkAVSDiffuseVolume&) = delete;
  vtkAVSDiffuseVolume& operator=(const vtkAVSDiffuseVolume&) = delete;

  /// Uploads phi (three grids on the light grid: R, G, B, avs::ComputeDiffuse) with the
  /// averaged extinction on the same grid into the texture of `window`'s context.
  bool Upload(vtkOpenGLRenderWindow* window,
    const std::vector<avs::Grid>& phi,
    const avs::Grid& averaged,
    std::string& error);
  /// The same solve on the GPU (the caller checked for compute shaders): the source from the
  /// averaged extinction and the packed light volumes on the light grid (textures of the ray
  /// caster; `lights1` may be null for up to four lights), then the red-black SOR
  /// sweeps of the nested solve (avs::ComputeDiffusion: `resolved.DiffusionCoarseIterations` per
  /// coarser level, `resolved.DiffusionIterations` on the finest) over the cells that are not
  /// vacuum (ListCells, for `averagedVersion`), into the fluence on `grid`
  /// (DiffusionGeometry), then phi interpolated onto the light grid with the averaged extinction
  /// into the texture, over the light grid's `tiles` (Core/LightTiles.h: those that the rays
  /// read; every tile when `tiles` is empty or the texture new). `lights` are in the data's
  /// frame, as for the light volumes.
  bool Compute(vtkOpenGLRenderWindow* window,
    const avs::GridGeometry& grid,
    const std::array<int, 3>& lightDimensions,
    const std::vector<std::uint32_t>& tiles,
    vtkTextureObject* averaged,
    vtkTextureObject* lights0,
    vtkTextureObject* lights1,
    const std::vector<avs::Light>& lights,
    const avs::ScatteringParameters& resolved,
    int averagedVersion,
    std::string& error);
  /// Lists, on the GPU, the cells of the solve's levels on `grid` that are not vacuum, from the
  /// averaged extinction `averaged` (on the light grid) and `resolved`'s albedo, anisotropy and
  /// radius: what the sweeps go over and MarkTiles reads. Redone when `averagedVersion` (the
  /// caller's count of changes of the averaged extinction), a grid or those parameters change;
  /// `lights` (null: none yet) choose the source's program.
  bool ListCells(vtkOpenGLRenderWindow* window,
    const avs::GridGeometry& grid,
    const std::array<int, 3>& lightDimensions,
    vtkTextureObject* averaged,
    const std::vector<avs::Light>* lights,
    const avs::ScatteringParameters& resolved,
    int averagedVersion,
    std::string& error);
  /// Writes into `tiles` (on the GPU) the tiles of the light grid that `light` (the data's
  /// frame) is read at: the rays' `rayTiles`, and those that the source reads r downstream of
  /// the cells that ListCells listed.
  bool MarkTiles(vtkOpenGLRenderWindow* window,
    const avs::GridGeometry& grid,
    const std::array<int, 3>& lightDimensions,
    const avs::Light& light,
    const avs::ScatteringParameters& resolved,
    const std::vector<std::uint32_t>& rayTiles,
    vtkAVSTileList& tiles,
    std::string& error);
  /// The bytes of its textures (vtkAVSTextureMemory): the packed texture, and after a GPU solve
  /// phi and q on every level, kept for the next solve.
  double HeldBytes() const;
  /// Its 3D textures now (the GPU memory budget counts them with the volume's).
  std::vector<vtkTextureObject*> GetTextures() const;
  /// The other 3D textures of its volume (vtkAVSVolumeTextures::VolumeTextures), which the GPU
  /// memory budget counts beside its own when it allocates (set by vtkAVSRayCaster).
  std::function<std::vector<vtkTextureObject*>()> OtherTextures;
  /// Whether a fluence is uploaded.
  bool IsReady() const { return this->Texture != nullptr; }
  /// The texture (phi, sigma~t) on the light grid; null before the first upload or solve.
  vtkTextureObject* GetTexture() const { return this->Texture; }
  /// How often the texture was written (uploaded or solved into): a copy of it is current
  /// while it was made at this count.
  int GetWrites() const { return this->Writes; }
  /// Activates the texture and sets the program's u_diffuse, u_anisotropy and u_reducedFloor
  /// (the flux limiter's, for the flux term along the ray) for `resolved`; with `colour` (lights
  /// of one colour whose fluence the rays read from a light texture's slot,
  /// vtkAVSLightVolumePass::CopyFluence) u_phiColour instead of the texture.
  void Bind(vtkShaderProgram* program,
    const avs::ScatteringParameters& resolved,
    const avs::Vec3* colour = nullptr);
  void Unbind();
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// An RGBA float texture of dimensions d, from `data` (null: undefined, for the GPU solve),
  /// through vtkAVSTextureUpload, within the GPU memory budget of everything the volume holds.
  bool Allocate(vtkOpenGLRenderWindow* window,
    vtkSmartPointer<vtkTextureObject>& texture,
    const std::array<int, 3>& d,
    const float* data,
    std::string& error);
  vtkSmartPointer<vtkTextureObject> Texture; ///< (phi, sigma~t) on the light grid
  vtkSmartPointer<vtkTextureObject> Fluence; ///< the GPU solve's phi on the diffusion grid
  vtkSmartPointer<vtkTextureObject> Source;  ///< the GPU solve's q
  /// The nested solve's coarser levels (DiffusionLevels 1, 2, ...): phi and q of each.
  std::vector<vtkSmartPointer<vtkTextureObject>> Coarser;
  /// phi and q of level l (0: Fluence and Source, then Coarser's pairs).
  vtkSmartPointer<vtkTextureObject>& LevelFluence(std::size_t l)
  {
    return l == 0 ? this->Fluence : this->Coarser[2 * l - 2];
  }
  vtkSmartPointer<vtkTextureObject>& LevelSource(std::size_t l)
  {
    return l == 0 ? this->Source : this->Coarser[2 * l - 1];
  }
  /// The stages of avs_diffusion_cs.glsl (AVS_DIFFUSION_STAGE).
  enum Stage
  {
    ListStage = 0,
    RelaxStage = 1,
    PackStage = 2,
    SourceStage = 3,
    MarkStage = 4,
    CompactStage = 5,
    NumberOfStages
  };
  /// The programs of the stages (a software rasterizer runs every branch of a shader, so one
  /// program would pay for all), the source's for ProgramDefines (the lights' kinds).
  bool EnsurePrograms(const std::vector<avs::Light>* lights, std::string& error);
  void SetModelUniforms(unsigned int program,
    const std::array<int, 3>& lightDimensions,
    vtkTextureObject* averaged,
    const avs::ScatteringParameters& resolved);
  void SetLevelUniforms(unsigned int program,
    const std::vector<avs::GridGeometry>& levels,
    std::size_t level);
  std::array<unsigned int, NumberOfStages> Programs{};
  /// The shader storage buffers: the levels' cells that are not vacuum (ListCells: a level's
  /// dispatches, counts and lists after the coarser ones'), CellEntries long, for ListedKey; the
  /// tiles' flags of MarkTiles; the tiles that the packing writes.
  unsigned int CellBuffer = 0;
  std::size_t CellEntries = 0;
  std::vector<double> ListedKey;
  unsigned int FlagBuffer = 0;
  vtkAVSTileList PackTiles;
  std::string ProgramDefines;
  std::array<int, 3> Dimensions{ 0, 0, 0 }; ///< the texture's (the light grid)
  int Writes = 0;                           ///< GetWrites
};

#endif
