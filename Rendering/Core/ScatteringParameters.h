// The one parameter struct of the renderers: the CPU reference reads it, the VTK mappers fill it
// from their properties and upload it as shader uniforms, so the two cannot drift apart.
// Defaults here are the mappers' defaults; 0 for a length means "automatic" (see Resolve).
#ifndef avs_ScatteringParameters_h
#define avs_ScatteringParameters_h

#include "DisplayTransform.h"
#include "Grid.h"
#include "SurfaceShading.h"

#include <algorithm>
#include <cmath>

namespace avs
{

enum class RenderMode
{
  EmissionAbsorption, ///< ALGORITHM.md section 2
  AmbientOcclusion,   ///< section 7
  AmbientScattering   ///< sections 3-6
};

/// Which model of ambient scattering (ARCHITECTURE.md, "Beyond the paper").
enum class ScatteringModel
{
  Paper,   ///< ALGORITHM.md sections 3-6 as published
  Extended ///< the paper's plus the diffuse fluence of a diffusion solve (DiffuseFluence.h)
};

struct ScatteringParameters
{
  // Medium (section 1).
  double Albedo = 0.8;         ///< Lambda in [0, 1]
  double Anisotropy = 0.0;     ///< Henyey–Greenstein g in [-0.95, 0.95]
  double AmbientRadius = 0.0;  ///< r in the grid's (data) units; 0: automatic
  double EmissionWeight = 0.0; ///< k_e >= 0: emitted radiance k_e c
  /// >= 0: multiplies every light's irradiance (VTK light units, E = 4 pi I c LightScale); applied
  /// where the VTK lights are translated (vtkAVSSceneTranslator::ToLights).
  double LightScale = 1.0;

  /// Surfaces inside the medium (SurfaceShading.h): ShadeOn, the Phong coefficients and the
  /// blending; ambient scattering only.
  SurfaceShading Surface;

  // The extended model (DiffuseFluence.h).
  ScatteringModel Model = ScatteringModel::Extended;
  int DiffusionVolumeMaximumDimension = 64; ///< the diffusion grid: the light grid, capped
  int DiffusionIterations = 8;              ///< red-black SOR sweeps on the diffusion grid
  int DiffusionCoarseIterations = 24; ///< the sweeps on each coarser level of the nested solve

  // Ambient occlusion (section 7).
  double OcclusionRadius = 0.0;   ///< R in data units; 0: the ambient radius
  int NumberOfDirections = 32;    ///< K >= 14
  double AmbientWeight = 1.0;     ///< k_amb
  double DirectLightWeight = 0.0; ///< optional unshadowed direct light in the AO renderer

  // Ray casting.
  double SampleDistance = 0.0; ///< data units; 0: automatic (half the smallest spacing)
  double TerminationTransmittance = 1.0 / 255.0; ///< stop a ray when T falls below
  int LightVolumeMaximumDimension = 128;     ///< light volumes use the data's size, capped by this
  int OcclusionVolumeMaximumDimension = 128; ///< the AO volume likewise

  // Display (DisplayTransform.h): exposure and tone curve of the linear radiance. The defaults
  // here are the identity (the emission-absorption and ambient-occlusion mappers' defaults);
  // vtkAmbientScatteringVolumeMapper sets its own.
  DisplayTransform Display;
  /// Display.Exposure is multiplied by AutoExposureFactor of the lights (the mappers meter it;
  /// after Resolve, Display.Exposure is still the user's factor).
  bool AutoExposure = false;

  /// The automatic ambient radius of a grid: 1/64 of the box diagonal, but at least one voxel,
  /// and at most half the box's smallest side, so that the ball fits into thin volumes (a slab of
  /// two voxels, a stack of a few slices).
  static double DefaultAmbientRadius(const GridGeometry& g)
  {
    const double minSpacing = std::min({ g.Spacing.x, g.Spacing.y, g.Spacing.z });
    const Vec3 side = g.LocalExtent();
    const double smallestSide = std::min({ side.x, side.y, side.z });
    const double r = std::max(g.Diagonal() / 64.0, minSpacing);
    return smallestSide > 0.0 ? std::min(r, 0.5 * smallestSide) : r;
  }
  /// The automatic sample distance: half the smallest spacing.
  static double DefaultSampleDistance(const GridGeometry& g)
  {
    return 0.5 * std::min({ g.Spacing.x, g.Spacing.y, g.Spacing.z });
  }

  /// How many consecutive ray samples ambient scattering reads its lights (the light volumes,
  /// the averaged extinction, the table and the extended model's fluence) for at once, at their
  /// midpoint (ARCHITECTURE.md, "The lights once per group of samples"): 4 where four steps of
  /// `sampleDistance` (a resolved SampleDistance) span at most one cell of the light grid
  /// `lightGrid` along every axis, where the lights are interpolated linearly between its nodes
  /// (with the automatic step of half a voxel: a light grid at least twice as coarse as the
  /// data's, as the default 128 per axis on volumes of 255 voxels or more), else 2 where two
  /// steps do, else 1 (each sample its own).
  static int LightGroup(double sampleDistance, const GridGeometry& lightGrid)
  {
    const Vec3& s = lightGrid.Spacing;
    const double cell = std::min({ s.x, s.y, s.z }) * (1.0 + 1e-9);
    if (!(sampleDistance > 0.0))
    {
      return 1;
    }
    return 4.0 * sampleDistance <= cell ? 4 : (2.0 * sampleDistance <= cell ? 2 : 1);
  }

  /// A copy with automatic values filled in for grid g and values clamped into their ranges.
  ScatteringParameters Resolve(const GridGeometry& g) const
  {
    ScatteringParameters p = *this;
    p.Albedo = std::clamp(p.Albedo, 0.0, 1.0);
    p.Anisotropy = std::clamp(p.Anisotropy, -0.95, 0.95);
    if (!(p.AmbientRadius > 0.0) || !std::isfinite(p.AmbientRadius))
    {
      p.AmbientRadius = DefaultAmbientRadius(g);
    }
    p.EmissionWeight = std::max(0.0, p.EmissionWeight);
    p.LightScale = std::isfinite(p.LightScale) ? std::max(0.0, p.LightScale) : 1.0;
    if (!(p.OcclusionRadius > 0.0) || !std::isfinite(p.OcclusionRadius))
    {
      p.OcclusionRadius = p.AmbientRadius;
    }
    p.NumberOfDirections = std::max(14, p.NumberOfDirections);
    p.AmbientWeight = std::max(0.0, p.AmbientWeight);
    p.DirectLightWeight = std::max(0.0, p.DirectLightWeight);
    if (!(p.SampleDistance > 0.0) || !std::isfinite(p.SampleDistance))
    {
      p.SampleDistance = DefaultSampleDistance(g);
    }
    p.TerminationTransmittance = std::clamp(p.TerminationTransmittance, 0.0, 1.0);
    p.LightVolumeMaximumDimension = std::max(2, p.LightVolumeMaximumDimension);
    p.OcclusionVolumeMaximumDimension = std::max(2, p.OcclusionVolumeMaximumDimension);
    p.DiffusionVolumeMaximumDimension = std::max(2, p.DiffusionVolumeMaximumDimension);
    p.DiffusionIterations = std::clamp(p.DiffusionIterations, 0, 4096);
    p.DiffusionCoarseIterations = std::clamp(p.DiffusionCoarseIterations, 0, 4096);
    p.Surface = p.Surface.Resolved();
    p.Display.Exposure =
      std::isfinite(p.Display.Exposure) ? std::max(0.0, p.Display.Exposure) : 1.0;
    return p;
  }
};

} // namespace avs

#endif
