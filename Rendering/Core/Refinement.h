// The picture of the path-traced refinement (ARCHITECTURE.md, "Refinement at rest"). While the
// view rests, an unbiased path tracer adds samples of the radiance of every pixel; what is shown
// is the ambient-scattering picture A corrected by the residual r = M - A of the path tracer's
// running mean M, in two bands over a window of (2 R + 1)^2 = N pixels:
//
//   A + w_s r_s + w_d (r - r_s),   r_s the window's mean residual,
//
// each band weighed by w = b^2 / (b^2 + its noise), the weight that minimises the expected
// squared error, with its squared bias b^2 estimated from the window and taken one noise lower
// (max(E - 2 noise, 0), E the band's energy, whose expectation is b^2 + noise):
//  - the smooth band: E = |r_s|^2 against the noise v / N of a mean of N pixels (v a pixel's
//    variance of M, summed over the four channels, averaged over the window). The bias of A
//    varies slowly across the picture, so this band takes the correction first, with 1/N of
//    the noise: a few samples already lift a picture that is too dark as a whole;
//  - the detail band: E = the window's mean of |r|^2 - |r_s|^2, against the larger of v and
//    the pixel's own variance (a pixel that met a rare bright path keeps its detail from A until
//    its mean is sure). It follows M where A's errors have structure finer than the window.
// Guards, because the estimates are themselves noisy: the bias one noise lower (where A is right,
// E - noise scatters around 0 and would let noise in half of the time); a channel's variance at
// least that of a mean of n hits and misses as likely as A says (alpha a: a (1 - a) / n;
// radiance A_c: A_c^2 (1 - a) / (a n)), since samples that have not met a rare event show no
// variance; and A below 16 samples (path-traced radiance is skewed: a few samples that have not
// met the rare bright paths look certain and dark). Measured on the accuracy study's scenes
// (avs-bench-refinement): never worse than A at any number of samples; the smooth band halves
// A's error within 16 to 32 samples where one weight for both bands needed 200 to 800.
// As n grows, the noise falls as 1/n and both weights go to 1 wherever A is biased: the picture
// converges to M. The GPU computes the same in avs_refine_fs.glsl; this is its reference.
#ifndef avs_Refinement_h
#define avs_Refinement_h

#include <vector>

namespace avs
{

/// Half width R of the window.
constexpr int RefinementWindowRadius = 2;
/// Samples per pixel below which the ambient-scattering picture is shown as it is.
constexpr int RefinementMinimumSamples = 16;

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

/// The weights at pixel (x, y) of the two bands of the residual M - A: its mean over the window
/// (Residual) and the pixel's difference from that mean.
struct RefinementBands
{
  double Smooth = 0.0;
  double Detail = 0.0;
  double Residual[4] = { 0, 0, 0, 0 };
};
RefinementBands RefinementWeights(const RefinementBuffers& buffers, int x, int y);

/// The picture shown: A + w (M - A) per pixel (A below RefinementMinimumSamples samples).
std::vector<float> RefinedPicture(const RefinementBuffers& buffers);

} // namespace avs

#endif
