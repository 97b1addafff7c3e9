#include "SoakTimeSeries.h"

#include "SoakCensus.h"

#include "ProceduralVolume.h"
#include "vtkAVSVolumeMapper.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr int Voxels = 48;               // per axis
constexpr int Pixels = 96;               // per side of each window
constexpr int Checkpoint = 25;           // steps between checkpoints; the first is the reference
constexpr double MemoryTolerance = 32.0; // MiB

struct View
{
  const char* Name;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkAVSVolumeMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
  long Errors = 0;
  GLCensus Reference;              ///< at the first checkpoint
  double GPUBytes = -1.0;          ///< after the first step
  std::vector<unsigned char> Held; ///< the frame a repeated step must give
};

void CountError(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<long*>(clientData);
}

long Rebuilds(vtkAVSVolumeMapper* m)
{
  return m->GetNumberOfDataUploads() + m->GetNumberOfExtinctionRebuilds() +
    m->GetNumberOfLightVolumeRebuilds() + m->GetNumberOfOcclusionRebuilds() +
    m->GetNumberOfDiffusionRebuilds();
}

std::vector<unsigned char> Frame(vtkRenderWindow* window)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, Pixels - 1, Pixels - 1, 0, pixels);
  const unsigned char* p = pixels->GetPointer(0);
  return std::vector<unsigned char>(p, p + pixels->GetNumberOfValues());
}

// The values of step `step`: the nebula moved `step` voxels along x (wrapping round); every
// tenth step instead keeps the step before's values and raises a block of slices.
void Values(const avs::Grid& nebula, int step, float* out)
{
  const int n = Voxels;
  const bool block = step % 10 == 5;
  if (block)
  {
    --step;
  }
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const std::size_t id = (static_cast<std::size_t>(k) * n + j) * n + i;
        out[id] = nebula.Values[(static_cast<std::size_t>(k) * n + j) * n + (i + n - step % n) % n];
      }
  if (block)
  {
    for (int k = 20; k < 28; ++k)
      for (int j = 8; j < 40; ++j)
        for (int i = 8; i < 40; ++i)
        {
          out[(static_cast<std::size_t>(k) * n + j) * n + i] = 0.9f;
        }
  }
}

vtkSmartPointer<vtkImageData> NewImage()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(Voxels, Voxels, Voxels);
  const double h = 2.0 / (Voxels - 1);
  image->SetSpacing(h, h, h);
  image->SetOrigin(-1.0, -1.0, -1.0);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(Voxels) * Voxels * Voxels);
  image->GetPointData()->SetScalars(values);
  return image;
}
// What a new mapper of the view's kind draws from `image` alone, in a window of its own with the
// view's camera and lights.
std::vector<unsigned char> FreshFrame(const View& v, vtkImageData* image)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Pixels, Pixels);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->DeepCopy(v.Renderer->GetActiveCamera());
  vtkLightCollection* lights = v.Renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    renderer->AddLight(light);
  }
  vtkSmartPointer<vtkAVSVolumeMapper> mapper;
  mapper.TakeReference(v.Mapper->NewInstance());
  mapper->SetSampleDistance(v.Mapper->GetSampleDistance());
  mapper->UseJitteringOff();
  mapper->SetInputData(image);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(v.Volume->GetProperty());
  renderer->AddVolume(volume);
  window->Render();
  std::vector<unsigned char> frame = Frame(window);
  renderer->RemoveVolume(volume);
  window->Finalize();
  return frame;
}
} // namespace

