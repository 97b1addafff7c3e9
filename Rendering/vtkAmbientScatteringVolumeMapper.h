/**
 * @class   vtkAmbientScatteringVolumeMapper
 * @brief   GPU volume mapper with ambient volume scattering (ALGORITHM.md sections 3-6)
 *
 * A drop-in vtkVolumeMapper for vtkImageData that lights the volume with the renderer's lights
 * (directional, positional, spot, headlight, light kit; up to 8) including soft shadows,
 * translucency and multiple scattering, after Ament, Sadlo and Weiskopf (IEEE TVCG 2013):
 *
 * - the extinction averaged over balls of radius AmbientRadius (a summed-area table, O(N) for any
 *   radius);
 * - per light, a light volume of tube transmittance: balls chained from the light to each voxel,
 *   each passing on the share F of light that a preintegrated table says a homogeneous ball lets
 *   through, scattering included (stored where the light enters the ball around the voxel);
 * - a ray caster that adds, at each sample, the light the ball ahead scatters towards the camera,
 *   read from the preintegrated in-scattering table A for the current Anisotropy and Albedo.
 *
 * Precomputation is redone only when its inputs change (see vtkAVSVolumeMapper). The table is the
 * one shipped with the module unless ScatteringTableFileName names another.
 *
 * The radiance these rays integrate is linear and, lit by ordinary VTK lights, brighter than a
 * Phong-shaded picture (multiple scattering adds what single scattering lacks): what the
 * framebuffer receives goes through the display transform, with this mapper's defaults exposure
 * DefaultExposure (0.5) and the shoulder tone curve (vtkAVSVolumeMapper::SetExposure).
 */
#ifndef vtkAmbientScatteringVolumeMapper_h
#define vtkAmbientScatteringVolumeMapper_h

#include "vtkAVSVolumeMapper.h"

#include <memory> // for std::unique_ptr

