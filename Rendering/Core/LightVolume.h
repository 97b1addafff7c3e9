// Light volumes by tube marching (ALGORITHM.md section 5).
//
// For a point x, the light path runs from x0 (where the light enters the volume box, or the
// point light itself when it is inside the box) to x, D = |x - x0|. Balls of radius r are
// chained along it, anchored at x: with n = floor(D / 2r) and eta = D / 2r - n, n whole balls
// centred at x - (2i + 1) r d (i < n) and the rest, 2 r eta long, at the light's end as a ball
// centred at x0 + eta r d weighted as seed eq. 8.5 weights its last ball:
// T(x) = prod_i F(r avg_sigma_t(m_i)) ((1 - eta) + eta F(r avg_sigma_t(x0 + eta r d))).
// This is ALGORITHM.md section 5's product of the same number of factors, counted from x
// instead of x0, so that the balls sit at the same places relative to x whatever the distance
// to the box face: counted from x0, T behind a dense surface depends on (the surface's distance
// from x0 mod 2r) and shows bands of period 2r (ARCHITECTURE.md, "Light volumes"). With
// albedo 0, F = exp(-2 tau) and this is a shadow ray with step 2r over the averaged extinction.
//
// A light volume stores, at each grid point x, T where the light enters the ball of radius r
// around x: at x - r d (x0 when that is nearer to x). The ray caster lights the ball around x'
// with it. The scattering table's ball is lit by unit irradiance at its surface. Lighting it
// with T(x') instead would attenuate the light over the ball's near half twice, once in the
// tube and once inside the table. The seed's eq. 8.9 likewise takes each light's distributed
// radiance at its own point x_j, not at x'. ARCHITECTURE.md records this choice.
#ifndef avs_LightVolume_h
#define avs_LightVolume_h

#include "Grid.h"
#include "Lights.h"
#include "ScatteringTable.h"

#include <cstdint>
#include <functional>

namespace avs
{

/// How a tube passes the light on from ball to ball.
enum class TubeLaw
{
  /// F(tau, g, albedo) per ball (ALGORITHM.md section 5): the direct light and the light
  /// scattered forwards (the paper's model; the extended model's directional lights).
  Forward,
  /// exp(-2 tau) per ball: the unscattered light alone, which follows the light's own falloff
  /// (the extended model's positional lights, whose scattered light the diffusion solve carries;
  /// ARCHITECTURE.md, "Beyond the paper", says why).
  DirectBeam
};

/// The law of a light volume of a light of `type` in the paper's model (`extended` false) or the
/// extended one.
TubeLaw TubeLawFor(bool extended, LightType type);

struct LightVolumeStatistics
{
  std::uint64_t Steps = 0; ///< balls marched, over all voxels
};

/// The light volume of `light` on the grid `target` (same box as `averaged`): at each point,
/// BallEntryTransmittance. `slice` holds F for the current g and albedo; `radius` is the
/// ambient radius r (> 0). Multi-threaded.
Grid ComputeLightVolume(const Grid& averaged,
  const GridGeometry& target,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  LightVolumeStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {},
  TubeLaw law = TubeLaw::Forward);

/// The tube transmittance T at one world point.
double TubeTransmittance(const Grid& averaged,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& world,
  std::uint64_t* steps = nullptr,
  TubeLaw law = TubeLaw::Forward);

/// T where the light enters the ball of radius `radius` around a world point: at distance
/// max(D - r, 0) from x0 on the light path (what ComputeLightVolume stores per point).
double BallEntryTransmittance(const Grid& averaged,
  const Light& light,
  const ScatteringSlice& slice,
  double radius,
  const Vec3& world,
  std::uint64_t* steps = nullptr,
  TubeLaw law = TubeLaw::Forward);

/// Dimensions of a light volume for data of dimensions `dims` capped at `maximum` per axis,
/// keeping the aspect ratio.
std::array<int, 3> LightVolumeDimensions(const std::array<int, 3>& dims, int maximum);

} // namespace avs

#endif
