// Which part of the volume is there (ALGORITHM.md section 1): clipping planes and cropping, in
// the continuous index frame of the data's grid. Material outside the region is absent for every
// purpose: sigma_t = 0 in the rays, the averaged extinction, the light volumes, AO and the path
// tracer, so light enters through a cut. The GPU's copy is Rendering/Shaders/avs_clip.glsl.
//
// - Clipping planes (vtkAbstractMapper::ClippingPlanes): half-spaces; a point is kept where
//   dot(n, x - o) >= 0 for every plane (the normal points into the kept side, as VTK's).
//   Given in world coordinates, they are expressed here in the index frame through the
//   index -> world map of the data (PlaneToIndex), which stays exact for any affine map
//   (the vtkVolume's scale, shear and user matrix included).
// - Cropping (vtkVolumeMapper::Cropping): two planes per index axis cut the grid into 3 x 3 x 3
//   regions; region (a, b, c), a, b, c in {0, 1, 2} (below the lower plane, between, from the
//   upper plane on), is kept where bit a + 3 b + 9 c of the flags is set, as VTK numbers them
//   (0x2000, bit 13, is the middle region: VTK's sub-volume preset).
#ifndef avs_ClipRegion_h
#define avs_ClipRegion_h

#include "Grid.h"
#include "Vec3.h"

#include <array>
#include <vector>

namespace avs
{

/// A half-space of the index frame: kept where dot(Normal, index) + Offset >= 0.
struct IndexPlane
{
  Vec3 Normal{ 0, 0, 1 };
  double Offset = 0.0;

  double Evaluate(const Vec3& index) const { return Dot(this->Normal, index) + this->Offset; }
  bool operator==(const IndexPlane& o) const
  {
    return this->Normal.x == o.Normal.x && this->Normal.y == o.Normal.y &&
      this->Normal.z == o.Normal.z && this->Offset == o.Offset;
  }
};

struct ClipRegion
{
  /// Clipping planes the renderers take (vtkGPUVolumeRayCastMapper's shader holds 8).
  static constexpr int MaximumNumberOfPlanes = 8;
  /// VTK's sub-volume preset: the middle region only.
  static constexpr int SubVolume = 0x0002000;

  std::vector<IndexPlane> Planes;
  bool Cropping = false;
  /// Cropping planes in the index frame: i_low, i_high, j_low, j_high, k_low, k_high.
  std::array<double, 6> CroppingPlanes{ 0, 0, 0, 0, 0, 0 };
  int CroppingRegionFlags = SubVolume;

  /// Whether anything is clipped or cropped at all.
  bool Clips() const { return !this->Planes.empty() || this->Cropping; }
  /// Whether a continuous index lies in the kept part (on a plane counts as kept).
  bool IsInside(const Vec3& index) const;
  /// The cropping region (0-26) of a continuous index.
  int Region(const Vec3& index) const;
  /// The box of the index frame that holds every kept cropping region (unbounded sides are
  /// +-1e30); false when no region is kept. Without cropping: everything.
  bool KeptBox(Vec3& low, Vec3& high) const;
  /// Shortens [t0, t1] of the ray index(t) = o + t d to the part inside every plane and inside
  /// the kept box (the kept regions themselves are tested per sample); false when nothing is
  /// left.
  bool ClipRay(const Vec3& o, const Vec3& d, double& t0, double& t1) const;
  /// Whether the whole index box [low, high] is outside (a conservative test: false may still
  /// be outside). For majorants.
  bool BoxOutside(const Vec3& low, const Vec3& high) const;

  bool operator==(const ClipRegion& o) const
  {
    return this->Planes == o.Planes && this->Cropping == o.Cropping &&
      (!this->Cropping ||
        (this->CroppingPlanes == o.CroppingPlanes &&
          this->CroppingRegionFlags == o.CroppingRegionFlags));
  }
  bool operator!=(const ClipRegion& o) const { return !(*this == o); }
};

/// The world plane through `origin` with `normal` (kept where dot(normal, x - origin) >= 0)
/// in the index frame of a grid placed by the affine map world = A index + b, given row-major
/// as { A00, A01, A02, b0, A10, ..., b2 }. The normal is normalised first; it must not be zero.
IndexPlane PlaneToIndex(const Vec3& origin,
  const Vec3& normal,
  const std::array<double, 12>& indexToWorld);

/// The index -> world map of a grid alone (no further transform), as PlaneToIndex takes it.
std::array<double, 12> IndexToWorldMap(const GridGeometry& g);

/// Sets the values of `values` (on the data's grid) to 0 at the voxels outside `region`.
void ClearOutside(const ClipRegion& region, Grid& values);

} // namespace avs

#endif
