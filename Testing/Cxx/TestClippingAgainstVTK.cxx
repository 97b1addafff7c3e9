// Clipping planes and cropping of vtkEmissionAbsorptionVolumeMapper against VTK's own
// vtkGPUVolumeRayCastMapper (unshaded, same sample distance, no jittering): 1, 3 and 6 planes,
// planes with a rotated, scaled and moved vtkVolume, VTK's cropping presets and other region
// flags, and cropping with planes. Each case: PSNR >= 52 dB against VTK's picture, and VTK's
// clipped picture differs from its unclipped one, so that a mapper ignoring the
// setting would fail (VTK's clipped picture against its unclipped one: < 33 dB).
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPNGWriter.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct PlaneSpec
{
  double Origin[3];
  double Normal[3];
};

struct Case
{
  std::string Name;
  std::vector<PlaneSpec> Planes;
  int CropFlags = -1; ///< -1: no cropping
  bool Transformed = false;
  bool NarrowCropping = false; ///< cropping planes near the centre instead of the wider ones
};

// VTK 9.1's ray caster maps its texture coordinates to data coordinates as if the texel
// centres of N points spanned the whole box, so it clips and crops where the data coordinates
// are k = (N - 1) / N times their distance from the box centre: a plane at distance d from the
// centre acts at d / k (up to half a voxel further out, at the box faces). Our mappers clip
// where the planes are (the CPU reference and the path tracer agree). For the comparison, VTK's
// mapper is handed the planes moved towards the centre by that factor, which puts its effective
// planes where ours are; `world` maps data to world (the volume's matrix).
//
// VTK changed, not ours: after VTK 9.3 its mapper clips where the clipping planes are (k = 1 for
// planes; cropping keeps k = (N - 1) / N). Handed the 9.1 correction, VTK 9.6 measured 34.8-52.3
// dB against our unchanged pictures (planes6, planes3, plane1); without it, 57.7-62.7 dB, what
// VTK 9.1 measures with it. VTK 9.3 still needs it (without: 33.4-55.5 dB); 9.4 and 9.5 were not
// tried. Cropping without the correction measured 38-49 dB in 9.3 and 9.6.
//
// MakeTestVolume(40): 40 points on every axis. K: cropping; KPlanes: clipping planes.
constexpr double Points = 40.0;
constexpr double K = (Points - 1.0) / Points;
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
constexpr double KPlanes = 1.0;
#else
constexpr double KPlanes = K;
#endif
const double Centre[3] = { -0.025, -0.025, -0.03 }; // the test volume's box centre (data)

