#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSPrecomputeInputs.h"
#include "vtkAVSPropertyTranslator.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSSceneTranslator.h"
#include "vtkAVSShaderOptions.h"
#include "vtkAVSTextureMemory.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>

vtkCxxSetObjectMacro(vtkAVSVolumeMapper, MaskInput, vtkImageData);

vtkAVSVolumeMapper::vtkAVSVolumeMapper()
  : Internal(new Internals)
{
}

vtkAVSVolumeMapper::~vtkAVSVolumeMapper()
{
  this->SetMaskInput(nullptr);
  this->SetController(nullptr);
  this->Internal->RayCaster.ReleaseGraphicsResources(this->Internal->RayCaster.GetWindow());
}

double* vtkAVSVolumeMapper::GetBounds()
{
  double* bounds = nullptr;
  vtkDataObject* given = this->GetInputDataObject(0, 0);
  if (vtkDataObjectTree::SafeDownCast(given))
  {
    // The merged image's (the superclass knows vtkDataSet inputs only).
    if (vtkAlgorithm* producer = this->GetInputAlgorithm())
    {
      producer->Update();
    }
    std::string error; // (reported by the render)
    vtkImageData* image = this->Internal->CompositeInput.Resolve(given, error);
    if (image && image->GetNumberOfPoints() > 0)
    {
      image->GetBounds(this->Bounds);
    }
    else
    {
      vtkMath::UninitializeBounds(this->Bounds);
    }
    bounds = this->Bounds;
  }
  else
  {
    bounds = this->Superclass::GetBounds();
  }
  if (bounds)
  {
    for (int i = 0; i < 6; ++i)
    {
      if (!std::isfinite(bounds[i]))
      {
        return nullptr;
      }
    }
  }
  return bounds;
}

void vtkAVSVolumeMapper::SetInputData(vtkDataObjectTree* input)
{
  this->SetInputDataInternal(0, input);
}

vtkDataSet* vtkAVSVolumeMapper::GetInput()
{
  return this->GetInput(0);
}

vtkDataSet* vtkAVSVolumeMapper::GetInput(int port)
{
  if (port == 0 && this->GetNumberOfInputConnections(0) > 0)
  {
    vtkDataObject* given = this->GetInputDataObject(0, 0);
    if (vtkDataObjectTree::SafeDownCast(given))
    {
      // Reported here too, once per failure: a caller that checks the input before rendering
      // (ParaView's vtkPVLODVolume) then never renders, and the render's report never comes.
      auto& in = *this->Internal;
      std::string error;
      vtkImageData* image = in.CompositeInput.Resolve(given, error);
      if (!image && !error.empty() && error != in.ReportedCompositeError)
      {
        vtkErrorMacro("Cannot render the " << given->GetClassName() << ": " << error << ".");
      }
      in.ReportedCompositeError = error;
      return image;
    }
  }
  return this->Superclass::GetInput(port);
}

int vtkAVSVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (!this->Superclass::FillInputPortInformation(port, info))
  {
    return 0;
  }
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObjectTree");
  return 1;
}

void vtkAVSVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window && window == this->Internal->RayCaster.GetWindow())
  {
    this->ResetGraphicsState();
  }
}

void vtkAVSVolumeMapper::ResetGraphicsState()
{
  // The one reset of what the GPU holds: a released window, a context switch, a volume that
  // could not be prepared. The textures and programs go, and everything that knew what they
  // held forgets it, so the next frame uploads and rebuilds from nothing.
  auto& in = *this->Internal;
  in.RayCaster.ReleaseGraphicsResources(in.RayCaster.GetWindow());
  in.ForgetUploads();
  this->InvalidateLighting();
}

void vtkAVSVolumeMapper::Internals::ForgetUploads()
{
  this->UploadedScalarsVersion = -1;
  this->UploadedTransferVersion = -1;
  this->UploadedFingerprints.clear();
  this->UploadedContentKey.clear();
}

