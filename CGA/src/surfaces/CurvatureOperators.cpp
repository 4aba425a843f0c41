#include "cga/surfaces/CurvatureOperators.h"

#include "cga/PointPairs.h"

#include "CurvatureOperatorTerms.h"

#include <cmath>

namespace cga
{
std::string PatchFrame::fromDirections(Vec3 origin, Vec3 uDirection, Vec3 vDirection, PatchFrame& out)
{
  if (!isFinite(origin) || !isFinite(uDirection) || !isFinite(vDirection))
  {
    return "the patch origin and directions must be finite";
  }
  const Vec3 u = normalized(uDirection);
  if (norm2(u) == 0.0)
  {
    return "the u direction must not be zero";
  }
  const Vec3 v = normalized(vDirection - dot(vDirection, u) * u);
  // A v direction within about 1e-9 rad of u leaves no usable plane.
  if (norm2(v) == 0.0 || norm(vDirection - dot(vDirection, u) * u) <= 1e-9 * norm(vDirection))
  {
    return "the v direction must not be zero or parallel to the u direction";
  }
  out.origin = origin;
  out.u = u;
  out.v = v;
  out.normal = cross(u, v);
  return {};
}

// The operators are written once, for double and for the curvature patch's jets, in
// CurvatureOperatorTerms.h.
CurvatureGenerator bentLine(const PatchFrame& frame, double kappa, double b)
{
  return detail::bentLineOf(frame, kappa, b);
}

CurvatureGenerator translatedTangents(const PatchFrame& frame, double kappaU, double kappaV, double a, double b)
{
  return detail::translatedTangentsOf(frame, kappaU, kappaV, a, b);
}

std::string CurvatureControlPoint::normalize()
{
  if (!isFinite(location) || !isFinite(normal) || !isFinite(uDirection) ||
    !std::isfinite(kappaU) || !std::isfinite(kappaV))
  {
    return "a control point has a non-finite location, normal, u direction or curvature";
  }
  const Vec3 n = normalized(normal);
  if (norm2(n) == 0.0)
  {
    return "a control point has a zero normal";
  }
  const Vec3 inPlane = uDirection - dot(uDirection, n) * n;
  if (norm(inPlane) <= 1e-9 * norm(uDirection)) // also a zero inPlane or uDirection
  {
    return "a control point's u direction is zero or parallel to its normal";
  }
  normal = n;
  uDirection = normalized(inPlane);
  return {};
}

double squaredCircleDistance(Vec3 p, Vec3 center, double radius, Vec3 planeNormal)
{
  const Vec3 d = p - center;
  const double sphere = 0.5 * (norm2(d) - radius * radius); // -up(p).sigma
  const double plane = dot(d, planeNormal);                   // up(p).pi
  return sphere * sphere + radius * radius * plane * plane;
}

double osculatingTerm(const CurvatureControlPoint& c, Vec3 along, double kappa, Vec3 p, double epsilon)
{
  // squaredCircleDistance(p, x - n/kappa, 1/|kappa|, along x n) written in q = p - x.
  const detail::PointOf<double> q = detail::difference(detail::pointOf<double>(p), c.location);
  return detail::osculatingWeight(q, detail::squaredLength(q), detail::dotProduct(q, c.normal),
    cross(along, c.normal), kappa, epsilon);
}

CurvatureGenerator osculatingCircles(const CurvatureControlPoint& c, Vec3 p, double epsilon)
{
  return detail::osculatingCirclesOf(c, detail::pointOf<double>(p), epsilon);
}

CurvatureGenerator controlPoints(const CurvatureControlPoint* points,
                                 std::size_t count,
                                 Vec3 p,
                                 double falloff,
                                 double epsilon,
                                 Vec3 shift)
{
  return ControlPointSum(points, count, falloff, epsilon, shift).at(p);
}

ControlPointSum::ControlPointSum(const CurvatureControlPoint* points, std::size_t count,
  double falloff, double epsilon, Vec3 shift)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    Prepared prepared;
    prepared.point = points[i];
    prepared.point.location = points[i].location - shift;
    const CurvatureControlPoint& c = prepared.point;
    // osculatingCircles' pieces: tau(x, n) and, for osculatingTerm, cross(along, n).
    prepared.pair = nullPointPairCompact(c.location, c.normal);
    prepared.planeNormalU = cross(c.uDirection, c.normal);
    prepared.planeNormalV = cross(cross(c.normal, c.uDirection), c.normal);
    this->Points.push_back(prepared);
  }
}

CurvatureGenerator ControlPointSum::at(Vec3 p) const
{
  return detail::controlPointSumOf(*this, detail::pointOf<double>(p));
}

CurvatureGenerator linearInterpolation(Vec3 x1, const CornerGenerator& g1, Vec3 x2, const CornerGenerator& g2, double t)
{
  return detail::linearInterpolationOf(
    detail::pointOf<double>(x1), g1, detail::pointOf<double>(x2), g2, t);
}

CurvatureGenerator bilinearInterpolation(const Vec3 x[4], const CornerGenerator g[4], double s, double t)
{
  return detail::bilinearInterpolationOf(detail::BilinearCorners(x, g), s, t);
}
} // namespace cga
