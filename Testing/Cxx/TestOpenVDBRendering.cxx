// VTK regression image test: a VDB fog volume imported with vtkOpenVDBImageReader and rendered by
// vtkAmbientScatteringVolumeMapper (a directional light and a point light), with its direction
// matrix. Argument: the .vdb file (written by MakeTestCloudVDB), then -V baseline -T directory
// [--remake | --wrong] (RegressionImage.h; --remake's check: the CPU reference of the
// same scene at 55 dB or more).
#include "MapperTestScene.h"
#include "RegressionImage.h"
#include "TestErrorObserver.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkVolumeReferenceRenderer.h"

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestOpenVDBRendering FILE.vdb -V baseline.png -T directory [--remake | "
                 "--wrong]\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkOpenVDBImageReader> reader;
  vtkNew<TestErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(argv[1]);
  reader->Update();
  if (errors->Errors || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "could not read " << argv[1] << ": " << errors->LastError << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->SetInputConnection(reader->GetOutputPort());
  mapper->SetAlbedo(0.95);
  mapper->SetAnisotropy(0.5);
  mapper->UseJitteringOff();

  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(1.2, 0.95, 0.97, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.05, 0.0);
  opacity->AddPoint(1.2, 0.6);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.08);

  vtkNew<vtkRenderWindow> window;
  const int size = 160;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.35, 0.5, 0.75);
  window->AddRenderer(renderer);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(0.3, 1.0, -0.8); // from above and behind: a cloud lit from behind
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(1.1);
  renderer->AddLight(sun);
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180);
  lamp->SetPosition(0.0, -0.2, 0.0);
  lamp->SetDiffuseColor(1.0, 0.6, 0.3);
  lamp->SetIntensity(0.32);
  lamp->SetAttenuationValues(1.0, 0.0, 4.0);
  renderer->AddLight(lamp);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.4, 0.3, 3.4);
  camera->SetFocalPoint(0, -0.05, 0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  if (errors->Errors || mapper->GetNumberOfRenderedFrames() != 1)
  {
    std::cerr << "the mapper did not render: " << errors->LastError << "\n";
    return EXIT_FAILURE;
  }
  auto check = [&]()
  {
    vtkNew<vtkVolumeReferenceRenderer> reference;
    reference->SetInputConnection(reader->GetOutputPort());
    reference->SetVolumeProperty(property);
    reference->SetRenderer(renderer);
    reference->SetImageSize(size, size);
    reference->SetAlbedo(0.95);
    reference->SetAnisotropy(0.5);
    reference->SetBackground(renderer->GetBackground());
    reference->Update();
    const double psnr = Psnr(Grab(window), reference->GetOutput());
    std::cout << "against the CPU reference: " << psnr << " dB\n";
    return psnr >= 55.0;
  };
  auto otherMapper = [&]() -> vtkSmartPointer<vtkImageData>
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    ea->SetInputConnection(reader->GetOutputPort());
    ea->UseJitteringOff();
    volume->SetMapper(ea);
    window->Render();
    auto out = Grab(window);
    volume->SetMapper(mapper);
    return out;
  };
  return RegressionTest(argc, argv, Grab(window), check, otherMapper);
}
