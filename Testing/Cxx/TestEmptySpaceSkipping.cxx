// Empty-space skipping (vtkAVSVolumeMapper::EmptySpaceSkipping) changes no picture: each mapper
// (EA, AO, ambient scattering in the paper's and the extended model) renders each volume with
// and without it, and the pictures are the same to one level of 255 (the rays take the same
// samples, so they are bit for bit equal where the compiler keeps the arithmetic), while the
// frame with it did leap (LastSkippedEmptySpace) over a volume whose cells are largely empty
// (LastEmptyCellFraction). Volumes: the shell with its core, clipped by two planes, cropped
// (fence), with a binary mask and a label map, two independent components, two dependent
// ones, NaN voxels, gradient opacity, split into bricks, jittered, at image sample distance 2,
// a transfer function whose opacity is a narrow band, a light grid coarse enough that ambient
// scattering reads its lights once per four samples (unsplit and in bricks; with forward
// scattering, whose diffuse field's slope reads the group before), a small ball in
// empty space (with the default ambient radius and a large one), and a dense slab with a radius
// that makes the extended model's diffusion read the light volumes far outside the rays' tiles
// (the tiles it reads are flagged on the GPU). The blend
// modes other than composite and ambient scattering's explicit look-ahead (a radius beyond the
// ring) do not leap, and say so. One mapper kept through a transfer-function change and new data
// draws what a mapper without skipping draws. (Against the CPU reference the pictures are compared,
// with skipping on, by TestMappersAgainstReference, TestMasks, TestComponents, TestBricking and the
// others.)
#include "DataTestScene.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace
{
constexpr int N = 64;     // voxels per axis: 8 cells of 8
constexpr int Size = 128; // pixels

struct Case
{
  std::string Name;
  vtkSmartPointer<vtkImageData> Data;
  vtkSmartPointer<vtkVolumeProperty> Property;
  std::function<void(vtkAVSVolumeMapper*)> Configure; ///< may be empty
  bool Leaps = true;                                  ///< whether the frame is expected to leap
  double MostEmpty = 0.25;                            ///< at least this share of the cells is empty
};

// A mask's labels at (x, y, z) in [-1, 1]^3: 1 where x < -0.2, 2 where y > 0.3, else 0.
std::array<double, 4> Labels(double x, double y, double)
{
  return { x < -0.2 ? 1.0 : (y > 0.3 ? 2.0 : 0.0), 0, 0, 0 };
}

// Two components: the shell and the slab.
std::array<double, 4> ShellAndSlab(double x, double y, double z)
{
  return { ShellValue(x, y, z)[0], SlabValue(x, y, z)[0], 0, 0 };
}

// A ball of radius 0.35 with a soft edge, in the middle of the box.
std::array<double, 4> SmallBall(double x, double y, double z)
{
  const double r = std::sqrt(x * x + y * y + z * z);
  return { 900.0 * std::clamp((0.35 - r) / 0.1, 0.0, 1.0), 0, 0, 0 };
}

// A dense slab across the box, x in [-0.8, -0.2].
std::array<double, 4> DenseSlab(double x, double, double)
{
  return { x > -0.8 && x < -0.2 ? 900.0 : 0.0, 0, 0, 0 };
}

// The shell with NaN voxels in a band through it.
std::array<double, 4> ShellWithNaN(double x, double y, double z)
{
  return { std::abs(x + y) < 0.1 ? std::nan("") : ShellValue(x, y, z)[0], 0, 0, 0 };
}

vtkSmartPointer<vtkImageData> Shell()
{
  auto image = MakeTestImage(N);
  image->GetPointData()->SetScalars(AddArray(image, "shell", 1, false, ShellValue));
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  auto property = MakeTestProperty();
  property->SetScalarOpacityUnitDistance(0.15);
  return property;
}
} // namespace

