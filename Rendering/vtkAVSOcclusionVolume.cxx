#include "vtkAVSOcclusionVolume.h"

#include "vtkAVSPrecomputeInputs.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSVolumeMapper.h"

#include "AmbientOcclusion.h"

bool vtkAVSOcclusionVolume::Update(const vtkAVSPrecomputeInputs& inputs, std::string& error)
{
  vtkAVSRayCaster& caster = *inputs.RayCaster;
  const avs::GridGeometry& g = inputs.Scene->Scalars.Geometry;
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  // The occlusion volume's grid: the data's, capped like the light volumes'.
  const avs::GridGeometry occlusionGrid = g.Capped(rp.OcclusionVolumeMaximumDimension);
  if (this->Key[0] == inputs.DataVersion && this->Key[1] == inputs.OpacityVersion &&
    this->Radius == rp.OcclusionRadius && this->Directions == rp.NumberOfDirections &&
    this->Dimensions == occlusionGrid.Dimensions && this->Uploaded)
  {
    return true;
  }
  inputs.Progress(0.0);
  // (The GPU pass classifies the unsplit scalars' texture: a split volume's occlusion is
  // computed on the CPU.)
  const bool gpu = inputs.PrecomputeOnGPU && caster.SupportsComputeShaders() &&
    rp.NumberOfDirections <= 256 && !caster.IsBricked();
  if (gpu)
  {
    if (!caster.ComputeOcclusion(g,
          occlusionGrid.Dimensions,
          rp.OcclusionRadius,
          rp.NumberOfDirections,
          inputs.Scene->Clip,
          error))
    {
      return false;
    }
  }
  else
  {
    const avs::Grid ao = avs::ComputeAmbientOcclusion(inputs.Extinction(),
      occlusionGrid,
      rp.OcclusionRadius,
      rp.NumberOfDirections,
      0.0,
      nullptr,
      inputs.Progress);
    if (!caster.UploadOcclusion(ao, error))
    {
      return false;
    }
  }
  this->OnGPU = gpu;
  inputs.Progress(1.0);
  this->Key[0] = inputs.DataVersion;
  this->Key[1] = inputs.OpacityVersion;
  this->Radius = rp.OcclusionRadius;
  this->Directions = rp.NumberOfDirections;
  this->Dimensions = occlusionGrid.Dimensions;
  this->Uploaded = true;
  ++this->Rebuilds;
  if (inputs.StageDone)
  {
    inputs.StageDone(vtkAVSVolumeMapper::LightVolumeStage); // (the light volumes' stage)
  }
  return true;
}

void vtkAVSOcclusionVolume::Invalidate()
{
  this->Uploaded = false;
}
