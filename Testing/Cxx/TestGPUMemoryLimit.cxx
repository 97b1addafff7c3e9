// A volume the GPU cannot hold: one clear error, nothing of it left on the GPU, and the next,
// smaller volume renders. On a software rasterizer the GPU memory is the process's, so the
// limit is set through AVS_GPU_MEMORY_LIMIT_MB (vtkAVSTextureMemory), which the mappers obey
// as they obey a GPU that reports GL_OUT_OF_MEMORY.
//
// For each mapper, with a limit of 6 MiB: a 128^3 volume (8 MiB of scalars: refused at the
// first texture), a 100^3 volume (4 MiB of scalars fit, its second texture does not, for the
// ambient-occlusion and ambient-scattering mappers; emission-absorption fits it), then a 32^3
// volume, which must render. The mask counts too: EA's 100^3 volume with a mask of its size is
// refused. The window's GL objects are counted by name after each frame. Then ambient
// scattering's two models under SetMaximumGPUMemory: the extended model's fluence counts.
#include "MapperTestScene.h"
#include "SoakCensus.h"
#include "TestErrorObserver.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"

#include "vtkFloatArray.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
vtkSmartPointer<vtkImageData> Cube(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1));
  image->SetOrigin(-1, -1, -1);
  vtkNew<vtkFloatArray> v;
  v->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = 2.0 * i / (n - 1) - 1, y = 2.0 * j / (n - 1) - 1,
                     z = 2.0 * k / (n - 1) - 1;
        v->SetValue(
          id++, static_cast<float>(std::max(0.0, 1.0 - std::sqrt(x * x + y * y + z * z))));
      }
  image->GetPointData()->SetScalars(v);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  auto p = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> c;
  c->AddRGBPoint(0, 1, 0.8, 0.6);
  c->AddRGBPoint(1, 1, 1, 1);
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(0, 0);
  o->AddPoint(1, 0.5);
  p->SetColor(c);
  p->SetScalarOpacity(o);
  p->SetScalarOpacityUnitDistance(0.1);
  p->SetInterpolationTypeToLinear();
  return p;
}

int failures = 0;
void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::printf("FAIL: %s\n", what.c_str());
    ++failures;
  }
}
} // namespace

