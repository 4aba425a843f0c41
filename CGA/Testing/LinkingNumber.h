// Linking numbers of closed polygons for the tests (the Hopf fibers, the torus knots and their
// core circles), computed from the points alone: independent of the code that made them.
#pragma once

#include "cga/Vec3.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cgatest
{
/// The Gauss linking integral (1/4pi) sum over segment pairs of (a - b).(da x db) / |a - b|^3 at
/// segment midpoints, for the closed polygons a and b (the last point joins the first). It
/// converges to the linking number as the segments shrink (slowly where the curves come close).
inline double gaussLinkingIntegral(const std::vector<cga::Vec3>& a, const std::vector<cga::Vec3>& b)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const cga::Vec3 da = a[(i + 1) % a.size()] - a[i];
    const cga::Vec3 ma = a[i] + 0.5 * da;
    for (std::size_t j = 0; j < b.size(); ++j)
    {
      const cga::Vec3 db = b[(j + 1) % b.size()] - b[j];
      const cga::Vec3 r = ma - (b[j] + 0.5 * db);
      const double d = cga::norm(r);
      sum += cga::dot(r, cross(da, db)) / (d * d * d);
    }
  }
  return sum / (4.0 * 3.14159265358979323846);
}

/// The same double integral evaluated exactly for polygons: each pair of segments contributes the
/// solid angle of the quadrilateral it spans (Klenin and Langowski 2000), so the sum is an integer
/// up to rounding for any two disjoint closed polygons.
inline double polygonLinkingNumber(const std::vector<cga::Vec3>& a, const std::vector<cga::Vec3>& b)
{
  auto unitCross = [](cga::Vec3 x, cga::Vec3 y) { return cga::normalized(cga::cross(x, y)); };
  auto arcsin = [](double x) { return std::asin(std::clamp(x, -1.0, 1.0)); };
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const cga::Vec3 p1 = a[i], p2 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j)
    {
      const cga::Vec3 p3 = b[j], p4 = b[(j + 1) % b.size()];
      const cga::Vec3 r13 = p3 - p1, r14 = p4 - p1, r23 = p3 - p2, r24 = p4 - p2;
      const cga::Vec3 n1 = unitCross(r13, r14), n2 = unitCross(r14, r24);
      const cga::Vec3 n3 = unitCross(r24, r23), n4 = unitCross(r23, r13);
      const double omega = arcsin(cga::dot(n1, n2)) + arcsin(cga::dot(n2, n3)) +
        arcsin(cga::dot(n3, n4)) + arcsin(cga::dot(n4, n1));
      const double side = cga::dot(cga::cross(p4 - p3, p2 - p1), r13);
      sum += side > 0.0 ? omega : (side < 0.0 ? -omega : 0.0);
    }
  }
  return sum / (4.0 * 3.14159265358979323846);
}
} // namespace cgatest
