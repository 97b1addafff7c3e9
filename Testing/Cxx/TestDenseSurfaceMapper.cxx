// No bands on dense surfaces in vtkAmbientScatteringVolumeMapper: a dense fog sphere (a level
// set turned fog volume, opacity 0.9 per voxel) under one directional light, with the light
// volume marched in the compute shader and on the CPU (PrecomputeOnGPUOff), against
// vtkVolumeReferenceRenderer; and the high-frequency energy of the mapper's picture along the lit
// surface. Tube marching counted from the box face put bands of period 2r there (2.3e-3 of the
// surface's energy; the core's Testing/Unit/TestDenseSurface measures the path tracer's at 0).
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "HighFrequencyEnergy.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkFloatArray.h"
#include "vtkPNGWriter.h"
#include "vtkVolumeReferenceRenderer.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
constexpr int Size = 128;

// A sphere of radius 0.6 in [-1, 1]^3 as OpenVDB's sdfToFogVolume makes it from a level set:
// 0 outside, rising linearly to 1 over 0.05 inside.
vtkSmartPointer<vtkImageData> DenseFogSphere(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  const double h = 2.0 / (n - 1);
  image->SetSpacing(h, h, h);
  image->SetOrigin(-1, -1, -1);
  vtkNew<vtkFloatArray> s;
  s->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double sdf =
          std::sqrt(std::pow(-1 + i * h, 2) + std::pow(-1 + j * h, 2) + std::pow(-1 + k * h, 2)) -
          0.6;
        s->SetValue(id++, static_cast<float>(std::clamp(-sdf / 0.05, 0.0, 1.0)));
      }
  image->GetPointData()->SetScalars(s);
  return image;
}

Picture Luminance(vtkImageData* image)
{
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  Picture p{ Size, Size, std::vector<double>(Size * Size, 0.0) };
  for (vtkIdType i = 0; i < std::min<vtkIdType>(rgb->GetNumberOfTuples(), Size * Size); ++i)
  {
    p.Values[i] = (0.2126 * rgb->GetComponent(i, 0) + 0.7152 * rgb->GetComponent(i, 1) +
                    0.0722 * rgb->GetComponent(i, 2)) /
      255.0;
  }
  return p;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int n = 96;
  auto data = DenseFogSphere(n);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  color->AddRGBPoint(1, 1, 1, 1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0);
  opacity->AddPoint(1, 0.9);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(2.0 / (n - 1)); // opacity 0.9 per voxel
  property->SetInterpolationTypeToLinear();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, Size, Size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.7);
  camera->SetClippingRange(1.0, 10.0);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 0.4, 0.5); // propagating along (1, -0.4, -0.5)
  sun->SetFocalPoint(0, 0, 0);
  renderer->AddLight(sun);

  const double step = 1.0 / (n - 1); // half a voxel
  vtkNew<vtkVolumeReferenceRenderer> reference;
  reference->SetInputData(data);
  reference->SetVolumeProperty(property);
  reference->SetRenderer(renderer);
  reference->SetImageSize(Size, Size);
  reference->SetSampleDistance(step);
  reference->SetRenderModeToAmbientScattering();
  reference->SetAlbedo(0.9);
  reference->SetAnisotropy(0.0);
  // Exposed so that the brightest pixel is at about 0.7, whatever the light units.
  sun->SetIntensity(1.0);
  reference->Update();
  const Picture probe = Luminance(reference->GetOutput());
  const double peak = *std::max_element(probe.Values.begin(), probe.Values.end());
  AVS_CHECK(peak > 0.0);
  sun->SetIntensity(0.7 / std::max(peak, 1e-6));
  reference->Modified();
  reference->Update();
  const Picture truth = Luminance(reference->GetOutput());

  // The lit surface, covered within the blur's reach. The bands' period 2r is 10 pixels.
  const double s = 2.0;
  std::vector<bool> covered(Size * Size);
  for (int i = 0; i < Size * Size; ++i)
  {
    covered[i] = truth.Values[i] > 0.0;
  }
  const std::vector<bool> mask = LitRegion(truth, covered, static_cast<int>(std::ceil(3 * s)) + 2);
  AVS_CHECK(std::count(mask.begin(), mask.end(), true) > 3000);

  for (bool onGPU : { true, false })
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(data);
    mapper->SetSampleDistance(step);
    mapper->UseJitteringOff();
    mapper->SetAlbedo(0.9);
    mapper->SetAnisotropy(0.0);
    mapper->SetPrecomputeOnGPU(onGPU);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    window->Render();
    auto gpu = Grab(window);
    renderer->RemoveVolume(volume);
    AVS_CHECK(errors->Errors == 0);
    const Picture picture = Luminance(gpu);
    const double psnr = Psnr(gpu, reference->GetOutput());
    const double high = HighFrequencyEnergy(picture, mask, s) / Energy(picture, mask);
    std::cout << "light volume " << (mapper->GetLightVolumesOnGPU() ? "on the GPU" : "on the CPU")
              << ": PSNR against the reference " << psnr
              << " dB, relative high-frequency energy on the lit surface " << high
              << " (reference's " << HighFrequencyEnergy(truth, mask, s) / Energy(truth, mask)
              << ")\n";
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName((dir + "/dense_surface_" + (onGPU ? "gpu" : "cpu") + ".png").c_str());
    writer->SetInputData(gpu);
    writer->Write();
    AVS_CHECK(psnr >= 50.0);
    AVS_CHECK(high < 5e-4);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
