// Where a straight segment leaves a ball: used to cut sampled curves and meshes exactly at a
// clipping sphere.
#pragma once

#include "cga/Vec3.h"

#include <algorithm>
#include <cmath>

namespace cga
{
/// The parameter s in [0, 1] where the segment inside -> outside (|inside - center| <= radius <
/// |outside - center|) crosses the sphere |x - center| = radius: the root of the quadratic
/// |u + s d|^2 = radius^2 (u = inside - center, d = outside - inside) with s >= 0, taken in the
/// form that does not cancel.
inline double segmentSphereExit(Vec3 inside, Vec3 outside, Vec3 center, double radius)
{
  const Vec3 u = inside - center;
  const Vec3 d = outside - inside;
  const double a = dot(d, d);
  const double b = dot(u, d);
  const double c = std::min(0.0, dot(u, u) - radius * radius); // <= 0 for an inside point
  if (!(a > 0.0))
  {
    return 0.0;
  }
  const double root = std::sqrt(std::max(0.0, b * b - a * c));
  const double s = b > 0.0 ? -c / (b + root) : (root - b) / a;
  return std::max(0.0, std::min(1.0, s));
}

/// The point where the segment inside -> outside crosses the sphere, put on it to round-off
/// (the crossing's small residual is removed along the radius).
inline Vec3 segmentSphereExitPoint(Vec3 inside, Vec3 outside, Vec3 center, double radius)
{
  const double s = segmentSphereExit(inside, outside, center, radius);
  const Vec3 p = inside + s * (outside - inside);
  const double distance = norm(p - center);
  return distance > 0.0 ? center + (radius / distance) * (p - center) : p;
}
} // namespace cga
