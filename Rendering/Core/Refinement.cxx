#include "Refinement.h"

#include <algorithm>
#include <cstddef>

namespace avs
{

double RefinementWeight(const RefinementBuffers& b, int x, int y)
{
  const double n = b.Samples;
  if (b.Samples < RefinementMinimumSamples || b.Width < 1 || b.Height < 1)
  {
    return 0.0;
  }
  double difference = 0.0, variance = 0.0;
  int count = 0;
  const int R = RefinementWindowRadius;
  for (int dy = -R; dy <= R; ++dy)
  {
    for (int dx = -R; dx <= R; ++dx)
    {
      // Clamped to the picture, as the GPU's texelFetch of the clamped coordinate.
      const int qx = std::clamp(x + dx, 0, b.Width - 1);
      const int qy = std::clamp(y + dy, 0, b.Height - 1);
      const std::size_t at = 4 * (static_cast<std::size_t>(qy) * b.Width + qx);
      for (int c = 0; c < 4; ++c)
      {
        const double m = b.Mean[at + c];
        const double d = m - b.Ambient[at + c];
        difference += d * d;
        variance += std::max(b.MeanOfSquares[at + c] - m * m, 0.0) / (n - 1.0);
      }
      ++count;
    }
  }
  difference /= count;
  variance /= count;
  const double bias2 = std::max(difference - 2.0 * variance, 0.0);
  return bias2 + variance > 0.0 ? bias2 / (bias2 + variance) : 1.0;
}

std::vector<float> RefinedPicture(const RefinementBuffers& b)
{
  std::vector<float> out(b.Ambient);
  for (int y = 0; y < b.Height; ++y)
  {
    for (int x = 0; x < b.Width; ++x)
    {
      const double w = RefinementWeight(b, x, y);
      const std::size_t at = 4 * (static_cast<std::size_t>(y) * b.Width + x);
      for (int c = 0; c < 4; ++c)
      {
        out[at + c] =
          static_cast<float>(b.Ambient[at + c] + w * (b.Mean[at + c] - b.Ambient[at + c]));
      }
    }
  }
  return out;
}

} // namespace avs
