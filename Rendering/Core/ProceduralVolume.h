// Procedural volumes for the demo, the benchmarks and the tests: structure at several scales,
// made from a seed, nothing downloaded.
#ifndef avs_ProceduralVolume_h
#define avs_ProceduralVolume_h

#include "Grid.h"

#include <cstdint>

namespace avs
{

/// Smooth value noise in [0, 1] at p (lattice spacing 1).
double ValueNoise(const Vec3& p, std::uint64_t seed);
/// Fractal sum of `octaves` octaves of value noise, normalised to [0, 1].
double FractalNoise(const Vec3& p, int octaves, std::uint64_t seed);

/// A nebula: a turbulent shell around a hollow centre (where a point light sits in the demo),
/// with filaments and holes at several scales. n^3 voxels over the box [-1, 1]^3, values in
/// [0, 1].
Grid MakeNebula(int n, std::uint64_t seed = 7);

/// A cumulus-like cloud: a lumpy, flat-bottomed blob with billows at several scales, n^3
/// voxels over [-1, 1]^3, values in [0, 1].
Grid MakeCloud(int n, std::uint64_t seed = 11);

} // namespace avs

#endif
