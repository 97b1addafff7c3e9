#include "vtkAVSScatteringVolumes.h"

#include "vtkAVSPrecomputeInputs.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSVolumeMapper.h"

#include "AveragedExtinction.h"
#include "DiffuseFluence.h"
#include "PieceAveraging.h"

#include "vtkMatrix4x4.h"

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

// Whether a light volume marched over the tiles chosen by `built` (vtkAVSScatteringVolumes'
// LightState::TilesKey) holds those that `needed` chooses: all of them, or those of the same
// occupancy with the diffusion's reads, on the same diffusion grid, where they are needed.
bool CoversTiles(const std::array<int, 4>& built, const std::array<int, 4>& needed)
{
  return built[1] == 0 ||
    (needed[1] == 1 && built[0] == needed[0] &&
      (needed[2] == 0 || (built[2] == 1 && built[3] == needed[3])));
}
} // namespace

bool vtkAVSScatteringVolumes::Update(const vtkAVSPrecomputeInputs& inputs,
  const avs::ScatteringTable& table,
  std::string& error)
{
  vtkAVSRayCaster& caster = *inputs.RayCaster;
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  // With compute shaders no extinction grid is needed on the CPU: the averaged extinction asks
  // for sigma_t where it is computed on the CPU (no compute shaders, a piece of a larger whole, a
  // split volume). (The GPU light-volume pass takes tables of up to MaximumTauNodes tau nodes;
  // larger user tables are marched on the CPU.)
  const bool gpu = inputs.PrecomputeOnGPU && caster.SupportsComputeShaders() &&
    table.Axes.NumberOfTau <= vtkAVSRayCaster::MaximumTauNodes;
  if (!this->UpdateSlice(inputs, table, error))
  {
    return false;
  }
  // The averaged extinction and the light volumes share the light grid: over the whole image
  // when the input is a piece of it (vtkAVSVolumeMapperPieces.cxx).
  const avs::GridGeometry lightGrid = inputs.Whole->Capped(rp.LightVolumeMaximumDimension);
  bool rebuilt = false;
  const int lightRebuilds = this->LightVolumeRebuilds;
  if (!this->UpdateAveraged(inputs, lightGrid, gpu, error))
  {
    return false;
  }
  if (inputs.StageDone)
  {
    inputs.StageDone(vtkAVSVolumeMapper::AveragedExtinctionStage);
  }
  if (!this->UpdateLights(inputs, lightGrid, gpu, rebuilt, error))
  {
    return false;
  }
  if (inputs.StageDone)
  {
    inputs.StageDone(vtkAVSVolumeMapper::LightVolumeStage);
  }
  if (!this->UpdateDiffuse(inputs, lightGrid, gpu, rebuilt, error))
  {
    return false;
  }
  if (inputs.StageDone)
  {
    inputs.StageDone(vtkAVSVolumeMapper::DiffusionStage);
  }
  if (this->LightVolumeRebuilds != lightRebuilds)
  {
    inputs.Progress(1.0); // the light volumes' progress (and the fluence after them) done
  }
  return true;
}

void vtkAVSScatteringVolumes::Invalidate()
{
  this->SliceTable = nullptr;
  this->AveragedRadius = -1.0;
  this->LightVolumesUploaded = false;
  this->DiffuseUploaded = false;
}

bool vtkAVSScatteringVolumes::UpdateSlice(const vtkAVSPrecomputeInputs& inputs,
  const avs::ScatteringTable& table,
  std::string& error)
{
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  if (&table != this->SliceTable || rp.Anisotropy != this->SliceG || rp.Albedo != this->SliceAlbedo)
  {
    this->Slice = table.Slice(rp.Anisotropy, rp.Albedo);
    if (!inputs.RayCaster->UploadTableSlice(this->Slice, error))
    {
      return false;
    }
    this->SliceTable = &table;
    this->SliceG = rp.Anisotropy;
    this->SliceAlbedo = rp.Albedo;
    ++this->SliceVersion;
  }
  return true;
}

