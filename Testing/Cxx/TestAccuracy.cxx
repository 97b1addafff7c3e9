// The accuracy study at small size (48 x 48, 48^3 voxels, 128 paths per pixel: the path tracer's
// own noise is measured and must stay well below the differences tested). What holds with the
// default parameters, and is asserted here:
// - on the study's four scenes (clouds of optical thickness about 27 lit from behind and from
//   the side, a nebula with a point light inside, a dense medical-like volume) both models of
//   ambient scattering, the default extended one (asx) and the paper's (as), are closer to the
//   truth than EA and AO;
// - so they are on an optically thin cloud (about 2.6 across, --cloud-opacity 0.08), lit from
//   behind and from the side;
// - and each model's RMSE is bounded on every scene: at most 1.2 times what it measured when the
//   bound was set (llvmpipe, Debian 12; the table below). The path tracer is deterministic for
//   its seed and the mappers for a driver, so the bound's fifth is room for another driver's
//   arithmetic, not for noise: a model that got a fifth worse anywhere fails, where the ranking
//   alone let ambient scattering get up to 14x worse on the nebula and still pass.
// - with surfaces inside the medium (ShadeOn, VolumetricScatteringBlending 0; the truth traces
//   surface events) the extended model is closer to the truth than EA, AO, VTK's shaded mapper
//   at its best exposure and itself with ShadeOff, on the four scenes, and bounded the same way.
// Documentation/Accuracy.md gives the full-size figures and where ambient
// scattering does not win (side-lit clouds of intermediate thickness).
#include "AccuracyStudy.h"
#include "MapperTestScene.h"

#include <iostream>
#include <limits>
#include <map>

namespace
{
int failures = 0;

// Runs the study; returns the results by "scene/model".
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
              << " rel_l1=" << r.RelativeL1 << " (cloud opacity " << settings.CloudOpacity
              << ", path-tracer noise " << r.TruthNoise << ")\n";
    byName[r.Scene + "/" + r.Model] = r;
  }
  return byName;
}

void ExpectBetter(std::map<std::string, AccuracyResult>& results,
  const std::string& scene,
  const std::string& other,
  const std::string& model)
{
  const double as = results[scene + "/" + model].Rmse, o = results[scene + "/" + other].Rmse;
  const double noise = results[scene + "/" + model].TruthNoise;
  // The truth's own noise adds to both errors alike (in quadrature); it must be small against
  // the errors compared.
  if (!(as < o) || !(noise < 0.25 * o))
  {
    std::cerr << scene << ": ambient scattering (" << model << ") " << as << " not clearly below "
              << other << " " << o << " (noise " << noise << ")\n";
    ++failures;
  }
}
/// RMSE measured when the bounds were set (48^2, 48^3, 128 and 256 paths), extended and paper.
struct Measured
{
  const char* Scene;
  double Opacity;
  double Extended, Paper;
};
const Measured Today[] = {
  { "cloud_back", 0.6, 0.0347, 0.0501 },
  { "cloud_side", 0.6, 0.0504, 0.1626 },
  { "nebula_point", 0.6, 0.0109, 0.0161 },
  { "dense_medical", 0.6, 0.0567, 0.0813 },
  { "cloud_back", 0.08, 0.0256, 0.0460 },
  { "cloud_side", 0.08, 0.0262, 0.0601 },
};

void ExpectBounded(std::map<std::string, AccuracyResult>& results,
  const std::string& scene,
  double opacity)
{
  for (const Measured& m : Today)
  {
    if (scene != m.Scene || opacity != m.Opacity)
    {
      continue;
    }
    for (const auto& [model, measured] :
      { std::make_pair("asx", m.Extended), std::make_pair("as", m.Paper) })
    {
      const double rmse = results[scene + "/" + model].Rmse;
      if (!(rmse <= 1.2 * measured))
      {
        std::cerr << scene << " (cloud opacity " << opacity << "): " << model << " RMSE " << rmse
                  << " above 1.2 x the " << measured << " measured\n";
        ++failures;
      }
    }
    return;
  }
  std::cerr << scene << ": no bound\n";
  ++failures;
}
} // namespace

int main(int, char*[])
{
  AccuracySettings settings;
  settings.ImageSize = 48;
  settings.Voxels = 48;
  settings.SamplesPerPixel = 128;
  settings.Scenes = { "cloud_back", "cloud_side", "nebula_point", "dense_medical" };
  auto study = Measure(settings);
  for (const std::string& scene : settings.Scenes)
  {
    for (const char* model : { "asx", "as" })
    {
      ExpectBetter(study, scene, "ea", model);
      ExpectBetter(study, scene, "ao", model);
    }
    ExpectBounded(study, scene, settings.CloudOpacity);
  }

  // The thin cloud: twice the paths, since the differences are smaller.
  settings.Scenes = { "cloud_back", "cloud_side" };
  settings.CloudOpacity = 0.08;
  settings.SamplesPerPixel = 256;
  auto thin = Measure(settings);
  for (const std::string& scene : settings.Scenes)
  {
    for (const char* model : { "asx", "as" })
    {
      ExpectBetter(thin, scene, "ea", model);
      ExpectBetter(thin, scene, "ao", model);
    }
    ExpectBounded(thin, scene, settings.CloudOpacity);
  }

  // Surfaces inside the medium, on the study's lattice (64 voxels: at 48 the dense scene's
  // surfaces lose their structure, and VTK 9.6's shaded mapper at its best exposure came within
  // the truth's noise of ours there, 0.051 against 0.053), with twice the paths (the truth's
  // noise must stay below a quarter of the errors compared). RMSE of the extended model
  // measured when the bounds were set.
  AccuracySettings shade;
  shade.ImageSize = 48;
  shade.Voxels = 64;
  shade.SamplesPerPixel = 256;
  shade.Shade = true;
  auto shaded = Measure(shade);
  const std::pair<const char*, double> shadedToday[] = { { "cloud_back", 0.0675 },
    { "cloud_side", 0.0634 },
    { "nebula_point", 0.0101 },
    { "dense_medical", 0.0385 } };
  for (const auto& [name, measured] : shadedToday)
  {
    const std::string scene = std::string(name) + "_shaded";
    for (const char* other : { "ea", "ao", "vtk", "asx_off" })
    {
      ExpectBetter(shaded, scene, other, "asx");
    }
    const double rmse = shaded[scene + "/asx"].Rmse;
    if (!(rmse <= 1.2 * measured))
    {
      std::cerr << scene << ": asx RMSE " << rmse << " above 1.2 x the " << measured
                << " measured\n";
      ++failures;
    }
  }

  // Settings the study refuses, before rendering anything.
  std::vector<AccuracyResult> none;
  AccuracySettings unknown = settings;
  unknown.Scenes = { "cloud_back", "no_such_scene" };
  AccuracySettings empty = settings;
  empty.Scenes.clear();
  AccuracySettings opaque = settings;
  opaque.CloudOpacity = 0.0;
  AccuracySettings radius = settings;
  radius.AmbientRadius = std::numeric_limits<double>::quiet_NaN();
  for (const AccuracySettings* bad : { &unknown, &empty, &opaque, &radius })
  {
    if (RunAccuracyStudy(*bad, none) || !none.empty())
    {
      std::cerr << "the study accepted bad settings\n";
      ++failures;
    }
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
