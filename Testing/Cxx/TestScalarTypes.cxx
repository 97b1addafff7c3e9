// Every scalar type the mappers take: char, signed char, unsigned char,
// short, unsigned short, int, unsigned int, float and double. 8- and 16-bit scalars go to the
// GPU as normalized texels (signed ones with the sign bit flipped, vtkAVSTextureUpload.h), the
// rest as floats, and the shader maps them back to data values. For each type three volumes:
//   full  the lumpy shell over the type's whole range (floats and doubles over +-1e6 and +-1e20),
//   low   for 8- and 16-bit types, the type's four lowest values (the minimum, where a signed
//         normalized texel would clamp it onto the value above), the transfer function over
//         just them, non-monotone, with nearest interpolation: the values themselves;
//   high  the four highest values the same way (a scale off by one step shows there).
// EA's picture against the CPU reference: >= 60 dB for the full range, >= 50 dB for low and
// high (a texel mapped one step off gives about 25 dB there; what is left at 57-64 dB is the
// single-precision transfer-function coordinate of a range 3 wide at values up to 65535, which
// float volumes share). Linear interpolation across one step of an 8-bit texture is not exact
// on llvmpipe, which filters 8-bit texels in 8-bit fixed point (ARCHITECTURE.md, "Texel
// formats"); the full range checks it at the scale of a transfer function over the type's range.
// AO and ambient scattering for the
// full range against the same mapper's picture of the same values in a float array (>= 60 dB),
// which is the texture path checked alone.
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkDataArray.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkVolumeReferenceRenderer.h"

#include <cmath>
#include <iostream>
#include <limits>

