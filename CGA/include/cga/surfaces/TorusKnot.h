// Torus knots as orbits (docs/conventions.md section 3 item 13; the paper's end of section 4 after
// Dorst and Valkenburg): two round circles A and C, orthogonal and linked once (a Hopf link, as
// two antipodal fibers of the classical Hopf fibration), have commuting unit duals A*, C*
// (squares -1): exp(t A*) turns space about A, exp(t C*) about C. The orbit of a point under
// exp(t B), B = (pi/P) A* + (pi/Q) C*, winds about both and is a (P, Q) torus knot.
//
// Placement: the two circles have the same radius r; A lies in the plane through
// center - (r/sqrt 2) u with normal n, C in the plane through center + (r/sqrt 2) u spanned by u
// and n (normal n x u), where n = normal/|normal| and u = direction made orthogonal to n. Then C
// passes through A's disc at center - (1 - 1/sqrt 2) r u. The orbits of exp(t B) lie on the
// invariant tori about A and C (Dupin cyclides); `center`, the midpoint of the two circles'
// centers, lies on the middle one, which passes through infinity (the two circles are congruent
// because the stereographic projection's pole is as far from one as from the other): orbits of
// seeds there run through infinity. Seeds between the middle torus and A (e.g.
// center + 0.15 r u) lie on compact tori about A, between it and C on compact tori about C.
//
// Period and windings: the rotor exp(t pi/P A*) is -1 (the identity on points) at t = P, and
// exp(t pi/Q C*) at t = Q, so exp(t B) has the period lcm(P, Q) on points (P Q when coprime). Over
// one period a point turns lcm/P times about A and lcm/Q times about C: the knot's linking number
// with A is Q and with C is P (coprime P, Q; tested with the Gauss linking integral), i.e. the
// classical T(P, Q) on a torus whose core circle is A and whose axis is C.
#pragma once

#include "cga/Compact.h"
#include "cga/Orbit.h"
#include "cga/Vec3.h"

#include <string>

namespace cga
{
struct TorusKnot
{
  Vec3 center{ 0, 0, 0 };
  Vec3 normal{ 0, 0, 1 };    // of A's plane; any finite non-zero length
  Vec3 direction{ 1, 0, 0 }; // from A's center to C's; not parallel to normal
  double radius = 1.0;
  int p = 2;
  int q = 3;
  /// The largest P or Q.
  static constexpr int kMaximumWinding = 1000;

  struct Circle
  {
    Vec3 center, normal;
    double radius = 0.0;
  };

  /// Empty when the parameters are valid, otherwise what is wrong with them.
  std::string validate() const;
  /// The greatest common divisor of P and Q (1: a knot traced once over lcm(P, Q)).
  int commonDivisor() const;

  /// The two core circles, oriented counter-clockwise about their normals.
  Circle coreA() const;
  Circle coreC() const;
  /// The unit dual of a circle, the generator of the rotation about it: U^2 = -1, and exp(t U)
  /// moves a point near the circle counter-clockwise about the circle's oriented tangent.
  static Bivector rotationAbout(const Circle& circle);

  /// The orbit of B = (pi/P) A* + (pi/Q) C*, built from its two parts (no decomposition).
  Orbit orbit() const;
};

/// Points of a circle: center + radius (cos a e + sin a (n x e)), a = 2 pi i / count, e the
/// orthogonalUnit of n.
void circlePoints(const TorusKnot::Circle& circle, int count, Vec3* points);
} // namespace cga
