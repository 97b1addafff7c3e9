// The GPU mappers as a VTK user meets them: precomputation redone only when its inputs change
// (rebuild counters), opaque geometry ends the rays, several windows, resizing, releasing
// resources, bad input (an error and nothing drawn), and PrintSelf.
#include "MapperTestScene.h"
#include "ScatteringTable.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringTable.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkFloatArray.h"
#include "vtkLightCollection.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRectilinearGrid.h"
#include "vtkSphereSource.h"
#include "vtkTrivialProducer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <utility>

namespace
{

vtkLight* LightAt(vtkRenderer* renderer, int index)
{
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  vtkLight* l = nullptr;
  for (int i = 0; i <= index; ++i)
  {
    l = lights->GetNextItem();
  }
  return l;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  auto data = MakeTestVolume(32);

  // --- Rebuild counters: ambient scattering (from the paper's model, then the extended one).
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    AVS_CHECK(mapper->GetScatteringModel() == vtkAmbientScatteringVolumeMapper::ExtendedModel);
    mapper->SetScatteringModelToPaper();
    ShowLinear(mapper.Get()); // the models' radiance, not the display's compression of it
    mapper->SetInputData(data);
    TestScene scene(mapper);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfDataUploads() == 1);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 1);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 2);
    // A camera move only re-renders.
    scene.Renderer->GetActiveCamera()->Azimuth(30);
    scene.Render();
    scene.Renderer->GetActiveCamera()->Elevation(10);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == 3);
    AVS_CHECK(mapper->GetNumberOfDataUploads() == 1);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 1);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 2);
    // A light move rebuilds that light's volume only; a change of intensity nothing.
    LightAt(scene.Renderer, 1)->SetPosition(0.2, -0.1, 0.1);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 3);
    LightAt(scene.Renderer, 0)->SetIntensity(0.24);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 3);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 1);
    // Moving the volume moves every light relative to it.
    scene.Volume->SetPosition(0.1, 0.0, 0.0);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 5);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 1);
    // A transfer-function change rebuilds the averaged extinction and every light volume.
    scene.Volume->GetProperty()->GetScalarOpacity()->AddPoint(500, 0.3);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 2);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 7);
    AVS_CHECK(mapper->GetNumberOfDataUploads() == 1);
    // A change of colour alone changes the picture but no extinction: nothing is rebuilt.
    const auto before = scene.Render();
    scene.Volume->GetProperty()->GetRGBTransferFunction()->AddRGBPoint(500, 0.1, 0.9, 0.2);
    const auto after = scene.Render();
    AVS_CHECK(Psnr(before, after) < 40.0);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 2);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 7);
    // The radius: both. g and the albedo: the light volumes (F changes), not the average.
    mapper->SetAmbientRadius(0.1);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 3);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 9);
    mapper->SetAlbedo(0.5);
    scene.Render();
    mapper->SetAnisotropy(-0.3);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 3);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 13);
    // The same values marked modified: nothing (the fingerprints agree).
    data->Modified();
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfDataUploads() == 1);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 3);
    // New values: everything.
    vtkDataArray* values = data->GetPointData()->GetScalars();
    values->SetComponent(0, 0, values->GetComponent(0, 0) + 1.0);
    values->Modified();
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfDataUploads() == 2);
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 4);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 15);
    // The sample distance and jittering only re-render.
    mapper->SetSampleDistance(0.03);
    mapper->UseJitteringOff();
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfExtinctionRebuilds() == 4);
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 15);
    // The extended model: its diffusion solve follows the light volumes, not the camera; back to
    // the paper's model, the picture is the paper's again.
    AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == 0);
    const auto paper = scene.Render();
    mapper->SetScatteringModelToExtended();
    const auto extended = scene.Render();
    AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == 1);
    AVS_CHECK(Psnr(paper, extended) < 45.0);
    // The positional light's tube carries the direct beam in the extended model (TubeLaw), and
    // the directional light's volume is marched again over the tiles of the light grid that the
    // diffusion reads too (LightTiles.h): both are rebuilt.
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 17);
    scene.Renderer->GetActiveCamera()->Azimuth(10);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == 1);
    scene.Renderer->GetActiveCamera()->Azimuth(-10);
    scene.Volume->GetProperty()->GetScalarOpacity()->AddPoint(700, 0.3);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == 2);
    scene.Volume->GetProperty()->GetScalarOpacity()->RemovePoint(700);
    scene.Render();
    mapper->SetScatteringModelToPaper();
    AVS_CHECK(Psnr(paper, scene.Render()) > 60.0);
    AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == 3);
    // (Back in the paper's model the positional light's alone: the directional light's tiles hold
    // the paper's.)
    AVS_CHECK(mapper->GetNumberOfLightVolumeRebuilds() == 22);
    // What the light volumes do not hold but the diffusion's source does: a light's colour, a
    // positional light's attenuation and its cone. Each change re-solves and changes the
    // picture; undone, the picture is the first again.
    {
      mapper->SetScatteringModelToExtended();
      const auto before = scene.Render();
      int solves = mapper->GetNumberOfDiffusionRebuilds();
      vtkLightCollection* lights = scene.Renderer->GetLights();
      vtkLight* sun = vtkLight::SafeDownCast(lights->GetItemAsObject(0));
      vtkLight* lamp = vtkLight::SafeDownCast(lights->GetItemAsObject(1));
      AVS_CHECK(sun && lamp && lamp->GetPositional());
      // Each change: its name, and setting it (true) or undoing it (false).
      const std::pair<const char*, std::function<void(bool)>> changes[3] = {
        { "the sun's colour",
          [&](bool on) { sun->SetDiffuseColor(on ? 0.4 : 1.0, on ? 0.6 : 1.0, 1.0); } },
        { "the lamp's attenuation",
          [&](bool on) { lamp->SetAttenuationValues(1.0, 0.0, on ? 8.0 : 2.0); } },
        { "the lamp's cone", [&](bool on) { lamp->SetConeAngle(on ? 20 : 180); } }
      };
      for (const auto& [name, set] : changes)
      {
        if (!sun || !lamp)
        {
          break;
        }
        set(true);
        const auto changed = scene.Render();
        std::printf("%s: %d solve(s), %.1f dB from before\n",
          name,
          mapper->GetNumberOfDiffusionRebuilds() - solves,
          Psnr(before, changed));
        AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == solves + 1);
        AVS_CHECK(Psnr(before, changed) < 50.0);
        set(false);
        AVS_CHECK(Psnr(before, scene.Render()) > 60.0);
        AVS_CHECK(mapper->GetNumberOfDiffusionRebuilds() == solves + 2);
        solves += 2;
      }
      mapper->SetScatteringModelToPaper();
    }

    std::ostringstream os;
    mapper->Print(os);
    for (const char* key : { "AmbientRadius",
           "Anisotropy",
           "Albedo",
           "EmissionWeight",
           "LightVolumeMaximumDimension",
           "ScatteringModel",
           "NumberOfDiffusionRebuilds",
           "ScatteringTableFileName",
           "SampleDistance",
           "UseJittering",
           "TerminationTransmittance",
           "NumberOfLightVolumeRebuilds",
           "Table" })
    {
      AVS_CHECK(os.str().find(key) != std::string::npos);
    }
  }

  // --- Light volumes computed on the GPU (compute shaders) agree with the CPU code they fall
  // back to, also after a light and the volume moved.
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> onGPU;
    vtkNew<vtkAmbientScatteringVolumeMapper> onCPU;
    onCPU->PrecomputeOnGPUOff();
    for (vtkAVSVolumeMapper* m :
      { static_cast<vtkAVSVolumeMapper*>(onGPU), static_cast<vtkAVSVolumeMapper*>(onCPU) })
    {
      m->SetInputData(data);
      m->UseJitteringOff();
    }
    TestScene a(onGPU, 96);
    TestScene b(onCPU, 96);
    for (int step = 0; step < 2; ++step)
    {
      const auto pa = a.Render();
      const auto pb = b.Render();
      AVS_CHECK(onCPU->GetLightVolumesOnGPU() == 0);
      // (A context with compute shaders, as llvmpipe's 4.5: the GPU path must have run, or
      // this compares the CPU with itself.)
      AVS_CHECK(onGPU->GetLightVolumesOnGPU() == 1);
      std::cout << "light volumes on the GPU: " << (onGPU->GetLightVolumesOnGPU() ? "yes" : "no")
                << ", PSNR against the CPU's " << Psnr(pa, pb) << " dB\n";
      AVS_CHECK(Brightness(pa) > 1000.0);
      AVS_CHECK(Psnr(pa, pb) > 50.0);
      LightAt(a.Renderer, 1)->SetPosition(-0.2, 0.3, 0.1);
      LightAt(b.Renderer, 1)->SetPosition(-0.2, 0.3, 0.1);
      a.Volume->SetPosition(0.05, 0.0, 0.02);
      b.Volume->SetPosition(0.05, 0.0, 0.02);
    }
    AVS_CHECK(onGPU->GetNumberOfLightVolumeRebuilds() == onCPU->GetNumberOfLightVolumeRebuilds());
    // The averaged-extinction pass in slabs of 3 slices along z (of a 32-voxel-wide light grid:
    // 11 slabs, the last of 2), and its pass 1 without its ring of classified values (each voxel
    // classified again when it leaves the window, as for windows wider than the ring can hold),
    // give what the default gives: the same sums. (Each set from the environment for one render
    // of a mapper of its own.)
    const auto pa = a.Render();
    const char* variants[2][3] = {
      { "AVS_AVERAGING_SLAB_BYTES", "12288", "in slabs of 3 slices" },
      { "AVS_AVERAGING_WINDOW_RING", "0", "without the ring" },
    };
    for (const auto& [variable, value, what] : variants)
    {
      vtkNew<vtkAmbientScatteringVolumeMapper> other;
      other->SetInputData(data);
      other->UseJitteringOff();
      TestScene c(other, 96);
      c.Volume->SetPosition(a.Volume->GetPosition());
      LightAt(c.Renderer, 1)->SetPosition(-0.2, 0.3, 0.1);
      setenv(variable, value, 1);
      const auto pc = c.Render();
      unsetenv(variable);
      std::cout << "averaged extinction " << what << ": PSNR against the default " << Psnr(pc, pa)
                << " dB\n";
      AVS_CHECK(other->GetLightVolumesOnGPU() == 1);
      AVS_CHECK(Psnr(pc, pa) > 80.0);
    }
  }
  // --- A user table whose tau axis is longer than the GPU light-volume pass takes (64 nodes):
  // the shipped table resampled onto 80 tau nodes. The mapper marches the light volumes on the
  // CPU and renders what the shipped table gives, up to the resampling.
  {
    avs::ScatteringTable shipped;
    std::string error;
    AVS_CHECK(shipped.Read(vtkAmbientScatteringTable::GetDefaultFileName(), &error));
    avs::ScatteringTableAxes axes = shipped.Axes;
    axes.NumberOfTau = 80;
    avs::ScatteringTable fine;
    fine.Allocate(axes);
    for (int l = 0; l < axes.NumberOfAlbedo; ++l)
      for (int k = 0; k < axes.NumberOfAnisotropy; ++k)
        for (int j = 0; j < axes.NumberOfTau; ++j)
        {
          const double tau = axes.Tau(j), g = axes.Anisotropy(k), albedo = axes.Albedo(l);
          fine.F[fine.FIndex(j, k, l)] =
            static_cast<float>(shipped.ForwardTransport(tau, g, albedo));
          for (int i = 0; i < axes.NumberOfTheta; ++i)
          {
            fine.A[fine.AIndex(i, j, k, l)] =
              static_cast<float>(shipped.InScattering(axes.Theta(i), tau, g, albedo));
          }
        }
    const std::string file =
      std::string(argc > 1 ? argv[1] : ".") + "/TestMapperBehaviour_tau80.avst";
    AVS_CHECK(fine.Write(file, &error));
    vtkNew<vtkAmbientScatteringVolumeMapper> shippedTable;
    vtkNew<vtkAmbientScatteringVolumeMapper> longAxis;
    longAxis->SetScatteringTableFileName(file.c_str());
    for (vtkAVSVolumeMapper* m : { static_cast<vtkAVSVolumeMapper*>(shippedTable),
           static_cast<vtkAVSVolumeMapper*>(longAxis) })
    {
      m->SetInputData(data);
      m->UseJitteringOff();
    }
    TestScene a(shippedTable, 96);
    TestScene b(longAxis, 96);
    const auto pa = a.Render();
    const auto pb = b.Render();
    std::cout << "80 tau nodes: light volumes on the GPU: "
              << (longAxis->GetLightVolumesOnGPU() ? "yes" : "no")
              << ", PSNR against the shipped table's " << Psnr(pa, pb) << " dB (" << error << ")\n";
    AVS_CHECK(longAxis->GetLightVolumesOnGPU() == 0);
    AVS_CHECK(longAxis->GetNumberOfRenderedFrames() == 1);
    AVS_CHECK(Brightness(pb) > 1000.0);
    AVS_CHECK(Psnr(pa, pb) > 40.0);
    std::remove(file.c_str());
  }
  // The same for the occlusion volume.
  {
    vtkNew<vtkAmbientOcclusionVolumeMapper> onGPU;
    vtkNew<vtkAmbientOcclusionVolumeMapper> onCPU;
    onCPU->PrecomputeOnGPUOff();
    for (vtkAmbientOcclusionVolumeMapper* m : { onGPU.Get(), onCPU.Get() })
    {
      m->SetInputData(data);
      m->UseJitteringOff();
      m->SetOcclusionRadius(0.2);
    }
    TestScene a(onGPU, 96);
    TestScene b(onCPU, 96);
    const auto pa = a.Render();
    const auto pb = b.Render();
    AVS_CHECK(onCPU->GetOcclusionOnGPU() == 0);
    AVS_CHECK(onGPU->GetOcclusionOnGPU() == 1); // as above: else the CPU against itself
    std::cout << "occlusion on the GPU: " << (onGPU->GetOcclusionOnGPU() ? "yes" : "no")
              << ", PSNR against the CPU's " << Psnr(pa, pb) << " dB\n";
    AVS_CHECK(Brightness(pa) > 1000.0);
    AVS_CHECK(Psnr(pa, pb) > 50.0);
  }

  // --- Rebuild counters: ambient occlusion.
  {
    vtkNew<vtkAmbientOcclusionVolumeMapper> mapper;
    mapper->SetInputData(data);
    TestScene scene(mapper);
    scene.Render();
    scene.Renderer->GetActiveCamera()->Azimuth(40);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 1);
    mapper->SetOcclusionRadius(0.2);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 2);
    scene.Volume->GetProperty()->GetScalarOpacity()->AddPoint(450, 0.2);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 3);
    // A coarser occlusion grid (the test volume is 32^3) rebuilds; a cap above the data's size
    // changes nothing.
    mapper->SetOcclusionVolumeMaximumDimension(16);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 4);
    mapper->SetOcclusionVolumeMaximumDimension(64);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 5);
    mapper->SetOcclusionVolumeMaximumDimension(100);
    scene.Render();
    AVS_CHECK(mapper->GetNumberOfOcclusionRebuilds() == 5);
    std::ostringstream os;
    mapper->Print(os);
    for (const char* key : { "OcclusionRadius",
           "NumberOfDirections",
           "OcclusionVolumeMaximumDimension",
           "AmbientWeight",
           "EmissionWeight",
           "DirectLightWeight" })
    {
      AVS_CHECK(os.str().find(key) != std::string::npos);
    }
  }

  // --- Opaque geometry ends the rays; several windows; resize; releasing resources.
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> mapper;
    mapper->SetInputData(data);
    mapper->UseJitteringOff();
    TestScene scene(mapper, 96);
    const auto volumeOnly = scene.Render();
    // A red ball between the camera and the volume hides the volume where it is drawn.
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(0.38, 0.28, 1.0); // on the line of sight to the centre, in front of the box
    ball->SetRadius(0.08);
    ball->SetThetaResolution(24);
    ball->SetPhiResolution(24);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(ball->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(ballMapper);
    actor->GetProperty()->SetColor(1, 0, 0);
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    scene.Renderer->AddActor(actor);
    const auto withBall = scene.Render();
    const double centre[3] = { withBall->GetScalarComponentAsDouble(48, 48, 0, 0),
      withBall->GetScalarComponentAsDouble(48, 48, 0, 1),
      withBall->GetScalarComponentAsDouble(48, 48, 0, 2) };
    AVS_CHECK(centre[0] == 255 && centre[1] == 0 && centre[2] == 0);
    // Elsewhere the picture is unchanged.
    AVS_CHECK(withBall->GetScalarComponentAsDouble(10, 10, 0, 1) ==
      volumeOnly->GetScalarComponentAsDouble(10, 10, 0, 1));
    // The same with a multisampled window (VTK's default): its depth is resolved for the rays.
    {
      TestScene msaa(mapper, 96);
      msaa.Window->SetMultiSamples(4);
      msaa.Volume->SetProperty(scene.Volume->GetProperty());
      msaa.Renderer->AddActor(actor);
      const auto picture = msaa.Render();
      AVS_CHECK(picture->GetScalarComponentAsDouble(48, 48, 0, 0) > 250);
      AVS_CHECK(picture->GetScalarComponentAsDouble(48, 48, 0, 1) < 5);
      AVS_CHECK(std::abs(picture->GetScalarComponentAsDouble(10, 10, 0, 1) -
                  volumeOnly->GetScalarComponentAsDouble(10, 10, 0, 1)) < 3);
      msaa.Renderer->RemoveActor(actor);
    }
    // A ball inside the volume: volume in front of it is added, volume behind it is not.
    ball->SetCenter(0, 0, 0);
    ball->SetRadius(0.3);
    const auto inside = scene.Render();
    scene.Renderer->RemoveActor(actor);
    const double r = inside->GetScalarComponentAsDouble(48, 48, 0, 0);
    const double g = inside->GetScalarComponentAsDouble(48, 48, 0, 1);
    AVS_CHECK(g > 0.0); // the volume in front of the ball adds colour
    AVS_CHECK(r > g);   // and the red ball shows through
    AVS_CHECK(std::abs(g - volumeOnly->GetScalarComponentAsDouble(48, 48, 0, 1)) > 2.0);

    // A second window with the same mapper, then back to the first.
    TestScene other(mapper, 64);
    other.Volume->SetProperty(scene.Volume->GetProperty());
    const auto second = other.Render();
    AVS_CHECK(Brightness(second) > 1000.0);
    const auto again = scene.Render();
    AVS_CHECK(Psnr(again, volumeOnly) > 60.0);
    // Resize.
    scene.Window->SetSize(80, 72);
    const auto resized = scene.Render();
    int dims[3];
    resized->GetDimensions(dims);
    AVS_CHECK(dims[0] == 80 && dims[1] == 72);
    AVS_CHECK(Brightness(resized) > 1000.0);
    // Released resources come back on the next render.
    mapper->ReleaseGraphicsResources(scene.Window);
    scene.Window->SetSize(96, 96);
    AVS_CHECK(Psnr(scene.Render(), volumeOnly) > 60.0);
  }

  // --- Bad input: an error, nothing drawn, no crash; for every mapper (one window for all).
  {
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
    vtkNew<vtkAmbientScatteringVolumeMapper> as;
    TestScene scene(ea, 48);
    for (vtkAVSVolumeMapper* mapper : { static_cast<vtkAVSVolumeMapper*>(ea),
           static_cast<vtkAVSVolumeMapper*>(ao),
           static_cast<vtkAVSVolumeMapper*>(as) })
    {
      vtkNew<TestErrorObserver> errors;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      scene.Volume->SetMapper(mapper);
      auto expectError = [&](vtkImageData* input, const std::string& text)
      {
        errors->Clear();
        mapper->SetInputData(input);
        const int frames = mapper->GetNumberOfRenderedFrames();
        const auto picture = scene.Render();
        if (errors->Errors == 0 || errors->LastError.find(text) == std::string::npos)
        {
          std::cerr << mapper->GetClassName() << ": expected an error with '" << text << "', got '"
                    << errors->LastError << "'\n";
          ++failures;
        }
        AVS_CHECK(Brightness(picture) == 0.0);
        AVS_CHECK(mapper->GetNumberOfRenderedFrames() == frames);
      };
      vtkNew<vtkImageData> empty;
      expectError(empty, "empty");
      // A rectilinear grid (VTK's mapper renders one): an error naming it, nothing drawn.
      {
        vtkNew<vtkRectilinearGrid> grid;
        grid->SetDimensions(8, 8, 8);
        vtkNew<vtkDoubleArray> coordinates;
        for (int i = 0; i < 8; ++i)
        {
          coordinates->InsertNextValue(0.01 * i * i);
        }
        grid->SetXCoordinates(coordinates);
        grid->SetYCoordinates(coordinates);
        grid->SetZCoordinates(coordinates);
        vtkNew<vtkFloatArray> values;
        values->SetNumberOfTuples(grid->GetNumberOfPoints());
        values->Fill(500.0);
        grid->GetPointData()->SetScalars(values);
        errors->Clear();
        mapper->SetInputData(grid);
        const int frames = mapper->GetNumberOfRenderedFrames();
        const auto picture = scene.Render();
        AVS_CHECK(errors->Errors > 0);
        AVS_CHECK(errors->LastError.find("the input is a vtkRectilinearGrid") != std::string::npos);
        AVS_CHECK(Brightness(picture) == 0.0);
        AVS_CHECK(mapper->GetNumberOfRenderedFrames() == frames);
      }
      auto noScalars = MakeTestVolume(8);
      noScalars->GetPointData()->RemoveArray(0);
      expectError(noScalars, "no point scalars");
      auto vectors = MakeTestVolume(8);
      vtkNew<vtkFloatArray> v;
      v->SetNumberOfComponents(5); // VTK's mappers take 1-4
      v->SetNumberOfTuples(vectors->GetNumberOfPoints());
      v->Fill(1.0);
      vectors->GetPointData()->SetScalars(v);
      expectError(vectors, "components");
      // Three dependent components: VTK's dependent modes are 2 (colour, opacity) and 4 (RGBA).
      auto three = MakeTestVolume(8);
      vtkNew<vtkFloatArray> t;
      t->SetNumberOfComponents(3);
      t->SetNumberOfTuples(three->GetNumberOfPoints());
      t->Fill(1.0);
      three->GetPointData()->SetScalars(t);
      scene.Volume->GetProperty()->IndependentComponentsOff();
      expectError(three, "dependent components");
      scene.Volume->GetProperty()->IndependentComponentsOn();
      auto flat = MakeTestVolume(8);
      flat->SetSpacing(0.1, std::numeric_limits<double>::quiet_NaN(), 0.1);
      expectError(flat, "spacing");
      // Wider than any GPU's 3D textures (2 points deep and high, so it is small in memory): not
      // an error, split into bricks (SetPartitions' automatic default; TestBricking).
      vtkNew<vtkImageData> huge;
      huge->SetDimensions(70000, 2, 2);
      huge->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
      huge->GetPointData()->GetScalars()->Fill(0);
      errors->Clear();
      mapper->SetInputData(huge);
      scene.Render();
      if (errors->Errors != 0)
      {
        std::cerr << mapper->GetClassName() << ", a volume 70000 wide: " << errors->LastError
                  << "\n";
      }
      AVS_CHECK(errors->Errors == 0);
      const int automatic = mapper->GetNumberOfBricks();
      AVS_CHECK(automatic > 1);
      // Partitions asked for along the long axis, fewer than it needs: as many as it needs.
      mapper->SetPartitions(2, 1, 1);
      errors->Clear();
      scene.Render();
      AVS_CHECK(errors->Errors == 0);
      AVS_CHECK(mapper->GetNumberOfBricks() == std::max(2, automatic));
      mapper->SetPartitions(1, 1, 1);
      // Good input again renders.
      mapper->SetInputData(data);
      errors->Clear();
      AVS_CHECK(Brightness(scene.Render()) > 0.0);
      AVS_CHECK(errors->Errors == 0);
    }
    // A missing scattering table.
    vtkNew<TestErrorObserver> errors;
    as->AddObserver(vtkCommand::ErrorEvent, errors);
    as->SetScatteringTableFileName("/nonexistent/table.avst");
    scene.Volume->SetMapper(as);
    AVS_CHECK(Brightness(scene.Render()) == 0.0);
    AVS_CHECK(errors->Errors >= 1);
  }

  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
