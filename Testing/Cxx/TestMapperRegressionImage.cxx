// Regression image test of one mapper (argument ea, ao or as) on a structured scene: the lumpy
// shell with its dense core, an opaque bar through the volume, a directional light and a point
// light inside the volume, a perspective camera, each mapper at its defaults but for the medium
// (ambient scattering shows its display transform). Compared with RegressionImage.h; --remake
// writes the baseline only after the same scene without the bar agrees with the CPU reference
// (vtkVolumeReferenceRenderer) at 55 dB or more (measured 59-76 dB).
#include "MapperTestScene.h"
#include "RegressionImage.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCubeSource.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkVolumeReferenceRenderer.h"

#include <cstring>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestMapperRegressionImage ea|ao|as -V baseline.png -T directory "
                 "[--remake | --wrong]\n";
    return EXIT_FAILURE;
  }
  const std::string mode = argv[1];
  vtkSmartPointer<vtkAVSVolumeMapper> mapper;
  vtkNew<vtkVolumeReferenceRenderer> reference; // the same scene, for --remake's check
  if (mode == "ea")
  {
    mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
    reference->SetRenderModeToEmissionAbsorption();
  }
  else if (mode == "ao")
  {
    auto ao = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
    ao->SetOcclusionRadius(0.15);
    mapper = ao;
    reference->SetRenderModeToAmbientOcclusion();
    reference->SetOcclusionRadius(0.15);
  }
  else
  {
    auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    as->SetAmbientRadius(0.06);
    as->SetAnisotropy(0.3);
    as->SetAlbedo(0.9);
    mapper = as;
    reference->SetRenderModeToAmbientScattering();
    reference->SetAmbientRadius(0.06);
    reference->SetAnisotropy(0.3);
    reference->SetAlbedo(0.9);
  }
  vtkNew<TestErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  auto data = MakeTestVolume(48);
  mapper->SetInputData(data);
  mapper->SetSampleDistance(0.015);
  mapper->UseJitteringOff();

  vtkNew<vtkRenderWindow> window;
  const int size = 192;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(MakeTestProperty());
  renderer->AddVolume(volume);

  // An opaque bar through the volume.
  vtkNew<vtkCubeSource> bar;
  bar->SetXLength(1.8);
  bar->SetYLength(0.12);
  bar->SetZLength(0.12);
  bar->SetCenter(0.1, -0.2, 0.2);
  vtkNew<vtkPolyDataMapper> barMapper;
  barMapper->SetInputConnection(bar->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(barMapper);
  actor->GetProperty()->SetColor(0.3, 0.8, 0.4);
  actor->GetProperty()->LightingOff(); // the scene lights are bright for the volume
  renderer->AddActor(actor);
  renderer->ResetCameraClippingRange();

  window->Render();
  if (errors->Errors != 0)
  {
    std::cerr << "the mapper reported an error: " << errors->LastError << "\n";
    return EXIT_FAILURE;
  }
  auto picture = Grab(window);
  auto check = [&]()
  {
    actor->VisibilityOff();
    window->Render();
    auto gpu = Grab(window);
    actor->VisibilityOn();
    reference->SetInputData(data);
    reference->SetVolumeProperty(volume->GetProperty());
    reference->SetRenderer(renderer);
    reference->SetImageSize(size, size);
    reference->SetSampleDistance(0.015);
    reference->SetBackground(renderer->GetBackground());
    reference->Update();
    const double psnr = Psnr(gpu, reference->GetOutput());
    std::cout << "without the bar against the CPU reference: " << psnr << " dB\n";
    return errors->Errors == 0 && psnr >= 55.0;
  };
  auto otherMapper = [&]() -> vtkSmartPointer<vtkImageData>
  {
    // Emission-absorption for the lit mappers, ambient scattering for emission-absorption.
    vtkSmartPointer<vtkAVSVolumeMapper> other;
    if (mode == "ea")
      other = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    else
      other = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
    other->SetInputData(data);
    other->SetSampleDistance(0.015);
    other->UseJitteringOff();
    volume->SetMapper(other);
    window->Render();
    auto out = Grab(window);
    volume->SetMapper(mapper);
    return out;
  };
  return RegressionTest(argc, argv, picture, check, otherMapper);
}
