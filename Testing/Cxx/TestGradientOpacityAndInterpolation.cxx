// Gradient opacity, interpolation type and shading flags. EA against
// vtkGPUVolumeRayCastMapper (>= 35 dB) with a gradient opacity (SetGradientOpacity), with it
// disabled (DisableGradientOpacityOn: the picture without it), and with nearest interpolation
// (SetInterpolationTypeToNearest) on point and cell data; each picture differs from the one
// with the feature ignored. AO and AS with both against the CPU reference (>= 35 dB). The
// shading flags change no picture of EA and AO, and a warning says so once; they shade surfaces
// in ambient scattering's picture (without a warning).
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include <cmath>
#include <iostream>

namespace
{
vtkSmartPointer<vtkVolumeProperty> CopyProperty(vtkVolumeProperty* p)
{
  auto copy = vtkSmartPointer<vtkVolumeProperty>::New();
  copy->DeepCopy(p);
  return copy;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  const double step = 0.01;

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  auto data = MakeTestVolume();
  auto plain = MakeTestProperty();
  plain->ShadeOff();
  // Gradient opacity: transparent where the field is flat (the inside of the core and of the
  // lumps), opaque at its edges. VTK's gradient magnitude is in scalar units per mean spacing.
  auto gradient = CopyProperty(plain);
  vtkNew<vtkPiecewiseFunction> go;
  go->AddPoint(0, 0.0);
  go->AddPoint(40, 0.1);
  go->AddPoint(120, 1.0);
  gradient->SetGradientOpacity(go);
  auto disabled = CopyProperty(gradient);
  disabled->DisableGradientOpacityOn();
  // Nearest interpolation on a coarse volume of voxel-scale detail, where it shows.
  auto detail = [](double x, double y, double z) -> std::array<double, 4>
  {
    return {
      450.0 + 450.0 * std::sin(17 * x + 3) * std::sin(19 * y + 1) * std::sin(23 * z + 2), 0, 0, 0
    };
  };
  auto coarse = MakeTestImage(12);
  coarse->SetSpacing(0.15, 0.15, 0.18);
  AddArray(coarse, "points", 1, false, detail);
  coarse->GetPointData()->SetActiveScalars("points");
  auto coarseCells = MakeTestImage(13);
  coarseCells->SetSpacing(0.15, 0.15, 0.18);
  AddArray(coarseCells, "cells", 1, true, detail);
  coarseCells->GetCellData()->SetActiveScalars("cells");
  auto nearest = CopyProperty(plain);
  nearest->SetInterpolationTypeToNearest();

  struct Case
  {
    const char* Tag;
    vtkImageData* Data;
    vtkVolumeProperty* Property;
    vtkVolumeProperty* Ignored; // the property whose picture this one must differ from
  };
  const Case cases[] = {
    { "gradient_opacity", data, gradient, plain },
    { "gradient_opacity_disabled", data, disabled, nullptr },
    { "nearest", coarse, nearest, plain },
    { "nearest_cells", coarseCells, nearest, plain },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkGPUVolumeRayCastMapper> reference;
    ConfigureVTKMapper(reference, step);
    reference->SetInputData(c.Data);
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    ea->SetInputData(c.Data);
    ea->SetSampleDistance(step);
    ea->UseJitteringOff();
    vtkNew<TestErrorObserver> errors;
    ea->AddObserver(vtkCommand::ErrorEvent, errors);
    const std::string tag = c.Tag;
    auto vtkPicture = RenderVolume(window, renderer, reference, c.Property, dir, tag + "_vtk");
    auto picture = RenderVolume(window, renderer, ea, c.Property, dir, tag + "_ea");
    const double psnr = Psnr(vtkPicture, picture);
    std::cout << tag << ": EA against VTK " << psnr << " dB";
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(Brightness(picture) > 1000.0);
    AVS_CHECK(psnr >= 35.0);
    if (c.Ignored)
    {
      auto ignored = RenderVolume(window, renderer, ea, c.Ignored);
      const double other = Psnr(ignored, picture);
      std::cout << ", against the picture without it " << other << " dB";
      AVS_CHECK(other < 30.0);
    }
    else
    {
      auto without = RenderVolume(window, renderer, ea, plain);
      const double same = Psnr(without, picture);
      std::cout << ", against the picture without gradient opacity " << same << " dB";
      AVS_CHECK(same > 80.0);
    }
    std::cout << "\n";
  }

  // AO and AS against the CPU reference.
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  as->SetAnisotropy(0.4);
  vtkAVSVolumeMapper* mappers[2] = { ao, as };
  for (int m = 0; m < 2; ++m)
  {
    for (const Case& c : { cases[0], cases[2], cases[3] })
    {
      vtkAVSVolumeMapper* mapper = mappers[m];
      vtkNew<TestErrorObserver> errors;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->SetInputData(c.Data);
      mapper->SetSampleDistance(0.02);
      mapper->UseJitteringOff();
      const std::string tag = std::string(m ? "as_" : "ao_") + c.Tag;
      auto picture = RenderVolume(window, renderer, mapper, c.Property, dir, tag);
      auto ignored = RenderVolume(window, renderer, mapper, c.Ignored);
      vtkNew<vtkVolumeReferenceRenderer> cpu;
      cpu->SetInputData(c.Data);
      cpu->SetVolumeProperty(c.Property);
      cpu->SetRenderer(renderer);
      cpu->SetImageSize(size, size);
      cpu->SetSampleDistance(0.02);
      cpu->SetRenderMode(m ? vtkVolumeReferenceRenderer::AMBIENT_SCATTERING
                           : vtkVolumeReferenceRenderer::AMBIENT_OCCLUSION);
      cpu->SetOcclusionRadius(0.15);
      cpu->SetAmbientRadius(0.08);
      cpu->SetAnisotropy(0.4);
      cpu->Update();
      const double psnr = Psnr(picture, cpu->GetOutput());
      const double other = Psnr(picture, ignored);
      std::cout << tag << ": against the CPU reference " << psnr << " dB, against the picture "
                << "without it " << other << " dB\n";
      AVS_CHECK(errors->Errors == 0);
      // Measured 59.5-71 dB against the CPU reference (llvmpipe), 21-38 dB against the picture
      // without the setting: a GPU that ignored the setting would sit at the latter.
      AVS_CHECK(psnr >= 55.0);
      AVS_CHECK(other < 45.0);
      mapper->RemoveObserver(errors);
    }
  }

  // Shading flags: EA and AO change no picture and warn once; ambient scattering shades surfaces
  // inside the medium with them (TestSurfaceShading), without a warning.
  {
    auto shaded = CopyProperty(plain);
    shaded->ShadeOn();
    auto phong = CopyProperty(shaded);
    phong->SetSpecular(0.8);
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea2;
    vtkNew<vtkAmbientOcclusionVolumeMapper> ao2;
    vtkNew<vtkAmbientScatteringVolumeMapper> as2;
    vtkAVSVolumeMapper* all[3] = { ea2, ao2, as2 };
    for (int m = 0; m < 3; ++m)
    {
      vtkAVSVolumeMapper* mapper = all[m];
      mapper->SetInputData(data);
      mapper->UseJitteringOff();
      vtkNew<TestErrorObserver> messages;
      mapper->AddObserver(vtkCommand::WarningEvent, messages);
      auto unshaded = RenderVolume(window, renderer, mapper, plain);
      AVS_CHECK(messages->Warnings == 0);
      auto withShade = RenderVolume(window, renderer, mapper, shaded);
      RenderVolume(window, renderer, mapper, shaded);
      const int afterShade = messages->Warnings;
      auto withPhong = RenderVolume(window, renderer, mapper, phong);
      const int afterPhong = messages->Warnings;
      std::cout << mapper->GetClassName() << ": warnings after ShadeOn " << afterShade
                << ", after a Phong coefficient " << afterPhong << "; pictures "
                << Psnr(unshaded, withShade) << " / " << Psnr(unshaded, withPhong) << " dB\n";
      if (m < 2)
      {
        AVS_CHECK(Psnr(unshaded, withShade) > 80.0);
        AVS_CHECK(Psnr(unshaded, withPhong) > 80.0);
        AVS_CHECK(afterShade == 1);
        AVS_CHECK(afterPhong == 1);
      }
      else
      {
        AVS_CHECK(Psnr(unshaded, withShade) < 45.0);
        AVS_CHECK(Psnr(withShade, withPhong) < 60.0);
        AVS_CHECK(afterPhong == 0);
      }
      // A second component's flags are read too by EA and AO (for one component ambient
      // scattering reads component 0's, as VTK's mapper does); UseClippedVoxelIntensity is not
      // used: a warning each.
      auto second = CopyProperty(plain);
      second->ShadeOn(1);
      second->SetSpecular(1, 0.8);
      RenderVolume(window, renderer, mapper, plain);
      const int beforeSecond = messages->Warnings;
      RenderVolume(window, renderer, mapper, second);
      const int secondWarnings = m < 2 ? 1 : 0;
      AVS_CHECK(messages->Warnings == beforeSecond + secondWarnings);
      auto clipped = CopyProperty(plain);
      clipped->UseClippedVoxelIntensityOn();
      RenderVolume(window, renderer, mapper, clipped);
      AVS_CHECK(messages->Warnings == beforeSecond + secondWarnings + 1);
      AVS_CHECK(messages->LastWarning.find("UseClippedVoxelIntensity") != std::string::npos);
    }
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
