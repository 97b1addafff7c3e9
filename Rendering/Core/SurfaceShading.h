// Surfaces inside the medium (ALGORITHM.md section 11; ARCHITECTURE.md, "Surfaces"): with
// ShadeOn, a sample where the normalised gradient is strong reflects the light that reaches it
// like a surface, with the vtkVolumeProperty's Phong coefficients made an energy-conserving
// BRDF, and elsewhere scatters it with the phase function. One definition for every renderer:
// the CPU reference (ReferenceRenderer.cxx), the GPU (avs_surface.glsl) and the path tracer.
//
//   gamma = h |grad s| / range      the gradient of the shading component normalised by its
//                                   range, per mean spacing h (VTK's gradient: central
//                                   differences one voxel on either side)
//   alpha = 1 - exp(-sigma_t u)     the sample's opacity per unit distance u
//   P_s   = (1 - exp(-gamma / gamma_0)) (1 - w(B, gamma / gamma_0, alpha)),
//   w     = VTK's volumetric weight of VolumetricScatteringBlending B: B exp(-B g alpha) below 1,
//           (2 - B) exp(-B g alpha) + B - 1 from 1 (w = 0 at B = 0, 1 at B = 2)
//
// A scattering event (albedo) is a surface event with probability P_s. A surface event returns
// k_a of what a phase-function event would of the ball's light (the light of the neighbourhood:
// the ambient term), k_a + k_d (times c) + k_s (white) of the extended model's diffuse field (near
// isotropic, which a BRDF reflects by its integral; DiffuseFieldColor), and reflects the light
// that arrives directly from the lights with the BRDF
//
//   f = k_d c / pi + k_s (p + 2) / (2 pi) max(0, r.v)^p,   r the light's mirror direction,
//
// on the viewer's side of the normal n = -grad s / |grad s| (two-sided: n turned towards the
// viewer; one-sided: nothing where the viewer or the light is behind n). k_a + k_d + k_s are
// scaled down to 1 where they sum to more, so that no event returns more than it receives. In
// ambient scattering the direct light is the light volume's times e^(-l sigma~), l = min(r,
// 1 / sigma~) / 2 (ARCHITECTURE.md, "Surfaces inside the medium"). The renderers read gamma's
// direction and the first factor of P_s from a precomputed grid (SurfaceGrid.h).
#ifndef avs_SurfaceShading_h
#define avs_SurfaceShading_h

#include "Vec3.h"

namespace avs
{

struct MediumOptions;

/// gamma_0: the normalised gradient at which 63 % of the scattering events are surface events
/// (blending 0): 1/32 of the range per voxel.
constexpr double SurfaceGradientReference = 1.0 / 16.0;

struct SurfaceShading
{
  bool Shade = false;          ///< the property's ShadeOn (component 0)
  double Blending = 0.0;       ///< the mapper's VolumetricScatteringBlending B in [0, 2]
  double Ambient = 0.1;        ///< k_a
  double Diffuse = 0.7;        ///< k_d
  double Specular = 0.2;       ///< k_s
  double SpecularPower = 10.0; ///< p
  bool TwoSided = true;        ///< the renderer's TwoSidedLighting

  /// Whether the hybrid changes anything: ShadeOn and B below 2.
  bool Active() const { return this->Shade && this->Blending < 2.0; }
  /// Coefficients clamped to >= 0 and scaled to sum at most 1, B into [0, 2], p into [0, 128].
  SurfaceShading Resolved() const;
};

/// The share of the events that are surface events, P_s(gamma, alpha, B) above.
double SurfaceProbability(double gamma, double alpha, double blending);
/// Its first factor, the edge share 1 - exp(-gamma / gamma_0) (what SurfaceGrid.h stores).
double SurfaceEdge(double gamma);
/// P_s from the edge share e (gamma / gamma_0 = -ln(1 - e)): e (1 - w); e itself at B = 0.
double SurfaceProbabilityOfEdge(double edge, double alpha, double blending);

/// What a sample returns of the volumetric (phase-function) light: 1 - P_s (1 - k_a).
inline double VolumetricShare(double surfaceProbability, double ambient)
{
  return 1.0 - surfaceProbability * (1.0 - ambient);
}

/// The colour with which a sample of colour c returns the extended model's diffuse field (near
/// isotropic light): the medium with c, a surface with k_a c (its ambient share) plus the
/// BRDF's integral over the field, k_d c + k_s, where the surface faces the viewer (Facing):
/// c (1 - P_s (1 - k_a - k_d)) + P_s k_s, or c (1 - P_s (1 - k_a)).
inline Vec3 DiffuseFieldColor(double surfaceProbability,
  const SurfaceShading& s,
  const Vec3& c,
  bool facing)
{
  const double p = surfaceProbability;
  const double k = facing ? p * s.Specular : 0.0;
  return c * (1.0 - p * (1.0 - s.Ambient - (facing ? s.Diffuse : 0.0))) + Vec3{ k, k, k };
}

/// Whether a surface with normal `normal` reflects towards `toViewer` (always on two sides; on
/// one side where the viewer is in front of it), and the normal turned to the viewer.
bool Facing(const SurfaceShading& s, const Vec3& normal, const Vec3& toViewer, Vec3& facing);

/// Directions for a path that leaves a surface (the path tracer): cosine-weighted about the
/// facing normal n (pdf cos / pi), and about the direction `mirror` within the Phong lobe of
/// power p (pdf (p + 1) / (2 pi) cos^p), from two uniform numbers in [0, 1).
Vec3 SampleCosine(const Vec3& n, double u1, double u2);
Vec3 SamplePhongLobe(const Vec3& mirror, double power, double u1, double u2);

/// The BRDF times the cosine at the light for light arriving from `toLight`, seen from
/// `toViewer` (unit vectors away from the point), with the normal `normal` (unit): the diffuse
/// part (times the colour) and the specular part (white). Both 0 on the dark side.
struct SurfaceReflectance
{
  double Diffuse = 0.0;
  double Specular = 0.0;
};
SurfaceReflectance Reflect(const SurfaceShading& s,
  const Vec3& normal,
  const Vec3& toLight,
  const Vec3& toViewer);

/// The component whose gradient gives the normal: the one that gives the opacity (0; 1 for
/// dependent colour and opacity; 3 for dependent RGBA).
int ShadingComponent(const MediumOptions& medium);

} // namespace avs

#endif
