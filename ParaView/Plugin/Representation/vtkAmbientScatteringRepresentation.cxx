#include "vtkAmbientScatteringRepresentation.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVView.h"

vtkStandardNewMacro(vtkAmbientScatteringRepresentation);

vtkAmbientScatteringRepresentation::vtkAmbientScatteringRepresentation()
{
  // The superclass made a vtkMultiBlockVolumeMapper; ours takes its place (it gets the input and
  // the scalar selection at each render, in ProcessViewRequest and UpdateMapperParameters).
  this->VolumeMapper = this->AmbientScatteringMapper.GetPointer();
}

vtkAmbientScatteringRepresentation::~vtkAmbientScatteringRepresentation() = default;

void vtkAmbientScatteringRepresentation::SetLightingModel(int model)
{
  if (model < EmissionAbsorption || model > AmbientScattering)
  {
    vtkErrorMacro("LightingModel " << model
                                   << " is none of EmissionAbsorption (0), AmbientOcclusion (1) "
                                      "and AmbientScattering (2); it stays "
                                   << this->LightingModel);
    return;
  }
  if (model == this->LightingModel)
  {
    return;
  }
  vtkVolumeMapper* next = model == EmissionAbsorption
    ? static_cast<vtkVolumeMapper*>(this->EmissionAbsorptionMapper)
    : model == AmbientOcclusion ? static_cast<vtkVolumeMapper*>(this->AmbientOcclusionMapper)
                                : static_cast<vtkVolumeMapper*>(this->AmbientScatteringMapper);
  vtkVolumeMapper* previous = this->VolumeMapper;
  next->SetCropping(previous->GetCropping());
  next->SetCroppingRegionFlags(previous->GetCroppingRegionFlags());
  next->SetBlendMode(previous->GetBlendMode());
  next->SetInputConnection(previous->GetInputConnection(0, 0));
  previous->RemoveAllInputConnections(0);
  this->VolumeMapper = next;
  this->LightingModel = model;
  this->Modified();
}

vtkVolumeMapper* vtkAmbientScatteringRepresentation::GetActiveVolumeMapper()
{
  return this->VolumeMapper;
}

void vtkAmbientScatteringRepresentation::SetAlbedo(double albedo)
{
  this->AmbientScatteringMapper->SetAlbedo(albedo);
}

double vtkAmbientScatteringRepresentation::GetAlbedo()
{
  return this->AmbientScatteringMapper->GetAlbedo();
}

void vtkAmbientScatteringRepresentation::SetVolumetricScatteringBlending(float blending)
{
  this->Superclass::SetVolumetricScatteringBlending(blending);
  this->AmbientScatteringMapper->SetVolumetricScatteringBlending(blending);
}

float vtkAmbientScatteringRepresentation::GetVolumetricScatteringBlending()
{
  return this->AmbientScatteringMapper->GetVolumetricScatteringBlending();
}

void vtkAmbientScatteringRepresentation::SetExposure(double exposure)
{
  this->AmbientScatteringMapper->SetExposure(exposure);
}

double vtkAmbientScatteringRepresentation::GetExposure()
{
  return this->AmbientScatteringMapper->GetExposure();
}

void vtkAmbientScatteringRepresentation::SetToneMapping(int curve)
{
  this->AmbientScatteringMapper->SetToneMapping(curve);
}

int vtkAmbientScatteringRepresentation::GetToneMapping()
{
  return this->AmbientScatteringMapper->GetToneMapping();
}

void vtkAmbientScatteringRepresentation::SetAutoExposure(int on)
{
  this->AmbientScatteringMapper->SetAutoExposure(on);
}

int vtkAmbientScatteringRepresentation::GetAutoExposure()
{
  return this->AmbientScatteringMapper->GetAutoExposure();
}

void vtkAmbientScatteringRepresentation::SetScatteringAnisotropy(double g)
{
  this->AmbientScatteringMapper->SetAnisotropy(g);
}

double vtkAmbientScatteringRepresentation::GetScatteringAnisotropy()
{
  return this->AmbientScatteringMapper->GetAnisotropy();
}

