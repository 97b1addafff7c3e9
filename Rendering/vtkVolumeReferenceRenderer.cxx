#include "vtkVolumeReferenceRenderer.h"

#include "DisplayTransform.h"
#include "PathTracer.h"
#include "ReferenceRenderer.h"
#include "vtkAVSClipTranslator.h"
#include "vtkAVSCompositeInput.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSPropertyTranslator.h"
#include "vtkAVSSceneTranslator.h"
#include "vtkAmbientScatteringTable.h"
#include "vtkAmbientScatteringVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkVolumeReferenceRenderer);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, Renderer, vtkRenderer);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, ScatteringTable, vtkAmbientScatteringTable);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, ClippingPlanes, vtkPlaneCollection);
vtkCxxSetObjectMacro(vtkVolumeReferenceRenderer, MaskInput, vtkImageData);

vtkVolumeReferenceRenderer::vtkVolumeReferenceRenderer()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkVolumeReferenceRenderer::~vtkVolumeReferenceRenderer()
{
  this->SetVolumeProperty(nullptr);
  this->SetRenderer(nullptr);
  this->SetCamera(nullptr);
  this->SetScatteringTable(nullptr);
  this->SetClippingPlanes(nullptr);
  this->SetMaskInput(nullptr);
}

void vtkVolumeReferenceRenderer::SelectScalarArray(int arrayNum)
{
  if (this->ArrayId == arrayNum && this->ArrayAccessMode == 0)
  {
    return;
  }
  this->ArrayId = arrayNum;
  this->ArrayAccessMode = 0; // VTK_GET_ARRAY_BY_ID
  this->Modified();
}

void vtkVolumeReferenceRenderer::SelectScalarArray(const char* arrayName)
{
  if (!arrayName || (this->ArrayName == arrayName && this->ArrayAccessMode == 1))
  {
    return;
  }
  this->ArrayName = arrayName;
  this->ArrayAccessMode = 1; // VTK_GET_ARRAY_BY_NAME
  this->Modified();
}

const char* vtkVolumeReferenceRenderer::GetRenderModeAsString()
{
  switch (this->RenderMode)
  {
    case EMISSION_ABSORPTION:
      return "EmissionAbsorption";
    case AMBIENT_OCCLUSION:
      return "AmbientOcclusion";
    case PATH_TRACING:
      return "PathTracing";
    default:
      return "AmbientScattering";
  }
}

vtkMTimeType vtkVolumeReferenceRenderer::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->VolumeProperty)
  {
    t = std::max(t, this->VolumeProperty->GetMTime());
  }
  if (this->Camera)
  {
    t = std::max(t, this->Camera->GetMTime());
  }
  if (this->ScatteringTable)
  {
    t = std::max(t, this->ScatteringTable->GetMTime());
  }
  if (this->ClippingPlanes)
  {
    t = std::max(t, this->ClippingPlanes->GetMTime());
    vtkCollectionSimpleIterator it;
    this->ClippingPlanes->InitTraversal(it);
    while (vtkPlane* plane = this->ClippingPlanes->GetNextPlane(it))
    {
      t = std::max(t, plane->GetMTime());
    }
  }
  if (this->MaskInput)
  {
    t = std::max(t, this->MaskInput->GetMTime());
  }
  if (this->Renderer)
  {
    t = std::max(t, this->Renderer->GetMTime());
    if (vtkCamera* active = this->Renderer->GetActiveCamera())
    {
      t = std::max(t, active->GetMTime());
    }
    vtkLightCollection* lights = this->Renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* l = lights->GetNextLight(it))
    {
      t = std::max(t, l->GetMTime());
    }
  }
  return t;
}

int vtkVolumeReferenceRenderer::FillInputPortInformation(int, vtkInformation* info)
{
  // An image, or a tree of image blocks as the mappers take it (vtkAVSCompositeInput).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObjectTree");
  return 1;
}

int vtkVolumeReferenceRenderer::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int w = std::max(1, this->ImageSize[0]);
  const int h = std::max(1, this->ImageSize[1]);
  int extent[6] = { 0, w - 1, 0, h - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

int vtkVolumeReferenceRenderer::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // The whole volume is needed whatever part of the picture is asked for.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (inInfo && inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
      6);
  }
  return 1;
}

