// avs-demo: renders the built-in scene (or a volume file) with emission–absorption, ambient
// occlusion and ambient scattering, and writes each picture and the three side by side as PNG.
//
//   avs-demo [--size N] [--voxels N] [--light-grid N] [--output DIR] [--reference] [FILE]
//
// The renderers are the GPU mappers (vtkEmissionAbsorptionVolumeMapper,
// vtkAmbientOcclusionVolumeMapper, vtkAmbientScatteringVolumeMapper) in one window with three
// viewports; --reference renders with the CPU reference ray caster instead.
#include "DemoScene.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeReferenceRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>

namespace
{
class ProgressPrinter : public vtkCommand
{
public:
  static ProgressPrinter* New() { return new ProgressPrinter; }
  std::string Label;
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    const double v = *static_cast<double*>(data);
    std::fprintf(stderr, "\r  %-20s %3.0f%%", this->Label.c_str(), 100.0 * v);
    if (v >= 1.0)
    {
      std::fprintf(stderr, "\n");
    }
    std::fflush(stderr);
  }
};

void Usage()
{
  std::printf(
    "Usage: avs-demo [--size N] [--voxels N] [--light-grid N] [--output DIR] [--reference] "
    "[FILE]\n"
    "\n"
    "Renders the built-in procedural nebula (or FILE: .vti, .vtk, .slc, .nhdr, .nrrd, .vdb)\n"
    "with emission-absorption, ambient occlusion and ambient scattering using the GPU\n"
    "mappers, and writes ea.png, ao.png, as.png and the three side by side\n"
    "(side_by_side.png) into DIR.\n"
    "\n"
    "  --size N     picture size in pixels, per mapper [512]\n"
    "  --voxels N   voxels per axis of the built-in nebula [128]\n"
    "  --light-grid N  ambient scattering's LightVolumeMaximumDimension [the mapper's default]\n"
    "  --output DIR output folder [build/demo]\n"
    "  --reference  render with the CPU reference ray caster instead\n");
}

// The three GPU mappers in one window with three viewports sharing the camera and the lights.
int RenderWithMappers(DemoScene& scene, int size, int lightGrid, const std::string& output)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(3 * size, size);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  as->SetAnisotropy(0.3); // the medium scatters a little forwards; the rest: the defaults
  if (lightGrid > 0)
  {
    as->SetLightVolumeMaximumDimension(lightGrid);
  }
  vtkAVSVolumeMapper* mappers[3] = { ea, ao, as };
  const char* names[3] = { "ea", "ao", "as" };
  const char* labels[3] = { "emission-absorption", "ambient occlusion", "ambient scattering" };
  vtkRenderer* renderers[3];
  for (int m = 0; m < 3; ++m)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(m / 3.0, 0.0, (m + 1) / 3.0, 1.0);
    renderer->SetActiveCamera(scene.Renderer->GetActiveCamera());
    vtkLightCollection* lights = scene.Renderer->GetLights();
    lights->InitTraversal();
    while (vtkLight* light = lights->GetNextItem())
    {
      renderer->AddLight(light);
    }
    mappers[m]->SetInputData(scene.Volume);
    vtkNew<ProgressPrinter> progress;
    progress->Label = labels[m];
    mappers[m]->AddObserver(vtkCommand::ProgressEvent, progress);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mappers[m]);
    volume->SetProperty(scene.Property);
    renderer->AddVolume(volume);
    window->AddRenderer(renderer);
    renderers[m] = renderer;
  }
  renderers[0]->ResetCameraClippingRange();
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (int m = 0; m < 3; ++m)
  {
    if (mappers[m]->GetNumberOfRenderedFrames() != 1)
    {
      std::fprintf(stderr, "avs-demo: the %s picture could not be rendered\n", labels[m]);
      return 1;
    }
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  const std::string path = output + "/side_by_side.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  for (int m = 0; m < 3; ++m)
  {
    vtkNew<vtkImageData> alone;
    alone->SetExtent(0, size - 1, 0, size - 1, 0, 0);
    alone->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    vtkImageData* all = grab->GetOutput();
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        for (int c = 0; c < 3; ++c)
          alone->SetScalarComponentFromDouble(
            x, y, 0, c, all->GetScalarComponentAsDouble(m * size + x, y, 0, c));
    const std::string one = output + "/" + names[m] + ".png";
    vtkNew<vtkPNGWriter> w;
    w->SetInputData(alone);
    w->SetFileName(one.c_str());
    w->Write();
    std::printf("%s (%s, GPU)\n", one.c_str(), labels[m]);
  }
  std::printf("%s (EA | AO | ambient scattering, GPU mappers, first frame %.1f s with "
              "precomputation)\n",
    path.c_str(),
    seconds);
  return 0;
}