void vtkAmbientScatteringRepresentation::SetAmbientRadius(double radius)
{
  this->AmbientScatteringMapper->SetAmbientRadius(radius);
  this->AmbientOcclusionMapper->SetOcclusionRadius(radius);
}

double vtkAmbientScatteringRepresentation::GetAmbientRadius()
{
  return this->AmbientScatteringMapper->GetAmbientRadius();
}

void vtkAmbientScatteringRepresentation::SetLightScale(double scale)
{
  this->AmbientScatteringMapper->SetLightScale(scale);
  this->AmbientOcclusionMapper->SetLightScale(scale);
}

double vtkAmbientScatteringRepresentation::GetLightScale()
{
  return this->AmbientScatteringMapper->GetLightScale();
}

void vtkAmbientScatteringRepresentation::SetEmissionWeight(double weight)
{
  this->AmbientScatteringMapper->SetEmissionWeight(weight);
  this->AmbientOcclusionMapper->SetEmissionWeight(weight);
}

double vtkAmbientScatteringRepresentation::GetEmissionWeight()
{
  return this->AmbientScatteringMapper->GetEmissionWeight();
}

void vtkAmbientScatteringRepresentation::SetLightVolumeMaximumDimension(int dimension)
{
  this->AmbientScatteringMapper->SetLightVolumeMaximumDimension(dimension);
  this->AmbientOcclusionMapper->SetOcclusionVolumeMaximumDimension(dimension);
}

int vtkAmbientScatteringRepresentation::GetLightVolumeMaximumDimension()
{
  return this->AmbientScatteringMapper->GetLightVolumeMaximumDimension();
}

void vtkAmbientScatteringRepresentation::SetScatteringModel(int model)
{
  this->AmbientScatteringMapper->SetScatteringModel(model);
}

int vtkAmbientScatteringRepresentation::GetScatteringModel()
{
  return this->AmbientScatteringMapper->GetScatteringModel();
}

void vtkAmbientScatteringRepresentation::SetPathTracedRefinement(int on)
{
  this->AmbientScatteringMapper->SetPathTracedRefinement(on != 0);
}

int vtkAmbientScatteringRepresentation::GetPathTracedRefinement()
{
  return this->AmbientScatteringMapper->GetPathTracedRefinement() ? 1 : 0;
}

void vtkAmbientScatteringRepresentation::SetMaximumSamplesPerPixel(int samples)
{
  this->AmbientScatteringMapper->SetMaximumSamplesPerPixel(samples);
}

int vtkAmbientScatteringRepresentation::GetMaximumSamplesPerPixel()
{
  return this->AmbientScatteringMapper->GetMaximumSamplesPerPixel();
}

int vtkAmbientScatteringRepresentation::GetSamplesPerPixel()
{
  return this->AmbientScatteringMapper->GetSamplesPerPixel();
}

void vtkAmbientScatteringRepresentation::SetDiffusionVolumeMaximumDimension(int dimension)
{
  this->AmbientScatteringMapper->SetDiffusionVolumeMaximumDimension(dimension);
}

int vtkAmbientScatteringRepresentation::GetDiffusionVolumeMaximumDimension()
{
  return this->AmbientScatteringMapper->GetDiffusionVolumeMaximumDimension();
}

void vtkAmbientScatteringRepresentation::SetSampleDistance(double distance)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetSampleDistance(distance);
  }
}

double vtkAmbientScatteringRepresentation::GetSampleDistance()
{
  return this->AmbientScatteringMapper->GetSampleDistance();
}

void vtkAmbientScatteringRepresentation::SetUseJittering(int jitter)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetUseJittering(jitter);
  }
}

int vtkAmbientScatteringRepresentation::GetUseJittering()
{
  return this->AmbientScatteringMapper->GetUseJittering();
}

void vtkAmbientScatteringRepresentation::SetMaximumGPUMemory(int mebibytes)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetMaximumGPUMemory(mebibytes);
  }
}

