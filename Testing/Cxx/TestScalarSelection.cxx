// Which scalars the mappers draw: ScalarMode (default, point data, cell data,
// point field data, cell field data), SelectScalarArray by name and by index, ArrayAccessMode,
// and cell scalars rendered as vtkGPUVolumeRayCastMapper renders them (values at the cell
// centres, the volume spanning the points). Each case: our EA against VTK's mapper with the same
// selection (PSNR >= 35 dB), and the picture of the selected array differs from that of the
// active one (so the test fails if the selection were ignored). AO and AS with cell data and
// selected arrays against the CPU reference (>= 35 dB). A missing array is an error with
// nothing drawn.
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include <iostream>
#include <map>

namespace
{
struct Selection
{
  const char* Tag;
  int Mode;
  const char* Name; // nullptr: by index
  int Index;
};

template<typename Mapper>
void Select(Mapper* mapper, const Selection& s)
{
  mapper->SetScalarMode(s.Mode);
  if (s.Name)
  {
    mapper->SelectScalarArray(s.Name);
  }
  else
  {
    mapper->SelectScalarArray(s.Index);
  }
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  const double step = 0.01;
  auto property = MakeTestProperty();
  property->ShadeOff();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  // Point data: "slab" (index 0, the active scalars) and "shell" (index 1).
  auto points = MakeTestImage();
  AddArray(points, "slab", 1, false, SlabValue);
  AddArray(points, "shell", 1, false, ShellValue);
  points->GetPointData()->SetActiveScalars("slab");
  // Cell data only: "cshell" (active) and "cslab".
  auto cells = MakeTestImage();
  AddArray(cells, "cshell", 1, true, ShellValue);
  AddArray(cells, "cslab", 1, true, SlabValue);
  cells->GetCellData()->SetActiveScalars("cshell");

  struct Case
  {
    vtkImageData* Data;
    Selection Chosen;
    const char* Ignored; // the tag of the case the picture must differ from (nullptr: none)
  };
  const Case cases[] = {
    { points, { "point_default", VTK_SCALAR_MODE_DEFAULT, nullptr, -1 }, nullptr },
    { points, { "point_data", VTK_SCALAR_MODE_USE_POINT_DATA, nullptr, -1 }, nullptr },
    { points,
      { "point_field_name", VTK_SCALAR_MODE_USE_POINT_FIELD_DATA, "shell", -1 },
      "point_default" },
    { points,
      { "point_field_index", VTK_SCALAR_MODE_USE_POINT_FIELD_DATA, nullptr, 1 },
      "point_default" },
    { cells, { "cell_default", VTK_SCALAR_MODE_DEFAULT, nullptr, -1 }, nullptr },
    { cells, { "cell_data", VTK_SCALAR_MODE_USE_CELL_DATA, nullptr, -1 }, nullptr },
    { cells,
      { "cell_field_name", VTK_SCALAR_MODE_USE_CELL_FIELD_DATA, "cslab", -1 },
      "cell_default" },
    { cells,
      { "cell_field_index", VTK_SCALAR_MODE_USE_CELL_FIELD_DATA, nullptr, 1 },
      "cell_default" },
  };
  std::map<std::string, vtkSmartPointer<vtkImageData>> ours;
  for (const Case& c : cases)
  {
    vtkNew<vtkGPUVolumeRayCastMapper> reference;
    ConfigureVTKMapper(reference, step);
    reference->SetInputData(c.Data);
    Select(reference.Get(), c.Chosen);
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    ea->SetInputData(c.Data);
    ea->SetSampleDistance(step);
    ea->UseJitteringOff();
    Select(ea.Get(), c.Chosen);
    vtkNew<TestErrorObserver> errors;
    ea->AddObserver(vtkCommand::ErrorEvent, errors);
    const std::string tag = c.Chosen.Tag;
    auto vtkPicture = RenderVolume(window, renderer, reference, property, dir, tag + "_vtk");
    auto picture = RenderVolume(window, renderer, ea, property, dir, tag + "_ea");
    const double psnr = Psnr(vtkPicture, picture);
    std::cout << tag << ": EA against VTK " << psnr << " dB";
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(Brightness(picture) > 1000.0);
    AVS_CHECK(psnr >= 35.0);
    if (c.Ignored)
    {
      const double other = Psnr(ours[c.Ignored], picture);
      std::cout << ", against the active array's picture " << other << " dB";
      AVS_CHECK(other < 25.0);
    }
    std::cout << "\n";
    ours[tag] = picture;
  }
  // SetArrayAccessMode alone switches between the selected name ("shell") and index (0, "slab").
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    ea->SetInputData(points);
    ea->SetSampleDistance(step);
    ea->UseJitteringOff();
    ea->SetScalarModeToUsePointFieldData();
    ea->SelectScalarArray("shell");
    ea->SelectScalarArray(0);
    const double byId = Psnr(RenderVolume(window, renderer, ea, property), ours["point_default"]);
    ea->SetArrayAccessMode(VTK_GET_ARRAY_BY_NAME);
    const double byName =
      Psnr(RenderVolume(window, renderer, ea, property), ours["point_field_name"]);
    std::cout << "ArrayAccessMode by id (slab): " << byId << " dB, by name (shell): " << byName
              << " dB\n";
    AVS_CHECK(byId > 80.0);
    AVS_CHECK(byName > 80.0);
  }
  // Cell data is not point data: the cell picture of the shell differs from the point picture
  // of the same function (cells are sampled half a cell apart, and the box is the same).
  std::cout << "cell shell against point shell: "
            << Psnr(ours["cell_default"], ours["point_field_name"]) << " dB\n";

