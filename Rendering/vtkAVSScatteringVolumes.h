/**
 * @class   vtkAVSScatteringVolumes
 * @brief   the precomputed volumes of a vtkAmbientScatteringVolumeMapper (private)
 *
 * Owns ambient scattering's precomputation, each volume with its key, its rebuild (on the GPU
 * when the context can, else on the CPU and uploaded) and its count: the scattering table's
 * slice for the anisotropy and albedo, the averaged extinction on the light grid (over the whole
 * image when the data is a piece of it), one light volume per light, and the extended model's
 * diffuse fluence (ARCHITECTURE.md, "The mapper layer"). A camera move rebuilds nothing, a light
 * move rebuilds that light's volume, a change of data, opacity or parameters what depends on it.
 * Invalidate() forgets what the GPU holds (a released window, a context switch): the next Update
 * rebuilds everything.
 */
#ifndef vtkAVSScatteringVolumes_h
#define vtkAVSScatteringVolumes_h

#include "Grid.h"
#include "LightVolume.h"
#include "Lights.h"
#include "ScatteringTable.h"

#include <array>
#include <string>
#include <vector>

struct vtkAVSPrecomputeInputs;

class vtkAVSScatteringVolumes
{
public:
  /// Brings the volumes up to date for `table` (the loaded scattering table); false with the
  /// reason.
  bool Update(const vtkAVSPrecomputeInputs& inputs,
    const avs::ScatteringTable& table,
    std::string& error);
  void Invalidate();

  /// The light grid of the last build ((2, 2, 2) before the first).
  const std::array<int, 3>& GetLightGridDimensions() const { return this->LightGridDimensions; }
  /// Whether the last light volumes were computed on the GPU.
  bool GetLightVolumesOnGPU() const { return this->LightsOnGPU == 1; }
  int GetNumberOfExtinctionRebuilds() const { return this->ExtinctionRebuilds; }
  int GetNumberOfLightVolumeRebuilds() const { return this->LightVolumeRebuilds; }
  int GetNumberOfDiffusionRebuilds() const { return this->DiffusionRebuilds; }

private:
  bool UpdateSlice(const vtkAVSPrecomputeInputs& inputs,
    const avs::ScatteringTable& table,
    std::string& error);
  bool UpdateAveraged(const vtkAVSPrecomputeInputs& inputs,
    const avs::GridGeometry& lightGrid,
    bool gpu,
    std::string& error);
  /// `rebuilt`: whether a light volume was rebuilt (the fluence's source changed).
  bool UpdateLights(const vtkAVSPrecomputeInputs& inputs,
    const avs::GridGeometry& lightGrid,
    bool gpu,
    bool& rebuilt,
    std::string& error);
  bool UpdateDiffuse(const vtkAVSPrecomputeInputs& inputs,
    const avs::GridGeometry& lightGrid,
    bool gpu,
    bool rebuilt,
    std::string& error);

  // The table slice.
  const avs::ScatteringTable* SliceTable = nullptr;
  double SliceG = 2.0, SliceAlbedo = -1.0;
  avs::ScatteringSlice Slice;
  int SliceVersion = 0;

  // The averaged extinction, on the light grid.
  int AveragedKey[2] = { -1, -1 }; ///< data, opacity versions
  double AveragedRadius = -1.0;
  avs::Grid Averaged; ///< CPU precomputation
  int AveragedVersion = 0;
  int AveragedOnGPU = -1;
  std::array<int, 3> AveragedDimensions{ 0, 0, 0 };     ///< the light grid it was computed on
  std::array<int, 6> AveragedPiece{ 0, 0, 0, 0, 0, 0 }; ///< whole dimensions, piece offset
  int AveragedSum = -1;                                 ///< the pieces' sum it was made from

  // The light volumes.
  struct LightState
  {
    avs::Light DataFrame; ///< the light in the data's frame
    int AveragedVersion = -1;
    int SliceVersion = -1;
    double Radius = -1.0;
    avs::TubeLaw Law = avs::TubeLaw::Forward;
    /// What the light grid's tiles it was marched over were chosen from (GPU path): the
    /// occupancy's version, whether empty space was left out, whether the diffusion's reach was.
    std::array<int, 4> TilesKey{ -1, -1, -1, -1 };
    bool Built = false;
    avs::Grid Volume; ///< CPU path only
  };
  std::vector<LightState> Lights;
  bool LightVolumesUploaded = false;
  int LightsOnGPU = -1;
  int LightGridMaximum = -1;
  std::array<int, 3> LightGridDimensions{ 2, 2, 2 };

  // The extended model's diffuse fluence (for the light volumes of this build).
  bool DiffuseUploaded = false;
  int DiffuseOnGPU = -1;
  int DiffuseIterations = -1;
  int DiffuseCoarseIterations = -1;
  int DiffuseGridMaximum = -1;
  /// The lights the fluence was solved for (its source is their irradiance: a light's intensity,
  /// colour, attenuation or cone changes it without changing a light volume).
  std::vector<double> DiffuseLights;

  int ExtinctionRebuilds = 0;
  int LightVolumeRebuilds = 0;
  int DiffusionRebuilds = 0;
};

#endif
