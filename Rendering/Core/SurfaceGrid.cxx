#include "SurfaceGrid.h"

#include "Classifier.h"
#include "Medium.h"
#include "Parallel.h"
#include "ReferenceRenderer.h"
#include "SurfaceShading.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

std::uint8_t SurfaceGrid::EncodeDirection(double n)
{
  const double clamped = std::clamp(n, -1.0, 1.0);
  return static_cast<std::uint8_t>(128 + static_cast<int>(std::floor(127.0 * clamped + 0.5)));
}

std::uint8_t SurfaceGrid::EncodeEdge(double e)
{
  return static_cast<std::uint8_t>(std::floor(255.0 * std::clamp(e, 0.0, 1.0) + 0.5));
}

void SurfaceGrid::Sample(const Vec3& index, bool nearest, Vec3& direction, double& edge) const
{
  direction = { 0, 0, 0 };
  edge = 0.0;
  if (this->Empty())
  {
    return;
  }
  const std::array<int, 3>& n = this->Dimensions;
  int lo[3], hi[3];
  double w[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = std::clamp(index[a], 0.0, static_cast<double>(n[a] - 1));
    if (nearest)
    {
      lo[a] = hi[a] = std::min(static_cast<int>(std::floor(x + 0.5)), n[a] - 1);
      w[a] = 0.0;
    }
    else
    {
      lo[a] = std::min(static_cast<int>(std::floor(x)), n[a] - 1);
      hi[a] = std::min(lo[a] + 1, n[a] - 1);
      w[a] = x - lo[a];
    }
  }
  double sum[4] = { 0, 0, 0, 0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const int i = corner & 1 ? hi[0] : lo[0];
    const int j = corner & 2 ? hi[1] : lo[1];
    const int k = corner & 4 ? hi[2] : lo[2];
    const double weight = (corner & 1 ? w[0] : 1.0 - w[0]) * (corner & 2 ? w[1] : 1.0 - w[1]) *
      (corner & 4 ? w[2] : 1.0 - w[2]);
    if (weight == 0.0)
    {
      continue;
    }
    const std::uint8_t* t =
      &this->Texels[4 * ((static_cast<std::size_t>(k) * n[1] + j) * n[0] + i)];
    for (int c = 0; c < 4; ++c)
    {
      sum[c] += weight * t[c];
    }
  }
  direction = { DecodeDirection(sum[0]), DecodeDirection(sum[1]), DecodeDirection(sum[2]) };
  edge = std::min(1.0, Length(direction));
}

void DivideByValidity(const std::vector<float>& validity,
  std::size_t first,
  std::size_t count,
  float* values)
{
  for (std::size_t v = 0; v < count; ++v)
  {
    const float valid = validity.empty() ? 1.0f : validity[first + v];
    values[v] = valid > 0.0f && values[v] == values[v] ? values[v] / valid : 0.0f;
  }
}

