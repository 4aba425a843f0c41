// The null basis {e1, e2, e3, no, ni} of docs/conventions.md section 1, in which the compact types store and
// multiply their coefficients.
//
// A null basis blade is a 5-bit index like an orthonormal blade mask (Basis.h), except that bit 3
// means no and bit 4 means ni; both bits together mean E = no ^ ni. Every null blade is therefore a
// Euclidean blade A times one of 1, no, ni, E, written A ^ M = A M in that order (e.g. index 9 is
// e1 ^ no, index 27 is e1 ^ e2 ^ no ^ ni). That split makes products easy: Euclidean blades
// multiply with the orthonormal sign table and {1, no, ni, E} is a closed four-dimensional algebra.
//
// Why not compute in the orthonormal basis: a point far from the origin has a no coefficient of 1
// and an ni coefficient of |x|^2/2. In e+, e- these two mix, and reading the weight -ni.P back
// (the sum of the e+ and e- coefficients) cancels catastrophically; in the null basis they
// stay apart.
#pragma once

#include "cga/Basis.h"
#include "cga/Multivector.h"

namespace cga
{
namespace nullblade
{
constexpr unsigned e1 = 1u, e2 = 2u, e3 = 4u, no = 8u, ni = 16u, E = 24u;
constexpr unsigned euclideanMask = 7u;
}

/// One term of a product of null blades: coefficient * blade.
struct NullTerm
{
  unsigned blade = 0;
  double coefficient = 0.0;
};

/// Geometric product of two null basis blades. Writes its 0, 1 or 2 terms to `out` (no no = 0;
/// no ni = -1 + E) and returns how many there are.
int nullBladeProduct(unsigned a, unsigned b, NullTerm out[2]);

/// A null basis blade written in the orthonormal basis (for conversions and tests).
Multivector nullBladeToMultivector(unsigned blade);

/// 32 null-basis coefficients -> 32 orthonormal coefficients (Multivector order), and back.
/// With A a Euclidean blade: A no = (A e+ + A e-)/2, A ni = A e- - A e+, A E = A e+ e-.
void nullToOrthonormal(const double null[kBladeCount], double orthonormal[kBladeCount]);
void orthonormalToNull(const double orthonormal[kBladeCount], double null[kBladeCount]);
} // namespace cga
