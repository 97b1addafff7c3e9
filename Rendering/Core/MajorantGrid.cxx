#include "MajorantGrid.h"

#include "ReferenceRenderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

MajorantGrid::MajorantGrid(const Grid& scalars,
  const TransferFunction& tf,
  double unitDistance,
  int cellSize,
  const ClipRegion* clip)
  : Size(std::max(1, cellSize))
{
  VolumeScene scene;
  scene.Scalars = scalars;
  scene.Transfer = tf;
  scene.UnitDistance = unitDistance;
  *this = MajorantGrid(Classifier(scene), scalars.Geometry, cellSize, clip);
}

MajorantGrid::MajorantGrid(const Classifier& classifier,
  const GridGeometry& geometry,
  int cellSize,
  const ClipRegion* clip)
  : Size(std::max(1, cellSize))
{
  const auto& d = geometry.Dimensions;
  for (int a = 0; a < 3; ++a)
  {
    // Cells cover voxel intervals [c B, (c + 1) B]; the last ends at n - 1.
    this->Count[a] = std::max(1, (d[a] - 1 + this->Size - 1) / this->Size);
  }
  this->Values.assign(
    static_cast<std::size_t>(this->Count[0]) * this->Count[1] * this->Count[2], 0.0);
  for (int ck = 0; ck < this->Count[2]; ++ck)
    for (int cj = 0; cj < this->Count[1]; ++cj)
      for (int ci = 0; ci < this->Count[0]; ++ci)
      {
        const std::array<int, 3> lo{ ci * this->Size, cj * this->Size, ck * this->Size };
        const std::array<int, 3> hi{ std::min(d[0] - 1, (ci + 1) * this->Size),
          std::min(d[1] - 1, (cj + 1) * this->Size),
          std::min(d[2] - 1, (ck + 1) * this->Size) };
        double m = classifier.Bound(lo, hi);
        const Vec3 low{
          static_cast<double>(lo[0]), static_cast<double>(lo[1]), static_cast<double>(lo[2])
        };
        if (clip && clip->Clips() &&
          clip->BoxOutside(low, low + Vec3{ 1.0, 1.0, 1.0 } * static_cast<double>(this->Size)))
        {
          m = 0.0; // nothing of the cell is there
        }
        this->Values[(static_cast<std::size_t>(ck) * this->Count[1] + cj) * this->Count[0] + ci] =
          m;
        this->Largest = std::max(this->Largest, m);
      }
}

double MajorantGrid::At(const Vec3& index) const
{
  int c[3];
  for (int a = 0; a < 3; ++a)
  {
    c[a] = std::clamp(static_cast<int>(std::floor(index[a] / this->Size)), 0, this->Count[a] - 1);
  }
  return this->Cell(c[0], c[1], c[2]);
}

} // namespace avs
