// The accuracy study (issue: ground truth): scenes where scattering matters, rendered by the GPU
// mappers (EA, AO, ambient scattering) and by the path tracer with the same camera and lights,
// and the error of each mapper against the path tracer. Shared by avs-accuracy and its test.
//
// Comparability: EA has no lights and AO only an ambient term, so both get the radiance an
// unshadowed, isotropically scattering medium would return under the same lights: EA's colours
// and AO's ambient weight are scaled by k = albedo * sum_j E_j(x_c) / (4 pi), with E_j the
// light's irradiance (mean of RGB) at the volume's centre x_c. Ambient scattering and the path
// tracer use the albedo, anisotropy and lights themselves. All pictures are on one linear
// exposure (radiance 1 = white), without per-image normalisation; the environment is black.
#ifndef AccuracyStudy_h
#define AccuracyStudy_h

#include <string>
#include <vector>

struct AccuracyResult
{
  std::string Scene;
  std::string Model; ///< "ea", "ao", "as" (the paper's model) or "asx" (the extended one)
  double Rmse = 0.0;
  double RelativeL1 = 0.0;
  double TruthNoise = 0.0; ///< RMSE of the scene's truth itself (from two seeds)
  double MeanRatio = 0.0;  ///< the model's mean radiance / the truth's
};

struct AccuracySettings
{
  int ImageSize = 96;
  int Voxels = 64;
  int SamplesPerPixel = 512;
  std::vector<std::string> Scenes{ "cloud_back", "cloud_side", "nebula_point", "dense_medical" };
  /// Opacity of the clouds' densest scalar (1.0); the clouds' optical thickness scales with
  /// -ln(1 - CloudOpacity). 0.6 gives about 27 across the cloud's middle.
  double CloudOpacity = 0.6;
  /// Ambient radius of the ambient-scattering mapper and occlusion radius of the AO mapper, in
  /// world units (the scenes span [-1, 1]^3); 0 keeps their default (1/64 of the diagonal).
  double AmbientRadius = 0.0;
  /// A folder where the path tracer's pictures are kept between runs (keyed by scene, sizes,
  /// paths, cloud opacity and radius); empty: none.
  std::string TruthCache;
  std::string OutputPicture; ///< a PNG of truth | EA | AO | AS | 4x |errors|, one row per scene
  bool Verbose = false;
};

/// Renders and measures. Returns false (with a message on stderr) if a mapper could not render.
bool RunAccuracyStudy(const AccuracySettings& settings,
  std::vector<AccuracyResult>& results,
  double* pathTracerNoise = nullptr);

#endif