namespace
{
struct TypeCase
{
  int Type;
  const char* Name;
  double Lowest, Highest; // the values used: the type's range (floats: a wide one)
};

template<typename T>
TypeCase Of(int type, const char* name)
{
  return { type,
    name,
    static_cast<double>(std::numeric_limits<T>::lowest()),
    static_cast<double>(std::numeric_limits<T>::max()) };
}

// The shell's values (0-900) mapped onto [lo, hi] (case 0), or onto the four values from lo
// (case 1) or up to hi (case 2), rounded to integers for integer types.
vtkSmartPointer<vtkImageData> MakeVolume(const TypeCase& t, int which, bool asFloat)
{
  auto image = MakeTestImage(32);
  vtkFloatArray* f = AddArray(image, "v", 1, false, ShellValue);
  auto a = vtkSmartPointer<vtkDataArray>::Take(
    vtkDataArray::CreateDataArray(asFloat ? VTK_FLOAT : t.Type));
  a->SetName("scalars");
  a->SetNumberOfTuples(f->GetNumberOfTuples());
  const bool integer = t.Type != VTK_FLOAT && t.Type != VTK_DOUBLE;
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
  {
    const double s = f->GetValue(i) / 900.0; // [0, 1]
    double v;
    if (which == 0)
    {
      v = t.Lowest + s * (t.Highest - t.Lowest);
      // Integers of 32 bits become floats anyway; rounding keeps 8 and 16 bits exact.
      v = integer ? std::round(std::clamp(v, t.Lowest, t.Highest)) : v;
    }
    else
    {
      const double level = std::round(3.0 * s);
      v = which == 1 ? t.Lowest + level : t.Highest - 3.0 + level;
    }
    a->SetTuple1(i, v);
  }
  image->GetPointData()->SetScalars(a);
  return image;
}

// A property over [lo, hi]: case 0 the test property's shape stretched, else a non-monotone
// opacity and colour on the four levels.
vtkSmartPointer<vtkVolumeProperty> MakeProperty(double lo, double hi, int which)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  const double w = hi - lo;
  if (which == 0)
  {
    color->AddRGBPoint(lo, 0.2, 0.3, 0.9);
    color->AddRGBPoint(lo + w * 400.0 / 900.0, 0.9, 0.6, 0.3);
    color->AddRGBPoint(hi, 1.0, 0.95, 0.9);
    opacity->AddPoint(lo, 0.0);
    opacity->AddPoint(lo + w * 250.0 / 900.0, 0.0);
    opacity->AddPoint(lo + w * 600.0 / 900.0, 0.15);
    opacity->AddPoint(hi, 0.5);
  }
  else
  {
    const double levels[4] = { lo, lo + w / 3.0, lo + 2.0 * w / 3.0, hi };
    const double alpha[4] = { 0.0, 0.6, 0.05, 0.4 };
    const double rgb[4][3] = { { 0, 0, 0 }, { 1.0, 0.2, 0.1 }, { 0.1, 1.0, 0.2 }, { 0.2, 0.3, 1 } };
    for (int l = 0; l < 4; ++l)
    {
      color->AddRGBPoint(levels[l], rgb[l][0], rgb[l][1], rgb[l][2]);
      opacity->AddPoint(levels[l], alpha[l]);
    }
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.1);
  if (which == 0)
  {
    property->SetInterpolationTypeToLinear();
  }
  else
  {
    property->SetInterpolationTypeToNearest();
  }
  return property;
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  const int size = 96;
  const double step = 0.02;

  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  TypeCase types[] = { Of<char>(VTK_CHAR, "char"),
    Of<signed char>(VTK_SIGNED_CHAR, "signed_char"),
    Of<unsigned char>(VTK_UNSIGNED_CHAR, "unsigned_char"),
    Of<short>(VTK_SHORT, "short"),
    Of<unsigned short>(VTK_UNSIGNED_SHORT, "unsigned_short"),
    Of<int>(VTK_INT, "int"),
    Of<unsigned int>(VTK_UNSIGNED_INT, "unsigned_int"),
    { VTK_FLOAT, "float", -1e6, 1e6 },
    { VTK_DOUBLE, "double", -1e20, 1e20 } };
  const char* cases[3] = { "full", "low", "high" };

  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ao->SetOcclusionRadius(0.15);
  as->SetAmbientRadius(0.08);
  as->SetAnisotropy(0.4);
  for (const TypeCase& t : types)
  {
    // The lowest and highest four values for the normalized texels (8 and 16 bits).
    const bool ends = t.Highest - t.Lowest < 65536.0;
    for (int which = 0; which < (ends ? 3 : 1); ++which)
    {
      auto data = MakeVolume(t, which, false);
      double range[2];
      data->GetPointData()->GetScalars()->GetRange(range);
      auto property = MakeProperty(range[0], range[1], which);
      const std::string tag = std::string(t.Name) + "_" + cases[which];

      vtkNew<TestErrorObserver> errors;
      ea->AddObserver(vtkCommand::ErrorEvent, errors);
      ea->SetInputData(data);
      ea->SetSampleDistance(step);
      ea->UseJitteringOff();
      auto picture = RenderVolume(window, renderer, ea, property, dir, "types_ea_" + tag);
      vtkNew<vtkVolumeReferenceRenderer> cpu;
      cpu->SetInputData(data);
      cpu->SetVolumeProperty(property);
      cpu->SetRenderer(renderer);
      cpu->SetImageSize(size, size);
      cpu->SetSampleDistance(step);
      cpu->SetRenderMode(vtkVolumeReferenceRenderer::EMISSION_ABSORPTION);
      cpu->Update();
      const double psnr = Psnr(picture, cpu->GetOutput());
      std::cout << "ea " << tag << ": against the CPU reference " << psnr << " dB\n";
      AVS_CHECK(errors->Errors == 0);
      AVS_CHECK(Brightness(picture) > 1000.0);
      AVS_CHECK(psnr >= (which == 0 ? 60.0 : 50.0));
      ea->RemoveObserver(errors);

      if (which == 0)
      {
        auto floats = MakeVolume(t, which, true);
        vtkAVSVolumeMapper* lit[2] = { ao, as };
        const char* names[2] = { "ao", "as" };
        for (int m = 0; m < 2; ++m)
        {
          vtkNew<TestErrorObserver> litErrors;
          lit[m]->AddObserver(vtkCommand::ErrorEvent, litErrors);
          lit[m]->SetSampleDistance(step);
          lit[m]->UseJitteringOff();
          lit[m]->SetInputData(data);
          auto native = RenderVolume(
            window, renderer, lit[m], property, dir, std::string("types_") + names[m] + "_" + tag);
          lit[m]->SetInputData(floats);
          auto asFloats = RenderVolume(window, renderer, lit[m], property);
          const double same = Psnr(native, asFloats);
          std::cout << names[m] << " " << tag << ": against the same values as floats " << same
                    << " dB\n";
          AVS_CHECK(litErrors->Errors == 0);
          AVS_CHECK(Brightness(native) > 1000.0);
          AVS_CHECK(same >= 60.0);
          lit[m]->RemoveObserver(litErrors);
        }
      }
    }
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
