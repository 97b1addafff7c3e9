#include "DemoScene.h"

#include "ProceduralVolume.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSLCReader.h"
#include "vtkStructuredPoints.h"
#include "vtkStructuredPointsReader.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataReader.h"
#ifdef AVS_HAVE_OPENVDB
#include "vtkOpenVDBImageReader.h"
#endif

#include <algorithm>
#include <cmath>
#include <fstream>

namespace
{
bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    std::equal(suffix.rbegin(),
      suffix.rend(),
      s.rbegin(),
      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

// The world bounds of the samples whose first component exceeds `threshold` (the part of the
// volume the transfer function shows); the image's bounds where none does.
void VisibleBounds(vtkImageData* volume, double threshold, double b[6])
{
  volume->GetBounds(b);
  vtkDataArray* scalars = volume->GetPointData()->GetScalars();
  int dims[3];
  volume->GetDimensions(dims);
  int lo[3] = { dims[0], dims[1], dims[2] }, hi[3] = { -1, -1, -1 };
  vtkIdType id = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i, ++id)
      {
        if (scalars->GetComponent(id, 0) > threshold)
        {
          const int ijk[3] = { i, j, k };
          for (int a = 0; a < 3; ++a)
          {
            lo[a] = std::min(lo[a], ijk[a]);
            hi[a] = std::max(hi[a], ijk[a]);
          }
        }
      }
  if (hi[0] < 0)
  {
    return;
  }
  // The box's eight corners, one voxel to spare, through the image's placement.
  const int* e = volume->GetExtent();
  for (int a = 0; a < 3; ++a)
  {
    b[2 * a] = VTK_DOUBLE_MAX;
    b[2 * a + 1] = VTK_DOUBLE_MIN;
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    double index[3], point[3];
    for (int a = 0; a < 3; ++a)
    {
      const int first = std::max(0, lo[a] - 1), last = std::min(dims[a] - 1, hi[a] + 1);
      index[a] = e[2 * a] + ((corner >> a) & 1 ? last : first);
    }
    volume->TransformContinuousIndexToPhysicalPoint(index, point);
    for (int a = 0; a < 3; ++a)
    {
      b[2 * a] = std::min(b[2 * a], point[a]);
      b[2 * a + 1] = std::max(b[2 * a + 1], point[a]);
    }
  }
}

// The centre and the radius of the sphere around bounds.
void BoundingSphere(const double b[6], double centre[3], double& radius)
{
  for (int a = 0; a < 3; ++a)
  {
    centre[a] = 0.5 * (b[2 * a] + b[2 * a + 1]);
  }
  radius = 0.5 *
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
      (b[5] - b[4]) * (b[5] - b[4]));
}

// The nebula's lights and camera: a warm point light at its hollow centre, a cool directional
// light from the upper left, a camera looking at the centre.
void PlaceNebulaLightsAndCamera(DemoScene& scene)
{
  double b[6], c[3], radius;
  scene.Volume->GetBounds(b);
  BoundingSphere(b, c, radius);
  const double size = 2.0 * radius;

  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkNew<vtkLight> point;
  point->SetLightTypeToSceneLight();
  point->SetPositional(true);
  point->SetConeAngle(180.0);
  point->SetPosition(c);
  point->SetFocalPoint(c[0], c[1], c[2] - 1.0);
  point->SetDiffuseColor(1.0, 0.75, 0.45);
  point->SetIntensity(2.0);
  point->SetAttenuationValues(1.0, 0.0, 4.0 / (size * size));
  scene.Renderer->AddLight(point);

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(c[0] - size, c[1] + size, c[2] + 0.5 * size);
  sun->SetFocalPoint(c);
  sun->SetDiffuseColor(0.6, 0.75, 1.0);
  sun->SetIntensity(0.25);
  scene.Renderer->AddLight(sun);

  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0] + 0.2 * size, c[1] + 0.27 * size, c[2] + 1.0 * size);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30.0);
}

// A user's file, whose inside may be dense (a light there would be buried) and whose shape may
// be long: the camera frames the sphere around what the transfer function shows (above
// `threshold`) whole, a warm key light from the upper left front makes the shadows and the
// glow, a cool fill from the lower right keeps the far side from black. Directional lights: the
// same light wherever the material is.
void PlaceFileLightsAndCamera(DemoScene& scene, double threshold)
{
  double b[6], c[3], radius;
  VisibleBounds(scene.Volume, threshold, b);
  BoundingSphere(b, c, radius);
  radius = radius > 0.0 ? radius : 1.0;
  const double viewAngle = 30.0;

  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPositional(false);
  key->SetPosition(c[0] - radius, c[1] + 1.2 * radius, c[2] + 0.8 * radius);
  key->SetFocalPoint(c);
  key->SetDiffuseColor(1.0, 0.9, 0.75);
  key->SetIntensity(1.0);
  scene.Renderer->AddLight(key);

  vtkNew<vtkLight> fill;
  fill->SetLightTypeToSceneLight();
  fill->SetPositional(false);
  fill->SetPosition(c[0] + radius, c[1] - 0.3 * radius, c[2] + 0.6 * radius);
  fill->SetFocalPoint(c);
  fill->SetDiffuseColor(0.65, 0.75, 1.0);
  fill->SetIntensity(0.35);
  scene.Renderer->AddLight(fill);

  // The whole sphere in view: its radius over the sine of half the view angle, 5 % to spare.
  const double distance = 1.05 * radius / std::sin(0.5 * viewAngle * 3.14159265358979 / 180.0);
  const double direction[3] = { 0.2, 0.27, 1.0 };
  const double length = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(c);
  camera->SetPosition(c[0] + distance * direction[0] / length,
    c[1] + distance * direction[1] / length,
    c[2] + distance * direction[2] / length);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(viewAngle);
}
} // namespace

