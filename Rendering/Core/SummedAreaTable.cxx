#include "SummedAreaTable.h"

#include <algorithm>

namespace avs
{

SummedAreaTable::SummedAreaTable(const float* values, const std::array<int, 3>& dims)
  : Dims(dims)
{
  const std::size_t nx = dims[0] + 1, ny = dims[1] + 1, nz = dims[2] + 1;
  this->Table.assign(nx * ny * nz, 0.0);
  auto idx = [&](std::size_t i, std::size_t j, std::size_t k) { return (k * ny + j) * nx + i; };
  // Separable build: running sums along x, then y, then z; each entry is touched once per axis.
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      double run = 0.0;
      const float* row = values + (static_cast<std::size_t>(k) * dims[1] + j) * dims[0];
      for (int i = 0; i < dims[0]; ++i)
      {
        run += row[i];
        this->Table[idx(i + 1, j + 1, k + 1)] = run;
      }
    }
  }
  for (std::size_t k = 1; k < nz; ++k)
  {
    for (std::size_t j = 2; j < ny; ++j)
    {
      for (std::size_t i = 1; i < nx; ++i)
      {
        this->Table[idx(i, j, k)] += this->Table[idx(i, j - 1, k)];
      }
    }
  }
  for (std::size_t k = 2; k < nz; ++k)
  {
    for (std::size_t j = 1; j < ny; ++j)
    {
      for (std::size_t i = 1; i < nx; ++i)
      {
        this->Table[idx(i, j, k)] += this->Table[idx(i, j, k - 1)];
      }
    }
  }
  this->Operations = 3ull * dims[0] * dims[1] * dims[2];
}

double SummedAreaTable::BoxSum(std::array<int, 3> lo, std::array<int, 3> hi) const
{
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(lo[a], 0);
    hi[a] = std::min(hi[a], this->Dims[a] - 1);
    if (lo[a] > hi[a])
    {
      return 0.0;
    }
  }
  // Exclusive upper corner (hi + 1) and lower corner lo in table coordinates.
  const int x0 = lo[0], y0 = lo[1], z0 = lo[2];
  const int x1 = hi[0] + 1, y1 = hi[1] + 1, z1 = hi[2] + 1;
  return this->At(x1, y1, z1) - this->At(x0, y1, z1) - this->At(x1, y0, z1) - this->At(x1, y1, z0) +
    this->At(x0, y0, z1) + this->At(x0, y1, z0) + this->At(x1, y0, z0) - this->At(x0, y0, z0);
}

} // namespace avs
