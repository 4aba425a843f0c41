// Logarithm of an even versor: the bivector B with exp(B) = K (Exponential.h), for rotors,
// translators, motors (screws), boosts, dilators and their products (docs/conventions.md section 4 needs it
// for the Hopf twist M = exp(k log(L / L_theta))). For unit dual lines L1, L2 (L^2 = -1) the ratio
// L2 L1^-1 = -L2 L1 is the square of the motor M = exp(log(L2 L1^-1) / 2) with M L1 ~M = L2.
//
// Method: after normalizing K ~K = 1, K = K1 K2 with Ki = Ci + ui the exponentials of the two
// commuting planes (ui^2 = si). With X = <K>_2 and Y = <K>_4 = u1 u2:
//   s1 + s2 = <X X>_0 - 2 Y Y,  s1 s2 = Y Y,  Ci^2 = 1 + si,  C1 C2 = <K>_0,
//   X = C2 u1 + C1 u2,  <X Y>_2 = C1 s2 u1 + C2 s1 u2,
// so log K = g1 u1 + g2 u2 = cX X + cXY <X Y>_2, gi = (angle of plane i)/sqrt|si|. The divided
// differences in cX, cXY are evaluated as power series in s1 + s2, s1 s2 near the identity (which
// includes translators, where s1 = s2 = 0), and with sums of angles for nearly isoclinic rotations.
//
// Branch: each plane's angle is taken in [0, pi] with the orientation carried by the plane, and of
// the two factorizations (C1, u1, C2, u2) and (-C1, -u1, -C2, -u2) the one whose plane with the
// larger |Ci| has Ci > 0: it has the smaller total angle. For a simple rotor
// R = cos(a) + sin(a) U this gives log R = a U with a in [0, pi] (up to the orientation of U), i.e.
// the principal value in (-pi, pi]; R = exp(-theta B/2) gives back -theta B/2 for |theta| < 2 pi.
//
// Accuracy: exp(log K) reproduces K to about 1e-13 relative for motors, boosts and general versors
// of moderate size; the normalization K ~K = 1 is itself computed from coefficients of size |K|^2,
// so large boosts lose about eps |K|^2. Near two rotation planes whose angles add up to about pi
// (or are both about pi/2) the logarithm is ill-conditioned (not unique at the limit) and only
// approximately recovered.
#pragma once

#include "cga/Compact.h"

namespace cga
{
/// log K for an even versor K (K ~K a positive scalar; it need not be 1). Returns false, leaving
/// `out` unchanged, when K is not finite, when K ~K is not a positive scalar to within
/// `versorTolerance` (relative; e.g. the paper's non-versor exponentials), or when K has no unique
/// real logarithm (K = -1, -(1 + tau), -exp(boost)).
bool logVersor(const Even& k, Bivector& out, double versorTolerance = 1e-9);
} // namespace cga
