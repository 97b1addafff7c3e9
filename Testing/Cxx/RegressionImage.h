// Regression images that tell pictures apart: the picture against its baseline
// (Testing/Data/Baseline) with tolerances set from measured noise, instead of VTK 9.1's
// vtkRegressionTestImageThreshold, whose comparison forgives up to 105 levels per channel after
// +-2-pixel shifts and 3 x 3 averaging (it passed a mirrored baseline, one with two channels
// swapped and another mapper's).
//
// A picture matches its baseline when its PSNR is at least MinimumPsnr and at most Share of its
// pixels differ by more than Levels in a channel. Measured on llvmpipe: the same build renders
// the baselines bit for bit (inf dB); the GPU mappers sit at 59-76 dB against the CPU reference,
// which bounds what another driver's arithmetic moves. A 5 % brightness change measures 30-37 dB
// on the test scenes, a mirror, a colour swap or another mapper 13-25 dB.
//
// Each test program takes: -V BASELINE.png -T DIRECTORY (VTK's arguments; the picture and, on
// failure, the difference are written there), and
//   --remake            write the baseline, only after the picture's independent check against
//                       the CPU reference (vtkVolumeReferenceRenderer) passed;
//   --wrong             instead of the test: the picture must match its baseline, and four
//                       wrong pictures must not: the same scene rendered by another mapper, and
//                       the baseline with green and blue swapped, mirrored, or 5 % brighter.
#ifndef RegressionImage_h
#define RegressionImage_h

#include "MapperTestScene.h"

#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

struct RegressionTolerance
{
  double MinimumPsnr = 50.0;
  int Levels = 8;
  double Share = 0.005;
};

struct RegressionComparison
{
  double Psnr = 0.0;
  double Share = 1.0; ///< of the pixels with a channel more than Levels off
  double Largest = 255.0;
  bool Matches = false;
};

inline RegressionComparison CompareToBaseline(vtkImageData* picture,
  vtkImageData* baseline,
  const RegressionTolerance& tolerance = RegressionTolerance())
{
  RegressionComparison result;
  int a[3], b[3];
  picture->GetDimensions(a);
  baseline->GetDimensions(b);
  vtkDataArray* x = picture->GetPointData()->GetScalars();
  vtkDataArray* y = baseline->GetPointData()->GetScalars();
  if (a[0] != b[0] || a[1] != b[1] || !x || !y || x->GetNumberOfComponents() < 3 ||
    y->GetNumberOfComponents() < 3)
  {
    return result; // another size or format: no match
  }
  const vtkIdType n = x->GetNumberOfTuples();
  double se = 0.0, largest = 0.0;
  vtkIdType off = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(x->GetComponent(i, c) - y->GetComponent(i, c));
      se += d * d;
      worst = std::max(worst, d);
    }
    largest = std::max(largest, worst);
    off += worst > tolerance.Levels ? 1 : 0;
  }
  const double mse = se / (3.0 * n);
  result.Psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 1e9;
  result.Share = static_cast<double>(off) / n;
  result.Largest = largest;
  result.Matches = result.Psnr >= tolerance.MinimumPsnr && result.Share <= tolerance.Share;
  return result;
}

inline vtkSmartPointer<vtkImageData> ReadPicture(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(reader->GetOutput());
  return out;
}

inline void WritePicture(vtkImageData* picture, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(picture);
  writer->SetFileName(path.c_str());
  writer->Write();
}

/// A copy of an RGB(A) picture with each pixel changed by `change`(x, y, rgb in, rgb out).
inline vtkSmartPointer<vtkImageData> Altered(vtkImageData* picture,
  const std::function<void(int, int, const double*, double*)>& change)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(picture);
  int d[3];
  picture->GetDimensions(d);
  vtkDataArray* in = picture->GetPointData()->GetScalars();
  vtkDataArray* to = out->GetPointData()->GetScalars();
  for (int y = 0; y < d[1]; ++y)
    for (int x = 0; x < d[0]; ++x)
    {
      double rgb[3], result[3];
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = in->GetComponent(static_cast<vtkIdType>(y) * d[0] + x, c);
      }
      change(x, y, rgb, result);
      for (int c = 0; c < 3; ++c)
      {
        to->SetComponent(
          static_cast<vtkIdType>(y) * d[0] + x, c, std::clamp(std::round(result[c]), 0.0, 255.0));
      }
    }
  return out;
}

