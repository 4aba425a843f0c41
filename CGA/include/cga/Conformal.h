// Constructors and readers of the conformal model (docs/conventions.md section 1).
//
// Conventions: no = (e- + e+)/2, ni = e- - e+ (no.ni = -1); up(x) = no + x + |x|^2/2 ni;
// fn(P) = P / (-ni.P); T(d) = 1 - d ni / 2 translates by +d; R = exp(-theta B / 2).
#pragma once

#include "cga/Multivector.h"
#include "cga/Vec3.h"

namespace cga
{
// ---- basis elements ----
Multivector e1();
Multivector e2();
Multivector e3();
Multivector no();
Multivector ni();
/// Euclidean pseudoscalar e1 e2 e3.
Multivector euclideanPseudoscalar();
/// Minkowski plane E = no ^ ni.
Multivector minkowskiPlane();

// ---- Euclidean vectors ----
Multivector vector(Vec3 v);
/// The e1, e2, e3 coefficients of a multivector.
Vec3 euclideanPart(const Multivector& m);

// ---- points ----
/// up(x) = no + x + |x|^2/2 ni.
Multivector up(Vec3 x);
/// Normalization (eq 19-20) of the grade-1 part: P / (-ni.P). Returns false when -ni.P is zero or
/// not finite (the point went to infinity); then `out` is left unchanged.
bool normalizePoint(const Multivector& p, Vec3& out);
/// The Euclidean point of fn(P); non-finite when P is at infinity.
Vec3 down(const Multivector& p);

// ---- versors ----
/// T(d) = 1 - d ni / 2.
Multivector translator(Vec3 d);
/// R = exp(-theta B / 2) with B the unit bivector dual to the unit axis (right-hand rule).
Multivector rotor(Vec3 axis, double angle);
/// K x ~K.
Multivector sandwich(const Multivector& k, const Multivector& x);
/// ~K / (K ~K); requires K ~K to be a non-zero scalar.
Multivector versorInverse(const Multivector& k);
/// fn(K up(x) ~K), reference path through the full product.
Vec3 transformPoint(const Multivector& k, Vec3 x);

// ---- point pairs and tangents ----
/// Tangent at the origin t = no ^ v (eq 1).
Multivector tangent(Vec3 v);
/// Null point pair tau(x, v) = up(x) ^ (v + (v.x) ni) = T(x) (no ^ v) ~T(x) (eq 7).
Multivector nullPointPair(Vec3 location, Vec3 direction);
/// Point pair up(a) ^ up(b).
Multivector pointPair(Vec3 a, Vec3 b);

// ---- rounds and flats ----
/// Circle up(a) ^ up(b) ^ up(c), oriented a -> b -> c.
Multivector circleThroughPoints(Vec3 a, Vec3 b, Vec3 c);
/// Circle with the given center, unit normal and radius, counter-clockwise about the normal.
Multivector circle(Vec3 center, Vec3 normal, double radius);
/// Line up(a) ^ up(b) ^ ni through a and b.
Multivector line(Vec3 a, Vec3 b);
/// Dual line B + d ni of the line through a point with a direction (the undual of line()).
Multivector dualLine(Vec3 point, Vec3 direction);

/// What a mesher needs to know about a (possibly flattened) circle blade.
struct RoundInfo
{
  bool isLine = false;
  Vec3 center;    // circle center, or the point of the line closest to the origin
  Vec3 normal;    // unit normal of the carrier plane (undefined for a line)
  Vec3 direction; // unit direction of the line (undefined for a circle)
  double radius = 0.0; // circle radius (infinite for a line)
};

/// Reads a grade-3 circle or line blade. `flatTolerance` is the relative size of ni ^ X below
/// which the blade counts as a line.
RoundInfo readCircle(const Multivector& x, double flatTolerance = 1e-12);
} // namespace cga
