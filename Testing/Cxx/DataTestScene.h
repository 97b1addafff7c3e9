// Helpers of the tests of what data the mappers take (arrays, cell data, components, NaN,
// gradient opacity, masks): images filled from a function of the position, one render of a
// volume with any mapper, and the comparison with vtkGPUVolumeRayCastMapper or the reference.
#ifndef DataTestScene_h
#define DataTestScene_h

#include "MapperTestScene.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPNGWriter.h"
#include "vtkVolumeMapper.h"

#include <array>
#include <functional>
#include <string>

/// Normalised coordinates in [-1, 1]^3 of the test image (n points per axis) at the continuous
/// point index (i, j, k), centred like MakeTestVolume's.
using DataFunction = std::function<std::array<double, 4>(double x, double y, double z)>;

/// An image of n^3 points with MakeTestVolume's geometry (spacing, extent, origin).
inline vtkSmartPointer<vtkImageData> MakeTestImage(int n = 40)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(-n / 2, n - 1 - n / 2, -n / 2, n - 1 - n / 2, -n / 2, n - 1 - n / 2);
  image->SetSpacing(0.05, 0.05, 0.06);
  image->SetOrigin(0.0, 0.0, 0.0);
  return image;
}

/// A float array of `components` components sampled from f at the image's points (cells false)
/// or cell centres (cells true), added to the point or cell data under `name`.
inline vtkFloatArray* AddArray(vtkImageData* image,
  const char* name,
  int components,
  bool cells,
  const DataFunction& f)
{
  int dims[3];
  image->GetDimensions(dims);
  const int n[3] = {
    cells ? dims[0] - 1 : dims[0], cells ? dims[1] - 1 : dims[1], cells ? dims[2] - 1 : dims[2]
  };
  const double shift = cells ? 0.5 : 0.0;
  vtkNew<vtkFloatArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(n[0]) * n[1] * n[2]);
  vtkIdType id = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const double x = (i + shift - 0.5 * (dims[0] - 1)) / (0.5 * dims[0]);
        const double y = (j + shift - 0.5 * (dims[1] - 1)) / (0.5 * dims[1]);
        const double z = (k + shift - 0.5 * (dims[2] - 1)) / (0.5 * dims[2]);
        const std::array<double, 4> v = f(x, y, z);
        for (int c = 0; c < components; ++c)
        {
          a->SetTypedComponent(id, c, static_cast<float>(v[c]));
        }
        ++id;
      }
  if (cells)
  {
    image->GetCellData()->AddArray(a);
  }
  else
  {
    image->GetPointData()->AddArray(a);
  }
  return a;
}

/// MakeTestVolume's lumpy shell with a dense core, as a function (values 0-900).
inline std::array<double, 4> ShellValue(double x, double y, double z)
{
  const double r = std::sqrt(x * x + y * y + z * z);
  const double lumps = 0.5 + 0.5 * std::sin(7 * x) * std::cos(5 * y) * std::sin(6 * z + 1);
  double v = 0.0;
  if (r < 0.25)
    v = 900.0;
  else if (std::abs(r - 0.65) < 0.15)
    v = 300.0 + 500.0 * lumps;
  return { v, 0, 0, 0 };
}

/// Another field over the same range: a smooth slab tilted through the box.
inline std::array<double, 4> SlabValue(double x, double y, double z)
{
  const double d = 0.6 * x - 0.5 * y + 0.3 * z;
  return { 900.0 * std::exp(-12.0 * d * d) * (0.6 + 0.4 * std::cos(4 * y)), 0, 0, 0 };
}

/// One picture of `data` with `mapper` and `property` in `window` (its only renderer, the test
/// camera), written to dir/name.png when name is not empty.
inline vtkSmartPointer<vtkImageData> RenderVolume(vtkRenderWindow* window,
  vtkRenderer* renderer,
  vtkVolumeMapper* mapper,
  vtkVolumeProperty* property,
  const std::string& dir = std::string(),
  const std::string& name = std::string())
{
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  renderer->ResetCameraClippingRange();
  window->Render();
  auto picture = Grab(window);
  renderer->RemoveVolume(volume);
  if (!name.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName((dir + "/" + name + ".png").c_str());
    writer->SetInputData(picture);
    writer->Write();
  }
  return picture;
}

/// vtkGPUVolumeRayCastMapper set up as the tests compare with it: fixed sample distance, no
/// jittering.
inline void ConfigureVTKMapper(vtkGPUVolumeRayCastMapper* mapper, double sampleDistance)
{
  mapper->SetSampleDistance(sampleDistance);
  mapper->SetAutoAdjustSampleDistances(0);
  mapper->SetUseJittering(0);
}

#endif