int vtkVolumeReferenceRenderer::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();

  avs::VolumeScene scene;
  std::string error, warning;
  // A tree of image blocks: the image they make (as the mappers draw it).
  vtkSmartPointer<vtkImageData> merged;
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  if (auto* tree = vtkDataObjectTree::GetData(inputVector[0]))
  {
    merged = vtkAVSCompositeInput::Merge(tree, error);
    if (!merged)
    {
      vtkErrorMacro("Cannot render the " << tree->GetClassName() << ": " << error << ".");
      return 1;
    }
    input = merged;
  }
  vtkAVSDataTranslator::Selection selection;
  selection.ScalarMode = this->ScalarMode;
  selection.ArrayAccessMode = this->ArrayAccessMode;
  selection.ArrayId = this->ArrayId;
  selection.ArrayName = this->ArrayName;
  vtkAVSDataTranslator::Volume data;
  if (!vtkAVSDataTranslator::ToVolume(input, selection, data, error, warning))
  {
    vtkErrorMacro("Cannot render: " << error);
    return 1;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  scene.Scalars = std::move(data.Components[0]);
  for (std::size_t c = 1; c < data.Components.size(); ++c)
  {
    scene.Medium.Components.emplace_back();
    scene.Medium.Components.back().Values = std::move(data.Components[c]);
  }
  scene.Medium.Validity = std::move(data.Validity);
  if (this->MaskInput)
  {
    if (!vtkAVSDataTranslator::ToMask(
          this->MaskInput, scene.Scalars.Geometry, scene.Medium.MaskValues, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return 1;
    }
    scene.Medium.Mask = this->MaskType == 0 ? avs::MaskType::Binary : avs::MaskType::LabelMap;
    scene.Medium.MaskBlendFactor = this->MaskBlendFactor;
  }
  if (!this->VolumeProperty)
  {
    vtkErrorMacro("Cannot render: no volume property set.");
    return 1;
  }
  if (!vtkAVSClipTranslator::ToClipRegion(this->ClippingPlanes,
        this->Cropping != 0,
        this->CroppingRegionPlanes,
        this->CroppingRegionFlags,
        input,
        scene.Scalars.Geometry,
        nullptr,
        scene.Clip,
        error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return 1;
  }
  if (!vtkAVSPropertyTranslator::ToMedium(this->VolumeProperty,
        data.Ranges,
        data.ScalarType,
        scene.Medium.Mask == avs::MaskType::LabelMap,
        scene,
        error,
        warning))
  {
    vtkErrorMacro("Cannot render: " << error);
    return 1;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning << ".");
  }
  vtkCamera* camera =
    this->Camera ? this->Camera : (this->Renderer ? this->Renderer->GetActiveCamera() : nullptr);
  if (!camera)
  {
    vtkErrorMacro("Cannot render: no camera (set Camera or Renderer).");
    return 1;
  }
  const std::string cameraProblem = vtkAVSSceneTranslator::ToCamera(camera).Validate();
  if (!cameraProblem.empty())
  {
    vtkErrorMacro("Cannot render: " << cameraProblem << ".");
    return 1;
  }
  scene.Lights = vtkAVSSceneTranslator::ToLights(this->Renderer, camera, this->LightScale);
  scene.Background = { this->Background[0], this->Background[1], this->Background[2] };

  const avs::RenderMode mode = this->RenderMode == EMISSION_ABSORPTION
    ? avs::RenderMode::EmissionAbsorption
    : (this->RenderMode == AMBIENT_OCCLUSION ? avs::RenderMode::AmbientOcclusion
                                             : avs::RenderMode::AmbientScattering);
  const avs::ScatteringTable* table = nullptr;
  if (this->RenderMode == AMBIENT_SCATTERING)
  {
    if (!this->ScatteringTable)
    {
      vtkNew<vtkAmbientScatteringTable> defaultTable;
      this->SetScatteringTable(defaultTable);
    }
    if (!this->ScatteringTable->Update())
    {
      vtkErrorMacro("Cannot render ambient scattering without a scattering table.");
      return 1;
    }
    table = this->ScatteringTable->GetTable();
  }

  avs::ScatteringParameters parameters;
  parameters.Albedo = this->Albedo;
  parameters.Anisotropy = this->Anisotropy;
  parameters.AmbientRadius = this->AmbientRadius;
  parameters.EmissionWeight = this->EmissionWeight;
  parameters.OcclusionRadius = this->OcclusionRadius;
  parameters.NumberOfDirections = this->NumberOfDirections;
  parameters.AmbientWeight = this->AmbientWeight;
  parameters.DirectLightWeight = this->DirectLightWeight;
  parameters.LightScale = this->LightScale;
  parameters.SampleDistance = this->SampleDistance;
  parameters.TerminationTransmittance = this->TerminationTransmittance;
  parameters.LightVolumeMaximumDimension = this->LightVolumeMaximumDimension;
  parameters.DiffusionVolumeMaximumDimension = this->DiffusionVolumeMaximumDimension;
  parameters.OcclusionVolumeMaximumDimension = this->OcclusionVolumeMaximumDimension;
  parameters.Model = this->ScatteringModel == ExtendedModel ? avs::ScatteringModel::Extended
                                                            : avs::ScatteringModel::Paper;
  parameters.Surface = vtkAVSPropertyTranslator::ToSurface(
    this->VolumeProperty, this->VolumetricScatteringBlending, this->Renderer);
  const avs::ScatteringParameters resolved = parameters.Resolve(scene.Scalars.Geometry);

  const int w = std::max(1, this->ImageSize[0]);
  const int h = std::max(1, this->ImageSize[1]);
  avs::Image image;
  this->UpdateProgress(0.0);
  if (this->RenderMode == PATH_TRACING)
  {
    avs::PathTracerSettings settings;
    settings.SamplesPerPixel = this->SamplesPerPixel;
    settings.Seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(this->Seed));
    avs::Image squares;
    image = avs::RenderPathTraced(
      scene,
      resolved,
      settings,
      vtkAVSSceneTranslator::ToCamera(camera),
      w,
      h,
      nullptr,
      [this](double v) { this->UpdateProgress(v); },
      &squares);
    // (With the samples' second moment, for the variance of the estimate.)
    this->WriteOutput(output, image, &squares, scene.Background, this->ResolveDisplay(scene));
    this->UpdateProgress(1.0);
    return 1;
  }
  avs::PrecomputedVolumes volumes;
  if (!avs::Precompute(scene,
        resolved,
        table,
        mode,
        volumes,
        &error,
        [this](double v) { this->UpdateProgress(0.5 * v); }))
  {
    vtkErrorMacro("Cannot render: " << error);
    return 1;
  }
  image = avs::RenderReference(scene,
    resolved,
    volumes,
    mode,
    vtkAVSSceneTranslator::ToCamera(camera),
    w,
    h,
    [this](double v) { this->UpdateProgress(0.5 + 0.5 * v); });

  this->WriteOutput(output, image, nullptr, scene.Background, this->ResolveDisplay(scene));
  this->UpdateProgress(1.0);
  return 1;
}

