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

// Lights and camera placed relative to the volume's bounds: a warm point light at the centre,
// a cool directional light from the upper left, a camera looking at the centre.
void PlaceLightsAndCamera(DemoScene& scene)
{
  double b[6];
  scene.Volume->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double size = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));

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
  PlaceLightsAndCamera(scene);
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
  PlaceLightsAndCamera(scene);
  return true;
}
