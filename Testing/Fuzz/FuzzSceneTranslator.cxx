// Fuzz target: the input translators (vtkAVSDataTranslator::ToVolume and
// vtkAVSSceneTranslator::ToCamera directly, and everything they convert through
// vtkVolumeReferenceRenderer, the public class that uses them) on
// image data built from the input, rendered by the CPU reference at 8 x 8 pixels.
//
// The bytes choose the image's geometry (dimensions, extent, spacing, origin, direction
// matrix: identity, a rotation, an axis permutation or nine raw doubles), its scalar type and
// component count, whether scalars exist and match the points, and the values (raw bytes, so
// NaN and infinities come up); then a transfer function (raw node positions and values), a
// camera and a render mode. Invariants: the translator succeeds or says why; what it accepts
// is one finite grid of the image's shape per component (NaN voxels have validity 0); the renderer
// reports an error with an empty output for what the translator refuses, and otherwise either an
// error or a picture of finite radiance.
#include "FuzzInput.h"
#include "vtkAVSDataTranslator.h"
#include "vtkAVSSceneTranslator.h"
#include "vtkAmbientScatteringTable.h"
#include "vtkVolumeReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Errors; }
  int Errors = 0;
};

const int ScalarTypes[] = { VTK_CHAR,
  VTK_SIGNED_CHAR,
  VTK_UNSIGNED_CHAR,
  VTK_SHORT,
  VTK_UNSIGNED_SHORT,
  VTK_INT,
  VTK_UNSIGNED_INT,
  VTK_LONG,
  VTK_UNSIGNED_LONG,
  VTK_LONG_LONG,
  VTK_UNSIGNED_LONG_LONG,
  VTK_FLOAT,
  VTK_DOUBLE,
  VTK_ID_TYPE };

double Value(FuzzInput& in, bool raw, double lo, double hi)
{
  return raw ? in.Raw<double>() : in.Fraction(lo, hi);
}