bool RunTimeSeriesSoak(int steps, bool addressSanitizer)
{
  steps = std::max(100, steps);
  const avs::Grid nebula = avs::MakeNebula(Voxels);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0.0, 0.3, 0.4, 0.9);
  colour->AddRGBPoint(0.5, 0.9, 0.6, 0.4);
  colour->AddRGBPoint(1.0, 1.0, 0.95, 0.8);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.1, 0.0);
  opacity->AddPoint(0.5, 0.3);
  opacity->AddPoint(1.0, 0.8);
  property->SetColor(colour);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.1);
  property->SetInterpolationTypeToLinear();

  std::vector<View> views(3);
  views[0].Name = "ambient scattering";
  views[0].Mapper = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
  views[1].Name = "ambient occlusion";
  views[1].Mapper = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
  views[2].Name = "emission-absorption";
  views[2].Mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
  for (View& v : views)
  {
    v.Window = vtkSmartPointer<vtkRenderWindow>::New();
    v.Window->SetSize(Pixels, Pixels);
    v.Window->SetMultiSamples(0);
    v.Window->OffScreenRenderingOn();
    v.Renderer = vtkSmartPointer<vtkRenderer>::New();
    v.Window->AddRenderer(v.Renderer);
    v.Volume = vtkSmartPointer<vtkVolume>::New();
    v.Volume->SetMapper(v.Mapper);
    v.Volume->SetProperty(property);
    v.Renderer->AddVolume(v.Volume);
    v.Mapper->SetSampleDistance(0.04);
    v.Mapper->UseJitteringOff();
    vtkNew<vtkCallbackCommand> errors;
    errors->SetCallback(CountError);
    errors->SetClientData(&v.Errors);
    v.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkCamera* camera = v.Renderer->GetActiveCamera();
    camera->SetPosition(0.6, 0.8, 4.5);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
  }
  vtkNew<vtkLight> sun, lamp;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-1, 1, 0.5);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetPositional(false);
  lamp->SetLightTypeToSceneLight();
  lamp->SetPosition(0, 0, 0);
  lamp->SetFocalPoint(0, 0, -1);
  lamp->SetPositional(true);
  lamp->SetConeAngle(180);
  lamp->SetIntensity(0.6);
  views[0].Renderer->AddLight(sun);
  views[0].Renderer->AddLight(lamp);

  bool ok = true;
  auto fail = [&ok](const std::string& why)
  {
    std::printf("FAIL %s\n", why.c_str());
    ok = false;
  };
  vtkSmartPointer<vtkImageData> image = NewImage();
  int shown = 0; // the step whose values are shown
  double earlyPeak = 0.0, latePeak = 0.0;
  for (int step = 0; step < steps && ok; ++step)
  {
    // Five steps of each fifty repeat the step before them.
    const bool repeat = step % 50 >= 45;
    if (repeat)
    {
      image = NewImage();
      Values(nebula,
        shown,
        static_cast<vtkFloatArray*>(image->GetPointData()->GetScalars())->GetPointer(0));
    }
    else
    {
      shown = step;
      if (step % 2 == 0)
      {
        image = NewImage(); // as a reader: a new image
      }
      vtkDataArray* values = image->GetPointData()->GetScalars();
      Values(nebula, shown, static_cast<vtkFloatArray*>(values)->GetPointer(0));
      values->Modified(); // as a source: the values rewritten
    }
    for (View& v : views)
    {
      const long before = Rebuilds(v.Mapper);
      const int uploads = v.Mapper->GetNumberOfDataUploads();
      const long errors = v.Errors;
      v.Mapper->SetInputData(image);
      v.Renderer->ResetCameraClippingRange();
      v.Window->Render();
      const std::string at = std::string(v.Name) + ", step " + std::to_string(step + 1);
      if (v.Errors != errors)
      {
        fail(at + ": an error");
      }
      if (repeat)
      {
        if (Rebuilds(v.Mapper) != before)
        {
          fail(at + ": a repeated step uploaded or rebuilt something");
        }
        if (Frame(v.Window) != v.Held)
        {
          fail(at + ": a repeated step gave another frame");
        }
      }
      else
      {
        if (v.Mapper->GetNumberOfDataUploads() != uploads + 1)
        {
          fail(at + ": new values were not uploaded");
        }
        const double written = v.Mapper->GetLastDataUploadFraction();
        if (step % 10 == 5 && (written > 0.5 || written <= 0.0))
        {
          fail(at + ": the change of a block of slices wrote " + std::to_string(written * 100.0) +
            " % of the voxels");
        }
        if (step % 50 == 44)
        {
          v.Held = Frame(v.Window);
        }
      }
      if (step == 0)
      {
        v.GPUBytes = v.Mapper->GetGPUMemoryBytes();
      }
      else if (v.Mapper->GetGPUMemoryBytes() != v.GPUBytes)
      {
        fail(at + ": GPU memory " + std::to_string(v.Mapper->GetGPUMemoryBytes()) +
          " bytes, after the first step " + std::to_string(v.GPUBytes));
      }
    }
    const double resident = ResidentMegabytes();
    (step < 100 ? earlyPeak : latePeak) = std::max(step < 100 ? earlyPeak : latePeak, resident);
    if ((step + 1) % Checkpoint == 0)
    {
      for (View& v : views)
      {
        // The kept mapper draws what a new one draws from this step alone.
        if (FreshFrame(v, image) != Frame(v.Window))
        {
          fail(std::string(v.Name) + ", step " + std::to_string(step + 1) +
            ": the frame differs from a new mapper's");
        }
        const GLCensus census = CountGLObjects(v.Window);
        if (step + 1 == Checkpoint)
        {
          v.Reference = census;
        }
        else if (!census.NotAbove(v.Reference))
        {
          fail(std::string(v.Name) + ", step " + std::to_string(step + 1) + ": GL objects " +
            census.ToString() + ", more than at step " + std::to_string(Checkpoint) + "'s " +
            v.Reference.ToString());
        }
      }
      std::printf("step %d: %.0f MiB resident, GPU memory %.1f / %.1f / %.1f MiB\n",
        step + 1,
        resident,
        views[0].Mapper->GetGPUMemoryBytes() / 1048576.0,
        views[1].Mapper->GetGPUMemoryBytes() / 1048576.0,
        views[2].Mapper->GetGPUMemoryBytes() / 1048576.0);
      std::fflush(stdout);
    }
  }
  if (ok && addressSanitizer)
  {
    std::printf("resident memory not compared under AddressSanitizer (its quarantine keeps freed "
                "memory; LeakSanitizer checks for leaks at exit)\n");
  }
  else if (ok && latePeak > earlyPeak + MemoryTolerance)
  {
    fail("resident memory peaked at " + std::to_string(latePeak) + " MiB after step 100, " +
      std::to_string(earlyPeak) + " MiB before");
  }
  for (const View& v : views)
  {
    std::printf("%s: %d data uploads, %d frames\n",
      v.Name,
      v.Mapper->GetNumberOfDataUploads(),
      v.Mapper->GetNumberOfRenderedFrames());
  }
  std::printf("%s: %d time steps in 3 windows, resident memory peak %.0f MiB in the first 100 "
              "steps, %.0f MiB after\n",
    ok ? "PASS" : "FAIL",
    steps,
    earlyPeak,
    latePeak);
  return ok;
}
