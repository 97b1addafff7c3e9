#include "vtkAVSVolumeMapper.h"

#include "AmbientOcclusion.h"
#include "AveragedExtinction.h"
#include "LightVolume.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSRayCaster.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSSceneTranslator.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>

struct vtkAVSVolumeMapper::Internals
{
  vtkAVSRayCaster RayCaster;

  // What the uploaded data came from: the image, the selected array and the selection.
  vtkImageData* DataObject = nullptr;
  vtkMTimeType DataTime = 0;
  vtkDataArray* ArrayObject = nullptr;
  vtkMTimeType ArrayTime = 0;
  vtkAVSDataTranslator::Selection Selection;
  avs::Grid Scalars;
  double ScalarRange[2] = { 0.0, 1.0 };
  bool ScalarsUploaded = false;

  vtkVolumeProperty* PropertyObject = nullptr;
  vtkMTimeType PropertyTime = 0;
  double UnitDistance = 1.0;
  avs::TransferFunction Transfer;
  bool TransferUploaded = false;

  // Versions of the derived volumes: a change of a version invalidates what uses it.
  int DataVersion = 0;
  int TransferVersion = 0;
  int ExtinctionKey[2] = { -1, -1 }; // data, opacity versions of Extinction
  // What sigma_t depends on, and its version (a colour change leaves it).
  int OpacityVersion = 0;
  std::vector<float> ExtinctionOpacity;
  double ExtinctionRange[2] = { 0.0, 0.0 };
  double ExtinctionUnitDistance = -1.0;
  avs::Grid Extinction;

  // Ambient scattering.
  int AveragedKey[2] = { -1, -1 };
  double AveragedRadius = -1.0;
  avs::Grid Averaged; ///< on the light grid (CPU precomputation)
  int AveragedVersion = 0;
  int AveragedOnGPU = -1;
  std::array<int, 3> AveragedDimensions{ 0, 0, 0 }; ///< the light grid it was computed on
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
    bool Built = false;
    avs::Grid Volume; ///< CPU path only
  };
  std::vector<LightState> Lights;
  bool LightVolumesUploaded = false;
  int LightsOnGPU = -1;
  std::array<int, 3> LightGridDimensions{ 2, 2, 2 };

  // Ambient occlusion.
  std::array<int, 3> OcclusionDimensions{ 0, 0, 0 };
  int OcclusionKey[2] = { -1, -1 };
  double OcclusionRadius = -1.0;
  int OcclusionDirections = -1;
  bool OcclusionUploaded = false;

  vtkNew<vtkMatrix4x4> WorldToIndex;
  avs::ScatteringParameters Parameters;
  std::vector<avs::Light> WorldLights;
};

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

vtkAVSVolumeMapper::vtkAVSVolumeMapper()
  : Internal(new Internals)
{
}

vtkAVSVolumeMapper::~vtkAVSVolumeMapper()
{
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
      false;
    in.SliceTable = nullptr;
    in.AveragedRadius = -1.0;
  }
}

