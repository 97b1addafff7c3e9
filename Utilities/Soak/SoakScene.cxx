#include "SoakScene.h"

#include "ProceduralVolume.h"
#include "vtkAVSVolumeMapper.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <limits>
#include <sstream>

class SoakErrorCounter : public vtkCommand
{
public:
  static SoakErrorCounter* New() { return new SoakErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Errors;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  long Errors = 0;
  std::string Last; ///< the last message
};

namespace
{
constexpr double Pi = 3.14159265358979323846;

vtkSmartPointer<vtkImageData> ToImage(const avs::Grid& grid, const double* direction = nullptr)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  const auto& g = grid.Geometry;
  image->SetDimensions(g.Dimensions[0], g.Dimensions[1], g.Dimensions[2]);
  image->SetOrigin(g.Origin.x, g.Origin.y, g.Origin.z);
  image->SetSpacing(g.Spacing.x, g.Spacing.y, g.Spacing.z);
  if (direction)
  {
    image->SetDirectionMatrix(direction);
  }
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(grid.Values.size()));
  for (std::size_t i = 0; i < grid.Values.size(); ++i)
  {
    values->SetValue(static_cast<vtkIdType>(i), grid.Values[i]);
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

// Camera pose on a sphere around the volume's centre (kept per window between frames).
struct Pose
{
  double Azimuth = 0.6, Elevation = 0.3, Distance = 4.0;
  bool Parallel = false;
};
std::vector<Pose> Poses;
} // namespace

bool SoakCounters::operator==(const SoakCounters& o) const
{
  return this->DataUploads == o.DataUploads && this->ExtinctionRebuilds == o.ExtinctionRebuilds &&
    this->LightVolumeRebuilds == o.LightVolumeRebuilds &&
    this->OcclusionRebuilds == o.OcclusionRebuilds && this->RenderedFrames == o.RenderedFrames &&
    this->Errors == o.Errors;
}

SoakCounters& SoakCounters::operator+=(const SoakCounters& o)
{
  this->DataUploads += o.DataUploads;
  this->ExtinctionRebuilds += o.ExtinctionRebuilds;
  this->LightVolumeRebuilds += o.LightVolumeRebuilds;
  this->OcclusionRebuilds += o.OcclusionRebuilds;
  this->RenderedFrames += o.RenderedFrames;
  this->Errors += o.Errors;
  return *this;
}

std::string SoakCounters::ToString() const
{
  std::ostringstream os;
  os << "frames " << this->RenderedFrames << ", errors " << this->Errors << ", data uploads "
     << this->DataUploads << ", extinction rebuilds " << this->ExtinctionRebuilds
     << ", light-volume rebuilds " << this->LightVolumeRebuilds << ", occlusion rebuilds "
     << this->OcclusionRebuilds;
  return os.str();
}

SoakScene::SoakScene()
{
  // Valid volumes: the base, a larger, a smaller, and one turned by a direction matrix.
  const double turned[9] = { 0.8, -0.6, 0, 0.6, 0.8, 0, 0, 0, 1 };
  this->Volumes = { ToImage(avs::MakeCloud(36)),
    ToImage(avs::MakeNebula(56)),
    ToImage(avs::MakeCloud(24, 5)),
    ToImage(avs::MakeNebula(36, 3), turned) };
  this->Empty = vtkSmartPointer<vtkImageData>::New();
  // (NaN voxels are valid input, empty space: the bad volume is one without scalars.)
  this->NoScalars = vtkSmartPointer<vtkImageData>::New();
  this->NoScalars->DeepCopy(this->Volumes[2]);
  this->NoScalars->GetPointData()->SetScalars(nullptr);

  this->W.resize(2);
  Poses.assign(2, Pose());
  for (auto& w : this->W)
  {
    w.RenderWindow = vtkSmartPointer<vtkRenderWindow>::New();
    w.RenderWindow->SetMultiSamples(0);
    w.RenderWindow->OffScreenRenderingOn();
    w.Renderer = vtkSmartPointer<vtkRenderer>::New();
    w.Renderer->SetBackground(0.1, 0.1, 0.15);
    w.RenderWindow->AddRenderer(w.Renderer);
    w.Volume = vtkSmartPointer<vtkVolume>::New();
    w.Property = vtkSmartPointer<vtkVolumeProperty>::New();
    w.Property->SetInterpolationTypeToLinear();
    w.Volume->SetProperty(w.Property);
    w.Renderer->AddVolume(w.Volume);
    w.Errors = vtkSmartPointer<SoakErrorCounter>::New();
  }
}

SoakScene::~SoakScene() = default;

double SoakScene::Uniform(double lo, double hi)
{
  return lo + (hi - lo) * std::uniform_real_distribution<double>(0.0, 1.0)(this->Random);
}

int SoakScene::Integer(int lo, int hi)
{
  return std::uniform_int_distribution<int>(lo, hi)(this->Random);
}

bool SoakScene::Chance(double p)
{
  return this->Uniform(0.0, 1.0) < p;
}

void SoakScene::Reset(std::uint64_t seed)
{
  this->Random.seed(seed);
  for (std::size_t i = 0; i < this->W.size(); ++i)
  {
    Window& w = this->W[i];
    w.RenderWindow->SetSize(128, 112);
    w.Data = 0;
    w.Pending = Bad::None;
    w.Total = SoakCounters();
    Poses[i] = Pose();
    this->RandomTransferFunction(w);
    w.Renderer->RemoveAllLights();
    this->NewMapper(w, i == 0 ? Kind::AmbientScattering : Kind::AmbientOcclusion);
    this->MoveCamera(w, false);
  }
}

void SoakScene::NewMapper(Window& w, Kind kind)
{
  vtkSmartPointer<vtkAVSVolumeMapper> mapper;
  if (kind == Kind::EmissionAbsorption)
  {
    mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
  }
  else if (kind == Kind::AmbientOcclusion)
  {
    auto ao = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
    ao->SetOcclusionVolumeMaximumDimension(24);
    ao->SetNumberOfDirections(14);
    mapper = ao;
  }
  else
  {
    auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    as->SetLightVolumeMaximumDimension(24);
    mapper = as;
  }
  mapper->AddObserver(vtkCommand::ErrorEvent, w.Errors);
  mapper->SetInputData(this->Volumes[w.Data]);
  w.Mapper = mapper; // the previous mapper goes, and its GL resources with it
  w.MapperKind = kind;
  w.Volume->SetMapper(mapper);
}

void SoakScene::RandomLights(Window& w)
{
  w.Renderer->RemoveAllLights();
  const int n = this->Integer(0, 4);
  for (int i = 0; i < n; ++i)
  {
    vtkNew<vtkLight> light;
    const int kind = this->Integer(0, 4);
    if (kind == 3)
    {
      light->SetLightTypeToHeadlight();
    }
    else
    {
      kind == 4 ? light->SetLightTypeToCameraLight() : light->SetLightTypeToSceneLight();
      light->SetPositional(kind == 1 || kind == 2);
      light->SetConeAngle(kind == 2 ? this->Uniform(20.0, 70.0) : 180.0);
      light->SetExponent(this->Uniform(1.0, 4.0));
    }
    light->SetDiffuseColor(
      this->Uniform(0.5, 1.0), this->Uniform(0.5, 1.0), this->Uniform(0.5, 1.0));
    light->SetIntensity(this->Uniform(0.3, 1.5));
    light->SetFocalPoint(0, 0, 0);
    w.Renderer->AddLight(light);
  }
  for (int i = 0; i < n; ++i)
  {
    this->MoveLight(w);
  }
}

void SoakScene::MoveLight(Window& w)
{
  vtkLightCollection* lights = w.Renderer->GetLights();
  if (lights->GetNumberOfItems() == 0)
  {
    return;
  }
  auto* light = vtkLight::SafeDownCast(
    lights->GetItemAsObject(this->Integer(0, lights->GetNumberOfItems() - 1)));
  // Outside the volume or, for point lights now and then, inside it.
  const double r = this->Chance(0.2) ? this->Uniform(0.1, 0.6) : this->Uniform(1.5, 4.0);
  const double a = this->Uniform(0.0, 2 * Pi), e = this->Uniform(-1.2, 1.2);
  light->SetPosition(r * std::cos(e) * std::cos(a), r * std::sin(e), r * std::cos(e) * std::sin(a));
}

void SoakScene::RandomTransferFunction(Window& w)
{
  vtkNew<vtkColorTransferFunction> color;
  const int colors = this->Integer(2, 4);
  for (int i = 0; i < colors; ++i)
  {
    color->AddRGBPoint(i / (colors - 1.0),
      this->Uniform(0.2, 1.0),
      this->Uniform(0.2, 1.0),
      this->Uniform(0.2, 1.0));
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  const double start = this->Uniform(0.0, 0.4);
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(start, 0.0);
  opacity->AddPoint(this->Uniform(start + 0.05, 0.9), this->Uniform(0.05, 0.6));
  opacity->AddPoint(1.0, this->Uniform(0.1, 0.9));
  w.Property->SetColor(color);
  w.Property->SetScalarOpacity(opacity);
  w.Property->SetScalarOpacityUnitDistance(this->Uniform(0.02, 0.2));
}

void SoakScene::RandomParameters(Window& w)
{
  vtkAVSVolumeMapper* m = w.Mapper;
  switch (this->Integer(0, 5))
  {
    case 0:
      m->SetSampleDistance(this->Chance(0.5) ? 0.0 : this->Uniform(0.02, 0.06));
      break;
    case 1:
      m->SetUseJittering(this->Chance(0.7));
      break;
    case 2:
      m->SetPrecomputeOnGPU(this->Chance(0.8));
      break;
    default:
      break;
  }
  if (auto* as = vtkAmbientScatteringVolumeMapper::SafeDownCast(m))
  {
    switch (this->Integer(0, 5))
    {
      case 0:
        as->SetAlbedo(this->Uniform(0.0, 1.0));
        break;
      case 1:
        as->SetAnisotropy(this->Uniform(-0.9, 0.9));
        break;
      case 2:
        as->SetAmbientRadius(this->Chance(0.5) ? 0.0 : this->Uniform(0.03, 0.2));
        break;
      case 3:
        as->SetEmissionWeight(this->Chance(0.5) ? 0.0 : this->Uniform(0.1, 1.0));
        break;
      case 4:
        as->SetLightVolumeMaximumDimension(this->Integer(1, 3) * 8);
        break;
      default:
        as->SetLightScale(this->Uniform(0.5, 2.0));
    }
  }
  else if (auto* ao = vtkAmbientOcclusionVolumeMapper::SafeDownCast(m))
  {
    switch (this->Integer(0, 4))
    {
      case 0:
        ao->SetOcclusionRadius(this->Chance(0.5) ? 0.0 : this->Uniform(0.05, 0.25));
        break;
      case 1:
        ao->SetNumberOfDirections(this->Integer(14, 32));
        break;
      case 2:
        ao->SetDirectLightWeight(this->Chance(0.5) ? 0.0 : this->Uniform(0.2, 1.0));
        break;
      case 3:
        ao->SetOcclusionVolumeMaximumDimension(this->Integer(1, 3) * 8);
        break;
      default:
        ao->SetAmbientWeight(this->Uniform(0.5, 1.5));
    }
  }
}

void SoakScene::MoveCamera(Window& w, bool large)
{
  Pose& p = Poses[static_cast<std::size_t>(&w - this->W.data())];
  p.Azimuth += this->Uniform(-0.15, 0.15);
  p.Elevation = std::max(-1.2, std::min(1.2, p.Elevation + this->Uniform(-0.1, 0.1)));
  if (large)
  {
    // Now and then inside the volume (its box is [-1, 1]^3), or in parallel projection.
    p.Distance = this->Chance(0.15) ? this->Uniform(0.3, 0.8) : this->Uniform(2.5, 6.0);
    p.Parallel = this->Chance(0.2);
  }
  vtkCamera* c = w.Renderer->GetActiveCamera();
  c->SetFocalPoint(0, 0, 0);
  c->SetPosition(p.Distance * std::cos(p.Elevation) * std::cos(p.Azimuth),
    p.Distance * std::sin(p.Elevation),
    p.Distance * std::cos(p.Elevation) * std::sin(p.Azimuth));
  c->SetViewUp(0, 1, 0);
  c->SetViewAngle(35.0);
  c->SetParallelProjection(p.Parallel);
  c->SetParallelScale(1.3);
  c->SetClippingRange(0.05, 20.0);
}

void SoakScene::SetData(Window& w, int index)
{
  w.Data = index;
  w.Mapper->SetInputData(this->Volumes[index]);
}

void SoakScene::Change(Window& w, int frame, int which)
{
  // Restore what the last frame broke.
  if (w.Pending == Bad::MissingTable)
  {
    vtkAmbientScatteringVolumeMapper::SafeDownCast(w.Mapper)->SetScatteringTableFileName(nullptr);
  }
  else if (w.Pending != Bad::None)
  {
    w.Mapper->SetInputData(this->Volumes[w.Data]);
  }
  w.Pending = Bad::None;
  if (IsQuiet(frame))
  {
    return;
  }
  this->MoveCamera(w, this->Chance(0.1));
  if (this->Chance(0.06))
    this->RandomLights(w);
  if (this->Chance(0.12))
    this->MoveLight(w);
  if (this->Chance(0.08))
    this->RandomTransferFunction(w);
  if (this->Chance(0.12))
    this->RandomParameters(w);
  if (this->Chance(0.03))
    this->NewMapper(w, static_cast<Kind>(this->Integer(0, 2)));
  if (this->Chance(0.04))
    w.RenderWindow->SetSize(this->Integer(64, 160), this->Integer(64, 160));
  if (this->Chance(0.04))
    this->SetData(w, this->Integer(0, static_cast<int>(this->Volumes.size()) - 1));
  // Bad input at fixed frames of each window, never just before a checkpoint.
  const int period = which == 0 ? 61 : 67, phase = which == 0 ? 17 : 31;
  if (frame % period == phase && !IsQuiet(frame + 1))
  {
    const Bad bad = static_cast<Bad>(1 + (frame / period) % 3);
    if (bad == Bad::MissingTable)
    {
      if (w.MapperKind != Kind::AmbientScattering)
      {
        this->NewMapper(w, Kind::AmbientScattering);
      }
      vtkAmbientScatteringVolumeMapper::SafeDownCast(w.Mapper)->SetScatteringTableFileName(
        "/nonexistent/avs-soak-missing-table.avst");
    }
    else
    {
      w.Mapper->SetInputData(bad == Bad::EmptyImage ? this->Empty : this->NoScalars);
    }
    w.Pending = bad;
  }
}

SoakCounters SoakScene::Read(Window& w) const
{
  SoakCounters c;
  c.DataUploads = w.Mapper->GetNumberOfDataUploads();
  c.ExtinctionRebuilds = w.Mapper->GetNumberOfExtinctionRebuilds();
  c.LightVolumeRebuilds = w.Mapper->GetNumberOfLightVolumeRebuilds();
  c.OcclusionRebuilds = w.Mapper->GetNumberOfOcclusionRebuilds();
  c.RenderedFrames = w.Mapper->GetNumberOfRenderedFrames();
  c.Errors = w.Errors->Errors;
  return c;
}

bool SoakScene::Step(int frame, std::string& failure)
{
  for (std::size_t i = 0; i < this->W.size(); ++i)
  {
    Window& w = this->W[i];
    this->Change(w, frame, static_cast<int>(i));
    w.Before = this->Read(w);
  }
  for (auto& w : this->W)
  {
    w.RenderWindow->Render();
  }
  for (std::size_t i = 0; i < this->W.size(); ++i)
  {
    Window& w = this->W[i];
    const SoakCounters after = this->Read(w), &b = w.Before;
    SoakCounters d;
    d.DataUploads = after.DataUploads - b.DataUploads;
    d.ExtinctionRebuilds = after.ExtinctionRebuilds - b.ExtinctionRebuilds;
    d.LightVolumeRebuilds = after.LightVolumeRebuilds - b.LightVolumeRebuilds;
    d.OcclusionRebuilds = after.OcclusionRebuilds - b.OcclusionRebuilds;
    d.RenderedFrames = after.RenderedFrames - b.RenderedFrames;
    d.Errors = after.Errors - b.Errors;
    w.Total += d;
    std::ostringstream why;
    if (w.Pending != Bad::None && (d.Errors < 1 || d.RenderedFrames != 0))
    {
      why << "bad input " << static_cast<int>(w.Pending) << " gave " << d.Errors << " errors and "
          << d.RenderedFrames << " frames (1+ errors and no frame expected)";
    }
    else if (w.Pending == Bad::None && (d.Errors != 0 || d.RenderedFrames != 1))
    {
      why << "a valid frame gave " << d.Errors << " errors and " << d.RenderedFrames
          << " frames (no error and one frame expected)";
    }
    else if (IsQuiet(frame) && IsQuiet(frame - 1) &&
      (d.DataUploads || d.ExtinctionRebuilds || d.LightVolumeRebuilds || d.OcclusionRebuilds))
    {
      why << "a frame without changes rebuilt: " << d.ToString();
    }
    if (!why.str().empty())
    {
      failure = "frame " + std::to_string(frame) + ", window " + std::to_string(i) + ": " +
        why.str() + (d.Errors ? " (last error: " + w.Errors->Last + ")" : std::string());
      return false;
    }
  }
  return true;
}
