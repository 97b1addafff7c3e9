#include "vtkAVSBricks.h"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <numeric>

void vtkAVSBricks::Clear()
{
  this->Bricks.clear();
  this->Partitions = { 1, 1, 1 };
  for (auto& c : this->Cuts)
  {
    c.clear();
  }
}

void vtkAVSBricks::Split(const std::array<int, 3>& d,
  const std::array<int, 3>& partitions,
  double border,
  const std::array<int, 3>& ghost)
{
  this->Clear();
  for (int a = 0; a < 3; ++a)
  {
    const int n = std::clamp(partitions[a], 1, std::max(1, d[a] - 1));
    this->Partitions[a] = n;
    for (int k = 0; k <= n; ++k)
    {
      // Near-equal ranges of the d - 1 voxel intervals.
      this->Cuts[a].push_back(static_cast<int>((static_cast<long long>(d[a] - 1) * k) / n));
    }
  }
  const std::array<int, 3>& p = this->Partitions;
  for (int k = 0; k < p[2]; ++k)
  {
    for (int j = 0; j < p[1]; ++j)
    {
      for (int i = 0; i < p[0]; ++i)
      {
        Brick b;
        b.Cell = { i, j, k };
        for (int a = 0; a < 3; ++a)
        {
          const int c = b.Cell[a];
          const int lo = this->Cuts[a][c], hi = this->Cuts[a][c + 1];
          b.Low[a] = c == 0 ? -border : lo;
          b.High[a] = c == p[a] - 1 ? d[a] - 1 + border : hi;
          b.Origin[a] = std::max(0, lo - ghost[a]);
          b.Dimensions[a] = std::min(d[a] - 1, hi + ghost[a]) - b.Origin[a] + 1;
        }
        this->Bricks.push_back(b);
      }
    }
  }
}

bool vtkAVSBricks::PartitionsFor(const std::array<int, 3>& d,
  int maximumSize,
  const std::array<int, 3>& ghost,
  std::array<int, 3>& partitions,
  std::string& error)
{
  for (int a = 0; a < 3; ++a)
  {
    partitions[a] = 1;
    if (d[a] <= maximumSize)
    {
      continue;
    }
    // A brick of n intervals holds n + 1 voxels and at most 2 ghost layers.
    const int intervals = maximumSize - 1 - 2 * ghost[a];
    if (intervals < 1)
    {
      error = "the largest 3D texture (" + std::to_string(maximumSize) +
        " voxels per axis) is too small for a brick";
      return false;
    }
    partitions[a] = (d[a] - 1 + intervals - 1) / intervals;
    // The near-equal split's longest range is ceil((d - 1) / n) intervals.
    while ((d[a] - 1 + partitions[a] - 1) / partitions[a] > intervals)
    {
      ++partitions[a];
    }
  }
  return true;
}

std::vector<int> vtkAVSBricks::BackToFront(const std::array<double, 3>& eye) const
{
  std::array<int, 3> cell{ 0, 0, 0 };
  for (int a = 0; a < 3; ++a)
  {
    // The last cut plane at or below the eye, clamped to the grid's cells.
    const std::vector<int>& c = this->Cuts[a];
    int k = 0;
    while (k + 1 < this->Partitions[a] && eye[a] >= c[k + 1])
    {
      ++k;
    }
    cell[a] = k;
  }
  std::vector<int> key(this->Bricks.size());
  for (std::size_t b = 0; b < this->Bricks.size(); ++b)
  {
    const auto& c = this->Bricks[b].Cell;
    key[b] = std::abs(c[0] - cell[0]) + std::abs(c[1] - cell[1]) + std::abs(c[2] - cell[2]);
  }
  std::vector<int> order(this->Bricks.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&key](int a, int b) { return key[a] > key[b]; });
  return order;
}

avs::Grid vtkAVSBricks::Crop(const avs::Grid& grid,
  const std::array<int, 3>& origin,
  const std::array<int, 3>& dimensions)
{
  avs::Grid part;
  part.Geometry = grid.Geometry;
  part.Geometry.Dimensions = dimensions;
  const std::array<int, 3>& d = grid.Geometry.Dimensions;
  part.Values.reserve(static_cast<std::size_t>(dimensions[0]) * dimensions[1] * dimensions[2]);
  for (int z = 0; z < dimensions[2]; ++z)
  {
    for (int y = 0; y < dimensions[1]; ++y)
    {
      const std::size_t row =
        (static_cast<std::size_t>(origin[2] + z) * d[1] + origin[1] + y) * d[0] + origin[0];
      part.Values.insert(part.Values.end(),
        grid.Values.begin() + static_cast<std::ptrdiff_t>(row),
        grid.Values.begin() + static_cast<std::ptrdiff_t>(row + dimensions[0]));
    }
  }
  return part;
}

bool vtkAVSBricks::SameSplit(const vtkAVSBricks& other) const
{
  if (this->Bricks.size() != other.Bricks.size())
  {
    return false;
  }
  for (std::size_t b = 0; b < this->Bricks.size(); ++b)
  {
    const Brick& x = this->Bricks[b];
    const Brick& y = other.Bricks[b];
    if (x.Origin != y.Origin || x.Dimensions != y.Dimensions || x.Low != y.Low || x.High != y.High)
    {
      return false;
    }
  }
  return true;
}
