/**
 * @class   vtkAVSVolumeMapper
 * @brief   the GPU ray-casting machinery shared by the module's three volume mappers
 *
 * Abstract base of vtkEmissionAbsorptionVolumeMapper, vtkAmbientOcclusionVolumeMapper and
 * vtkAmbientScatteringVolumeMapper. It renders vtkImageData (point or cell scalars of any type,
 * 1-4 components, selected as vtkGPUVolumeRayCastMapper selects them with ScalarMode and
 * SelectScalarArray; origin, spacing, extent and direction matrix honoured; the vtkVolume's
 * transform applied) with the vtkVolumeProperty's colour and scalar-opacity functions and unit
 * distances, component modes and weights, gradient opacity and interpolation type,
 * by a full-screen GPU ray caster that clips rays to the volume box and to the depth of opaque
 * geometry drawn before, and composites its premultiplied result over the framebuffer as VTK's
 * own mappers do. The camera may be inside the volume; perspective and parallel projections,
 * window resizes and several render windows work.
 *
 * Composite inputs: a vtkMultiBlockDataSet, vtkPartitionedDataSet or
 * vtkPartitionedDataSetCollection whose non-empty leaves are vtkImageData pieces of one grid
 * (the same spacing and direction; extents, or origins that differ by whole voxels, on one
 * lattice; together filling a box) is drawn as the one image they make: their arrays are copied
 * into one image (kept while no block changes; one block is used as it is), so light and shadows
 * cross the blocks as if the volume had never been split. Blocks that are not images, of
 * other spacings (AMR levels) or that leave part of their box empty are an error naming them.
 * Across processes each process's blocks make its piece (see WholeExtent).
 *
 * Precomputed volumes (averaged extinction, light volumes, ambient occlusion) are rebuilt only
 * when their inputs change: a camera move only re-renders, a light move rebuilds that light's
 * volume, a change of data, transfer function or medium parameters rebuilds what depends on it.
 * The counters below say how often each happened.
 *
 * Interaction works as with vtkGPUVolumeRayCastMapper: with AutoAdjustSampleDistances on (the
 * default), a frame whose volume is allotted less than a second (VTK's test for an interactive
 * render: vtkRenderWindowInteractor's DesiredUpdateRate, 15 frames per second, while a mouse
 * button is down; its StillUpdateRate gives the still frame thousands of seconds) casts fewer
 * rays, chosen from the measured time of earlier frames to fit the allotted time, within
 * [MinimumImageSampleDistance, MaximumImageSampleDistance], and composites them upscaled; and
 * the light volumes of lights that follow the camera (headlights, camera lights, a light kit)
 * are kept from the last still frame instead of rebuilt on every camera move (a moved scene
 * light, or a change of data, transfer function or parameters, still rebuilds during
 * interaction). The still frame renders at MinimumImageSampleDistance (1: exact) and rebuilds
 * the light volumes that became stale, so it is the frame a render without interaction gives.
 *
 * Clipping planes (vtkAbstractMapper::ClippingPlanes, at most 8, in world coordinates) and
 * cropping (vtkVolumeMapper's Cropping, CroppingRegionPlanes in data coordinates along the
 * image's axes, CroppingRegionFlags and their presets) remove material for every purpose: the
 * rays, the averaged extinction, the light volumes and the occlusion volume, so light enters
 * through a cut. Moving a plane, or the volume against the planes, rebuilds what depends on the
 * extinction (the counters show it). Blend modes: vtkEmissionAbsorptionVolumeMapper renders
 * composite, maximum, minimum and average intensity (with AverageIPScalarRange), additive and
 * isosurface as vtkGPUVolumeRayCastMapper does unshaded, on one-component data (the first
 * component's transfer functions; gradient opacity and masks apply to composite only); the
 * ambient-occlusion and ambient-scattering mappers render composite only, and any other mode
 * (slice for all three) is a vtkErrorMacro naming the mode, with nothing drawn.
 *
 * NaN voxels are empty space and infinities are clamped to the finite range, with one warning
 * that counts them. The property's shading flags (ShadeOn, ambient, diffuse, specular) do not
 * change the emission-absorption and ambient-occlusion pictures (a warning says so); ambient
 * scattering shades surfaces inside the medium with them
 * (vtkAmbientScatteringVolumeMapper::SetVolumetricScatteringBlending).
 *
 * Bad input — no or empty image, no such array, more than four components, three dependent
 * components, bad spacing, a volume too large for the GPU, more than 8 clipping planes or one
 * with a zero normal, a blend mode other than composite on data of several components — gives
 * a vtkErrorMacro and draws nothing.
 */