bool vtkAVSScatteringVolumes::UpdateAveraged(const vtkAVSPrecomputeInputs& inputs,
  const avs::GridGeometry& lightGrid,
  bool gpuScattering,
  std::string& error)
{
  vtkAVSRayCaster& caster = *inputs.RayCaster;
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  const avs::GridGeometry& g = inputs.Scene->Scalars.Geometry;
  const std::array<int, 6> piece{ inputs.Whole->Dimensions[0],
    inputs.Whole->Dimensions[1],
    inputs.Whole->Dimensions[2],
    inputs.PieceOffset[0],
    inputs.PieceOffset[1],
    inputs.PieceOffset[2] };
  // The GPU pass reads the unsplit scalars' texture: a split volume's is computed on the CPU
  // (its box sums would need every brick; ARCHITECTURE.md, "Bricking").
  const bool gpu = gpuScattering && !caster.IsBricked();
  if (this->AveragedKey[0] == inputs.DataVersion && this->AveragedKey[1] == inputs.OpacityVersion &&
    this->AveragedRadius == rp.AmbientRadius && this->AveragedOnGPU == (gpu ? 1 : 0) &&
    this->AveragedDimensions == lightGrid.Dimensions && this->AveragedPiece == piece &&
    this->AveragedSum == inputs.SumVersion)
  {
    return true;
  }
  if (inputs.LitAsPiece)
  {
    // The pieces' shares summed (by UpdatePieceLighting, before the render), on the light grid
    // that the rays and the light-volume pass read.
    if (!inputs.AverageAcrossPieces(lightGrid, this->Averaged, error) ||
      !caster.UploadAveraged(this->Averaged, error))
    {
      return false;
    }
  }
  else if (gpu)
  {
    if (!caster.ComputeAveragedExtinction(g.Dimensions,
          lightGrid.Dimensions,
          avs::AveragingHalfWidths(rp.AmbientRadius, g.Spacing),
          inputs.Scene->Clip,
          error))
    {
      return false;
    }
  }
  else
  {
    this->Averaged = avs::AverageExtinctionOn(inputs.Extinction(), rp.AmbientRadius, lightGrid);
    if (!caster.UploadAveraged(this->Averaged, error))
    {
      return false;
    }
  }
  this->AveragedKey[0] = inputs.DataVersion;
  this->AveragedKey[1] = inputs.OpacityVersion;
  this->AveragedOnGPU = gpu ? 1 : 0;
  this->AveragedRadius = rp.AmbientRadius;
  this->AveragedDimensions = lightGrid.Dimensions;
  this->AveragedPiece = piece;
  this->AveragedSum = inputs.SumVersion;
  ++this->AveragedVersion;
  ++this->ExtinctionRebuilds;
  return true;
}

