// Each GPU mapper's picture against the CPU reference ray caster on the same scene: same
// volume, transfer functions, lights, camera and sample distance, jittering off. Metric: PSNR
// over the RGB picture; threshold 35 dB.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkPNGWriter.h"
#include "vtkVolumeReferenceRenderer.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  auto volumeData = MakeTestVolume();
  auto property = MakeTestProperty();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  const double sampleDistance = 0.02;
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  as->SetAnisotropy(0.4);
  as->SetAlbedo(0.9);
  vtkAVSVolumeMapper* mappers[3] = { ea, ao, as };
  const char* names[3] = { "ea", "ao", "as" };
  for (int m = 0; m < 3; ++m)
  {
    vtkAVSVolumeMapper* mapper = mappers[m];
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(volumeData);
    mapper->SetSampleDistance(sampleDistance);
    mapper->UseJitteringOff();
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    window->Render();
    auto gpu = Grab(window);
    renderer->RemoveVolume(volume);
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == 1);

    vtkNew<vtkVolumeReferenceRenderer> reference;
    reference->SetInputData(volumeData);
    reference->SetVolumeProperty(property);
    reference->SetRenderer(renderer);
    reference->SetImageSize(size, size);
    reference->SetSampleDistance(sampleDistance);
    reference->SetRenderMode(m);
    reference->SetOcclusionRadius(0.15);
    reference->SetAmbientRadius(0.08);
    reference->SetAnisotropy(0.4);
    reference->SetAlbedo(0.9);
    reference->Update();
    const double psnr = Psnr(gpu, reference->GetOutput());
    std::cout << names[m] << ": PSNR " << psnr << " dB, brightness GPU " << Brightness(gpu)
              << " CPU " << Brightness(reference->GetOutput()) << "\n";
    for (int which = 0; which < 2; ++which)
    {
      vtkNew<vtkPNGWriter> writer;
      writer->SetFileName((dir + "/" + names[m] + (which ? "_cpu.png" : "_gpu.png")).c_str());
      writer->SetInputData(which ? reference->GetOutput() : gpu.Get());
      writer->Write();
    }
    AVS_CHECK(Brightness(gpu) > 1000.0);
    AVS_CHECK(psnr >= 35.0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
