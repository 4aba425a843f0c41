// A Euclidean 3-vector: the only Euclidean type the kernel's users see.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace cga
{
struct Vec3
{
  double x = 0.0, y = 0.0, z = 0.0;

  constexpr Vec3() = default;
  constexpr Vec3(double ax, double ay, double az)
    : x(ax)
    , y(ay)
    , z(az)
  {
  }

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return { a.x + b.x, a.y + b.y, a.z + b.z }; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return { a.x - b.x, a.y - b.y, a.z - b.z }; }
  friend constexpr Vec3 operator-(Vec3 a) { return { -a.x, -a.y, -a.z }; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return { s * a.x, s * a.y, s * a.z }; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return s * a; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return { a.x / s, a.y / s, a.z / s }; }
};

/// The Vec3 of a C array of three numbers (what VTK's setters and points hold).
constexpr Vec3 toVec3(const double v[3])
{
  return { v[0], v[1], v[2] };
}

constexpr double dot(Vec3 a, Vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

constexpr Vec3 cross(Vec3 a, Vec3 b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}

/// True when a.a neither overflowed nor lost precision to underflow, so sqrt(a.a) is |a| to within
/// rounding. Below 1e-290 a square may be subnormal; above DBL_MAX (about 1.3e154 per component)
/// it is inf. Lengths in this range keep the plain formula (and its bits); outside it they are
/// scaled.
inline bool squareIsSafe(double square)
{
  return square >= 1e-290 && square <= std::numeric_limits<double>::max();
}

/// |a| without spurious overflow or underflow: 1e200 and 1e-200 long vectors have their length.
inline double norm(Vec3 a)
{
  const double square = dot(a, a);
  return squareIsSafe(square) ? std::sqrt(square) : std::hypot(a.x, a.y, a.z);
}

constexpr double norm2(Vec3 a)
{
  return dot(a, a);
}

inline bool isFinite(Vec3 a)
{
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// a / |a| for every finite non-zero a (also when |a| overflows or underflows), or the zero vector
/// when a is zero or not finite.
inline Vec3 normalized(Vec3 a)
{
  const double square = dot(a, a);
  if (squareIsSafe(square))
  {
    return a / std::sqrt(square);
  }
  const double largest = std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(a.z) });
  if (!isFinite(a) || !(largest > 0.0))
  {
    return Vec3{};
  }
  const Vec3 scaled = a / largest; // largest component +-1: its square is safe
  return scaled / std::sqrt(dot(scaled, scaled));
}

/// A unit vector orthogonal to the unit vector n. For n not parallel to x it lies in the plane of
/// n and x (so for n = z it is x, as the paper's figures use); otherwise it is y's projection.
inline Vec3 orthogonalUnit(Vec3 n)
{
  const Vec3 reference = std::fabs(n.x) < 0.9 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 };
  return normalized(reference - dot(reference, n) * n);
}
} // namespace cga
