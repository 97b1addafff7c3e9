// VTK regression image test of one mapper (argument ea, ao or as) on a structured scene: the
// lumpy shell with its dense core, an opaque bar through the volume, a directional light and a
// point light inside the volume, a perspective camera. The baselines in Testing/Data/Baseline
// were made by these mappers after TestMappersAgainstReference had checked the same mappers
// against the CPU reference ray caster.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCubeSource.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"

#include <cstring>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestMapperRegressionImage ea|ao|as -V baseline.png -T directory\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkAVSVolumeMapper> mapper;
  if (std::strcmp(argv[1], "ea") == 0)
  {
    mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
  }
  else if (std::strcmp(argv[1], "ao") == 0)
  {
    auto ao = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
    ao->SetOcclusionRadius(0.15);
    mapper = ao;
  }
  else
  {
    auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    as->SetAmbientRadius(0.06);
    as->SetAnisotropy(0.3);
    as->SetAlbedo(0.9);
    mapper = as;
  }
  vtkNew<TestErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->SetInputData(MakeTestVolume(48));
  mapper->SetSampleDistance(0.015);
  mapper->UseJitteringOff();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, 192, 192);
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
  const int result = vtkRegressionTestImageThreshold(window, 10.0);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
