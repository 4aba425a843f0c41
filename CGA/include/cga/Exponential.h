// Exponentials of bivectors (docs/conventions.md section 2, eq 9-10).
//
// Two rules, both returning an even element K (scalar + bivector + 4-vector):
//  * expPaper: the paper's formula with s = <B B>_0. Exact when B is a 2-blade; for a sum of point
//    pairs at different places it is not even a versor (K ~K = 1 + a grade-4 part).
//  * expExact: the true exponential, through the invariant decomposition B = B1 + B2 into
//    commuting 2-blades (B1 B2 = B2 B1, B1^2 = l1, B2^2 = l2 scalars), exp(B) = exp(B1) exp(B2).
//
// Scaling: a point is normalized after the sandwich, so K may be multiplied by any positive scalar
// without changing what it does to points. With ExpScaling::AvoidOverflow (the default) a
// hyperbolic factor with sqrt(l) > kExpScalingThreshold is divided by cosh(sqrt(l)): the result is
// exp(B) / cosh(sqrt(l)), which keeps the coefficients and the sandwich far from overflow (cosh
// itself overflows at sqrt(l) ~ 710). ExpScaling::None returns the unscaled value, which overflows
// to infinity for such B. Below the threshold both modes return exp(B) itself.
//
// Non-finite input (a NaN or infinite coefficient) gives an Even whose coefficients are all NaN;
// sandwichPoint() then reports failure.
#pragma once

#include "cga/Compact.h"
#include "cga/Multivector.h"

namespace cga
{
enum class ExpScaling
{
  AvoidOverflow,
  None
};

/// sqrt(l) of a hyperbolic factor above which AvoidOverflow divides by cosh(sqrt(l)).
constexpr double kExpScalingThreshold = 20.0;

/// The paper's rule (eq 9-10), s = <B B>_0: cosh(sqrt s) + sinh(sqrt s)/sqrt(s) B for s > 0,
/// cos(sqrt -s) + sin(sqrt -s)/sqrt(-s) B for s < 0, 1 + B at s = 0; near s = 0 the power series of
/// both functions of s is used, so the result is continuous across s = 0.
Even expPaper(const Bivector& b, ExpScaling scaling = ExpScaling::AvoidOverflow);

/// The exact exponential exp(B) = sum B^n/n!, in closed form:
/// exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 with W = B ^ B, where a0 = C1 C2, a4 = S1 S2 / 2,
/// b0 = (l1 S1 C2 - l2 S2 C1)/(l1 - l2), b4 = (C1 S2 - C2 S1)/(2 (l1 - l2)), Ci = cosh sqrt(li),
/// Si = sinh sqrt(li)/sqrt(li). When both |li| <= 1 the four coefficients come from the power
/// series in B^2 = s + W instead (no division by l1 - l2, so equal or zero li are no special case);
/// for a nearly isoclinic pair of rotations the divided differences are rewritten with sums of
/// angles.
Even expExact(const Bivector& b, ExpScaling scaling = ExpScaling::AvoidOverflow);

/// B = first + second with first second = second first, first^2 = firstSquare, second^2 =
/// secondSquare (scalars, firstSquare >= secondSquare).
struct InvariantDecomposition
{
  Bivector first, second;
  double firstSquare = 0.0, secondSquare = 0.0;
};

/// The invariant decomposition of B. A 2-blade gives (B, 0). Returns false when the two squares
/// coincide for a non-blade (e.g. an isoclinic rotation): then the split is not unique.
/// The split is ill-conditioned when the squares are close; expExact does not use it directly.
bool invariantDecomposition(const Bivector& b, InvariantDecomposition& out);

/// Reference exponential of any multivector in the full algebra (tests): Taylor series with
/// scaling and squaring (B scaled by 2^-k to coefficient norm <= 1/16, terms summed until below
/// 1e-19 relative, then squared k times). Non-finite input gives NaN coefficients.
Multivector expSeries(const Multivector& b);
} // namespace cga
