// The paper's curvature operators (docs/conventions.md section 3 items 5-8, 10, 11; eq 15-18, 21-22, 24-26):
// generators built from null point pairs that bend a plane patch to stated curvatures.
//
// Every operator returns the exponent E of its boost, K = exp(E), at one patch point, together
// with the local generator weight w (E = -sum_i w_i tau_i with tau_i of unit direction). The patch
// is p(a, b) = origin + a u + b v with orthonormal u, v and normal n = u x v.
//
// Sign convention (docs/conventions.md item 5): a positive curvature kappa puts the center of curvature on the
// -n side (center p - n/kappa); the same kappa is the true curvature of the bent line (0.5 gives
// radius 2).
#pragma once

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include <string>
#include <vector>

namespace cga
{
/// An orthonormal patch frame.
struct PatchFrame
{
  Vec3 origin{ 0, 0, 0 };
  Vec3 u{ 1, 0, 0 };
  Vec3 v{ 0, 1, 0 };
  Vec3 normal{ 0, 0, 1 };

  /// u = |uDirection|^-1 uDirection, v = the unit part of vDirection orthogonal to u, n = u x v.
  /// Empty on success, otherwise what is wrong (zero, parallel or non-finite input).
  static std::string fromDirections(Vec3 origin, Vec3 uDirection, Vec3 vDirection, PatchFrame& out);

  Vec3 at(double a, double b) const { return origin + a * u + b * v; }
};

/// The exponent of a boost and the local generator weight it carries.
struct CurvatureGenerator
{
  Bivector exponent; // K = exp(exponent)
  double weight = 0.0;
};

/// Eq 15: the u line of the patch at height b bent with curvature kappa at its point p = at(0, b):
/// K = 1 - kappa/2 tau(p, n). The line becomes the circle of radius 1/|kappa| tangent at p with
/// center p - n/kappa. Each row of a strip is bent at its own point (the strip stays a cylinder).
CurvatureGenerator bentLine(const PatchFrame& frame, double kappa, double b);

/// Eq 16: K = exp(-1/2 (kappaU tau(o + b v, n) + kappaV tau(o + a u, n))). The tangent translated
/// along v bends the u lines, so the principal curvatures at the origin are kappaU along u and
/// kappaV along v (docs/conventions.md writes the same sum with the tangents named by where they are moved).
CurvatureGenerator translatedTangents(const PatchFrame& frame, double kappaU, double kappaV, double a, double b);

/// A control point of eq 17 and 21: location, unit normal, unit u direction (orthogonal to the
/// normal) and the curvatures along u and along v = normal x u.
struct CurvatureControlPoint
{
  Vec3 location{ 0, 0, 0 };
  Vec3 normal{ 0, 0, 1 };
  Vec3 uDirection{ 1, 0, 0 };
  double kappaU = 0.0;
  double kappaV = 0.0;

  /// Normalizes normal and uDirection (u made orthogonal to the normal). Empty on success,
  /// otherwise what is wrong (zero or non-finite vectors, u parallel to the normal, NaN kappa).
  std::string normalize();
};

/// Eq 18: d^2 = (up(p) _| C*)^2 for the circle of center c, radius r and unit plane normal m, with
/// C* = sigma ^ pi (sigma the dual sphere of (c, r) with -ni.sigma = 1, pi the unit dual plane
/// through c). Closed form: ((|p - c|^2 - r^2)/2)^2 + r^2 ((p - c).m)^2; zero on the circle.
double squaredCircleDistance(Vec3 p, Vec3 center, double radius, Vec3 planeNormal);

/// kappa / (d^2 + epsilon) for the osculating circle of eq 17 in the direction `along` (unit, in
/// the control point's plane): the image of that line under eq 15, center x - n/kappa, radius
/// 1/|kappa|, in the plane of `along` and n. Zero when kappa is zero (a flat direction).
double osculatingTerm(const CurvatureControlPoint& c, Vec3 along, double kappa, Vec3 p, double epsilon);

/// Eq 17-18: K = exp(-W tau(x, n)), W = kappaU/(d_u^2 + eps) + kappaV/(d_v^2 + eps).
CurvatureGenerator osculatingCircles(const CurvatureControlPoint& c, Vec3 p, double epsilon);

/// Eq 21-22: K = exp(-sum_i W_i tau(x_i, n_i)), W_i = (kappaU_i/(d_ui^2 + eps) +
/// kappaV_i/(d_vi^2 + eps)) / (k |p - x_i|^2 + eps), k the falloff. With `shift`, of the
/// control points moved by -shift (p is then given moved too).
CurvatureGenerator controlPoints(const CurvatureControlPoint* points,
                                 std::size_t count,
                                 Vec3 p,
                                 double falloff,
                                 double epsilon,
                                 Vec3 shift = Vec3{});

/// Eq 21-22 at many points: controlPoints() with the pieces that do not depend on p (each
/// control point moved by -shift, its null point pair and the normals of its two osculating
/// circles' planes) made once. at(p) is controlPoints(points, count, p, falloff, epsilon, shift),
/// bit for bit.
class ControlPointSum
{
public:
  ControlPointSum(const CurvatureControlPoint* points, std::size_t count, double falloff,
    double epsilon, Vec3 shift = Vec3{});
  CurvatureGenerator at(Vec3 p) const;

  /// A control point with the pieces of its term that do not depend on p.
  struct Prepared
  {
    CurvatureControlPoint point; // moved by -shift
    Bivector pair;               // tau(location, normal)
    Vec3 planeNormalU, planeNormalV; // along x normal, for along = u and v = normal x u
  };
  /// What at() sums over (and the curvature patch's jets, src/surfaces/CurvatureOperatorTerms.h).
  const std::vector<Prepared>& prepared() const { return this->Points; }
  double falloff() const { return this->Falloff; }
  double epsilon() const { return this->Epsilon; }

private:
  std::vector<Prepared> Points;
  double Falloff, Epsilon;
};

/// A corner generator of eq 24-26: weight * tau(location, direction).
struct CornerGenerator
{
  Vec3 direction{ 0, 0, 1 };
  double weight = 1.0;
};

/// Eq 24: tau_t = (1 - t) tau_1 + t tau_2, K = exp(-tau_t / 2), with tau_i = w_i tau(x_i, d_i).
CurvatureGenerator linearInterpolation(Vec3 x1, const CornerGenerator& g1, Vec3 x2, const CornerGenerator& g2, double t);

/// Eq 25-26: tau_st = (1-s)((1-t) tau_1 + t tau_2) + s((1-t) tau_3 + t tau_4), K = exp(-tau_st/2).
/// corners[i] sit at x[i]; t runs from corner 1 to 2 (and 3 to 4), s from 1 to 3 (and 2 to 4).
CurvatureGenerator bilinearInterpolation(const Vec3 x[4], const CornerGenerator g[4], double s, double t);
} // namespace cga