namespace avs
{
class ScatteringTable;
}
class vtkAVSScatteringVolumes;
class vtkAmbientScatteringTable;

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkAmbientScatteringVolumeMapper
  : public vtkAVSVolumeMapper
{
public:
  static vtkAmbientScatteringVolumeMapper* New();
  vtkTypeMacro(vtkAmbientScatteringVolumeMapper, vtkAVSVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Ambient radius r in data units (world units for an untransformed volume). Default 0: automatic,
   * 1/64 of the volume's diagonal, at least the smallest voxel spacing and at most half the
   * volume's smallest side (so that the ball fits into thin slabs and stacks of a few slices).
   */
  vtkSetClampMacro(AmbientRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AmbientRadius, double);
  ///@}

  ///@{
  /**
   * Henyey–Greenstein anisotropy g in [-0.95, 0.95]; > 0 scatters forwards. Default 0.
   */
  vtkSetClampMacro(Anisotropy, double, -0.95, 0.95);
  vtkGetMacro(Anisotropy, double);
  ///@}

  ///@{
  /**
   * Scattering albedo in [0, 1]. Default 0.8 (the swap test shows why: with 0.9 the extended
   * model's diffuse light flattens the shading of dense media, at 0.8 they keep 0.7 or more of
   * the paper model's structure; Documentation/Parameters.md, "Display transform").
   */
  vtkSetClampMacro(Albedo, double, 0.0, 1.0);
  vtkGetMacro(Albedo, double);
  ///@}

  ///@{
  /**
   * Emission weight k_e >= 0: the medium also glows with k_e times its colour. Default 0.
   */
  vtkSetClampMacro(EmissionWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EmissionWeight, double);
  ///@}

  ///@{
  /**
   * Multiplies the irradiance of every light for this volume only (>= 0). Lights are in VTK's
   * units: a vtkLight of intensity I and colour c gives the irradiance 4 pi I c, so that a light
   * of intensity 1 on an optically thin, white, isotropic medium of albedo 1 returns the
   * emission-absorption colour. Default 1.
   */
  vtkSetClampMacro(LightScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Largest dimension per axis of the grid of the light volumes and the averaged extinction
   * (the data's size, capped, keeping the aspect ratio). Default 128: both vary on the scale of
   * the ambient radius, and on the 256^3 demo nebula a cap of 128 renders within 59 dB PSNR of
   * 256 (largest difference 5/255) while a transfer-function change rebuilds several times
   * faster.
   */
  vtkSetClampMacro(LightVolumeMaximumDimension, int, 2, 4096);
  vtkGetMacro(LightVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * Largest dimension per axis of the extended model's diffusion grid (the light grid, capped,
   * keeping the aspect ratio; ARCHITECTURE.md, "Beyond the paper"). Default 64: the diffuse
   * fluence varies on the scale of the transport mean free path, and the solve's cost grows with
   * the cube of this. The rays read the fluence interpolated onto the light grid. Only the
   * extended model uses it.
   */
  vtkSetClampMacro(DiffusionVolumeMaximumDimension, int, 2, 1024);
  vtkGetMacro(DiffusionVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * The model of ambient scattering. ExtendedModel (1, the default): the paper's model plus
   * long-range multiple scattering, the diffuse fluence of a diffusion solve on a coarse grid
   * sourced by the light the tubes deliver (ARCHITECTURE.md, "Beyond the paper"); closer to the
   * path tracer than the paper's model on every scene of the accuracy study (Documentation/
   * Accuracy.md), brighter in thick clouds lit from the side, the same in optically thin
   * media. Its fluence comes with the averaged extinction in one texture fetch per sample (with 4
   * or 8 lights no fetch beyond the paper's model's, with 1-3 or 5-7 one), and it costs the solve
   * at each light-volume rebuild. PaperModel (0): Ament et al. 2013 as this project implements it
   * (ALGORITHM.md sections 3-6).
   */
  enum
  {
    PaperModel = 0,
    ExtendedModel = 1
  };
  vtkSetClampMacro(ScatteringModel, int, PaperModel, ExtendedModel);
  vtkGetMacro(ScatteringModel, int);
  void SetScatteringModelToPaper() { this->SetScatteringModel(PaperModel); }
  void SetScatteringModelToExtended() { this->SetScatteringModel(ExtendedModel); }
  const char* GetScatteringModelAsString()
  {
    return this->ScatteringModel == ExtendedModel ? "Extended" : "Paper";
  }
  ///@}

  ///@{
  /**
   * Surfaces inside the medium, vtkGPUVolumeRayCastMapper's setting with the same meaning
   * (0-2, considered only with the property's ShadeOn; Documentation/VTKSettings.md says where
   * ours differs). With ShadeOn a scattering event where the normalised gradient is strong
   * reflects the light that reaches it like a surface: the property's ambient, diffuse and
   * specular coefficients and specular power made an energy-conserving BRDF, the gradient its
   * normal, lit by the same shadowed, scattered light as the medium (Rendering/Core/
   * SurfaceShading.h defines every term). 0 (the default, as in VTK): the share of surface
   * events grows with the gradient alone, VTK's shaded structure with this mapper's shadows and
   * glow; towards 1 it needs opacity as well (VTK's blend by opacity and gradient); 2: pure
   * volume scattering, the picture ShadeOff gives. ShadeOff gives the unshaded picture whatever
   * this value.
   */
  vtkSetClampMacro(VolumetricScatteringBlending, float, 0.0f, 2.0f);
  vtkGetMacro(VolumetricScatteringBlending, float);
  ///@}

  /**
   * The default Exposure of this mapper; its ToneMapping defaults to ShoulderToneMapping and
   * AutoExposure to off (the display transform: vtkAVSVolumeMapper::SetExposure). Measured by the
   * swap test (Testing/Python/TestSwapMapper.py): with the lights of an ordinary VTK scene (the
   * automatic headlight, a vtkLightKit, lights of intensity 1) this picture is 0.83-1.28 times as
   * bright as vtkGPUVolumeRayCastMapper's with ShadeOn, on seven volumes, with ShadeOn
   * (0.62-1.12 with ShadeOff), and nothing saturates; linear radiance (exposure 1, clamp) is
   * 1.4-2.3 times as bright and clips.
   */
  static constexpr double DefaultExposure = 0.5;

  ///@{
  /**
   * Path-traced refinement: while the view rests, every still frame (one after which nothing
   * changed: camera, viewport, lights, the volume's matrix, property, data, mask, clipping,
   * cropping, this mapper's parameters, the other 3D props) adds one sample per pixel of an
   * unbiased GPU path tracer of exactly the medium this mapper draws (delta and ratio tracking
   * over a grid of majorants, next-event estimation towards every light with VTK's attenuation
   * and cones, Henyey–Greenstein scattering, clipping, cropping, masks, components, NaN voxels
   * and the depth of opaque geometry), and shows the ambient-scattering picture moved towards the
   * path tracer's running mean by the weight that minimises the expected error (bias against
   * variance, measured per pixel over a 5 x 5 window; Rendering/Core/Refinement.h): never noisier
   * than the ambient-scattering picture, and converging to the path-traced truth. Any change
   * restarts from the ambient-scattering picture; a new exposure or tone curve does not. The
   * interactor's reduced frames (less than a second allotted, or an image sample distance other
   * than 1) never path-trace. Call Render() again (a timer, an idle loop) to refine; the
   * refinement stops at MaximumSamplesPerPixel. Not done for a piece of a distributed image or a
   * volume split into bricks (a warning says so). Default off.
   */
  vtkSetMacro(PathTracedRefinement, vtkTypeBool);
  vtkGetMacro(PathTracedRefinement, vtkTypeBool);
  vtkBooleanMacro(PathTracedRefinement, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Samples per pixel at which the path-traced refinement stops adding (GetSamplesPerPixel says
   * how many it has). Default 1024.
   */
  vtkSetClampMacro(MaximumSamplesPerPixel, int, 1, 1 << 20);
  vtkGetMacro(MaximumSamplesPerPixel, int);
  ///@}

  ///@{
  /**
   * The scattering table file. Default: empty, the table shipped with the module.
   */
  vtkSetStringMacro(ScatteringTableFileName);
  vtkGetStringMacro(ScatteringTableFileName);
  ///@}

  ///@{
  /**
   * Whether the last light volumes were computed on the GPU, and how often the averaged
   * extinction, a light volume (one count per light) and the extended model's diffusion were
   * rebuilt.
   */
  vtkTypeBool GetLightVolumesOnGPU() override;
  int GetNumberOfExtinctionRebuilds() override;
  int GetNumberOfLightVolumeRebuilds() override;
  int GetNumberOfDiffusionRebuilds() override;
  ///@}

protected:
  vtkAmbientScatteringVolumeMapper();
  ~vtkAmbientScatteringVolumeMapper() override;
  int GetEffect() const override { return 2; }
  void FillParameters(avs::ScatteringParameters& parameters) override;
  bool PrepareLighting(const vtkAVSPrecomputeInputs& inputs) override;
  void InvalidateLighting() override;
  void GetPrecomputedGrids(std::array<int, 3>& lightGrid,
    std::array<int, 3>& occlusionGrid) const override;
  /// The loaded scattering table, or nullptr after reporting an error.
  const avs::ScatteringTable* GetScatteringTable();

  double AmbientRadius = 0.0;
  double Anisotropy = 0.0;
  double Albedo = 0.8;
  double EmissionWeight = 0.0;
  double LightScale = 1.0;
  int LightVolumeMaximumDimension = 128;
  int DiffusionVolumeMaximumDimension = 64;
  char* ScatteringTableFileName = nullptr;
  int ScatteringModel = ExtendedModel;
  float VolumetricScatteringBlending = 0.0f;
  vtkAmbientScatteringTable* Table;

private:
  vtkAmbientScatteringVolumeMapper(const vtkAmbientScatteringVolumeMapper&) = delete;
  void operator=(const vtkAmbientScatteringVolumeMapper&) = delete;

  std::unique_ptr<vtkAVSScatteringVolumes> Volumes; ///< the precomputed volumes' owner
};

#endif
