// Internal: the remainder bound of the generator tree's expansions (docs/conventions.md section 3
// item 14), header-only so that the tests check it against the series itself.
#pragma once

#include <cmath>

namespace cga
{
namespace detail
{
/// A bound of |sum_{j > degree} q^j U_j(x)| for 0 <= q < 1 and |x| <= |u| < 1, where U_j are the
/// Chebyshev polynomials of the second kind and S >= 1/sqrt(1 - |u|^2) (HUGE_VAL: not known).
/// |U_j(x)| <= j + 1, and |U_j(cos theta)| = |sin((j + 1) theta)/sin theta| <= 1/sqrt(1 - x^2) <= S,
/// so the tail is at most the smaller of
///   sum_{j>p} (j + 1) q^j = q^(p+1) ((p + 2) - (p + 1) q)/(1 - q)^2  and  S q^(p+1)/(1 - q).
inline double treeRemainderBound(int degree, double q, double S)
{
  const double power = std::pow(q, degree + 1);
  const double chebyshev = power * ((degree + 2.0) - (degree + 1.0) * q) / ((1.0 - q) * (1.0 - q));
  const double geometric = S < HUGE_VAL ? S * power / (1.0 - q) : HUGE_VAL;
  return geometric < chebyshev ? geometric : chebyshev;
}
} // namespace detail
} // namespace cga
