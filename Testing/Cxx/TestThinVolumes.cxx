// Thin and small volumes under ambient scattering: a 64x64x2 slab, a 4x4x4 image and a
// 256x256x3 stack render (not black) and agree with the CPU reference; the automatic ambient
// radius fits into the volume (at most half its smallest side); a 64x64x1 image keeps its error.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include "ScatteringParameters.h"

#include "vtkFloatArray.h"

#include <iostream>

namespace
{
vtkSmartPointer<vtkImageData> Stack(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(1.0, 1.0, 1.0);
  vtkNew<vtkFloatArray> s;
  s->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny * nz);
  vtkIdType id = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s->SetValue(id++, static_cast<float>(0.5 + 0.5 * std::sin(0.3 * i) * std::cos(0.2 * j)));
  image->GetPointData()->SetScalars(s);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 0.8, 0.6);
  color->AddRGBPoint(1, 1, 1, 1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.1);
  opacity->AddPoint(1, 0.8);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  return property;
}
} // namespace

int main(int, char*[])
{
  int failures = 0;
  const int size = 96;
  const int shapes[3][3] = { { 64, 64, 2 }, { 4, 4, 4 }, { 256, 256, 3 } };
  for (const auto& shape : shapes)
  {
    auto data = Stack(shape[0], shape[1], shape[2]);
    avs::GridGeometry geometry;
    geometry.Dimensions = { shape[0], shape[1], shape[2] };
    const double radius = avs::ScatteringParameters::DefaultAmbientRadius(geometry);
    AVS_CHECK(radius <= 0.5 * (std::min({ shape[0], shape[1], shape[2] }) - 1) + 1e-12);
    AVS_CHECK(radius > 0.0);

    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(data);
    mapper->UseJitteringOff();
    vtkNew<vtkRenderWindow> window;
    PrepareTestWindow(window, size, size);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(Property());
    renderer->AddVolume(volume);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Elevation(30);
    renderer->GetActiveCamera()->Azimuth(20);
    renderer->ResetCameraClippingRange();
    window->Render(); // the automatic headlight
    auto gpu = Grab(window);

    vtkNew<vtkVolumeReferenceRenderer> reference;
    reference->SetInputData(data);
    reference->SetVolumeProperty(Property());
    reference->SetRenderer(renderer);
    reference->SetImageSize(size, size);
    reference->Update();
    const double psnr = Psnr(gpu, reference->GetOutput());
    const double mean = Brightness(gpu) / (3.0 * size * size);
    std::cout << shape[0] << "x" << shape[1] << "x" << shape[2] << ": radius " << radius
              << ", mean " << mean << ", PSNR against the reference " << psnr << " dB\n";
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(mean > 10.0); // lit, not black
    AVS_CHECK(psnr >= 45.0);
  }

  // One slice is not a volume: the error stays.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(Stack(64, 64, 1));
    vtkNew<vtkRenderWindow> window;
    PrepareTestWindow(window, 32, 32);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(Property());
    renderer->AddVolume(volume);
    renderer->ResetCamera();
    window->Render();
    std::cout << "64x64x1: " << errors->LastError << "\n";
    AVS_CHECK(errors->Errors >= 1);
    AVS_CHECK(Brightness(Grab(window)) == 0.0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
  }
  return failures ? 1 : 0;
}
