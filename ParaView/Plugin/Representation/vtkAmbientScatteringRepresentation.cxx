#include "vtkAmbientScatteringRepresentation.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkBoundingBox.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutlineSource.h"
#include "vtkPVLODVolume.h"
#include "vtkPVView.h"
#include "vtkPartitionedDataSet.h"
#include "vtkStructuredData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkAmbientScatteringRepresentation);

namespace
{
// The points of `image` that its cells without the ghost flag span (the cells from the first
// to the last that are not ghosts: a block's ghost cells are layers around it); false where every
// cell is a ghost (the block is another rank's data: left out).
bool CropGhostCells(vtkImageData* image)
{
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    image->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (!ghosts)
  {
    return true;
  }
  int points[6];
  image->GetExtent(points);
  const vtkIdType n = ghosts->GetNumberOfTuples();
  vtkIdType first = 0, last = n - 1;
  while (first < n && ghosts->GetValue(first) != 0)
  {
    ++first;
  }
  while (last > first && ghosts->GetValue(last) != 0)
  {
    --last;
  }
  if (first >= n)
  {
    return false;
  }
  int low[3], high[3];
  vtkStructuredData::ComputeCellStructuredCoordsForExtent(first, points, low);
  vtkStructuredData::ComputeCellStructuredCoordsForExtent(last, points, high);
  int crop[6];
  for (int a = 0; a < 3; ++a)
  {
    crop[2 * a] = low[a];
    crop[2 * a + 1] = std::min(high[a] + 1, points[2 * a + 1]);
  }
  image->Crop(crop);
  return true;
}
} // namespace

vtkAmbientScatteringRepresentation::vtkAmbientScatteringRepresentation()
{
  // The superclass made a vtkMultiBlockVolumeMapper; ours takes its place (it gets the input and
  // the scalar selection at each render, in ProcessViewRequest and UpdateMapperParameters).
  this->VolumeMapper = this->AmbientScatteringMapper.GetPointer();
}

vtkAmbientScatteringRepresentation::~vtkAmbientScatteringRepresentation() = default;

void vtkAmbientScatteringRepresentation::SetLightingModel(int model)
{
  if (model < EmissionAbsorption || model > AmbientScattering)
  {
    vtkErrorMacro("LightingModel " << model
                                   << " is none of EmissionAbsorption (0), AmbientOcclusion (1) "
                                      "and AmbientScattering (2); it stays "
                                   << this->LightingModel);
    return;
  }
  if (model == this->LightingModel)
  {
    return;
  }
  vtkVolumeMapper* next = model == EmissionAbsorption
    ? static_cast<vtkVolumeMapper*>(this->EmissionAbsorptionMapper)
    : model == AmbientOcclusion ? static_cast<vtkVolumeMapper*>(this->AmbientOcclusionMapper)
                                : static_cast<vtkVolumeMapper*>(this->AmbientScatteringMapper);
  vtkVolumeMapper* previous = this->VolumeMapper;
  next->SetCropping(previous->GetCropping());
  next->SetCroppingRegionFlags(previous->GetCroppingRegionFlags());
  next->SetBlendMode(previous->GetBlendMode());
  next->SetInputConnection(previous->GetInputConnection(0, 0));
  previous->RemoveAllInputConnections(0);
  this->VolumeMapper = next;
  this->LightingModel = model;
  this->Modified();
}

vtkVolumeMapper* vtkAmbientScatteringRepresentation::GetActiveVolumeMapper()
{
  return this->VolumeMapper;
}

void vtkAmbientScatteringRepresentation::SetAlbedo(double albedo)
{
  this->AmbientScatteringMapper->SetAlbedo(albedo);
}

double vtkAmbientScatteringRepresentation::GetAlbedo()
{
  return this->AmbientScatteringMapper->GetAlbedo();
}

void vtkAmbientScatteringRepresentation::SetVolumetricScatteringBlending(float blending)
{
  this->Superclass::SetVolumetricScatteringBlending(blending);
  this->AmbientScatteringMapper->SetVolumetricScatteringBlending(blending);
}

float vtkAmbientScatteringRepresentation::GetVolumetricScatteringBlending()
{
  return this->AmbientScatteringMapper->GetVolumetricScatteringBlending();
}

void vtkAmbientScatteringRepresentation::SetExposure(double exposure)
{
  this->AmbientScatteringMapper->SetExposure(exposure);
}

double vtkAmbientScatteringRepresentation::GetExposure()
{
  return this->AmbientScatteringMapper->GetExposure();
}

