// The unbiased reference (ALGORITHM.md sections 1 and 8): a volumetric path tracer for the full
// radiative transfer equation of the medium the mappers approximate. Delta tracking over a
// majorant grid samples free flights, ratio tracking estimates the transmittance of next-event
// estimation to every light (directional, point, spot), directions come from the
// Henyey–Greenstein phase function, the albedo is chromatic (albedo times the colour), the medium
// emits k_e (1 - albedo) sigma_t c, and Russian roulette ends paths. With surfaces inside the
// medium (ShadeOn, SurfaceShading.h) a collision is a surface event with probability P_s:
// next-event estimation through k_a c times the phase function plus the BRDF, and the path goes
// on by the phase function (k_a), the diffuse lobe (k_d), the specular lobe (k_s) or ends.
// Deterministic for a seed whatever the threads, progressive (one sample per pixel per pass), same
// camera as the mappers.
#ifndef avs_PathTracer_h
#define avs_PathTracer_h

#include "Camera.h"
#include "MajorantGrid.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"

#include <cstdint>
#include <functional>

namespace avs
{

struct PathTracerSettings
{
  int SamplesPerPixel = 64;
  std::uint64_t Seed = 1;
  int MajorantCellSize = 8; ///< voxels per majorant cell and axis
  int RouletteDepth = 4;    ///< bounces before Russian roulette starts
  int MaximumBounces = 100000;
};

struct PathTracerStatistics
{
  std::uint64_t Paths = 0;
  std::uint64_t RealCollisions = 0;
  std::uint64_t NullCollisions = 0; ///< tentative collisions of delta and ratio tracking
};

/// Renders `scene` with the medium parameters of `parameters` (albedo, anisotropy, emission
/// weight; resolved). As the reference renderer's: RGB the radiance the volume sends to the
/// camera (the environment is black), A the share of primary rays that collided (an unbiased
/// estimate of 1 - transmittance), so Image::Composited puts it over a background. `progress` gets
/// the fraction of passes done, from the calling thread. `secondMoment`, when given, receives the
/// mean of the squares of the samples per pixel and channel (alpha: the mean of the 0/1 hits), so
/// that a caller can tell the estimate's variance (the GPU estimator's tests).
Image RenderPathTraced(const VolumeScene& scene,
  const ScatteringParameters& parameters,
  const PathTracerSettings& settings,
  const Camera& camera,
  int width,
  int height,
  PathTracerStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {},
  Image* secondMoment = nullptr);

/// Tools of the path tracer, exposed for the tests.
class VolumeTracker
{
public:
  /// `surfaces`: the precomputed gradient its surfaces read (Classifier::SetSurfaceGrid;
  /// null: taken where asked), which must outlive it.
  VolumeTracker(const VolumeScene& scene,
    const MajorantGrid& majorants,
    const SurfaceGrid* surfaces = nullptr);

  /// Delta tracking from world point `origin` along unit `direction` up to world distance
  /// `maximum` (and the volume box): returns the distance of a real collision, or a negative
  /// value when the ray leaves without one.
  double SampleCollision(const Vec3& origin,
    const Vec3& direction,
    double maximum,
    class Random& rng,
    PathTracerStatistics& stats) const;
  /// Ratio tracking: an unbiased estimate of the transmittance along the segment.
  double Transmittance(const Vec3& origin,
    const Vec3& direction,
    double maximum,
    class Random& rng,
    PathTracerStatistics& stats) const;
  /// sigma_t and colour at a world point (zero outside the volume).
  double Extinction(const Vec3& world, Vec3* color = nullptr) const;
  /// The point with extinction `sigmaT` as a surface (SurfaceShading.h) for the blending.
  SurfacePoint Surface(const Vec3& world, double sigmaT, double blending) const;

private:
  template<typename Visit>
  void Walk(const Vec3& origin,
    const Vec3& direction,
    double maximum,
    class Random& rng,
    Visit&& visit) const;
  const VolumeScene& Scene;
  const MajorantGrid& Majorants;
  Classifier Classify;
};

} // namespace avs

#endif
