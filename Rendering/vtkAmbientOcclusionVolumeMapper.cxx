#include "vtkAmbientOcclusionVolumeMapper.h"

#include "ScatteringParameters.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkAmbientOcclusionVolumeMapper);

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