bool vtkAVSVolumeMapper::PrepareScene(vtkVolume* volume)
{
  auto& in = *this->Internal;
  std::string error;

  // The input, the mask and the property, converted and checked when they changed
  // (vtkAVSVolumeMapperData.cxx).
  vtkImageData* input = this->PrepareInput();
  if (!input)
  {
    return false;
  }
  vtkVolumeProperty* property = volume->GetProperty();
  if (!property)
  {
    vtkErrorMacro("Cannot render: the volume has no property.");
    return false;
  }
  if (!this->PrepareProperty(property))
  {
    return false;
  }

  // Distributed rendering: the whole image of which the input is a piece.
  if (!this->ResolvePiece(input, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }

  // Parameters: base values, then the subclass's.
  avs::ScatteringParameters p;
  p.SampleDistance = this->SampleDistance;
  if (this->LockSampleDistanceToInputSpacing)
  {
    double spacing[3];
    int extent[6];
    input->GetSpacing(spacing);
    input->GetExtent(extent);
    p.SampleDistance = this->SpacingAdjustedSampleDistance(spacing, extent);
  }
  p.TerminationTransmittance = this->TerminationTransmittance;
  p.Display.Exposure = this->Exposure;
  p.Display.Curve =
    this->ToneMapping == ShoulderToneMapping ? avs::ToneMapping::Shoulder : avs::ToneMapping::Clamp;
  p.AutoExposure = this->AutoExposure != 0;
  this->FillParameters(p);
  if (this->GetEffect() == 2)
  {
    // Surfaces inside the medium: the property's shading with the subclass's blending (two
    // sides until Prepare reads the renderer's TwoSidedLighting).
    p.Surface = vtkAVSPropertyTranslator::ToSurface(property, p.Surface.Blending, nullptr);
  }
  in.Parameters = p.Resolve(in.Whole); // the automatic radius: the whole image's

  // Transforms: data -> world is the volume's matrix; index -> data is the grid's placement.
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  vtkNew<vtkMatrix4x4> indexToData;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      indexToData->SetElement(r, c, g.Direction[3 * r + c] * g.Spacing[c]);
    }
    indexToData->SetElement(r, 3, g.Origin[r]);
  }
  vtkNew<vtkMatrix4x4> dataToWorld;
  dataToWorld->DeepCopy(volume->GetMatrix());
  vtkMatrix4x4::Multiply4x4(dataToWorld, indexToData, in.WorldToIndex);
  in.WorldToIndex->Invert();
  vtkMatrix4x4* worldToData = in.WorldToData;
  worldToData->DeepCopy(dataToWorld);
  worldToData->Invert();

  // Clipping planes and cropping in the index frame (vtkAVSVolumeMapperData.cxx).
  return this->PrepareClip(input, dataToWorld);
}

