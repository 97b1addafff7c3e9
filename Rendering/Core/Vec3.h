// Small 3-vector maths for the VTK-free core.
#ifndef avs_Vec3_h
#define avs_Vec3_h

#include <cmath>

namespace avs
{

struct Vec3
{
  double x = 0.0, y = 0.0, z = 0.0;

  constexpr Vec3() = default;
  constexpr Vec3(double a, double b, double c)
    : x(a)
    , y(b)
    , z(c)
  {
  }
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return { a.x + b.x, a.y + b.y, a.z + b.z };
}
constexpr Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
constexpr Vec3 operator-(const Vec3& a)
{
  return { -a.x, -a.y, -a.z };
}
constexpr Vec3 operator*(const Vec3& a, double s)
{
  return { a.x * s, a.y * s, a.z * s };
}
constexpr Vec3 operator*(double s, const Vec3& a)
{
  return a * s;
}
/// Component-wise product (colours).
constexpr Vec3 Mul(const Vec3& a, const Vec3& b)
{
  return { a.x * b.x, a.y * b.y, a.z * b.z };
}
constexpr double Dot(const Vec3& a, const Vec3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double Length(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}
inline Vec3 Normalize(const Vec3& a)
{
  const double l = Length(a);
  return l > 0.0 ? a * (1.0 / l) : Vec3{ 0.0, 0.0, 0.0 };
}

/// An orthonormal basis (s, t, n) around the unit vector n.
inline void OrthonormalBasis(const Vec3& n, Vec3& s, Vec3& t)
{
  // Duff et al. 2017, "Building an orthonormal basis, revisited".
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  s = { 1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x };
  t = { b, sign + n.y * n.y * a, -n.y };
}

/// Direction with polar cosine `cosTheta` and azimuth `phi` around the unit vector n.
inline Vec3 SphericalDirection(const Vec3& n, double cosTheta, double phi)
{
  Vec3 s, t;
  OrthonormalBasis(n, s, t);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return s * (sinTheta * std::cos(phi)) + t * (sinTheta * std::sin(phi)) + n * cosTheta;
}

constexpr double Pi = 3.14159265358979323846;

} // namespace avs

#endif
