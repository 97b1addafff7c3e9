#include "vtkAmbientOcclusionVolumeMapper.h"

#include "ScatteringParameters.h"
#include "vtkAVSOcclusionVolume.h"
#include "vtkAVSPrecomputeInputs.h"

#include "vtkObjectFactory.h"

#include <string>

vtkStandardNewMacro(vtkAmbientOcclusionVolumeMapper);

vtkAmbientOcclusionVolumeMapper::vtkAmbientOcclusionVolumeMapper()
  : Occlusion(new vtkAVSOcclusionVolume)
{
}

vtkAmbientOcclusionVolumeMapper::~vtkAmbientOcclusionVolumeMapper() = default;

bool vtkAmbientOcclusionVolumeMapper::PrepareLighting(const vtkAVSPrecomputeInputs& inputs)
{
  std::string error;
  if (!this->Occlusion->Update(inputs, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  return true;
}

void vtkAmbientOcclusionVolumeMapper::InvalidateLighting()
{
  this->Occlusion->Invalidate();
}

void vtkAmbientOcclusionVolumeMapper::GetPrecomputedGrids(std::array<int, 3>&,
  std::array<int, 3>& occlusionGrid) const
{
  occlusionGrid = this->Occlusion->GetDimensions();
}

vtkTypeBool vtkAmbientOcclusionVolumeMapper::GetOcclusionOnGPU()
{
  return this->Occlusion->GetOnGPU() ? 1 : 0;
}

int vtkAmbientOcclusionVolumeMapper::GetNumberOfOcclusionRebuilds()
{
  return this->Occlusion->GetNumberOfRebuilds();
}

void vtkAmbientOcclusionVolumeMapper::FillParameters(avs::ScatteringParameters& p)
{
  p.OcclusionRadius = this->OcclusionRadius;
  p.NumberOfDirections = this->NumberOfDirections;
  p.OcclusionVolumeMaximumDimension = this->OcclusionVolumeMaximumDimension;
  p.AmbientWeight = this->AmbientWeight;
  p.EmissionWeight = this->EmissionWeight;
  p.DirectLightWeight = this->DirectLightWeight;
  p.LightScale = this->LightScale;
  // The unshadowed direct light is isotropic and unattenuated by albedo.
  p.Albedo = 1.0;
  p.Anisotropy = 0.0;
}

void vtkAmbientOcclusionVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OcclusionRadius: " << this->OcclusionRadius
     << (this->OcclusionRadius > 0 ? "" : " (automatic)") << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "OcclusionVolumeMaximumDimension: " << this->OcclusionVolumeMaximumDimension
     << "\n";
  os << indent << "AmbientWeight: " << this->AmbientWeight << "\n";
  os << indent << "EmissionWeight: " << this->EmissionWeight << "\n";
  os << indent << "DirectLightWeight: " << this->DirectLightWeight << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
}