bool vtkAVSVolumeMapper::Prepare(vtkRenderer* renderer, vtkVolume* volume, bool interactive)
{
  auto& in = *this->Internal;
  std::string error;
  if (!this->PrepareScene(volume))
  {
    return false;
  }
  this->MarkStage(InputStage);
  // Surfaces are lit on one side or two as the renderer lights surfaces (SurfaceShading.h).
  in.Parameters.Surface.TwoSided = renderer->GetTwoSidedLighting() != 0;
  const avs::ScatteringParameters& rp = in.Parameters;

  // Lights in world space, at most 8.
  in.WorldLights = vtkAVSSceneTranslator::ToLights(
    renderer, renderer->GetActiveCamera(), rp.LightScale, &in.FollowsCamera);
  if (in.WorldLights.size() > static_cast<std::size_t>(vtkAVSRayCaster::MaximumNumberOfLights))
  {
    vtkWarningMacro("Only the first " << vtkAVSRayCaster::MaximumNumberOfLights << " of "
                                      << in.WorldLights.size() << " lights are used.");
    in.WorldLights.resize(vtkAVSRayCaster::MaximumNumberOfLights);
  }
  in.FollowsCamera.resize(in.WorldLights.size(), false);

  // Uploads of what changed.
  const std::array<int, 3> partitions{
    this->Partitions[0], this->Partitions[1], this->Partitions[2]
  };
  // Ambient scattering's bricks hold the voxels its look-ahead reads before their first samples.
  const std::array<int, 3>& dimensions = in.Scene.Scalars.Geometry.Dimensions;
  const int largest = in.RayCaster.MaximumTextureSize3D();
  const bool split = partitions != std::array<int, 3>{ 1, 1, 1 } ||
    std::any_of(dimensions.begin(), dimensions.end(), [largest](int d) { return d > largest; });
  const std::array<int, 3> lookBack = this->GetEffect() == 2 && split
    ? vtkAVSRayCaster::LookBackVoxels(
        rp.AmbientRadius, rp.SampleDistance, in.Scene.Scalars.Geometry.Spacing)
    : std::array<int, 3>{ 0, 0, 0 };
  const bool moreLayers = lookBack[0] > in.UploadedLookBack[0] ||
    lookBack[1] > in.UploadedLookBack[1] || lookBack[2] > in.UploadedLookBack[2];
  // (Bricks with more layers than the look-back needs serve: a smaller radius or sample distance
  // uploads nothing again; a larger one uploads the bricks with the layers it needs.)
  this->LastDataUploadFraction = 0.0; // unless this frame uploads the data
  if (in.UploadedScalarsVersion != in.ScalarsVersion || partitions != in.UploadedPartitions ||
    moreLayers)
  {
    const bool wasBricked = in.RayCaster.IsBricked();
    if (!in.RayCaster.UploadScalars(
          in.Scene, in.ScalarType, in.ScalarSource(), partitions, lookBack, error))
    {
      // Some textures may hold part of the new data: none is trusted for the next upload.
      in.ForgetUploads();
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.UploadedScalarsVersion = in.ScalarsVersion;
    in.UploadedPartitions = partitions;
    in.UploadedLookBack = lookBack;
    in.UploadedFingerprints = in.Fingerprints;
    in.UploadedContentKey = in.ContentKey;
    in.UploadedRangeDependent = in.RangeDependent();
    this->LastDataUploadFraction = in.RayCaster.GetUploadedVoxels() /
      std::max(1.0, static_cast<double>(in.Scene.Scalars.Geometry.NumberOfPoints()));
    ++this->NumberOfDataUploads;
    if (wasBricked || in.RayCaster.IsBricked())
    {
      in.UploadedTransferVersion = -1; // the mask and validity follow the bricks
    }
  }
  if (in.UploadedTransferVersion != in.TransferVersion)
  {
    if (!in.RayCaster.UploadClassification(in.Scene, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.UploadedTransferVersion = in.TransferVersion;
  }
  // Surfaces inside the medium (ShadeOn): the gradient, made again when the data or the
  // shading component's range changed.
  if (!in.RayCaster.UploadSurfaces(in.Scene,
        this->GetEffect() == 2 && in.Parameters.Surface.Active(),
        in.ScalarSource(),
        error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  this->MarkStage(UploadStage);

  // The subclass's precomputed volumes (vtkAVSOcclusionVolume, vtkAVSScatteringVolumes).
  vtkAVSPrecomputeInputs inputs;
  inputs.RayCaster = &in.RayCaster;
  inputs.Scene = &in.Scene;
  inputs.Parameters = &in.Parameters;
  inputs.DataVersion = in.DataVersion;
  inputs.OpacityVersion = in.OpacityVersion;
  inputs.PrecomputeOnGPU = this->PrecomputeOnGPU != 0;
  inputs.SkipEmptySpace = this->EmptySpaceSkipping != 0;
  inputs.Interactive = interactive;
  inputs.WorldToData = in.WorldToData;
  inputs.WorldLights = &in.WorldLights;
  inputs.FollowsCamera = &in.FollowsCamera;
  inputs.Whole = &in.Whole;
  inputs.PieceOffset = in.PieceOffset;
  inputs.LitAsPiece = this->LitAsPiece != 0;
  inputs.SumVersion = in.SumVersion;
  inputs.Extinction = [this]() -> const avs::Grid& { return this->UpdateExtinction(); };
  auto average = [this](const avs::GridGeometry& grid, avs::Grid& sum, std::string& message)
  { return this->AverageAcrossPieces(grid, sum, message); };
  inputs.AverageAcrossPieces = average;
  inputs.Progress = [this](double progress) { this->UpdateProgress(progress); };
  inputs.StageDone = [this](int stage) { this->MarkStage(stage); };
  return this->PrepareLighting(inputs);
}

void vtkAVSVolumeMapper::WarnAboutShading(vtkVolumeProperty* property)
{
  // Phong shading (ShadeOn with the ambient, diffuse, specular coefficients and the specular
  // power): EA and AO are never lit by the property's coefficients; ambient scattering shades
  // surfaces inside the medium with component 0's (SurfaceShading.h), and says so where another
  // component's differ.
  std::string warning;
  bool shade = false, differs = false;
  for (int c = 0; c < VTK_MAX_VRCOMP; ++c)
  {
    shade = shade || property->GetShade(c);
    differs = differs ||
      (c > 0 && c < this->Internal->Scene.Medium.NumberOfComponents() &&
        (property->GetShade(c) != property->GetShade(0) ||
          property->GetAmbient(c) != property->GetAmbient(0) ||
          property->GetDiffuse(c) != property->GetDiffuse(0) ||
          property->GetSpecular(c) != property->GetSpecular(0) ||
          property->GetSpecularPower(c) != property->GetSpecularPower(0)));
  }
  if (shade && this->GetEffect() != 2)
  {
    warning = "ShadeOn has no effect on " + std::string(this->GetClassName()) +
      ": it does not shade (vtkAmbientScatteringVolumeMapper shades surfaces inside the medium)";
  }
  else if (differs && this->GetEffect() == 2)
  {
    warning = "the shading flags and coefficients of components other than 0 are not used: "
              "component 0's shade the surfaces of every component";
  }
  if (property->GetUseClippedVoxelIntensity())
  {
    warning += std::string(warning.empty() ? "" : "; ") +
      "UseClippedVoxelIntensity is not used: the gradient at a cut face is the unclipped "
      "data's (ClippedVoxelIntensity is ignored)";
  }
  if (!warning.empty() && warning != this->ShadingWarning)
  {
    vtkWarningMacro(<< warning << ".");
  }
  this->ShadingWarning = warning;
}

void vtkAVSVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  // Inside vtkDualDepthPeelingPass's volume peeling the volume is drawn once, in the first call
  // (see vtkAVSRenderPasses): the later calls are no render of it.
  const vtkAVSRenderPasses::Role role = vtkAVSRenderPasses::RoleOf(volume, this);
  if (role == vtkAVSRenderPasses::Role::Skip)
  {
    return;
  }
  // As vtkGPUVolumeRayCastMapper::Render: the start event, the checks, the frame, its time, the
  // end event (an observer sees one pair per render, drawn or refused).
  this->InvokeEvent(vtkCommand::VolumeMapperRenderStartEvent, nullptr);
  const auto start = std::chrono::steady_clock::now();
  FrameAssembly assembly;
  assembly.Role = role;
  if (this->ValidateRender(renderer, volume, assembly))
  {
    this->GPURender(renderer, volume, assembly);
  }
  this->TimeToDraw =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->InvokeEvent(vtkCommand::VolumeMapperRenderEndEvent, nullptr);
}

bool vtkAVSVolumeMapper::ValidateRender(vtkRenderer* renderer,
  vtkVolume* volume,
  FrameAssembly& assembly)
{
  auto& in = *this->Internal;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("Cannot render: this mapper needs an OpenGL render window.");
    return false;
  }
  if (window != in.RayCaster.GetWindow())
  {
    // Another window: its context gets its own resources.
    this->ResetGraphicsState();
    in.RayCaster.SetWindow(window);
  }
  assembly.Window = window;
  return this->ResolveBlend(volume, assembly);
}

void vtkAVSVolumeMapper::GPURender(vtkRenderer* renderer,
  vtkVolume* volume,
  FrameAssembly& assembly)
{
  auto& in = *this->Internal;
  // VTK's test for an interactive render (vtkGPUVolumeRayCastMapper's and
  // vtkFixedPointVolumeRayCastMapper's): less than a second allotted to the volume.
  const bool adjust = this->AutoAdjustSampleDistances != 0;
  assembly.Interactive = adjust && volume->GetAllocatedRenderTime() < 1.0;
  // The GPU memory budget of this volume's textures, for its uploads and its draw.
  const vtkAVSTextureMemory::ScopedBudget budget(this->MaximumGPUMemory > 0
      ? this->MaximumGPUMemory * 1024.0 * 1024.0
      : in.RayCaster.ReportedGPUMemoryBytes());
  this->StartStages();
  if (!this->Prepare(renderer, volume, assembly.Interactive))
  {
    // Nothing of a volume that could not be prepared stays on the GPU (one that does not fit
    // gets one error, and the next starts from nothing).
    this->ResetGraphicsState();
    return;
  }
  if (!this->CheckPreparedBlend(assembly))
  {
    return;
  }
  this->AssembleFrame(renderer, volume, assembly);

  // The adjustment times the ray-casting pass alone (the precomputation does not scale with the
  // rays), finished on the GPU as vtkOpenGLGPUVolumeRayCastMapper finishes its frames.
  using Clock = std::chrono::steady_clock;
  if (adjust)
  {
    assembly.Window->WaitForCompletion();
  }
  const auto passStart = Clock::now();
  std::string error;
  const vtkAVSRayCaster::Frame& frame = assembly.Frame;
  if (!in.RayCaster.Render(renderer, frame, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return;
  }
  this->MarkStage(FrameStage);
  if (adjust && !in.RayCaster.GetLastRefined()) // (a refined frame is no ray-casting pass)
  {
    assembly.Window->WaitForCompletion();
    const auto& rays = in.RayCaster.GetLastPassSize();
    const double seconds = std::chrono::duration<double>(Clock::now() - passStart).count();
    in.SecondsPerRay = seconds / std::max(1.0, static_cast<double>(rays[0]) * rays[1]);
  }

  // Statistics.
  this->LastImageSampleDistance = static_cast<float>(frame.ImageSampleDistance);
  this->LastExposure = frame.Display.Exposure;
  this->LastToneMapping =
    frame.Display.Curve == avs::ToneMapping::Shoulder ? ShoulderToneMapping : ClampToneMapping;
  this->NumberOfBricks = in.RayCaster.GetNumberOfBricks();
  this->LastEmptyCellFraction = in.RayCaster.GetEmptyCellFraction();
  this->LastSkippedEmptySpace = in.RayCaster.GetLastSkippedEmptySpace() ? 1 : 0;
  ++this->NumberOfRenderedFrames;
  if (assembly.Interactive)
  {
    ++this->NumberOfInteractiveFrames;
  }
}

void vtkAVSVolumeMapper::StartStages()
{
  std::fill(std::begin(this->LastStageSeconds), std::end(this->LastStageSeconds), 0.0);
  vtkOpenGLRenderWindow* window = this->Internal->RayCaster.GetWindow();
  if (this->StageTiming && window)
  {
    window->WaitForCompletion(); // (what was queued before is no stage of this render)
    this->Internal->StageMark = std::chrono::steady_clock::now();
  }
}

void vtkAVSVolumeMapper::MarkStage(int stage)
{
  vtkOpenGLRenderWindow* window = this->Internal->RayCaster.GetWindow();
  if (!this->StageTiming || !window || stage < 0 || stage >= NumberOfRenderStages)
  {
    return;
  }
  window->WaitForCompletion();
  const auto now = std::chrono::steady_clock::now();
  this->LastStageSeconds[stage] +=
    std::chrono::duration<double>(now - this->Internal->StageMark).count();
  this->Internal->StageMark = now;
}

double vtkAVSVolumeMapper::GetLastStageSeconds(int stage) const
{
  return stage >= 0 && stage < NumberOfRenderStages ? this->LastStageSeconds[stage] : 0.0;
}

const char* vtkAVSVolumeMapper::GetRenderStageName(int stage)
{
  static const char* const names[NumberOfRenderStages] = {
    "input", "upload", "averaged_extinction", "light_volumes", "diffusion", "frame"
  };
  return stage >= 0 && stage < NumberOfRenderStages ? names[stage] : "";
}

void vtkAVSVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaskInput: " << this->MaskInput << "\n";
  os << indent << "MaskType: " << (this->MaskType == BinaryMaskType ? "Binary" : "LabelMap")
     << "\n";
  os << indent << "MaskBlendFactor: " << this->MaskBlendFactor << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance
     << (this->SampleDistance > 0 ? "" : " (automatic)") << "\n";
  os << indent << "LockSampleDistanceToInputSpacing: "
     << (this->LockSampleDistanceToInputSpacing ? "On" : "Off") << "\n";
  os << indent << "AutoAdjustSampleDistances: " << (this->AutoAdjustSampleDistances ? "On" : "Off")
     << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "MinimumImageSampleDistance: " << this->MinimumImageSampleDistance << "\n";
  os << indent << "MaximumImageSampleDistance: " << this->MaximumImageSampleDistance << "\n";
  os << indent << "LastImageSampleDistance: " << this->LastImageSampleDistance << "\n";
  os << indent << "UseJittering: " << (this->UseJittering ? "On" : "Off") << "\n";
  os << indent << "TerminationTransmittance: " << this->TerminationTransmittance << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << this->GetToneMappingAsString() << "\n";
  os << indent << "AutoExposure: " << (this->AutoExposure ? "On" : "Off") << "\n";
  os << indent << "LastExposure: " << this->LastExposure << "\n";
  os << indent << "LastToneMapping: " << this->LastToneMapping << "\n";
  os << indent << "PrecomputeOnGPU: " << (this->PrecomputeOnGPU ? "On" : "Off") << "\n";
  os << indent << "StageTiming: " << (this->StageTiming ? "On" : "Off") << "\n";
  os << indent << "LastStageSeconds:";
  for (int stage = 0; stage < NumberOfRenderStages; ++stage)
  {
    os << " " << GetRenderStageName(stage) << " " << this->LastStageSeconds[stage];
  }
  os << "\n";
  os << indent << "LightVolumesOnGPU: " << (this->GetLightVolumesOnGPU() ? "yes" : "no") << "\n";
  os << indent << "OcclusionOnGPU: " << (this->GetOcclusionOnGPU() ? "yes" : "no") << "\n";
  os << indent << "EmptySpaceSkipping: " << (this->EmptySpaceSkipping ? "On" : "Off") << "\n";
  os << indent << "LastEmptyCellFraction: " << this->LastEmptyCellFraction << "\n";
  os << indent << "LastDataUploadFraction: " << this->LastDataUploadFraction << "\n";
  os << indent << "LastSkippedEmptySpace: " << (this->LastSkippedEmptySpace ? "yes" : "no") << "\n";
  os << indent << "SamplesPerPixel: " << this->GetSamplesPerPixel() << "\n";
  os << indent << "WholeExtent: (" << this->WholeExtent[0] << ", " << this->WholeExtent[1] << ", "
     << this->WholeExtent[2] << ", " << this->WholeExtent[3] << ", " << this->WholeExtent[4] << ", "
     << this->WholeExtent[5] << ")"
     << (this->WholeExtent[0] > this->WholeExtent[1] ? " (the input is the whole)" : "") << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "LitAsPiece: " << (this->LitAsPiece ? "yes" : "no") << "\n";
  os << indent << "LastPieceLightingCalls: " << this->LastPieceLightingCalls << "\n";
  os << indent << "LastPieceLightingBytes: " << this->LastPieceLightingBytes << "\n";
  os << indent << "LastPieceLightingSeconds: " << this->LastPieceLightingSeconds << "\n";
  // What of vtkVolumeMapper's settings (printed above) this mapper honours.
  const int planes = this->ClippingPlanes ? this->ClippingPlanes->GetNumberOfItems() : 0;
  os << indent << "ClippingPlanes honoured: " << planes << " plane(s), at most "
     << avs::ClipRegion::MaximumNumberOfPlanes
     << (planes > avs::ClipRegion::MaximumNumberOfPlanes
            ? " (too many: rendering reports an error, draws nothing)"
            : "")
     << "\n";
  os << indent << "Cropping honoured: " << (this->Cropping ? "On" : "Off") << ", flags 0x"
     << std::hex << this->CroppingRegionFlags << std::dec << "\n";
  const bool blendHonoured = this->GetEffect() == 0
    ? vtkAVSShaderOptions::IsSupportedBlend(this->BlendMode)
    : this->BlendMode == vtkVolumeMapper::COMPOSITE_BLEND;
  os << indent << "BlendMode: " << vtkAVSShaderOptions::BlendModeName(this->BlendMode)
     << (blendHonoured
            ? (this->BlendMode == vtkVolumeMapper::COMPOSITE_BLEND
                  ? " (honoured)"
                  : " (honoured on one-component data; masks: binary only)")
            : " (not honoured by this mapper: rendering reports an error, draws nothing)")
     << "\n";
  os << indent << "NumberOfDataUploads: " << this->NumberOfDataUploads << "\n";
  os << indent << "NumberOfExtinctionRebuilds: " << this->GetNumberOfExtinctionRebuilds() << "\n";
  os << indent << "NumberOfLightVolumeRebuilds: " << this->GetNumberOfLightVolumeRebuilds() << "\n";
  os << indent << "NumberOfOcclusionRebuilds: " << this->GetNumberOfOcclusionRebuilds() << "\n";
  os << indent << "NumberOfDiffusionRebuilds: " << this->GetNumberOfDiffusionRebuilds() << "\n";
  os << indent << "NumberOfRenderedFrames: " << this->NumberOfRenderedFrames << "\n";
  os << indent << "NumberOfInteractiveFrames: " << this->NumberOfInteractiveFrames << "\n";
  os << indent << "MaximumGPUMemory: " << this->MaximumGPUMemory
     << (this->MaximumGPUMemory > 0 ? " MiB" : " (what the OpenGL context reports)") << "\n";
  os << indent << "Partitions: (" << this->Partitions[0] << ", " << this->Partitions[1] << ", "
     << this->Partitions[2] << ")"
     << (this->Partitions[0] * this->Partitions[1] * this->Partitions[2] == 1
            ? " (automatic: split where the 3D-texture limit needs it)"
            : "")
     << "\n";
  os << indent << "NumberOfBricks: " << this->NumberOfBricks << "\n";
  os << indent << "GPUMemoryBytes: " << this->GetGPUMemoryBytes() << "\n";
  os << indent << "GPUMemoryPeakBytes: " << this->GetGPUMemoryPeakBytes() << "\n";
}

double vtkAVSVolumeMapper::GetGPUMemoryBytes() const
{
  return this->Internal->RayCaster.VolumeTextureBytes();
}

double vtkAVSVolumeMapper::GetGPUMemoryPeakBytes() const
{
  return this->Internal->RayCaster.PeakVolumeTextureBytes();
}

void vtkAVSVolumeMapper::SetPartitions(int x, int y, int z)
{
  x = std::max(1, x);
  y = std::max(1, y);
  z = std::max(1, z);
  if (x != this->Partitions[0] || y != this->Partitions[1] || z != this->Partitions[2])
  {
    this->Partitions[0] = x;
    this->Partitions[1] = y;
    this->Partitions[2] = z;
    this->Modified();
  }
}