/// The picture's regression test as the header describes it. `check` is the independent check
/// --remake requires: it renders what it needs and returns whether the mapper agrees with the
/// CPU reference. `otherMapper` renders the same scene with another mapper (for --wrong).
inline int RegressionTest(int argc,
  char* argv[],
  vtkImageData* picture,
  const std::function<bool()>& check,
  const std::function<vtkSmartPointer<vtkImageData>()>& otherMapper)
{
  std::string baselinePath, directory = ".";
  bool remake = false, wrongBaselines = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "-V") && i + 1 < argc)
      baselinePath = argv[++i];
    else if (!std::strcmp(argv[i], "-T") && i + 1 < argc)
      directory = argv[++i];
    else if (!std::strcmp(argv[i], "--wrong"))
      wrongBaselines = true;
    else if (!std::strcmp(argv[i], "--remake"))
      remake = true;
  }
  if (baselinePath.empty())
  {
    std::cerr << "no baseline (-V BASELINE.png)\n";
    return EXIT_FAILURE;
  }
  const std::string name = baselinePath.substr(baselinePath.find_last_of('/') + 1);
  WritePicture(picture, directory + "/" + name);
  if (remake)
  {
    if (!check())
    {
      std::cerr << "not remade: the picture failed its check against the CPU reference\n";
      return EXIT_FAILURE;
    }
    WritePicture(picture, baselinePath);
    std::cout << "remade " << baselinePath << " (checked against the CPU reference)\n";
    return EXIT_SUCCESS;
  }
  auto baseline = ReadPicture(baselinePath);
  if (!baseline)
  {
    std::cerr << "cannot read the baseline " << baselinePath << "\n";
    return EXIT_FAILURE;
  }
  auto report = [](const std::string& what, const RegressionComparison& c)
  {
    std::cout << what << ": PSNR " << c.Psnr << " dB, " << 100.0 * c.Share
              << " % of the pixels more than " << RegressionTolerance().Levels
              << " levels off (largest " << c.Largest << ") -> "
              << (c.Matches ? "matches" : "differs") << "\n";
  };
  const RegressionComparison own = CompareToBaseline(picture, baseline);
  report("against " + name, own);
  if (!wrongBaselines)
  {
    if (!own.Matches)
    {
      auto difference = Altered(picture,
        [&](int x, int y, const double* p, double* out)
        {
          for (int c = 0; c < 3; ++c)
          {
            out[c] = 4.0 * std::abs(p[c] - baseline->GetScalarComponentAsDouble(x, y, 0, c));
          }
        });
      WritePicture(difference, directory + "/" + name.substr(0, name.size() - 4) + ".diff.png");
    }
    return own.Matches ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  // The discrimination: four wrong baselines must fail.
  const int width = baseline->GetDimensions()[0];
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkImageData>>> wrong = {
    { "another mapper's picture", otherMapper() },
    { "green and blue swapped",
      Altered(baseline,
        [](int, int, const double* p, double* o)
        {
          o[0] = p[0];
          o[1] = p[2];
          o[2] = p[1];
        }) },
    { "mirrored",
      Altered(baseline,
        [&](int x, int y, const double*, double* o)
        {
          for (int c = 0; c < 3; ++c)
            o[c] = baseline->GetScalarComponentAsDouble(width - 1 - x, y, 0, c);
        }) },
    { "5 % brighter",
      Altered(baseline,
        [](int, int, const double* p, double* o)
        {
          for (int c = 0; c < 3; ++c)
            o[c] = 1.05 * p[c];
        }) },
  };
  bool ok = own.Matches;
  for (const auto& w : wrong)
  {
    const RegressionComparison c = CompareToBaseline(picture, w.second);
    report(w.first, c);
    ok = ok && !c.Matches;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

#endif
