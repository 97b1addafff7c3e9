// Bricking (vtkAVSVolumeMapper::SetPartitions, SetMaximumGPUMemory): a small
// volume rendered unsplit and split into forced partitions, (2, 2, 2) and (3, 1, 2), must give
// the unsplit picture (>= 55 dB) for emission-absorption (point data, cell data, 16-bit scalars,
// a clipping plane, a binary mask, a gradient opacity, nearest interpolation, jittering, a
// parallel projection, a camera on the other side and one inside the volume, opaque geometry
// through it, an image sample distance of 2), ambient occlusion and ambient scattering
// with 1 and 4 lights (the GPU precomputation of the unsplit volume, and the CPU one of both:
// a split volume's averaged extinction is computed on the CPU); the split renders really use
// several bricks. A budget too small for the
// volume, or for its bricks together, gives one error naming the budget and a background-only
// picture; a blend mode other than composite on a split volume is an error with nothing drawn.
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>

namespace
{
using MapperFactory = std::function<vtkSmartPointer<vtkAVSVolumeMapper>()>;

template<typename T>
MapperFactory Factory(const std::function<void(T*)>& configure = nullptr)
{
  return [configure]() -> vtkSmartPointer<vtkAVSVolumeMapper>
  {
    auto mapper = vtkSmartPointer<T>::New();
    mapper->SetSampleDistance(0.02);
    mapper->UseJitteringOff();
    mapper->AutoAdjustSampleDistancesOff();
    if (configure)
    {
      configure(mapper);
    }
    return mapper;
  };
}

void Lights(vtkRenderer* renderer, int count)
{
  renderer->RemoveAllLights();
  const double positions[4][3] = {
    { -1.0, 1.0, 0.6 }, { 1.0, 0.3, 0.8 }, { 0.3, 0.1, 0.0 }, { -0.2, -0.3, 0.2 }
  };
  for (int l = 0; l < count; ++l)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(l >= 2); // two directional, then two point lights inside the volume
    light->SetConeAngle(180);
    light->SetPosition(positions[l][0], positions[l][1], positions[l][2]);
    light->SetFocalPoint(0, 0, 0);
    light->SetIntensity(l == 0 ? 1.1 : 0.6);
    light->SetAttenuationValues(1.0, 0.0, 2.0);
    renderer->AddLight(light);
  }
}