SurfaceGrid MakeSurfaceGrid(const std::array<int, 3>& n,
  const Vec3& spacing,
  double inverseRange,
  const SurfaceSliceReader& read,
  int threads)
{
  SurfaceGrid grid;
  grid.Dimensions = n;
  const std::size_t slice = static_cast<std::size_t>(n[0]) * n[1];
  grid.Texels.assign(4 * slice * n[2], 0);
  // gamma = h |grad s| / range with h the mean spacing; the gradient per world unit along axis
  // a is (s(+1) - s(-1)) / (2 h_a), the neighbours clamped into the lattice.
  const double mean = (spacing.x + spacing.y + spacing.z) / 3.0;
  const float sx = static_cast<float>(0.5 * inverseRange / spacing.x);
  const float sy = static_cast<float>(0.5 * inverseRange / spacing.y);
  const float sz = static_cast<float>(0.5 * inverseRange / spacing.z);
  // e = 1 - exp(-gamma / gamma_0), gamma = h |g|.
  const float reference = static_cast<float>(mean / SurfaceGradientReference);
  // Slices k - 1, k and k + 1 (clamped), read once each.
  std::vector<float> window[3];
  for (auto& w : window)
  {
    w.resize(slice);
  }
  int held[3] = { -1, -1, -1 }; // the slice each buffer holds
  auto slab = [&](int k) -> const float*
  {
    for (int b = 0; b < 3; ++b)
    {
      if (held[b] == k)
      {
        return window[b].data();
      }
    }
    const int b = k % 3; // k - 1, k, k + 1 land in different buffers
    read(k, window[b].data());
    held[b] = k;
    return window[b].data();
  };
  for (int k = 0; k < n[2]; ++k)
  {
    const float* below = slab(std::max(k - 1, 0));
    const float* here = slab(k);
    const float* above = slab(std::min(k + 1, n[2] - 1));
    ParallelFor(
      n[1],
      [&](std::int64_t begin, std::int64_t end)
      {
        for (int j = static_cast<int>(begin); j < end; ++j)
        {
          const float* row = here + static_cast<std::size_t>(j) * n[0];
          const float* back = here + static_cast<std::size_t>(std::max(j - 1, 0)) * n[0];
          const float* front = here + static_cast<std::size_t>(std::min(j + 1, n[1] - 1)) * n[0];
          const std::size_t at = static_cast<std::size_t>(j) * n[0];
          std::uint8_t* t = &grid.Texels[4 * (slice * k + at)];
          for (int i = 0; i < n[0]; ++i, t += 4)
          {
            const float gx = (row[std::min(i + 1, n[0] - 1)] - row[std::max(i - 1, 0)]) * sx;
            const float gy = (front[i] - back[i]) * sy;
            const float gz = (above[at + i] - below[at + i]) * sz;
            const float squared = gx * gx + gy * gy + gz * gz;
            if (!(squared > 0.0f) || !(squared < std::numeric_limits<float>::infinity()))
            {
              t[0] = t[1] = t[2] = 128;
              continue;
            }
            const float length = std::sqrt(squared);
            const float edge = 1.0f - std::exp(-length * reference);
            const float inverse = 127.0f * edge / length;
            // 128 + round(127 n), n in [-1, 1]: the byte's rounding without a library call.
            t[0] = static_cast<std::uint8_t>(static_cast<int>(gx * inverse + 128.5f));
            t[1] = static_cast<std::uint8_t>(static_cast<int>(gy * inverse + 128.5f));
            t[2] = static_cast<std::uint8_t>(static_cast<int>(gz * inverse + 128.5f));
            t[3] = static_cast<std::uint8_t>(static_cast<int>(255.0f * edge + 0.5f));
          }
        }
      },
      threads,
      4);
  }
  return grid;
}

SurfaceGrid MakeSurfaceGrid(const VolumeScene& scene, int threads)
{
  const Classifier classifier(scene);
  const int c = classifier.ShadingComponentIndex();
  const Grid& values = c == 0 ? scene.Scalars : scene.Medium.Components[c - 1].Values;
  const Grid& validity = scene.Medium.Validity;
  const GridGeometry& g = scene.Scalars.Geometry;
  if (values.Values.size() != g.NumberOfPoints() ||
    (!validity.Values.empty() && validity.Values.size() != g.NumberOfPoints()))
  {
    return SurfaceGrid(); // no values on the host
  }
  const std::size_t slice = static_cast<std::size_t>(g.Dimensions[0]) * g.Dimensions[1];
  const SurfaceSliceReader read = [&](int k, float* out)
  {
    const std::size_t first = slice * k;
    std::copy_n(values.Values.data() + first, slice, out);
    DivideByValidity(validity.Values, first, slice, out);
  };
  return MakeSurfaceGrid(g.Dimensions, g.Spacing, classifier.ShadingInverseRange(), read, threads);
}

} // namespace avs
