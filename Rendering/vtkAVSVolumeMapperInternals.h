/**
 * @struct  vtkAVSVolumeMapper::Internals
 * @brief   what every vtkAVSVolumeMapper keeps between frames (private)
 *
 * The ray caster of the mapper's render window and four groups of fields, each written by one
 * source file (ARCHITECTURE.md, "The mapper layer"):
 * - the scene (vtkAVSVolumeMapperData.cxx): what the data, the mask, the property and the clip
 *   region came from, the volume as the core classifies it, the versions that invalidate what
 *   is built from them, and sigma_t on the CPU;
 * - the uploads (vtkAVSVolumeMapper.cxx): what the scalar and classification textures hold;
 * - the pieces (vtkAVSVolumeMapperPieces.cxx): where the input lies in a distributed whole;
 * - the frame (vtkAVSVolumeMapper.cxx): the resolved parameters, transforms and lights.
 * The lit mappers' precomputed volumes are not here: vtkAVSOcclusionVolume and
 * vtkAVSScatteringVolumes own them, held by the mapper that draws with them.
 */
#ifndef vtkAVSVolumeMapperInternals_h
#define vtkAVSVolumeMapperInternals_h

#include "vtkAVSVolumeMapper.h"

#include "Grid.h"
#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "vtkAVSCompositeInput.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSRenderPasses.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

struct vtkAVSVolumeMapper::Internals
{
  vtkAVSRayCaster RayCaster;

  // ---- The scene (vtkAVSVolumeMapperData.cxx) ----
  /// A composite input's image blocks merged into the image drawn (kept while they do not
  /// change).
  vtkAVSCompositeInput CompositeInput;
  std::string ReportedCompositeError; ///< what GetInput last reported of it
  // What the uploaded data came from: the image, the selected array and the selection.
  vtkImageData* DataObject = nullptr;
  vtkMTimeType DataTime = 0;
  vtkDataArray* ArrayObject = nullptr;
  vtkMTimeType ArrayTime = 0;
  vtkAVSDataTranslator::Selection Selection;
  /// The volume as the core classifies it: the grids from the data, the functions from the
  /// property, the clip region (Scalars empty: nothing converted, unless SourceArray is set).
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
  /// association).
  std::vector<std::uint64_t> Fingerprints;
  std::vector<double> ContentKey;
  int FingerprintSlices = 0;
  bool RangeDependent() const
  {
    return this->ScalarInfinities != 0 || !this->Scene.Medium.Validity.Values.empty();
  }
  std::vector<std::array<double, 2>> Ranges; ///< finite range of each component
  vtkImageData* MaskObject = nullptr;        ///< what Scene.Medium.MaskValues came from
  vtkMTimeType MaskTime = 0;
  int ScalarType = 0;
  vtkVolumeProperty* PropertyObject = nullptr;
  vtkMTimeType PropertyTime = 0;
  vtkMTimeType ClassificationTime = 0; ///< this mapper's MTime when the property was converted
  // Versions: a change of a version invalidates what was built from it. ScalarsVersion: the
  // converted scalars (the upload); DataVersion: scalars or mask (sigma_t); TransferVersion: the
  // classification (the upload); OpacityVersion: what sigma_t depends on besides the data
  // (avs::ExtinctionKey and the clip region; a colour change leaves it).
  int ScalarsVersion = 0;
  int DataVersion = 0;
  int TransferVersion = 0;
  int OpacityVersion = 0;
  std::vector<double> ExtinctionInputs;
  int ExtinctionKey[2] = { -1, -1 }; // data, opacity versions of Extinction
  avs::Grid Extinction;

  // ---- The uploads (vtkAVSVolumeMapper.cxx) ----
  /// The versions the scalar and classification textures hold (-1: nothing trusted).
  int UploadedScalarsVersion = -1;
  int UploadedTransferVersion = -1;
  /// The fingerprints and content key of the data the scalar textures hold, set at each upload;
  /// whether it had infinities or NaN (their texels depend on the range, which any slice may
  /// change).
  std::vector<std::uint64_t> UploadedFingerprints;
  std::vector<double> UploadedContentKey;
  bool UploadedRangeDependent = false;
  std::array<int, 3> UploadedPartitions{ 1, 1, 1 }; ///< the Partitions of the last upload
  /// and its look-back voxels per axis (vtkAVSRayCaster::LookBackVoxels)
  std::array<int, 3> UploadedLookBack{ 0, 0, 0 };
  /// Forgets what the textures hold: the next upload writes everything.
  void ForgetUploads();

  // ---- The pieces (vtkAVSVolumeMapperPieces.cxx) ----
  // Distributed rendering: the whole grid of which the input is a piece (the input's own grid
  // when not lit as a piece) and the piece's first sample in it.
  avs::GridGeometry Whole;
  std::array<int, 3> PieceOffset{ 0, 0, 0 };
  /// UpdatePieceLighting: it was called (then rendering never communicates); the sum it made
  /// and its version; this piece's last box and the key of what it was made from.
  bool PieceLightingUpdated = false;
  int SumVersion = 0;
  std::vector<double> ShareKey;
  std::vector<int> SharedBoxes;
  avs::Grid Share;    ///< this piece's share of the averaged extinction (UpdatePieceLighting)
  avs::Grid WholeSum; ///< the pieces' shares summed (UpdatePieceLighting), on the light grid

  // ---- The frame (vtkAVSVolumeMapper.cxx) ----
  vtkNew<vtkMatrix4x4> WorldToIndex;
  vtkNew<vtkMatrix4x4> WorldToData;
  avs::ScatteringParameters Parameters;
  std::vector<avs::Light> WorldLights;
  std::vector<bool> FollowsCamera; ///< per light: a headlight or camera light
  /// The ray-casting pass's measured cost (AutoAdjustSampleDistances); 0: not measured yet.
  double SecondsPerRay = 0.0;
  /// StageTiming: the end of the last stage marked.
  std::chrono::steady_clock::time_point StageMark;
};

/// The frame being drawn (vtkAVSVolumeMapper::Render): its window, its role among the render
/// passes, whether it is interactive, and the ray caster's frame that
/// vtkAVSVolumeMapperFrame.cxx assembles.
struct vtkAVSVolumeMapper::FrameAssembly
{
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkAVSRenderPasses::Role Role = vtkAVSRenderPasses::Role::Composite;
  bool Interactive = false;
  vtkAVSRayCaster::Frame Frame;
};

#endif