vtkSmartPointer<vtkImageData> MakeImage(FuzzInput& in)
{
  const std::uint8_t flags = in.Byte();
  auto image = vtkSmartPointer<vtkImageData>::New();
  int dims[3], start[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = in.Range(0, 11);
    start[a] = in.Raw<std::int16_t>();
  }
  image->SetExtent(start[0],
    start[0] + dims[0] - 1,
    start[1],
    start[1] + dims[1] - 1,
    start[2],
    start[2] + dims[2] - 1);
  double spacing[3], origin[3];
  for (int a = 0; a < 3; ++a)
  {
    spacing[a] = Value(in, flags & 1, 0.01, 2.0);
    origin[a] = Value(in, flags & 2, -10.0, 10.0);
  }
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  double d[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  switch ((flags >> 2) & 3)
  {
    case 1: // a rotation from a quaternion
    {
      double q[4];
      for (double& c : q)
      {
        c = in.Fraction(-1.0, 1.0);
      }
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (n > 1e-3)
      {
        const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
        const double r[9] = { 1 - 2 * (y * y + z * z),
          2 * (x * y - w * z),
          2 * (x * z + w * y),
          2 * (x * y + w * z),
          1 - 2 * (x * x + z * z),
          2 * (y * z - w * x),
          2 * (x * z - w * y),
          2 * (y * z + w * x),
          1 - 2 * (x * x + y * y) };
        std::copy(r, r + 9, d);
      }
      break;
    }
    case 2: // an axis permutation with flips
    {
      const std::uint8_t p = in.Byte();
      int axes[3] = { 0, 1, 2 };
      for (int i = 0; i < p % 6; ++i)
      {
        std::next_permutation(axes, axes + 3);
      }
      std::fill(d, d + 9, 0.0);
      for (int r = 0; r < 3; ++r)
      {
        d[3 * r + axes[r]] = (p >> (3 + r)) & 1 ? -1.0 : 1.0;
      }
      break;
    }
    case 3:
      for (double& v : d)
      {
        v = in.Raw<double>();
      }
      break;
    default:
      break;
  }
  image->SetDirectionMatrix(d);
  if (flags & 0x10)
  {
    return image; // no scalars
  }
  const std::uint8_t kind = in.Byte();
  const int type = ScalarTypes[kind % (sizeof(ScalarTypes) / sizeof(ScalarTypes[0]))];
  const int components = (kind >> 4) == 15 ? 3 : ((kind >> 4) == 14 ? 2 : 1);
  vtkIdType tuples = image->GetNumberOfPoints();
  if (flags & 0x20)
  {
    tuples += (flags & 0x40) ? 1 : -1; // scalars that do not match the points
  }
  tuples = std::max<vtkIdType>(0, tuples);
  auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  auto* bytes = static_cast<std::uint8_t*>(array->GetVoidPointer(0));
  const std::size_t n = static_cast<std::size_t>(tuples) * components * array->GetDataTypeSize();
  const std::uint8_t* rest = in.Rest();
  const std::size_t have = in.Remaining();
  for (std::size_t i = 0; i < n; ++i)
  {
    bytes[i] = have ? rest[i % have] : 0;
  }
  array->SetName("values");
  image->GetPointData()->SetScalars(array);
  return image;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const bool verbose = std::getenv("AVS_FUZZ_VERBOSE") != nullptr;
  FuzzQuietVTK(); // AVS_FUZZ_VERBOSE=1: VTK's messages are shown
  static vtkAmbientScatteringTable* table = []
  {
    auto* t = vtkAmbientScatteringTable::New();
    t->Load();
    return t;
  }();
  // The settings come from the input's end, the image from its start (its values are the
  // bytes that remain), so that the two do not shift each other.
  const std::size_t tail = std::min<std::size_t>(size, 24);
  FuzzInput settings(data + size - tail, tail);
  FuzzInput in(data, size - tail);
  vtkSmartPointer<vtkImageData> image = MakeImage(in);

  vtkAVSDataTranslator::Volume volume;
  std::string error, warning;
  const bool gridOk = vtkAVSDataTranslator::ToVolume(
    image, vtkAVSDataTranslator::Selection(), volume, error, warning);
  FUZZ_CHECK(gridOk || !error.empty());
  if (verbose)
  {
    int e[6];
    image->GetExtent(e);
    const double* sp = image->GetSpacing();
    const double* o = image->GetOrigin();
    const double* m = image->GetDirectionMatrix()->GetData();
    std::fprintf(stderr,
      "extent %d %d %d %d %d %d spacing %g %g %g origin %g %g %g direction %g %g %g %g %g %g %g %g "
      "%g\nToVolume: %s\n",
      e[0],
      e[1],
      e[2],
      e[3],
      e[4],
      e[5],
      sp[0],
      sp[1],
      sp[2],
      o[0],
      o[1],
      o[2],
      m[0],
      m[1],
      m[2],
      m[3],
      m[4],
      m[5],
      m[6],
      m[7],
      m[8],
      gridOk ? "accepted" : error.c_str());
  }
  if (gridOk)
  {
    int dims[3];
    image->GetDimensions(dims);
    FUZZ_CHECK(!volume.Components.empty() &&
      volume.Components.size() <=
        static_cast<std::size_t>(vtkAVSDataTranslator::MaximumComponents));
    const auto expected = static_cast<std::size_t>(volume.CellData
        ? static_cast<vtkIdType>(dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1)
        : image->GetNumberOfPoints());
    for (const avs::Grid& grid : volume.Components)
    {
      FUZZ_CHECK(grid.Values.size() == expected);
      for (float v : grid.Values)
      {
        FUZZ_CHECK(std::isfinite(v));
      }
    }
    FUZZ_CHECK(volume.Validity.Values.empty() || volume.Validity.Values.size() == expected);
  }

  // A transfer function with raw nodes (NaN positions and values included).
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  const int nodes = settings.Range(0, 3);
  const bool rawNodes = settings.Byte() & 1;
  for (int i = 0; i < nodes; ++i)
  {
    const double x = Value(settings, rawNodes, -5.0, 300.0);
    color->AddRGBPoint(x, settings.Fraction(0, 1), settings.Fraction(-0.5, 1.5), 1.0);
    opacity->AddPoint(x, Value(settings, rawNodes, -0.5, 1.5));
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(settings.Fraction(-0.1, 2.0));
  // The camera looks at the image's centre from a direction the input picks.
  vtkNew<vtkCamera> camera;
  double bounds[6];
  image->GetBounds(bounds);
  const double centre[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  const double radius = 0.5 *
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
        (bounds[5] - bounds[4]) * (bounds[5] - bounds[4])) +
    1e-3;
  const double azimuth = settings.Fraction(0.0, 6.283), elevation = settings.Fraction(-1.5, 1.5);
  const double distance = radius * settings.Fraction(0.2, 6.0); // inside the volume too
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + distance * std::cos(elevation) * std::cos(azimuth),
    centre[1] + distance * std::cos(elevation) * std::sin(azimuth),
    centre[2] + distance * std::sin(elevation));
  camera->SetParallelProjection(settings.Byte() & 1);
  camera->SetParallelScale(radius);
  vtkAVSSceneTranslator::ToCamera(camera);

  // The rest through the public class that uses the translator (its colour, opacity and
  // light conversions included), so that this target follows the translator's API.
  const std::uint8_t render = settings.Byte();
  vtkNew<vtkVolumeReferenceRenderer> renderer;
  vtkNew<ErrorCounter> errors;
  renderer->AddObserver(vtkCommand::ErrorEvent, errors);
  renderer->SetInputData(image);
  renderer->SetVolumeProperty(property);
  renderer->SetCamera(camera);
  renderer->SetScatteringTable(table);
  renderer->SetRenderMode(render % 3);
  renderer->SetImageSize(8, 8);
  renderer->SetLightVolumeMaximumDimension(8);
  renderer->SetOcclusionVolumeMaximumDimension(8);
  renderer->SetNumberOfDirections(14);
  renderer->Update();
  vtkImageData* picture = renderer->GetOutput();
  if (verbose)
  {
    const double* p = camera->GetPosition();
    const double* f = camera->GetFocalPoint();
    std::fprintf(stderr,
      "camera %g %g %g -> %g %g %g; renderer: %d errors, %d pixels\n",
      p[0],
      p[1],
      p[2],
      f[0],
      f[1],
      f[2],
      errors->Errors,
      static_cast<int>(picture->GetNumberOfPoints()));
  }
  if (errors->Errors > 0 || !gridOk)
  {
    FUZZ_CHECK(errors->Errors > 0 && picture->GetNumberOfPoints() == 0);
    return 0;
  }
  FUZZ_CHECK(picture->GetNumberOfPoints() == 64);
  vtkDataArray* radiance = picture->GetPointData()->GetArray("Radiance");
  FUZZ_CHECK(radiance != nullptr);
  for (vtkIdType i = 0; i < radiance->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      FUZZ_CHECK(std::isfinite(radiance->GetComponent(i, c)));
    }
  }
  return 0;
}