void Configure(vtkVolumeMapper* mapper, const Case& c, vtkMatrix4x4* world, bool forVTK)
{
  double centre[4] = { Centre[0], Centre[1], Centre[2], 1.0 };
  world->MultiplyPoint(centre, centre);
  mapper->RemoveAllClippingPlanes();
  for (const PlaneSpec& p : c.Planes)
  {
    vtkNew<vtkPlane> plane;
    double o[3];
    for (int a = 0; a < 3; ++a)
    {
      o[a] = forVTK ? centre[a] + KPlanes * (p.Origin[a] - centre[a]) : p.Origin[a];
    }
    plane->SetOrigin(o);
    plane->SetNormal(p.Normal[0], p.Normal[1], p.Normal[2]);
    mapper->AddClippingPlane(plane);
  }
  mapper->SetCropping(c.CropFlags >= 0);
  double crop[6] = { -0.35, 0.4, -0.3, 0.45, -0.5, 0.3 };
  if (c.NarrowCropping)
  {
    const double narrow[6] = { -0.15, 0.1, -0.1, 0.15, -0.2, 0.1 };
    std::copy(narrow, narrow + 6, crop);
  }
  for (int i = 0; forVTK && i < 6; ++i)
  {
    crop[i] = Centre[i / 2] + K * (crop[i] - Centre[i / 2]);
  }
  mapper->SetCroppingRegionPlanes(crop);
  if (c.CropFlags >= 0)
  {
    mapper->SetCroppingRegionFlags(c.CropFlags);
  }
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 128;
  auto data = MakeTestVolume();
  auto property = MakeTestProperty();
  property->ShadeOff();

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  const double sampleDistance = 0.005;
  vtkNew<vtkGPUVolumeRayCastMapper> vtkMapper;
  vtkMapper->SetInputData(data);
  vtkMapper->SetSampleDistance(sampleDistance);
  vtkMapper->SetAutoAdjustSampleDistances(0);
  vtkMapper->SetUseJittering(0);
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ours;
  ours->SetInputData(data);
  ours->SetSampleDistance(sampleDistance);
  ours->UseJitteringOff();
  vtkNew<TestErrorObserver> errors;
  ours->AddObserver(vtkCommand::ErrorEvent, errors);

  const std::vector<PlaneSpec> six = { { { 0.5, 0, 0 }, { -1, 0.1, 0 } },
    { { -0.6, 0, 0 }, { 1, 0, 0.2 } },
    { { 0, 0.55, 0 }, { 0, -1, 0.1 } },
    { { 0, -0.5, 0 }, { 0.1, 1, 0 } },
    { { 0, 0, 0.6 }, { 0.2, 0, -1 } },
    { { 0, 0, -0.7 }, { 0, 0.1, 1 } } };
  std::vector<Case> cases;
  cases.push_back({ "plane1", { { { 0.15, 0.0, 0.1 }, { -1.0, 0.3, -0.4 } } } });
  cases.push_back({ "planes3", { six[0], six[2], six[4] } });
  cases.push_back({ "planes6", six });
  cases.push_back({ "planes2_transformed",
    { { { 0.6, 0.2, 0.0 }, { -1.0, -0.2, -0.6 } }, { { 0.0, 0.0, 0.5 }, { 0.0, 0.3, -1.0 } } },
    -1,
    true });
  cases.push_back({ "subvolume", {}, VTK_CROP_SUBVOLUME });
  cases.push_back({ "fence", {}, VTK_CROP_FENCE, false, true });
  cases.push_back({ "inverted_fence", {}, VTK_CROP_INVERTED_FENCE });
  cases.push_back({ "cross", {}, VTK_CROP_CROSS });
  cases.push_back({ "inverted_cross", {}, VTK_CROP_INVERTED_CROSS });
  // All regions but two (the corner nearest the camera and the one below it), and two
  // regions alone.
  cases.push_back({ "all_but_two", {}, 0x7ffffff & ~((1 << 26) | (1 << 17)), false, true });
  cases.push_back({ "two_regions", {}, (1 << 0) | (1 << 22) });
  cases.push_back(
    { "cross_and_plane", { { { 0.0, 0.0, 0.0 }, { -0.3, -1.0, 0.2 } } }, VTK_CROP_INVERTED_CROSS });
  cases.push_back({ "fence_transformed",
    { { { 0.0, 0.6, 0.0 }, { 0.0, -1.0, 0.0 } } },
    VTK_CROP_FENCE,
    true,
    true });

  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkImageData> pictures[3];
    for (int which = 0; which < 3; ++which)
    {
      // 0: VTK's, 1: ours, 2: VTK's without the clipping (to show the case matters).
      vtkVolumeMapper* mapper = which == 1 ? static_cast<vtkVolumeMapper*>(ours) : vtkMapper;
      vtkNew<vtkVolume> volume;
      volume->SetProperty(property);
      volume->SetMapper(mapper);
      if (c.Transformed)
      {
        volume->SetOrientation(10, 35, -20);
        volume->SetScale(1.2, 0.8, 1.1);
        volume->SetPosition(0.1, -0.15, 0.05);
      }
      Configure(mapper,
        which == 2 ? Case{ c.Name, {}, -1, c.Transformed } : c,
        volume->GetMatrix(),
        which != 1);
      renderer->AddVolume(volume);
      renderer->ResetCameraClippingRange();
      window->Render();
      pictures[which] = Grab(window);
      renderer->RemoveVolume(volume);
      if (which < 2)
      {
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName((dir + "/clip_" + c.Name + (which ? "_ours.png" : "_vtk.png")).c_str());
        writer->SetInputData(pictures[which]);
        writer->Write();
      }
    }
    const double psnr = Psnr(pictures[0], pictures[1]);
    const double matters = Psnr(pictures[0], pictures[2]);
    std::cout << c.Name << ": PSNR " << psnr << " dB against VTK (VTK clipped against unclipped "
              << matters << " dB; brightness VTK " << Brightness(pictures[0]) << ", ours "
              << Brightness(pictures[1]) << ")\n";
    AVS_CHECK(Brightness(pictures[0]) > 1000.0);
    // Measured 57.7-66.6 dB against VTK 9.1 and 9.6; 52 dB leaves about 6 dB for other drivers
    // (a 5 % brightness error: 30-38 dB).
    AVS_CHECK(psnr >= 52.0);
    AVS_CHECK(matters < 33.0); // what a mapper ignoring the setting would score
  }
  AVS_CHECK(errors->Errors == 0);

  // More planes than supported: an error, nothing drawn.
  {
    Case many{ "many", six };
    many.Planes.insert(many.Planes.end(), six.begin(), six.begin() + 3);
    vtkNew<vtkVolume> volume;
    Configure(ours, many, volume->GetMatrix(), false);
    volume->SetProperty(property);
    volume->SetMapper(ours);
    renderer->AddVolume(volume);
    errors->Clear();
    window->Render();
    auto picture = Grab(window);
    renderer->RemoveVolume(volume);
    std::cout << "9 planes: \"" << errors->LastError << "\"\n";
    AVS_CHECK(errors->Errors == 1);
    AVS_CHECK(errors->LastError.find("9 clipping planes") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