int main()
{
  std::vector<Case> cases;
  cases.push_back({ "shell", Shell(), Property(), nullptr });
  cases.push_back({ "clipped",
    Shell(),
    Property(),
    [](vtkAVSVolumeMapper* m)
    {
      vtkNew<vtkPlane> a, b;
      a->SetOrigin(0.1, 0.0, 0.0);
      a->SetNormal(-1, -0.2, 0.1);
      b->SetOrigin(0.0, -0.3, 0.0);
      b->SetNormal(0.1, 1, 0.3);
      m->AddClippingPlane(a);
      m->AddClippingPlane(b);
    } });
  cases.push_back({ "cropped",
    Shell(),
    Property(),
    [](vtkAVSVolumeMapper* m)
    {
      m->CroppingOn();
      m->SetCroppingRegionPlanes(0.4, 1.2, 0.4, 1.2, 0.5, 1.4);
      m->SetCroppingRegionFlagsToFence();
    } });
  {
    // A mask of the volume's points (Labels).
    auto mask = MakeTestImage(N);
    vtkFloatArray* labels = AddArray(mask, "labels", 1, false, Labels);
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetNumberOfTuples(labels->GetNumberOfTuples());
    for (vtkIdType i = 0; i < bytes->GetNumberOfTuples(); ++i)
    {
      bytes->SetValue(i, static_cast<unsigned char>(labels->GetValue(i)));
    }
    mask->GetPointData()->SetScalars(bytes);
    cases.push_back({ "binary mask",
      Shell(),
      Property(),
      [mask](vtkAVSVolumeMapper* m)
      {
        m->SetMaskInput(mask);
        m->SetMaskTypeToBinary();
      } });
    auto labelled = Property();
    vtkNew<vtkColorTransferFunction> red;
    red->AddRGBPoint(0, 1, 0.2, 0.1);
    vtkNew<vtkPiecewiseFunction> low;
    low->AddPoint(0, 0.0);
    low->AddPoint(200, 0.3); // opacity where the unlabelled function has none
    low->AddPoint(900, 0.3);
    labelled->SetLabelColor(1, red);
    labelled->SetLabelScalarOpacity(1, low);
    cases.push_back({ "label map",
      Shell(),
      labelled,
      [mask](vtkAVSVolumeMapper* m)
      {
        m->SetMaskInput(mask);
        m->SetMaskTypeToLabelMap();
        m->SetMaskBlendFactor(0.7f);
      },
      true,
      0.0 });
  }
  {
    auto image = MakeTestImage(N);
    image->GetPointData()->SetScalars(AddArray(image, "two", 2, false, ShellAndSlab));
    auto independent = Property();
    independent->IndependentComponentsOn();
    independent->SetColor(1, independent->GetRGBTransferFunction(0));
    independent->SetScalarOpacity(1, independent->GetScalarOpacity(0));
    independent->SetScalarOpacityUnitDistance(1, 0.15);
    cases.push_back({ "independent components", image, independent, nullptr, true, 0.1 });
    auto dependent = Property();
    dependent->IndependentComponentsOff();
    cases.push_back({ "dependent components", image, dependent, nullptr, true, 0.1 });
  }
  {
    auto image = MakeTestImage(N);
    image->GetPointData()->SetScalars(AddArray(image, "nan", 1, false, ShellWithNaN));
    cases.push_back({ "NaN voxels", image, Property(), nullptr });
  }
  {
    auto gradient = Property();
    vtkNew<vtkPiecewiseFunction> g;
    g->AddPoint(0, 0.2);
    g->AddPoint(200, 1.0);
    gradient->SetGradientOpacity(g);
    cases.push_back({ "gradient opacity", Shell(), gradient, nullptr });
  }
  cases.push_back(
    { "bricks", Shell(), Property(), [](vtkAVSVolumeMapper* m) { m->SetPartitions(2, 2, 1); } });
  // A light grid coarse enough that ambient scattering reads its lights once per four samples
  // (ScatteringParameters::LightGroup): a leap lands inside a group, whose samples before the
  // leap's end the ray takes again; unsplit and in bricks.
  auto coarseLights = [](vtkAVSVolumeMapper* m)
  {
    if (auto* as = vtkAmbientScatteringVolumeMapper::SafeDownCast(m))
    {
      as->SetLightVolumeMaximumDimension(16);
    }
  };
  cases.push_back({ "lights per four samples", Shell(), Property(), coarseLights });
  // Forward scattering: the extended model's rays read phi at the group before too, where that
  // group has no material (its slope along the ray), beyond the light volumes' reach.
  cases.push_back({ "lights per four samples, forward scattering",
    Shell(),
    Property(),
    [coarseLights](vtkAVSVolumeMapper* m)
    {
      coarseLights(m);
      if (auto* as = vtkAmbientScatteringVolumeMapper::SafeDownCast(m))
      {
        as->SetAnisotropy(0.6);
      }
    } });
  {
    // A small ball in a box of empty space: the light-volume pass marches only the tiles of the
    // light grid that something reads near occupied cells (LightTiles.h); with a large ambient
    // radius the averaged extinction reaches far from the material, and the extended model's
    // diffusion reads the light volumes r beyond that.
    auto ball = MakeTestImage(N);
    ball->GetPointData()->SetScalars(AddArray(ball, "ball", 1, false, SmallBall));
    cases.push_back({ "small ball", ball, Property(), nullptr, true, 0.6 });
    cases.push_back({ "small ball, large ambient radius",
      ball,
      Property(),
      [](vtkAVSVolumeMapper* m)
      {
        if (auto* as = vtkAmbientScatteringVolumeMapper::SafeDownCast(m))
        {
          as->SetAmbientRadius(0.3);
        }
      },
      true,
      0.6 });
  }
  {
    // A dense slab with a radius far beyond the rays' reach: the extended model's diffusion
    // reads the light volumes r downstream of its cells that are not vacuum, outside the tiles
    // that the rays read (the light-volume pass marches those the GPU flags from those cells).
    auto slab = MakeTestImage(N);
    slab->GetPointData()->SetScalars(AddArray(slab, "slab", 1, false, DenseSlab));
    cases.push_back({ "dense slab, large ambient radius",
      slab,
      Property(),
      [](vtkAVSVolumeMapper* m)
      {
        if (auto* as = vtkAmbientScatteringVolumeMapper::SafeDownCast(m))
        {
          as->SetAmbientRadius(1.4);
        }
      },
      true,
      0.4 });
  }
  cases.push_back({ "bricks, lights per four samples",
    Shell(),
    Property(),
    [coarseLights](vtkAVSVolumeMapper* m)
    {
      coarseLights(m);
      m->SetPartitions(2, 2, 1);
    } });
  cases.push_back(
    { "jittered", Shell(), Property(), [](vtkAVSVolumeMapper* m) { m->UseJitteringOn(); } });
  cases.push_back({ "image sample distance 2",
    Shell(),
    Property(),
    [](vtkAVSVolumeMapper* m)
    {
      m->AutoAdjustSampleDistancesOff();
      m->SetImageSampleDistance(2.0f);
    } });
  {
    auto band = Property();
    vtkNew<vtkPiecewiseFunction> o;
    o->AddPoint(0, 0.0);
    o->AddPoint(640, 0.0);
    o->AddPoint(650, 0.8);
    o->AddPoint(660, 0.0);
    band->SetScalarOpacity(o);
    cases.push_back({ "narrow band", Shell(), band, nullptr, true, 0.4 });
  }
  cases.push_back({ "maximum intensity",
    Shell(),
    Property(),
    [](vtkAVSVolumeMapper* m) { m->SetBlendModeToMaximumIntensity(); },
    false });

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, Size, Size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  int failures = 0;
  int compared = 0;
  for (const Case& c : cases)
  {
    for (int m = 0; m < 4; ++m)
    {
      if (c.Name == "maximum intensity" && m != 0)
      {
        continue; // an EA blend mode
      }
      const char* names[4] = { "EA", "AO", "AS paper", "AS extended" };
      vtkSmartPointer<vtkAVSVolumeMapper> mappers[2];
      vtkSmartPointer<vtkImageData> pictures[2];
      for (int skip = 0; skip < 2; ++skip)
      {
        vtkSmartPointer<vtkAVSVolumeMapper> mapper;
        if (m == 0)
          mapper = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
        else if (m == 1)
          mapper = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
        else
        {
          auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
          if (m == 2)
            as->SetScatteringModelToPaper();
          mapper = as;
        }
        mapper->SetInputData(c.Data);
        mapper->SetSampleDistance(0.025);
        mapper->UseJitteringOff();
        if (c.Configure)
        {
          c.Configure(mapper);
        }
        mapper->SetEmptySpaceSkipping(skip);
        pictures[skip] = RenderVolume(window, renderer, mapper, c.Property);
        mappers[skip] = mapper;
      }
      const std::string what = c.Name + ", " + names[m];
      const int most = MaximumDifference(pictures[0], pictures[1]);
      const double fraction = mappers[1]->GetLastEmptyCellFraction();
      const bool leapt = mappers[1]->GetLastSkippedEmptySpace() != 0;
      std::cout << what << ": largest difference " << most << " levels, " << fraction * 100.0
                << " % of the cells empty, " << (leapt ? "leapt" : "did not leap")
                << ", brightness " << Brightness(pictures[0]) << "\n";
      ++compared;
      if (most > 1)
      {
        std::cerr << "FAIL: " << what << ": the picture changed with empty-space skipping (" << most
                  << " levels)\n";
        ++failures;
      }
      if (leapt != c.Leaps || mappers[0]->GetLastSkippedEmptySpace())
      {
        std::cerr << "FAIL: " << what << ": expected " << (c.Leaps ? "a leap" : "no leap")
                  << " with skipping on and none with it off\n";
        ++failures;
      }
      if (c.Leaps && fraction < c.MostEmpty)
      {
        std::cerr << "FAIL: " << what << ": only " << fraction * 100.0
                  << " % of the cells empty, expected at least " << c.MostEmpty * 100.0 << "\n";
        ++failures;
      }
      if (!(Brightness(pictures[0]) > 0.0))
      {
        std::cerr << "FAIL: " << what << ": nothing drawn\n";
        ++failures;
      }
    }
  }
  {
    // The grid follows the mapper's input: the same mapper, after a transfer function that
    // gives opacity where the last one had none and after new data, draws what a mapper without
    // skipping draws.
    auto band = Property();
    vtkNew<vtkPiecewiseFunction> low;
    low->AddPoint(0, 0.03); // a haze where the last function left empty space
    low->AddPoint(100, 0.2);
    low->AddPoint(900, 0.5);
    auto moved = MakeTestImage(N);
    moved->GetPointData()->SetScalars(AddArray(moved, "slab", 1, false, SlabValue));
    for (int m = 0; m < 2; ++m)
    {
      vtkSmartPointer<vtkAVSVolumeMapper> live, fresh;
      if (m == 0)
      {
        live = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
        fresh = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
      }
      else
      {
        live = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
        fresh = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
      }
      for (vtkAVSVolumeMapper* mapper : { live.Get(), fresh.Get() })
      {
        mapper->SetSampleDistance(0.025);
        mapper->UseJitteringOff();
      }
      fresh->EmptySpaceSkippingOff();
      auto property = Property();
      live->SetInputData(cases[0].Data);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(live);
      volume->SetProperty(property);
      renderer->AddVolume(volume);
      window->Render(); // the grid of the first transfer function
      const double before = live->GetLastEmptyCellFraction();
      property->GetScalarOpacity()->DeepCopy(low);
      renderer->ResetCameraClippingRange();
      window->Render();
      auto changed = Grab(window);
      const double after = live->GetLastEmptyCellFraction();
      live->SetInputData(moved);
      window->Render();
      auto data = Grab(window);
      renderer->RemoveVolume(volume);
      fresh->SetInputData(cases[0].Data);
      const int tf = MaximumDifference(changed, RenderVolume(window, renderer, fresh, property));
      fresh->SetInputData(moved);
      const int input = MaximumDifference(data, RenderVolume(window, renderer, fresh, property));
      std::cout << (m == 0 ? "EA" : "AS") << " after a transfer-function change: " << tf
                << " levels (" << before * 100.0 << " % then " << after * 100.0
                << " % of the cells empty); after new data: " << input << " levels\n";
      if (tf > 1 || input > 1 || !(after < before))
      {
        std::cerr << "FAIL: the grid did not follow a transfer-function change or new data\n";
        ++failures;
      }
    }
  }
  {
    // Forward scattering with the lights once per four samples (light cells of 3.3 voxels), kept
    // from a haze everywhere to the small ball alone: the rays read phi at the group before (its
    // slope), where that group may have no material, so the fluence must be current there too,
    // not what the haze left.
    auto configure = [](vtkAmbientScatteringVolumeMapper* m)
    {
      m->SetLightVolumeMaximumDimension(20);
      m->SetAnisotropy(0.6);
      m->SetSampleDistance(0.025);
      m->UseJitteringOff();
    };
    vtkNew<vtkAmbientScatteringVolumeMapper> live, fresh;
    configure(live);
    configure(fresh);
    fresh->EmptySpaceSkippingOff();
    auto haze = Property();
    vtkNew<vtkPiecewiseFunction> everywhere;
    everywhere->AddPoint(0, 0.05);
    everywhere->AddPoint(900, 0.5);
    haze->SetScalarOpacity(everywhere);
    auto ballData = MakeTestImage(N);
    ballData->GetPointData()->SetScalars(AddArray(ballData, "ball", 1, false, SmallBall));
    live->SetInputData(ballData);
    RenderVolume(window, renderer, live, haze);
    auto kept = RenderVolume(window, renderer, live, Property());
    fresh->SetInputData(ballData);
    const int most = MaximumDifference(kept, RenderVolume(window, renderer, fresh, Property()));
    std::cout << "AS forward scattering kept from a haze to the ball: " << most << " levels\n";
    if (most > 1)
    {
      std::cerr << "FAIL: the fluence the rays read at the group before was not current (" << most
                << " levels)\n";
      ++failures;
    }
  }
  {
    // A radius beyond the ring: ambient scattering's explicit look-ahead does not leap.
    vtkNew<vtkAmbientScatteringVolumeMapper> as;
    as->SetInputData(cases[0].Data);
    as->SetSampleDistance(0.01);
    as->SetAmbientRadius(8.0);
    as->UseJitteringOff();
    RenderVolume(window, renderer, as, cases[0].Property);
    if (as->GetLastSkippedEmptySpace())
    {
      std::cerr << "FAIL: the explicit look-ahead leapt\n";
      ++failures;
    }
  }
  std::cout << compared << " pairs of pictures compared, " << failures << " failure(s)\n";
  return failures == 0 ? 0 : 1;
}
