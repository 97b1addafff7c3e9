// Classification (ALGORITHM.md section 1): sigma_t and colour of a volume at a point, from its
// components, transfer functions, unit distances, weights, gradient opacity, interpolation,
// NaN voxels and mask (Medium.h). Every CPU renderer classifies through it: the extinction grid
// (averaged extinction, ambient occlusion), the reference ray caster and the path tracer (and
// its majorants). The GPU's classification (Rendering/Shaders/avs_classify.glsl) computes the
// same, so the mappers and the reference agree.
#ifndef avs_Classifier_h
#define avs_Classifier_h

#include "Grid.h"
#include "Medium.h"
#include "TransferFunction.h"

#include <array>
#include <vector>

namespace avs
{

struct VolumeScene;
struct SurfaceGrid;

struct Classified
{
  double SigmaT = 0.0;
  Vec3 Color{ 0, 0, 0 };
};

/// A sample as a surface (SurfaceShading.h): the share of surface events P_s and the world
/// normal -grad s / |grad s| (0 where the gradient vanishes, with P_s = 0).
struct SurfacePoint
{
  double Probability = 0.0;
  Vec3 Normal{ 0, 0, 0 };
};

class Classifier
{
public:
  /// Reads `scene` (its Scalars, Transfer, UnitDistance and Medium), which must outlive it.
  explicit Classifier(const VolumeScene& scene);

  /// At a continuous index of the scalars' lattice; (0, black) outside the volume's box.
  Classified AtIndex(const Vec3& index) const;
  /// At a point of the scalars' local frame (GridGeometry::WorldToLocal).
  Classified AtLocal(const Vec3& local) const;
  /// At a world point.
  Classified AtWorld(const Vec3& world) const;
  /// At a lattice point (what the extinction grid holds).
  Classified AtVoxel(int i, int j, int k) const;

  /// An upper bound of sigma_t anywhere the samples come from the lattice points lo..hi
  /// (inclusive, per axis): the path tracer's majorant of a cell.
  double Bound(const std::array<int, 3>& lo, const std::array<int, 3>& hi) const;
  /// An upper bound of sigma_t anywhere the components' values lie in [low[c], high[c]] (what
  /// Bound takes over the lattice points' values); `widen` widens each range by one node of
  /// the table it is looked up in (the GPU's table coordinate is rounded: OccupancyGrid.h).
  double BoundOfValues(const double low[4], const double high[4], bool widen) const;

  int NumberOfComponents() const { return this->Count; }

  /// The gradient magnitudes of the components at a continuous index, as VTK defines them
  /// (Medium.h, MediumOptions::GradientOpacity); exposed for the tests.
  std::array<double, 4> GradientMagnitudes(const Vec3& index) const;

  /// The shading component's gradient (ShadingComponent, SurfaceShading.h) at a continuous
  /// index, in index units: (s(x + e_a) - s(x - e_a)) / 2 per axis, divided by the component's
  /// range (its transfer function's).
  Vec3 ShadingGradient(const Vec3& index) const;
  /// gamma of SurfaceShading.h for a ShadingGradient: the mean spacing times |grad s| / range.
  double NormalisedGradient(const Vec3& shadingGradient) const;
  /// The sample at a continuous index with extinction `sigmaT` as a surface, for the blending
  /// B (SurfaceShading.h): P_s from the edge share and alpha = 1 - e^(-sigma_t u), the normal
  /// in world space (the gradient taken there by the transpose of d index / d world); both from
  /// the surface grid where one is set (SetSurfaceGrid).
  SurfacePoint SurfaceAt(const Vec3& index, double sigmaT, double blending) const;
  /// The same for a pair of samples at the indices a and b: from the mean of their e n (what
  /// the GPU reads for both samples of a pair; the edge share its length).
  SurfacePoint SurfaceAtMean(const Vec3& a, const Vec3& b, double sigmaT, double blending) const;
  /// 1 / the shading component's range (what the GPU uploads).
  double ShadingInverseRange() const { return this->InverseRange; }
  /// The component ShadingGradient differentiates (ShadingComponent, within the components).
  int ShadingComponentIndex() const { return this->ShadedComponent; }
  /// The precomputed gradient SurfaceAt reads (not owned; it must outlive the classifier): a
  /// MakeSurfaceGrid of the same scene, as the GPU reads it. Without one (null, the default)
  /// SurfaceAt takes the central differences where it is asked, unquantised.
  void SetSurfaceGrid(const SurfaceGrid* grid) { this->Surfaces = grid; }

private:
  /// e n at a continuous index, local frame per spacing: from the surface grid where one is set,
  /// else from the central differences there (unquantised).
  Vec3 SurfaceVectorAt(const Vec3& index) const;
  /// The surface of e n `v` for a sample with extinction `sigmaT` (its edge share |v|).
  SurfacePoint SurfaceOf(const Vec3& v, double sigmaT, double blending) const;
  // The components at `index` (normalised by the validity) and the validity there; false when
  // the point is outside the box.
  bool Sample(const Vec3& index, double s[4], double& valid) const;
  // The components at `index` clamped into the lattice (the gradient's samples).
  void SampleClamped(const Vec3& index, double s[4]) const;
  // VTK's central differences s(x + e_a) - s(x - e_a) of the components along each index axis
  // (the samples clamped into the lattice): what both gradients are made of.
  void CentralDifferences(const Vec3& index, double d[3][4]) const;
  Classified FromSamples(const Vec3& index, const double s[4], double valid) const;

  const VolumeScene& Scene;
  const MediumOptions& Medium;
  int Count = 1;
  const Grid* Values[4] = {};
  const TransferFunction* Transfer[4] = {};
  const TransferFunction* Gradient[4] = {};
  double UnitDistance[4] = { 1, 1, 1, 1 };
  double Weight[4] = { 1, 1, 1, 1 };
  Vec3 GradientScale{ 0.5, 0.5, 0.5 }; // mean spacing / (2 spacing_a)
  bool AnyGradient = false;
  int ShadedComponent = 0;
  Vec3 ToIndex[3]; // rows of d index / d world
  double InverseRange = 1.0;
  const SurfaceGrid* Surfaces = nullptr;
};

/// Everything sigma_t depends on apart from the grids (opacity tables, ranges, unit distances,
/// weights, gradient opacity, interpolation, mode, labels' opacities, blend factor), as a list of
/// numbers: the renderers rebuild their extinction-based volumes when it changes and not for a
/// change of colour alone.
std::vector<double> ExtinctionKey(const VolumeScene& scene);
/// ExtinctionKey and the colour tables: everything the classification of a sample depends on
/// apart from the grids (the path-traced refinement restarts when it changes).
std::vector<double> AppearanceKey(const VolumeScene& scene);

} // namespace avs

#endif
