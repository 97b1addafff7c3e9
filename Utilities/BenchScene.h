// The benchmarks' scene on the nebula (avs-bench-mappers, avs-bench-memory): its transfer
// functions and its four lights, so that both programs measure the same thing.
#ifndef avs_BenchScene_h
#define avs_BenchScene_h

#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <vector>

/// The nebula's colour and opacity for scalars in [0, top] (1 for the float nebula, the type's
/// maximum for quantized copies), unshaded, linear, into `property`, `color` and `opacity`.
inline void ConfigureBenchProperty(vtkVolumeProperty* property,
  vtkColorTransferFunction* color,
  vtkPiecewiseFunction* opacity,
  double top)
{
  color->AddRGBPoint(0.0, 0.25, 0.35, 0.9);
  color->AddRGBPoint(0.5 * top, 0.9, 0.5, 0.4);
  color->AddRGBPoint(top, 1.0, 0.95, 0.8);
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.05 * top, 0.0);
  opacity->AddPoint(0.5 * top, 0.25);
  opacity->AddPoint(top, 0.6);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(2.0 / 48.0);
  property->SetInterpolationTypeToLinear();
  property->ShadeOff();
}

/// The four scene lights: a directional light, a point light at the centre, two more
/// directional (the one-light runs take the first).
inline std::vector<vtkSmartPointer<vtkLight>> MakeBenchLights()
{
  const double directions[3][3] = { { -1, 1, 0.5 }, { 1, 0.2, -0.3 }, { 0.1, -1, 0.4 } };
  std::vector<vtkSmartPointer<vtkLight>> lights;
  for (int i = 0; i < 4; ++i)
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    if (i == 1)
    {
      light->SetPositional(true);
      light->SetConeAngle(180);
      light->SetPosition(0, 0, 0);
      light->SetFocalPoint(0, 0, -1);
      light->SetIntensity(0.8);
    }
    else
    {
      const double* d = directions[i == 0 ? 0 : i - 1];
      light->SetPositional(false);
      light->SetPosition(d[0], d[1], d[2]);
      light->SetFocalPoint(0, 0, 0);
      light->SetIntensity(0.4);
    }
    lights.push_back(light);
  }
  return lights;
}

#endif