  // AO and AS: cell data, default and a selected cell array; a selected point array.
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  as->SetAnisotropy(0.4);
  vtkAVSVolumeMapper* mappers[2] = { ao, as };
  const Case scattering[] = { cases[4], cases[6], cases[2] };
  for (int m = 0; m < 2; ++m)
  {
    for (const Case& c : scattering)
    {
      vtkAVSVolumeMapper* mapper = mappers[m];
      vtkNew<TestErrorObserver> errors;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->SetInputData(c.Data);
      mapper->SetSampleDistance(0.02);
      mapper->UseJitteringOff();
      Select(mapper, c.Chosen);
      const std::string tag = std::string(m ? "as_" : "ao_") + c.Chosen.Tag;
      auto picture = RenderVolume(window, renderer, mapper, property, dir, tag);
      vtkNew<vtkVolumeReferenceRenderer> cpu;
      cpu->SetInputData(c.Data);
      Select(cpu.Get(), c.Chosen);
      cpu->SetVolumeProperty(property);
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
      std::cout << tag << ": against the CPU reference " << psnr << " dB\n";
      AVS_CHECK(errors->Errors == 0);
      AVS_CHECK(Brightness(picture) > 1000.0);
      AVS_CHECK(psnr >= 35.0);
      mapper->RemoveObserver(errors);
    }
  }

  // Errors: an array that does not exist, cell data asked of an image without, a string array.
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    vtkNew<TestErrorObserver> errors;
    ea->AddObserver(vtkCommand::ErrorEvent, errors);
    ea->SetInputData(points);
    ea->SetScalarModeToUsePointFieldData();
    ea->SelectScalarArray("missing");
    auto picture = RenderVolume(window, renderer, ea, property);
    AVS_CHECK(errors->Errors >= 1);
    AVS_CHECK(errors->LastError.find("no array named 'missing'") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
    errors->Clear();
    ea->SetScalarModeToUseCellData();
    picture = RenderVolume(window, renderer, ea, property);
    AVS_CHECK(errors->Errors >= 1);
    AVS_CHECK(errors->LastError.find("no cell scalars") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
