// Interaction, as vtkGPUVolumeRayCastMapper does it: frames allotted less than a second (the
// interactor's DesiredUpdateRate) cast fewer rays and keep the light volumes of camera-following
// lights; the still frame is exact, rebuilds what became stale and equals a frame rendered
// without any interaction. Also: the reduced picture is the low-resolution picture upscaled
// (rays through the same places), opaque geometry still ends its rays, other viewports,
// AutoAdjustSampleDistances off, LockSampleDistanceToInputSpacing, PrintSelf.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCommand.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGenericRenderWindowInteractor.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLightKit.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>

namespace
{
// vtkRenderWindowInteractor's still rate, and an interactive rate no frame can meet (so the
// adjustment goes to the maximum whatever the machine).
constexpr double StillRate = 0.0001;
constexpr double FastRate = 10000.0;

// The test scene without the test lights (VTK's headlight).
struct Scene : TestScene
{
  Scene(vtkVolumeMapper* mapper, vtkImageData* data, int size)
    : TestScene(mapper, size, false)
  {
    mapper->SetInputData(data);
  }
};

vtkSmartPointer<vtkLight> Headlight()
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToHeadlight();
  light->SetIntensity(12.0);
  return light;
}

vtkSmartPointer<vtkLight> Sun()
{
  auto sun = vtkSmartPointer<vtkLight>::New();
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-1.0, 1.0, 0.6);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(10.0);
  return sun;
}

/// A light kit whose lights are bright enough for a scattering medium.
void AddLightKit(vtkRenderer* renderer)
{
  vtkNew<vtkLightKit> kit;
  kit->SetKeyLightIntensity(12.0);
  kit->AddLightsToRenderer(renderer);
}

double Channel(vtkImageData* image, int x, int y, int c)
{
  return image->GetPointData()->GetScalars()->GetComponent(
    static_cast<vtkIdType>(y) * image->GetDimensions()[0] + x, c);
}

/// The pixels (px, py) of a full-resolution picture taken at image sample distance `d` (odd,
/// width and height multiples of d) whose centres are the centres of the low-resolution rays
/// (px = d i + (d - 1) / 2), against the low-resolution picture: the largest difference.
int DifferenceAtRays(vtkImageData* full, vtkImageData* low, int d, int offsetX = 0)
{
  const int* n = low->GetDimensions();
  double most = 0.0;
  for (int j = 0; j < n[1]; ++j)
    for (int i = 0; i < n[0]; ++i)
      for (int c = 0; c < 3; ++c)
        most = std::max(most,
          std::abs(Channel(full, offsetX + d * i + (d - 1) / 2, d * j + (d - 1) / 2, c) -
            Channel(low, i, j, c)));
  return static_cast<int>(most);
}

/// The right half of a picture twice as wide as high.
vtkSmartPointer<vtkImageData> RightHalf(vtkImageData* image)
{
  const int* n = image->GetDimensions();
  const int w = n[0] / 2, h = n[1];
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(w, h, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        out->GetPointData()->GetScalars()->SetComponent(
          static_cast<vtkIdType>(y) * w + x, c, Channel(image, w + x, y, c));
  return out;
}

/// An opaque sphere between the test camera and the whole volume, over part of the picture.
vtkSmartPointer<vtkActor> Occluder()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.87, 0.64, 2.29); // 3 units from the camera, towards the focal point
  sphere->SetRadius(0.3);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.3, 0.2);
  return actor;
}
} // namespace

