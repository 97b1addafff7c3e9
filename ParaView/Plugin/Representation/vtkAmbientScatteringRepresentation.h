/**
 * @class   vtkAmbientScatteringRepresentation
 * @brief   ParaView's volume representation of image data, rendered by this project's mappers
 *
 * The "Ambient Scattering" entry of ParaView's Representation menu for image data. It is
 * vtkImageVolumeRepresentation (data delivery, ghost cells, outline on ranks without data, the
 * colour map and opacity function of the vtkVolumeProperty, scalar array selection, cropping,
 * blend mode) with the volume mapper replaced by one of the project's three, chosen by
 * LightingModel: vtkEmissionAbsorptionVolumeMapper, vtkAmbientOcclusionVolumeMapper or
 * vtkAmbientScatteringVolumeMapper (the default). The mappers read the renderer's lights
 * (ParaView's light kit, headlight and the lights of the Lights panel) and camera as in any VTK
 * renderer.
 *
 * The medium parameters are forwarded to the mappers that have them: Albedo and
 * ScatteringAnisotropy to ambient scattering; AmbientRadius, EmissionWeight, LightScale and
 * LightVolumeMaximumDimension to ambient scattering and to ambient occlusion (as its
 * OcclusionRadius, EmissionWeight, LightScale and OcclusionVolumeMaximumDimension).
 *
 * ParaView's own Shade, Ambient, Diffuse, Specular and SpecularPower set the vtkVolumeProperty,
 * with which ambient scattering shades surfaces inside the medium; its Volumetric Scattering
 * Blending (SetVolumetricScatteringBlending) reaches the ambient-scattering mapper too.
 *
 * Composite inputs (vtkMultiBlockDataSet, vtkPartitionedDataSet, vtkPartitionedDataSetCollection
 * of image blocks: several pieces per rank) reach the mappers as a vtkPartitionedDataSet of the
 * rank's leaves, which they draw as the one image the leaves make (vtkAVSVolumeMapper). Under MPI
 * the whole extent is then the union of every rank's blocks' extents (their extents must place
 * them in one index space, as ParaView's readers and filters give them).
 */
#ifndef vtkAmbientScatteringRepresentation_h
#define vtkAmbientScatteringRepresentation_h

#include "vtkImageVolumeRepresentation.h"
#include "vtkNew.h"                       // for vtkNew
#include "vtkPVAmbientScatteringModule.h" // for export macro

#include <array> // for std::array

class vtkAVSVolumeMapper;
class vtkAmbientOcclusionVolumeMapper;
class vtkAmbientScatteringVolumeMapper;
class vtkEmissionAbsorptionVolumeMapper;

