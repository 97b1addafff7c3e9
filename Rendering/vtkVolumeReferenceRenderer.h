/**
 * @class   vtkVolumeReferenceRenderer
 * @brief   renders image data with the CPU reference ray caster into an image
 *
 * An image algorithm: its input is the volume (vtkImageData with point or cell scalars of any
 * type, the array selected as on the mappers; or a vtkMultiBlockDataSet, vtkPartitionedDataSet or
 * vtkPartitionedDataSetCollection of image blocks of one grid, merged into the image they make as
 * the mappers merge them), its output a picture of it as a renderer's camera
 * and lights see it. It runs the project's double-precision reference ray caster (ALGORITHM.md
 * sections 2-7): emission–absorption, volumetric ambient occlusion or ambient volume scattering; or
 * it path-traces the same scene without approximation (PATH_TRACING). The GPU mappers are measured
 * against it; it is also the renderer of `./avs demo` where no GPU mapper
 * is wanted.
 *
 * The output has ImageSize pixels, 3-component unsigned char scalars "RGB" (the volume
 * composited over Background) and a 4-component float array "Radiance" (premultiplied radiance
 * and alpha = 1 - transmittance) and "RadianceSecondMoment", the mean of the squares of the
 * samples (alpha: of the 0/1 hits), from which the estimate's variance follows: for path tracing
 * the samples', for the deterministic modes the square of "Radiance" (no variance). Every mode
 * gives the same arrays, so outputs of different modes append side by side (vtkImageAppend).
 *
 * Clipping planes and cropping (as a vtkVolumeMapper's) remove material for every purpose.
 * NaN voxels are empty space, infinities are clamped (one warning counts them).
 *
 * Bad input (no or empty image, no such array, more than four components, three dependent
 * components, bad spacing, no volume property, a missing or corrupt scattering table, more
 * than 8 or degenerate clipping planes) gives a vtkErrorMacro
 * and an empty output. Progress events are fired during the precomputation and the rendering.
 */
#ifndef vtkVolumeReferenceRenderer_h
#define vtkVolumeReferenceRenderer_h

