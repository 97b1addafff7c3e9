// New data, as a time series brings it: one mapper kept through a series of steps draws at each
// step what a new mapper draws from that step alone (to the level), and uses what the step did
// not change (vtkAVSVolumeMapper::GetLastDataUploadFraction):
//  - a static series (the same values in a new image, four times) uploads and rebuilds nothing
//    and gives the same frame, bit for bit, every time;
//  - a step that changes 8 of 64 slices writes those slices alone (an eighth of the voxels; with
//    bricks, only the bricks that hold them);
//  - a step that moves the volume, or that goes back to an earlier step, writes every slice
//    with material (the empty slices at the ends stay);
//  - NaN voxels make the texels depend on the range, which any slice may change: everything.
// For EA, AO, and ambient scattering in the paper's and the extended model, on 16-bit data
// (unsplit and split into 2 x 2 x 2 bricks), float data with NaN voxels, and two independent
// components as cell data (the texture's slices are the cells').
#include "DataTestScene.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkShortArray.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int N = 64;     // voxels per axis
constexpr int Size = 128; // pixels
// The slices a local change touches: two slabs of the mappers' four-slice fingerprints.
constexpr int ChangedFrom = 20, ChangedTo = 28;

// A new image with the values of `source` (another object and array: as a reader's next step).
vtkSmartPointer<vtkImageData> Copy(vtkImageData* source)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(source);
  return image;
}

// The image's scalars: N^3 point values, or the cell values of an image of (N + 1)^3 points.
vtkDataArray* Values(vtkImageData* image)
{
  vtkDataArray* points = image->GetPointData()->GetScalars();
  return points ? points : image->GetCellData()->GetScalars();
}

// `source` with a dense block in the slices [ChangedFrom, ChangedTo) (every component).
vtkSmartPointer<vtkImageData> LocallyChanged(vtkImageData* source)
{
  auto image = Copy(source);
  vtkDataArray* a = Values(image);
  for (int k = ChangedFrom; k < ChangedTo; ++k)
    for (int j = 10; j < 30; ++j)
      for (int i = 16; i < 48; ++i)
      {
        const vtkIdType id = (static_cast<vtkIdType>(k) * N + j) * N + i;
        for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        {
          a->SetComponent(id, c, 700.0);
        }
      }
  return image;
}

// `source` moved by 5 voxels along x (every slice with material changes).
vtkSmartPointer<vtkImageData> Moved(vtkImageData* source)
{
  auto image = Copy(source);
  vtkDataArray* from = Values(source);
  vtkDataArray* to = Values(image);
  for (vtkIdType id = 0; id < to->GetNumberOfTuples(); ++id)
  {
    const vtkIdType i = id % N;
    for (int c = 0; c < to->GetNumberOfComponents(); ++c)
    {
      to->SetComponent(id, c, from->GetComponent(id - i + (i + N - 5) % N, c));
    }
  }
  return image;
}

// The shell and the slab, two components.
std::array<double, 4> ShellAndSlab(double x, double y, double z)
{
  return { ShellValue(x, y, z)[0], SlabValue(x, y, z)[0], 0, 0 };
}

// Two components (the shell and the slab) as cell data: N^3 cells.
vtkSmartPointer<vtkImageData> TwoComponentCells()
{
  auto image = MakeTestImage(N + 1);
  image->GetCellData()->SetScalars(AddArray(image, "two", 2, true, ShellAndSlab));
  return image;
}

vtkSmartPointer<vtkImageData> FloatsWithNaN()
{
  auto image = MakeTestImage(N);
  image->GetPointData()->SetScalars(AddArray(image,
    "nan",
    1,
    false,
    [](double x, double y, double z)
    {
      return std::array<double, 4>{
        std::abs(x - y) < 0.08 ? std::nan("") : ShellValue(x, y, z)[0], 0, 0, 0
      };
    }));
  return image;
}

vtkSmartPointer<vtkAVSVolumeMapper> NewMapper(int kind, bool bricks)
{
  vtkSmartPointer<vtkAVSVolumeMapper> m;
  if (kind == 0)
    m = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
  else if (kind == 1)
    m = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
  else
  {
    auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    if (kind == 2)
      as->SetScatteringModelToPaper();
    m = as;
  }
  m->SetSampleDistance(0.03);
  m->UseJitteringOff();
  if (bricks)
  {
    m->SetPartitions(2, 2, 2);
  }
  return m;
}

long Rebuilds(vtkAVSVolumeMapper* m)
{
  return m->GetNumberOfDataUploads() + m->GetNumberOfExtinctionRebuilds() +
    m->GetNumberOfLightVolumeRebuilds() + m->GetNumberOfOcclusionRebuilds() +
    m->GetNumberOfDiffusionRebuilds();
}

struct Step
{
  std::string Name;
  vtkSmartPointer<vtkImageData> Data;
  double LeastFraction, MostFraction; ///< of the voxels written (0: nothing uploaded)
};
} // namespace

