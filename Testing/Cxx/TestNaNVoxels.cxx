// Not-a-number voxels: simulation output with masked cells. A volume with a
// block of NaN voxels, scattered NaNs and infinities renders with every mapper and the CPU
// reference (no error), with exactly one warning that gives the counts; NaN is empty space
// (rays through the NaN block alone stay black, and the block changes the picture); infinities
// are clamped to the finite range (the picture equals that of the data with the clamped values,
// so neither the range nor the transfer functions see them); the GPU mappers agree with the
// CPU reference (>= 35 dB), with the precomputation on the GPU and on the CPU.
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include <cmath>

#include <iostream>
#include <limits>

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

// The test shell with NaN in the block x > 0.35 ("land"), NaN at a few scattered points,
// +inf at one point of the core and -inf at one point of the shell.
vtkSmartPointer<vtkImageData> MakeNaNVolume(bool clampedInstead)
{
  auto image = MakeTestImage();
  AddArray(image,
    "field",
    1,
    false,
    [&](double x, double y, double z) -> std::array<double, 4>
    {
      std::array<double, 4> v = ShellValue(x, y, z);
      if (x > 0.35 && !clampedInstead)
      {
        v[0] = NaN;
      }
      return v;
    });
  vtkDataArray* a = image->GetPointData()->GetArray("field");
  image->GetPointData()->SetActiveScalars("field");
  int dims[3];
  image->GetDimensions(dims);
  auto id = [&](int i, int j, int k)
  { return (static_cast<vtkIdType>(k) * dims[1] + j) * dims[0] + i; };
  if (!clampedInstead)
  {
    a->SetComponent(id(12, 20, 20), 0, NaN);
    a->SetComponent(id(20, 12, 25), 0, NaN);
    a->SetComponent(id(20, 20, 20), 0, Inf);  // in the core: 900, the largest value
    a->SetComponent(id(20, 33, 20), 0, -Inf); // in the shell: becomes 0, the smallest
  }
  else
  {
    // The data without the NaN block, with finite values in place of the infinities.
    a->SetComponent(id(20, 20, 20), 0, 900.0);
    a->SetComponent(id(20, 33, 20), 0, 0.0);
  }
  return image;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  auto property = MakeTestProperty();
  auto data = MakeNaNVolume(false);

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  vtkNew<vtkAmbientScatteringVolumeMapper> asCPU;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  asCPU->SetAmbientRadius(0.08);
  asCPU->PrecomputeOnGPUOff();
  vtkAVSVolumeMapper* mappers[4] = { ea, ao, as, asCPU };
  const char* names[4] = { "ea", "ao", "as", "as_cpu_precomputation" };
  for (int m = 0; m < 4; ++m)
  {
    vtkAVSVolumeMapper* mapper = mappers[m];
    vtkNew<TestErrorObserver> messages;
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->SetInputData(data);
    mapper->SetSampleDistance(0.02);
    mapper->UseJitteringOff();
    auto picture =
      RenderVolume(window, renderer, mapper, property, dir, std::string("nan_") + names[m]);
    // A second frame: no second warning.
    RenderVolume(window, renderer, mapper, property);
    std::cout << names[m] << ": " << messages->Errors << " errors, " << messages->Warnings
              << " warnings, brightness " << Brightness(picture) << "\n";
    AVS_CHECK(messages->Errors == 0);
    AVS_CHECK(messages->Warnings == 1);
    AVS_CHECK(Brightness(picture) > 1000.0);

    vtkNew<vtkVolumeReferenceRenderer> cpu;
    vtkNew<TestErrorObserver> cpuMessages;
    cpu->AddObserver(vtkCommand::ErrorEvent, cpuMessages);
    cpu->AddObserver(vtkCommand::WarningEvent, cpuMessages);
    cpu->SetInputData(data);
    cpu->SetVolumeProperty(property);
    cpu->SetRenderer(renderer);
    cpu->SetImageSize(size, size);
    cpu->SetSampleDistance(0.02);
    cpu->SetRenderMode(m < 2 ? m : 2);
    cpu->SetOcclusionRadius(0.15);
    cpu->SetAmbientRadius(0.08);
    cpu->Update();
    const double psnr = Psnr(picture, cpu->GetOutput());
    std::cout << names[m] << ": against the CPU reference " << psnr << " dB\n";
    AVS_CHECK(cpuMessages->Errors == 0);
    AVS_CHECK(cpuMessages->Warnings == 1);
    AVS_CHECK(psnr >= 35.0);
  }

  // NaN is empty space: seen along x, the rays cross the NaN block (x > 0.35 in normalised
  // coordinates) first; the picture differs from that of the data without the block.
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(4.0, 0.0, 0.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0, 0, 1);
    camera->ParallelProjectionOn();
    camera->SetParallelScale(1.2);
    ea->SetInputData(data);
    auto withNaN = RenderVolume(window, renderer, ea, property, dir, "nan_side");
    auto clean = MakeNaNVolume(true);
    ea->SetInputData(clean);
    auto withoutNaN = RenderVolume(window, renderer, ea, property, dir, "nan_side_clean");
    const double difference = Psnr(withNaN, withoutNaN);
    std::cout << "side view with and without the NaN block: " << difference << " dB\n";
    AVS_CHECK(difference < 30.0); // the NaN block removes material
    AVS_CHECK(Brightness(withNaN) > 1000.0);
    camera->ParallelProjectionOff();
    PlaceTestCamera(camera);
  }
  // A ray entirely in NaN voxels: a volume whose only material lies in the NaN block renders
  // black (the block's NaN voxels are empty space, whatever the transfer function says of the
  // value 0 there).
  {
    auto block = MakeTestImage();
    AddArray(block,
      "field",
      1,
      false,
      [&](double x, double, double) -> std::array<double, 4>
      {
        const double value = x > 0.0 ? NaN : 0.0; // NaN in the right half
        return { value, 0, 0, 0 };
      });
    block->GetPointData()->SetActiveScalars("field");
    vtkNew<vtkVolumeProperty> dense;
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(-1, 0.8);
    opacity->AddPoint(1, 0.8);
    dense->SetScalarOpacity(opacity);
    dense->SetScalarOpacityUnitDistance(0.1);
    vtkNew<vtkColorTransferFunction> white;
    white->AddRGBPoint(-1, 1, 1, 1);
    white->AddRGBPoint(1, 1, 1, 1);
    dense->SetColor(white);
    ea->SetInputData(block);
    // The left half of the box (x < 0) is dense; the right half is NaN. Seen along z, the rays
    // through x > 0 stay black.
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0, 1, 0);
    camera->ParallelProjectionOn();
    camera->SetParallelScale(1.2);
    auto picture = RenderVolume(window, renderer, ea, dense, dir, "nan_half_front");
    // Pixels left of the centre look through x < 0 (material), right of it through x > 0.
    const double left = picture->GetScalarComponentAsDouble(size / 2 - 20, size / 2, 0, 0);
    const double right = picture->GetScalarComponentAsDouble(size / 2 + 20, size / 2, 0, 0);
    std::cout << "half NaN: left " << left << ", right " << right << "\n";
    AVS_CHECK(left > 100.0);
    AVS_CHECK(right == 0.0);
    camera->ParallelProjectionOff();
    PlaceTestCamera(camera);
  }
  // Infinities are clamped to the finite range: the same picture as the data with 900 and 0 in
  // their place (the NaNs kept in both).
  {
    auto clamped = MakeNaNVolume(false);
    vtkDataArray* a = clamped->GetPointData()->GetArray("field");
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      const double v = a->GetComponent(i, 0);
      if (std::isinf(v))
      {
        a->SetComponent(i, 0, v > 0 ? 900.0 : 0.0);
      }
    }
    ea->SetInputData(data);
    auto withInfinities = RenderVolume(window, renderer, ea, property);
    ea->SetInputData(clamped);
    auto withClamped = RenderVolume(window, renderer, ea, property);
    const double psnr = Psnr(withInfinities, withClamped);
    std::cout << "infinities against their clamped values: " << psnr << " dB\n";
    AVS_CHECK(psnr > 80.0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
