#include "OccupancyGrid.h"

#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

namespace
{
// The lattice points a sample in cell a reads on an axis of n points (see the header).
int SupportBegin(int a, int size)
{
  return std::max(0, a * size - 1);
}
int SupportEnd(int a, int size, int n) // exclusive
{
  return std::min(n, (a + 1) * size + 2);
}
} // namespace

ValueRangeGrid::ValueRangeGrid(const std::array<int, 3>& dimensions,
  int components,
  int cellSize,
  const RowReader& read,
  const std::vector<float>& validity)
  : Lattice(dimensions)
  , Size(std::max(1, cellSize))
  , ComponentCount(std::clamp(components, 1, 4))
{
  const int B = this->Size;
  for (int a = 0; a < 3; ++a)
  {
    this->Count[a] = std::max(1, (dimensions[a] + B - 1) / B);
  }
  const int nx = dimensions[0], ny = dimensions[1], nz = dimensions[2];
  const int cx = this->Count[0], cy = this->Count[1], cz = this->Count[2];
  const int C = this->ComponentCount;
  constexpr float inf = std::numeric_limits<float>::infinity();
  // Per lattice slice z: the ranges over x and y of each (cx, cy) cell column.
  const std::size_t perSlice = static_cast<std::size_t>(cx) * cy * 4;
  std::vector<float> sliceLow(perSlice * nz, inf), sliceHigh(perSlice * nz, -inf);
  ParallelFor(nz,
    [&](std::int64_t z0, std::int64_t z1)
    {
      std::vector<float> row(static_cast<std::size_t>(nx));
      // Per row y: the ranges over x of each cx cell.
      std::vector<float> rowLow(static_cast<std::size_t>(ny) * cx * 4);
      std::vector<float> rowHigh(rowLow.size());
      for (std::int64_t z = z0; z < z1; ++z)
      {
        std::fill(rowLow.begin(), rowLow.end(), inf);
        std::fill(rowHigh.begin(), rowHigh.end(), -inf);
        for (int y = 0; y < ny; ++y)
        {
          const std::size_t begin = (static_cast<std::size_t>(z) * ny + y) * nx;
          const float* valid = validity.empty() ? nullptr : validity.data() + begin;
          for (int c = 0; c < C; ++c)
          {
            read(c, begin, begin + nx, row.data());
            for (int i = 0; i < cx; ++i)
            {
              float lo = inf, hi = -inf;
              for (int x = SupportBegin(i, B); x < SupportEnd(i, B, nx); ++x)
              {
                if (valid && !(valid[x] > 0.0f))
                {
                  continue; // a NaN voxel adds no value to the samples' range
                }
                lo = std::min(lo, row[x]);
                hi = std::max(hi, row[x]);
              }
              const std::size_t at = (static_cast<std::size_t>(y) * cx + i) * 4 + c;
              rowLow[at] = lo;
              rowHigh[at] = hi;
            }
          }
        }
        float* low = sliceLow.data() + perSlice * z;
        float* high = sliceHigh.data() + perSlice * z;
        for (int j = 0; j < cy; ++j)
        {
          for (int y = SupportBegin(j, B); y < SupportEnd(j, B, ny); ++y)
          {
            for (int k = 0; k < cx * 4; ++k)
            {
              const std::size_t at = static_cast<std::size_t>(j) * cx * 4 + k;
              low[at] = std::min(low[at], rowLow[static_cast<std::size_t>(y) * cx * 4 + k]);
              high[at] = std::max(high[at], rowHigh[static_cast<std::size_t>(y) * cx * 4 + k]);
            }
          }
        }
      }
    });
  this->Lows.assign(this->NumberOfCells() * 4, inf);
  this->Highs.assign(this->Lows.size(), -inf);
  for (int k = 0; k < cz; ++k)
  {
    float* low = this->Lows.data() + perSlice * k;
    float* high = this->Highs.data() + perSlice * k;
    for (int z = SupportBegin(k, B); z < SupportEnd(k, B, nz); ++z)
    {
      for (std::size_t at = 0; at < perSlice; ++at)
      {
        low[at] = std::min(low[at], sliceLow[perSlice * z + at]);
        high[at] = std::max(high[at], sliceHigh[perSlice * z + at]);
      }
    }
  }
}

std::vector<float> Majorants(const ValueRangeGrid& ranges, const Classifier& classifier)
{
  std::vector<float> majorants(ranges.NumberOfCells(), 0.0f);
  const int C = ranges.Components();
  for (std::size_t cell = 0; cell < majorants.size(); ++cell)
  {
    double low[4] = { 0, 0, 0, 0 }, high[4] = { 0, 0, 0, 0 };
    bool any = true;
    for (int c = 0; c < C; ++c)
    {
      low[c] = ranges.Low(cell, c);
      high[c] = ranges.High(cell, c);
      any = any && low[c] <= high[c];
    }
    if (any)
    {
      // Rounded up, so that the float is still a bound.
      const double bound = classifier.BoundOfValues(low, high, true);
      float f = static_cast<float>(bound);
      if (static_cast<double>(f) < bound)
      {
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
      }
      majorants[cell] = f;
    }
  }
  return majorants;
}

std::vector<unsigned char> Occupancy(const ValueRangeGrid& ranges, const Classifier& classifier)
{
  const std::vector<float> majorants = Majorants(ranges, classifier);
  std::vector<unsigned char> occupied(majorants.size(), 0);
  for (std::size_t cell = 0; cell < majorants.size(); ++cell)
  {
    occupied[cell] = majorants[cell] > 0.0f ? 1 : 0;
  }
  return occupied;
}

double EmptyFraction(const std::vector<unsigned char>& occupancy)
{
  if (occupancy.empty())
  {
    return 0.0;
  }
  const auto empty = std::count(occupancy.begin(), occupancy.end(), 0);
  return static_cast<double>(empty) / static_cast<double>(occupancy.size());
}

} // namespace avs
