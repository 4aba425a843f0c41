// Where a straight segment leaves a ball: used to cut sampled curves and meshes exactly at a
// clipping sphere.
#pragma once

#include "cga/Vec3.h"

#include <algorithm>
#include <cmath>

namespace cga
{
/// The segment inside -> outside as a unit direction and a length, also when outside - inside
/// overflows (an outside point near +-DBL_MAX on the other side): its halves do not.
struct SegmentDirection
{
  Vec3 direction;
  double length = 0.0;
};

inline SegmentDirection segmentDirection(Vec3 inside, Vec3 outside)
{
  const Vec3 d = outside - inside;
  if (isFinite(d))
  {
    return { normalized(d), norm(d) };
  }
  const Vec3 half = 0.5 * outside - 0.5 * inside;
  return { normalized(half), 2.0 * norm(half) };
}

/// The distance along the unit `direction` from the inside point (u = inside - center) to where
/// it leaves the sphere: the root t >= 0 of |u + t direction|^2 = radius^2, taken in the form
/// that does not cancel.
inline double sphereExitDistance(Vec3 u, Vec3 direction, double radius)
{
  const double b = dot(u, direction);
  const double c = std::min(0.0, dot(u, u) - radius * radius); // <= 0 for an inside point
  const double root = std::sqrt(std::max(0.0, b * b - c));
  return b > 0.0 ? -c / (b + root) : root - b;
}

/// The parameter s in [0, 1] where the segment inside -> outside (|inside - center| <= radius <
/// |outside - center|) crosses the sphere |x - center| = radius. Solved along the unit direction,
/// so that a segment of any finite length (up to outside points near DBL_MAX) has its crossing.
inline double segmentSphereExit(Vec3 inside, Vec3 outside, Vec3 center, double radius)
{
  const SegmentDirection segment = segmentDirection(inside, outside);
  if (!(segment.length > 0.0))
  {
    return 0.0;
  }
  const double t = sphereExitDistance(inside - center, segment.direction, radius);
  return std::max(0.0, std::min(1.0, t / segment.length));
}

/// The point where the segment inside -> outside crosses the sphere, put on it to round-off
/// (the crossing's small residual is removed along the radius). Finite for every finite input:
/// also when the crossing rounds to within a subnormal distance of the center (a sphere far
/// from the origin, where the crossing's step is below the coordinates' spacing), where
/// radius / distance would overflow.
inline Vec3 segmentSphereExitPoint(Vec3 inside, Vec3 outside, Vec3 center, double radius)
{
  const SegmentDirection segment = segmentDirection(inside, outside);
  const double t = segment.length > 0.0
    ? std::min(segment.length, sphereExitDistance(inside - center, segment.direction, radius))
    : 0.0;
  const Vec3 p = inside + t * segment.direction;
  const Vec3 radial = normalized(p - center); // zero when p is the center
  return dot(radial, radial) > 0.0 ? center + radius * radial : p;
}
} // namespace cga
