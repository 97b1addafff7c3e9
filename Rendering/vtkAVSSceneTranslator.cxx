#include "vtkAVSSceneTranslator.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
constexpr int TableSize = 1024;
constexpr double MinimumSpacing = 1e-30;
constexpr double MaximumCoordinate = 1e30;
constexpr double MaximumSamplesPerAxis = 1 << 23; // half-spacing samples: 2^24 per axis

template<typename T>
void CopyValues(const T* in, vtkIdType n, int components, float* out)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    out[i] = static_cast<float>(in[i * components]);
  }
}
} // namespace

bool vtkAVSSceneTranslator::ToGrid(vtkImageData* image, avs::Grid& grid, std::string& error)
{
  if (!image)
  {
    error = "no input image data";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || image->GetNumberOfPoints() < 1)
  {
    error = "the input image is empty";
    return false;
  }
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    std::ostringstream os;
    os << "the input image is not a volume (dimensions " << dims[0] << " x " << dims[1] << " x "
       << dims[2] << "; at least 2 points per axis are needed)";
    error = os.str();
    return false;
  }
  if (static_cast<double>(dims[0]) * dims[1] * dims[2] > MaximumVoxels)
  {
    error = "the input image is too large (more than 2^30 voxels)";
    return false;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    error = "the input image has no point scalars";
    return false;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    std::ostringstream os;
    os << "unsupported number of scalar components: " << scalars->GetNumberOfComponents()
       << " (only single-component scalars are supported)";
    error = os.str();
    return false;
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    error = "the point scalars do not match the image's number of points";
    return false;
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(spacing[a]) || !(spacing[a] > 0.0))
    {
      std::ostringstream os;
      os << "invalid spacing (" << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
         << "): it must be finite and positive";
      error = os.str();
      return false;
    }
    if (!std::isfinite(origin[a]))
    {
      error = "the image origin is not finite";
      return false;
    }
  }
  // Geometry the renderers can compute with (the GPU in single precision): spacing within
  // [1e-30, 1e30], the box within +-1e30, and rays of at most 2^24 samples of half the smallest
  // spacing (the casts of step counts to int are undefined beyond that, and no ray needs it).
  {
    double lo = spacing[0], extent = 0.0;
    int e[6];
    image->GetExtent(e);
    for (int a = 0; a < 3; ++a)
    {
      lo = std::min(lo, spacing[a]);
      const double reach = std::max(std::abs(static_cast<double>(e[2 * a])),
                             std::abs(static_cast<double>(e[2 * a + 1]))) *
        spacing[a];
      extent = std::max(extent, (dims[a] - 1) * spacing[a]);
      if (!(spacing[a] >= MinimumSpacing && spacing[a] <= MaximumCoordinate) ||
        !(std::abs(origin[a]) + reach <= MaximumCoordinate))
      {
        std::ostringstream os;
        os << "the image's geometry (spacing " << spacing[0] << ", " << spacing[1] << ", "
           << spacing[2] << ", origin " << origin[0] << ", " << origin[1] << ", " << origin[2]
           << ") is outside [1e-30, 1e30]";
        error = os.str();
        return false;
      }
    }
    if (!(extent / lo <= MaximumSamplesPerAxis))
    {
      std::ostringstream os;
      os << "the image is more than " << MaximumSamplesPerAxis
         << " times as long as its smallest spacing (spacing " << spacing[0] << ", " << spacing[1]
         << ", " << spacing[2] << "): rays would take too many samples";
      error = os.str();
      return false;
    }
  }
  avs::GridGeometry g;
  g.Dimensions = { dims[0], dims[1], dims[2] };
  g.Spacing = { spacing[0], spacing[1], spacing[2] };
  // VTK 9.1 image data has a direction matrix: world = origin + D (ijk * spacing), where ijk
  // runs over the extent. The core's grid starts at index 0, so its origin is the world
  // position of the extent's first point.
  const double* d = image->GetDirectionMatrix()->GetData();
  int extent[6];
  image->GetExtent(extent);
  const double first[3] = {
    extent[0] * spacing[0], extent[2] * spacing[1], extent[4] * spacing[2]
  };
  g.Origin = { origin[0] + d[0] * first[0] + d[1] * first[1] + d[2] * first[2],
    origin[1] + d[3] * first[0] + d[4] * first[1] + d[5] * first[2],
    origin[2] + d[6] * first[0] + d[7] * first[1] + d[8] * first[2] };
  for (int i = 0; i < 9; ++i)
  {
    g.Direction[i] = d[i];
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        dot += d[3 * k + r] * d[3 * k + c];
      }
      if (!std::isfinite(dot) || std::abs(dot - (r == c ? 1.0 : 0.0)) > 1e-6)
      {
        error = "the image's direction matrix is not orthonormal";
        return false;
      }
    }
  }
  grid = avs::Grid(g);
  const vtkIdType n = image->GetNumberOfPoints();
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(CopyValues(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)),
      n,
      scalars->GetNumberOfComponents(),
      grid.Values.data()));
    default:
      for (vtkIdType i = 0; i < n; ++i)
      {
        grid.Values[i] = static_cast<float>(scalars->GetComponent(i, 0));
      }
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(grid.Values[i]))
    {
      std::ostringstream os;
      os << "the scalars contain NaN or infinite values (first at point " << i << ")";
      error = os.str();
      grid = avs::Grid();
      return false;
    }
  }
  return true;
}

