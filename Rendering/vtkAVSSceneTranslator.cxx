#include "vtkAVSSceneTranslator.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>

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
