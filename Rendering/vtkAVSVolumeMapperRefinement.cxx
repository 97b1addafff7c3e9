// vtkAVSVolumeMapper: ambient scattering's path-traced refinement (vtkAVSRefinement): when it
// runs, what restarts it, and its buffers for measurements.
#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "Classifier.h"
#include "Refinement.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>

namespace
{
void AddMatrix(std::vector<double>& key, vtkMatrix4x4* m)
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      key.push_back(m->GetElement(r, c));
    }
  }
}

void AddVector(std::vector<double>& key, const avs::Vec3& v)
{
  key.insert(key.end(), { v.x, v.y, v.z });
}
} // namespace

void vtkAVSVolumeMapper::ResolveRefinement(vtkRenderer* renderer,
  vtkVolume* volume,
  bool still,
  bool bricked,
  bool& enabled,
  bool& isStill,
  std::vector<double>& key,
  std::vector<double>& geometry)
{
  auto& in = *this->Internal;
  enabled = false;
  isStill = still;
  key.clear();
  geometry.clear();
  if (!this->PathTracedRefinement || this->GetEffect() != 2)
  {
    this->RefinementWarning.clear();
    return;
  }
  // A piece of a distributed image cannot trace light through the others' pieces, and a split
  // volume has no single texture to trace through.
  std::string warning;
  if (this->LitAsPiece)
  {
    warning = "PathTracedRefinement is not done for a piece of a distributed image (the paths "
              "would miss the other processes' pieces): the ambient-scattering picture is shown";
  }
  else if (bricked)
  {
    warning = "PathTracedRefinement is not done for a volume split into bricks (see "
              "SetPartitions): the ambient-scattering picture is shown";
  }
  if (!warning.empty())
  {
    if (warning != this->RefinementWarning)
    {
      vtkWarningMacro(<< warning << ".");
    }
    this->RefinementWarning = warning;
    return;
  }
  this->RefinementWarning.clear();
  enabled = true;

  // The data and the classification (colours included; the display transform is left out: a
  // new exposure shows the same samples differently).
  key.push_back(static_cast<double>(in.DataVersion));
  key.push_back(static_cast<double>(in.OpacityVersion)); // clipping and cropping bump it
  const std::vector<double> appearance = avs::AppearanceKey(in.Scene);
  key.insert(key.end(), appearance.begin(), appearance.end());
  // The parameters (the ambient-scattering picture's too).
  const avs::ScatteringParameters& p = in.Parameters;
  key.insert(key.end(),
    { p.Albedo,
      p.Anisotropy,
      p.EmissionWeight,
      p.LightScale,
      p.AmbientRadius,
      p.SampleDistance,
      p.TerminationTransmittance,
      static_cast<double>(p.Model),
      static_cast<double>(p.LightVolumeMaximumDimension),
      static_cast<double>(p.DiffusionVolumeMaximumDimension),
      static_cast<double>(this->UseJittering) });
  // Surfaces inside the medium: what the ray caster and the path tracer shade with.
  const avs::SurfaceShading& s = p.Surface;
  key.insert(key.end(),
    { static_cast<double>(s.Active()),
      s.Blending,
      s.Ambient,
      s.Diffuse,
      s.Specular,
      s.SpecularPower,
      static_cast<double>(s.TwoSided) });
  // The viewport, the volume's placement, the camera and the lights.
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  key.insert(key.end(), { double(width), double(height), double(x), double(y) });
  key.push_back(static_cast<double>(in.WorldLights.size()));
  AddMatrix(geometry, in.WorldToIndex);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = height > 0 ? static_cast<double>(width) / height : 1.0;
  AddMatrix(geometry, camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  for (const avs::Light& light : in.WorldLights)
  {
    key.push_back(static_cast<double>(light.Type));
    AddVector(geometry, light.Position);
    AddVector(geometry, light.FocalPoint);
    AddVector(geometry, light.Irradiance);
    AddVector(geometry, light.Attenuation);
    geometry.insert(geometry.end(), { light.ConeAngle, light.Exponent });
  }
  // What else the renderer draws in 3D: opaque geometry ends the camera rays. (2D props, text
  // and annotations, draw over the picture and restart nothing.)
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop != volume && vtkProp3D::SafeDownCast(prop))
    {
      key.push_back(prop->GetVisibility());
      key.push_back(static_cast<double>(prop->GetRedrawMTime()));
    }
  }
}

int vtkAVSVolumeMapper::GetSamplesPerPixel()
{
  return this->PathTracedRefinement && this->GetEffect() == 2
    ? this->Internal->RayCaster.GetRefinement().GetSamples()
    : 0;
}

bool vtkAVSVolumeMapper::GetRefinementBuffers(vtkFloatArray* ambient,
  vtkFloatArray* mean,
  vtkFloatArray* meanOfSquares)
{
  auto& in = *this->Internal;
  vtkOpenGLRenderWindow* window = in.RayCaster.GetWindow();
  if (!ambient || !mean || !meanOfSquares)
  {
    vtkErrorMacro("GetRefinementBuffers needs three arrays.");
    return false;
  }
  if (!window || this->GetSamplesPerPixel() < 1)
  {
    return false;
  }
  window->MakeCurrent();
  avs::RefinementBuffers buffers;
  if (!in.RayCaster.GetRefinement().Download(buffers))
  {
    vtkErrorMacro("Could not read the path-traced refinement's buffers back.");
    return false;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(buffers.Width) * buffers.Height;
  const std::pair<vtkFloatArray*, const std::vector<float>*> copies[3] = {
    { ambient, &buffers.Ambient },
    { mean, &buffers.Mean },
    { meanOfSquares, &buffers.MeanOfSquares },
  };
  for (const auto& copy : copies)
  {
    copy.first->SetNumberOfComponents(4);
    copy.first->SetNumberOfTuples(pixels);
    std::copy(copy.second->begin(), copy.second->end(), copy.first->GetPointer(0));
  }
  return true;
}
