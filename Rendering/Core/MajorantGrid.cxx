#include "MajorantGrid.h"

#include "Extinction.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

namespace
{
// Largest sigma_t of the (linearly interpolated) opacity table over scalars [lo, hi].
double MaximumExtinction(const TransferFunction& tf, double unitDistance, double lo, double hi)
{
  double alpha = std::max(tf.OpacityAt(lo), tf.OpacityAt(hi));
  const std::size_t n = tf.Opacity.size();
  if (n > 1 && tf.Maximum > tf.Minimum)
  {
    const double step = (tf.Maximum - tf.Minimum) / (n - 1);
    const double a = std::clamp((lo - tf.Minimum) / step, 0.0, static_cast<double>(n - 1));
    const double b = std::clamp((hi - tf.Minimum) / step, 0.0, static_cast<double>(n - 1));
    for (std::size_t i = static_cast<std::size_t>(std::ceil(a)); i <= static_cast<std::size_t>(b);
         ++i)
    {
      alpha = std::max(alpha, static_cast<double>(tf.Opacity[i]));
    }
  }
  return OpacityToExtinction(alpha, unitDistance);
}
} // namespace

MajorantGrid::MajorantGrid(const Grid& scalars,
  const TransferFunction& tf,
  double unitDistance,
  int cellSize,
  const ClipRegion* clip)
  : Size(std::max(1, cellSize))
{
  const auto& d = scalars.Geometry.Dimensions;
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
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (int k = ck * this->Size; k <= std::min(d[2] - 1, (ck + 1) * this->Size); ++k)
          for (int j = cj * this->Size; j <= std::min(d[1] - 1, (cj + 1) * this->Size); ++j)
            for (int i = ci * this->Size; i <= std::min(d[0] - 1, (ci + 1) * this->Size); ++i)
            {
              const double s = scalars.At(i, j, k);
              lo = std::min(lo, s);
              hi = std::max(hi, s);
            }
        double m = MaximumExtinction(tf, unitDistance, lo, hi);
        const Vec3 low{ static_cast<double>(ci * this->Size),
          static_cast<double>(cj * this->Size),
          static_cast<double>(ck * this->Size) };
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
