// Internal: d out / d b in closed form for the lanes that PointMapCore.h's strongHyperbolicSandwich
// maps as a similarity's bivector (a strong dilation with rotations, twists, translations), where
// the forward-mode tangents of that sandwich miss the derivative (docs/conventions.md section 3
// item 15, "The derivative by B next to a strong dilation"). Pointwise only
// (PointPairField::mapWithExponentDerivative); compiled once, for the baseline instruction set.
#pragma once

namespace cga
{
namespace core
{
/// d out / d b (byExponent[10 j + k] = d out_j / d b_k) of out = fn(<exp(b) up(p) exp(-b)>_1) for
/// b (the ten Bivector components) a similarity's bivector (no e_i^no part) with a non-zero no^ni
/// component, at p (three coordinates, the same frame as b): the Frechet derivative of the
/// exponential of the 5 x 5 action in the eigenbasis of b about its fixed point (computed in
/// double-double), with every factor e^{+-2a} combined with the point's normalization before it
/// is formed. False where a derivative is not finite (beyond the doubles' range).
/// With `image` given, also out there (its fixed point plus its displacement from it).
bool strongSimilarityExponentDerivative(
  const double* b, const double* p, double* byExponent, double* image = nullptr);

/// d out / d b as above for b with a strong hyperbolic plane and e_i^no parts (a boost between two
/// finite points; a strong plane beside point pairs), the lanes PointMapCore.h maps through their
/// two fixed points: the same closed form conjugated by the inversion about b's repeller r, which
/// sends r to infinity and b to a similarity's bivector (out = r + inv(out'')); at p = r, the
/// repeller's motion times (I - e^{2 d'} Q). False where a derivative is not finite or the fixed
/// points are not found.
bool strongBoostExponentDerivative(const double* b, const double* p, double* byExponent);
} // namespace core
} // namespace cga