// A binary mask of the test image's points: 0 where x < -0.2.
vtkSmartPointer<vtkImageData> MakeMask(int n)
{
  auto mask = MakeTestImage(n);
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetName("mask");
  bytes->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = (i - 0.5 * (n - 1)) / (0.5 * n);
        bytes->SetValue(id++, x < -0.2 ? 0 : 1);
      }
  mask->GetPointData()->SetScalars(bytes);
  return mask;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, 128, 128);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  auto plain = MakeTestProperty();
  plain->ShadeOff();
  auto nearest = MakeTestProperty();
  nearest->ShadeOff();
  nearest->SetInterpolationTypeToNearest();
  auto gradient = MakeTestProperty();
  gradient->ShadeOff();
  vtkNew<vtkPiecewiseFunction> go;
  go->AddPoint(0, 0.0);
  go->AddPoint(40, 0.1);
  go->AddPoint(120, 1.0);
  gradient->SetGradientOpacity(go);

  auto points = MakeTestImage(40);
  AddArray(points, "shell", 1, false, ShellValue);
  points->GetPointData()->SetActiveScalars("shell");
  auto cells = MakeTestImage(40);
  AddArray(cells, "shell", 1, true, ShellValue);
  cells->GetCellData()->SetActiveScalars("shell");
  auto shorts = MakeTestVolume(40); // 16-bit scalars: normalized texels
  auto mask = MakeMask(40);

  vtkNew<vtkPlaneCollection> planes;
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.05, 0.0, 0.0);
  plane->SetNormal(-0.6, 0.3, -0.74);
  planes->AddItem(plane);

  struct Case
  {
    std::string Tag;
    vtkImageData* Data;
    vtkVolumeProperty* Property;
    MapperFactory Make;
    int Lights;
    int View; // 0 the test camera, 1 the other side, 2 parallel projection, 3 inside the volume
    bool Geometry = false; // an opaque sphere through the volume
  };
  using EA = vtkEmissionAbsorptionVolumeMapper;
  using AS = vtkAmbientScatteringVolumeMapper;
  const std::vector<Case> cases = {
    { "ea_points", points, plain, Factory<EA>(), 2, 0 },
    { "ea_cells", cells, plain, Factory<EA>(), 2, 0 },
    { "ea_short", shorts, plain, Factory<EA>(), 2, 0 },
    { "ea_jitter", shorts, plain, Factory<EA>([](EA* m) { m->UseJitteringOn(); }), 2, 0 },
    { "ea_gradient", shorts, gradient, Factory<EA>(), 2, 0 },
    { "ea_nearest", shorts, nearest, Factory<EA>(), 2, 0 },
    { "ea_other_side", points, plain, Factory<EA>(), 2, 1 },
    { "ea_parallel", points, plain, Factory<EA>(), 2, 2 },
    { "ea_inside", points, plain, Factory<EA>(), 2, 3 },
    { "ea_geometry", points, plain, Factory<EA>(), 2, 0, true },
    { "ea_sampled",
      points,
      plain,
      Factory<EA>([](EA* m) { m->SetImageSampleDistance(2.0); }),
      2,
      0 },
    { "ea_clipped",
      points,
      plain,
      Factory<EA>([&](EA* m) { m->SetClippingPlanes(planes); }),
      2,
      0 },
    { "ea_mask",
      points,
      plain,
      Factory<EA>(
        [&](EA* m)
        {
          m->SetMaskInput(mask);
          m->SetMaskTypeToBinary();
        }),
      2,
      0 },
    { "ao_points", points, plain, Factory<vtkAmbientOcclusionVolumeMapper>(), 2, 0 },
    { "as_1light", points, plain, Factory<AS>(), 1, 0 },
    { "as_4lights_cpu", points, plain, Factory<AS>([](AS* m) { m->PrecomputeOnGPUOff(); }), 4, 0 },
    { "as_4lights", points, plain, Factory<AS>(), 4, 0 },
    // (Clipped, the GPU and the CPU averaged extinction of the unsplit volume differ by 55 dB,
    // so this one compares the CPU precomputation of both.)
    { "as_clipped_cpu",
      points,
      plain,
      Factory<AS>(
        [&](AS* m)
        {
          m->SetClippingPlanes(planes);
          m->PrecomputeOnGPUOff();
        }),
      4,
      0 },
    { "as_cells_clipped",
      cells,
      plain,
      Factory<AS>([&](AS* m) { m->SetClippingPlanes(planes); }),
      4,
      0 },
  };
  const std::array<int, 3> splits[2] = { { 2, 2, 2 }, { 3, 1, 2 } };
  for (const Case& c : cases)
  {
    Lights(renderer, c.Lights);
    vtkCamera* camera = renderer->GetActiveCamera();
    PlaceTestCamera(camera);
    if (c.View == 1)
    {
      camera->SetPosition(-2.2, -1.6, -4.6);
    }
    else if (c.View == 3)
    {
      camera->SetPosition(0.15, 0.1, 0.35); // inside the shell, in the brick of the centre
      camera->SetFocalPoint(0.9, -0.5, -1.0);
      camera->SetViewAngle(70);
    }
    vtkNew<vtkSphereSource> sphereSource;
    sphereSource->SetCenter(0.3, -0.2, 0.1);
    sphereSource->SetRadius(0.35);
    sphereSource->SetThetaResolution(32);
    sphereSource->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphereSource->GetOutputPort());
    vtkNew<vtkActor> sphere;
    sphere->SetMapper(sphereMapper);
    if (c.Geometry)
    {
      renderer->AddActor(sphere);
    }
    camera->SetParallelProjection(c.View == 2);
    camera->SetParallelScale(1.2);
    auto unsplit = c.Make();
    unsplit->SetInputData(c.Data);
    vtkNew<TestErrorObserver> errors;
    unsplit->AddObserver(vtkCommand::ErrorEvent, errors);
    auto expected = RenderVolume(window, renderer, unsplit, c.Property, dir, "bricks_" + c.Tag);
    AVS_CHECK(unsplit->GetNumberOfBricks() == 1);
    AVS_CHECK(Brightness(expected) > 1000.0);
    std::cout << c.Tag << ":";
    for (const auto& p : splits)
    {
      auto split = c.Make();
      split->SetInputData(c.Data);
      split->AddObserver(vtkCommand::ErrorEvent, errors);
      split->SetPartitions(p[0], p[1], p[2]);
      const std::string name = "bricks_" + c.Tag + "_" + std::to_string(p[0]) +
        std::to_string(p[1]) + std::to_string(p[2]);
      auto picture = RenderVolume(window, renderer, split, c.Property, dir, name);
      const double psnr = Psnr(expected, picture);
      std::cout << " (" << p[0] << ", " << p[1] << ", " << p[2] << ") " << psnr << " dB";
      AVS_CHECK(split->GetNumberOfBricks() == p[0] * p[1] * p[2]);
      AVS_CHECK(psnr >= 55.0);
    }
    std::cout << "\n";
    AVS_CHECK(errors->Errors == 0);
    renderer->RemoveActor(sphere);
  }
  PlaceTestCamera(renderer->GetActiveCamera());
  renderer->GetActiveCamera()->SetParallelProjection(false);
  Lights(renderer, 2);

  // Budgets: a 2.4 MiB volume of floats does not fit in 1 MiB, whole or split (its bricks all
  // stay resident): one error naming the budget, and nothing drawn.
  auto large = MakeTestImage(86);
  AddArray(large, "shell", 1, false, ShellValue);
  large->GetPointData()->SetActiveScalars("shell");
  for (int split = 0; split < 2; ++split)
  {
    vtkNew<EA> mapper;
    mapper->SetInputData(large);
    mapper->SetMaximumGPUMemory(1);
    if (split)
    {
      mapper->SetPartitions(2, 2, 2);
    }
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    auto picture = RenderVolume(window, renderer, mapper, plain);
    std::cout << "1 MiB budget" << (split ? ", split" : "") << ": " << errors->LastError << "\n";
    AVS_CHECK(errors->Errors == 1);
    AVS_CHECK(errors->LastError.find("1.0 MiB allowed") != std::string::npos);
    AVS_CHECK(errors->LastError.find("SetMaximumGPUMemory") != std::string::npos);
    AVS_CHECK(!split || errors->LastError.find("brick") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
    AVS_CHECK(mapper->GetGPUMemoryBytes() == 0.0);
    // A budget it fits in: drawn.
    mapper->SetMaximumGPUMemory(64);
    errors->Clear();
    auto drawn = RenderVolume(window, renderer, mapper, plain);
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(Brightness(drawn) > 1000.0);
    AVS_CHECK(mapper->GetNumberOfBricks() == (split ? 8 : 1));
  }

  // Maximum intensity on a split volume: an error, nothing drawn; composite again: drawn.
  {
    vtkNew<EA> mapper;
    mapper->SetInputData(points);
    mapper->SetPartitions(2, 1, 1);
    mapper->SetBlendModeToMaximumIntensity();
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    auto picture = RenderVolume(window, renderer, mapper, plain);
    std::cout << "maximum intensity, split: " << errors->LastError << "\n";
    AVS_CHECK(errors->Errors == 1);
    AVS_CHECK(errors->LastError.find("split into bricks") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
    mapper->SetBlendModeToComposite();
    auto drawn = RenderVolume(window, renderer, mapper, plain);
    AVS_CHECK(errors->Errors == 1);
    AVS_CHECK(Brightness(drawn) > 1000.0);
    AVS_CHECK(mapper->GetNumberOfBricks() == 2);
    std::ostringstream print;
    mapper->Print(print);
    AVS_CHECK(print.str().find("Partitions: (2, 1, 1)") != std::string::npos);
    AVS_CHECK(print.str().find("NumberOfBricks: 2") != std::string::npos);
    AVS_CHECK(print.str().find("MaximumGPUMemory: 0 (what the OpenGL context reports)") !=
      std::string::npos);
    // Back to automatic: one brick (the volume fits one texture).
    mapper->SetPartitions(1, 1, 1);
    RenderVolume(window, renderer, mapper, plain);
    AVS_CHECK(mapper->GetNumberOfBricks() == 1);
  }
  // The automatic split, which a volume beyond the GPU's largest 3D texture takes, with that
  // limit lowered to 24 voxels (AVS_MAXIMUM_3D_TEXTURE_SIZE) for the 40^3 volume: split into
  // bricks by itself, the unsplit picture.
  for (int effect = 0; effect < 2; ++effect)
  {
    vtkSmartPointer<vtkAVSVolumeMapper> whole, automatic;
    if (effect == 0)
    {
      whole = vtkSmartPointer<EA>::New();
      automatic = vtkSmartPointer<EA>::New();
    }
    else
    {
      whole = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
      automatic = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    }
    for (vtkAVSVolumeMapper* m : { whole.Get(), automatic.Get() })
    {
      m->SetInputData(points);
      m->UseJitteringOff();
    }
    vtkNew<TestErrorObserver> errors;
    automatic->AddObserver(vtkCommand::ErrorEvent, errors);
    auto expected = RenderVolume(window, renderer, whole, plain);
    setenv("AVS_MAXIMUM_3D_TEXTURE_SIZE", "24", 1);
    auto picture = RenderVolume(window, renderer, automatic, plain);
    unsetenv("AVS_MAXIMUM_3D_TEXTURE_SIZE");
    std::cout << "automatic split under a 24-voxel limit, " << automatic->GetClassName() << ": "
              << automatic->GetNumberOfBricks() << " bricks, " << Psnr(expected, picture)
              << " dB\n";
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(whole->GetNumberOfBricks() == 1);
    AVS_CHECK(automatic->GetNumberOfBricks() >= 8);
    AVS_CHECK(Brightness(expected) > 1000.0);
    AVS_CHECK(Psnr(expected, picture) >= 55.0);
  }
  // A gradient opacity of 1 everywhere, as vtkVolumeProperty::GetStoredGradientOpacity (and so
  // DeepCopy) creates where a property has none, is no gradient opacity: the picture and the
  // bricks (no gradient layer) of a disabled gradient opacity (one volume that stays in the
  // renderer while measured).
  {
    vtkNew<vtkVolumeProperty> none, constant;
    none->DeepCopy(plain);
    none->DisableGradientOpacityOn();
    constant->DeepCopy(plain);
    vtkNew<vtkPiecewiseFunction> one; // what VTK's default gradient opacity is
    one->AddPoint(0.0, 1.0);
    one->AddPoint(255.0, 1.0);
    constant->SetGradientOpacity(one);
    std::array<double, 2> bytes{ 0.0, 0.0 };
    std::array<vtkSmartPointer<vtkImageData>, 2> pictures;
    for (int c = 0; c < 2; ++c)
    {
      vtkNew<EA> mapper;
      mapper->SetInputData(points);
      mapper->UseJitteringOff();
      mapper->SetPartitions(2, 2, 1);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(c == 0 ? none.Get() : constant.Get());
      renderer->AddVolume(volume);
      window->Render();
      pictures[c] = Grab(window);
      bytes[c] = mapper->GetGPUMemoryBytes();
      renderer->RemoveVolume(volume);
    }
    std::cout << "constant gradient opacity (stored: "
              << (constant->HasGradientOpacity() ? "yes" : "no")
              << "): " << Psnr(pictures[0], pictures[1]) << " dB, GPU bytes " << bytes[0] << " and "
              << bytes[1] << "\n";
    AVS_CHECK(constant->HasGradientOpacity());
    AVS_CHECK(Psnr(pictures[0], pictures[1]) > 80.0);
    AVS_CHECK(bytes[0] > 0.0);
    AVS_CHECK(bytes[0] == bytes[1]);
  }
  // Anisotropic spacing (z three times x and y): the look-back layers are counted per axis
  // (fewer along z), and the split picture is still the unsplit one.
  {
    vtkNew<vtkImageData> stretched;
    stretched->ShallowCopy(points);
    double h[3];
    points->GetSpacing(h);
    stretched->SetSpacing(h[0], h[1], 3.0 * h[2]);
    vtkNew<vtkAmbientScatteringVolumeMapper> whole, split;
    for (vtkAmbientScatteringVolumeMapper* m : { whole.Get(), split.Get() })
    {
      m->SetInputData(stretched);
      m->UseJitteringOff();
    }
    split->SetPartitions(2, 2, 3);
    auto expected = RenderVolume(window, renderer, whole, plain);
    auto picture = RenderVolume(window, renderer, split, plain);
    std::cout << "anisotropic spacing, (2, 2, 3): " << Psnr(expected, picture) << " dB\n";
    AVS_CHECK(split->GetNumberOfBricks() == 12);
    AVS_CHECK(Brightness(expected) > 1000.0);
    AVS_CHECK(Psnr(expected, picture) >= 55.0);
  }
  // Ambient scattering's bricks keep the look-back layers of the largest radius they were
  // uploaded for: a smaller radius draws from them (no upload), a larger one uploads again.
  // (One volume that stays in the renderer: removing a prop releases its mapper's resources.)
  {
    vtkNew<vtkAmbientScatteringVolumeMapper> unsplit, split;
    for (vtkAmbientScatteringVolumeMapper* m : { unsplit.Get(), split.Get() })
    {
      m->SetInputData(points);
      m->UseJitteringOff();
      m->SetAmbientRadius(0.2);
    }
    split->SetPartitions(2, 1, 2);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(split);
    volume->SetProperty(plain);
    renderer->AddVolume(volume);
    window->Render();
    const int uploads = split->GetNumberOfDataUploads();
    split->SetAmbientRadius(0.1);
    window->Render();
    auto picture = Grab(window);
    const int after = split->GetNumberOfDataUploads();
    split->SetAmbientRadius(0.3);
    window->Render();
    const int larger = split->GetNumberOfDataUploads();
    renderer->RemoveVolume(volume);
    unsplit->SetAmbientRadius(0.1);
    auto expected = RenderVolume(window, renderer, unsplit, plain);
    std::cout << "radius 0.2 -> 0.1 -> 0.3, split: uploads " << uploads << " -> " << after << " -> "
              << larger << ", at 0.1 " << Psnr(expected, picture) << " dB against unsplit\n";
    AVS_CHECK(after == uploads);
    AVS_CHECK(larger == uploads + 1);
    AVS_CHECK(Psnr(expected, picture) >= 55.0);
  }
  return failures == 0 ? 0 : 1;
}