int vtkAmbientScatteringRepresentation::GetMaximumGPUMemory()
{
  return this->AmbientScatteringMapper->GetMaximumGPUMemory();
}

std::array<vtkAVSVolumeMapper*, 3> vtkAmbientScatteringRepresentation::Mappers()
{
  return { this->EmissionAbsorptionMapper.GetPointer(),
    this->AmbientOcclusionMapper.GetPointer(),
    this->AmbientScatteringMapper.GetPointer() };
}

int vtkAmbientScatteringRepresentation::ProcessViewRequest(vtkInformationRequestKey* request,
  vtkInformation* inInfo,
  vtkInformation* outInfo)
{
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  // Every rank gets the render request (the culling comes later, in the renderer), so the
  // ranks meet here. The visibility is the same on every rank.
  if (request == vtkPVView::REQUEST_RENDER() && this->GetVisibility())
  {
    this->ShareLightAcrossRanks();
    if (auto* mapper = vtkAVSVolumeMapper::SafeDownCast(this->VolumeMapper))
    {
      mapper->UpdatePieceLighting(this->GetRenderedProp());
    }
  }
  return result;
}

void vtkAmbientScatteringRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  this->ShareLightAcrossRanks();
}

void vtkAmbientScatteringRepresentation::ShareLightAcrossRanks()
{
  // The whole extent comes from the pipeline (RequestData); every rank has the same.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool distributed =
    this->LightAcrossRanks && controller && controller->GetNumberOfProcesses() > 1;
  const int none[6] = { 0, -1, 0, -1, 0, -1 };
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetWholeExtent(distributed ? this->WholeExtent : none);
    m->SetController(distributed ? controller : nullptr);
  }
}

void vtkAmbientScatteringRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = {
    "EmissionAbsorption", "AmbientOcclusion", "AmbientScattering"
  };
  os << indent << "LightingModel: " << names[this->LightingModel] << "\n";
  os << indent << "Albedo: " << this->GetAlbedo() << "\n";
  os << indent << "Exposure: " << this->GetExposure() << "\n";
  os << indent << "ToneMapping: " << this->AmbientScatteringMapper->GetToneMappingAsString()
     << "\n";
  os << indent << "AutoExposure: " << (this->GetAutoExposure() ? "On" : "Off") << "\n";
  os << indent << "ScatteringAnisotropy: " << this->GetScatteringAnisotropy() << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->GetVolumetricScatteringBlending()
     << "\n";
  os << indent << "AmbientRadius: " << this->GetAmbientRadius() << "\n";
  os << indent << "LightScale: " << this->GetLightScale() << "\n";
  os << indent << "EmissionWeight: " << this->GetEmissionWeight() << "\n";
  os << indent << "LightVolumeMaximumDimension: " << this->GetLightVolumeMaximumDimension() << "\n";
  os << indent << "ScatteringModel: " << this->GetScatteringModel() << "\n";
  os << indent << "DiffusionVolumeMaximumDimension: " << this->GetDiffusionVolumeMaximumDimension()
     << "\n";
  os << indent << "PathTracedRefinement: " << (this->GetPathTracedRefinement() ? "On" : "Off")
     << "\n";
  os << indent << "MaximumSamplesPerPixel: " << this->GetMaximumSamplesPerPixel() << "\n";
  os << indent << "SampleDistance: " << this->GetSampleDistance() << "\n";
  os << indent << "UseJittering: " << this->GetUseJittering() << "\n";
  os << indent << "MaximumGPUMemory: " << this->GetMaximumGPUMemory() << " MiB\n";
  os << indent << "LightAcrossRanks: " << (this->LightAcrossRanks ? "On" : "Off") << "\n";
  os << indent << "EmissionAbsorptionMapper: " << this->EmissionAbsorptionMapper.GetPointer()
     << "\n";
  os << indent << "AmbientOcclusionMapper: " << this->AmbientOcclusionMapper.GetPointer() << "\n";
  os << indent << "AmbientScatteringMapper: " << this->AmbientScatteringMapper.GetPointer() << "\n";
}
