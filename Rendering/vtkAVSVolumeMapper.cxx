#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "Classifier.h"
#include "ImageSampleDistance.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "vtkAVSClipTranslator.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSPropertyTranslator.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSSceneTranslator.h"
#include "vtkAVSShaderOptions.h"
#include "vtkAVSTextureMemory.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
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
  double* bounds = this->Superclass::GetBounds();
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

void vtkAVSVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  auto& in = *this->Internal;
  if (window && window == in.RayCaster.GetWindow())
  {
    in.RayCaster.ReleaseGraphicsResources(window);
    in.ScalarsUploaded = in.TransferUploaded = in.LightVolumesUploaded = in.OcclusionUploaded =
      in.DiffuseUploaded = false;
    in.SliceTable = nullptr;
    in.AveragedRadius = -1.0;
    in.ForgetUploadedContent();
  }
}

bool vtkAVSVolumeMapper::PrepareScene(vtkVolume* volume)
{
  auto& in = *this->Internal;
  std::string error;

  // The input and the mask, converted and checked when they changed
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
  if (property != in.PropertyObject || property->GetMTime() != in.PropertyTime ||
    this->GetMTime() != in.ClassificationTime)
  {
    std::string warning;
    avs::MediumOptions& medium = in.Scene.Medium;
    medium.Mask = medium.MaskValues.Values.empty()
      ? avs::MaskType::None
      : (this->MaskType == BinaryMaskType ? avs::MaskType::Binary : avs::MaskType::LabelMap);
    medium.MaskBlendFactor = this->MaskBlendFactor;
    if (!vtkAVSPropertyTranslator::ToMedium(property,
          in.Ranges,
          in.ScalarType,
          medium.Mask == avs::MaskType::LabelMap,
          in.Scene,
          error,
          warning))
    {
      in.PropertyObject = nullptr;
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning << ".");
    }
    this->WarnAboutShading(property);
    in.PropertyObject = property;
    in.PropertyTime = property->GetMTime();
    in.ClassificationTime = this->GetMTime();
    in.TransferUploaded = false;
    ++in.TransferVersion;
    // Extinction depends on the opacity alone: a change of colour alone rebuilds nothing.
    std::vector<double> inputs = avs::ExtinctionKey(in.Scene);
    if (inputs != in.ExtinctionInputs)
    {
      in.ExtinctionInputs = std::move(inputs);
      ++in.OpacityVersion;
    }
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

  // Clipping planes (world) and cropping (data coordinates) in the index frame.
  avs::ClipRegion clip;
  if (!vtkAVSClipTranslator::ToClipRegion(this->ClippingPlanes,
        this->Cropping != 0,
        this->CroppingRegionPlanes,
        this->CroppingRegionFlags,
        input,
        g,
        dataToWorld,
        clip,
        error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  // The clip region is in the scene (its index frame); a change bumps OpacityVersion, since
  // sigma_t depends on it (everything built from sigma_t is rebuilt).
  if (clip != in.Scene.Clip)
  {
    in.Scene.Clip = clip;
    ++in.OpacityVersion;
  }

  return true;
}

bool vtkAVSVolumeMapper::Prepare(vtkRenderer* renderer, vtkVolume* volume, bool interactive)
{
  auto& in = *this->Internal;
  std::string error;
  if (!this->PrepareScene(volume))
  {
    return false;
  }
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
  if (partitions != in.UploadedPartitions || moreLayers)
  {
    in.ScalarsUploaded = false;
  }
  this->LastDataUploadFraction = 0.0; // unless this frame uploads the data
  if (!in.ScalarsUploaded)
  {
    const bool wasBricked = in.RayCaster.IsBricked();
    if (!in.RayCaster.UploadScalars(
          in.Scene, in.ScalarType, in.ScalarSource(), partitions, lookBack, error))
    {
      // Some textures may hold part of the new data: none is trusted for the next upload.
      in.ForgetUploadedContent();
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.ScalarsUploaded = true;
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
      in.TransferUploaded = false; // the mask and validity follow the bricks
    }
  }
  if (!in.TransferUploaded)
  {
    if (!in.RayCaster.UploadClassification(in.Scene, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.TransferUploaded = true;
  }

  const int effect = this->GetEffect();
  if (effect == 0)
  {
    return true;
  }
  // Ambient scattering with compute shaders needs no extinction grid on the CPU. (The GPU
  // light-volume pass takes tables of up to MaximumTauNodes tau nodes; larger user tables are
  // marched on the CPU.)
  const avs::ScatteringTable* table = effect == 2 ? this->GetScatteringTable() : nullptr;
  if (effect == 2 && !table)
  {
    return false; // the subclass reported why
  }
  const bool gpuScattering = effect == 2 && this->PrecomputeOnGPU &&
    in.RayCaster.SupportsComputeShaders() &&
    table->Axes.NumberOfTau <= vtkAVSRayCaster::MaximumTauNodes;
  // (A piece of a larger whole computes its share of the averaged extinction on the CPU, and so
  // does a split volume: the GPU pass reads the unsplit scalars' texture. Ambient occlusion asks
  // for the grid itself where it computes on the CPU.)
  if (effect == 2 && (!gpuScattering || this->LitAsPiece || in.RayCaster.IsBricked()))
  {
    this->UpdateExtinction();
  }

  if (effect == 1)
  {
    return this->PrepareOcclusion();
  }
  return this->PrepareScattering(table, gpuScattering, in.WorldToData, interactive);
}

void vtkAVSVolumeMapper::WarnAboutShading(vtkVolumeProperty* property)
{
  // Phong shading (ShadeOn with the ambient, diffuse, specular coefficients and the specular
  // power) has no meaning for these physically based mappers: EA and AO are never lit by the
  // property's coefficients, ambient scattering is always lit by its scattering model.
  std::string warning;
  bool shade = false, phong = false;
  for (int c = 0; c < VTK_MAX_VRCOMP; ++c)
  {
    shade = shade || property->GetShade(c);
    phong = phong ||
      (property->GetShade(c) &&
        (property->GetAmbient(c) != 0.1 || property->GetDiffuse(c) != 0.7 ||
          property->GetSpecular(c) != 0.2 || property->GetSpecularPower(c) != 10.0));
  }
  if (shade)
  {
    if (this->GetEffect() != 2)
    {
      warning = "ShadeOn has no effect on " + std::string(this->GetClassName()) +
        ": it does not shade (vtkAmbientScatteringVolumeMapper lights the volume by scattering)";
    }
    else if (phong)
    {
      warning = "the property's ambient, diffuse and specular coefficients and specular power are "
                "not used: ambient scattering lights the volume through its scattering model "
                "(Albedo, Anisotropy, the renderer's lights)";
    }
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
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto& in = *this->Internal;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("Cannot render: this mapper needs an OpenGL render window.");
    return;
  }
  // Inside vtkDualDepthPeelingPass's volume peeling the volume is drawn once, in the first call
  // (see vtkAVSRenderPasses).
  const vtkAVSRenderPasses::Role role = vtkAVSRenderPasses::RoleOf(volume, this);
  if (role == vtkAVSRenderPasses::Role::Skip)
  {
    return;
  }
  if (window != in.RayCaster.GetWindow())
  {
    // Another window: its context gets its own resources.
    this->ReleaseGraphicsResources(in.RayCaster.GetWindow());
    in.ForgetUploadedContent();
    in.RayCaster.SetWindow(window);
    in.ScalarsUploaded = in.TransferUploaded = in.LightVolumesUploaded = in.OcclusionUploaded =
      false;
    in.SliceTable = nullptr;
    in.AveragedRadius = -1.0;
  }
  // Blend modes: emission-absorption renders VTK's (but slice), the lit mappers composite only.
  const bool lit = this->GetEffect() != 0;
  if (lit ? this->BlendMode != vtkVolumeMapper::COMPOSITE_BLEND
          : !vtkAVSShaderOptions::IsSupportedBlend(this->BlendMode))
  {
    vtkErrorMacro(
      "Cannot render: " << this->GetClassName() << " does not render the "
                        << vtkAVSShaderOptions::BlendModeName(this->BlendMode)
                        << " blend mode (BlendMode " << this->BlendMode << "); "
                        << (lit ? "it renders the composite blend mode only"
                                : "vtkEmissionAbsorptionVolumeMapper renders composite, "
                                  "maximum, minimum and average intensity, additive "
                                  "and isosurface"));
    return;
  }
  vtkAVSShaderOptions::Blend blend;
  blend.Mode = this->BlendMode;
  if (blend.Mode == vtkVolumeMapper::ISOSURFACE_BLEND)
  {
    vtkContourValues* contours =
      volume->GetProperty() ? volume->GetProperty()->GetIsoSurfaceValues() : nullptr;
    for (int c = 0; contours && c < contours->GetNumberOfContours(); ++c)
    {
      blend.IsoValues.push_back(contours->GetValue(c));
    }
    if (blend.IsoValues.empty())
    {
      return; // as vtkGPUVolumeRayCastMapper: no contour, nothing to draw
    }
    std::sort(blend.IsoValues.begin(), blend.IsoValues.end());
  }
  // VTK's test for an interactive render (vtkGPUVolumeRayCastMapper's and
  // vtkFixedPointVolumeRayCastMapper's): less than a second allotted to the volume.
  const double allocated = volume->GetAllocatedRenderTime();
  const bool adjust = this->AutoAdjustSampleDistances != 0;
  const bool interactive = adjust && allocated < 1.0;
  // The GPU memory budget of this volume's textures, for its uploads and its draw.
  const vtkAVSTextureMemory::ScopedBudget budget(this->MaximumGPUMemory > 0
      ? this->MaximumGPUMemory * 1024.0 * 1024.0
      : in.RayCaster.ReportedGPUMemoryBytes());
  if (!this->Prepare(renderer, volume, interactive))
  {
    // Nothing of a volume that could not be prepared stays on the GPU (one that does not fit
    // gets one error, and the next starts from nothing).
    this->ReleaseGraphicsResources(window);
    return;
  }
  if (!lit && blend.Mode != vtkVolumeMapper::COMPOSITE_BLEND &&
    in.Scene.Medium.NumberOfComponents() > 1)
  {
    vtkErrorMacro("Cannot render: the " << vtkAVSShaderOptions::BlendModeName(this->BlendMode)
                                        << " blend mode takes one-component data; this volume has "
                                        << in.Scene.Medium.NumberOfComponents()
                                        << " components (use the composite blend mode)");
    return;
  }
  if (blend.Mode != vtkVolumeMapper::COMPOSITE_BLEND && in.RayCaster.IsBricked())
  {
    // Each brick's pass sees a part of the ray: the extreme value, the average, the sum and the
    // crossings between two samples are not what "over" of the parts gives.
    vtkErrorMacro("Cannot render: the "
      << vtkAVSShaderOptions::BlendModeName(this->BlendMode) << " blend mode is not rendered on a "
      << "volume split into bricks (" << in.RayCaster.GetNumberOfBricks()
      << "; see SetPartitions): use the composite blend mode, or a volume within one 3D texture");
    this->ReleaseGraphicsResources(window); // nothing of it stays on the GPU
    return;
  }
  blend.ScalarRange[0] = in.Scene.Transfer.Minimum;
  blend.ScalarRange[1] = in.Scene.Transfer.Maximum;
  blend.AverageRange[0] = std::min(this->AverageIPScalarRange[0], this->AverageIPScalarRange[1]);
  blend.AverageRange[1] = std::max(this->AverageIPScalarRange[0], this->AverageIPScalarRange[1]);
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  double distance = this->ImageSampleDistance;
  if (adjust)
  {
    avs::FrameBudget budget;
    budget.AllocatedSeconds = allocated;
    budget.SecondsPerRay = in.SecondsPerRay;
    budget.Pixels = static_cast<double>(width) * height;
    budget.Previous = this->LastImageSampleDistance;
    budget.Minimum = this->MinimumImageSampleDistance;
    budget.Maximum = this->MaximumImageSampleDistance;
    distance = avs::ChooseImageSampleDistance(budget);
  }
  vtkAVSRayCaster::Frame frame;
  frame.Mode = this->GetEffect() == 0
    ? avs::RenderMode::EmissionAbsorption
    : (this->GetEffect() == 1 ? avs::RenderMode::AmbientOcclusion
                              : avs::RenderMode::AmbientScattering);
  frame.Parameters = in.Parameters;
  frame.WorldToIndex = in.WorldToIndex;
  frame.Dimensions = in.Scene.Scalars.Geometry.Dimensions;
  frame.Spacing = in.Scene.Scalars.Geometry.Spacing;
  frame.Border = in.Scene.Scalars.Geometry.Border;
  frame.Clip = in.Scene.Clip;
  frame.Blend = blend;
  frame.LightVolumeDimensions = in.LightGridDimensions;
  frame.LightsPerPair = avs::ScatteringParameters::LightsPerPair(
    in.Parameters.SampleDistance, in.Whole.Capped(in.Parameters.LightVolumeMaximumDimension));
  frame.WholeDimensions = in.Whole.Dimensions;
  frame.PieceOffset = in.PieceOffset;
  frame.OcclusionDimensions = in.OcclusionDimensions;
  frame.Lights = in.WorldLights;
  frame.Jitter = this->UseJittering != 0;
  frame.Prop = volume;
  frame.Mapper = this;
  frame.PeelingFront = role == vtkAVSRenderPasses::Role::PeelingFront;
  frame.ImageSampleDistance = distance;
  frame.Display = this->ResolveDisplay(renderer, volume);
  frame.SkipEmptySpace = this->EmptySpaceSkipping != 0;
  // VTK's still frame: a second or more allotted (the interactor's frames get less).
  this->ResolveRefinement(renderer,
    volume,
    allocated >= 1.0,
    in.RayCaster.IsBricked(),
    frame.Refinement.Enabled,
    frame.Refinement.Still,
    frame.Refinement.Key,
    frame.Refinement.Geometry);
  frame.Refinement.MaximumSamples = this->MaximumSamplesPerPixel;
  // The adjustment times the ray-casting pass alone (the precomputation does not scale with the
  // rays), finished on the GPU as vtkOpenGLGPUVolumeRayCastMapper finishes its frames.
  if (adjust)
  {
    window->WaitForCompletion();
  }
  const auto passStart = Clock::now();
  std::string error;
  if (!in.RayCaster.Render(renderer, frame, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return;
  }
  if (adjust && !in.RayCaster.GetLastRefined()) // (a refined frame is no ray-casting pass)
  {
    window->WaitForCompletion();
    const auto& rays = in.RayCaster.GetLastPassSize();
    const double seconds = std::chrono::duration<double>(Clock::now() - passStart).count();
    in.SecondsPerRay = seconds / std::max(1.0, static_cast<double>(rays[0]) * rays[1]);
  }
  this->LastImageSampleDistance = static_cast<float>(distance);
  this->LastExposure = frame.Display.Exposure;
  this->LastToneMapping =
    frame.Display.Curve == avs::ToneMapping::Shoulder ? ShoulderToneMapping : ClampToneMapping;
  this->NumberOfBricks = in.RayCaster.GetNumberOfBricks();
  this->LastEmptyCellFraction = in.RayCaster.GetEmptyCellFraction();
  this->LastSkippedEmptySpace = in.RayCaster.GetLastSkippedEmptySpace() ? 1 : 0;
  ++this->NumberOfRenderedFrames;
  if (interactive)
  {
    ++this->NumberOfInteractiveFrames;
  }
  this->TimeToDraw = std::chrono::duration<double>(Clock::now() - start).count();
}

avs::DisplayTransform vtkAVSVolumeMapper::ResolveDisplay(vtkRenderer* renderer, vtkVolume* volume)
{
  const avs::ScatteringParameters& rp = this->Internal->Parameters;
  avs::DisplayTransform display = rp.Display;
  // Auto exposure meters the lights (world space) over the world box of the whole image (of
  // which the input may be a piece: every process of a distributed render meters the same);
  // only ambient scattering is lit by them.
  if (rp.AutoExposure && this->GetEffect() == 2)
  {
    display.Exposure *= avs::AutoExposureFactor(
      this->Internal->WorldLights, this->Internal->Whole, &volume->GetMatrix()->Element[0][0]);
  }
  // Under vtkToneMappingPass the pass maps the picture: the radiance goes to it linear.
  if (vtkAVSRenderPasses::UnderToneMapping(renderer))
  {
    display.Curve = avs::ToneMapping::Clamp;
  }
  return display;
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
  os << indent << "LightVolumesOnGPU: " << (this->LightVolumesOnGPU ? "yes" : "no") << "\n";
  os << indent << "OcclusionOnGPU: " << (this->OcclusionOnGPU ? "yes" : "no") << "\n";
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
  os << indent << "NumberOfExtinctionRebuilds: " << this->NumberOfExtinctionRebuilds << "\n";
  os << indent << "NumberOfLightVolumeRebuilds: " << this->NumberOfLightVolumeRebuilds << "\n";
  os << indent << "NumberOfOcclusionRebuilds: " << this->NumberOfOcclusionRebuilds << "\n";
  os << indent << "NumberOfDiffusionRebuilds: " << this->NumberOfDiffusionRebuilds << "\n";
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