int main(int, char*[])
{
  // The kept mapper's window, and another for the new mappers (a volume removed from a
  // renderer releases its mapper's graphics resources).
  vtkNew<vtkRenderWindow> window, other;
  vtkNew<vtkRenderer> renderer, otherRenderer;
  PrepareTestWindow(window, Size, Size);
  PrepareTestWindow(other, Size, Size);
  window->AddRenderer(renderer);
  other->AddRenderer(otherRenderer);
  for (vtkRenderer* r : { renderer.Get(), otherRenderer.Get() })
  {
    AddTestLights(r);
    PlaceTestCamera(r->GetActiveCamera());
  }
  auto single = MakeTestProperty();

  int failures = 0;
  const char* kinds[4] = { "EA", "AO", "AS paper", "AS extended" };
  // Two independent components share the first's functions.
  auto independent = MakeTestProperty();
  independent->IndependentComponentsOn();
  independent->SetColor(1, independent->GetRGBTransferFunction(0));
  independent->SetScalarOpacity(1, independent->GetScalarOpacity(0));
  independent->SetScalarOpacityUnitDistance(1, independent->GetScalarOpacityUnitDistance(0));
  for (int data = 0; data < 4; ++data)
  {
    const bool bricks = data == 1, nan = data == 2, cells = data == 3;
    const std::string series = cells
      ? "two components, cell data"
      : (nan ? "floats with NaN" : (bricks ? "16 bits, bricks" : "16 bits"));
    auto first = cells ? TwoComponentCells() : (nan ? FloatsWithNaN() : MakeTestVolume(N));
    vtkVolumeProperty* property = cells ? independent.Get() : single.Get();
    const double local = static_cast<double>(ChangedTo - ChangedFrom) / N;
    // (Bricks count their shared and ghost layers: more than the volume's voxels.)
    std::vector<Step> steps = { { "first", first, 1.0, 2.0 } };
    for (int s = 0; s < 4; ++s)
    {
      steps.push_back({ "static " + std::to_string(s + 1), Copy(first), 0.0, 0.0 });
    }
    auto changed = LocallyChanged(first);
    // Unsplit: the eight slices. Bricks: those slices of the lower bricks alone (which hold a
    // little more than half of each slice: the shared and ghost layers), none of the upper.
    steps.push_back({ "8 of 64 slices changed",
      changed,
      nan ? 1.0 : local,
      nan ? 2.0 : (bricks ? 2.0 * local : local) });
    // Moving along x changes the slices with material: all but the empty eighth at the ends.
    steps.push_back({ "moved", Moved(changed), 0.85, 2.0 });
    steps.push_back({ "the first again", Copy(first), 0.85, 2.0 });
    for (int kind = 0; kind < 4; ++kind)
    {
      auto mapper = NewMapper(kind, bricks);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(property);
      renderer->AddVolume(volume);
      vtkSmartPointer<vtkImageData> firstPicture;
      for (const Step& step : steps)
      {
        const long before = Rebuilds(mapper);
        const int uploads = mapper->GetNumberOfDataUploads();
        mapper->SetInputData(step.Data);
        renderer->ResetCameraClippingRange();
        window->Render();
        auto picture = Grab(window);
        // What a new mapper draws from this step alone.
        auto fresh = NewMapper(kind, bricks);
        fresh->SetInputData(step.Data);
        auto expected = RenderVolume(other, otherRenderer, fresh, property);
        const int most = MaximumDifference(picture, expected);
        const bool uploaded = mapper->GetNumberOfDataUploads() > uploads;
        const double fraction = mapper->GetLastDataUploadFraction();
        const std::string what = series + ", " + kinds[kind] + ", " + step.Name;
        std::cout << what << ": " << (uploaded ? "uploaded" : "not uploaded") << ", "
                  << fraction * 100.0 << " % of the voxels written, " << Rebuilds(mapper) - before
                  << " uploads and rebuilds, largest difference from a new mapper " << most
                  << " levels\n";
        if (most > 0)
        {
          std::cerr << "FAIL: " << what << ": the kept mapper's picture differs from a new "
                    << "mapper's by " << most << " levels\n";
          ++failures;
        }
        if (fraction < step.LeastFraction - 1e-9 || fraction > step.MostFraction + 1e-9)
        {
          std::cerr << "FAIL: " << what << ": " << fraction * 100.0
                    << " % of the voxels written, expected " << step.LeastFraction * 100.0 << " to "
                    << step.MostFraction * 100.0 << " %\n";
          ++failures;
        }
        if (step.MostFraction == 0.0)
        {
          // A static step: nothing rebuilt, the first step's frame bit for bit.
          const int flicker = MaximumDifference(picture, firstPicture);
          if (Rebuilds(mapper) != before || flicker != 0)
          {
            std::cerr << "FAIL: " << what << ": " << Rebuilds(mapper) - before
                      << " uploads and rebuilds, frame differs from the first by " << flicker
                      << " levels\n";
            ++failures;
          }
        }
        if (step.Name == "first")
        {
          firstPicture = picture;
        }
        if (step.Name == "the first again" && MaximumDifference(picture, firstPicture) != 0)
        {
          std::cerr << "FAIL: " << what << ": not the first step's frame\n";
          ++failures;
        }
        if (Brightness(picture) < 1.0)
        {
          std::cerr << "FAIL: " << what << ": nothing drawn\n";
          ++failures;
        }
      }
      renderer->RemoveVolume(volume);
    }
  }
  if (failures)
  {
    std::cerr << failures << " failure(s)\n";
    return 1;
  }
  std::cout << "PASS\n";
  return 0;
}
