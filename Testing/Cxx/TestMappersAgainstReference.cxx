// Each GPU mapper's picture against the CPU reference ray caster on the same scene: same
// volume, transfer functions, lights, camera and sample distance, jittering off; in perspective
// from outside, from inside the volume (with a spot light and a headlight added) and in parallel
// projection (with light volumes coarser than the data, and the diffusion grid coarser still);
// and a fourth view with five lights (two
// light-volume textures), AO with direct light, emission in AO and ambient scattering, and an
// ambient radius too large for the ring buffer (the explicit look-ahead). Ambient scattering in
// both models: the paper's and the extended one (its diffusion solve on the CPU, its extra
// per-sample term in the shader), which must also be brighter than the paper's. Metric: PSNR
// over the RGB picture; threshold 35 dB, and 55 dB for ambient scattering in the first three
// views, where it reads its lights once per pair of samples, or per four on view 2's coarse light
// grid (as the reference must too).
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPNGWriter.h"
#include "vtkVolumeReferenceRenderer.h"

#include <cstdlib>
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

  const double sampleDistance = 0.02;
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  as->SetAnisotropy(0.4);
  as->SetAlbedo(0.9);
  as->SetScatteringModelToPaper();
  vtkNew<vtkAmbientScatteringVolumeMapper> asx;
  asx->SetAnisotropy(0.4);
  asx->SetAlbedo(0.9);
  asx->SetScatteringModelToExtended();
  vtkAVSVolumeMapper* mappers[4] = { ea, ao, as, asx };
  const char* names[4] = { "ea", "ao", "as", "asx" };
  vtkAmbientScatteringVolumeMapper* scattering[2] = { as, asx };

  // Three views: perspective from outside (a directional and a point light); the camera inside
  // the volume (plus a spot light and a headlight); parallel projection.
  for (int view = 0; view < 4; ++view)
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    PlaceTestCamera(camera);
    double radius = 0.08, step = sampleDistance, direct = 0.0, emission = 0.0;
    if (view == 1)
    {
      camera->SetPosition(0.15, 0.1, 0.45); // inside the box, in the shell's cavity
      camera->SetFocalPoint(0.0, 0.0, -0.5);
      camera->SetViewAngle(60);
      camera->SetClippingRange(0.0005, 5.0);
      vtkNew<vtkLight> spot;
      spot->SetLightTypeToSceneLight();
      spot->SetPositional(true);
      spot->SetPosition(0.9, -0.6, 0.9);
      spot->SetFocalPoint(0, 0, 0);
      spot->SetConeAngle(25);
      spot->SetExponent(2);
      spot->SetIntensity(1.6);
      renderer->AddLight(spot);
      vtkNew<vtkLight> head;
      head->SetLightTypeToHeadlight();
      head->SetIntensity(0.16);
      renderer->AddLight(head);
    }
    else if (view == 2)
    {
      camera->ParallelProjectionOn();
      camera->SetParallelScale(1.1);
    }
    else if (view == 3)
    {
      // Back to the two test lights, plus three directional ones.
      renderer->RemoveAllLights();
      AddTestLights(renderer);
      const double directions[3][3] = { { 1, 0, 0 }, { 0, -1, 0.3 }, { -0.5, 0.5, -1 } };
      for (const auto& d : directions)
      {
        vtkNew<vtkLight> light;
        light->SetLightTypeToSceneLight();
        light->SetPosition(-d[0], -d[1], -d[2]);
        light->SetFocalPoint(0, 0, 0);
        light->SetIntensity(0.056);
        renderer->AddLight(light);
      }
      // 2 r / step > vtkAVSRayCaster::MaximumRingSize.
      radius = 1.2;
      step = 0.004;
      direct = 0.5;
      emission = 0.8;
    }
    double paperBrightness = 0.0;
    for (int m = 0; m < 4; ++m)
    {
      vtkAVSVolumeMapper* mapper = mappers[m];
      vtkNew<TestErrorObserver> errors;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->SetInputData(volumeData);
      mapper->SetSampleDistance(step);
      mapper->UseJitteringOff();
      for (vtkAmbientScatteringVolumeMapper* s : scattering)
      {
        s->SetAmbientRadius(radius);
        // Parallel view: light volumes, averaged extinction and occlusion on grids coarser than
        // the data.
        s->SetLightVolumeMaximumDimension(view == 2 ? 24 : 256);
        // ... and the extended model's diffusion grid coarser than the light grid (its fluence
        // interpolated onto the light grid).
        s->SetDiffusionVolumeMaximumDimension(view == 2 ? 12 : 64);
        s->SetEmissionWeight(emission);
      }
      // The extended model isotropic (g = 0: the program without the diffuse field's flux
      // term) in the last view (the explicit look-ahead); anisotropic in the others, view 2's
      // lights once per four samples (its coarse light grid) included.
      const double extendedAnisotropy = view == 3 ? 0.0 : 0.4;
      asx->SetAnisotropy(extendedAnisotropy);
      ao->SetOcclusionVolumeMaximumDimension(view == 2 ? 20 : 256);
      ao->SetDirectLightWeight(direct);
      ao->SetEmissionWeight(emission);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(property);
      renderer->AddVolume(volume);
      window->Render();
      auto gpu = Grab(window);
      renderer->RemoveVolume(volume);
      AVS_CHECK(errors->Errors == 0);
      if (m == 3)
      {
        AVS_CHECK(asx->GetNumberOfDiffusionRebuilds() >= 1);
      }
      // Which path computed the precomputed volumes: the GPU's where the context has compute
      // shaders (else the comparison below is of the CPU code with itself), the CPU's in the
      // OpenGL 4.1 run (the context really has none).
      const bool gpuExpected = std::getenv("AVS_EXPECT_CPU_PRECOMPUTATION") == nullptr;
      if (m == 1)
      {
        AVS_CHECK(ao->GetOcclusionOnGPU() == (gpuExpected ? 1 : 0));
      }
      else if (m == 2)
      {
        AVS_CHECK(as->GetLightVolumesOnGPU() == (gpuExpected ? 1 : 0));
      }
      else if (m == 3)
      {
        AVS_CHECK(asx->GetLightVolumesOnGPU() == (gpuExpected ? 1 : 0));
      }

      vtkNew<vtkVolumeReferenceRenderer> reference;
      reference->SetInputData(volumeData);
      reference->SetVolumeProperty(property);
      reference->SetRenderer(renderer);
      reference->SetImageSize(size, size);
      reference->SetSampleDistance(step);
      reference->SetDirectLightWeight(direct);
      reference->SetEmissionWeight(emission);
      reference->SetRenderMode(m == 3 ? 2 : m);
      reference->SetScatteringModel(m == 3 ? vtkVolumeReferenceRenderer::ExtendedModel
                                           : vtkVolumeReferenceRenderer::PaperModel);
      reference->SetOcclusionRadius(0.15);
      reference->SetAmbientRadius(radius);
      reference->SetLightVolumeMaximumDimension(view == 2 ? 24 : 256);
      reference->SetDiffusionVolumeMaximumDimension(view == 2 ? 12 : 64);
      reference->SetOcclusionVolumeMaximumDimension(view == 2 ? 20 : 256);
      // The AO mapper's direct light scatters with albedo 1 and g = 0.
      reference->SetAnisotropy(m == 1 ? 0.0 : (m == 3 ? extendedAnisotropy : 0.4));
      // (the reference renderer's model: the paper's unless m == 3)
      reference->SetAlbedo(m == 1 ? 1.0 : 0.9);
      reference->Update();
      const double psnr = Psnr(gpu, reference->GetOutput());
      const std::string tag = std::string(names[m]) + "_view" + std::to_string(view);
      std::cout << tag << ": PSNR " << psnr << " dB, brightness GPU " << Brightness(gpu) << " CPU "
                << Brightness(reference->GetOutput()) << "\n";
      for (int which = 0; which < 2; ++which)
      {
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName((dir + "/" + tag + (which ? "_cpu.png" : "_gpu.png")).c_str());
        writer->SetInputData(which ? reference->GetOutput() : gpu.Get());
        writer->Write();
      }
      AVS_CHECK(Brightness(gpu) > 1000.0);
      // Measured on llvmpipe: EA 60.5-66.7 dB, AO 62.7-69.1, ambient scattering 61.8-71.7 (both
      // the compute-shader and the OpenGL 4.1 run). 55 dB leaves about 5 dB (under twice the RMS
      // error) for another driver's rounding; EA 5 % too bright (Exposure 1.05) measures
      // 30.0-37.5 dB on these pictures and fails (the former 35 dB passed two of the views).
      AVS_CHECK(psnr >= 55.0);
      if (m >= 2 && view < 3)
      {
        // Ambient scattering reads its lights once per pair of samples here, per four in view 2
        // (their midpoint; ScatteringParameters::LightGroup): read at the samples themselves
        // instead, the reference differs by 50-54 dB in views 1 and 2 (60-68 dB in view 0).
        AVS_CHECK(psnr >= 55.0);
      }
      if (m == 2)
      {
        paperBrightness = Brightness(gpu);
      }
      if (m == 3)
      {
        // The diffuse light adds to the paper's model.
        AVS_CHECK(Brightness(gpu) > 1.02 * paperBrightness);
      }
    }
    camera->ParallelProjectionOff();
  }

  // An ambient-scattering mapper's picture of `volumeProperty` against the CPU reference's (the
  // paper's or the extended model), both with the radius `radius`, the step `step`, g
  // `anisotropy`, albedo 0.9, the 256 light grid and the 64 diffusion grid, no emission: the
  // PSNR, after checking that the picture is not black.
  auto againstReference = [&](vtkAmbientScatteringVolumeMapper* s,
                            vtkVolumeProperty* volumeProperty,
                            bool extended,
                            double radius,
                            double step,
                            double anisotropy)
  {
    s->SetAnisotropy(anisotropy);
    s->SetAmbientRadius(radius);
    s->SetSampleDistance(step);
    s->SetLightVolumeMaximumDimension(256);
    s->SetDiffusionVolumeMaximumDimension(64);
    s->SetEmissionWeight(0.0);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(s);
    volume->SetProperty(volumeProperty);
    renderer->AddVolume(volume);
    window->Render();
    auto gpu = Grab(window);
    renderer->RemoveVolume(volume);
    vtkNew<vtkVolumeReferenceRenderer> reference;
    reference->SetInputData(volumeData);
    reference->SetVolumeProperty(volumeProperty);
    reference->SetRenderer(renderer);
    reference->SetImageSize(size, size);
    reference->SetSampleDistance(step);
    reference->SetRenderModeToAmbientScattering();
    reference->SetScatteringModel(extended ? vtkVolumeReferenceRenderer::ExtendedModel
                                           : vtkVolumeReferenceRenderer::PaperModel);
    reference->SetAmbientRadius(radius);
    reference->SetLightVolumeMaximumDimension(256);
    reference->SetDiffusionVolumeMaximumDimension(64);
    reference->SetAnisotropy(anisotropy);
    reference->SetAlbedo(0.9);
    reference->Update();
    AVS_CHECK(Brightness(gpu) > 1000.0);
    return Psnr(gpu, reference->GetOutput());
  };

  // The extended model with lights of one colour, whose fluence the rays read beside the lights
  // and the averaged extinction as one number per point (vtkAVSLightVolumePass::CopyFluence):
  // two white lights (slots 2 and 3 of the first light texture), then one tinted light alone
  // (slots 1 and 2), each with the ring and g = 0.4 (phi's derivative along the ray), g = 0, and
  // the explicit look-ahead. Measured on llvmpipe: 67-72 dB; with the fluence halved in the
  // lights' read 33-40 dB in the first two cases, halved in the explicit look-ahead's 40-44 dB
  // in the third.
  {
    const double tint[2][3] = { { 1.0, 1.0, 1.0 }, { 0.9, 0.7, 1.0 } };
    for (int lights = 2; lights >= 1; --lights)
    {
      renderer->RemoveAllLights();
      AddTestLights(renderer);
      vtkLight* lamp = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(1));
      vtkLight* sun = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
      if (!lamp || !sun)
      {
        AVS_CHECK(false);
        break;
      }
      lamp->SetDiffuseColor(tint[0][0], tint[0][1], tint[0][2]);
      if (lights == 1)
      {
        renderer->RemoveLight(lamp);
        sun->SetDiffuseColor(tint[1][0], tint[1][1], tint[1][2]);
      }
      PlaceTestCamera(renderer->GetActiveCamera());
      for (int c = 0; c < 3; ++c)
      {
        const double anisotropy = c == 1 ? 0.0 : 0.4;
        const double radius = c == 2 ? 1.2 : 0.08, step = c == 2 ? 0.004 : sampleDistance;
        const double psnr = againstReference(asx, property, true, radius, step, anisotropy);
        std::cout << "asx_one_colour_" << lights << "_lights_case" << c << ": PSNR " << psnr
                  << " dB\n";
        AVS_CHECK(psnr >= 55.0);
      }
    }
  }

  // An ambient radius below the ray step (a look-ahead of 0 steps), both models: the rays must
  // end where the transmittance falls below the threshold, as the reference's do (taking two
  // samples per iteration, the GPU once went on past an odd sample that ended its ray, with
  // stale transmittances, and lit what lies behind).
  {
    renderer->RemoveAllLights();
    AddTestLights(renderer);
    PlaceTestCamera(renderer->GetActiveCamera());
    // Dense enough that most rays end in the shell, with more of it behind.
    vtkNew<vtkVolumeProperty> dense;
    dense->DeepCopy(property);
    dense->SetScalarOpacityUnitDistance(0.005);
    for (int m = 2; m < 4; ++m)
    {
      const double psnr = againstReference(
        scattering[m - 2], dense, m == 3, 0.5 * sampleDistance, sampleDistance, 0.4);
      std::cout << names[m] << "_small_radius: PSNR " << psnr << " dB\n";
      AVS_CHECK(psnr >= 55.0);
    }
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
