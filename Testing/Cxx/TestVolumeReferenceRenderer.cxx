// vtkVolumeReferenceRenderer: renders EA, AO and ambient scattering of a structured volume,
// honours the renderer's lights, and rejects bad input with an error and an empty output.
#include "TestErrorObserver.h"
#include "vtkVolumeReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkShortArray.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace
{
// A ball of density 1 inside a 24^3 image with short scalars (not float: any type works).
vtkSmartPointer<vtkImageData> Ball()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(24, 24, 24);
  image->SetSpacing(0.5, 0.5, 0.5);
  image->SetOrigin(-5.75, -5.75, -5.75);
  vtkNew<vtkShortArray> s;
  s->SetNumberOfTuples(24 * 24 * 24);
  for (int k = 0; k < 24; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i)
      {
        const double r =
          std::sqrt((i - 11.5) * (i - 11.5) + (j - 11.5) * (j - 11.5) + (k - 11.5) * (k - 11.5));
        s->SetValue((k * 24 + j) * 24 + i, static_cast<short>(r < 8 ? 100 : 0));
      }
  image->GetPointData()->SetScalars(s);
  return image;
}

double PixelSum(vtkImageData* image)
{
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  double sum = 0.0;
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    sum += rgb->GetComponent(i, 0) + rgb->GetComponent(i, 1) + rgb->GetComponent(i, 2);
  }
  return sum;
}
} // namespace

