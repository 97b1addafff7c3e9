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

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>

namespace
{
// Progress lines ("\r  label  50%") on stderr, each ended by a newline before anything else is
// printed: at 100 %, or by EndProgressLine where a computation stops short of it.
bool ProgressLineOpen = false;
std::string ProgressOpenLabel; // the open line's computation
std::string ProgressLastDone;  // the label of the last line ended at 100 %

void EndProgressLine()
{
  if (ProgressLineOpen)
  {
    std::fprintf(stderr, "\n");
    std::fflush(stderr);
    ProgressLineOpen = false;
  }
}

class ProgressPrinter : public vtkCommand
{
public:
  static ProgressPrinter* New() { return new ProgressPrinter; }
  std::string Label;
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    const double v = *static_cast<double*>(data);
    if (v >= 1.0 && !ProgressLineOpen && ProgressLastDone == this->Label)
    {
      return; // already reported done
    }
    if (ProgressLineOpen && this->Label != ProgressOpenLabel)
    {
      EndProgressLine(); // another computation's line, stopped short of 100 %
    }
    std::fprintf(stderr, "\r  %-20s %3.0f%%", this->Label.c_str(), 100.0 * v);
    ProgressLineOpen = true;
    ProgressOpenLabel = this->Label;
    if (v >= 1.0)
    {
      EndProgressLine();
      ProgressLastDone = this->Label;
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
    "(side_by_side.png) into DIR. A file is framed whole and lit by a key and a fill light\n"
    "from outside; ambient scattering's exposure is metered against the emission-absorption\n"
    "picture.\n"
    "\n"
    "  --size N     picture size in pixels, per mapper [512]\n"
    "  --voxels N   voxels per axis of the built-in nebula [128]\n"
    "  --light-grid N  ambient scattering's LightVolumeMaximumDimension [the mapper's default]\n"
    "  --output DIR output folder [build/demo]\n"
    "  --reference  render with the CPU reference ray caster instead\n");
}

// Brightness of a panel of the side-by-side picture where the emission-absorption panel shows
// the data (its luminance above 2 of 255): the mean luminance there and the share of those
// pixels with a channel at 255.
struct PanelBrightness
{
  double Mean = 0.0;
  double Saturated = 0.0;
};

PanelBrightness MeasurePanel(vtkImageData* all, int size, int panel)
{
  auto luminance = [all](int x, int y)
  {
    return 0.2126 * all->GetScalarComponentAsDouble(x, y, 0, 0) +
      0.7152 * all->GetScalarComponentAsDouble(x, y, 0, 1) +
      0.0722 * all->GetScalarComponentAsDouble(x, y, 0, 2);
  };
  PanelBrightness b;
  long pixels = 0;
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      if (luminance(x, y) <= 2.0)
      {
        continue;
      }
      const int px = panel * size + x;
      b.Mean += luminance(px, y);
      bool full = false;
      for (int c = 0; c < 3; ++c)
      {
        full = full || all->GetScalarComponentAsDouble(px, y, 0, c) >= 255.0;
      }
      b.Saturated += full ? 1.0 : 0.0;
      ++pixels;
    }
  }
  if (pixels > 0)
  {
    b.Mean /= pixels;
    b.Saturated /= pixels;
  }
  return b;
}

// The three GPU mappers in one window with three viewports sharing the camera and the lights.
// `meter`: a user's file, whose brightness nobody tuned: the ambient-scattering panel's exposure
// is metered until its brightness is near the emission-absorption panel's (as a camera meters
// a scene: only the display transform changes, nothing is rebuilt).
int RenderWithMappers(DemoScene& scene,
  int size,
  int lightGrid,
  bool meter,
  const std::string& output)
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
  EndProgressLine();
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
  for (int round = 0; meter && round < 4; ++round)
  {
    const double reference = MeasurePanel(grab->GetOutput(), size, 0).Mean;
    const double ours = MeasurePanel(grab->GetOutput(), size, 2).Mean;
    if (reference <= 0.0 || (ours <= 0.0 && as->GetExposure() >= 64.0))
    {
      break; // nothing to meter against, or nothing the exposure can bring out
    }
    const double ratio = ours > 0.0 ? ours / reference : 1.0 / 64.0; // black: the most exposure
    if (ratio > 0.8 && ratio < 1.25)
    {
      break;
    }
    // The tone curve's shoulder compresses the bright end: a few rounds converge.
    as->SetExposure(std::min(64.0, std::max(1.0 / 64.0, as->GetExposure() / ratio)));
    window->Render();
    grab->Modified();
    grab->Update();
  }
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
  if (meter)
  {
    const PanelBrightness reference = MeasurePanel(grab->GetOutput(), size, 0);
    const PanelBrightness ours = MeasurePanel(grab->GetOutput(), size, 2);
    std::printf("ambient scattering's exposure %.3g, metered against the emission-absorption "
                "panel: brightness %.2f of it, %.1f %% of the data's pixels saturated\n",
      as->GetExposure(),
      reference.Mean > 0.0 ? ours.Mean / reference.Mean : 0.0,
      100.0 * ours.Saturated);
  }
  std::printf("%s (EA | AO | ambient scattering, GPU mappers, first frame %.1f s with "
              "precomputation)\n",
    path.c_str(),
    seconds);
  std::fflush(stdout);
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
    EndProgressLine();
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
    std::fflush(stdout);
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
                   : RenderWithMappers(scene, size, lightGrid, !file.empty(), output);
}
