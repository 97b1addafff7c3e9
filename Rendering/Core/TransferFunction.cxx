#include "TransferFunction.h"

#include <algorithm>
#include <cmath>

namespace avs
{

namespace
{
// Continuous table coordinate of s, clamped; returns false for NaN.
inline bool Coordinate(double s, double lo, double hi, std::size_t n, std::size_t& i, double& f)
{
  if (!(s == s) || n == 0)
  {
    return false;
  }
  if (n == 1 || !(hi > lo))
  {
    i = 0;
    f = 0.0;
    return true;
  }
  const double c = std::clamp((s - lo) / (hi - lo), 0.0, 1.0) * (n - 1);
  i = std::min(static_cast<std::size_t>(c), n - 2);
  f = c - i;
  return true;
}
} // namespace

Vec3 TransferFunction::ColorAt(double s) const
{
  std::size_t i;
  double f;
  if (!Coordinate(s, this->Minimum, this->Maximum, this->Color.size(), i, f))
  {
    return { 0, 0, 0 };
  }
  const auto& a = this->Color[i];
  const auto& b = this->Color[std::min(i + 1, this->Color.size() - 1)];
  return { a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f };
}

double TransferFunction::OpacityAt(double s) const
{
  std::size_t i;
  double f;
  if (!Coordinate(s, this->Minimum, this->Maximum, this->Opacity.size(), i, f))
  {
    return 0.0;
  }
  const double a = this->Opacity[i];
  const double b = this->Opacity[std::min(i + 1, this->Opacity.size() - 1)];
  return a + (b - a) * f;
}

TransferFunction TransferFunction::Ramp(double lo,
  double hi,
  double alpha,
  const Vec3& color,
  int samples)
{
  TransferFunction tf;
  tf.Minimum = lo;
  tf.Maximum = hi;
  for (int i = 0; i < samples; ++i)
  {
    tf.Opacity.push_back(static_cast<float>(alpha * i / (samples - 1.0)));
    tf.Color.push_back(
      { static_cast<float>(color.x), static_cast<float>(color.y), static_cast<float>(color.z) });
  }
  return tf;
}

TransferFunction TransferFunction::Constant(double alpha, const Vec3& color)
{
  TransferFunction tf;
  tf.Opacity = { static_cast<float>(alpha), static_cast<float>(alpha) };
  const std::array<float, 3> c{
    static_cast<float>(color.x), static_cast<float>(color.y), static_cast<float>(color.z)
  };
  tf.Color = { c, c };
  return tf;
}

} // namespace avs