avs::DisplayTransform vtkVolumeReferenceRenderer::ResolveDisplay(const avs::VolumeScene& scene)
{
  const bool lit = this->RenderMode == AMBIENT_SCATTERING || this->RenderMode == PATH_TRACING;
  avs::DisplayTransform display;
  display.Exposure = this->Exposure > 0.0
    ? this->Exposure
    : (lit ? vtkAmbientScatteringVolumeMapper::DefaultExposure : 1.0);
  const int curve = this->ToneMapping != AutomaticToneMapping
    ? this->ToneMapping
    : (lit ? ShoulderToneMapping : ClampToneMapping);
  display.Curve =
    curve == ShoulderToneMapping ? avs::ToneMapping::Shoulder : avs::ToneMapping::Clamp;
  if (this->AutoExposure && lit)
  {
    display.Exposure *= avs::AutoExposureFactor(scene.Lights, scene.Scalars.Geometry);
  }
  this->ResolvedExposure = display.Exposure;
  this->ResolvedToneMapping = curve;
  return display;
}

void vtkVolumeReferenceRenderer::WriteOutput(vtkImageData* output,
  const avs::Image& image,
  const avs::Image* squares,
  const avs::Vec3& background,
  const avs::DisplayTransform& display)
{
  const int w = image.Width, h = image.Height;
  output->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  output->SetSpacing(1, 1, 1);
  output->SetOrigin(0, 0, 0);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(4);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  vtkNew<vtkFloatArray> second;
  second->SetName("RadianceSecondMoment");
  second->SetNumberOfComponents(4);
  second->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const vtkIdType id = static_cast<vtkIdType>(y) * w + x;
      // The volume's radiance through the display transform, then over the background, as the
      // mappers composite it.
      const float* l = image.At(x, y);
      const avs::Vec3 c = display.Apply({ l[0], l[1], l[2] }) + background * (1.0 - l[3]);
      for (int k = 0; k < 3; ++k)
      {
        const double v = std::clamp(c[k], 0.0, 1.0);
        rgb->SetTypedComponent(id, k, static_cast<unsigned char>(std::lround(255.0 * v)));
      }
      const float* p = image.At(x, y);
      const float* q = squares ? squares->At(x, y) : nullptr;
      for (int k = 0; k < 4; ++k)
      {
        radiance->SetTypedComponent(id, k, p[k]);
        second->SetTypedComponent(id, k, q ? q[k] : p[k] * p[k]);
      }
    }
  }
  output->GetPointData()->SetScalars(rgb);
  output->GetPointData()->AddArray(radiance);
  output->GetPointData()->AddArray(second);
}

void vtkVolumeReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->GetRenderModeAsString() << "\n";
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
  os << indent << "ArrayAccessMode: " << (this->ArrayAccessMode ? "ByName" : "ById") << "\n";
  os << indent << "ArrayId: " << this->ArrayId << "\n";
  os << indent << "ArrayName: " << this->ArrayName << "\n";
  os << indent << "MaskInput: " << this->MaskInput << "\n";
  os << indent << "MaskType: " << (this->MaskType == 0 ? "Binary" : "LabelMap") << "\n";
  os << indent << "MaskBlendFactor: " << this->MaskBlendFactor << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ScatteringTable: " << this->ScatteringTable << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "Background: (" << this->Background[0] << ", " << this->Background[1] << ", "
     << this->Background[2] << ")\n";
  os << indent << "Exposure: " << this->Exposure
     << (this->Exposure > 0 ? "" : " (automatic: the render mode's mapper's)") << "\n";
  os << indent << "ToneMapping: "
     << (this->ToneMapping == AutomaticToneMapping
            ? "Automatic (the render mode's mapper's)"
            : (this->ToneMapping == ShoulderToneMapping ? "Shoulder" : "Clamp"))
     << "\n";
  os << indent << "AutoExposure: " << (this->AutoExposure ? "On" : "Off") << "\n";
  os << indent << "ResolvedExposure: " << this->ResolvedExposure << "\n";
  os << indent << "ResolvedToneMapping: "
     << (this->ResolvedToneMapping == ShoulderToneMapping ? "Shoulder" : "Clamp") << "\n";
  os << indent << "Albedo: " << this->Albedo << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->VolumetricScatteringBlending << "\n";
  os << indent << "ScatteringModel: " << this->GetScatteringModelAsString() << "\n";
  os << indent << "AmbientRadius: " << this->AmbientRadius
     << (this->AmbientRadius > 0 ? "" : " (automatic)") << "\n";
  os << indent << "EmissionWeight: " << this->EmissionWeight << "\n";
  os << indent << "OcclusionRadius: " << this->OcclusionRadius
     << (this->OcclusionRadius > 0 ? "" : " (the ambient radius)") << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "AmbientWeight: " << this->AmbientWeight << "\n";
  os << indent << "DirectLightWeight: " << this->DirectLightWeight << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance
     << (this->SampleDistance > 0 ? "" : " (automatic)") << "\n";
  os << indent << "TerminationTransmittance: " << this->TerminationTransmittance << "\n";
  os << indent << "LightVolumeMaximumDimension: " << this->LightVolumeMaximumDimension << "\n";
  os << indent << "DiffusionVolumeMaximumDimension: " << this->DiffusionVolumeMaximumDimension
     << "\n";
  os << indent << "OcclusionVolumeMaximumDimension: " << this->OcclusionVolumeMaximumDimension
     << "\n";
  os << indent
     << "ClippingPlanes: " << (this->ClippingPlanes ? this->ClippingPlanes->GetNumberOfItems() : 0)
     << "\n";
  os << indent << "Cropping: " << (this->Cropping ? "On" : "Off") << "\n";
  os << indent << "CroppingRegionPlanes: (" << this->CroppingRegionPlanes[0] << ", "
     << this->CroppingRegionPlanes[1] << ", " << this->CroppingRegionPlanes[2] << ", "
     << this->CroppingRegionPlanes[3] << ", " << this->CroppingRegionPlanes[4] << ", "
     << this->CroppingRegionPlanes[5] << ")\n";
  os << indent << "CroppingRegionFlags: 0x" << std::hex << this->CroppingRegionFlags << std::dec
     << "\n";
  os << indent << "SamplesPerPixel: " << this->SamplesPerPixel << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
