// The accuracy study (issue: ground truth): scenes where scattering matters, rendered by the GPU
// mappers (EA, AO, ambient scattering) and by the path tracer with the same camera and lights,
// and the error of each mapper against the path tracer. Shared by avs-accuracy, its test and
// avs-bench-refinement (which sets the scenes up with SetUpAccuracyScene).
//
// Comparability: EA has no lights and AO only an ambient term, so both get the radiance an
// unshadowed, isotropically scattering medium would return under the same lights: EA's colours
// and AO's ambient weight are scaled by k = albedo * sum_j E_j(x_c) / (4 pi), with E_j the
// light's irradiance (mean of RGB) at the volume's centre x_c. Ambient scattering and the path
// tracer use the albedo, anisotropy and lights themselves. All pictures are on one linear
// exposure (radiance 1 = white), without per-image normalisation; the environment is black.
#ifndef AccuracyStudy_h
#define AccuracyStudy_h

#include "Camera.h"
#include "PathTracer.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAmbientScatteringVolumeMapper;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;
class vtkVolumeProperty;

struct AccuracyResult
{
  std::string Scene;
  /// "ea", "ao", "as" (the paper's model) or "asx" (the extended one); with Shade also
  /// "asx_off" (the extended model with ShadeOff) and "vtk" (vtkGPUVolumeRayCastMapper with
  /// ShadeOn at the exposure that minimises its RMSE).
  std::string Model;
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
  /// Surfaces inside the medium: the property's ShadeOn (VTK's coefficients) with this
  /// VolumetricScatteringBlending, in the truth (the path tracer's surface events) and in
  /// ambient scattering; the scenes' names get "_shaded".
  bool Shade = false;
  double Blending = 0.0;
  bool Verbose = false;
};

/// One of the study's scenes, set up in a renderer (its lights and camera), with the volume and
/// property the mappers get and the same scene as the path tracer sees it.
struct AccuracyScene
{
  std::string Name;
  vtkSmartPointer<vtkImageData> Data;
  vtkSmartPointer<vtkVolumeProperty> Property;
  double Albedo = 0.9;
  double Anisotropy = 0.0;
  avs::VolumeScene Core;                ///< the path tracer's scene, lights included
  avs::ScatteringParameters Parameters; ///< the path tracer's medium parameters (resolved)
  avs::Camera Camera;
};

/// Whether the settings name known scenes (plume_point included) and valid values; false with a
/// message on stderr that starts with `program`.
bool CheckAccuracySettings(const AccuracySettings& settings, const char* program);

/// Makes scene `name` (one the settings accept): adds its lights to `renderer`, places its
/// active camera, and returns the volume, its property and the path tracer's scene.
AccuracyScene SetUpAccuracyScene(const AccuracySettings& settings,
  const std::string& name,
  vtkRenderer* renderer);

/// The study's settings of an ambient-scattering mapper for `scene`: its albedo and anisotropy,
/// the settings' ambient radius, no jittering, linear radiance (exposure 1, clamp). The model is
/// left as it is (extended by default).
void ConfigureAccuracyMapper(vtkAmbientScatteringVolumeMapper* mapper,
  const AccuracyScene& scene,
  const AccuracySettings& settings);

/// The truth: the mean of two path-traced pictures (seeds 17 and 18, the settings'
/// SamplesPerPixel each, from the truth cache when it has them), RGB clamped to [0, 1], row 0 at
/// the bottom. `noise`, when given, gets its own RMSE (half the RMSE between the two).
std::vector<double> AccuracyTruth(const AccuracySettings& settings,
  const AccuracyScene& scene,
  double* noise = nullptr);

/// The RGB of `window`'s back buffer (8 bits) in [0, 1], row 0 at the bottom, as the study reads
/// the mappers' pictures.
std::vector<double> AccuracyGrab(vtkRenderWindow* window);

/// The RGB of a float picture clamped to [0, 1], row 0 at the bottom (how the study compares).
std::vector<double> ClampedRgb(const avs::Image& image);

/// The study's error: the RMSE over all values of `picture` against `reference`.
double AccuracyRmse(const std::vector<double>& picture, const std::vector<double>& reference);

/// An 8-bit RGB picture of size x size from RGB values (times `scale`, clamped to [0, 1]).
vtkSmartPointer<vtkImageData> AccuracyPicture(const std::vector<double>& rgb,
  int size,
  double scale = 1.0);

/// Renders and measures. Returns false (with a message on stderr) if a mapper could not render.
bool RunAccuracyStudy(const AccuracySettings& settings,
  std::vector<AccuracyResult>& results,
  double* pathTracerNoise = nullptr);

#endif