bool vtkAVSScatteringVolumes::UpdateLights(const vtkAVSPrecomputeInputs& inputs,
  const avs::GridGeometry& lightGrid,
  bool gpu,
  bool& rebuilt,
  std::string& error)
{
  vtkAVSRayCaster& caster = *inputs.RayCaster;
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  if (this->LightGridMaximum != rp.LightVolumeMaximumDimension ||
    this->LightsOnGPU != (gpu ? 1 : 0))
  {
    this->Lights.clear();
    this->LightGridMaximum = rp.LightVolumeMaximumDimension;
    this->LightsOnGPU = gpu ? 1 : 0;
    this->LightVolumesUploaded = false;
  }
  this->LightGridDimensions = lightGrid.Dimensions;
  const std::vector<avs::Light>& worldLights = *inputs.WorldLights;
  const std::size_t n = worldLights.size();
  bool changed = this->Lights.size() != n || !this->LightVolumesUploaded;
  rebuilt = changed; // a light volume was rebuilt (on the CPU or the GPU)
  this->Lights.resize(n);
  // On the GPU the tiles of the light grid that something reads are marched (a light volume
  // marched over tiles chosen otherwise is not current); a piece of a distributed volume
  // marches the whole grid, which every rank's diffusion reads.
  const bool skipEmpty = inputs.SkipEmptySpace && !inputs.LitAsPiece;
  const bool diffusion = rp.Model == avs::ScatteringModel::Extended;
  const std::array<int, 4> tilesKey{ gpu && skipEmpty ? caster.GetOccupancyVersion() : -2,
    gpu && skipEmpty ? 1 : 0,
    gpu && skipEmpty && diffusion ? 1 : 0,
    gpu && skipEmpty && diffusion ? rp.DiffusionVolumeMaximumDimension : 0 };
  for (std::size_t j = 0; j < n; ++j)
  {
    avs::Light dataLight = worldLights[j];
    dataLight.Position = Transform(inputs.WorldToData, dataLight.Position);
    dataLight.FocalPoint = Transform(inputs.WorldToData, dataLight.FocalPoint);
    auto& state = this->Lights[j];
    const avs::TubeLaw law =
      avs::TubeLawFor(rp.Model == avs::ScatteringModel::Extended, dataLight.Type);
    const bool current = state.Built && state.AveragedVersion == this->AveragedVersion &&
      state.SliceVersion == this->SliceVersion && state.Radius == rp.AmbientRadius &&
      state.Law == law && CoversTiles(state.TilesKey, tilesKey);
    // While interacting, a light that follows the camera keeps the volume of its last pose (the
    // still frame rebuilds it): only the pose is stale, and it moves with every camera move.
    const bool keep = inputs.Interactive && current && (*inputs.FollowsCamera)[j] &&
      state.DataFrame.Type == dataLight.Type;
    if (!current || (!SamePose(state.DataFrame, dataLight) && !keep))
    {
      inputs.Progress(static_cast<double>(j) / n);
      if (gpu)
      {
        if (!caster.UpdateLightTiles(
              lightGrid, dataLight, rp, diffusion, skipEmpty, this->AveragedVersion, error) ||
          !caster.ComputeLightVolume(
            static_cast<int>(j), lightGrid, dataLight, rp.AmbientRadius, law, error))
        {
          return false;
        }
      }
      else
      {
        const auto& progress = inputs.Progress;
        state.Volume = avs::ComputeLightVolume(
          this->Averaged,
          lightGrid,
          dataLight,
          this->Slice,
          rp.AmbientRadius,
          nullptr,
          [&progress, j, n](double v) { progress((j + v) / static_cast<double>(n)); },
          law);
        changed = true;
      }
      state.DataFrame = dataLight;
      state.AveragedVersion = this->AveragedVersion;
      state.SliceVersion = this->SliceVersion;
      state.Radius = rp.AmbientRadius;
      state.Law = law;
      state.TilesKey = tilesKey;
      state.Built = true;
      rebuilt = true;
      ++this->LightVolumeRebuilds;
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
    for (const auto& state : this->Lights)
    {
      volumes.push_back(state.Volume);
    }
    if (!caster.UploadLightVolumes(volumes, error))
    {
      return false;
    }
  }
  this->LightVolumesUploaded = true;
  // The averaged extinction beside the lights' channels, where there is room (1-3, 5-7 lights).
  return caster.PackAveraged(static_cast<int>(n), error);
}

bool vtkAVSScatteringVolumes::UpdateDiffuse(const vtkAVSPrecomputeInputs& inputs,
  const avs::GridGeometry& lightGrid,
  bool gpu,
  bool rebuilt,
  std::string& error)
{
  vtkAVSRayCaster& caster = *inputs.RayCaster;
  const avs::ScatteringParameters& rp = *inputs.Parameters;
  // The extended model: the diffuse fluence from the light volumes (DiffuseFluence.h).
  if (rp.Model != avs::ScatteringModel::Extended)
  {
    this->DiffuseUploaded = false;
    return true;
  }
  std::vector<double> lightKey;
  for (const auto& state : this->Lights)
  {
    const avs::Light& l = state.DataFrame;
    for (const avs::Vec3& v : { l.Position, l.FocalPoint, l.Irradiance, l.Attenuation })
    {
      lightKey.insert(lightKey.end(), { v.x, v.y, v.z });
    }
    lightKey.insert(lightKey.end(),
      { static_cast<double>(l.Type), l.ConeAngle, l.Exponent, rp.Albedo, rp.Anisotropy });
  }
  std::vector<avs::Light> lights;
  for (const auto& state : this->Lights)
  {
    lights.push_back(state.DataFrame);
  }
  if (!rebuilt && this->DiffuseUploaded && this->DiffuseOnGPU == (gpu ? 1 : 0) &&
    this->DiffuseLights == lightKey && this->DiffuseIterations == rp.DiffusionIterations &&
    this->DiffuseCoarseIterations == rp.DiffusionCoarseIterations &&
    this->DiffuseGridMaximum == rp.DiffusionVolumeMaximumDimension)
  {
    // (The fluence beside the lights where it fits, again where their textures were remade.)
    return caster.PackFluence(lights, error);
  }
  std::vector<avs::Grid> volumes;
  for (const auto& state : this->Lights)
  {
    volumes.push_back(state.Volume);
  }
  vtkAVSDiffuseVolume& diffuse = caster.GetDiffuseVolume();
  // The packed fluence is read by the rays alone: where they read the light volumes, and with
  // anisotropic scattering also at the group before a sample (phi's slope), which may lie
  // farther from the material (then every tile: an empty list).
  const bool packRays = inputs.SkipEmptySpace && !inputs.LitAsPiece && rp.Anisotropy == 0.0;
  const bool done = gpu
    ? diffuse.Compute(caster.GetWindow(),
        avs::DiffusionGeometry(lightGrid, rp.DiffusionVolumeMaximumDimension),
        lightGrid.Dimensions,
        packRays ? caster.RayTiles(lightGrid, true) : std::vector<std::uint32_t>(),
        caster.GetAveragedExtinctionTexture(),
        caster.GetLightVolumeTexture(0),
        caster.GetLightVolumeTexture(1),
        lights,
        rp,
        this->AveragedVersion,
        error)
    : diffuse.Upload(caster.GetWindow(),
        avs::ComputeDiffuse(this->Averaged, lights, volumes, rp),
        this->Averaged,
        error);
  if (!done)
  {
    return false;
  }
  this->DiffuseOnGPU = gpu ? 1 : 0;
  this->DiffuseUploaded = true;
  this->DiffuseIterations = rp.DiffusionIterations;
  this->DiffuseCoarseIterations = rp.DiffusionCoarseIterations;
  this->DiffuseGridMaximum = rp.DiffusionVolumeMaximumDimension;
  this->DiffuseLights = lightKey;
  ++this->DiffusionRebuilds;
  // With lights of one colour, the fluence as one number beside them, for one fetch fewer.
  return caster.PackFluence(lights, error);
}
