#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "AmbientOcclusion.h"
#include "AveragedExtinction.h"
#include "DiffuseFluence.h"
#include "LightVolume.h"
#include "PieceAveraging.h"
#include "ReferenceRenderer.h"

#include <string>

// The precomputation of vtkAVSVolumeMapper::Prepare: each precomputed volume is rebuilt (on the
// GPU when the context can, else on the CPU and uploaded) when a key it was built for changed,
// and the mapper counts the rebuild.

namespace
{
bool SamePose(const avs::Light& a, const avs::Light& b)
{
  auto same = [](const avs::Vec3& x, const avs::Vec3& y)
  { return x.x == y.x && x.y == y.y && x.z == y.z; };
  return a.Type == b.Type && same(a.Position, b.Position) && same(a.FocalPoint, b.FocalPoint);
}

avs::Vec3 Transform(vtkMatrix4x4* m, const avs::Vec3& p)
{
  double in[4] = { p.x, p.y, p.z, 1.0 }, out[4];
  m->MultiplyPoint(in, out);
  return { out[0] / out[3], out[1] / out[3], out[2] / out[3] };
}
} // namespace

bool vtkAVSVolumeMapper::PrepareOcclusion()
{
  auto& in = *this->Internal;
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  const avs::ScatteringParameters& rp = in.Parameters;
  std::string error;
  // The occlusion volume's grid: the data's, capped like the light volumes'.
  const avs::GridGeometry occlusionGrid = g.Capped(rp.OcclusionVolumeMaximumDimension);
  if (in.OcclusionKey[0] != in.DataVersion || in.OcclusionKey[1] != in.OpacityVersion ||
    in.OcclusionRadius != rp.OcclusionRadius || in.OcclusionDirections != rp.NumberOfDirections ||
    in.OcclusionDimensions != occlusionGrid.Dimensions || !in.OcclusionUploaded)
  {
    this->UpdateProgress(0.0);
    // (The GPU pass classifies the unsplit scalars' texture: a split volume's occlusion is
    // computed on the CPU.)
    const bool gpu = this->PrecomputeOnGPU && in.RayCaster.SupportsComputeShaders() &&
      rp.NumberOfDirections <= 256 && !in.RayCaster.IsBricked();
    if (gpu)
    {
      if (!in.RayCaster.ComputeOcclusion(g,
            occlusionGrid.Dimensions,
            rp.OcclusionRadius,
            rp.NumberOfDirections,
            in.Scene.Clip,
            error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    else
    {
      this->UpdateExtinction();
      const avs::Grid ao = avs::ComputeAmbientOcclusion(in.Extinction,
        occlusionGrid,
        rp.OcclusionRadius,
        rp.NumberOfDirections,
        0.0,
        nullptr,
        [this](double v) { this->UpdateProgress(v); });
      if (!in.RayCaster.UploadOcclusion(ao, error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    this->OcclusionOnGPU = gpu;
    this->UpdateProgress(1.0);
    in.OcclusionKey[0] = in.DataVersion;
    in.OcclusionKey[1] = in.OpacityVersion;
    in.OcclusionRadius = rp.OcclusionRadius;
    in.OcclusionDirections = rp.NumberOfDirections;
    in.OcclusionDimensions = occlusionGrid.Dimensions;
    in.OcclusionUploaded = true;
    ++this->NumberOfOcclusionRebuilds;
  }
  return true;
}

bool vtkAVSVolumeMapper::PrepareScattering(const avs::ScatteringTable* table,
  bool gpuScattering,
  vtkMatrix4x4* worldToData,
  bool interactive)
{
  auto& in = *this->Internal;
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  const avs::ScatteringParameters& rp = in.Parameters;
  std::string error;
  // Ambient scattering: table slice, averaged extinction, light volumes.
  if (table != in.SliceTable || rp.Anisotropy != in.SliceG || rp.Albedo != in.SliceAlbedo)
  {
    in.Slice = table->Slice(rp.Anisotropy, rp.Albedo);
    if (!in.RayCaster.UploadTableSlice(in.Slice, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.SliceTable = table;
    in.SliceG = rp.Anisotropy;
    in.SliceAlbedo = rp.Albedo;
    ++in.SliceVersion;
  }
  // The averaged extinction and the light volumes share the light grid: over the whole image
  // when the input is a piece of it (vtkAVSVolumeMapperPieces.cxx).
  const avs::GridGeometry lightGrid = in.Whole.Capped(rp.LightVolumeMaximumDimension);
  const std::array<int, 6> piece{ in.Whole.Dimensions[0],
    in.Whole.Dimensions[1],
    in.Whole.Dimensions[2],
    in.PieceOffset[0],
    in.PieceOffset[1],
    in.PieceOffset[2] };
  // The GPU pass reads the unsplit scalars' texture: a split volume's is computed on the CPU
  // (its box sums would need every brick; ARCHITECTURE.md, "Bricking").
  const bool gpuAveraged = gpuScattering && !in.RayCaster.IsBricked();
  if (in.AveragedKey[0] != in.DataVersion || in.AveragedKey[1] != in.OpacityVersion ||
    in.AveragedRadius != rp.AmbientRadius || in.AveragedOnGPU != (gpuAveraged ? 1 : 0) ||
    in.AveragedDimensions != lightGrid.Dimensions || in.AveragedPiece != piece ||
    in.AveragedSum != in.SumVersion)
  {
    if (this->LitAsPiece)
    {
      // The pieces' shares summed (by UpdatePieceLighting, before the render), on the light
      // grid that the rays and the light-volume pass read.
      if (!this->AverageAcrossPieces(lightGrid, error) ||
        !in.RayCaster.UploadAveraged(in.Averaged, error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    else if (gpuAveraged)
    {
      if (!in.RayCaster.ComputeAveragedExtinction(g.Dimensions,
            lightGrid.Dimensions,
            avs::AveragingHalfWidths(rp.AmbientRadius, g.Spacing),
            in.Scene.Clip,
            error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    else
    {
      in.Averaged = avs::AverageExtinctionOn(in.Extinction, rp.AmbientRadius, lightGrid);
      if (!in.RayCaster.UploadAveraged(in.Averaged, error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    in.AveragedKey[0] = in.DataVersion;
    in.AveragedKey[1] = in.OpacityVersion;
    in.AveragedOnGPU = gpuAveraged ? 1 : 0;
    in.AveragedRadius = rp.AmbientRadius;
    in.AveragedDimensions = lightGrid.Dimensions;
    in.AveragedPiece = piece;
    in.AveragedSum = in.SumVersion;
    ++in.AveragedVersion;
    ++this->NumberOfExtinctionRebuilds;
  }
  const bool gpu = gpuScattering;
  if (in.LightGridMaximum != rp.LightVolumeMaximumDimension || in.LightsOnGPU != (gpu ? 1 : 0))
  {
    in.Lights.clear();
    in.LightGridMaximum = rp.LightVolumeMaximumDimension;
    in.LightsOnGPU = gpu ? 1 : 0;
    in.LightVolumesUploaded = false;
  }
  in.LightGridDimensions = lightGrid.Dimensions;
  this->LightVolumesOnGPU = gpu;
  const std::size_t n = in.WorldLights.size();
  bool changed = in.Lights.size() != n || !in.LightVolumesUploaded;
  bool rebuilt = changed; // a light volume was rebuilt (on the CPU or the GPU)
  in.Lights.resize(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    avs::Light dataLight = in.WorldLights[j];
    dataLight.Position = Transform(worldToData, dataLight.Position);
    dataLight.FocalPoint = Transform(worldToData, dataLight.FocalPoint);
    auto& state = in.Lights[j];
    const avs::TubeLaw law =
      avs::TubeLawFor(rp.Model == avs::ScatteringModel::Extended, dataLight.Type);
    const bool current = state.Built && state.AveragedVersion == in.AveragedVersion &&
      state.SliceVersion == in.SliceVersion && state.Radius == rp.AmbientRadius && state.Law == law;
    // While interacting, a light that follows the camera keeps the volume of its last pose (the
    // still frame rebuilds it): only the pose is stale, and it moves with every camera move.
    const bool keep =
      interactive && current && in.FollowsCamera[j] && state.DataFrame.Type == dataLight.Type;
    if (!current || (!SamePose(state.DataFrame, dataLight) && !keep))
    {
      this->UpdateProgress(static_cast<double>(j) / n);
      if (gpu)
      {
        if (!in.RayCaster.ComputeLightVolume(
              static_cast<int>(j), lightGrid, dataLight, rp.AmbientRadius, law, error))
        {
          vtkErrorMacro("Cannot render: " << error);
          return false;
        }
      }
      else
      {
        state.Volume = avs::ComputeLightVolume(
          in.Averaged,
          lightGrid,
          dataLight,
          in.Slice,
          rp.AmbientRadius,
          nullptr,
          [this, j, n](double v) { this->UpdateProgress((j + v) / static_cast<double>(n)); },
          law);
        changed = true;
      }
      state.DataFrame = dataLight;
      state.AveragedVersion = in.AveragedVersion;
      state.SliceVersion = in.SliceVersion;
      state.Radius = rp.AmbientRadius;
      state.Law = law;
      state.Built = true;
      rebuilt = true;
      ++this->NumberOfLightVolumeRebuilds;
    }
    // What the light volume does not depend on (its transmittances), but the extended model's
    // source does: always the current light's.
    state.DataFrame.Irradiance = dataLight.Irradiance;
    state.DataFrame.Attenuation = dataLight.Attenuation;
    state.DataFrame.ConeAngle = dataLight.ConeAngle;
    state.DataFrame.Exponent = dataLight.Exponent;
  }
  if (!gpu && changed)
  {
    std::vector<avs::Grid> volumes;
    for (const auto& state : in.Lights)
    {
      volumes.push_back(state.Volume);
    }
    if (!in.RayCaster.UploadLightVolumes(volumes, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
  }
  in.LightVolumesUploaded = true;
  // The averaged extinction beside the lights' channels, where there is room (1-3, 5-7 lights).
  if (!in.RayCaster.PackAveraged(static_cast<int>(n), error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  // The extended model: the diffuse fluence from the light volumes (DiffuseFluence.h).
  if (rp.Model != avs::ScatteringModel::Extended)
  {
    in.DiffuseUploaded = false;
    return true;
  }
  std::vector<double> lightKey;
  for (const auto& state : in.Lights)
  {
    const avs::Light& l = state.DataFrame;
    for (const avs::Vec3& v : { l.Position, l.FocalPoint, l.Irradiance, l.Attenuation })
    {
      lightKey.insert(lightKey.end(), { v.x, v.y, v.z });
    }
    lightKey.insert(lightKey.end(),
      { static_cast<double>(l.Type), l.ConeAngle, l.Exponent, rp.Albedo, rp.Anisotropy });
  }
  if (rebuilt || !in.DiffuseUploaded || in.DiffuseOnGPU != (gpu ? 1 : 0) ||
    in.DiffuseLights != lightKey || in.DiffuseIterations != rp.DiffusionIterations ||
    in.DiffuseCoarseIterations != rp.DiffusionCoarseIterations ||
    in.DiffuseGridMaximum != rp.DiffusionVolumeMaximumDimension)
  {
    std::vector<avs::Light> lights;
    std::vector<avs::Grid> volumes;
    for (const auto& state : in.Lights)
    {
      lights.push_back(state.DataFrame);
      volumes.push_back(state.Volume);
    }
    vtkAVSDiffuseVolume& diffuse = in.RayCaster.GetDiffuseVolume();
    const bool done = gpu ? diffuse.Compute(in.RayCaster.GetWindow(),
                              avs::DiffusionGeometry(lightGrid, rp.DiffusionVolumeMaximumDimension),
                              lightGrid.Dimensions,
                              in.RayCaster.GetAveragedExtinctionTexture(),
                              in.RayCaster.GetLightVolumeTexture(0),
                              in.RayCaster.GetLightVolumeTexture(1),
                              lights,
                              rp,
                              error)
                          : diffuse.Upload(in.RayCaster.GetWindow(),
                              avs::ComputeDiffuse(in.Averaged, lights, volumes, rp),
                              in.Averaged,
                              error);
    if (!done)
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.DiffuseOnGPU = gpu ? 1 : 0;
    in.DiffuseUploaded = true;
    in.DiffuseIterations = rp.DiffusionIterations;
    in.DiffuseCoarseIterations = rp.DiffusionCoarseIterations;
    in.DiffuseGridMaximum = rp.DiffusionVolumeMaximumDimension;
    in.DiffuseLights = lightKey;
    ++this->NumberOfDiffusionRebuilds;
  }
  return true;
}