// The CPU reference ray caster, one picture per model.
int RenderWithReference(DemoScene& scene, int size, int lightGrid, const std::string& output)
{
  struct Mode
  {
    int Value;
    const char* Name;
    const char* Label;
  };
  const Mode modes[] = {
    { vtkVolumeReferenceRenderer::EMISSION_ABSORPTION, "ea", "emission-absorption" },
    { vtkVolumeReferenceRenderer::AMBIENT_OCCLUSION, "ao", "ambient occlusion" },
    { vtkVolumeReferenceRenderer::AMBIENT_SCATTERING, "as", "ambient scattering" }
  };
  vtkNew<vtkImageAppend> sideBySide;
  sideBySide->SetAppendAxis(0);
  for (const Mode& mode : modes)
  {
    vtkNew<vtkVolumeReferenceRenderer> renderer;
    renderer->SetInputData(scene.Volume);
    renderer->SetVolumeProperty(scene.Property);
    renderer->SetRenderer(scene.Renderer);
    renderer->SetRenderMode(mode.Value);
    renderer->SetImageSize(size, size);
    renderer->SetAnisotropy(0.3);
    if (lightGrid > 0)
    {
      renderer->SetLightVolumeMaximumDimension(lightGrid);
    }
    vtkNew<ProgressPrinter> progress;
    progress->Label = mode.Label;
    renderer->AddObserver(vtkCommand::ProgressEvent, progress);
    const auto start = std::chrono::steady_clock::now();
    renderer->Update();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    vtkImageData* picture = renderer->GetOutput();
    if (picture->GetNumberOfPoints() == 0)
    {
      std::fprintf(stderr, "avs-demo: the %s picture could not be rendered\n", mode.Label);
      return 1;
    }
    vtkNew<vtkImageData> copy;
    copy->DeepCopy(picture);
    sideBySide->AddInputData(copy);
    const std::string path = output + "/" + mode.Name + ".png";
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(copy);
    writer->SetFileName(path.c_str());
    writer->Write();
    std::printf("%s (%s, CPU reference, %.1f s)\n", path.c_str(), mode.Label, seconds);
  }
  sideBySide->Update();
  const std::string path = output + "/side_by_side.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(sideBySide->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  std::printf("%s (EA | AO | ambient scattering, CPU reference)\n", path.c_str());
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  int size = 512;
  int voxels = 128;
  int lightGrid = 0;
  std::string output = "build/demo";
  std::string file;
  bool reference = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      Usage();
      return 0;
    }
    if (arg == "--reference")
    {
      reference = true;
      continue;
    }
    if ((arg == "--size" || arg == "--voxels" || arg == "--light-grid" || arg == "--output") &&
      i + 1 < argc)
    {
      const std::string value = argv[++i];
      if (arg == "--output")
      {
        output = value;
      }
      else
      {
        const int v = std::atoi(value.c_str());
        if (v < (arg == "--light-grid" ? 2 : 8) || v > 4096)
        {
          std::fprintf(stderr,
            "avs-demo: %s must be between %d and 4096\n",
            arg.c_str(),
            arg == "--light-grid" ? 2 : 8);
          return 2;
        }
        (arg == "--size" ? size : (arg == "--voxels" ? voxels : lightGrid)) = v;
      }
      continue;
    }
    if (arg.rfind("--", 0) == 0)
    {
      std::fprintf(stderr, "avs-demo: unknown option %s\n", arg.c_str());
      return 2;
    }
    file = arg;
  }
  mkdir(output.c_str(), 0755);

  DemoScene scene;
  if (file.empty())
  {
    scene = MakeDemoScene(voxels);
  }
  else
  {
    std::string error;
    if (!LoadDemoScene(file, scene, error))
    {
      std::fprintf(stderr, "avs-demo: %s\n", error.c_str());
      return 1;
    }
  }

  return reference ? RenderWithReference(scene, size, lightGrid, output)
                   : RenderWithMappers(scene, size, lightGrid, output);
}