int main(int, char*[])
{
  int failures = 0;
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  color->AddRGBPoint(100, 1, 0.8, 0.6);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0);
  opacity->AddPoint(100, 0.3);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);

  vtkNew<vtkRenderer> renderer;
  renderer->GetActiveCamera()->SetPosition(0, 0, 40);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  vtkNew<vtkLight> light;
  light->SetPositional(false);
  light->SetPosition(-1, 1, 1);
  light->SetFocalPoint(0, 0, 0);
  light->SetIntensity(0.64);
  renderer->AddLight(light);

  vtkNew<vtkVolumeReferenceRenderer> filter;
  vtkNew<TestErrorObserver> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetVolumeProperty(property);
  filter->SetRenderer(renderer);
  filter->SetImageSize(32, 24);
  filter->SetInputData(Ball());

  double sums[3];
  double lit[3], shaded[3]; // radiance of the ball's half towards the light, and the other half
  for (int mode = 0; mode < 3; ++mode)
  {
    filter->SetRenderMode(mode);
    filter->Update();
    vtkImageData* out = filter->GetOutput();
    AVS_CHECK(errors->Errors == 0);
    int dims[3];
    out->GetDimensions(dims);
    AVS_CHECK(dims[0] == 32 && dims[1] == 24);
    AVS_CHECK(out->GetPointData()->GetArray("Radiance") != nullptr);
    sums[mode] = PixelSum(out);
    AVS_CHECK(sums[mode] > 0.0);
    // Background corners stay black; the centre shows the ball.
    AVS_CHECK(out->GetScalarComponentAsDouble(0, 0, 0, 0) == 0.0);
    AVS_CHECK(out->GetScalarComponentAsDouble(16, 12, 0, 0) > 0.0);
    // The light comes from the upper left (x < 0, y > 0 on the screen).
    vtkDataArray* radiance = out->GetPointData()->GetArray("Radiance");
    lit[mode] = shaded[mode] = 0.0;
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x)
      {
        const double r = radiance->GetComponent(y * 32 + x, 0);
        (x - 16 < y - 12 ? lit[mode] : shaded[mode]) += r;
      }
  }
  // The modes against each other, each doing what it names: EA knows no light, AO only darkens
  // EA (every pixel) and knows no light either (its halves as EA's, which differ a little with
  // the 32 x 24 picture's aspect), ambient scattering is brighter on the lit half (measured: EA
  // 0.82, AO 0.82, AS 1.21).
  std::cout << "sums EA " << sums[0] << ", AO " << sums[1] << ", AS " << sums[2]
            << "; lit / shaded half: EA " << lit[0] / shaded[0] << ", AO " << lit[1] / shaded[1]
            << ", AS " << lit[2] / shaded[2] << "\n";
  const double ea = lit[0] / shaded[0], ao = lit[1] / shaded[1], as = lit[2] / shaded[2];
  AVS_CHECK(std::abs(ao / ea - 1.0) < 0.05);
  AVS_CHECK(as / ea > 1.3);
  AVS_CHECK(sums[1] < 0.95 * sums[0]);
  {
    filter->SetRenderModeToEmissionAbsorption();
    filter->Update();
    vtkNew<vtkImageData> ea;
    ea->DeepCopy(filter->GetOutput());
    filter->SetRenderModeToAmbientOcclusion();
    filter->Update();
    vtkDataArray* a = ea->GetPointData()->GetArray("Radiance");
    vtkDataArray* b = filter->GetOutput()->GetPointData()->GetArray("Radiance");
    int darker = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      darker += b->GetComponent(i, 0) <= a->GetComponent(i, 0) + 1e-6 ? 1 : 0;
    }
    AVS_CHECK(darker == a->GetNumberOfTuples());
  }
  // The extent's lower corner places the volume: the same ball with extent starting at -12 and
  // the origin moved back by 12 voxels renders the same picture.
  {
    filter->SetRenderModeToEmissionAbsorption();
    filter->SetInputData(Ball());
    filter->Update();
    vtkNew<vtkImageData> first;
    first->DeepCopy(filter->GetOutput());
    auto shifted = Ball();
    shifted->SetExtent(-12, 11, -12, 11, -12, 11);
    shifted->SetOrigin(-5.75 + 6.0, -5.75 + 6.0, -5.75 + 6.0);
    filter->SetInputData(shifted);
    filter->Update();
    AVS_CHECK(PixelSum(filter->GetOutput()) > 0.0);
    AVS_CHECK(std::abs(PixelSum(filter->GetOutput()) - PixelSum(first)) < 1e-9);
    filter->SetInputData(Ball());
  }
  // The light matters for ambient scattering: switching it off (a headlight is used instead
  // only when the renderer has no lights at all) darkens the picture.
  filter->SetRenderModeToAmbientScattering();
  light->SwitchOff();
  filter->Update();
  AVS_CHECK(PixelSum(filter->GetOutput()) < 0.01 * sums[2]);
  light->SwitchOn();

  // Bad input: each gives an error and an empty output, and no crash.
  auto expectError = [&](vtkImageData* input, const std::string& text)
  {
    errors->Clear();
    filter->SetInputData(input);
    filter->Update();
    if (errors->Errors == 0 || errors->LastError.find(text) == std::string::npos ||
      filter->GetOutput()->GetNumberOfPoints() != 0)
    {
      std::cerr << "expected an error containing '" << text << "', got '" << errors->LastError
                << "'\n";
      ++failures;
    }
  };
  vtkNew<vtkImageData> empty;
  expectError(empty, "empty");
  {
    auto noScalars = Ball();
    noScalars->GetPointData()->RemoveArray(0);
    expectError(noScalars, "no point scalars");
  }
  {
    auto vectors = Ball();
    vtkNew<vtkFloatArray> v;
    v->SetNumberOfComponents(5); // VTK's mappers take 1-4
    v->SetNumberOfTuples(vectors->GetNumberOfPoints());
    v->Fill(1.0);
    vectors->GetPointData()->SetScalars(v);
    expectError(vectors, "components");
  }
  {
    auto flat = Ball();
    flat->SetSpacing(0.5, 0.0, 0.5);
    expectError(flat, "spacing");
    flat->SetSpacing(0.5, std::numeric_limits<double>::infinity(), 0.5);
    expectError(flat, "spacing");
    // Found by the translator fuzzer: huge and subnormal spacings (an undefined step count,
    // NaN pixels), and rays of more samples than any renderer takes.
    flat->SetSpacing(6.9e174, 0.5, 1.8e-310);
    expectError(flat, "outside [1e-30, 1e30]");
    flat->SetSpacing(0.5, 0.5, 0.5);
    flat->SetOrigin(0.0, 2e30, 0.0);
    expectError(flat, "outside [1e-30, 1e30]");
    flat->SetOrigin(0.0, 0.0, 0.0);
    flat->SetSpacing(1e6, 1e-3, 1.0);
    expectError(flat, "too many samples");
  }
  {
    // Found by the translator fuzzer: a camera on its focal point (a volume far from the
    // origin, where position and focal point round to the same number) gave NaN pixels.
    vtkNew<vtkCamera> degenerate;
    degenerate->SetFocalPoint(1e28, 1e28, 1e28);
    degenerate->SetPosition(1e28 + 1.0, 1e28, 1e28);
    filter->SetCamera(degenerate);
    expectError(Ball(), "focal point");
    filter->SetCamera(nullptr);
  }
  {
    vtkNew<vtkImageData> plane;
    plane->SetDimensions(10, 10, 1);
    plane->AllocateScalars(VTK_FLOAT, 1);
    expectError(plane, "not a volume");
  }
  filter->SetInputData(Ball());
  filter->SetVolumeProperty(nullptr);
  errors->Clear();
  filter->Update();
  AVS_CHECK(errors->Errors == 1 && errors->LastError.find("volume property") != std::string::npos);

  std::ostringstream os;
  filter->Print(os);
  for (const char* key : { "RenderMode",
         "Albedo",
         "Anisotropy",
         "AmbientRadius",
         "EmissionWeight",
         "OcclusionRadius",
         "NumberOfDirections",
         "AmbientWeight",
         "SampleDistance",
         "TerminationTransmittance",
         "LightVolumeMaximumDimension",
         "OcclusionVolumeMaximumDimension",
         "ImageSize",
         "Background" })
  {
    AVS_CHECK(os.str().find(key) != std::string::npos);
  }
  if (failures)
  {
    std::cerr << failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