void vtkAmbientScatteringRepresentation::SetToneMapping(int curve)
{
  this->AmbientScatteringMapper->SetToneMapping(curve);
}

int vtkAmbientScatteringRepresentation::GetToneMapping()
{
  return this->AmbientScatteringMapper->GetToneMapping();
}

void vtkAmbientScatteringRepresentation::SetAutoExposure(int on)
{
  this->AmbientScatteringMapper->SetAutoExposure(on);
}

int vtkAmbientScatteringRepresentation::GetAutoExposure()
{
  return this->AmbientScatteringMapper->GetAutoExposure();
}

void vtkAmbientScatteringRepresentation::SetScatteringAnisotropy(double g)
{
  this->AmbientScatteringMapper->SetAnisotropy(g);
}

double vtkAmbientScatteringRepresentation::GetScatteringAnisotropy()
{
  return this->AmbientScatteringMapper->GetAnisotropy();
}

void vtkAmbientScatteringRepresentation::SetAmbientRadius(double radius)
{
  this->AmbientScatteringMapper->SetAmbientRadius(radius);
  this->AmbientOcclusionMapper->SetOcclusionRadius(radius);
}

double vtkAmbientScatteringRepresentation::GetAmbientRadius()
{
  return this->AmbientScatteringMapper->GetAmbientRadius();
}

void vtkAmbientScatteringRepresentation::SetLightScale(double scale)
{
  this->AmbientScatteringMapper->SetLightScale(scale);
  this->AmbientOcclusionMapper->SetLightScale(scale);
}

double vtkAmbientScatteringRepresentation::GetLightScale()
{
  return this->AmbientScatteringMapper->GetLightScale();
}

void vtkAmbientScatteringRepresentation::SetEmissionWeight(double weight)
{
  this->AmbientScatteringMapper->SetEmissionWeight(weight);
  this->AmbientOcclusionMapper->SetEmissionWeight(weight);
}

double vtkAmbientScatteringRepresentation::GetEmissionWeight()
{
  return this->AmbientScatteringMapper->GetEmissionWeight();
}

void vtkAmbientScatteringRepresentation::SetLightVolumeMaximumDimension(int dimension)
{
  this->AmbientScatteringMapper->SetLightVolumeMaximumDimension(dimension);
  this->AmbientOcclusionMapper->SetOcclusionVolumeMaximumDimension(dimension);
}

int vtkAmbientScatteringRepresentation::GetLightVolumeMaximumDimension()
{
  return this->AmbientScatteringMapper->GetLightVolumeMaximumDimension();
}

void vtkAmbientScatteringRepresentation::SetScatteringModel(int model)
{
  this->AmbientScatteringMapper->SetScatteringModel(model);
}

int vtkAmbientScatteringRepresentation::GetScatteringModel()
{
  return this->AmbientScatteringMapper->GetScatteringModel();
}

void vtkAmbientScatteringRepresentation::SetPathTracedRefinement(int on)
{
  this->AmbientScatteringMapper->SetPathTracedRefinement(on != 0);
}

int vtkAmbientScatteringRepresentation::GetPathTracedRefinement()
{
  return this->AmbientScatteringMapper->GetPathTracedRefinement() ? 1 : 0;
}

void vtkAmbientScatteringRepresentation::SetMaximumSamplesPerPixel(int samples)
{
  this->AmbientScatteringMapper->SetMaximumSamplesPerPixel(samples);
}

int vtkAmbientScatteringRepresentation::GetMaximumSamplesPerPixel()
{
  return this->AmbientScatteringMapper->GetMaximumSamplesPerPixel();
}

int vtkAmbientScatteringRepresentation::GetSamplesPerPixel()
{
  return this->AmbientScatteringMapper->GetSamplesPerPixel();
}

void vtkAmbientScatteringRepresentation::SetDiffusionVolumeMaximumDimension(int dimension)
{
  this->AmbientScatteringMapper->SetDiffusionVolumeMaximumDimension(dimension);
}

int vtkAmbientScatteringRepresentation::GetDiffusionVolumeMaximumDimension()
{
  return this->AmbientScatteringMapper->GetDiffusionVolumeMaximumDimension();
}

void vtkAmbientScatteringRepresentation::SetSampleDistance(double distance)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetSampleDistance(distance);
  }
}

double vtkAmbientScatteringRepresentation::GetSampleDistance()
{
  return this->AmbientScatteringMapper->GetSampleDistance();
}