class VTKPVAMBIENTSCATTERING_EXPORT vtkAmbientScatteringRepresentation
  : public vtkImageVolumeRepresentation
{
public:
  static vtkAmbientScatteringRepresentation* New();
  vtkTypeMacro(vtkAmbientScatteringRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum LightingModels
  {
    EmissionAbsorption = 0,
    AmbientOcclusion = 1,
    AmbientScattering = 2
  };

  ///@{
  /**
   * The lighting model, that is the mapper: EmissionAbsorption (0, no lights), AmbientOcclusion
   * (1, local ambient occlusion) or AmbientScattering (2, lights with soft shadows and multiple
   * scattering). Default AmbientScattering. Cropping and the blend mode move with the switch.
   */
  void SetLightingModel(int model);
  vtkGetMacro(LightingModel, int);
  ///@}

  ///@{
  /**
   * Scattering albedo in [0, 1] (ambient scattering). Default 0.8.
   */
  void SetAlbedo(double albedo);
  double GetAlbedo();
  ///@}

  ///@{
  /**
   * The display transform of ambient scattering (vtkAVSVolumeMapper::SetExposure,
   * SetToneMapping, SetAutoExposure): the exposure factor (default 0.5), the tone curve (0 clamp,
   * 1 the shoulder, the default) and auto exposure from the light the volume receives (default
   * off). The emission-absorption and ambient-occlusion models keep the identity.
   */
  void SetExposure(double exposure);
  double GetExposure();
  void SetToneMapping(int curve);
  int GetToneMapping();
  void SetAutoExposure(int on);
  int GetAutoExposure();
  ///@}

  ///@{
  /**
   * ParaView's VolumetricScatteringBlending property: the superclass's (for its own mapper) and
   * vtkAmbientScatteringVolumeMapper::SetVolumetricScatteringBlending (0-2, default 0, with
   * Shade: surfaces inside the medium).
   */
  void SetVolumetricScatteringBlending(float blending);
  float GetVolumetricScatteringBlending();
  ///@}

  ///@{
  /**
   * Henyey–Greenstein anisotropy g in [-0.95, 0.95]; > 0 scatters forwards (ambient scattering).
   * Default 0. (ParaView's own VolumeAnisotropy sets the vtkVolumeProperty's, which these mappers
   * do not read.)
   */
  void SetScatteringAnisotropy(double g);
  double GetScatteringAnisotropy();
  ///@}

  ///@{
  /**
   * Ambient radius in data units (ambient scattering) and occlusion radius (ambient occlusion).
   * Default 0: automatic, 1/64 of the volume's diagonal, at least the smallest voxel spacing and at
   * most half the volume's smallest side.
   */
  void SetAmbientRadius(double radius);
  double GetAmbientRadius();
  ///@}

  ///@{
  /**
   * Multiplies the irradiance of every light for this volume (>= 0; VTK light units, a light of
   * intensity 1 gives the irradiance 4 pi). Default 1.
   */
  void SetLightScale(double scale);
  double GetLightScale();
  ///@}

  ///@{
  /**
   * Emission weight k_e >= 0: the medium also glows with k_e times its colour. Default 0.
   */
  void SetEmissionWeight(double weight);
  double GetEmissionWeight();
  ///@}

  ///@{
  /**
   * Largest dimension per axis (2 to 4096) of the light volumes and the averaged extinction
   * (ambient scattering) and of the occlusion volume (ambient occlusion). Default 128.
   */
  void SetLightVolumeMaximumDimension(int dimension);
  int GetLightVolumeMaximumDimension();
  ///@}

  ///@{
  /**
   * The model of ambient scattering (vtkAmbientScatteringVolumeMapper::SetScatteringModel):
   * 1, the extended model with long-range multiple scattering (the default); 0, the paper's.
   */
  void SetScatteringModel(int model);
  int GetScatteringModel();
  ///@}

  ///@{
  /**
   * Path-traced refinement (vtkAmbientScatteringVolumeMapper::SetPathTracedRefinement): while
   * the view rests, every still render adds a path-traced sample per pixel, up to
   * MaximumSamplesPerPixel, and the picture converges to the path tracer's. Off by default.
   */
  void SetPathTracedRefinement(int on);
  int GetPathTracedRefinement();
  void SetMaximumSamplesPerPixel(int samples);
  int GetMaximumSamplesPerPixel();
  /// Samples per pixel of the ambient-scattering mapper's refinement so far.
  int GetSamplesPerPixel();
  ///@}

  ///@{
  /**
   * Largest dimension per axis (2 to 1024) of the extended model's diffusion grid
   * (vtkAmbientScatteringVolumeMapper::SetDiffusionVolumeMaximumDimension). Default 64.
   */
  void SetDiffusionVolumeMaximumDimension(int dimension);
  int GetDiffusionVolumeMaximumDimension();
  ///@}

  ///@{
  /**
   * Ray-marching step in data units for the three mappers. Default 0: half the smallest voxel
   * spacing.
   */
  void SetSampleDistance(double distance);
  double GetSampleDistance();
  ///@}

  ///@{
  /**
   * Jitter the rays' start (hides wood-grain artefacts; off gives the same picture at each
   * render). Default on.
   */
  void SetUseJittering(int jitter);
  int GetUseJittering();
  ///@}

  ///@{
  /**
   * The budget of the volume's GPU textures in MiB, for the three mappers
   * (vtkAVSVolumeMapper::SetMaximumGPUMemory). Default 0: what the context reports.
   */
  void SetMaximumGPUMemory(int mebibytes);
  int GetMaximumGPUMemory();
  ///@}

  ///@{
  /**
   * Under MPI (more than one process in vtkMultiProcessController::GetGlobalController()): on
   * (the default), the mappers light each rank's piece as a part of the whole image (their
   * WholeExtent and Controller; vtkAVSVolumeMapper), so light and shadows cross the pieces'
   * boundaries; off, each rank lights its piece alone. The ranks share the light in the render
   * request (ProcessViewRequest), which every rank receives before its renderer culls anything.
   */
  vtkSetMacro(LightAcrossRanks, vtkTypeBool);
  vtkGetMacro(LightAcrossRanks, vtkTypeBool);
  vtkBooleanMacro(LightAcrossRanks, vtkTypeBool);
  ///@}

  /**
   * The superclass's, and in the render request, on every rank whether its piece is visible or
   * not, the collective update of the light shared across the ranks
   * (vtkAVSVolumeMapper::UpdatePieceLighting), so that rendering never waits for a rank whose
   * piece is culled or empty.
   */
  int ProcessViewRequest(vtkInformationRequestKey* request,
    vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  /**
   * The mapper of the current lighting model.
   */
  vtkVolumeMapper* GetActiveVolumeMapper();

protected:
  vtkAmbientScatteringRepresentation();
  ~vtkAmbientScatteringRepresentation() override;

  /// Composite inputs (any vtkDataObjectTree): a vtkPartitionedDataSet of the leaves for the
  /// mappers (the superclass gives those to vtkMultiBlockVolumeMapper only, without the leaves
  /// that are not images); the rest is the superclass's.
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::array<vtkAVSVolumeMapper*, 3> Mappers();
  /// The superclass's, then the whole extent and the controller of distributed lighting.
  void UpdateMapperParameters() override;
  /// The mappers' WholeExtent and Controller: the pipeline's whole extent (for a composite
  /// input, the ranks' blocks' union, CompositeWholeExtent) and the global controller under MPI
  /// with LightAcrossRanks on, none otherwise.
  void ShareLightAcrossRanks();
  /// Under MPI with LightAcrossRanks on, in the render request: the union of the ranks'
  /// BlocksExtent (a collective of every rank; empty where no rank has a composite input).
  void UniteBlockExtents();

  vtkTypeBool LightAcrossRanks = 1;
  /// A composite input's blocks' extent on this rank (RequestData; empty: none) and the union
  /// over the ranks (UniteBlockExtents).
  int BlocksExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int CompositeWholeExtent[6] = { 0, -1, 0, -1, 0, -1 };

  int LightingModel = AmbientScattering;
  vtkNew<vtkEmissionAbsorptionVolumeMapper> EmissionAbsorptionMapper;
  vtkNew<vtkAmbientOcclusionVolumeMapper> AmbientOcclusionMapper;
  vtkNew<vtkAmbientScatteringVolumeMapper> AmbientScatteringMapper;

private:
  vtkAmbientScatteringRepresentation(const vtkAmbientScatteringRepresentation&) = delete;
  void operator=(const vtkAmbientScatteringRepresentation&) = delete;
};

#endif
