#include "vtkAmbientScatteringVolumeMapper.h"

#include "ScatteringParameters.h"
#include "vtkAVSPrecomputeInputs.h"
#include "vtkAVSScatteringVolumes.h"
#include "vtkAmbientScatteringTable.h"

#include "vtkObjectFactory.h"

#include <string>

vtkStandardNewMacro(vtkAmbientScatteringVolumeMapper);

vtkAmbientScatteringVolumeMapper::vtkAmbientScatteringVolumeMapper()
  : Table(vtkAmbientScatteringTable::New())
  , Volumes(new vtkAVSScatteringVolumes)
{
  // The display transform's defaults for lit, multiply scattering media (see the header).
  this->Exposure = DefaultExposure;
  this->ToneMapping = ShoulderToneMapping;
}

vtkAmbientScatteringVolumeMapper::~vtkAmbientScatteringVolumeMapper()
{
  this->SetScatteringTableFileName(nullptr);
  this->Table->Delete();
}

void vtkAmbientScatteringVolumeMapper::FillParameters(avs::ScatteringParameters& p)
{
  p.AmbientRadius = this->AmbientRadius;
  p.Anisotropy = this->Anisotropy;
  p.Albedo = this->Albedo;
  p.EmissionWeight = this->EmissionWeight;
  p.LightScale = this->LightScale;
  p.LightVolumeMaximumDimension = this->LightVolumeMaximumDimension;
  p.DiffusionVolumeMaximumDimension = this->DiffusionVolumeMaximumDimension;
  p.Model = this->ScatteringModel == ExtendedModel ? avs::ScatteringModel::Extended
                                                   : avs::ScatteringModel::Paper;
  p.Surface.Blending = this->VolumetricScatteringBlending;
}

const avs::ScatteringTable* vtkAmbientScatteringVolumeMapper::GetScatteringTable()
{
  const std::string wanted = this->ScatteringTableFileName ? this->ScatteringTableFileName : "";
  const std::string current = this->Table->GetFileName() ? this->Table->GetFileName() : "";
  if (wanted != current)
  {
    this->Table->SetFileName(wanted.empty() ? nullptr : wanted.c_str());
  }
  if (!this->Table->Update())
  {
    vtkErrorMacro("Cannot render: no usable scattering table (see the error above).");
    return nullptr;
  }
  return this->Table->GetTable();
}

bool vtkAmbientScatteringVolumeMapper::PrepareLighting(const vtkAVSPrecomputeInputs& inputs)
{
  const avs::ScatteringTable* table = this->GetScatteringTable();
  if (!table)
  {
    return false; // GetScatteringTable reported why
  }
  std::string error;
  if (!this->Volumes->Update(inputs, *table, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  return true;
}

void vtkAmbientScatteringVolumeMapper::InvalidateLighting()
{
  this->Volumes->Invalidate();
}

void vtkAmbientScatteringVolumeMapper::GetPrecomputedGrids(std::array<int, 3>& lightGrid,
  std::array<int, 3>&) const
{
  lightGrid = this->Volumes->GetLightGridDimensions();
}

vtkTypeBool vtkAmbientScatteringVolumeMapper::GetLightVolumesOnGPU()
{
  return this->Volumes->GetLightVolumesOnGPU() ? 1 : 0;
}

int vtkAmbientScatteringVolumeMapper::GetNumberOfExtinctionRebuilds()
{
  return this->Volumes->GetNumberOfExtinctionRebuilds();
}

int vtkAmbientScatteringVolumeMapper::GetNumberOfLightVolumeRebuilds()
{
  return this->Volumes->GetNumberOfLightVolumeRebuilds();
}

int vtkAmbientScatteringVolumeMapper::GetNumberOfDiffusionRebuilds()
{
  return this->Volumes->GetNumberOfDiffusionRebuilds();
}

void vtkAmbientScatteringVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AmbientRadius: " << this->AmbientRadius
     << (this->AmbientRadius > 0 ? "" : " (automatic)") << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "Albedo: " << this->Albedo << "\n";
  os << indent << "EmissionWeight: " << this->EmissionWeight << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "LightVolumeMaximumDimension: " << this->LightVolumeMaximumDimension << "\n";
  os << indent << "ScatteringModel: " << this->GetScatteringModelAsString() << "\n";
  os << indent << "DiffusionVolumeMaximumDimension: " << this->DiffusionVolumeMaximumDimension
     << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->VolumetricScatteringBlending << "\n";
  os << indent << "PathTracedRefinement: " << (this->PathTracedRefinement ? "On" : "Off") << "\n";
  os << indent << "MaximumSamplesPerPixel: " << this->MaximumSamplesPerPixel << "\n";
  os << indent << "ScatteringTableFileName: "
     << (this->ScatteringTableFileName ? this->ScatteringTableFileName : "(the shipped table)")
     << "\n";
  os << indent << "Table:\n";
  this->Table->PrintSelf(os, indent.GetNextIndent());
}