void vtkAmbientScatteringRepresentation::SetUseJittering(int jitter)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetUseJittering(jitter);
  }
}

int vtkAmbientScatteringRepresentation::GetUseJittering()
{
  return this->AmbientScatteringMapper->GetUseJittering();
}

void vtkAmbientScatteringRepresentation::SetMaximumGPUMemory(int mebibytes)
{
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetMaximumGPUMemory(mebibytes);
  }
}

int vtkAmbientScatteringRepresentation::GetMaximumGPUMemory()
{
  return this->AmbientScatteringMapper->GetMaximumGPUMemory();
}

int vtkAmbientScatteringRepresentation::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  const int none[6] = { 0, -1, 0, -1, 0, -1 };
  std::copy(none, none + 6, this->BlocksExtent);
  auto* tree = inputVector[0]->GetNumberOfInformationObjects() == 1
    ? vtkDataObjectTree::GetData(inputVector[0], 0)
    : nullptr;
  if (!tree)
  {
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  // The leaves, images or not (the mappers name what they cannot draw), their bounds and the
  // images' extent.
  vtkMath::UninitializeBounds(this->DataBounds);
  std::copy(none, none + 6, this->WholeExtent);
  vtkNew<vtkPartitionedDataSet> cache;
  vtkBoundingBox bounds;
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->TraverseSubTreeOn();
  it->SkipEmptyNodesOn();
  unsigned int count = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkDataObject* leaf = it->GetCurrentDataObject();
    if (auto* image = vtkImageData::SafeDownCast(leaf))
    {
      vtkNew<vtkImageData> copy; // (the separate opacity array is added to the copy)
      copy->ShallowCopy(image);
      // As the superclass does for an image: pieces that do not overlap across ranks.
      if (copy->HasAnyGhostCells() && !CropGhostCells(copy))
      {
        continue;
      }
      if (this->UseSeparateOpacityArray)
      {
        this->AppendOpacityComponent(copy);
      }
      if (copy->GetNumberOfPoints() > 0)
      {
        bounds.AddBounds(copy->GetBounds());
        const int* e = copy->GetExtent();
        int* b = this->BlocksExtent;
        const bool first = b[0] > b[1];
        for (int a = 0; a < 3; ++a)
        {
          b[2 * a] = first ? e[2 * a] : std::min(b[2 * a], e[2 * a]);
          b[2 * a + 1] = first ? e[2 * a + 1] : std::max(b[2 * a + 1], e[2 * a + 1]);
        }
      }
      cache->SetPartition(count++, copy);
    }
    else
    {
      if (auto* set = vtkDataSet::SafeDownCast(leaf))
      {
        bounds.AddBounds(set->GetBounds());
      }
      cache->SetPartition(count++, leaf);
    }
  }
  if (bounds.IsValid())
  {
    bounds.GetBounds(this->DataBounds);
    this->OutlineSource->SetBounds(this->DataBounds);
    this->OutlineSource->Update();
  }
  this->DataSize = cache->GetActualMemorySize();
  this->Actor->SetEnableLOD(0);
  this->Cache = cache.GetPointer();
  // The superclass's superclass: the superclass's own would hand the tree to
  // vtkMultiBlockVolumeMapper only.
  return this->vtkVolumeRepresentation::RequestData(request, inputVector, outputVector);
}

std::array<vtkAVSVolumeMapper*, 3> vtkAmbientScatteringRepresentation::Mappers()
{
  return { this->EmissionAbsorptionMapper.GetPointer(),
    this->AmbientOcclusionMapper.GetPointer(),
    this->AmbientScatteringMapper.GetPointer() };
}

int vtkAmbientScatteringRepresentation::ProcessViewRequest(vtkInformationRequestKey* request,
  vtkInformation* inInfo,
  vtkInformation* outInfo)
{
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  // Every rank gets the render request (the culling comes later, in the renderer), so the
  // ranks meet here. The visibility is the same on every rank.
  if (request == vtkPVView::REQUEST_RENDER() && this->GetVisibility())
  {
    this->UniteBlockExtents();
    this->ShareLightAcrossRanks();
    if (auto* mapper = vtkAVSVolumeMapper::SafeDownCast(this->VolumeMapper))
    {
      mapper->UpdatePieceLighting(this->GetRenderedProp());
    }
  }
  return result;
}

void vtkAmbientScatteringRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  this->ShareLightAcrossRanks();
}

