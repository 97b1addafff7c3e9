// The extended model against the truth at small size (48 x 48, 48^3 voxels, 128 paths per
// pixel), asserting what Documentation/Accuracy.md ("The extended model, measured") reports at
// full size:
// - on the side-lit clouds of optical thickness 8.8 and 27 (--cloud-opacity 0.25, 0.6) the
//   extended model has the lowest RMSE of EA, AO and both ambient-scattering models (by more
//   than the truth's noise), and its mean radiance is within 0.75-1.33 of the truth's (the
//   paper's model: about 0.40);
// - lit from behind, its error is no worse than the paper model's (the silver lining stays);
// - on an optically thin cloud (thickness about 0.3, --cloud-opacity 0.01) it reduces to the
//   paper's model: both errors and both mean radiances agree within the truth's noise.
#include "AccuracyStudy.h"

#include <cmath>
#include <iostream>
#include <map>

namespace
{
int failures = 0;

std::map<std::string, AccuracyResult> Measure(const AccuracySettings& settings)
{
  std::vector<AccuracyResult> results;
  std::map<std::string, AccuracyResult> byName;
  if (!RunAccuracyStudy(settings, results))
  {
    ++failures;
    return byName;
  }
  for (const auto& r : results)
  {
    std::cout << "accuracy " << r.Scene << " " << r.Model << " rmse=" << r.Rmse
              << " mean/truth=" << r.MeanRatio << " (cloud opacity " << settings.CloudOpacity
              << ", path-tracer noise " << r.TruthNoise << ")\n";
    byName[r.Scene + "/" + r.Model] = r;
  }
  return byName;
}

void Expect(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "failed: " << what << "\n";
    ++failures;
  }
}
} // namespace

int main(int, char*[])
{
  AccuracySettings settings;
  settings.ImageSize = 48;
  settings.Voxels = 48;
  settings.SamplesPerPixel = 128;
  settings.Scenes = { "cloud_back", "cloud_side" };
  for (double opacity : { 0.25, 0.6 })
  {
    settings.CloudOpacity = opacity;
    auto r = Measure(settings);
    const std::string tag = " (cloud opacity " + std::to_string(opacity) + ")";
    const AccuracyResult& x = r["cloud_side/asx"];
    for (const char* other : { "ea", "ao", "as" })
    {
      const AccuracyResult& o = r[std::string("cloud_side/") + other];
      Expect(
        o.Rmse - x.Rmse > x.TruthNoise, std::string("side-lit: extended below ") + other + tag);
    }
    // Measured 0.82 and 0.87 here (0.75 and 0.86 at the study's full size): the 0.75-1.33 the
    // Documentation/Accuracy.md reports, with 0.07 to spare for other drivers.
    Expect(x.MeanRatio >= 0.75 && x.MeanRatio <= 1.33, "side-lit mean within 0.75-1.33" + tag);
    Expect(r["cloud_side/as"].MeanRatio < 0.6, "the paper's model too dark side-lit" + tag);
    Expect(r["cloud_back/asx"].Rmse <= r["cloud_back/as"].Rmse + r["cloud_back/as"].TruthNoise,
      "back-lit: extended no worse than the paper's" + tag);
  }
  // Optically thin: the same picture within noise.
  settings.CloudOpacity = 0.01;
  auto thin = Measure(settings);
  for (const char* scene : { "cloud_back", "cloud_side" })
  {
    const AccuracyResult& x = thin[std::string(scene) + "/asx"];
    const AccuracyResult& p = thin[std::string(scene) + "/as"];
    Expect(std::abs(x.Rmse - p.Rmse) < x.TruthNoise, std::string(scene) + ": thin, same error");
    Expect(std::abs(x.MeanRatio - p.MeanRatio) < 0.1 && x.MeanRatio >= p.MeanRatio,
      std::string(scene) + ": thin, same mean, the extended one not darker");
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
