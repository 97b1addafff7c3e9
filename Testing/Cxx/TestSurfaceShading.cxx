// Surfaces inside the medium (Rendering/Core/SurfaceShading.h): ambient scattering with the
// property's ShadeOn.
//
// - The GPU mapper against the CPU reference with ShadeOn, in both models, at blendings 0 and 1,
//   lit on two sides and on one, with VTK's coefficients and with a sharper specular lobe, split
//   into bricks, with the lights (and the surfaces) read per sample instead of per pair, and per
//   four samples on a coarse light grid (unsplit and in bricks), and with a radius too large for
//   the ring (the explicit look-ahead): PSNR at least 55 dB, as the unshaded comparison demands
//   (TestMappersAgainstReference).
// - ShadeOff, and ShadeOn at VolumetricScatteringBlending 2, give the unshaded picture bit for
//   bit; ShadeOn at the default blending differs from it clearly.
// - The surface term and its normal: a solid ball lit on one side only by a light behind the
//   camera. The ball's surface faces the camera and reflects it: with the diffuse and specular
//   coefficients the picture is more than twice as bright as with them at 0 (the ambient term
//   alone), on the GPU and in the reference. A surface term dropped fails here, and so does a
//   normal pointing into the material: the viewer is then behind the near surface, which
//   reflects nothing on one side (measured: 1.02x, against 2.99x).
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkLight.h"
#include "vtkPNGWriter.h"
#include "vtkVolumeReferenceRenderer.h"

#include <iostream>
#include <string>

namespace
{
struct Case
{
  const char* Name;
  bool Extended;
  float Blending;
  bool TwoSided;
  double Specular;
  double SpecularPower;
  double Radius = 0.08;
  double Step = 0.02;
  bool Bricked = false;
  int LightGrid = 128; ///< LightVolumeMaximumDimension (24: the lights once per four samples)
};

// A solid ball of value 900 (radius 0.6) with a smooth edge, in a box of side 2.
vtkSmartPointer<vtkImageData> MakeBall(int n = 40)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  const double h = 2.0 / (n - 1);
  image->SetSpacing(h, h, h);
  image->SetOrigin(-1.0, -1.0, -1.0);
  vtkNew<vtkShortArray> s;
  s->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = -1.0 + i * h, y = -1.0 + j * h, z = -1.0 + k * h;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double v = 900.0 * std::min(1.0, std::max(0.0, (0.65 - r) / 0.1));
        s->SetValue(id++, static_cast<short>(v));
      }
  image->GetPointData()->SetScalars(s);
  return image;
}