void vtkAmbientScatteringRepresentation::UniteBlockExtents()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!this->LightAcrossRanks || !controller || controller->GetNumberOfProcesses() < 2)
  {
    return;
  }
  // One MIN over the lows and the negated highs; a rank without blocks gives nothing.
  const int* b = this->BlocksExtent;
  const bool has = b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5];
  int mine[6], all[6];
  for (int a = 0; a < 3; ++a)
  {
    mine[2 * a] = has ? b[2 * a] : VTK_INT_MAX;
    mine[2 * a + 1] = has ? -b[2 * a + 1] : VTK_INT_MAX;
  }
  controller->AllReduce(mine, all, 6, vtkCommunicator::MIN_OP);
  const bool any = all[0] != VTK_INT_MAX;
  for (int a = 0; a < 3; ++a)
  {
    this->CompositeWholeExtent[2 * a] = any ? all[2 * a] : 0;
    this->CompositeWholeExtent[2 * a + 1] = any ? -all[2 * a + 1] : -1;
  }
}

void vtkAmbientScatteringRepresentation::ShareLightAcrossRanks()
{
  // The whole extent comes from the pipeline (RequestData; every rank has the same), or for a
  // composite input from the ranks' blocks (UniteBlockExtents).
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool distributed =
    this->LightAcrossRanks && controller && controller->GetNumberOfProcesses() > 1;
  const int none[6] = { 0, -1, 0, -1, 0, -1 };
  const int* w = this->WholeExtent;
  const int* whole = w[0] <= w[1] && w[2] <= w[3] && w[4] <= w[5] ? w : this->CompositeWholeExtent;
  for (vtkAVSVolumeMapper* m : this->Mappers())
  {
    m->SetWholeExtent(distributed ? whole : none);
    m->SetController(distributed ? controller : nullptr);
  }
}

void vtkAmbientScatteringRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = {
    "EmissionAbsorption", "AmbientOcclusion", "AmbientScattering"
  };
  os << indent << "LightingModel: " << names[this->LightingModel] << "\n";
  os << indent << "Albedo: " << this->GetAlbedo() << "\n";
  os << indent << "Exposure: " << this->GetExposure() << "\n";
  os << indent << "ToneMapping: " << this->AmbientScatteringMapper->GetToneMappingAsString()
     << "\n";
  os << indent << "AutoExposure: " << (this->GetAutoExposure() ? "On" : "Off") << "\n";
  os << indent << "ScatteringAnisotropy: " << this->GetScatteringAnisotropy() << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->GetVolumetricScatteringBlending()
     << "\n";
  os << indent << "AmbientRadius: " << this->GetAmbientRadius() << "\n";
  os << indent << "LightScale: " << this->GetLightScale() << "\n";
  os << indent << "EmissionWeight: " << this->GetEmissionWeight() << "\n";
  os << indent << "LightVolumeMaximumDimension: " << this->GetLightVolumeMaximumDimension() << "\n";
  os << indent << "ScatteringModel: " << this->GetScatteringModel() << "\n";
  os << indent << "DiffusionVolumeMaximumDimension: " << this->GetDiffusionVolumeMaximumDimension()
     << "\n";
  os << indent << "PathTracedRefinement: " << (this->GetPathTracedRefinement() ? "On" : "Off")
     << "\n";
  os << indent << "MaximumSamplesPerPixel: " << this->GetMaximumSamplesPerPixel() << "\n";
  os << indent << "SampleDistance: " << this->GetSampleDistance() << "\n";
  os << indent << "UseJittering: " << this->GetUseJittering() << "\n";
  os << indent << "MaximumGPUMemory: " << this->GetMaximumGPUMemory() << " MiB\n";
  os << indent << "LightAcrossRanks: " << (this->LightAcrossRanks ? "On" : "Off") << "\n";
  const int* b = this->BlocksExtent;
  const int* c = this->CompositeWholeExtent;
  os << indent << "BlocksExtent: (" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3] << ", "
     << b[4] << ", " << b[5] << ")\n";
  os << indent << "CompositeWholeExtent: (" << c[0] << ", " << c[1] << ", " << c[2] << ", " << c[3]
     << ", " << c[4] << ", " << c[5] << ")\n";
  os << indent << "EmissionAbsorptionMapper: " << this->EmissionAbsorptionMapper.GetPointer()
     << "\n";
  os << indent << "AmbientOcclusionMapper: " << this->AmbientOcclusionMapper.GetPointer() << "\n";
  os << indent << "AmbientScatteringMapper: " << this->AmbientScatteringMapper.GetPointer() << "\n";
}