bool vtkAVSSceneTranslator::ToTransferFunction(vtkVolumeProperty* property,
  double lo,
  double hi,
  avs::TransferFunction& tf,
  double& unitDistance,
  std::string& error)
{
  if (!property)
  {
    error = "no volume property";
    return false;
  }
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    error = "the scalar range is not finite";
    return false;
  }
  if (hi <= lo)
  {
    hi = lo + 1.0;
  }
  tf = avs::TransferFunction();
  tf.Minimum = lo;
  tf.Maximum = hi;
  std::vector<float> color(3 * TableSize), opacity(TableSize);
  if (property->GetColorChannels(0) == 1)
  {
    vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(0);
    gray->GetTable(lo, hi, TableSize, opacity.data());
    for (int i = 0; i < TableSize; ++i)
    {
      color[3 * i] = color[3 * i + 1] = color[3 * i + 2] = opacity[i];
    }
  }
  else
  {
    property->GetRGBTransferFunction(0)->GetTable(lo, hi, TableSize, color.data());
  }
  property->GetScalarOpacity(0)->GetTable(lo, hi, TableSize, opacity.data());
  for (int i = 0; i < TableSize; ++i)
  {
    tf.Color.push_back({ std::min(1.0f, std::max(0.0f, color[3 * i])),
      std::min(1.0f, std::max(0.0f, color[3 * i + 1])),
      std::min(1.0f, std::max(0.0f, color[3 * i + 2])) });
    tf.Opacity.push_back(std::min(1.0f, std::max(0.0f, opacity[i])));
  }
  unitDistance = property->GetScalarOpacityUnitDistance(0);
  if (!std::isfinite(unitDistance) || !(unitDistance > 0.0))
  {
    error = "the scalar opacity unit distance must be finite and positive";
    return false;
  }
  return true;
}

std::vector<avs::Light> vtkAVSSceneTranslator::ToLights(vtkRenderer* renderer,
  vtkCamera* camera,
  double lightScale,
  std::vector<bool>* followsCamera)
{
  // VTK light units: E = 4 pi I c (ALGORITHM.md section 1).
  const double unit = 4.0 * avs::Pi * (std::isfinite(lightScale) ? std::max(0.0, lightScale) : 0.0);
  std::vector<avs::Light> lights;
  if (followsCamera)
  {
    followsCamera->clear();
  }
  auto toVec = [](const double* v) { return avs::Vec3{ v[0], v[1], v[2] }; };
  auto add = [&](vtkLight* l)
  {
    if (!l->GetSwitch())
    {
      return;
    }
    avs::Light out;
    double position[3], focal[3];
    l->GetPosition(position);
    l->GetFocalPoint(focal);
    if (l->LightTypeIsHeadlight() && camera)
    {
      camera->GetPosition(position);
      camera->GetFocalPoint(focal);
    }
    else if (l->LightTypeIsCameraLight() && camera)
    {
      vtkMatrix4x4* m = camera->GetCameraLightTransformMatrix();
      double p[4] = { position[0], position[1], position[2], 1.0 };
      double f[4] = { focal[0], focal[1], focal[2], 1.0 };
      m->MultiplyPoint(p, p);
      m->MultiplyPoint(f, f);
      for (int i = 0; i < 3; ++i)
      {
        position[i] = p[i] / p[3];
        focal[i] = f[i] / f[3];
      }
    }
    out.Type = l->GetPositional() ? avs::LightType::Positional : avs::LightType::Directional;
    out.Position = toVec(position);
    out.FocalPoint = toVec(focal);
    double color[3];
    l->GetDiffuseColor(color);
    out.Irradiance = toVec(color) * (l->GetIntensity() * unit);
    out.Attenuation = toVec(l->GetAttenuationValues());
    out.ConeAngle = l->GetConeAngle();
    out.Exponent = l->GetExponent();
    if (out.Type == avs::LightType::Directional &&
      avs::Length(out.FocalPoint - out.Position) == 0.0)
    {
      return; // no direction: VTK draws nothing from it either
    }
    lights.push_back(out);
    if (followsCamera)
    {
      followsCamera->push_back(l->LightTypeIsHeadlight() || l->LightTypeIsCameraLight());
    }
  };
  bool any = false;
  if (renderer)
  {
    vtkLightCollection* collection = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    collection->InitTraversal(it);
    while (vtkLight* l = collection->GetNextLight(it))
    {
      any = true;
      add(l);
    }
  }
  if (!any)
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    add(headlight);
  }
  return lights;
}

avs::Camera vtkAVSSceneTranslator::ToCamera(vtkCamera* camera)
{
  avs::Camera c;
  if (!camera)
  {
    return c;
  }
  const double* p = camera->GetPosition();
  const double* f = camera->GetFocalPoint();
  const double* u = camera->GetViewUp();
  c.Position = { p[0], p[1], p[2] };
  c.FocalPoint = { f[0], f[1], f[2] };
  c.ViewUp = { u[0], u[1], u[2] };
  c.ViewAngle = camera->GetViewAngle();
  c.Parallel = camera->GetParallelProjection() != 0;
  c.ParallelScale = camera->GetParallelScale();
  return c;
}
