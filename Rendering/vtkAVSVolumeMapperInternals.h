/**
 * @struct  vtkAVSVolumeMapper::Internals
 * @brief   what vtkAVSVolumeMapper keeps between frames (private)
 *
 * The ray caster of the mapper's render window, what the uploaded data and classification came
 * from (objects and modification times), the versions of the derived volumes and the keys each
 * precomputed volume was built for (vtkAVSVolumeMapperPrecompute.cxx compares them), and the
 * frame's resolved parameters, transform and lights. Shared by vtkAVSVolumeMapper.cxx and
 * vtkAVSVolumeMapperPrecompute.cxx.
 */
#ifndef vtkAVSVolumeMapperInternals_h
#define vtkAVSVolumeMapperInternals_h

#include "vtkAVSVolumeMapper.h"

#include "Grid.h"
#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSRayCaster.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <cstdint>
#include <vector>

struct vtkAVSVolumeMapper::Internals
{
  vtkAVSRayCaster RayCaster;

  // What the uploaded data came from: the image, the selected array and the selection.
  vtkImageData* DataObject = nullptr;
  vtkMTimeType DataTime = 0;
  vtkDataArray* ArrayObject = nullptr;
  vtkMTimeType ArrayTime = 0;
  vtkAVSDataTranslator::Selection Selection;
  /// The volume as the core classifies it: the grids from the data, the functions from the
  /// property (Scalars empty: nothing converted, unless SourceArray is set).
  avs::VolumeScene Scene;
  /// Where the scalars' values stay when the scene's grids hold only their geometry
  /// (vtkAVSDataTranslator::Volume::Deferred): the GPU upload reads them from the array, slab by
  /// slab, and EnsureHostScalars copies them for the CPU's precomputation. Null when the grids
  /// hold the values (NaN data, arrays of another memory layout).
  vtkSmartPointer<vtkDataArray> SourceArray;
  vtkIdType ScalarInfinities = 0; ///< infinite values the conversion clamps
  /// What UploadScalars reads where the grids are empty.
  vtkAVSVolumeTextures::ScalarSource ScalarSource() const;
  /// Fills the scene's grids from SourceArray (the CPU's precomputation needs them); kept until
  /// the data changes.
  void EnsureHostScalars();
  /// What a new time step did not change (Fingerprint.h): the fingerprints of the converted
  /// array's memory in slabs of FingerprintSlices slices (empty where the array has no standard
  /// memory layout; FingerprintSlices 0 where the slabs are not slices of the texture), and what
  /// else its conversion depends on (ContentKey: the grid, the array's type, size and
  /// association); those of the data the scalar textures hold, set at each upload and
  /// cleared when the textures are released.
  std::vector<std::uint64_t> Fingerprints, UploadedFingerprints;
  std::vector<double> ContentKey, UploadedContentKey;
  int FingerprintSlices = 0;
  /// Whether the uploaded data had infinities or NaN (their texels depend on the range, which
  /// any slice may change).
  bool UploadedRangeDependent = false;
  bool RangeDependent() const
  {
    return this->ScalarInfinities != 0 || !this->Scene.Medium.Validity.Values.empty();
  }
  /// Forgets what the textures hold: the next upload writes everything.
  void ForgetUploadedContent()
  {
    this->UploadedFingerprints.clear();
    this->UploadedContentKey.clear();
  }
  std::vector<std::array<double, 2>> Ranges; ///< finite range of each component
  vtkImageData* MaskObject = nullptr;        ///< what Scene.Medium.MaskValues came from
  vtkMTimeType MaskTime = 0;
  int ScalarType = 0;
  bool ScalarsUploaded = false;
  std::array<int, 3> UploadedPartitions{ 1, 1, 1 }; ///< the Partitions of the last upload
  /// and its look-back voxels per axis (vtkAVSRayCaster::LookBackVoxels)
  std::array<int, 3> UploadedLookBack{ 0, 0, 0 };