#include "vtkImageAlgorithm.h"
#include "vtkRenderingAmbientScatteringModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkAmbientScatteringTable;
class vtkImageData;
namespace avs
{
struct DisplayTransform;
struct Image;
struct VolumeScene;
struct Vec3;
}
class vtkCamera;
class vtkPlaneCollection;
class vtkRenderer;
class vtkVolumeProperty;

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkVolumeReferenceRenderer : public vtkImageAlgorithm
{
public:
  static vtkVolumeReferenceRenderer* New();
  vtkTypeMacro(vtkVolumeReferenceRenderer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RenderModes
  {
    EMISSION_ABSORPTION = 0,
    AMBIENT_OCCLUSION = 1,
    AMBIENT_SCATTERING = 2,
    PATH_TRACING = 3
  };

  ///@{
  /**
   * What to render. Default: AMBIENT_SCATTERING. PATH_TRACING solves the full radiative
   * transfer of the same medium (albedo, anisotropy, emission weight, lights) with the unbiased
   * path tracer: the ground truth the other models are measured against.
   */
  vtkSetClampMacro(RenderMode, int, EMISSION_ABSORPTION, PATH_TRACING);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToEmissionAbsorption() { this->SetRenderMode(EMISSION_ABSORPTION); }
  void SetRenderModeToAmbientOcclusion() { this->SetRenderMode(AMBIENT_OCCLUSION); }
  void SetRenderModeToAmbientScattering() { this->SetRenderMode(AMBIENT_SCATTERING); }
  void SetRenderModeToPathTracing() { this->SetRenderMode(PATH_TRACING); }
  const char* GetRenderModeAsString();
  ///@}

  ///@{
  /**
   * The volume's property: colour and scalar-opacity functions of component 0 and the scalar
   * opacity unit distance. Required.
   */
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);
  ///@}

  ///@{
  /**
   * Which array of the input to render, as vtkAbstractVolumeMapper selects it (the same calls as
   * on the mappers): ScalarMode VTK_SCALAR_MODE_DEFAULT (default: point scalars, else cell
   * scalars), _USE_POINT_DATA, _USE_CELL_DATA, _USE_POINT_FIELD_DATA or _USE_CELL_FIELD_DATA;
   * the last two take the array chosen with SelectScalarArray (by index: ArrayAccessMode
   * VTK_GET_ARRAY_BY_ID, default; by name: VTK_GET_ARRAY_BY_NAME). Cell data is rendered as
   * VTK's mapper renders it: the cell values sit at the cell centres, and the volume spans the
   * points.
   */
  vtkSetMacro(ScalarMode, int);
  vtkGetMacro(ScalarMode, int);
  void SetScalarModeToDefault() { this->SetScalarMode(0); }
  void SetScalarModeToUsePointData() { this->SetScalarMode(1); }
  void SetScalarModeToUseCellData() { this->SetScalarMode(2); }
  void SetScalarModeToUsePointFieldData() { this->SetScalarMode(3); }
  void SetScalarModeToUseCellFieldData() { this->SetScalarMode(4); }
  vtkSetMacro(ArrayAccessMode, int);
  vtkGetMacro(ArrayAccessMode, int);
  void SelectScalarArray(int arrayNum);
  void SelectScalarArray(const char* arrayName);
  vtkGetMacro(ArrayId, int);
  const char* GetArrayName() { return this->ArrayName.c_str(); }
  ///@}

  ///@{
  /**
   * A mask, as on the mappers (vtkAVSVolumeMapper::SetMaskInput): binary or label map
   * (default, as in VTK), with MaskBlendFactor (default 1). Default: no mask.
   */
  void SetMaskInput(vtkImageData* mask);
  vtkGetObjectMacro(MaskInput, vtkImageData);
  vtkSetClampMacro(MaskType, int, 0, 1);
  vtkGetMacro(MaskType, int);
  void SetMaskTypeToBinary() { this->SetMaskType(0); }
  void SetMaskTypeToLabelMap() { this->SetMaskType(1); }
  vtkSetClampMacro(MaskBlendFactor, float, 0.0f, 1.0f);
  vtkGetMacro(MaskBlendFactor, float);
  ///@}

  ///@{
  /**
   * The renderer whose lights light the volume and whose active camera looks at it, unless
   * Camera is set. Without a renderer the camera's headlight is used.
   */
  void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  ///@{
  /**
   * The camera; default: the renderer's active camera.
   */
  void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * The scattering table; default: the shipped table, loaded on first use.
   */
  void SetScatteringTable(vtkAmbientScatteringTable* table);
  vtkGetObjectMacro(ScatteringTable, vtkAmbientScatteringTable);
  ///@}

  ///@{
  /**
   * Output size in pixels. Default: 256 x 256.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  ///@{
  /**
   * Colour behind the volume in the "RGB" output. Default: black.
   */
  vtkSetVector3Macro(Background, double);
  vtkGetVector3Macro(Background, double);
  ///@}

  ///@{
  /**
   * The display transform of the "RGB" output, as the mappers apply it
   * (vtkAVSVolumeMapper::SetExposure, SetToneMapping, SetAutoExposure): the premultiplied
   * radiance times the exposure, through the tone curve, then composited over Background. The
   * "Radiance" array stays linear. Exposure 0 and ToneMapping AutomaticToneMapping (the
   * defaults) take the defaults of the render mode's mapper: exposure 1 and clamp for
   * emission-absorption and ambient occlusion, vtkAmbientScatteringVolumeMapper's (exposure
   * vtkAmbientScatteringVolumeMapper::DefaultExposure, the shoulder) for ambient scattering and
   * path tracing, so that each mode's picture is its mapper's. AutoExposure (default off)
   * multiplies the exposure by the lights' metered factor over the input's box in ambient
   * scattering and path tracing. GetResolvedExposure and GetResolvedToneMapping say what the
   * last render applied.
   */
  vtkSetClampMacro(Exposure, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Exposure, double);
  enum ToneMappings
  {
    AutomaticToneMapping = -1,
    ClampToneMapping = 0,
    ShoulderToneMapping = 1
  };
  vtkSetClampMacro(ToneMapping, int, AutomaticToneMapping, ShoulderToneMapping);
  vtkGetMacro(ToneMapping, int);
  void SetToneMappingToAutomatic() { this->SetToneMapping(AutomaticToneMapping); }
  void SetToneMappingToClamp() { this->SetToneMapping(ClampToneMapping); }
  void SetToneMappingToShoulder() { this->SetToneMapping(ShoulderToneMapping); }
  vtkSetClampMacro(AutoExposure, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoExposure, vtkTypeBool);
  vtkBooleanMacro(AutoExposure, vtkTypeBool);
  vtkGetMacro(ResolvedExposure, double);
  vtkGetMacro(ResolvedToneMapping, int);
  ///@}

  ///@{
  /**
   * Scattering albedo Lambda in [0, 1]. Default 0.8.
   */
  vtkSetClampMacro(Albedo, double, 0.0, 1.0);
  vtkGetMacro(Albedo, double);
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
   * Surfaces inside the medium (ambient scattering and the path tracer), as
   * vtkAmbientScatteringVolumeMapper::SetVolumetricScatteringBlending: with the property's
   * ShadeOn, 0 (the default) to 2 (pure volume scattering). The renderer's TwoSidedLighting
   * says whether surfaces reflect on both sides (on without a renderer).
   */
  vtkSetClampMacro(VolumetricScatteringBlending, float, 0.0f, 2.0f);
  vtkGetMacro(VolumetricScatteringBlending, float);
  ///@}

  ///@{
  /**
   * Henyey–Greenstein anisotropy g in [-0.95, 0.95]. Default 0.
   */
  vtkSetClampMacro(Anisotropy, double, -0.95, 0.95);
  vtkGetMacro(Anisotropy, double);
  ///@}

  ///@{
  /**
   * Ambient radius r in world units. Default 0: automatic, 1/64 of the volume's diagonal but at
   * least the smallest voxel spacing.
   */
  vtkSetClampMacro(AmbientRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AmbientRadius, double);
  ///@}

  ///@{
  /**
   * Emission weight k_e >= 0 (emitted radiance k_e times the colour). Default 0.
   */
  vtkSetClampMacro(EmissionWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EmissionWeight, double);
  ///@}

  ///@{
  /**
   * Ambient-occlusion radius R in world units. Default 0: the ambient radius.
   */
  vtkSetClampMacro(OcclusionRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(OcclusionRadius, double);
  ///@}

  ///@{
  /**
   * Ambient-occlusion directions K, at least 14. Default 32.
   */
  vtkSetClampMacro(NumberOfDirections, int, 14, 1024);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /**
   * Ambient-occlusion weight k_amb >= 0. Default 1.
   */
  vtkSetClampMacro(AmbientWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AmbientWeight, double);
  ///@}

  ///@{
  /**
   * Weight of the unshadowed direct light added by the AO renderer. Default 0.
   */
  vtkSetClampMacro(DirectLightWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DirectLightWeight, double);
  ///@}

  ///@{
  /**
   * Multiplies the irradiance of every light (>= 0). Lights are in VTK's units: a vtkLight of
   * intensity I and colour c gives the irradiance 4 pi I c. Default 1.
   */
  vtkSetClampMacro(LightScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Ray-marching step in world units. Default 0: half the smallest voxel spacing.
   */
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /**
   * Early ray termination: rays stop when their transmittance falls below this. Default 1/255.
   */
  vtkSetClampMacro(TerminationTransmittance, double, 0.0, 1.0);
  vtkGetMacro(TerminationTransmittance, double);
  ///@}

  ///@{
  /**
   * Largest light-volume dimension per axis (the data's dimensions, capped). Default 128.
   */
  vtkSetClampMacro(LightVolumeMaximumDimension, int, 2, 4096);
  vtkGetMacro(LightVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * Largest dimension per axis of the extended model's diffusion grid (the light grid, capped).
   * Default 64, as on vtkAmbientScatteringVolumeMapper.
   */
  vtkSetClampMacro(DiffusionVolumeMaximumDimension, int, 2, 1024);
  vtkGetMacro(DiffusionVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * Largest occlusion-volume dimension per axis (the data's dimensions, capped). Default 128.
   */
  vtkSetClampMacro(OcclusionVolumeMaximumDimension, int, 2, 4096);
  vtkGetMacro(OcclusionVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * Path tracing: samples per pixel (default 64) and the random seed (default 1; the same seed
   * gives the same picture).
   */
  vtkSetClampMacro(SamplesPerPixel, int, 1, 1 << 20);
  vtkGetMacro(SamplesPerPixel, int);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Clipping planes in world coordinates (the volume is not transformed here: world = data), as
   * vtkAbstractMapper::ClippingPlanes: material where dot(normal, x - origin) < 0 for a plane is
   * absent for every purpose (rays, averaged extinction, light volumes, AO, path tracer). At
   * most 8. Default none.
   */
  void SetClippingPlanes(vtkPlaneCollection* planes);
  vtkGetObjectMacro(ClippingPlanes, vtkPlaneCollection);
  ///@}

  ///@{
  /**
   * Cropping as vtkVolumeMapper's: region planes (xmin, xmax, ymin, ymax, zmin, zmax) in data
   * coordinates, origin + index x spacing along the image's axes, and the 27 region flags
   * (vtkVolumeMapper's presets, the same values as VTK_CROP_SUBVOLUME and so on). Default off,
   * sub-volume.
   */
  vtkSetMacro(Cropping, vtkTypeBool);
  vtkGetMacro(Cropping, vtkTypeBool);
  vtkBooleanMacro(Cropping, vtkTypeBool);
  vtkSetVector6Macro(CroppingRegionPlanes, double);
  vtkGetVector6Macro(CroppingRegionPlanes, double);
  vtkSetClampMacro(CroppingRegionFlags, int, 0x0, 0x7ffffff);
  vtkGetMacro(CroppingRegionFlags, int);
  void SetCroppingRegionFlagsToSubVolume() { this->SetCroppingRegionFlags(0x0002000); }
  void SetCroppingRegionFlagsToFence() { this->SetCroppingRegionFlags(0x2ebfeba); }
  void SetCroppingRegionFlagsToInvertedFence() { this->SetCroppingRegionFlags(0x5140145); }
  void SetCroppingRegionFlagsToCross() { this->SetCroppingRegionFlags(0x0417410); }
  void SetCroppingRegionFlagsToInvertedCross() { this->SetCroppingRegionFlags(0x7be8bef); }
  ///@}

  /**
   * Includes the property's, the camera's, the renderer's, the lights' and the clipping
   * planes' modification times.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkVolumeReferenceRenderer();
  ~vtkVolumeReferenceRenderer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int RenderMode = AMBIENT_SCATTERING;
  int ScalarMode = 0;      // VTK_SCALAR_MODE_DEFAULT
  int ArrayAccessMode = 0; // VTK_GET_ARRAY_BY_ID
  int ArrayId = -1;
  std::string ArrayName;
  vtkImageData* MaskInput = nullptr;
  int MaskType = 1; // label map, as vtkGPUVolumeRayCastMapper
  float MaskBlendFactor = 1.0f;
  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkCamera* Camera = nullptr;
  vtkAmbientScatteringTable* ScatteringTable = nullptr;
  int ImageSize[2] = { 256, 256 };
  double Background[3] = { 0.0, 0.0, 0.0 };
  double Exposure = 0.0;
  int ToneMapping = AutomaticToneMapping;
  vtkTypeBool AutoExposure = 0;
  double ResolvedExposure = 0.0;
  int ResolvedToneMapping = ClampToneMapping;
  double Albedo = 0.8;
  double Anisotropy = 0.0;
  float VolumetricScatteringBlending = 0.0f;
  int ScatteringModel = ExtendedModel;
  double AmbientRadius = 0.0;
  double EmissionWeight = 0.0;
  double OcclusionRadius = 0.0;
  int NumberOfDirections = 32;
  double AmbientWeight = 1.0;
  double DirectLightWeight = 0.0;
  double LightScale = 1.0;
  double SampleDistance = 0.0;
  double TerminationTransmittance = 1.0 / 255.0;
  int LightVolumeMaximumDimension = 128;
  int DiffusionVolumeMaximumDimension = 64;
  int OcclusionVolumeMaximumDimension = 128;
  int SamplesPerPixel = 64;
  int Seed = 1;
  vtkPlaneCollection* ClippingPlanes = nullptr;
  vtkTypeBool Cropping = 0;
  double CroppingRegionPlanes[6] = { 0, 1, 0, 1, 0, 1 };
  int CroppingRegionFlags = 0x0002000;

private:
  /// The output's arrays, the same in every mode: "RGB", "Radiance" and
  /// "RadianceSecondMoment" (`squares`: the path tracer's; null: the deterministic modes',
  /// the squares of the radiance).
  void WriteOutput(vtkImageData* output,
    const avs::Image& image,
    const avs::Image* squares,
    const avs::Vec3& background,
    const avs::DisplayTransform& display);
  /// The display transform of this render: the mode's defaults where automatic, the metered
  /// exposure with AutoExposure (ResolvedExposure, ResolvedToneMapping).
  avs::DisplayTransform ResolveDisplay(const avs::VolumeScene& scene);
  vtkVolumeReferenceRenderer(const vtkVolumeReferenceRenderer&) = delete;
  void operator=(const vtkVolumeReferenceRenderer&) = delete;
};

#endif
