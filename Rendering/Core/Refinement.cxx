#include "Refinement.h"

#include <algorithm>
#include <cstddef>

namespace avs
{

RefinementBands RefinementWeights(const RefinementBuffers& b, int x, int y)
{
  RefinementBands bands;
  const double n = b.Samples;
  if (b.Samples < RefinementMinimumSamples || b.Width < 1 || b.Height < 1)
  {
    return bands;
  }
  double sum[4] = { 0, 0, 0, 0 }, squares = 0.0, variance = 0.0, own = 0.0;
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
      const double a = std::clamp(static_cast<double>(b.Ambient[at + 3]), 0.0, 1.0);
      for (int c = 0; c < 4; ++c)
      {
        const double m = b.Mean[at + c];
        const double ambient = b.Ambient[at + c];
        const double r = m - ambient;
        sum[c] += r;
        squares += r * r;
        // At least the variance of a mean of hits and misses as likely as A says.
        const double least =
          a <= 0.0 ? 0.0 : (c == 3 ? a * (1.0 - a) : ambient * ambient * (1.0 - a) / a) / n;
        const double v =
          std::max(std::max(b.MeanOfSquares[at + c] - m * m, 0.0) / (n - 1.0), least);
        variance += v;
        if (dx == 0 && dy == 0)
        {
          own += v;
        }
      }
      ++count;
    }
  }
  const double N = count;
  double smooth = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    bands.Residual[c] = sum[c] / N;
    smooth += bands.Residual[c] * bands.Residual[c];
  }
  const double v = variance / N; // a pixel's
  // The window's mean residual: its bias against its variance (v / N).
  const double smoothBias2 = std::max(smooth - 2.0 * v / N, 0.0);
  bands.Smooth = smoothBias2 + v / N > 0.0 ? smoothBias2 / (smoothBias2 + v / N) : 1.0;
  // The residual's detail (the pixel's minus the window's mean): the window's variance of the
  // residual, b^2 + v (1 - 1/N) in expectation, against the pixel's noise.
  const double detailBias2 = std::max(squares / N - smooth - 2.0 * v, 0.0);
  const double noise = std::max(v, own);
  bands.Detail = detailBias2 + noise > 0.0 ? detailBias2 / (detailBias2 + noise) : 1.0;
  return bands;
}

std::vector<float> RefinedPicture(const RefinementBuffers& b)
{
  std::vector<float> out(b.Ambient);
  for (int y = 0; y < b.Height; ++y)
  {
    for (int x = 0; x < b.Width; ++x)
    {
      const RefinementBands w = RefinementWeights(b, x, y);
      const std::size_t at = 4 * (static_cast<std::size_t>(y) * b.Width + x);
      for (int c = 0; c < 4; ++c)
      {
        const double r = b.Mean[at + c] - b.Ambient[at + c];
        out[at + c] = static_cast<float>(
          b.Ambient[at + c] + w.Smooth * w.Residual[c] + w.Detail * (r - w.Residual[c]));
      }
    }
  }
  return out;
}

} // namespace avs
