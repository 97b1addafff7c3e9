// The CPU reference ray caster (ALGORITHM.md sections 2, 6 and 7): emission–absorption, ambient
// occlusion and ambient scattering with any number of lights, in double precision, into an RGBA
// float image. Short and obviously correct: the GPU mappers are measured against it.
#ifndef avs_ReferenceRenderer_h
#define avs_ReferenceRenderer_h

#include "Camera.h"
#include "ClipRegion.h"
#include "Grid.h"
#include "Lights.h"
#include "Medium.h"
#include "ScatteringParameters.h"
#include "ScatteringTable.h"
#include "TransferFunction.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace avs
{

/// What the renderers draw: the scalars on a grid, the transfer functions, the unit distance of
/// the opacity, the lights, the background behind the volume, and which part of the volume is
/// there (clipping planes and cropping, ClipRegion.h). Scalars, Transfer and UnitDistance are
/// component 0; Medium holds the rest (more components, gradient opacity, interpolation, NaN
/// voxels, a mask), and Classifier turns both into sigma_t and colour.
struct VolumeScene
{
  Grid Scalars;
  TransferFunction Transfer;
  double UnitDistance = 1.0;
  MediumOptions Medium;
  std::vector<Light> Lights;
  Vec3 Background{ 0, 0, 0 };
  ClipRegion Clip; ///< in the index frame of Scalars; material outside is absent
};

/// RGBA float image, row 0 at the bottom (VTK's convention). RGB is the radiance L the volume
/// adds (premultiplied), A = 1 - T.
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Pixels;

  float* At(int x, int y)
  {
    return &this->Pixels[4 * (static_cast<std::size_t>(y) * this->Width + x)];
  }
  const float* At(int x, int y) const
  {
    return &this->Pixels[4 * (static_cast<std::size_t>(y) * this->Width + x)];
  }
  /// The pixel composited over `background`: L + T * background.
  Vec3 Composited(int x, int y, const Vec3& background) const;
};

/// The volumes the ray caster reads, computed once per change of their inputs.
struct PrecomputedVolumes
{
  Grid Extinction;                ///< sigma_t at the voxels
  Grid Averaged;                  ///< averaged sigma_t (section 3) on the light volumes' grid,
                                  ///< where tube marching and the rays read it
  std::vector<Grid> LightVolumes; ///< one per light (section 5)
  Grid Occlusion;                 ///< AO (section 7)
  std::vector<Grid> Diffuse;      ///< extended model: RGB fluence phi (DiffuseFluence.h)
  ScatteringSlice Slice;          ///< A and F for the current g and albedo
};

/// sigma_t at every voxel of the scalars' grid, classified (Classifier::AtVoxel); 0 outside the
/// scene's clip region.
Grid ExtinctionGrid(const VolumeScene& scene);

/// The extended model's diffuse fluence (DiffuseFluence.h, three grids: RGB) from the averaged
/// extinction and the light volumes on the light grid: solved on the diffusion grid
/// (ComputeDiffusion) and interpolated onto the light grid, where the rays read it.
std::vector<Grid> ComputeDiffuse(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const ScatteringParameters& resolved,
  double* residual = nullptr);

/// Computes what `mode` needs (the table is needed for ambient scattering). Returns false and
/// says why in `error` for unusable input.
bool Precompute(const VolumeScene& scene,
  const ScatteringParameters& resolved,
  const ScatteringTable* table,
  RenderMode mode,
  PrecomputedVolumes& out,
  std::string* error = nullptr,
  const std::function<void(double)>& progress = {});

/// Renders the scene. `resolved` must come from ScatteringParameters::Resolve.
Image RenderReference(const VolumeScene& scene,
  const ScatteringParameters& resolved,
  const PrecomputedVolumes& volumes,
  RenderMode mode,
  const Camera& camera,
  int width,
  int height,
  const std::function<void(double)>& progress = {});

} // namespace avs

#endif