DemoScene MakeDemoScene(int n)
{
  DemoScene scene;
  const avs::Grid nebula = avs::MakeNebula(n);
  const auto& g = nebula.Geometry;
  scene.Volume = vtkSmartPointer<vtkImageData>::New();
  scene.Volume->SetDimensions(g.Dimensions[0], g.Dimensions[1], g.Dimensions[2]);
  scene.Volume->SetSpacing(g.Spacing.x, g.Spacing.y, g.Spacing.z);
  scene.Volume->SetOrigin(g.Origin.x, g.Origin.y, g.Origin.z);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(nebula.Values.size()));
  std::copy(nebula.Values.begin(), nebula.Values.end(), values->GetPointer(0));
  scene.Volume->GetPointData()->SetScalars(values);

  scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.25, 0.35, 0.9);
  color->AddRGBPoint(0.35, 0.6, 0.45, 0.95);
  color->AddRGBPoint(0.7, 1.0, 0.55, 0.35);
  color->AddRGBPoint(1.0, 1.0, 0.95, 0.8);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.05, 0.0);
  opacity->AddPoint(0.5, 0.25);
  opacity->AddPoint(1.0, 0.6);
  scene.Property->SetColor(color);
  scene.Property->SetScalarOpacity(opacity);
  scene.Property->SetScalarOpacityUnitDistance(2.0 / 48.0);
  scene.Property->SetInterpolationTypeToLinear();
  PlaceNebulaLightsAndCamera(scene);
  return scene;
}

bool LoadDemoScene(const std::string& fileName, DemoScene& scene, std::string& error)
{
  if (!std::ifstream(fileName))
  {
    error = "cannot open '" + fileName + "'";
    return false;
  }
  vtkSmartPointer<vtkImageData> image;
  if (EndsWith(fileName, ".vti"))
  {
    vtkNew<vtkXMLImageDataReader> r;
    r->SetFileName(fileName.c_str());
    r->Update();
    image = r->GetOutput();
  }
  else if (EndsWith(fileName, ".vtk"))
  {
    vtkNew<vtkStructuredPointsReader> r;
    r->SetFileName(fileName.c_str());
    r->Update();
    image = r->GetOutput();
  }
  else if (EndsWith(fileName, ".slc"))
  {
    vtkNew<vtkSLCReader> r;
    r->SetFileName(fileName.c_str());
    r->Update();
    image = r->GetOutput();
  }
  else if (EndsWith(fileName, ".nhdr") || EndsWith(fileName, ".nrrd"))
  {
    vtkNew<vtkNrrdReader> r;
    r->SetFileName(fileName.c_str());
    r->Update();
    image = r->GetOutput();
  }
#ifdef AVS_HAVE_OPENVDB
  else if (EndsWith(fileName, ".vdb"))
  {
    vtkNew<vtkOpenVDBImageReader> r;
    r->SetFileName(fileName.c_str());
    r->LevelSetToFogVolumeOn(); // a level set's signed distance is no density
    r->Update();
    image = r->GetOutput();
  }
#endif
  else
  {
    error = "unsupported file type '" + fileName +
      "' (this build reads .vti, .vtk, .slc, .nhdr, .nrrd"
#ifdef AVS_HAVE_OPENVDB
      " and .vdb"
#endif
      " volumes)";
    return false;
  }
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    error = "'" + fileName + "' holds no volume with point scalars";
    return false;
  }
  scene.Volume = image;
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range, 0);
  const double lo = range[0], hi = range[1] > range[0] ? range[1] : range[0] + 1.0;
  scene.Property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.3, 0.4, 0.9);
  color->AddRGBPoint(lo + 0.5 * (hi - lo), 0.9, 0.6, 0.4);
  color->AddRGBPoint(hi, 1.0, 0.95, 0.85);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(lo + 0.1 * (hi - lo), 0.0);
  opacity->AddPoint(hi, 0.5);
  scene.Property->SetColor(color);
  scene.Property->SetScalarOpacity(opacity);
  double spacing[3];
  image->GetSpacing(spacing);
  scene.Property->SetScalarOpacityUnitDistance(
    2.0 * std::max({ spacing[0], spacing[1], spacing[2] }));
  PlaceFileLightsAndCamera(scene, lo + 0.1 * (hi - lo));
  return true;
}
