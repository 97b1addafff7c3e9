// vtkAVSVolumeMapper: the frame's assembly (Internals' FrameAssembly): the blend-mode rules
// before and after the scene is prepared, the image sample distance, the display transform and
// the refinement's settings, gathered into the ray caster's frame.
#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "DisplayTransform.h"
#include "ImageSampleDistance.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderOptions.h"

#include "vtkContourValues.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

bool vtkAVSVolumeMapper::ResolveBlend(vtkVolume* volume, FrameAssembly& assembly)
{
  vtkAVSShaderOptions::Blend& blend = assembly.Frame.Blend;
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
    return false;
  }
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
      return false; // as vtkGPUVolumeRayCastMapper: no contour, nothing to draw
    }
    std::sort(blend.IsoValues.begin(), blend.IsoValues.end());
  }
  return true;
}

bool vtkAVSVolumeMapper::CheckPreparedBlend(const FrameAssembly& assembly)
{
  auto& in = *this->Internal;
  const vtkAVSShaderOptions::Blend& blend = assembly.Frame.Blend;
  if (this->GetEffect() == 0 && blend.Mode != vtkVolumeMapper::COMPOSITE_BLEND &&
    in.Scene.Medium.NumberOfComponents() > 1)
  {
    vtkErrorMacro("Cannot render: the " << vtkAVSShaderOptions::BlendModeName(this->BlendMode)
                                        << " blend mode takes one-component data; this volume has "
                                        << in.Scene.Medium.NumberOfComponents()
                                        << " components (use the composite blend mode)");
    return false;
  }
  if (blend.Mode != vtkVolumeMapper::COMPOSITE_BLEND && in.RayCaster.IsBricked())
  {
    // Each brick's pass sees a part of the ray: the extreme value, the average, the sum and the
    // crossings between two samples are not what "over" of the parts gives.
    vtkErrorMacro("Cannot render: the "
      << vtkAVSShaderOptions::BlendModeName(this->BlendMode) << " blend mode is not rendered on a "
      << "volume split into bricks (" << in.RayCaster.GetNumberOfBricks()
      << "; see SetPartitions): use the composite blend mode, or a volume within one 3D texture");
    this->ResetGraphicsState(); // nothing of it stays on the GPU
    return false;
  }
  return true;
}

void vtkAVSVolumeMapper::AssembleFrame(vtkRenderer* renderer,
  vtkVolume* volume,
  FrameAssembly& assembly)
{
  auto& in = *this->Internal;
  vtkAVSRayCaster::Frame& frame = assembly.Frame;
  vtkAVSShaderOptions::Blend& blend = frame.Blend;
  blend.ScalarRange[0] = in.Scene.Transfer.Minimum;
  blend.ScalarRange[1] = in.Scene.Transfer.Maximum;
  blend.AverageRange[0] = std::min(this->AverageIPScalarRange[0], this->AverageIPScalarRange[1]);
  blend.AverageRange[1] = std::max(this->AverageIPScalarRange[0], this->AverageIPScalarRange[1]);

  // The image sample distance: fixed, or chosen for the time allotted to the volume.
  const double allocated = volume->GetAllocatedRenderTime();
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  double distance = this->ImageSampleDistance;
  if (this->AutoAdjustSampleDistances)
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
  // The grids of the precomputed volumes (the subclass's; these values where it has none).
  frame.LightVolumeDimensions = { 2, 2, 2 };
  frame.OcclusionDimensions = { 0, 0, 0 };
  this->GetPrecomputedGrids(frame.LightVolumeDimensions, frame.OcclusionDimensions);
  frame.LightGroup = avs::ScatteringParameters::LightGroup(
    in.Parameters.SampleDistance, in.Whole.Capped(in.Parameters.LightVolumeMaximumDimension));
  frame.WholeDimensions = in.Whole.Dimensions;
  frame.PieceOffset = in.PieceOffset;
  frame.Lights = in.WorldLights;
  frame.Jitter = this->UseJittering != 0;
  frame.Prop = volume;
  frame.Mapper = this;
  frame.PeelingFront = assembly.Role == vtkAVSRenderPasses::Role::PeelingFront;
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
