// The extended model's long-range multiple scattering (ARCHITECTURE.md, "Beyond the paper"):
// the diffuse fluence phi of the light the tubes lose to scattering, from the diffusion
// equation on a coarse grid, solved by nested red-black SOR sweeps (coarse grids to fine).
//
//   -div(D grad phi) + sigma_a phi = q,   D = 1 / (3 sigma'),   sigma' = sigma~t (1 - albedo g),
//   sigma_a = (1 - albedo) sigma~t,       q = sigma~t b sum_j w_j E_j^free T_j(x),
//
// with sigma~t the averaged extinction (section 3), T_j the light volumes (section 5; for
// positional lights the direct beam, TubeLaw::DirectBeam) at x (read r downstream of x, since a
// light volume holds T at the ball's entry), w_j = DiffusionSourceWeight (albedo (1 - g) for
// directional lights, albedo for positional ones), b = BeyondTheBall (the share the ball term does
// not count) and E_j^free the lights' free irradiance (RGB: phi has three channels). D is limited
// to TransportLengthLimit / 3; cells with sigma' h < VacuumOpticalDepth are vacuum; a face between
// the medium and vacuum (or the grid's border) carries Marshak's condition phi = 2 D dphi/dn.
// The ray caster adds T (1 - exp(-sigma_t dt)) albedo c (phi + g clamp(3 D dphi/dt, -phi, phi))
// / (4 pi) per sample: the P1 field's light scattered towards the camera by the phase function.
#ifndef avs_DiffuseFluence_h
#define avs_DiffuseFluence_h

#include "Grid.h"
#include "LightVolume.h"
#include "Lights.h"

#include <array>
#include <cstdint>
#include <vector>

namespace avs
{

struct DiffusionSettings
{
  double Albedo = 0.9;
  double Anisotropy = 0.0;
  int Iterations = 8;                ///< red-black SOR sweeps (each: red then black cells)
  int CoarseIterations = 24;         ///< the sweeps on each coarser level (ComputeDiffusion)
  double Relaxation = 1.85;          ///< SOR factor omega in (0, 2)
  double TransportLengthLimit = 1.0; ///< 1 / sigma' at most (world units; 16 r in the renderers)
  /// r: a light volume holds T where the light enters the ball around a point, r before it, so
  /// the source reads T at x r downstream of x; and it keeps only the light's share beyond the
  /// ball (BeyondTheBall).
  double AmbientRadius = 0.0;
};

/// Cells whose reduced optical depth sigma' h (h the mean spacing) is below this are vacuum:
/// rounding in the averaged extinction's sums leaves traces of ~1e-7 in empty space, which must
/// not become a conducting medium.
constexpr double VacuumOpticalDepth = 1e-3;

/// The transport mean free path limit of the renderers, in ambient radii.
constexpr double TransportLengthLimitInRadii = 16.0;

/// The share of sigma~t E T~ that a light's tube gives the diffusion as its source, by the law of
/// its tube (TubeLawFor(true, type)): albedo (1 - g) where the tube's F keeps the
/// forward-scattered share g (Forward), albedo where it carries the direct light alone
/// (DirectBeam: all scattered light goes to the diffusion).
double DiffusionSourceWeight(TubeLaw law, double albedo, double anisotropy);

/// The share of the light diffusing from a point source that lies beyond the ambient ball
/// around it, (1 + kappa r) exp(-kappa r) with kappa = sqrt(sigma_a / D) (the infinite
/// homogeneous medium's Green function; D flux-limited as in the solve): the ball term (the
/// table A) already counts the light's scattering inside the ball, so the source q is weighted by
/// this, which is 1 in thin or conservative media and at r -> 0.
double BeyondTheBall(double sigma, const DiffusionSettings& settings);

/// The diffusion grid: the light grid (or any grid over the data's lattice box) capped at
/// `maximum` points per axis.
GridGeometry DiffusionGeometry(const GridGeometry& data, int maximum);

/// The source q (RGB, three grids on `target`) from the averaged extinction and the light volumes
/// (all on the light grid) and the lights.
std::array<Grid, 3> DiffusionSource(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const GridGeometry& target,
  const DiffusionSettings& settings);

/// phi (RGB) on the source's grid. `averaged` is the averaged extinction on the same grid.
/// `residual`, if given, receives the final relative residual |q - A phi|_1 / |q|_1 (channel 0).
/// The sweeps start from `initial` (three grids on the same grid) where given, else from 0;
/// vacuum cells hold 0 either way.
std::array<Grid, 3> SolveDiffusion(const Grid& averaged,
  const std::array<Grid, 3>& source,
  const DiffusionSettings& settings,
  double* residual = nullptr,
  const std::array<Grid, 3>* initial = nullptr);

/// The levels of the nested solve, finest (`finest` itself) first: each next one halves every
/// axis of more than two points ((n + 1) / 2, over the same box), down to the first level with
/// at most NestedCoarsestDimension points on every axis.
constexpr int NestedCoarsestDimension = 8;
std::vector<GridGeometry> DiffusionLevels(const GridGeometry& finest);

/// The extended model's whole solve on `target` (DiffusionGeometry), by nested iteration: on
/// each level from the coarsest up, the averaged extinction resampled there, the source
/// (DiffusionSource) evaluated there, and `settings.CoarseIterations` sweeps (on the finest
/// level `settings.Iterations`) starting from the coarser level's phi interpolated trilinearly
/// onto it (0 on the coarsest). The light diffuses over the coarse levels, where a sweep reaches
/// far and costs little, and the finer sweeps only correct what the coarser grid could not
/// resolve. `averaged` and `lightVolumes` are on the light grid.
std::array<Grid, 3> ComputeDiffusion(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const GridGeometry& target,
  const DiffusionSettings& settings,
  double* residual = nullptr);

} // namespace avs

#endif
