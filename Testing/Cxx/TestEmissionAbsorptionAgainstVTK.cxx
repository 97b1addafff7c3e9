// vtkEmissionAbsorptionVolumeMapper against VTK's own vtkGPUVolumeRayCastMapper, unshaded, same
// sample distance, no jittering, same transfer functions: PSNR >= 35 dB over the RGB picture, in
// perspective and in parallel projection.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPNGWriter.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  auto data = MakeTestVolume();
  auto property = MakeTestProperty();
  property->ShadeOff();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  const double sampleDistance = 0.01;
  vtkNew<vtkGPUVolumeRayCastMapper> vtkMapper;
  vtkMapper->SetInputData(data);
  vtkMapper->SetSampleDistance(sampleDistance);
  vtkMapper->SetAutoAdjustSampleDistances(0);
  vtkMapper->SetUseJittering(0);
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ours;
  ours->SetInputData(data);
  ours->SetSampleDistance(sampleDistance);
  ours->UseJitteringOff();
  vtkNew<TestErrorObserver> errors;
  ours->AddObserver(vtkCommand::ErrorEvent, errors);

  for (int parallel = 0; parallel < 2; ++parallel)
  {
    renderer->GetActiveCamera()->SetParallelProjection(parallel);
    renderer->GetActiveCamera()->SetParallelScale(1.2);
    vtkSmartPointer<vtkImageData> pictures[2];
    for (int which = 0; which < 2; ++which)
    {
      vtkNew<vtkVolume> volume;
      volume->SetProperty(property);
      volume->SetMapper(which ? static_cast<vtkVolumeMapper*>(ours) : vtkMapper);
      renderer->AddVolume(volume);
      renderer->ResetCameraClippingRange();
      window->Render();
      pictures[which] = Grab(window);
      renderer->RemoveVolume(volume);
      vtkNew<vtkPNGWriter> writer;
      writer->SetFileName(
        (dir + "/ea_vs_vtk_" + std::to_string(parallel) + (which ? "_ours.png" : "_vtk.png"))
          .c_str());
      writer->SetInputData(pictures[which]);
      writer->Write();
    }
    const double psnr = Psnr(pictures[0], pictures[1]);
    std::cout << (parallel ? "parallel" : "perspective") << ": PSNR " << psnr
              << " dB (brightness VTK " << Brightness(pictures[0]) << ", ours "
              << Brightness(pictures[1]) << ")\n";
    AVS_CHECK(Brightness(pictures[0]) > 1000.0);
    // Measured against VTK 9.1's mapper: 63.9 dB in perspective, 62.0 in parallel projection;
    // 55 dB leaves room for another driver's rounding, not for a 5 % brightness error (Exposure
    // 1.05: 37.5 and 35.7 dB, which the former 35 dB passed).
    AVS_CHECK(psnr >= 55.0);
  }
  AVS_CHECK(errors->Errors == 0);
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
