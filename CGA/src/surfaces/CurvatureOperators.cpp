#include "cga/surfaces/CurvatureOperators.h"

#include "cga/PointPairs.h"

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

CurvatureGenerator bentLine(const PatchFrame& frame, double kappa, double b)
{
  CurvatureGenerator g;
  g.weight = 0.5 * kappa;
  g.exponent = nullPointPairCompact(frame.at(0.0, b), frame.normal) * (-g.weight);
  return g;
}

CurvatureGenerator translatedTangents(const PatchFrame& frame, double kappaU, double kappaV, double a, double b)
{
  const Vec3 locations[2] = { frame.at(0.0, b), frame.at(a, 0.0) };
  const Vec3 directions[2] = { frame.normal, frame.normal };
  const double weights[2] = { -0.5 * kappaU, -0.5 * kappaV };
  CurvatureGenerator g;
  g.exponent = weightedNullPointPairSum(locations, directions, weights, 2);
  g.weight = 0.5 * (kappaU + kappaV);
  return g;
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
  if (kappa == 0.0)
  {
    return 0.0; // the line stays a line: no bending in this direction
  }
  // squaredCircleDistance(p, x - n/kappa, 1/|kappa|, along x n) written in q = p - x, where the
  // r^2 of |p - center|^2 - r^2 cancels exactly: for |kappa| below ~1e-154 r^2 overflows and the
  // direct form gives inf - inf = NaN instead of a weight near 0.
  const Vec3 q = p - c.location;
  const double sphere = 0.5 * norm2(q) + dot(q, c.normal) / kappa;
  const double plane = dot(q, cross(along, c.normal)) / kappa;
  return kappa / (sphere * sphere + plane * plane + epsilon);
}

CurvatureGenerator osculatingCircles(const CurvatureControlPoint& c, Vec3 p, double epsilon)
{
  const Vec3 v = cross(c.normal, c.uDirection);
  CurvatureGenerator g;
  g.weight = osculatingTerm(c, c.uDirection, c.kappaU, p, epsilon) +
    osculatingTerm(c, v, c.kappaV, p, epsilon);
  if (g.weight != 0.0) // else zero: tau of a far-away location may not be finite (0 * inf)
  {
    g.exponent = nullPointPairCompact(c.location, c.normal) * (-g.weight);
  }
  return g;
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
  // PointPairField does not fit here: its generator weights are fixed, while W_i depends on p
  // through the osculating circle distances as well as through |p - x_i|. The terms are
  // osculatingCircles' and osculatingTerm's, in their order of operations; |q|^2 and q.n, which
  // they and eq 22's distance each compute, are computed once.
  CurvatureGenerator g;
  for (const Prepared& prepared : this->Points)
  {
    const CurvatureControlPoint& c = prepared.point;
    const Vec3 q = p - c.location;
    const double q2 = norm2(q), qn = dot(q, c.normal);
    auto term = [&](Vec3 planeNormal, double kappa) {
      if (kappa == 0.0)
      {
        return 0.0;
      }
      const double sphere = 0.5 * q2 + qn / kappa;
      const double plane = dot(q, planeNormal) / kappa;
      return kappa / (sphere * sphere + plane * plane + this->Epsilon);
    };
    const double weight = term(prepared.planeNormalU, c.kappaU) + term(prepared.planeNormalV, c.kappaV);
    Bivector exponent;
    if (weight != 0.0) // else zero: tau of a far-away location may not be finite (0 * inf)
    {
      exponent = prepared.pair * (-weight);
    }
    // eq 22: d_p^2 = -2 up(p).up(x) = |p - x|^2
    const double scale = 1.0 / (this->Falloff * q2 + this->Epsilon);
    g.exponent += exponent * scale;
    g.weight += weight * scale;
  }
  return g;
}

CurvatureGenerator linearInterpolation(Vec3 x1, const CornerGenerator& g1, Vec3 x2, const CornerGenerator& g2, double t)
{
  const Vec3 locations[2] = { x1, x2 };
  const Vec3 directions[2] = { g1.direction, g2.direction };
  const double weights[2] = { -0.5 * (1.0 - t) * g1.weight, -0.5 * t * g2.weight };
  CurvatureGenerator g;
  g.exponent = weightedNullPointPairSum(locations, directions, weights, 2);
  g.weight = 0.5 * ((1.0 - t) * g1.weight * norm(g1.direction) + t * g2.weight * norm(g2.direction));
  return g;
}

CurvatureGenerator bilinearInterpolation(const Vec3 x[4], const CornerGenerator g[4], double s, double t)
{
  const double factors[4] = { (1.0 - s) * (1.0 - t), (1.0 - s) * t, s * (1.0 - t), s * t };
  Vec3 directions[4];
  double weights[4];
  CurvatureGenerator result;
  for (int i = 0; i < 4; ++i)
  {
    directions[i] = g[i].direction;
    weights[i] = -0.5 * factors[i] * g[i].weight;
    result.weight += 0.5 * factors[i] * g[i].weight * norm(g[i].direction);
  }
  result.exponent = weightedNullPointPairSum(x, directions, weights, 4);
  return result;
}
} // namespace cga
