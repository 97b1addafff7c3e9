/**
 * @struct  vtkAVSPrecomputeInputs
 * @brief   what a lit mapper's precomputed volumes are built from, for one frame (private)
 *
 * vtkAVSVolumeMapper::Prepare fills it after the data and the classification are uploaded and
 * hands it to the subclass's PrepareLighting, whose owner (vtkAVSOcclusionVolume,
 * vtkAVSScatteringVolumes) compares it with the keys it was built for. Everything is borrowed
 * for the call: the owners keep copies of what they compare, never these pointers.
 */
#ifndef vtkAVSPrecomputeInputs_h
#define vtkAVSPrecomputeInputs_h

#include "Grid.h"
#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkAVSRayCaster;
class vtkMatrix4x4;

struct vtkAVSPrecomputeInputs
{
  vtkAVSRayCaster* RayCaster = nullptr; ///< the window's textures and compute passes
  const avs::VolumeScene* Scene = nullptr;
  const avs::ScatteringParameters* Parameters = nullptr; ///< resolved
  /// Versions of the data (scalars, mask) and of what sigma_t depends on besides the data
  /// (opacity, clipping, cropping): a new version invalidates what was built from the old one.
  int DataVersion = 0;
  int OpacityVersion = 0;
  bool PrecomputeOnGPU = true; ///< the mapper's PrecomputeOnGPU
  /// The mapper's EmptySpaceSkipping: the light-volume pass on the GPU leaves out the tiles of
  /// the light grid that nothing reads near the cells that may hold material.
  bool SkipEmptySpace = true;
  /// An interactive frame: lights that follow the camera keep the volume of their last pose.
  bool Interactive = false;
  vtkMatrix4x4* WorldToData = nullptr;
  const std::vector<avs::Light>* WorldLights = nullptr; ///< at most 8, world space
  const std::vector<bool>* FollowsCamera = nullptr;     ///< per light
  /// Distributed rendering: the whole grid of which the data is a piece (the data's own grid
  /// when it is not), the piece's first sample in it, whether it is lit as a piece, and the
  /// version of the pieces' sum (vtkAVSVolumeMapper::UpdatePieceLighting).
  const avs::GridGeometry* Whole = nullptr;
  std::array<int, 3> PieceOffset{ 0, 0, 0 };
  bool LitAsPiece = false;
  int SumVersion = 0;
  /// sigma_t on the data's grid, computed on the CPU when first asked for in a frame.
  std::function<const avs::Grid&()> Extinction;
  /// The whole's averaged extinction on `lightGrid` from the pieces' shares; false with the
  /// reason.
  std::function<bool(const avs::GridGeometry& lightGrid, avs::Grid& averaged, std::string& error)>
    AverageAcrossPieces;
  /// The mapper's UpdateProgress.
  std::function<void(double)> Progress;
  /// The end of one of the render's stages (vtkAVSVolumeMapper::RenderStage), for StageTiming.
  std::function<void(int)> StageDone;
};

#endif
