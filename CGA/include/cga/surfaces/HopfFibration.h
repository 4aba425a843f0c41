// The Hopf fibration of docs/conventions.md section 4 (paper eq 11-14, Fig 4-5): every point (theta, phi) of the
// base 2-sphere (theta the longitude, phi the latitude in [-pi/2, pi/2]) gets a fiber, the image of
// a base circle C under a versor KH(theta, phi).
//
// Everything is computed for the canonical circle C (unit circle in the xy plane, centred at the
// origin, counter-clockwise about +z) and then carried to the user's circle by the similarity
// x -> center + radius * (x.x a + x.y b + x.z n), with n the unit normal, a = orthogonalUnit(n)
// and b = n x a (theta = 0 points along a). A similarity is conformal, so circles stay circles and
// linking is preserved.
//
// Two modes:
//  * Paper (eq 11-14): k = 1/2 + phi/pi, v = (cos theta, sin theta, 0), the boost K = 1 + k no v
//    takes C at k = 1 to the line L_theta through v/2 with direction (-sin theta, cos theta, 0).
//    The twist M = exp(k/2 log(L L_theta^-1)) with L the z axis (both unit dual lines, L^2 = -1):
//    exp(1/2 log(L L_theta^-1)) carries L_theta onto L by sandwiching (the ratio is the square of
//    that motor; see Logarithm.h). KH = M K. Its fibers form a topological Hopf fibration (circles,
//    pairwise disjoint and linked once) but not the round one.
//  * Classical: the stereographic image of the Hopf fibration of S^3,
//    KH = R_z(theta + pi/2) exp(-(eta/2)(e1^e3 - e2^e+)), eta = (phi + pi/2)/2,
//    R_z(a) = exp(-(a/2) e1^e2). With up(x) = no + x + x^2/2 ni, the vector part on e1, e2, e3, e+
//    of a point normalized to e- coefficient 1 is s = (2x, 1 - |x|^2)/(1 + |x|^2) on the unit
//    3-sphere; the fibers are the images of the great circles e^{it}(z1, z2) with
//    z1 = s1 + i s2, z2 = s3 - i s+, and the fiber over (theta, phi) has the Hopf image
//    (2 z1 conj(z2), |z1|^2 - |z2|^2) = (cos phi cos(theta + pi/2), cos phi sin(theta + pi/2),
//    -sin phi) (tested). Antipodal classical fibers commute as blades; antipodal Paper fibers are
//    orthogonal but do not commute.
//
// At phi = -pi/2 both modes give C for every theta; at phi = +pi/2 the axis line of C.
#pragma once

#include "cga/Compact.h"
#include "cga/Multivector.h"
#include "cga/Vec3.h"

#include <string>
#include <vector>

namespace cga
{
enum class HopfMode
{
  Paper,
  Classical
};

struct HopfFibration
{
  Vec3 center{ 0, 0, 0 };
  Vec3 normal{ 0, 0, 1 }; // need not be unit; only its direction is used
  double radius = 1.0;
  HopfMode mode = HopfMode::Paper;

  /// Empty when the parameters are valid, otherwise what is wrong with them.
  std::string validate() const;

  /// KH(theta, phi) in the canonical frame, as a compact even versor (the fast path).
  /// Returns false when it cannot be formed (non-finite angles, or the motor logarithm failed).
  bool versor(double theta, double phi, Even& out) const;

  /// Points of the fiber over (theta, phi) in world coordinates: the images of the canonical circle
  /// points (cos t, sin t, 0), t = 2 pi j / count, j = 0 .. count-1. A point sent to infinity (the
  /// fiber is a line through it) is returned as NaN, and so is a point whose weight -ni.P is below
  /// 1e-13 of its largest coefficient (round-off of a point at infinity; in the canonical frame
  /// that is farther than about 1e7 from the origin). Returns false when versor() fails.
  bool fiberPoints(double theta, double phi, int count, std::vector<Vec3>& out) const;

  /// The canonical circle points (cos t, sin t, 0), t = 2 pi j / count, j = 0 .. count-1: the
  /// same for every fiber, so a source computes them once for all its fibers.
  static std::vector<Vec3> circleSamples(int count);

  /// fiberPoints of the given canonical circle points (circleSamples(count)) into
  /// out[0 .. circle.size()): the same points, without the per-fiber sines and cosines.
  bool fiberPoints(double theta, double phi, const std::vector<Vec3>& circle, Vec3* out) const;

  /// Canonical frame to world: center + radius * (p.x a + p.y b + p.z n).
  Vec3 toWorld(Vec3 canonical) const;

private:
  /// The world directions (a, b, n) of the canonical axes.
  void worldFrame(Vec3& a, Vec3& b, Vec3& n) const;

public:

  // ---- the construction's pieces, with the full multivector product (reference) ----

  /// The canonical base circle C (fiber over the south pole).
  static Multivector baseCircle();
  /// The unit dual line L of the z axis (C's axis), L^2 = -1.
  static Multivector baseAxis();
  /// The unit dual line L_theta through v/2 with direction (-sin theta, cos theta, 0).
  static Multivector boostedLine(double theta);
  /// Paper boost K = 1 + k no v_theta, k = 1/2 + phi/pi.
  static Multivector paperBoost(double theta, double phi);
  /// Paper twist M = exp(k/2 log(L L_theta^-1)), the log by logVersor, the exponential by series.
  /// Returns false when the logarithm fails.
  static bool paperTwist(double theta, double phi, Multivector& out);
  /// Classical KH, from its closed form with the full product and series exponentials.
  static Multivector classicalVersor(double theta, double phi);
  /// KH with the full product (reference of versor()); false when the logarithm fails.
  bool versorReference(double theta, double phi, Multivector& out) const;
  /// The fiber blade KH C ~KH in the canonical frame (reference); false as versorReference.
  bool fiberBladeReference(double theta, double phi, Multivector& out) const;
};

/// k = 1/2 + phi/pi of eq 11.
inline double hopfBoostParameter(double phi)
{
  return 0.5 + phi / 3.14159265358979323846;
}
} // namespace cga
