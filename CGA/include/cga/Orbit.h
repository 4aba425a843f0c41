// The orbit of points under the one-parameter group exp(t B) of a bivector B
// (docs/conventions.md section 3 item 13).
//
// B splits into commuting 2-blades B = B1 + B2 with scalar squares l1 >= l2 (the invariant
// decomposition, Exponential.h), so exp(t B) = exp(t B1) exp(t B2) and each factor has the closed
// form of a blade: cos(t r) + sin(t r)/r Bi for li = -r^2 < 0 (a rotation about a circle or a
// line), cosh and sinh for li > 0 (a boost between two points), 1 + t Bi for li = 0 (a
// translation or a transversion). Every t is evaluated directly, never by steps from the previous
// one, through the product's expansion in B, W = B ^ B and <W B>_2 (expExact's closed form, which
// needs no explicit split and stays exact for equal squares). The squares and the rates
// r = sqrt|li| are computed in extended precision (long double) from B's own coefficients, and
// the angles t r are not rounded to double, so the angle at t = 1e4 is not off by 1e4 ulps.
// Where the squares are at least a quarter of the larger apart and of B's largest coefficient
// squared, eight times run side by side (versors): each angle t r as a sum of two doubles (about
// 106 bits), its sine and cosine (or cosh and sinh) by SLEEF's 1-ulp vector functions corrected
// to first order by the low part, and the coefficients in double: the point map within 7 units of
// 2^-53 of its largest entry against an eigendecomposition in long double (tested). Closer or
// smaller squares, hyperbolic angles beyond the scaling threshold and bad times take the
// extended form throughout (small angles there: the power series).
//
// Period: exp(t B) acts on points with period T when every non-zero part is elliptic and, for two
// of them, the rates are in a rational ratio r1/r2 = m/n (coprime, both at most kMaximumWindings,
// the two periods m pi/r1 and n pi/r2 equal to kPeriodTolerance): T = pi/r for one part,
// m pi/r1 = n pi/r2 for two. A rotor exp(t Bi) is -1 at t = pi/r, which is the identity on points.
#pragma once

#include "cga/Compact.h"
#include "cga/Conformal.h"
#include "cga/Vec3.h"

#include <cstddef>
#include <string>

namespace cga
{
/// The kind of one commuting part of a bivector, by its square.
enum class OrbitPartKind
{
  Zero,       ///< no part (a blade has one)
  Elliptic,   ///< square < 0: a rotation, periodic
  Parabolic,  ///< square 0, part not zero: a translation or a transversion
  Hyperbolic  ///< square > 0: a boost between two fixed points
};

struct OrbitPart
{
  Bivector blade;
  double square = 0.0;
  OrbitPartKind kind = OrbitPartKind::Zero;
  /// sqrt|square| in extended precision: the rate of the part (radians of the rotor per unit t).
  long double rate = 0.0L;
};

namespace detail
{
/// What Orbit::versors needs of B at every call (Orbit.cpp), made once: whether B takes the
/// lanes' closed form; per part its rate as a sum high + low of two doubles, whether its factors
/// are circular (cos, sin), hyperbolic (cosh, sinh) or those of a zero rate (1, t) and its
/// square; the squares' difference; and the largest coefficients of W, B and <W B>_2, which
/// bound a versor's largest component.
struct OrbitLanes
{
  bool form = false;
  double rateHigh[2] = { 0.0, 0.0 }, rateLow[2] = { 0.0, 0.0 };
  OrbitPartKind kind[2] = { OrbitPartKind::Zero, OrbitPartKind::Zero };
  double square[2] = { 0.0, 0.0 }, difference = 0.0;
  double largestW = 0.0, largestB = 0.0, largestWB = 0.0;
};
} // namespace detail

class Orbit
{
public:
  /// The largest numerator or denominator of a rational ratio of two rotation rates that counts
  /// as periodic.
  static constexpr int kMaximumWindings = 1000;
  /// The relative agreement of the two parts' periods m pi/r1 and n pi/r2.
  static constexpr double kPeriodTolerance = 1e-12;
  /// Coefficients beyond this size are refused (their squares would overflow).
  static constexpr double kMaximumCoefficient = 1e150;

  /// Decomposes B. Non-finite or too large B: problem() says so and every point map fails.
  explicit Orbit(const Bivector& b);
  /// From two parts known to commute and to be 2-blades (b = first + second), e.g. the torus
  /// knot's two rotations: no decomposition, exact even when the squares are equal.
  Orbit(const Bivector& first, const Bivector& second);

  /// Empty when B can be used; otherwise why not.
  const std::string& problem() const { return this->Problem; }
  const Bivector& bivector() const { return this->B; }
  /// B = part(0) + part(1); part(0).square >= part(1).square unless given explicitly.
  const OrbitPart& part(int i) const { return this->Parts[i]; }
  /// True when B is zero: exp(t B) is the identity.
  bool isIdentity() const { return this->Identity; }
  /// True when the parts' blades are known: given, a 2-blade, or decomposed; false when the two
  /// squares are equal (an isoclinic double rotation: the split is not unique), where only the
  /// squares are known. exp(t B) never needs the blades.
  bool hasParts() const { return this->KnownParts; }

  /// The period T of exp(t B) on points, 0 when there is none (see above).
  double period() const { return this->Period; }
  /// With a period: how many half-turns of each rotor's angle make T (T = windings(i) pi/r_i),
  /// i.e. how many times a generic orbit winds around the core of part i; 0 without a period or
  /// for a zero part.
  int windings(int i) const { return this->Windings[i]; }

  /// exp(t B), scaled like expExact's AvoidOverflow for a large hyperbolic angle and by a power
  /// of two where a component passes 2^64 (the point map does not change, and its 5 x 5 matrix
  /// stays finite); not finite only where t B itself overflows.
  Even versor(double t) const;
  /// versor(times[i]) into out[i] for count times, eight at a time: the same bits as versor for
  /// each time, whatever the count and the neighbours.
  void versors(const double* times, std::size_t count, Even* out) const;
  /// out = fn(exp(t B) up(p) exp(-t B)); false (out unchanged) at infinity or for bad input.
  bool point(Vec3 p, double t, Vec3& out) const;

  /// The core of part i: the circle (or line) that the rotation exp(t B_i) keeps fixed and turns
  /// space about, read from the undual of B_i. False for a part that is not a rotation, or whose
  /// blade is not known (equal squares without a given split). Oriented so that the rotation
  /// turns space right-handed about it: a circle counter-clockwise about `normal`, a line along
  /// `direction`.
  bool core(int i, RoundInfo& out) const;

private:
  void classify(const Bivector& b);
  void setPart(int i, const Bivector& blade, long double square, bool zero);
  void findPeriod();
  void prepareLanes();
  /// Whether versor(t) takes the lanes' closed form (see Orbit.cpp).
  bool inLanes(double t) const;
  /// exp(t B) with every angle, factor and coefficient in extended precision.
  Even extendedVersor(double t) const;

  Bivector B;
  OrbitPart Parts[2];
  bool Identity = false;
  bool KnownParts = false;
  long double Squares[2] = { 0.0L, 0.0L }; // the parts' squares, extended
  Quadvector W;                            // B ^ B
  Bivector WB;                             // <W B>_2
  double Period = 0.0;
  int Windings[2] = { 0, 0 };
  std::string Problem;
  detail::OrbitLanes Lanes;
};
} // namespace cga