  vtkVolumeProperty* PropertyObject = nullptr;
  vtkMTimeType PropertyTime = 0;
  vtkMTimeType ClassificationTime = 0; ///< this mapper's MTime when the property was converted
  bool TransferUploaded = false;

  // Versions of the derived volumes: a change of a version invalidates what uses it.
  int DataVersion = 0;
  int TransferVersion = 0;
  int ExtinctionKey[2] = { -1, -1 }; // data, opacity versions of Extinction
  // What sigma_t depends on besides the data (avs::ExtinctionKey), and its version (a colour
  // change leaves it).
  int OpacityVersion = 0;
  std::vector<double> ExtinctionInputs;
  avs::Grid Extinction;

  // Ambient scattering.
  int AveragedKey[2] = { -1, -1 };
  double AveragedRadius = -1.0;
  avs::Grid Averaged; ///< on the light grid (CPU precomputation)
  int AveragedVersion = 0;
  int AveragedOnGPU = -1;
  std::array<int, 3> AveragedDimensions{ 0, 0, 0 };     ///< the light grid it was computed on
  std::array<int, 6> AveragedPiece{ 0, 0, 0, 0, 0, 0 }; ///< whole dimensions, piece offset
  const avs::ScatteringTable* SliceTable = nullptr;
  double SliceG = 2.0, SliceAlbedo = -1.0;
  avs::ScatteringSlice Slice;
  int SliceVersion = 0;
  int LightGridMaximum = -1;
  struct LightState
  {
    avs::Light DataFrame; ///< the light in the data's frame
    int AveragedVersion = -1;
    int SliceVersion = -1;
    double Radius = -1.0;
    avs::TubeLaw Law = avs::TubeLaw::Forward;
    bool Built = false;
    avs::Grid Volume; ///< CPU path only
  };
  std::vector<LightState> Lights;
  bool LightVolumesUploaded = false;
  int LightsOnGPU = -1;
  std::array<int, 3> LightGridDimensions{ 2, 2, 2 };

  // The extended model's diffuse fluence (uploaded for the light volumes of this build).
  bool DiffuseUploaded = false;
  int DiffuseOnGPU = -1;
  int DiffuseIterations = -1;
  int DiffuseCoarseIterations = -1;
  int DiffuseGridMaximum = -1;
  /// The lights the fluence was solved for (its source is their irradiance: a light's intensity,
  /// colour, attenuation or cone changes it without changing a light volume).
  std::vector<double> DiffuseLights;

  // Ambient occlusion.
  std::array<int, 3> OcclusionDimensions{ 0, 0, 0 };
  int OcclusionKey[2] = { -1, -1 };
  double OcclusionRadius = -1.0;
  int OcclusionDirections = -1;
  bool OcclusionUploaded = false;

  // Distributed rendering: the whole grid of which the input is a piece (the input's own grid
  // when not lit as a piece) and the piece's first sample in it.
  avs::GridGeometry Whole;
  std::array<int, 3> PieceOffset{ 0, 0, 0 };
  /// UpdatePieceLighting: it was called (then rendering never communicates); the sum it made
  /// (in Averaged) and its version; this piece's last box and the key of what it was made from.
  bool PieceLightingUpdated = false;
  int SumVersion = 0;
  int AveragedSum = -1;
  std::vector<double> ShareKey;
  std::vector<int> SharedBoxes;
  avs::Grid Share;    ///< this piece's share of the averaged extinction (UpdatePieceLighting)
  avs::Grid WholeSum; ///< the pieces' shares summed (UpdatePieceLighting), on the light grid

  vtkNew<vtkMatrix4x4> WorldToIndex;
  vtkNew<vtkMatrix4x4> WorldToData;
  avs::ScatteringParameters Parameters;
  std::vector<avs::Light> WorldLights;
  std::vector<bool> FollowsCamera; ///< per light: a headlight or camera light

  /// The ray-casting pass's measured cost (AutoAdjustSampleDistances); 0: not measured yet.
  double SecondsPerRay = 0.0;
};

#endif
