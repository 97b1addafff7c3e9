// Local volumetric ambient occlusion (ALGORITHM.md section 7), after Hernell, Ljung and
// Ynnerman (TVCG 2010):
//
//     AO(x) = (1 / K) sum_k exp(-integral_0^R sigma_t(x + s v_k) ds)
//
// over K well-spread directions v_k (a spherical Fibonacci set), stored on a grid.
#ifndef avs_AmbientOcclusion_h
#define avs_AmbientOcclusion_h

#include "Grid.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace avs
{

/// K unit directions spread evenly over the sphere (spherical Fibonacci points).
std::vector<Vec3> SphereDirections(int count);

struct OcclusionStatistics
{
  std::uint64_t Samples = 0; ///< extinction samples taken
};

/// AO on the grid `target` from the extinction grid `sigmaT` (same box). Integration by the
/// midpoint rule with step `step` (0: half the smallest spacing). Multi-threaded.
Grid ComputeAmbientOcclusion(const Grid& sigmaT,
  const GridGeometry& target,
  double radius,
  int directions,
  double step = 0.0,
  OcclusionStatistics* statistics = nullptr,
  const std::function<void(double)>& progress = {});

} // namespace avs

#endif
