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

/// The spread of a node's generators (Salmon and Warren's absolute moments): given
/// moments[k] = sum_i m_i s_i^k for k = 0..power (m_i >= 0, s_i = |x_i - c|/rho in [0, 1]), returns
///   sum_i m_i (a s_i + b)^power = sum_k C(power, k) a^k b^(power - k) moments[k]   (a, b >= 0).
/// With a = rho/(rho + r), b = r/(rho + r) it is sum_i m_i ((|x_i - c| + r)/(rho + r))^power: the
/// generators' own distances where the remainder bound takes the node's radius rho (plus r, a cube
/// of points' radius). Each term of the remainder's series grows like q_i^j, so a generator at
/// q_i = q (a s_i + b) <= q errs by at most (a s_i + b)^(p+1) times treeRemainderBound(p, q, S)
/// (its factors besides q^(p+1) increase with q): the node errs by at most that bound times
/// treeSpreadMoment(moments, p + 1, a, b) instead of times sum_i m_i.
/// power <= kMaxSpreadPower.
constexpr int kMaxSpreadPower = 64;
inline double treeSpreadMoment(const double* moments, int power, double a, double b)
{
  // b^j by repeated products from 1 (b = 0 gives 0^0 = 1), tabulated once.
  double bPowers[kMaxSpreadPower + 1];
  bPowers[0] = 1.0;
  for (int j = 1; j <= power; ++j)
  {
    bPowers[j] = bPowers[j - 1] * b;
  }
  double sum = 0.0, binomial = 1.0, aPower = 1.0;
  for (int k = 0; k <= power; ++k)
  {
    const double bPower = bPowers[power - k];
    sum += binomial * aPower * bPower * moments[k];
    binomial = binomial * (power - k) / (k + 1);
    aPower *= a;
  }
  return sum;
}
} // namespace detail
} // namespace cga