int main(int, char*[])
{
  int failures = 0;
  auto data = MakeTestVolume(32);

  // --- A headlight, through a real interactor: press, drag, release.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    Scene scene(mapper, data, 96);
    scene.Renderer->AddLight(Headlight());
    mapper->SetMaximumImageSampleDistance(4.0f);
    vtkNew<vtkGenericRenderWindowInteractor> interactor; // events from the test alone
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(scene.Window);
    interactor->SetDesiredUpdateRate(FastRate);
    interactor->Initialize(); // renders a still frame
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == 1);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 1);
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 0);
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 1.0f);
    const auto before = Grab(scene.Window);

    interactor->SetEventInformation(48, 48);
    interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
    for (int i = 1; i <= 5; ++i)
    {
      interactor->SetEventInformation(48 + 6 * i, 48 + 2 * i);
      interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
    }
    // Five interactive frames, at the maximum distance, without a light-volume rebuild.
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == 6);
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 5);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 1);
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 4.0f);
    const auto interactive = Grab(scene.Window);
    interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent); // the still frame
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == 7);
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 5);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 2); // the headlight, stale: rebuilt
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 1.0f);
    const auto still = Grab(scene.Window);
    AVS_CHECK(Psnr(before, still) < 40.0); // the camera did turn

    // The still frame is the frame a fresh mapper renders at that camera, bit for bit; the
    // interactive frame (a quarter of the rays each way, an older light volume) is not.
    vtkNew<vtkAmbientScatteringVolumeMapper> fresh;
    Scene reference(fresh, data, 96);
    reference.Renderer->AddLight(Headlight());
    reference.Renderer->GetActiveCamera()->DeepCopy(scene.Renderer->GetActiveCamera());
    const auto expected = reference.Render();
    AVS_CHECK(MaximumDifference(still, expected) == 0);
    AVS_CHECK(Psnr(interactive, expected) < 40.0);
    AVS_CHECK(Psnr(interactive, expected) > 15.0); // the same volume, coarser
    if (MaximumDifference(still, expected) != 0)
    {
      std::cerr << "still vs fresh: PSNR " << Psnr(still, expected) << " dB\n";
    }
  }

  // --- A light kit (five camera-following lights) and a scene light.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    Scene scene(mapper, data, 64);
    AddLightKit(scene.Renderer);
    auto sun = Sun();
    scene.Renderer->AddLight(sun);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 6);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    scene.Window->SetDesiredUpdateRate(FastRate);
    for (int i = 0; i < 4; ++i)
    {
      camera->Azimuth(5.0);
      camera->Elevation(2.0);
      camera->OrthogonalizeViewUp();
      scene.Render();
    }
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 4);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 6);
    AVS_CHECK(mapper->GetLastImageSampleDistance() > 1.0f);
    // A scene light moved during the interaction is rebuilt: it does not follow the camera.
    sun->SetPosition(-1.0, 0.8, 0.9);
    camera->Azimuth(5.0);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 7);
    // So is everything when the transfer function changes.
    scene.Volume->GetProperty()->GetScalarOpacity()->AddPoint(500, 0.3);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 13);
    camera->Azimuth(5.0);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 13);
    // The still frame: exactly the five stale light volumes, not the sun's.
    scene.Window->SetDesiredUpdateRate(StillRate);
    const auto still = scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 18);
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 1.0f);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 18);
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 7);
    // The GL 4.1 variant of this test marches the light volumes on the CPU.
    AVS_CHECK(
      mapper->GetLightVolumesOnGPU() == (std::getenv("AVS_EXPECT_CPU_PRECOMPUTATION") ? 0 : 1));

    vtkNew<vtkAmbientScatteringVolumeMapper> fresh;
    Scene reference(fresh, data, 64);
    AddLightKit(reference.Renderer);
    auto movedSun = Sun();
    movedSun->SetPosition(-1.0, 0.8, 0.9);
    reference.Renderer->AddLight(movedSun);
    reference.Volume->GetProperty()->GetScalarOpacity()->AddPoint(500, 0.3);
    reference.Renderer->GetActiveCamera()->DeepCopy(camera);
    AVS_CHECK(MaximumDifference(still, reference.Render()) == 0);
  }

  // --- The same interaction with AutoAdjustSampleDistances off: every frame exact.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    mapper->AutoAdjustSampleDistancesOff();
    Scene scene(mapper, data, 64);
    scene.Renderer->AddLight(Headlight());
    scene.Render();
    scene.Window->SetDesiredUpdateRate(FastRate);
    scene.Renderer->GetActiveCamera()->Azimuth(10.0);
    const auto frame = scene.Render();
    AVS_CHECK(mapper->GetNumberOfInteractiveFrames() == 0);
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 1.0f);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 2);
    scene.Window->SetDesiredUpdateRate(StillRate);
    AVS_CHECK(MaximumDifference(frame, scene.Render()) == 0);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 2);
  }

  // --- Each mapper at image sample distance 3: the 120^2 picture is the 40^2 picture
  // upscaled (its pixels 3i + 1 are the 40^2 picture's pixels), an opaque sphere in front still
  // ends the rays (inside it the picture is the sphere alone), and it differs from 120^2 rays.
  // The same in the right-hand viewport of a window twice as wide.
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
    vtkNew<vtkAmbientScatteringVolumeMapper> as;
    for (vtkAVSVolumeMapper* mapper : { static_cast<vtkAVSVolumeMapper*>(ea),
           static_cast<vtkAVSVolumeMapper*>(ao),
           static_cast<vtkAVSVolumeMapper*>(as) })
    {
      const std::string name = mapper->GetClassName();
      auto occluder = Occluder();
      auto picture = [&](int size, float distance, bool volume)
      {
        Scene scene(mapper, data, size);
        AddTestLights(scene.Renderer);
        scene.Renderer->AddActor(occluder);
        scene.Volume->SetVisibility(volume);
        mapper->AutoAdjustSampleDistancesOff();
        mapper->SetImageSampleDistance(distance);
        return scene.Render();
      };
      const auto low = picture(40, 1.0f, true);
      const auto sampled = picture(120, 3.0f, true);
      AVS_CHECK(mapper->GetLastImageSampleDistance() == 3.0f);
      const auto full = picture(120, 1.0f, true);
      const auto sphere = picture(120, 1.0f, false);
      const int atRays = DifferenceAtRays(sampled, low, 3);
      AVS_CHECK(atRays <= 1);
      const double psnr = Psnr(sampled, full);
      AVS_CHECK(psnr < 40.0);
      AVS_CHECK(psnr > 20.0);
      // Inside the sphere (its pixels at least 4 pixels from its outline), nothing of the
      // volume behind it.
      int inside = 0, covered = 0;
      for (int y = 4; y < 116; ++y)
        for (int x = 4; x < 116; ++x)
        {
          bool all = true;
          for (int dy = -4; dy <= 4 && all; ++dy)
            for (int dx = -4; dx <= 4 && all; ++dx)
              all = Channel(sphere, x + dx, y + dy, 0) > 0.0;
          if (!all)
            continue;
          ++inside;
          bool same = true;
          for (int c = 0; c < 3; ++c)
            same = same && Channel(sampled, x, y, c) == Channel(sphere, x, y, c);
          covered += same ? 1 : 0;
        }
      AVS_CHECK(inside > 200);
      AVS_CHECK(covered == inside);
      // The right-hand viewport of a 240 x 120 window, the left one empty.
      vtkNew<vtkRenderWindow> window;
      PrepareTestWindow(window, 240, 120);
      vtkNew<vtkRenderer> left, right;
      left->SetViewport(0.0, 0.0, 0.5, 1.0);
      right->SetViewport(0.5, 0.0, 1.0, 1.0);
      window->AddRenderer(left);
      window->AddRenderer(right);
      PlaceTestCamera(right->GetActiveCamera());
      AddTestLights(right);
      right->AddActor(occluder);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(MakeTestProperty());
      right->AddVolume(volume);
      mapper->SetImageSampleDistance(3.0f);
      window->Render();
      const auto wide = Grab(window);
      const int viewport = MaximumDifference(RightHalf(wide), sampled);
      AVS_CHECK(viewport <= 1);
      if (atRays > 1 || !(psnr < 40.0 && psnr > 20.0) || covered != inside || viewport > 1)
      {
        std::cerr << name << ": at the rays " << atRays << ", PSNR against 120^2 rays " << psnr
                  << " dB, inside the sphere " << covered << " of " << inside << ", right viewport "
                  << viewport << "\n";
      }
      mapper->SetImageSampleDistance(1.0f);
      mapper->AutoAdjustSampleDistancesOn();
    }
  }

  // --- Image sample distance 0.5: four rays per pixel, the 60^2 picture is the 120^2 picture
  // averaged over 2 x 2 blocks (the bilinear sample at a pixel's centre, between four rays).
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    mapper->AutoAdjustSampleDistancesOff();
    // Dimmed so that no ray saturates: the offscreen target keeps radiance above 1, which the
    // 8-bit 120^2 picture clamps ray by ray before the means are taken. (Linear on the screen:
    // the shoulder of the tone curve is not linear either.)
    mapper->SetLightScale(0.6);
    mapper->SetAlbedo(0.9);
    ShowLinear(mapper.Get());
    Scene fine(mapper, data, 120);
    AddTestLights(fine.Renderer);
    const auto full = fine.Render();
    Scene coarse(mapper, data, 60);
    AddTestLights(coarse.Renderer);
    mapper->SetImageSampleDistance(0.5f);
    const auto super = coarse.Render();
    double most = 0.0;
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 60; ++x)
        for (int c = 0; c < 3; ++c)
        {
          const double mean = 0.25 *
            (Channel(full, 2 * x, 2 * y, c) + Channel(full, 2 * x + 1, 2 * y, c) +
              Channel(full, 2 * x, 2 * y + 1, c) + Channel(full, 2 * x + 1, 2 * y + 1, c));
          most = std::max(most, std::abs(Channel(super, x, y, c) - mean));
        }
    AVS_CHECK(most <= 1.0);
    mapper->SetImageSampleDistance(1.0f);
    const auto single = coarse.Render();
    AVS_CHECK(MaximumDifference(super, single) > 8); // one ray per pixel is another picture
    if (most > 1.0)
    {
      std::cerr << "distance 0.5 against 2 x 2 means of 120^2 rays: " << most << "\n";
    }
  }

  // --- Interaction reduces the rays of every mapper; the clamps hold.
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
    for (vtkAVSVolumeMapper* mapper :
      { static_cast<vtkAVSVolumeMapper*>(ea), static_cast<vtkAVSVolumeMapper*>(ao) })
    {
      Scene scene(mapper, data, 64);
      mapper->SetMaximumImageSampleDistance(2.5f);
      const auto still = scene.Render();
      scene.Window->SetDesiredUpdateRate(FastRate);
      const auto interactive = scene.Render();
      AVS_CHECK(mapper->GetLastImageSampleDistance() == 2.5f);
      AVS_CHECK(Psnr(still, interactive) < 45.0);
      mapper->SetMinimumImageSampleDistance(2.0f);
      scene.Window->SetDesiredUpdateRate(StillRate);
      scene.Render();
      AVS_CHECK(mapper->GetLastImageSampleDistance() == 2.0f); // still frames at the minimum
      mapper->SetMinimumImageSampleDistance(1.0f);
      AVS_CHECK(MaximumDifference(still, scene.Render()) == 0);
    }
  }

  // --- LockSampleDistanceToInputSpacing: the step of vtkVolumeMapper's formula, whatever
  // SampleDistance says.
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> mapper;
    Scene scene(mapper, data, 64);
    // Spacing (0.05, 0.05, 0.06), 31 cells per axis: half the mean spacing times
    // 0.01 + 0.99 * 31^(3 * 0.333) / 100.
    const double locked =
      (0.05 + 0.05 + 0.06) / 6.0 * (0.01 + 0.99 * std::pow(31.0 * 31.0 * 31.0, 0.333) / 100.0);
    mapper->SetSampleDistance(locked);
    const auto explicitStep = scene.Render();
    mapper->SetSampleDistance(0.1);
    const auto coarse = scene.Render();
    mapper->LockSampleDistanceToInputSpacingOn();
    const auto lockedStep = scene.Render();
    AVS_CHECK(MaximumDifference(lockedStep, explicitStep) == 0);
    AVS_CHECK(Psnr(lockedStep, coarse) < 50.0);
  }

  // --- Defaults, clamps and PrintSelf.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    AVS_CHECK(mapper->GetAutoAdjustSampleDistances() == 1);
    AVS_CHECK(mapper->GetImageSampleDistance() == 1.0f);
    AVS_CHECK(mapper->GetMinimumImageSampleDistance() == 1.0f);
    AVS_CHECK(mapper->GetMaximumImageSampleDistance() == 10.0f);
    AVS_CHECK(mapper->GetLockSampleDistanceToInputSpacing() == 0);
    AVS_CHECK(mapper->GetLastImageSampleDistance() == 1.0f);
    mapper->SetImageSampleDistance(1000.0f);
    AVS_CHECK(mapper->GetImageSampleDistance() == 100.0f);
    mapper->SetMinimumImageSampleDistance(0.0f);
    AVS_CHECK(mapper->GetMinimumImageSampleDistance() == 0.1f);
    std::ostringstream os;
    mapper->Print(os);
    for (const char* name : { "AutoAdjustSampleDistances: On",
           "ImageSampleDistance: 100",
           "MinimumImageSampleDistance: 0.1",
           "MaximumImageSampleDistance: 10",
           "LastImageSampleDistance: 1",
           "LockSampleDistanceToInputSpacing: Off",
           "NumberOfInteractiveFrames: 0" })
    {
      if (os.str().find(name) == std::string::npos)
      {
        std::cerr << "PrintSelf lacks '" << name << "'\n";
        ++failures;
      }
    }
  }

  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
