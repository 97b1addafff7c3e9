// A structured test scene shared by the GPU mapper tests: a lumpy shell with a dense core
// (short scalars, anisotropic spacing, shifted extent), a directional light and a point light
// inside the volume, a perspective camera, and helpers to render and compare pictures.
#ifndef MapperTestScene_h
#define MapperTestScene_h

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShortArray.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>

/// A window for the tests: off screen, no multisampling unless asked.
inline void PrepareTestWindow(vtkRenderWindow* window, int width, int height)
{
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
}

inline vtkSmartPointer<vtkImageData> MakeTestVolume(int n = 40)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(-n / 2, n - 1 - n / 2, -n / 2, n - 1 - n / 2, -n / 2, n - 1 - n / 2);
  image->SetSpacing(0.05, 0.05, 0.06);
  image->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkShortArray> s;
  s->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = (i - 0.5 * (n - 1)) / (0.5 * n), y = (j - 0.5 * (n - 1)) / (0.5 * n),
                     z = (k - 0.5 * (n - 1)) / (0.5 * n);
        const double r = std::sqrt(x * x + y * y + z * z);
        const double lumps = 0.5 + 0.5 * std::sin(7 * x) * std::cos(5 * y) * std::sin(6 * z + 1);
        double v = 0.0;
        if (r < 0.25)
          v = 900.0; // dense core
        else if (std::abs(r - 0.65) < 0.15)
          v = 300.0 + 500.0 * lumps; // lumpy shell
        s->SetValue(id++, static_cast<short>(v));
      }
  image->GetPointData()->SetScalars(s);
  return image;
}

inline vtkSmartPointer<vtkVolumeProperty> MakeTestProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.2, 0.3, 0.9);
  color->AddRGBPoint(400, 0.9, 0.6, 0.3);
  color->AddRGBPoint(900, 1.0, 0.95, 0.9);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(250, 0.0);
  opacity->AddPoint(600, 0.15);
  opacity->AddPoint(900, 0.5);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.1);
  property->SetInterpolationTypeToLinear();
  return property;
}

/// Lights: a directional light from the upper left and a point light inside the shell.
inline void AddTestLights(vtkRenderer* renderer)
{
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 1.0, 0.6);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(1.1);
  renderer->AddLight(sun);
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180);
  lamp->SetPosition(0.3, 0.1, 0.0);
  lamp->SetFocalPoint(0, 0, 0);
  lamp->SetDiffuseColor(1.0, 0.8, 0.5);
  lamp->SetIntensity(0.8);
  lamp->SetAttenuationValues(1.0, 0.0, 2.0);
  renderer->AddLight(lamp);
}

inline void PlaceTestCamera(vtkCamera* camera)
{
  camera->SetPosition(1.9, 1.4, 5.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(0.5, 10.0);
}

/// Linear radiance on the screen (exposure 1, no tone curve), on a mapper or on
/// vtkVolumeReferenceRenderer: for the tests that measure the physics (light units, the models
/// against each other, against the truth) rather than the picture the display transform makes
/// of it.
template<class T>
void ShowLinear(T* renderer)
{
  renderer->SetExposure(1.0);
  renderer->SetToneMappingToClamp();
}

/// The window's RGB picture.
inline vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(grab->GetOutput());
  return out;
}

/// PSNR in dB between two RGB pictures of the same size (255 peak).
inline double Psnr(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples())
  {
    return 0.0;
  }
  double se = 0.0;
  const vtkIdType n = x->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
    {
      const double d = x->GetComponent(i, c) - y->GetComponent(i, c);
      se += d * d;
    }
  const double mse = se / (3.0 * n);
  return mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

/// Largest difference of one channel between two RGB pictures, in levels of 255 (256 when their
/// sizes differ).
inline int MaximumDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples())
  {
    return 256;
  }
  double most = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      most = std::max(most, std::abs(x->GetComponent(i, c) - y->GetComponent(i, c)));
  return static_cast<int>(most);
}

/// A window of `size` x `size` pixels with the test lights and camera, showing `mapper`'s
/// volume with the test property (the test sets the mapper's input).
struct TestScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  /// `testLights`: the test lights (AddTestLights); else none, so that VTK makes its headlight.
  explicit TestScene(vtkVolumeMapper* mapper, int size = 96, bool testLights = true)
  {
    PrepareTestWindow(this->Window, size, size);
    this->Window->AddRenderer(this->Renderer);
    if (testLights)
    {
      AddTestLights(this->Renderer);
    }
    PlaceTestCamera(this->Renderer->GetActiveCamera());
    this->Volume->SetMapper(mapper);
    this->Volume->SetProperty(MakeTestProperty());
    this->Renderer->AddVolume(this->Volume);
  }
  vtkSmartPointer<vtkImageData> Render()
  {
    this->Window->Render();
    return Grab(this->Window);
  }
};

/// Sum of the RGB values (to tell a picture from a blank one).
inline double Brightness(vtkImageData* a)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  double s = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      s += x->GetComponent(i, c);
  return s;
}

#endif