int main(int, char*[])
{
  setenv("AVS_GPU_MEMORY_LIMIT_MB", "6", 1);
  const auto big = Cube(128), middle = Cube(100), small = Cube(32);
  for (int kind = 0; kind < 3; ++kind)
  {
    vtkSmartPointer<vtkAVSVolumeMapper> mapper;
    const char* name = kind == 0 ? "EA" : (kind == 1 ? "AO" : "AS");
    if (kind == 0)
      mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
    else if (kind == 1)
      mapper = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
    else
      mapper = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<vtkRenderWindow> window;
    PrepareTestWindow(window, 96, 96);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    renderer->GetActiveCamera()->SetPosition(0, 0, 6);
    window->Render(); // the window's own objects exist before the volume comes
    const GLCensus empty = CountGLObjects(window);

    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(Property());
    renderer->AddVolume(volume);
    for (vtkImageData* image : { big.Get(), middle.Get() })
    {
      const int before = errors->Errors;
      mapper->SetInputData(image);
      window->Render();
      const GLCensus after = CountGLObjects(window);
      const std::string what =
        std::string(name) + ", " + std::to_string(image->GetDimensions()[0]) + "^3";
      if (image == big.Get() || kind != 0)
      {
        Check(errors->Errors == before + 1,
          what + ": one error, got " + std::to_string(errors->Errors - before));
        Check(errors->LastError.find("out of GPU memory") != std::string::npos &&
            errors->LastError.find("AVS_GPU_MEMORY_LIMIT_MB") != std::string::npos,
          what + ": the error says what is wrong: " + errors->LastError);
        Check(mapper->GetNumberOfRenderedFrames() == 0, what + ": nothing drawn");
        Check(after.Textures <= empty.Textures,
          what + ": its textures released (" + std::to_string(after.Textures) + " textures, " +
            std::to_string(empty.Textures) + " before the volume)");
      }
      std::printf("%s %d^3: %d errors, %d frames, %s\n",
        name,
        image->GetDimensions()[0],
        errors->Errors - before,
        mapper->GetNumberOfRenderedFrames(),
        after.ToString().c_str());
    }
    if (kind == 0)
    {
      // The 100^3 volume fits EA alone; with a mask (another 4 MiB texture) it does not.
      const int before = errors->Errors;
      mapper->SetInputData(middle);
      mapper->SetMaskInput(middle);
      window->Render();
      const GLCensus after = CountGLObjects(window);
      Check(errors->Errors == before + 1,
        "EA, 100^3 with a mask: one error, got " + std::to_string(errors->Errors - before));
      Check(errors->LastError.find("AVS_GPU_MEMORY_LIMIT_MB") != std::string::npos,
        "EA, 100^3 with a mask: the error says what is wrong: " + errors->LastError);
      Check(after.Textures <= empty.Textures, "EA, 100^3 with a mask: its textures released");
      std::printf(
        "EA 100^3 with a mask: %d errors, %s\n", errors->Errors - before, after.ToString().c_str());
      mapper->SetMaskInput(nullptr);
    }
    const int before = errors->Errors, frames = mapper->GetNumberOfRenderedFrames();
    mapper->SetInputData(small);
    window->Render();
    Check(
      errors->Errors == before, std::string(name) + ", 32^3: no error (" + errors->LastError + ")");
    Check(
      mapper->GetNumberOfRenderedFrames() == frames + 1, std::string(name) + ", 32^3: rendered");
    Check(Brightness(Grab(window)) > 0.0, std::string(name) + ", 32^3: a picture");
  }
  unsetenv("AVS_GPU_MEMORY_LIMIT_MB");

  // The extended model's fluence textures count in the budget (SetMaximumGPUMemory) too: with a
  // budget that the paper's model fits at its peak and the extended model does not once its
  // fluence is added, the paper's renders and the extended model gives one clear error.
  {
    vtkNew<vtkRenderWindow> window;
    PrepareTestWindow(window, 96, 96);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    renderer->GetActiveCamera()->SetPosition(0, 0, 6);
    // Renders the 100^3 volume with the paper's (0) or the extended (1) model under `budget`
    // MiB (0: none), errors to `errors`; its mapper and its volume, still in the renderer (removing
    // it releases the mapper's textures).
    struct Rendered
    {
      vtkSmartPointer<vtkAmbientScatteringVolumeMapper> Mapper;
      vtkSmartPointer<vtkVolume> Volume;
    };
    auto renderModel = [&](int model, int budget, vtkCommand* errors)
    {
      auto mapper = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
      if (errors)
        mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      if (model == 0)
        mapper->SetScatteringModelToPaper();
      else
        mapper->SetScatteringModelToExtended();
      mapper->SetMaximumGPUMemory(budget);
      mapper->SetInputData(middle);
      auto volume = vtkSmartPointer<vtkVolume>::New();
      volume->SetMapper(mapper);
      volume->SetProperty(Property());
      renderer->AddVolume(volume);
      window->Render();
      return Rendered{ mapper, volume };
    };
    const Rendered paper = renderModel(0, 0, nullptr);
    const double paperPeak = paper.Mapper->GetGPUMemoryPeakBytes();
    renderer->RemoveVolume(paper.Volume);
    paper.Mapper->ReleaseGraphicsResources(window);
    const Rendered extended = renderModel(1, 0, nullptr);
    const double extendedHeld = extended.Mapper->GetGPUMemoryBytes();
    renderer->RemoveVolume(extended.Volume);
    extended.Mapper->ReleaseGraphicsResources(window);
    const int budget = static_cast<int>(std::ceil(paperPeak / (1024.0 * 1024.0)));
    std::printf("AS 100^3: the paper's peak %.1f MiB, the extended model holds %.1f MiB; "
                "budget %d MiB\n",
      paperPeak / (1024.0 * 1024.0),
      extendedHeld / (1024.0 * 1024.0),
      budget);
    Check(extendedHeld > (budget + 1) * 1024.0 * 1024.0,
      "the extended model holds more than the paper's peak (its fluence)");
    for (int model = 0; model < 2; ++model)
    {
      vtkNew<TestErrorObserver> errors;
      const Rendered rendered = renderModel(model, budget, errors);
      vtkAmbientScatteringVolumeMapper* mapper = rendered.Mapper;
      const std::string what = std::string(model == 0 ? "paper's" : "extended") + " model within " +
        std::to_string(budget) + " MiB";
      if (model == 0)
      {
        Check(errors->Errors == 0, what + ": no error (" + errors->LastError + ")");
        Check(mapper->GetNumberOfRenderedFrames() == 1, what + ": rendered");
      }
      else
      {
        Check(errors->Errors == 1, what + ": one error, got " + std::to_string(errors->Errors));
        Check(errors->LastError.find("out of GPU memory") != std::string::npos &&
            errors->LastError.find("SetMaximumGPUMemory") != std::string::npos,
          what + ": the error says what is wrong: " + errors->LastError);
        Check(mapper->GetNumberOfRenderedFrames() == 0, what + ": nothing drawn");
        Check(mapper->GetGPUMemoryBytes() == 0.0, what + ": its textures released");
      }
      std::printf("%s: %d errors (%s), %d frames\n",
        what.c_str(),
        errors->Errors,
        errors->LastError.c_str(),
        mapper->GetNumberOfRenderedFrames());
      renderer->RemoveVolume(rendered.Volume);
    }
  }
  std::printf("%s\n", failures ? "FAILED" : "PASSED");
  return failures ? 1 : 0;
}
