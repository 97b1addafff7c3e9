// The picture of the path-traced refinement (ARCHITECTURE.md, "Refinement at rest"). While the
// view rests, an unbiased path tracer adds samples of the radiance of every pixel; what is shown
// is the ambient-scattering picture A moved towards the path tracer's running mean M:
//
//   A + w (M - A),  w = b^2 / (b^2 + v),  b^2 = max(D - 2 v, 0),
//
// with v the variance of M (the sample variance over n - 1, summed over the four channels) and D
// the squared difference |M - A|^2, both averaged over a window of (2 R + 1)^2 pixels (the bias
// of A varies slowly across the picture; one pixel's estimate of it would be as noisy as M).
// E[D] = b^2 + v, so D - v estimates A's squared bias, and w = b^2 / (b^2 + v) is the weight
// that minimises the expected squared error of A + w (M - A). The estimate of the bias is taken
// one v lower (D - 2 v): D and v are themselves noisy (about 14 % of v over the window's 100
// values), and where A is right, D - v scatters around 0 and would let noise in half of the time;
// one v below, it does not, while a real bias still takes over as v falls as 1/n. With fewer
// than four samples v is unknown or too uncertain (a pixel's sample variance of two samples has
// one degree of freedom) and A is shown. As n grows, w goes to 1 wherever A is biased:
// the picture converges to the path tracer's. The GPU computes the same in avs_refine_fs.glsl;
// this is its reference.
#ifndef avs_Refinement_h
#define avs_Refinement_h

#include <vector>

namespace avs
{

/// Half width R of the window over which the bias and the variance are averaged.
constexpr int RefinementWindowRadius = 2;
/// Samples per pixel below which the ambient-scattering picture is shown as it is.
constexpr int RefinementMinimumSamples = 4;

/// The buffers of a refinement: width x height pixels of premultiplied RGBA (alpha: 1 -
/// transmittance for A, the share of camera rays that collided for the path tracer), bottom row
/// first.
struct RefinementBuffers
{
  int Width = 0;
  int Height = 0;
  int Samples = 0;                  ///< path-traced samples per pixel
  std::vector<float> Ambient;       ///< A
  std::vector<float> Mean;          ///< M, the mean of the samples
  std::vector<float> MeanOfSquares; ///< the mean of their squares
};

/// The weight w of the path tracer's mean at pixel (x, y).
double RefinementWeight(const RefinementBuffers& buffers, int x, int y);

/// The picture shown: A + w (M - A) per pixel (A where there are fewer than four samples).
std::vector<float> RefinedPicture(const RefinementBuffers& buffers);

} // namespace avs

#endif