bool vtkAVSVolumeMapper::Prepare(vtkRenderer* renderer, vtkVolume* volume)
{
  auto& in = *this->Internal;
  std::string error;

  // The input, converted and checked when it changed.
  if (vtkAlgorithm* producer = this->GetInputAlgorithm())
  {
    producer->Update();
  }
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  if (!input)
  {
    vtkErrorMacro("Cannot render: no input image data.");
    return false;
  }
  // The array to draw, as vtkGPUVolumeRayCastMapper selects it.
  vtkAVSDataTranslator::Selection selection;
  selection.ScalarMode = this->ScalarMode;
  selection.ArrayAccessMode = this->ArrayAccessMode;
  selection.ArrayId = this->ArrayId;
  selection.ArrayName = this->ArrayName ? this->ArrayName : "";
  bool cellData = false;
  vtkDataArray* array = vtkAVSDataTranslator::Select(input, selection, cellData, error);
  if (!array)
  {
    in.DataObject = nullptr;
    in.Scalars = avs::Grid();
    vtkErrorMacro("Cannot render: " << error);
    return false;
  }
  const bool sameSelection = selection.ScalarMode == in.Selection.ScalarMode &&
    selection.ArrayAccessMode == in.Selection.ArrayAccessMode &&
    selection.ArrayId == in.Selection.ArrayId && selection.ArrayName == in.Selection.ArrayName;
  if (input != in.DataObject || input->GetMTime() != in.DataTime || array != in.ArrayObject ||
    array->GetMTime() != in.ArrayTime || !sameSelection || in.Scalars.Values.empty())
  {
    vtkAVSDataTranslator::Volume data;
    std::string warning;
    if (!vtkAVSDataTranslator::ToVolume(input, selection, data, error, warning))
    {
      in.DataObject = nullptr;
      in.Scalars = avs::Grid();
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    if (data.Components.size() != 1)
    {
      in.DataObject = nullptr;
      in.Scalars = avs::Grid();
      vtkErrorMacro("Cannot render: unsupported number of scalar components: "
        << data.Components.size() << " (only single-component scalars are supported)");
      return false;
    }
    if (data.NaNVoxels || data.Infinities)
    {
      in.DataObject = nullptr;
      in.Scalars = avs::Grid();
      vtkErrorMacro("Cannot render: the scalars contain NaN or infinite values");
      return false;
    }
    in.Scalars = std::move(data.Components[0]);
    in.ScalarRange[0] = data.Ranges[0][0];
    in.ScalarRange[1] = data.Ranges[0][1];
    in.DataObject = input;
    in.DataTime = input->GetMTime();
    in.ArrayObject = array;
    in.ArrayTime = array->GetMTime();
    in.Selection = selection;
    in.ScalarsUploaded = false;
    ++in.DataVersion;
    in.PropertyObject = nullptr; // the scalar range may have changed
  }
  vtkVolumeProperty* property = volume->GetProperty();
  if (!property)
  {
    vtkErrorMacro("Cannot render: the volume has no property.");
    return false;
  }
  if (property != in.PropertyObject || property->GetMTime() != in.PropertyTime)
  {
    if (!vtkAVSSceneTranslator::ToTransferFunction(
          property, in.ScalarRange[0], in.ScalarRange[1], in.Transfer, in.UnitDistance, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.PropertyObject = property;
    in.PropertyTime = property->GetMTime();
    in.TransferUploaded = false;
    ++in.TransferVersion;
    // Extinction depends on the opacity alone: a change of colour alone rebuilds nothing.
    if (in.Transfer.Opacity != in.ExtinctionOpacity ||
      in.Transfer.Minimum != in.ExtinctionRange[0] ||
      in.Transfer.Maximum != in.ExtinctionRange[1] || in.UnitDistance != in.ExtinctionUnitDistance)
    {
      in.ExtinctionOpacity = in.Transfer.Opacity;
      in.ExtinctionRange[0] = in.Transfer.Minimum;
      in.ExtinctionRange[1] = in.Transfer.Maximum;
      in.ExtinctionUnitDistance = in.UnitDistance;
      ++in.OpacityVersion;
    }
  }

  // Parameters: base values, then the subclass's.
  avs::ScatteringParameters p;
  p.SampleDistance = this->SampleDistance;
  p.TerminationTransmittance = this->TerminationTransmittance;
  this->FillParameters(p);
  in.Parameters = p.Resolve(in.Scalars.Geometry);
  const avs::ScatteringParameters& rp = in.Parameters;

  // Transforms: data -> world is the volume's matrix; index -> data is the grid's placement.
  const avs::GridGeometry& g = in.Scalars.Geometry;
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
  vtkNew<vtkMatrix4x4> worldToData;
  worldToData->DeepCopy(dataToWorld);
  worldToData->Invert();

  // Lights in world space, at most 8.
  in.WorldLights =
    vtkAVSSceneTranslator::ToLights(renderer, renderer->GetActiveCamera(), rp.LightScale);
  if (in.WorldLights.size() > static_cast<std::size_t>(vtkAVSRayCaster::MaximumNumberOfLights))
  {
    vtkWarningMacro("Only the first " << vtkAVSRayCaster::MaximumNumberOfLights << " of "
                                      << in.WorldLights.size() << " lights are used.");
    in.WorldLights.resize(vtkAVSRayCaster::MaximumNumberOfLights);
  }

  // Uploads of what changed.
  if (!in.ScalarsUploaded)
  {
    if (!in.RayCaster.UploadScalars(in.Scalars, error))
    {
      vtkErrorMacro("Cannot render: " << error);
      return false;
    }
    in.ScalarsUploaded = true;
    ++this->NumberOfDataUploads;
  }
  if (!in.TransferUploaded)
  {
    if (!in.RayCaster.UploadTransferFunction(in.Transfer, error))
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
  avs::VolumeScene scene;
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
  if (!gpuScattering &&
    (in.ExtinctionKey[0] != in.DataVersion || in.ExtinctionKey[1] != in.OpacityVersion))
  {
    scene.Transfer = in.Transfer;
    scene.UnitDistance = in.UnitDistance;
    scene.Scalars.Geometry = g;
    scene.Scalars.Values = in.Scalars.Values;
    in.Extinction = avs::ExtinctionGrid(scene);
    in.ExtinctionKey[0] = in.DataVersion;
    in.ExtinctionKey[1] = in.OpacityVersion;
  }

  if (effect == 1)
  {
    // The occlusion volume's grid: the data's, capped like the light volumes'.
    const avs::GridGeometry occlusionGrid = g.Capped(rp.OcclusionVolumeMaximumDimension);
    if (in.OcclusionKey[0] != in.ExtinctionKey[0] || in.OcclusionKey[1] != in.ExtinctionKey[1] ||
      in.OcclusionRadius != rp.OcclusionRadius || in.OcclusionDirections != rp.NumberOfDirections ||
      in.OcclusionDimensions != occlusionGrid.Dimensions || !in.OcclusionUploaded)
    {
      this->UpdateProgress(0.0);
      const bool gpu = this->PrecomputeOnGPU && in.RayCaster.SupportsComputeShaders() &&
        rp.NumberOfDirections <= 256;
      if (gpu)
      {
        if (!in.RayCaster.ComputeOcclusion(in.Extinction,
              occlusionGrid.Dimensions,
              rp.OcclusionRadius,
              rp.NumberOfDirections,
              error))
        {
          vtkErrorMacro("Cannot render: " << error);
          return false;
        }
      }
      else
      {
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
      in.OcclusionKey[0] = in.ExtinctionKey[0];
      in.OcclusionKey[1] = in.ExtinctionKey[1];
      in.OcclusionRadius = rp.OcclusionRadius;
      in.OcclusionDirections = rp.NumberOfDirections;
      in.OcclusionDimensions = occlusionGrid.Dimensions;
      in.OcclusionUploaded = true;
      ++this->NumberOfOcclusionRebuilds;
    }
    return true;
  }

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
  // The averaged extinction and the light volumes share the light grid.
  const avs::GridGeometry lightGrid = g.Capped(rp.LightVolumeMaximumDimension);
  if (in.AveragedKey[0] != in.DataVersion || in.AveragedKey[1] != in.OpacityVersion ||
    in.AveragedRadius != rp.AmbientRadius || in.AveragedOnGPU != (gpuScattering ? 1 : 0) ||
    in.AveragedDimensions != lightGrid.Dimensions)
  {
    if (gpuScattering)
    {
      if (!in.RayCaster.ComputeAveragedExtinction(g.Dimensions,
            lightGrid.Dimensions,
            in.UnitDistance,
            avs::AveragingHalfWidths(rp.AmbientRadius, g.Spacing),
            error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    else
    {
      in.Averaged = avs::AverageExtinctionOn(in.Extinction, rp.AmbientRadius, lightGrid);
      if (!in.RayCaster.UploadScalarsAveraged(
            in.Scalars, avs::ResampleTrilinear(in.Averaged, g), error))
      {
        vtkErrorMacro("Cannot render: " << error);
        return false;
      }
    }
    in.AveragedKey[0] = in.DataVersion;
    in.AveragedKey[1] = in.OpacityVersion;
    in.AveragedOnGPU = gpuScattering ? 1 : 0;
    in.AveragedRadius = rp.AmbientRadius;
    in.AveragedDimensions = lightGrid.Dimensions;
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
  in.Lights.resize(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    avs::Light dataLight = in.WorldLights[j];
    dataLight.Position = Transform(worldToData, dataLight.Position);
    dataLight.FocalPoint = Transform(worldToData, dataLight.FocalPoint);
    auto& state = in.Lights[j];
    if (!state.Built || !SamePose(state.DataFrame, dataLight) ||
      state.AveragedVersion != in.AveragedVersion || state.SliceVersion != in.SliceVersion ||
      state.Radius != rp.AmbientRadius)
    {
      this->UpdateProgress(static_cast<double>(j) / n);
      if (gpu)
      {
        if (!in.RayCaster.ComputeLightVolume(
              static_cast<int>(j), lightGrid, dataLight, rp.AmbientRadius, error))
        {
          vtkErrorMacro("Cannot render: " << error);
          return false;
        }
      }
      else
      {
        state.Volume = avs::ComputeLightVolume(in.Averaged,
          lightGrid,
          dataLight,
          in.Slice,
          rp.AmbientRadius,
          nullptr,
          [this, j, n](double v) { this->UpdateProgress((j + v) / static_cast<double>(n)); });
        changed = true;
      }
      state.DataFrame = dataLight;
      state.AveragedVersion = in.AveragedVersion;
      state.SliceVersion = in.SliceVersion;
      state.Radius = rp.AmbientRadius;
      state.Built = true;
      ++this->NumberOfLightVolumeRebuilds;
    }
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
  return true;
}

void vtkAVSVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
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
    in.RayCaster.SetWindow(window);
    in.ScalarsUploaded = in.TransferUploaded = in.LightVolumesUploaded = in.OcclusionUploaded =
      false;
    in.SliceTable = nullptr;
    in.AveragedRadius = -1.0;
  }
  if (!this->Prepare(renderer, volume))
  {
    return;
  }
  vtkAVSRayCaster::Frame frame;
  frame.Mode = this->GetEffect() == 0
    ? avs::RenderMode::EmissionAbsorption
    : (this->GetEffect() == 1 ? avs::RenderMode::AmbientOcclusion
                              : avs::RenderMode::AmbientScattering);
  frame.Parameters = in.Parameters;
  frame.WorldToIndex = in.WorldToIndex;
  frame.Dimensions = in.Scalars.Geometry.Dimensions;
  frame.Border = in.Scalars.Geometry.Border;
  frame.LightVolumeDimensions = in.LightGridDimensions;
  frame.OcclusionDimensions = in.OcclusionDimensions;
  frame.UnitDistance = in.UnitDistance;
  frame.Lights = in.WorldLights;
  frame.Jitter = this->UseJittering != 0;
  frame.Prop = volume;
  frame.Mapper = this;
  frame.PeelingFront = role == vtkAVSRenderPasses::Role::PeelingFront;
  std::string error;
  if (!in.RayCaster.Render(renderer, frame, error))
  {
    vtkErrorMacro("Cannot render: " << error);
    return;
  }
  ++this->NumberOfRenderedFrames;
}

void vtkAVSVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDistance: " << this->SampleDistance
     << (this->SampleDistance > 0 ? "" : " (automatic)") << "\n";
  os << indent << "UseJittering: " << (this->UseJittering ? "On" : "Off") << "\n";
  os << indent << "TerminationTransmittance: " << this->TerminationTransmittance << "\n";
  os << indent << "PrecomputeOnGPU: " << (this->PrecomputeOnGPU ? "On" : "Off") << "\n";
  os << indent << "LightVolumesOnGPU: " << (this->LightVolumesOnGPU ? "yes" : "no") << "\n";
  os << indent << "OcclusionOnGPU: " << (this->OcclusionOnGPU ? "yes" : "no") << "\n";
  os << indent << "NumberOfDataUploads: " << this->NumberOfDataUploads << "\n";
  os << indent << "NumberOfExtinctionRebuilds: " << this->NumberOfExtinctionRebuilds << "\n";
  os << indent << "NumberOfLightVolumeRebuilds: " << this->NumberOfLightVolumeRebuilds << "\n";
  os << indent << "NumberOfOcclusionRebuilds: " << this->NumberOfOcclusionRebuilds << "\n";
  os << indent << "NumberOfRenderedFrames: " << this->NumberOfRenderedFrames << "\n";
}