void Write(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}
} // namespace

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

  vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
  mapper->SetInputData(volumeData);
  mapper->SetSampleDistance(0.02);
  mapper->SetAmbientRadius(0.08);
  mapper->SetAnisotropy(0.3);
  mapper->UseJitteringOff();
  ShowLinear(mapper.Get());
  vtkNew<TestErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);

  auto render = [&]()
  {
    window->Render();
    return Grab(window);
  };
  auto reference = [&](const Case& c)
  {
    vtkNew<vtkVolumeReferenceRenderer> cpu;
    cpu->SetInputData(volumeData);
    cpu->SetVolumeProperty(property);
    cpu->SetRenderer(renderer);
    cpu->SetImageSize(size, size);
    cpu->SetSampleDistance(c.Step);
    cpu->SetRenderMode(vtkVolumeReferenceRenderer::AMBIENT_SCATTERING);
    cpu->SetScatteringModel(c.Extended ? vtkVolumeReferenceRenderer::ExtendedModel
                                       : vtkVolumeReferenceRenderer::PaperModel);
    cpu->SetAmbientRadius(c.Radius);
    cpu->SetLightVolumeMaximumDimension(c.LightGrid);
    cpu->SetAnisotropy(0.3);
    cpu->SetVolumetricScatteringBlending(c.Blending);
    ShowLinear(cpu.Get());
    cpu->Update();
    auto out = vtkSmartPointer<vtkImageData>::New();
    out->DeepCopy(cpu->GetOutput());
    return out;
  };
  auto setCase = [&](const Case& c)
  {
    mapper->SetScatteringModel(c.Extended ? vtkAmbientScatteringVolumeMapper::ExtendedModel
                                          : vtkAmbientScatteringVolumeMapper::PaperModel);
    mapper->SetVolumetricScatteringBlending(c.Blending);
    renderer->SetTwoSidedLighting(c.TwoSided);
    property->SetSpecular(c.Specular);
    property->SetSpecularPower(c.SpecularPower);
    mapper->SetAmbientRadius(c.Radius);
    mapper->SetLightVolumeMaximumDimension(c.LightGrid);
    mapper->SetSampleDistance(c.Step);
    mapper->SetPartitions(c.Bricked ? 2 : 1, c.Bricked ? 2 : 1, 1);
  };

  // ShadeOff, and ShadeOn with blending 2: the unshaded picture, bit for bit.
  property->ShadeOff();
  auto unshaded = render();
  Write(unshaded, dir + "/surface_off.png");
  property->ShadeOn();
  mapper->SetVolumetricScatteringBlending(2.0f);
  auto pure = render();
  const int blendingTwo = MaximumDifference(unshaded, pure);
  std::cout << "ShadeOn at blending 2 against ShadeOff: largest difference " << blendingTwo << "\n";
  AVS_CHECK(blendingTwo == 0);
  mapper->SetVolumetricScatteringBlending(0.0f);
  auto shaded = render();
  Write(shaded, dir + "/surface_on.png");
  const double onOff = Psnr(shaded, unshaded);
  std::cout << "ShadeOn (blending 0) against ShadeOff: PSNR " << onOff << " dB\n";
  AVS_CHECK(onOff < 35.0);

  // The GPU against the CPU reference.
  const Case cases[] = {
    { "paper_b0_two", false, 0.0f, true, 0.2, 10.0 },
    { "extended_b0_one", true, 0.0f, false, 0.5, 30.0 },
    { "extended_b1_two", true, 1.0f, true, 0.2, 10.0 },
    { "paper_b15_one", false, 1.5f, false, 0.2, 10.0 },
    { "extended_b0_bricks", true, 0.0f, true, 0.2, 10.0, 0.08, 0.02, true },
    // Two steps longer than a cell of the light grid: the lights, and the surfaces, per sample.
    { "extended_b0_per_sample", true, 0.0f, false, 0.2, 10.0, 0.08, 0.04 },
    // Four steps within a cell of a coarse light grid: the lights, and the surfaces' gradient
    // (its group's two middle samples'), once per four samples; unsplit and in bricks.
    { "extended_b0_fours", true, 0.0f, true, 0.2, 10.0, 0.08, 0.02, false, 24 },
    { "paper_b1_fours", false, 1.0f, false, 0.2, 10.0, 0.08, 0.02, false, 24 },
    { "extended_b0_bricks_fours", true, 0.0f, true, 0.2, 10.0, 0.08, 0.02, true, 24 },
    // 2 r / step > vtkAVSRayCaster::MaximumRingSize: the explicit look-ahead.
    { "extended_b0_explicit", true, 0.0f, true, 0.2, 10.0, 1.2, 0.004 },
  };
  for (const Case& c : cases)
  {
    setCase(c);
    auto gpu = render();
    auto cpu = reference(c);
    const double psnr = Psnr(gpu, cpu);
    std::cout << c.Name << ": PSNR " << psnr << " dB, brightness GPU " << Brightness(gpu) << " CPU "
              << Brightness(cpu) << "\n";
    Write(gpu, dir + "/surface_" + c.Name + "_gpu.png");
    Write(cpu, dir + "/surface_" + c.Name + "_cpu.png");
    AVS_CHECK(Brightness(gpu) > 1000.0);
    AVS_CHECK(psnr >= 55.0);
    // On a software rasterizer the scalars of one channel ride in the gradient's texels (each
    // sample's fetch brings its gradient); the same without (AVS_SURFACES_PACKED=0), the
    // gradient fetched per pair as a GPU does: the CPU reference's picture as well, and the
    // packed one's up to the scalars' 16 bits there.
    if (!c.Bricked)
    {
      setenv("AVS_SURFACES_PACKED", "0", 1);
      mapper->Modified(); // (the textures are looked at again)
      auto separate = render();
      unsetenv("AVS_SURFACES_PACKED");
      mapper->Modified();
      const double alone = Psnr(separate, cpu);
      const double packedSeparate = Psnr(gpu, separate);
      std::cout << c.Name << " without packing: PSNR " << alone << " dB; against packed "
                << packedSeparate << " dB\n";
      AVS_CHECK(alone >= 55.0);
      AVS_CHECK(packedSeparate >= 60.0);
    }
  }

  // The surface term and its normal: a ball, one side, a light from behind the camera.
  volumeData = MakeBall();
  mapper->SetInputData(volumeData);
  renderer->RemoveAllLights();
  vtkNew<vtkLight> front;
  front->SetLightTypeToSceneLight();
  front->SetPositional(false);
  front->SetPosition(renderer->GetActiveCamera()->GetPosition());
  front->SetFocalPoint(0, 0, 0);
  renderer->AddLight(front);
  const Case sided{ "sided", true, 0.0f, false, 0.2, 10.0 };
  mapper->SetInputData(volumeData);
  setCase(sided);
  auto reflecting = render();
  auto reflectingCpu = reference(sided);
  property->SetDiffuse(0.0);
  property->SetSpecular(0.0);
  auto ambientOnly = render();
  auto ambientOnlyCpu = reference(sided);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.2);
  const double gain = Brightness(reflecting) / Brightness(ambientOnly);
  const double gainCpu = Brightness(reflectingCpu) / Brightness(ambientOnlyCpu);
  std::cout << "one-sided, lit from the camera: with the diffuse and specular terms " << gain
            << " x (CPU " << gainCpu << " x) as bright as with the ambient term alone\n";
  AVS_CHECK(gain > 2.0);
  AVS_CHECK(gainCpu > 2.0);
  AVS_CHECK(errors->Errors == 0);
  renderer->RemoveVolume(volume);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
