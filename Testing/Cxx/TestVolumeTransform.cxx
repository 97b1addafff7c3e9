// The vtkVolume's transform. Opacity is integrated along the ray in data units (the volume's
// coordinates before its matrix), as vtkGPUVolumeRayCastMapper does, and the sample distance,
// the ambient and occlusion radii are data units too. So:
// - with a scaled, rotated volume and with a sheared user matrix, our EA agrees with VTK's
//   unshaded mapper (PSNR >= 35 dB; integrated in world units it was 24 dB);
// - each of the three mappers renders a volume scaled by 2 (with the camera twice as far)
//   as the unscaled one (PSNR >= 40 dB), while the unscaled one with half the unit distance,
//   which is what integrating in world units gives, differs (< 33 dB).
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkMatrix4x4.h"
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
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-1.0, 1.0, 0.6);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(1.1);
  renderer->AddLight(sun);

  auto render = [&](vtkVolumeMapper* mapper,
                  vtkVolumeProperty* p,
                  vtkMatrix4x4* user,
                  const double scale[3],
                  const double orientation[3])
  {
    vtkNew<vtkVolume> volume;
    volume->SetProperty(p);
    volume->SetMapper(mapper);
    volume->SetScale(scale[0], scale[1], scale[2]);
    volume->SetOrientation(orientation[0], orientation[1], orientation[2]);
    volume->SetUserMatrix(user);
    renderer->AddVolume(volume);
    renderer->ResetCameraClippingRange();
    window->Render();
    auto picture = Grab(window);
    renderer->RemoveVolume(volume);
    return picture;
  };
  auto write = [&](vtkImageData* picture, const std::string& name)
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName((dir + "/transform_" + name + ".png").c_str());
    writer->SetInputData(picture);
    writer->Write();
  };

  // EA against VTK's mapper: a scaled and rotated volume, and a sheared user matrix.
  {
    PlaceTestCamera(renderer->GetActiveCamera());
    renderer->GetActiveCamera()->SetPosition(2.9, 2.1, 7.5);
    vtkNew<vtkGPUVolumeRayCastMapper> vtkMapper;
    vtkMapper->SetInputData(data);
    vtkMapper->SetSampleDistance(0.01);
    vtkMapper->SetAutoAdjustSampleDistances(0);
    vtkMapper->SetUseJittering(0);
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ours;
    ours->SetInputData(data);
    ours->SetSampleDistance(0.01);
    ours->UseJitteringOff();
    vtkNew<vtkMatrix4x4> shear;
    shear->SetElement(0, 1, 0.4);
    shear->SetElement(2, 0, -0.3);
    shear->SetElement(1, 1, 1.3);
    const double scales[2][3] = { { 1.6, 0.7, 1.2 }, { 1.0, 1.0, 1.0 } };
    const double orientations[2][3] = { { 20, -30, 10 }, { 0, 0, 0 } };
    for (int c = 0; c < 2; ++c)
    {
      vtkMatrix4x4* user = c == 1 ? shear.Get() : nullptr;
      auto reference = render(vtkMapper, property, user, scales[c], orientations[c]);
      auto mine = render(ours, property, user, scales[c], orientations[c]);
      const double psnr = Psnr(reference, mine);
      std::cout << (c ? "sheared user matrix" : "scaled, rotated") << ": PSNR " << psnr
                << " dB against VTK (brightness VTK " << Brightness(reference) << ", ours "
                << Brightness(mine) << ")\n";
      write(reference, std::to_string(c) + "_vtk");
      write(mine, std::to_string(c) + "_ours");
      AVS_CHECK(Brightness(reference) > 1000.0);
      AVS_CHECK(psnr >= 35.0);
    }
  }

  // Each mapper: scaled by 2 with the camera twice as far = the unscaled volume.
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  vtkAVSVolumeMapper* mappers[3] = { ea, ao, as };
  const char* names[3] = { "ea", "ao", "as" };
  auto thinner = vtkSmartPointer<vtkVolumeProperty>::New();
  thinner->DeepCopy(property);
  thinner->SetScalarOpacityUnitDistance(0.5 * property->GetScalarOpacityUnitDistance());
  const double one[3] = { 1, 1, 1 }, two[3] = { 2, 2, 2 }, none[3] = { 0, 0, 0 };
  for (int m = 0; m < 3; ++m)
  {
    vtkNew<TestErrorObserver> errors;
    mappers[m]->AddObserver(vtkCommand::ErrorEvent, errors);
    mappers[m]->SetInputData(data);
    mappers[m]->SetSampleDistance(0.02);
    mappers[m]->UseJitteringOff();
    PlaceTestCamera(renderer->GetActiveCamera());
    auto unscaled = render(mappers[m], property, nullptr, one, none);
    auto thick = render(mappers[m], thinner, nullptr, one, none);
    double position[3];
    renderer->GetActiveCamera()->GetPosition(position);
    renderer->GetActiveCamera()->SetPosition(2 * position[0], 2 * position[1], 2 * position[2]);
    auto scaled = render(mappers[m], property, nullptr, two, none);
    const double psnr = Psnr(unscaled, scaled);
    const double matters = Psnr(thick, scaled);
    std::cout << names[m] << ": scaled by 2 against unscaled PSNR " << psnr
              << " dB (against the unit distance halved " << matters << " dB)\n";
    write(unscaled, std::string(names[m]) + "_unscaled");
    write(scaled, std::string(names[m]) + "_scaled");
    AVS_CHECK(Brightness(unscaled) > 1000.0);
    AVS_CHECK(psnr >= 40.0);
    AVS_CHECK(matters < 33.0);
    AVS_CHECK(errors->Errors == 0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