#ifndef vtkAVSVolumeMapper_h
#define vtkAVSVolumeMapper_h

#include "vtkRenderingAmbientScatteringModule.h" // for export macro
#include "vtkVolumeMapper.h"

#include <array>  // for std::array
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace avs
{
struct DisplayTransform;
struct Grid;
struct GridGeometry;
struct ScatteringParameters;
}
struct vtkAVSPrecomputeInputs;

class vtkDataObjectTree;
class vtkFloatArray;
class vtkImageData;
class vtkMatrix4x4;
class vtkMultiProcessController;
class vtkVolumeProperty;

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkAVSVolumeMapper : public vtkVolumeMapper
{
public:
  vtkTypeMacro(vtkAVSVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Ray-marching step in data units (the volume's coordinates before the vtkVolume's matrix:
   * world units for an untransformed volume), as vtkGPUVolumeRayCastMapper's. Opacity is
   * integrated in data units too, so a scaled vtkVolume renders as the unscaled one magnified.
   * Default 0: half the smallest voxel spacing. Not used when LockSampleDistanceToInputSpacing
   * is on.
   */
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /**
   * If on (the default), the image sample distance is varied to fit the render time allotted
   * to the volume (vtkProp::GetAllocatedRenderTime(): the render window's desired update rate,
   * which vtkRenderWindowInteractor raises to its DesiredUpdateRate while interacting, shared
   * among the renderers and props), within [MinimumImageSampleDistance,
   * MaximumImageSampleDistance], and frames allotted less than a second count as interactive:
   * they keep the light volumes of camera-following lights (see the class documentation). Off:
   * every frame renders at ImageSampleDistance and rebuilds what is stale.
   *
   * As VTK's documentation describes it. Two differences from vtkOpenGLGPUVolumeRayCastMapper
   * (VTK 9.1), whose auto-adjustment lengthens the ray step (to the smallest spacing over its
   * reduction factor, ignoring SampleDistance) and leaves the picture's size alone: here the
   * number of rays is adjusted and the step stays SampleDistance (an interactive picture is
   * the still picture at a lower resolution); and ImageSampleDistance keeps the value set (the
   * distance in use is GetLastImageSampleDistance()), so switching this off returns to it.
   */
  vtkSetClampMacro(AutoAdjustSampleDistances, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkBooleanMacro(AutoAdjustSampleDistances, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Pixels per ray along each axis when AutoAdjustSampleDistances is off: 1 (the default) casts
   * one ray per pixel, 2 one ray for every 2 x 2 pixels (the picture is composited from them,
   * interpolated bilinearly), 0.5 four rays per pixel. Range [0.1, 100].
   */
  vtkSetClampMacro(ImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(ImageSampleDistance, float);
  ///@}

  ///@{
  /**
   * The range of the image sample distance when AutoAdjustSampleDistances is on: still frames
   * render at the minimum (default 1), interactive frames at most at the maximum (default 10).
   * Range [0.1, 100] each.
   */
  vtkSetClampMacro(MinimumImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(MinimumImageSampleDistance, float);
  vtkSetClampMacro(MaximumImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(MaximumImageSampleDistance, float);
  ///@}

  /**
   * The image sample distance the last frame was rendered at (1 before the first frame).
   */
  vtkGetMacro(LastImageSampleDistance, float);

  ///@{
  /**
   * Compute the ray step from the data's spacing instead of SampleDistance, as VTK's
   * vtkVolumeMapper::SpacingAdjustedSampleDistance does: half the mean spacing, shrunk for
   * volumes of fewer than 100 voxels per axis (about 1/200 of the mean spacing for 2 x 2 x 2
   * voxels). Off by default. (vtkOpenGLGPUVolumeRayCastMapper applies it only when
   * AutoAdjustSampleDistances is off; here the step is never auto-adjusted, so it always
   * applies.)
   */
  vtkSetClampMacro(LockSampleDistanceToInputSpacing, vtkTypeBool, 0, 1);
  vtkGetMacro(LockSampleDistanceToInputSpacing, vtkTypeBool);
  vtkBooleanMacro(LockSampleDistanceToInputSpacing, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Jitter the first sample of each ray against wood-grain artefacts. Default on.
   */
  vtkSetClampMacro(UseJittering, vtkTypeBool, 0, 1);
  vtkGetMacro(UseJittering, vtkTypeBool);
  vtkBooleanMacro(UseJittering, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Early ray termination: rays stop when their transmittance falls below this. Default 1/255.
   */
  vtkSetClampMacro(TerminationTransmittance, double, 0.0, 1.0);
  vtkGetMacro(TerminationTransmittance, double);
  ///@}

  ///@{
  /**
   * The display transform: what the framebuffer receives of the linear radiance the rays
   * integrate (ALGORITHM.md section 1, "Display"). Exposure is a factor on the radiance (>= 0);
   * then the tone curve, ToneMapping: ClampToneMapping (the radiance as it is, which the
   * framebuffer clamps at 1) or ShoulderToneMapping (linear up to 0.8, then a shoulder that
   * approaches 1 without reaching it, applied to the largest of R, G and B so that hue and
   * saturation stay: highlights compress instead of burning out). Applied once, where each ray
   * ends (for a split volume or another image sample distance, to the composited rays), before
   * the volume is composited over what the renderer drew: geometry is not touched. Under a
   * vtkToneMappingPass the volume hands over its radiance times the exposure, without its tone
   * curve: the pass maps the whole picture.
   *
   * Defaults: the identity (exposure 1, clamp) for the emission-absorption and
   * ambient-occlusion mappers, whose colours do not exceed the transfer function's;
   * vtkAmbientScatteringVolumeMapper sets its own (see there).
   */
  vtkSetClampMacro(Exposure, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Exposure, double);
  enum
  {
    ClampToneMapping = 0,
    ShoulderToneMapping = 1
  };
  vtkSetClampMacro(ToneMapping, int, ClampToneMapping, ShoulderToneMapping);
  vtkGetMacro(ToneMapping, int);
  void SetToneMappingToClamp() { this->SetToneMapping(ClampToneMapping); }
  void SetToneMappingToShoulder() { this->SetToneMapping(ShoulderToneMapping); }
  const char* GetToneMappingAsString()
  {
    return this->ToneMapping == ShoulderToneMapping ? "Shoulder" : "Clamp";
  }
  ///@}

  ///@{
  /**
   * Auto exposure: the exposure applied is Exposure times a factor metered from the light the
   * medium receives: 4 pi over the mean luminance of the lights' summed irradiance (VTK's units,
   * 4 pi x intensity x colour x LightScale, with attenuation and cones) over the volume's box,
   * unshadowed. One white light of intensity 1 meters 1; lights of intensity 40, or a
   * LightScale of 40, meter 1/40. The meter does not depend on the camera, nor on the light's
   * direction, so an orbit with a headlight or a light kit keeps the exposure (as do the
   * interactor's reduced frames); it changes when the lights' intensities, colours, attenuation
   * or cones change, or a positional light moves against the volume. The emission-absorption
   * and ambient-occlusion mappers are not lit by the lights: their factor is 1. Default off.
   */
  vtkSetClampMacro(AutoExposure, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoExposure, vtkTypeBool);
  vtkBooleanMacro(AutoExposure, vtkTypeBool);
  ///@}

  /**
   * The exposure the last frame applied (Exposure, times the metered factor with AutoExposure
   * on); 0 before the first frame.
   */
  vtkGetMacro(LastExposure, double);

  /**
   * The tone curve the last frame applied: ToneMapping, or ClampToneMapping (none) where the
   * renderer's passes hold a vtkToneMappingPass, which maps the picture itself; -1 before the
   * first frame.
   */
  vtkGetMacro(LastToneMapping, int);

  ///@{
  /**
   * Compute the averaged extinction, the light volumes and the occlusion volume on the GPU
   * (compute shaders, OpenGL 4.3) when the context allows; otherwise, or when off, the CPU
   * computes them (multi-threaded). Default on.
   */
  vtkSetMacro(PrecomputeOnGPU, vtkTypeBool);
  vtkGetMacro(PrecomputeOnGPU, vtkTypeBool);
  vtkBooleanMacro(PrecomputeOnGPU, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Leap over empty space: a coarse grid of the volume (cells of 8^3 voxels) says where no
   * sample can have opacity for the current transfer functions, and rays leap over those cells
   * to the first of their own samples beyond them, so the picture is the one without it. Built
   * when the data or the opacity change, never for a camera move; conservative (gradient
   * opacity, masks, clipping and cropping only make space emptier). The blend modes other than
   * composite read every sample and do not leap. Default on; off is for comparing.
   */
  vtkSetMacro(EmptySpaceSkipping, vtkTypeBool);
  vtkGetMacro(EmptySpaceSkipping, vtkTypeBool);
  vtkBooleanMacro(EmptySpaceSkipping, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The share of the grid's cells that were empty for the last frame's transfer functions
   * (0 before the first frame), and whether the last frame leapt over them.
   */
  vtkGetMacro(LastEmptyCellFraction, double);
  vtkGetMacro(LastSkippedEmptySpace, vtkTypeBool);
  ///@}

  /**
   * The share of the volume's voxels that the last frame's upload of the data wrote to the
   * GPU (0 when the frame uploaded no data). New data (a time step) is compared with the uploaded
   * data slab by slab of slices, by 64-bit fingerprints of the array's memory: data equal to what
   * is uploaded (a static series, a step shown again) uploads and rebuilds nothing, and where only
   * some slices changed, only those are written again (and only the bricks that hold them), into
   * the textures already allocated. Bricks count their shared and ghost layers.
   */
  vtkGetMacro(LastDataUploadFraction, double);

  /**
   * A render's stages, for GetLastStageSeconds: the input's conversion and fingerprints
   * (InputStage); the uploads of the data, the classification and the surfaces' gradient
   * (UploadStage); the averaged extinction (AveragedExtinctionStage); the light volumes, or the
   * ambient-occlusion volume (LightVolumeStage); the extended model's diffusion
   * (DiffusionStage); the frame: its assembly and the ray-casting pass (FrameStage).
   */
  enum RenderStage
  {
    InputStage = 0,
    UploadStage,
    AveragedExtinctionStage,
    LightVolumeStage,
    DiffusionStage,
    FrameStage,
    NumberOfRenderStages
  };

  ///@{
  /**
   * Timing of each render's stages, for profiling (off by default). When on, a render waits for
   * the GPU at the end of each stage, so it is a little slower, and GetLastStageSeconds(stage)
   * is the wall time the last render spent in that stage (0 for a stage it did not run, and
   * when off). avs-bench-mappers --time-series prints a time step's breakdown with it.
   */
  vtkSetMacro(StageTiming, vtkTypeBool);
  vtkGetMacro(StageTiming, vtkTypeBool);
  vtkBooleanMacro(StageTiming, vtkTypeBool);
  double GetLastStageSeconds(int stage) const;
  /// The stage's name ("input", "upload", "averaged_extinction", "light_volumes", "diffusion",
  /// "frame"); "" for a number that is no stage.
  static const char* GetRenderStageName(int stage);
  ///@}

  /**
   * Ambient scattering's path-traced refinement (vtkAmbientScatteringVolumeMapper::
   * SetPathTracedRefinement): the path-traced samples per pixel taken since the last change
   * (0 when off, and for the other mappers).
   */
  int GetSamplesPerPixel();

  /**
   * The path-traced refinement's buffers, for measurements and tests: the ambient-scattering
   * picture the refinement started from, the running mean of the path tracer's samples and the
   * mean of their squares, each a 4-component array of the viewport's pixels (bottom row first;
   * premultiplied linear radiance, and alpha: 1 - transmittance, the share of camera rays that
   * met the medium). False when there is no sample yet. Makes the render window's context
   * current.
   */
  bool GetRefinementBuffers(vtkFloatArray* ambient,
    vtkFloatArray* mean,
    vtkFloatArray* meanOfSquares);

  ///@{
  /**
   * Distributed rendering (ParaView's pvserver and pvbatch under MPI, or any application whose
   * processes render one piece of an image each and composite the pictures): WholeExtent is the
   * extent of the whole image of which the input is a piece (VTK's extents are global, so the
   * input's extent lies inside it), Controller the processes that render the pieces.
   *
   * When the whole extent is larger than the input's, ambient scattering lights the piece as a
   * part of the whole: the automatic ambient radius and the light grid are the whole image's,
   * each process adds its share of the averaged extinction on that grid to the others'
   * (UpdatePieceLighting, called on every process before each render: one
   * vtkMultiProcessController::AllReduce of at most LightVolumeMaximumDimension^3 floats and an
   * AllGather of the pieces' extents when the data, transfer function, clipping or radius
   * changed), and every process marches the light volumes through the whole, so light and
   * shadows cross the pieces' boundaries. Samples that pieces share (the common face of point
   * data, ghost layers) count once, for the piece of lowest rank. A piece's share is computed on
   * the CPU; the light volumes and the extended model's diffusion are computed as for a whole
   * volume (on the GPU where it can). With a controller of several processes, rendering a piece
   * without UpdatePieceLighting is an error (nothing drawn); without a controller (or with one
   * process) the rest of the whole is empty space.
   *
   * Differences: the emission-absorption mapper needs neither (compositing is exact); the
   * ambient-occlusion mapper occludes within its piece only. Defaults: an empty whole extent
   * (0, -1, 0, -1, 0, -1: the input is the whole) and no controller.
   */
  vtkSetVector6Macro(WholeExtent, int);
  vtkGetVector6Macro(WholeExtent, int);
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /**
   * Distributed rendering, collective: brings the whole's averaged extinction up to date from
   * every process's piece (see WholeExtent), for `volume` (its property and matrix). Call it on
   * every process of the Controller before each render, whether or not the process's piece is
   * visible, culled or empty (ParaView's representation does, in its render request): one
   * AllReduce of two ints per call, and when a piece changed, the AllGather of the pieces'
   * boxes and the AllReduce of the light grid. Rendering never communicates, so a process whose
   * volume is culled or has no piece cannot hold the others up. Nothing happens without a
   * controller of more than one process.
   */
  void UpdatePieceLighting(vtkVolume* volume);

  ///@{
  /**
   * What the last UpdatePieceLighting communicated: the collective calls it made on the
   * Controller and the bytes this process gave them (its send buffers: 8 for the call that asks
   * whether anything changed, 24 for its box, 4 per light-grid point for its share), and how
   * long it took (seconds, waiting for the other processes included). 0 without a controller of
   * several processes.
   */
  vtkGetMacro(LastPieceLightingCalls, int);
  vtkGetMacro(LastPieceLightingBytes, double);
  vtkGetMacro(LastPieceLightingSeconds, double);
  ///@}

  /**
   * Whether the last frame lit its input as a piece of a larger whole (see WholeExtent).
   */
  vtkGetMacro(LitAsPiece, vtkTypeBool);

  ///@{
  /**
   * A mask, as vtkGPUVolumeRayCastMapper's (VTK 9.1): image data with as many samples as the
   * volume (points for point data, cells for cell data; read by sample, its own origin and
   * spacing unused), its point (else cell) scalars, first component. MaskType
   * BinaryMaskType: samples whose nearest mask value is <= 0 are empty space (MaskBlendFactor is
   * not used). LabelMapMaskType (default, as in VTK): label L = the nearest mask value rounded;
   * samples of label L >= 1 take the property's label functions (vtkVolumeProperty::
   * SetLabelColor, SetLabelScalarOpacity; labels without them take component 0's), mixed with
   * the unlabelled medium by MaskBlendFactor (default 1: the label's alone; 0: no labels; in
   * between, sigma_t = (1 - b) sigma + b sigma_label and the colour their extinction-weighted
   * mean); label maps need single-component scalars. Default: no mask.
   */
  void SetMaskInput(vtkImageData* mask);
  vtkGetObjectMacro(MaskInput, vtkImageData);
  enum
  {
    BinaryMaskType = 0,
    LabelMapMaskType
  };
  vtkSetClampMacro(MaskType, int, BinaryMaskType, LabelMapMaskType);
  vtkGetMacro(MaskType, int);
  void SetMaskTypeToBinary() { this->SetMaskType(BinaryMaskType); }
  void SetMaskTypeToLabelMap() { this->SetMaskType(LabelMapMaskType); }
  vtkSetClampMacro(MaskBlendFactor, float, 0.0f, 1.0f);
  vtkGetMacro(MaskBlendFactor, float);
  ///@}

  ///@{
  /**
   * Whether the last light volumes (ambient scattering) or occlusion volume (ambient occlusion)
   * were computed on the GPU (always false for the mappers that do not build them).
   */
  virtual vtkTypeBool GetLightVolumesOnGPU() { return 0; }
  virtual vtkTypeBool GetOcclusionOnGPU() { return 0; }
  ///@}

  ///@{
  /**
   * How often the mapper converted and uploaded the input scalars, rebuilt the averaged
   * extinction, rebuilt a light volume (one count per light), rebuilt the ambient-occlusion
   * volume, rendered a frame, and rendered an interactive frame (AutoAdjustSampleDistances
   * on, less than a second allotted), and solved the extended model's diffusion. The rebuilds
   * are counted by the mapper that builds the volume (0 for the others).
   */
  vtkGetMacro(NumberOfDataUploads, int);
  virtual int GetNumberOfExtinctionRebuilds() { return 0; }
  virtual int GetNumberOfLightVolumeRebuilds() { return 0; }
  virtual int GetNumberOfOcclusionRebuilds() { return 0; }
  virtual int GetNumberOfDiffusionRebuilds() { return 0; }
  vtkGetMacro(NumberOfRenderedFrames, int);
  vtkGetMacro(NumberOfInteractiveFrames, int);
  ///@}

  /**
   * Bytes of the 3D textures the mapper holds on the GPU for its volume (the scalars in their
   * texel format, the precomputed volumes, the precomputation's scratch grids, the mask and the
   * validity), as the GPU memory budget (environment variable AVS_GPU_MEMORY_LIMIT_MB) counts
   * them: 0 before the first frame and after ReleaseGraphicsResources. The 1D and 2D tables and
   * the extended model's fluence are not counted. GetGPUMemoryPeakBytes: the most they took at
   * once since the last release (the precomputation allocates its intermediate grids and
   * releases them after it).
   */
  double GetGPUMemoryBytes() const;
  double GetGPUMemoryPeakBytes() const;

  ///@{
  /**
   * The GPU memory budget of this mapper's volume textures (the same textures
   * GetGPUMemoryBytes counts), in MiB. 0 (default): what the OpenGL context reports
   * (GL_NVX_gpu_memory_info's dedicated video memory, its total available memory on a device
   * with unified memory, or GL_ATI_meminfo's free texture memory), and no limit where it
   * reports nothing (or less than 64 MiB); the environment variable AVS_GPU_MEMORY_LIMIT_MB,
   * where set, limits it further. A texture that would take the volume past the budget is
   * refused before anything is allocated: the render reports an error naming the sizes and the
   * budget, draws nothing, and releases what the volume held. The bricks of a split volume (see
   * SetPartitions) all stay resident, so they must fit together (they are not streamed).
   */
  vtkSetClampMacro(MaximumGPUMemory, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumGPUMemory, int);
  ///@}

  ///@{
  /**
   * Bricking, as vtkOpenGLGPUVolumeRayCastMapper names it: the scalar volume is split into
   * x * y * z bricks (near-equal voxel ranges per axis sharing one voxel layer, clamped to
   * the voxels there are), one 3D texture each, drawn back to front with each ray's samples at
   * the unsplit ray's positions, so the picture agrees with the unsplit one (ARCHITECTURE.md,
   * "Bricking"). (1, 1, 1) (default): automatic, split only along the axes longer than the
   * context's largest 3D texture (GL_MAX_3D_TEXTURE_SIZE). A mask and a separate validity
   * texture are split the same way; the precomputation stays on its coarse grids (a split
   * volume's averaged extinction and occlusion volume are computed on the CPU). A split volume
   * renders the composite blend mode only (the other blend modes report an error and draw nothing).
   * Each value is at least 1.
   */
  void SetPartitions(int x, int y, int z);
  vtkGetVector3Macro(Partitions, int);
  ///@}

  /**
   * Bricks the last frame drew (1: unsplit; 0 before the first frame drawn).
   */
  vtkGetMacro(NumberOfBricks, int);

  /**
   * Renders the volume (called by vtkVolume), as vtkGPUVolumeRayCastMapper::Render does: a
   * vtkCommand::VolumeMapperRenderStartEvent, the checks (an error draws nothing), the frame
   * (uploads and precomputation of what changed, then the ray-casting pass), TimeToDraw, and a
   * vtkCommand::VolumeMapperRenderEndEvent: one pair of events per render, drawn or refused.
   * (Inside vtkDualDepthPeelingPass the volume is drawn in the pass's first call; the later
   * calls of the same frame draw nothing and fire no events.)
   */
  void Render(vtkRenderer* renderer, vtkVolume* volume) override;

  /**
   * The input's bounds; nullptr when they are not finite (NaN or infinite spacing or origin), so
   * that the renderer does not cull the volume and Render reports the bad input.
   */
  double* GetBounds() override;
  using vtkVolumeMapper::GetBounds;

  /**
   * Sets a composite input: a vtkMultiBlockDataSet, vtkPartitionedDataSet or
   * vtkPartitionedDataSetCollection of vtkImageData pieces of one grid (see the class
   * documentation). vtkImageData inputs go through vtkVolumeMapper's SetInputData.
   */
  void SetInputData(vtkDataObjectTree* input);
  using vtkVolumeMapper::SetInputData;

  ///@{
  /**
   * The image drawn: the input image, or for a composite input the image its blocks make (see
   * the class documentation; nullptr where they cannot be merged).
   */
  vtkDataSet* GetInput() override;
  vtkDataSet* GetInput(int port) override;
  ///@}

  /**
   * Frees the GL resources of `window`.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkAVSVolumeMapper();
  ~vtkAVSVolumeMapper() override;

  /// Port 0 takes a vtkImageData or a vtkDataObjectTree of image blocks.
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /// 0: emission–absorption, 1: ambient occlusion, 2: ambient scattering.
  virtual int GetEffect() const = 0;
  /// The subclass's parameters into the shared parameter struct (Core/ScatteringParameters.h),
  /// which already holds the base class's values.
  virtual void FillParameters(avs::ScatteringParameters& parameters) = 0;
  /// The subclass's precomputed volumes (the lit mappers' owners, vtkAVSOcclusionVolume and
  /// vtkAVSScatteringVolumes), brought up to date for the frame after the data and the
  /// classification are uploaded; false after reporting an error. None by default.
  virtual bool PrepareLighting(const vtkAVSPrecomputeInputs&) { return true; }
  /// Forgets what the GPU holds of them (part of the one reset: a released window, a context
  /// switch, a volume that could not be prepared).
  virtual void InvalidateLighting() {}
  /// The grids of the precomputed volumes the ray caster samples: the light grid, the occlusion
  /// grid (left as they are by a mapper without them).
  virtual void GetPrecomputedGrids(std::array<int, 3>&, std::array<int, 3>&) const {}

  double SampleDistance = 0.0;
  vtkTypeBool AutoAdjustSampleDistances = 1;
  float ImageSampleDistance = 1.0f;
  float MinimumImageSampleDistance = 1.0f;
  float MaximumImageSampleDistance = 10.0f;
  float LastImageSampleDistance = 1.0f;
  vtkTypeBool LockSampleDistanceToInputSpacing = 0;
  vtkImageData* MaskInput = nullptr;
  int MaskType = LabelMapMaskType;
  float MaskBlendFactor = 1.0f;
  vtkTypeBool UseJittering = 1;
  double TerminationTransmittance = 1.0 / 255.0;
  vtkTypeBool PrecomputeOnGPU = 1;
  vtkTypeBool EmptySpaceSkipping = 1;
  double LastEmptyCellFraction = 0.0;
  double LastDataUploadFraction = 0.0;
  vtkTypeBool LastSkippedEmptySpace = 0;
  double Exposure = 1.0;
  int ToneMapping = ClampToneMapping;
  vtkTypeBool AutoExposure = 0;
  double LastExposure = 0.0;
  int LastToneMapping = -1;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkMultiProcessController* Controller = nullptr;
  vtkTypeBool LitAsPiece = 0;
  int LastPieceLightingCalls = 0;
  double LastPieceLightingBytes = 0.0;
  double LastPieceLightingSeconds = 0.0;
  int MaximumGPUMemory = 0;
  int Partitions[3] = { 1, 1, 1 };
  vtkTypeBool PathTracedRefinement = 0; ///< ambient scattering only
  int MaximumSamplesPerPixel = 1024;

  vtkTypeBool StageTiming = 0;
  double LastStageSeconds[NumberOfRenderStages] = {};

  int NumberOfDataUploads = 0;
  int NumberOfRenderedFrames = 0;
  int NumberOfInteractiveFrames = 0;
  int NumberOfBricks = 0;

private:
  vtkAVSVolumeMapper(const vtkAVSVolumeMapper&) = delete;
  void operator=(const vtkAVSVolumeMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
  /// The frame being drawn (vtkAVSVolumeMapperInternals.h).
  struct FrameAssembly;
  /// Render's steps: the window (a new one resets what the GPU held) and the blend-mode rules;
  /// false: nothing is drawn (after an error, or for an isosurface without contours) ...
  bool ValidateRender(vtkRenderer* renderer, vtkVolume* volume, FrameAssembly& assembly);
  /// ... then the uploads and precomputation of what changed, the frame and its statistics.
  void GPURender(vtkRenderer* renderer, vtkVolume* volume, FrameAssembly& assembly);
  /// The one reset of what the GPU holds: the ray caster's resources, what the uploads held, the
  /// subclass's precomputed volumes (InvalidateLighting).
  void ResetGraphicsState();
  /// Converts, checks, uploads and precomputes what changed; an interactive frame keeps the light
  /// volumes of camera-following lights.
  bool Prepare(vtkRenderer* renderer, vtkVolume* volume, bool interactive);
  /// With StageTiming on: the GPU's work finished, the time since the last mark added to the
  /// stage's (StartStages starts the clock, once per render).
  void StartStages();
  void MarkStage(int stage);
  /// Prepare's first part, without a renderer or GL: the input, the mask, the property, the
  /// piece, the parameters, the transforms and the clip region, converted and checked when they
  /// changed (errors reported).
  bool PrepareScene(vtkVolume* volume);
  /// PrepareScene's parts that make the scene (vtkAVSVolumeMapperData.cxx): the input image and
  /// its mask, converted and checked when they changed (new data with the values of the
  /// converted data is not converted again; null after an error, reported) ...
  vtkImageData* PrepareInput();
  bool PrepareMask();
  /// ... the property's classification, and the clipping planes and cropping in the index frame
  /// (false after an error, reported).
  bool PrepareProperty(vtkVolumeProperty* property);
  bool PrepareClip(vtkImageData* input, vtkMatrix4x4* dataToWorld);
  /// The frame's assembly (vtkAVSVolumeMapperFrame.cxx): the blend mode this mapper renders
  /// (errors reported; false also for an isosurface without contours), the checks it needs
  /// after the scene is prepared, and the ray caster's frame: image sample distance, display
  /// transform, refinement.
  bool ResolveBlend(vtkVolume* volume, FrameAssembly& assembly);
  bool CheckPreparedBlend(const FrameAssembly& assembly);
  void AssembleFrame(vtkRenderer* renderer, vtkVolume* volume, FrameAssembly& assembly);
  /// Distributed rendering (vtkAVSVolumeMapperPieces.cxx): where the input lies in WholeExtent
  /// (Internals' Whole, PieceOffset, LitAsPiece), checked; and the averaged extinction of the
  /// whole on `lightGrid` for the render (the sum UpdatePieceLighting made; one process: its
  /// share alone), without communicating.
  bool ResolvePiece(vtkImageData* input, std::string& error);
  /// UpdatePieceLighting's work (it times it and counts what it sends).
  void ShareAcrossPieces(vtkVolume* volume);
  bool AverageAcrossPieces(const avs::GridGeometry& lightGrid,
    avs::Grid& averaged,
    std::string& error);
  /// sigma_t on the CPU (Internals' Extinction), rebuilt when the data or the opacity changed
  /// (vtkAVSVolumeMapperData.cxx).
  const avs::Grid& UpdateExtinction();
  /// The frame's display transform: the parameters' exposure (metered with AutoExposure) and
  /// tone curve (none under a vtkToneMappingPass).
  avs::DisplayTransform ResolveDisplay(vtkRenderer* renderer, vtkVolume* volume);
  // One warning when the property's shading flags ask for what this mapper does not do.
  void WarnAboutShading(vtkVolumeProperty* property);
  std::string ShadingWarning;
  /// The path-traced refinement's settings for this frame (vtkAVSVolumeMapperRefinement.cxx):
  /// on where asked for and possible (one warning where not), still where the frame is not
  /// interactive, and the key of everything the picture depends on apart from the display
  /// transform: the data, the classification, the clipping, the parameters and the other props
  /// that may hide the volume (`key`), the camera, the volume's matrix and the lights
  /// (`geometry`).
  void ResolveRefinement(vtkRenderer* renderer,
    vtkVolume* volume,
    bool still,
    bool bricked,
    bool& enabled,
    bool& isStill,
    std::vector<double>& key,
    std::vector<double>& geometry);
  std::string RefinementWarning;
};

#endif
