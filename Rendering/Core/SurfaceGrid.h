// The surfaces' gradient, precomputed per voxel (SurfaceShading.h; ARCHITECTURE.md, "Surfaces
// inside the medium"): for every lattice point the direction of the shading component's
// gradient in the grid's local frame (VTK's central differences one voxel on either side, the
// neighbours clamped into the lattice, divided by the spacing) times its edge share
// e = 1 - exp(-gamma / gamma_0), quantised into three bytes (and e alone into a fourth, which
// the decoding does not read: a sample's edge share is the length of the interpolated e n, so
// that one texel can carry the scalar beside it). The GPU reads it in one fetch per pair of
// samples (avs_surface.glsl), where six fetches of the scalars would make the gradient on the
// fly; the CPU reference and the path tracer read the same bytes the same way
// (Classifier::SurfaceAt), so that all of them agree.
#ifndef avs_SurfaceGrid_h
#define avs_SurfaceGrid_h

#include "Vec3.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace avs
{

struct VolumeScene;

struct SurfaceGrid
{
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  /// RGBA per lattice point, x fastest: the components of e n, n the unit local gradient, as
  /// 128 + round(127 e n) (128 where the gradient vanishes), and e as round(255 e).
  std::vector<std::uint8_t> Texels;

  bool Empty() const { return this->Texels.empty(); }
  std::size_t Bytes() const { return this->Texels.size(); }

  /// The decoded values at a continuous index clamped into the lattice, trilinear (or of the
  /// nearest point), as a GPU texture filters them: e n interpolated (its direction the local
  /// gradient's; 0 where the gradient vanishes) and the edge share, its length (at most 1).
  void Sample(const Vec3& index, bool nearest, Vec3& direction, double& edge) const;

  /// The byte of a unit-vector component and of an edge share, and back.
  static std::uint8_t EncodeDirection(double n);
  static std::uint8_t EncodeEdge(double e);
  static double DecodeDirection(double byte) { return (byte - 128.0) / 127.0; }
  static double DecodeEdge(double byte) { return byte / 255.0; }
};

/// The lattice's values `values[0, count)` from point `first` on, divided by the validity there
/// as the classifier divides them (empty validity: all valid), 0 where it is 0 or a value is NaN:
/// what a SurfaceSliceReader writes.
void DivideByValidity(const std::vector<float>& validity,
  std::size_t first,
  std::size_t count,
  float* values);

/// Writes lattice slice k of the shading component (its values divided by the validity, 0 where
/// that is 0; n0 n1 floats, x fastest) into `out`.
using SurfaceSliceReader = std::function<void(int k, float* out)>;

/// The grid of a lattice of `dimensions` and `spacing` whose shading component's transfer
/// function spans 1 / `inverseRange`, its slices read once each, in order, through `read`;
/// computed on `threads` threads (0: the default).
SurfaceGrid MakeSurfaceGrid(const std::array<int, 3>& dimensions,
  const Vec3& spacing,
  double inverseRange,
  const SurfaceSliceReader& read,
  int threads = 0);
/// The same from the scene's own grids (Classifier's shading component and range); empty where
/// they hold no values.
SurfaceGrid MakeSurfaceGrid(const VolumeScene& scene, int threads = 0);

} // namespace avs

#endif
