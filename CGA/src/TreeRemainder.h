// Internal: the remainder bound of the generator tree's expansions (docs/conventions.md section 3
// item 14), header-only so that the tests check it against the series itself.
#pragma once

#include <algorithm>
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

/// C(n, k) for n <= kMaxSpreadPower, row n from n (n + 1)/2 (Pascal's rule: exact integers while
/// they stay below 2^53, n <= 56; the tree takes n <= 22).
struct TreeBinomials
{
  double values[(kMaxSpreadPower + 1) * (kMaxSpreadPower + 2) / 2] = {};
  constexpr TreeBinomials()
  {
    for (int n = 0; n <= kMaxSpreadPower; ++n)
    {
      const int row = n * (n + 1) / 2, above = (n - 1) * n / 2;
      values[row] = 1.0;
      values[row + n] = 1.0;
      for (int k = 1; k < n; ++k)
      {
        values[row + k] = values[above + k - 1] + values[above + k];
      }
    }
  }
  constexpr const double* row(int n) const { return values + n * (n + 1) / 2; }
};
inline constexpr TreeBinomials kTreeBinomials{};

/// treeSpreadMoment for one (a, b) at several powers: the powers of a and b tabulated once
/// (repeated products from 1; b = 0 gives 0^0 = 1), each power's sum then power + 1 terms of
/// C(power, k) a^k b^(power - k) moments[k], summed from k = 0.
class TreeSpreadWeights
{
public:
  /// powers <= kMaxSpreadPower: the largest power moment() is asked for.
  TreeSpreadWeights(double a, double b, int powers)
  {
    this->APowers[0] = 1.0;
    this->BPowers[0] = 1.0;
    for (int j = 1; j <= powers; ++j)
    {
      this->APowers[j] = this->APowers[j - 1] * a;
      this->BPowers[j] = this->BPowers[j - 1] * b;
    }
  }
  double moment(const double* moments, int power) const
  {
    const double* binomial = kTreeBinomials.row(power);
    double sum = 0.0;
    for (int k = 0; k <= power; ++k)
    {
      sum += binomial[k] * this->APowers[k] * this->BPowers[power - k] * moments[k];
    }
    return sum;
  }

private:
  double APowers[kMaxSpreadPower + 1], BPowers[kMaxSpreadPower + 1];
};

inline double treeSpreadMoment(const double* moments, int power, double a, double b)
{
  return TreeSpreadWeights(a, b, power).moment(moments, power);
}

/// The norm of the degree-j term's tensor: the term of the series above is
///   h_j(z) = |z|^j U_j(u.z/|z|) = 2^j <pi(X^(j)), Z^(j)>,   X = (u, sqrt(1 - |u|^2)), Z = (z, 0),
/// in R^4 (1/|X - Y|^2 is the Newton kernel of R^4 and the U_j its zonal harmonics), pi the
/// orthogonal projection onto trace-free symmetric tensors, <pi(x^(j)), y^(j)> = 2^-j |x|^j |y|^j
/// U_j(cos) in R^4; its Frobenius norm is 2^j sqrt(<pi(X^(j)), X^(j)>) = sqrt((j + 1) 2^j), and
/// contracting it with a vector v shrinks it by at most |v| (docs/conventions.md section 3 item 14).
inline double treeHarmonicTermNorm(int degree)
{
  return std::sqrt((degree + 1.0) * std::ldexp(1.0, degree));
}

/// The norm ||pi(V_k)|| of the trace-free part in R^4 of the moment tensor of degree k of vectors
/// g_i (components values each), V_k = sum_i g_i yhat_i^(k) (yhat_i in R^3, fourth component 0),
/// from its distinct entries: moment(a, b, c) returns the `components` values of
/// sum_i g_i yhat_x^a yhat_y^b yhat_z^c (a + b + c <= k). With
/// <pi(x^(k)), y^(k)> = 2^-k |x|^k |y|^k U_k(cos) and
/// |x|^k |y|^k U_k(cos) = sum_m (-1)^m C(k - m, m) 2^(k - 2m) (x.y)^(k-2m) |x|^2m |y|^2m,
///   ||pi(V_k)||^2 = sum_ij g_i.g_j <pi(yhat_i^(k)), yhat_j^(k)>
///                 = sum_m (-1)^m C(k - m, m) 2^-2m ||tr^m V_k||^2,
/// tr^m V_k = sum_i g_i |yhat_i|^2m yhat_i^(k-2m), whose entries are
/// sum_{|gamma| = m} m!/gamma! V_(beta + 2 gamma), and ||T||^2 = sum_beta n!/beta! |T_beta|^2 for a
/// symmetric tensor of degree n. The alternating sum cancels where the g_i do (the point of it):
/// 1e-12 of the sum of its terms' magnitudes is added before the square root (its rounding).
/// k <= kMaxSpreadPower, components <= 16.
template <class Moment>
double treeTraceFreeNorm(int k, int components, const Moment& moment)
{
  double factorials[kMaxSpreadPower + 1];
  factorials[0] = 1.0;
  for (int n = 1; n <= k; ++n)
  {
    factorials[n] = factorials[n - 1] * n;
  }
  double sum = 0.0, magnitude = 0.0;
  for (int m = 0; 2 * m <= k; ++m)
  {
    const int n = k - 2 * m;
    double traceNorm = 0.0; // ||tr^m V_k||^2
    for (int a = n; a >= 0; --a)
    {
      for (int b = n - a; b >= 0; --b)
      {
        const int c = n - a - b;
        double entry[16] = {};
        for (int ga = m; ga >= 0; --ga)
        {
          for (int gb = m - ga; gb >= 0; --gb)
          {
            const int gc = m - ga - gb;
            const double weight = factorials[m] / (factorials[ga] * factorials[gb] * factorials[gc]);
            const double* v = moment(a + 2 * ga, b + 2 * gb, c + 2 * gc);
            for (int i = 0; i < components; ++i)
            {
              entry[i] += weight * v[i];
            }
          }
        }
        double squared = 0.0;
        for (int i = 0; i < components; ++i)
        {
          squared += entry[i] * entry[i];
        }
        traceNorm += factorials[n] / (factorials[a] * factorials[b] * factorials[c]) * squared;
      }
    }
    // (-1)^m C(k - m, m) 2^-2m
    const double coefficient = factorials[k - m] / (factorials[m] * factorials[k - 2 * m]) * std::ldexp(1.0, -2 * m);
    sum += (m % 2 ? -coefficient : coefficient) * traceNorm;
    magnitude += coefficient * traceNorm;
  }
  return std::sqrt(std::max(0.0, sum) + 1e-12 * magnitude);
}
} // namespace detail
} // namespace cga
