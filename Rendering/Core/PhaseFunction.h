// The Henyey–Greenstein phase function (ALGORITHM.md section 1) as an Eval / Sample / PDF triple.
//
// Convention: mu is the cosine between the propagation direction of the incoming light and the
// propagation direction of the scattered light (mu = 1: straight on, no deflection). The function
// is normalised over the sphere of directions:
//
//     p_g(mu) = (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^(3/2)),   integral over the sphere = 1.
//
// VTK's shaders use 4 pi p_g; pbrt's HenyeyGreenstein takes the cosine between the two directions
// pointing *away* from the scattering point, i.e. -mu. Neither convention is used here.
#ifndef avs_PhaseFunction_h
#define avs_PhaseFunction_h

#include "Vec3.h"

namespace avs
{

/// Largest |g| the project supports (ALGORITHM.md section 1).
constexpr double MaximumAnisotropy = 0.95;

/// Clamps g into [-0.95, 0.95].
double ClampAnisotropy(double g);

/// p_g(mu) as above. |g| is clamped; mu is clamped into [-1, 1].
double HenyeyGreenstein(double mu, double g);

struct PhaseSample
{
  Vec3 Direction; ///< propagation direction of the scattered light
  double Mu = 1;  ///< cosine between incoming and scattered propagation directions
  double Pdf = 0; ///< solid-angle density of Direction; equals HenyeyGreenstein(Mu, g)
};

/// Samples the cosine mu of p_g from a uniform number u in [0, 1) (exact inversion).
double SampleHenyeyGreensteinCosine(double u, double g);

/// Samples a scattered propagation direction for light propagating along `incoming` (unit),
/// from two uniform numbers in [0, 1). The returned pdf is the phase function's value.
PhaseSample SampleHenyeyGreenstein(const Vec3& incoming, double g, double u1, double u2);

/// The pdf of SampleHenyeyGreenstein: identical to the phase function (perfect importance
/// sampling).
inline double HenyeyGreensteinPdf(double mu, double g)
{
  return HenyeyGreenstein(mu, g);
}

} // namespace avs

#endif
