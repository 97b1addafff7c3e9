// Transfer functions sampled into tables, as the GPU holds them: colour c(s) in [0, 1]^3 and
// scalar opacity alpha(s) over [Minimum, Maximum], linearly interpolated, clamped outside.
#ifndef avs_TransferFunction_h
#define avs_TransferFunction_h

#include "Vec3.h"

#include <array>
#include <vector>

namespace avs
{

struct TransferFunction
{
  double Minimum = 0.0;
  double Maximum = 1.0;
  std::vector<std::array<float, 3>> Color; ///< evenly spaced samples over [Minimum, Maximum]
  std::vector<float> Opacity;              ///< evenly spaced samples over [Minimum, Maximum]

  Vec3 ColorAt(double s) const;
  double OpacityAt(double s) const;

  /// A ramp from (0 at lo) to (alpha at hi) with a constant colour: handy for tests.
  static TransferFunction Ramp(double lo,
    double hi,
    double alpha,
    const Vec3& color,
    int samples = 256);
  /// Constant opacity and colour.
  static TransferFunction Constant(double alpha, const Vec3& color);
};

} // namespace avs

#endif
