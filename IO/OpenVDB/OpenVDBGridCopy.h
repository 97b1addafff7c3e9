// The copy of an OpenVDB grid's box into a VTK array, averaging f^3 blocks (private to
// vtkOpenVDBImageReader): one output z-slab at a time, in chunks of whole blocks, so the memory
// stays bounded whatever the box.
#ifndef avs_OpenVDBGridCopy_h
#define avs_OpenVDBGridCopy_h

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace avs
{

/// Where the output sits and how it is sampled.
struct OpenVDBLayout
{
  openvdb::CoordBBox Box; ///< inclusive index box read from the grid
  int Factor = 1;         ///< downsampling factor
  int Dimensions[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
};

/// Values per chunk of the copy: memory stays bounded whatever the box.
constexpr std::int64_t ChunkValues = std::int64_t(1) << 22;

/// The copy of a typed grid's box into the output array, averaging f^3 blocks: one output
/// z-slab at a time, in chunks of whole blocks (the whole slab when it fits ChunkValues).
/// `Out` is the VTK array's value type; `components` 1 or 3; `convert` maps a grid value to
/// `components` output values; `progress` gets the share of slabs done. Returns false when a
/// value is NaN or infinite.
template<typename GridT, typename Out, typename Convert>
bool CopyGrid(const GridT& grid,
  const OpenVDBLayout& L,
  Out* out,
  int components,
  Convert convert,
  const std::function<void(double)>& progress)
{
  using ValueT = typename GridT::ValueType;
  const openvdb::Coord lo = L.Box.min();
  const openvdb::Coord hi = L.Box.max();
  const std::int64_t f = L.Factor;
  const std::int64_t nx = L.Dimensions[0], ny = L.Dimensions[1], nz = L.Dimensions[2];
  const std::int64_t block = f * f * f;
  // Chunk: cx x cy output voxels of one z-slab.
  std::int64_t cx = nx, cy = 1;
  if (nx * block > ChunkValues)
  {
    cx = std::max<std::int64_t>(1, ChunkValues / block);
  }
  else
  {
    cy = std::max<std::int64_t>(1, std::min(ny, ChunkValues / (nx * block)));
  }
  // A plain array: std::vector<bool> has no data().
  std::unique_ptr<ValueT[]> chunk(new ValueT[static_cast<std::size_t>(cx * cy * block)]);
  std::vector<double> sum(static_cast<std::size_t>(cx * cy * components));
  std::vector<std::int64_t> count(static_cast<std::size_t>(cx * cy));
  double values[3];
  bool finite = true;
  for (std::int64_t kz = 0; kz < nz; ++kz)
  {
    const std::int64_t z0 = lo.z() + kz * f;
    const std::int64_t z1 = std::min<std::int64_t>(hi.z(), z0 + f - 1);
    for (std::int64_t jy = 0; jy < ny; jy += cy)
    {
      const std::int64_t y0 = lo.y() + jy * f;
      const std::int64_t y1 = std::min<std::int64_t>(hi.y(), y0 + cy * f - 1);
      for (std::int64_t ix = 0; ix < nx; ix += cx)
      {
        const std::int64_t x0 = lo.x() + ix * f;
        const std::int64_t x1 = std::min<std::int64_t>(hi.x(), x0 + cx * f - 1);
        const openvdb::CoordBBox box(openvdb::Coord(static_cast<openvdb::Int32>(x0),
                                       static_cast<openvdb::Int32>(y0),
                                       static_cast<openvdb::Int32>(z0)),
          openvdb::Coord(static_cast<openvdb::Int32>(x1),
            static_cast<openvdb::Int32>(y1),
            static_cast<openvdb::Int32>(z1)));
        openvdb::tools::Dense<ValueT, openvdb::tools::LayoutXYZ> dense(box, chunk.get());
        openvdb::tools::copyToDense(grid, dense); // multi-threaded
        const std::int64_t bx = x1 - x0 + 1, by = y1 - y0 + 1, bz = z1 - z0 + 1;
        const std::int64_t ox = (bx + f - 1) / f, oy = (by + f - 1) / f;
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(count.begin(), count.end(), 0);
        for (std::int64_t z = 0; z < bz; ++z)
          for (std::int64_t y = 0; y < by; ++y)
            for (std::int64_t x = 0; x < bx; ++x)
            {
              convert(chunk[static_cast<std::size_t>((z * by + y) * bx + x)], values);
              const std::size_t o = static_cast<std::size_t>((y / f) * ox + x / f);
              for (int c = 0; c < components; ++c)
              {
                finite = finite && std::isfinite(values[c]);
                sum[o * components + c] += values[c];
              }
              ++count[o];
            }
        for (std::int64_t y = 0; y < oy; ++y)
          for (std::int64_t x = 0; x < ox; ++x)
          {
            const std::size_t o = static_cast<std::size_t>(y * ox + x);
            const std::size_t p = static_cast<std::size_t>((kz * ny + jy + y) * nx + ix + x);
            for (int c = 0; c < components; ++c)
            {
              // f == 1: a single value, copied exactly (integers stay exact).
              out[p * components + c] = static_cast<Out>(
                count[o] == 1 ? sum[o * components + c] : sum[o * components + c] / count[o]);
            }
          }
      }
    }
    progress(static_cast<double>(kz + 1) / nz);
  }
  return finite;
}

} // namespace avs

#endif
