// VTK light units (ALGORITHM.md section 1): a vtkLight of intensity 1 on an optically thin,
// white, isotropic medium of albedo 1 returns the emission-absorption colour, in the CPU
// reference and in the GPU mappers; LightScale multiplies every light; AO's direct light of
// weight 1 is the unshadowed single scattering of the same lights (the EA colour here). Linear
// radiance on the screen (ShowLinear): these are the physics' units, not the display's.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include "vtkFloatArray.h"

#include <iostream>

namespace
{
// A unit cube of constant density: optical depth 0.2 straight through.
vtkSmartPointer<vtkImageData> ThinCube()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(24, 24, 24);
  image->SetSpacing(1.0 / 23, 1.0 / 23, 1.0 / 23);
  image->SetOrigin(-0.5, -0.5, -0.5);
  vtkNew<vtkFloatArray> s;
  s->SetNumberOfTuples(24 * 24 * 24);
  s->FillValue(1.0f);
  s->SetValue(0, 0.0f); // a scalar range to map the opacity over
  image->GetPointData()->SetScalars(s);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> WhiteThin()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  color->AddRGBPoint(1, 1, 1, 1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(0.5, 0.0199);
  opacity->AddPoint(1, 0.0199); // sigma_t = -ln(1 - 0.0199) / 0.1 = 0.2 per unit
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.1);
  property->SetInterpolationTypeToLinear();
  return property;
}

void Setup(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 4);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.45); // the picture lies inside the cube's face
  camera->SetClippingRange(1, 8);
  vtkNew<vtkLight> light; // a plain VTK light of intensity 1
  light->SetLightTypeToSceneLight();
  light->SetPosition(0.3, 0.4, 1.0);
  light->SetFocalPoint(0, 0, 0);
  light->SetIntensity(1.0);
  renderer->AddLight(light);
}

double Reference(int mode, double lightScale, double directWeight = 0.0)
{
  vtkNew<vtkRenderer> renderer;
  Setup(renderer);
  vtkNew<vtkVolumeReferenceRenderer> reference;
  reference->SetInputData(ThinCube());
  reference->SetVolumeProperty(WhiteThin());
  reference->SetRenderer(renderer);
  reference->SetImageSize(32, 32);
  reference->SetRenderMode(mode);
  reference->SetAlbedo(1.0);
  reference->SetAnisotropy(0.0);
  reference->SetLightScale(lightScale);
  reference->SetAmbientWeight(directWeight > 0 ? 0.0 : 1.0);
  reference->SetDirectLightWeight(directWeight);
  ShowLinear(reference.Get());
  reference->Update();
  return Brightness(reference->GetOutput());
}

double Mapper(vtkAVSVolumeMapper* mapper, TestErrorObserver* errors)
{
  mapper->SetInputData(ThinCube());
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  ShowLinear(mapper);
  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, 32, 32);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  Setup(renderer);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(WhiteThin());
  renderer->AddVolume(volume);
  window->Render();
  return Brightness(Grab(window));
}
} // namespace

int main(int, char*[])
{
  int failures = 0;
  using R = vtkVolumeReferenceRenderer;
  // The CPU reference.
  const double ea = Reference(R::EMISSION_ABSORPTION, 1.0);
  const double as = Reference(R::AMBIENT_SCATTERING, 1.0);
  const double as2 = Reference(R::AMBIENT_SCATTERING, 2.0);
  const double ao = Reference(R::AMBIENT_OCCLUSION, 1.0, 1.0);
  const double ao3 = Reference(R::AMBIENT_OCCLUSION, 3.0, 1.0);
  std::cout << "reference: EA " << ea << ", AS/EA " << as / ea << ", AS(scale 2)/AS " << as2 / as
            << ", AO direct/EA " << ao / ea << ", AO direct (scale 3)/AO " << ao3 / ao << "\n";
  AVS_CHECK(ea > 0.1 * 255 * 3 * 32 * 32);   // about 46/255 per channel: thin, far from saturation
  AVS_CHECK(as / ea > 0.8 && as / ea < 1.1); // the light is attenuated a little inside
  AVS_CHECK(as2 / as > 1.95 && as2 / as < 2.05);
  AVS_CHECK(ao / ea > 0.97 && ao / ea < 1.03);
  AVS_CHECK(ao3 / ao > 2.9 && ao3 / ao < 3.1);

  // The GPU mappers, same scene.
  vtkNew<TestErrorObserver> errors;
  vtkNew<vtkEmissionAbsorptionVolumeMapper> eaMapper;
  eaMapper->UseJitteringOff();
  const double gea = Mapper(eaMapper, errors);
  vtkNew<vtkAmbientScatteringVolumeMapper> asMapper;
  asMapper->UseJitteringOff();
  asMapper->SetAlbedo(1.0);
  asMapper->SetAnisotropy(0.0);
  const double gas = Mapper(asMapper, errors);
  vtkNew<vtkAmbientScatteringVolumeMapper> asMapper2;
  asMapper2->UseJitteringOff();
  asMapper2->SetAlbedo(1.0);
  asMapper2->SetLightScale(2.0);
  const double gas2 = Mapper(asMapper2, errors);
  vtkNew<vtkAmbientOcclusionVolumeMapper> aoMapper;
  aoMapper->UseJitteringOff();
  aoMapper->SetAmbientWeight(0.0);
  aoMapper->SetDirectLightWeight(1.0);
  const double gao = Mapper(aoMapper, errors);
  std::cout << "mappers: EA " << gea << ", AS/EA " << gas / gea << ", AS(scale 2)/AS " << gas2 / gas
            << ", AO direct/EA " << gao / gea << "\n";
  AVS_CHECK(errors->Errors == 0);
  AVS_CHECK(gea > 0.1 * 255 * 3 * 32 * 32);
  AVS_CHECK(gas / gea > 0.8 && gas / gea < 1.1);
  AVS_CHECK(std::abs(gas / gea - as / ea) < 0.03); // the mapper and the reference agree
  AVS_CHECK(gas2 / gas > 1.95 && gas2 / gas < 2.05);
  AVS_CHECK(gao / gea > 0.97 && gao / gea < 1.03);
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
  }
  return failures ? 1 : 0;
}
