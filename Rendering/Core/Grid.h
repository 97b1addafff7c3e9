// A scalar field on a regular grid in world space, as vtkImageData holds it: dimensions,
// origin, spacing and a direction matrix; values stored x fastest. The core works with float
// values; the VTK adapters convert any scalar type.
#ifndef avs_Grid_h
#define avs_Grid_h

#include "Vec3.h"

#include <array>
#include <cstddef>
#include <vector>

namespace avs
{

/// Placement of a regular grid in world space. world = origin + D * (index * spacing), with D the
/// 3x3 direction matrix (row-major, orthonormal), exactly as vtkImageData defines it.
///
/// The grid's points are its samples (the lattice). The volume they fill (the box) is the
/// lattice's box, widened by `Border` samples on every side: 0 for point data, 0.5 for cell data,
/// whose samples sit at the cell centres while the volume spans the points (as VTK renders cell
/// scalars). Inside the border a sample takes the value at the nearest face of the lattice.
struct GridGeometry
{
  std::array<int, 3> Dimensions{ 1, 1, 1 };
  Vec3 Origin{ 0, 0, 0 };
  Vec3 Spacing{ 1, 1, 1 };
  std::array<double, 9> Direction{ 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double Border = 0.0; ///< samples the box extends beyond the lattice on every side (0 or 0.5)

  std::size_t NumberOfPoints() const
  {
    return static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] *
      this->Dimensions[2];
  }
  std::size_t Index(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * this->Dimensions[1] + j) * this->Dimensions[0] + i;
  }

  /// Continuous index (i, j, k) of a world point.
  Vec3 WorldToIndex(const Vec3& world) const;
  /// World point of a continuous index.
  Vec3 IndexToWorld(const Vec3& index) const;
  /// A world-space direction expressed in the grid's local (axis-aligned, unscaled) frame.
  Vec3 WorldToLocalDirection(const Vec3& d) const;
  /// A local-frame direction in world space.
  Vec3 LocalToWorldDirection(const Vec3& d) const;
  /// A world point in the local frame: local = D^T (world - origin); the box is [0, (n-1) s].
  Vec3 WorldToLocal(const Vec3& world) const
  {
    return this->WorldToLocalDirection(world - this->Origin);
  }
  Vec3 LocalToWorld(const Vec3& local) const
  {
    return this->Origin + this->LocalToWorldDirection(local);
  }
  /// Upper corner of the lattice's box in the local frame, (n - 1) * spacing per axis.
  Vec3 LocalExtent() const
  {
    return { (this->Dimensions[0] - 1) * this->Spacing.x,
      (this->Dimensions[1] - 1) * this->Spacing.y,
      (this->Dimensions[2] - 1) * this->Spacing.z };
  }
  /// Corners of the volume's box in the local frame: the lattice's box widened by the border.
  Vec3 BoxLower() const { return this->Spacing * (-this->Border); }
  Vec3 BoxUpper() const { return this->LocalExtent() + this->Spacing * this->Border; }
  /// The same placement with other dimensions covering the same lattice box, without a border
  /// (for coarser grids: light volumes, averaged extinction, occlusion).
  GridGeometry Resampled(const std::array<int, 3>& dims) const;
  /// The same box with at most `maximum` points per axis (at least 2), keeping the aspect
  /// ratio: the grid of the light volumes, the averaged extinction and the occlusion volume.
  GridGeometry Capped(int maximum) const;
  /// Length of the box diagonal in world units.
  double Diagonal() const { return Length(this->LocalExtent()); }
};

/// A float field on a grid.
struct Grid
{
  GridGeometry Geometry;
  std::vector<float> Values;

  Grid() = default;
  explicit Grid(const GridGeometry& geometry, float value = 0.0f)
    : Geometry(geometry)
    , Values(geometry.NumberOfPoints(), value)
  {
  }

  float& At(int i, int j, int k) { return this->Values[this->Geometry.Index(i, j, k)]; }
  float At(int i, int j, int k) const { return this->Values[this->Geometry.Index(i, j, k)]; }

  /// Trilinear interpolation at a continuous index; points outside the box return `outside`
  /// (ALGORITHM.md: empty space outside the volume), points on the boundary are interpolated, and
  /// points in the border (cell data) take the value at the lattice's nearest face.
  double SampleIndex(const Vec3& index, double outside = 0.0) const;
  /// The value of the nearest sample (floor(index + 0.5), as a GPU's nearest filter picks it),
  /// with the same treatment of the box as SampleIndex.
  double NearestIndex(const Vec3& index, double outside = 0.0) const;
  /// Trilinear interpolation with the index clamped into the lattice (a GPU texture's clamp to
  /// the edge): for grids that cover a volume's lattice while the volume's border reaches beyond.
  double SampleClamped(const Vec3& index) const;
  /// Trilinear interpolation at a world point.
  double SampleWorld(const Vec3& world, double outside = 0.0) const
  {
    return this->SampleIndex(this->Geometry.WorldToIndex(world), outside);
  }
};

/// Intersection of the ray o + t d (local frame) with the box [0, extent]: returns false when the
/// ray misses; otherwise t0 <= t1 are the entry and exit parameters (t0 may be negative).
bool IntersectBox(const Vec3& extent, const Vec3& o, const Vec3& d, double& t0, double& t1);
/// The same for the volume's box of `g` (BoxLower to BoxUpper, local frame).
bool IntersectVolumeBox(const GridGeometry& g,
  const Vec3& o,
  const Vec3& d,
  double& t0,
  double& t1);

} // namespace avs

#endif
