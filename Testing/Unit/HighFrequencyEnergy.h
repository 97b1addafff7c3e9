// The high-frequency energy of a picture over a region: the picture minus its Gaussian blur,
// squared and summed. The dense-surface tests measure bands with it (core and GPU).
#ifndef HighFrequencyEnergy_h
#define HighFrequencyEnergy_h

#include <algorithm>
#include <cmath>
#include <vector>

/// A width x height picture of one channel, row by row.
struct Picture
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Values;
};

/// Separable Gaussian blur with standard deviation `s` pixels, clamped at the borders.
inline Picture Blur(const Picture& in, double s)
{
  const int k = static_cast<int>(std::ceil(3.0 * s));
  std::vector<double> w(2 * k + 1);
  double sum = 0.0;
  for (int i = -k; i <= k; ++i)
  {
    sum += w[i + k] = std::exp(-0.5 * i * i / (s * s));
  }
  const int W = in.Width, H = in.Height;
  Picture tmp{ W, H, std::vector<double>(in.Values.size(), 0.0) };
  Picture out = tmp;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int i = -k; i <= k; ++i)
        tmp.Values[y * W + x] += w[i + k] / sum * in.Values[y * W + std::clamp(x + i, 0, W - 1)];
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int i = -k; i <= k; ++i)
        out.Values[y * W + x] += w[i + k] / sum * tmp.Values[std::clamp(y + i, 0, H - 1) * W + x];
  return out;
}

/// The region measured: pixels at least `fraction` of the brightest, whose neighbourhood within
/// `reach` pixels is all `covered` (so the blur reads no background).
inline std::vector<bool> LitRegion(const Picture& p,
  const std::vector<bool>& covered,
  int reach,
  double fraction = 0.1)
{
  const int W = p.Width, H = p.Height;
  const double brightest = *std::max_element(p.Values.begin(), p.Values.end());
  std::vector<bool> mask(p.Values.size(), false);
  for (int y = reach; y < H - reach; ++y)
    for (int x = reach; x < W - reach; ++x)
    {
      bool inside = true;
      for (int dy = -reach; dy <= reach && inside; ++dy)
        for (int dx = -reach; dx <= reach && inside; ++dx)
          inside = covered[(y + dy) * W + x + dx];
      mask[y * W + x] = inside && p.Values[y * W + x] > fraction * brightest;
    }
  return mask;
}

/// Sum over the mask of (p - blur(p))^2.
inline double HighFrequencyEnergy(const Picture& p, const std::vector<bool>& mask, double s)
{
  const Picture low = Blur(p, s);
  double sum = 0.0;
  for (std::size_t i = 0; i < p.Values.size(); ++i)
  {
    const double d = p.Values[i] - low.Values[i];
    sum += mask[i] ? d * d : 0.0;
  }
  return sum;
}

/// Sum over the mask of p^2.
inline double Energy(const Picture& p, const std::vector<bool>& mask)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < p.Values.size(); ++i)
  {
    sum += mask[i] ? p.Values[i] * p.Values[i] : 0.0;
  }
  return sum;
}

#endif
