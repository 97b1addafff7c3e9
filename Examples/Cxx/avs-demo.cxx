// avs-demo: renders the built-in scene (or a volume file) with emission–absorption, ambient
// occlusion and ambient scattering, and writes each picture and the three side by side as PNG.
//
//   avs-demo [--size N] [--voxels N] [--output DIR] [FILE]
//
// The renderer is the CPU reference ray caster (vtkVolumeReferenceRenderer).
#include "DemoScene.h"

#include "vtkCommand.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderer.h"
#include "vtkVolumeReferenceRenderer.h"

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
  std::printf("Usage: avs-demo [--size N] [--voxels N] [--output DIR] [FILE]\n"
              "\n"
              "Renders the built-in procedural nebula (or FILE: .vti, .vtk, .slc, .nhdr, .nrrd)\n"
              "with emission-absorption, ambient occlusion and ambient scattering using the CPU\n"
              "reference ray caster, and writes ea.png, ao.png, as.png and the three side by\n"
              "side (side_by_side.png) into DIR.\n"
              "\n"
              "  --size N     picture size in pixels [256]\n"
              "  --voxels N   voxels per axis of the built-in nebula [128]\n"
              "  --output DIR output folder [build/demo]\n");
}
} // namespace

int main(int argc, char* argv[])
{
  int size = 256;
  int voxels = 128;
  std::string output = "build/demo";
  std::string file;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      Usage();
      return 0;
    }
    if ((arg == "--size" || arg == "--voxels" || arg == "--output") && i + 1 < argc)
    {
      const std::string value = argv[++i];
      if (arg == "--output")
      {
        output = value;
      }
      else
      {
        const int v = std::atoi(value.c_str());
        if (v < 8 || v > 4096)
        {
          std::fprintf(stderr, "avs-demo: %s must be between 8 and 4096\n", arg.c_str());
          return 2;
        }
        (arg == "--size" ? size : voxels) = v;
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
    renderer->SetAlbedo(0.9);
    renderer->SetAnisotropy(0.3);
    renderer->SetAmbientWeight(1.0);
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
    std::printf("%s (%s, %.1f s)\n", path.c_str(), mode.Label, seconds);
  }
  sideBySide->Update();
  const std::string path = output + "/side_by_side.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(sideBySide->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  std::printf("%s (EA | AO | ambient scattering)\n", path.c_str());
  return 0;
}
