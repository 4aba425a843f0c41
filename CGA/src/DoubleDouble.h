// Internal: double-double numbers (an unevaluated sum hi + lo of two doubles, |lo| <= ulp(hi)/2,
// about 106 bits), a number type of PointMapCore.h for the one place where double precision is
// not enough: the Exact exponential of a huge, nearly nilpotent bivector at a point far from its
// nilpotent part (docs/conventions.md section 2 item 12, AccurateImage.cpp).
//
// The arithmetic is Dekker's and Knuth's error-free transformations (splitting, no fused
// multiply-add: the library is compiled with -ffp-contract=off, and the same bits come on every
// instruction set); the elementary functions (sqrt, exp, cosh, sinh, tanh, sin, cos) reduce their
// argument and sum Taylor series to below 2^-104 of the result. Every operation is accurate to a
// few units of 2^-104 of its result (the division and sqrt by one Newton step, the sums with both
// parts' errors kept), so a computation that loses c bits to cancellation in double keeps
// 106 - c here. Comparisons order by value (hi, then lo); a non-finite hi is the value.
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "LaneMath.h"

namespace cga
{
namespace core
{
namespace
{
struct DoubleDouble
{
  static constexpr int kLanes = 1;
  using Mask = bool;

  double hi = 0.0, lo = 0.0;

  DoubleDouble() = default;
  DoubleDouble(double x) // NOLINT(google-explicit-constructor): a double is a number of this type
    : hi(x)
  {
  }
  DoubleDouble(double h, double l)
    : hi(h)
    , lo(l)
  {
  }
};
using DD = DoubleDouble;

/// s + e = a + b exactly (Knuth's two-sum).
inline DD twoSum(double a, double b)
{
  const double s = a + b;
  const double bb = s - a;
  return { s, (a - (s - bb)) + (b - bb) };
}

/// s + e = a + b exactly for |a| >= |b| (or a = 0).
inline DD quickTwoSum(double a, double b)
{
  const double s = a + b;
  return { s, b - (s - a) };
}

/// hi + lo = a with hi holding the upper 26 bits (Dekker's split), scaled where 2^27 a would
/// overflow.
inline void split(double a, double& hi, double& lo)
{
  constexpr double kSplitter = 134217729.0; // 2^27 + 1
  constexpr double kLimit = 0x1p996;
  if (a > kLimit || a < -kLimit)
  {
    const double scaled = a * 0x1p-28;
    const double t = kSplitter * scaled;
    hi = (t - (t - scaled)) * 0x1p28;
    lo = a - hi;
    return;
  }
  const double t = kSplitter * a;
  hi = t - (t - a);
  lo = a - hi;
}

/// p + e = a b exactly (Dekker's product), for finite products away from underflow.
inline DD twoProduct(double a, double b)
{
  const double p = a * b;
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return { p, ((ah * bh - p) + ah * bl + al * bh) + al * bl };
}

inline bool isFiniteValue(double x)
{
  return __builtin_fabs(x) < __builtin_inf();
}

inline DD operator+(const DD& a, const DD& b)
{
  DD s = twoSum(a.hi, b.hi);
  if (!isFiniteValue(s.hi))
  {
    return { s.hi, 0.0 };
  }
  const DD t = twoSum(a.lo, b.lo);
  s.lo += t.hi;
  s = quickTwoSum(s.hi, s.lo);
  s.lo += t.lo;
  return quickTwoSum(s.hi, s.lo);
}
inline DD operator-(const DD& a)
{
  return { -a.hi, -a.lo };
}
inline DD operator-(const DD& a, const DD& b)
{
  return a + (-b);
}
inline DD operator*(const DD& a, const DD& b)
{
  DD p = twoProduct(a.hi, b.hi);
  if (!isFiniteValue(p.hi))
  {
    return { p.hi, 0.0 };
  }
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return quickTwoSum(p.hi, p.lo);
}
inline DD operator/(const DD& a, const DD& b)
{
  const double q1 = a.hi / b.hi;
  if (!isFiniteValue(q1) || q1 == 0.0)
  {
    return { q1, 0.0 };
  }
  DD r = a - b * DD(q1);
  const double q2 = r.hi / b.hi;
  r = r - b * DD(q2);
  const double q3 = r.hi / b.hi;
  return quickTwoSum(q1, q2) + DD(q3);
}
// With a double on either side (the templates' constants).
inline DD operator+(const DD& a, double b)
{
  return a + DD(b);
}
inline DD operator+(double a, const DD& b)
{
  return DD(a) + b;
}
inline DD operator-(const DD& a, double b)
{
  return a - DD(b);
}
inline DD operator-(double a, const DD& b)
{
  return DD(a) - b;
}
inline DD operator*(const DD& a, double b)
{
  return a * DD(b);
}
inline DD operator*(double a, const DD& b)
{
  return DD(a) * b;
}
inline DD operator/(const DD& a, double b)
{
  return a / DD(b);
}
inline DD operator/(double a, const DD& b)
{
  return DD(a) / b;
}

// What LaneMath.h lists, for one lane.
inline void toLanes(const DD& x, double* lanes)
{
  lanes[0] = x.hi;
}
inline void fromLanes(const double* lanes, DD& x)
{
  x = DD(lanes[0]);
}
inline bool lessThan(const DD& a, const DD& b)
{
  return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}
inline bool lessEqual(const DD& a, const DD& b)
{
  return a.hi < b.hi || (a.hi == b.hi && a.lo <= b.lo);
}
inline bool equalTo(const DD& a, const DD& b)
{
  return a.hi == b.hi && a.lo == b.lo;
}
inline DD select(bool mask, const DD& a, const DD& b)
{
  return mask ? a : b;
}
inline DD magnitude(const DD& x)
{
  return x.hi < 0.0 ? -x : x;
}
inline DD valueOf(const DD& x)
{
  return x;
}
/// The power of two of hi (binaryFloor): a power of two within a factor 2 of |x|, which is all
/// the templates need of it (an exact scale).
inline DD binaryFloor(const DD& x)
{
  return DD(binaryFloor(x.hi));
}
inline DD binaryExponentOf(const DD& x)
{
  return DD(binaryExponentOf(x.hi));
}
/// 2^k for k rounded toward zero (the templates' rounding of k by adding 1.5 2^52 is exact in
/// double-double and may leave a half; 2^k and 2^-k stay each other's inverse).
inline DD powerOfTwoOf(const DD& k)
{
  return DD(powerOfTwoOf(static_cast<double>(static_cast<int>(k.hi))));
}

/// x 2^e for an integral e (both parts exactly, away from overflow and underflow).
inline DD scaleByPowerOfTwo(const DD& x, int e)
{
  return { __builtin_ldexp(x.hi, e), __builtin_ldexp(x.lo, e) };
}

inline DD laneSqrt(const DD& a)
{
  if (!(a.hi > 0.0) || !isFiniteValue(a.hi))
  {
    return DD(__builtin_sqrt(a.hi));
  }
  // One Newton step from the double root r: sqrt(a) = r + (a - r^2) / (2 r) to 2^-104.
  const double r = __builtin_sqrt(a.hi);
  const DD residual = a - twoProduct(r, r);
  return quickTwoSum(r, residual.hi / (2.0 * r));
}

constexpr double kLn2Hi = 6.931471805599452862e-01, kLn2Lo = 2.319046813846299558e-17;
constexpr double kHalfPiHi = 1.570796326794896558e+00, kHalfPiLo = 6.123233995736766036e-17;

/// exp(x) - 1 for |x| <= ln2/2^10 by its Taylor series (10 terms: the next is below 2^-120).
inline DD expm1Reduced(const DD& r)
{
  DD term = r, sum = r;
  for (int n = 2; n <= 11; ++n)
  {
    term = term * r / static_cast<double>(n);
    sum = sum + term;
  }
  return sum;
}

/// exp(x): x = k ln2 + 2^9 r, e^x = 2^k (1 + expm1(r))^(2^9), the squarings kept as
/// (1 + s)^2 - 1 = s (2 + s) so that the small part stays exact.
inline DD exponential(const DD& x)
{
  if (x.hi != x.hi)
  {
    return x;
  }
  if (x.hi > 709.0)
  {
    return DD(__builtin_inf());
  }
  if (x.hi < -745.0)
  {
    return DD(0.0);
  }
  const double k = __builtin_nearbyint(x.hi / kLn2Hi);
  const DD reduced = (x - DD(kLn2Hi, kLn2Lo) * DD(k)) * 0x1p-9;
  DD s = expm1Reduced(reduced);
  for (int i = 0; i < 9; ++i)
  {
    s = s * (s + 2.0);
  }
  return scaleByPowerOfTwo(s + 1.0, static_cast<int>(k));
}

/// sinh(x) for |x| < 1/2 by its Taylor series (the next term is below 2^-110 of x).
inline DD sinhSeries(const DD& x)
{
  const DD x2 = x * x;
  DD term = x, sum = x;
  for (int n = 1; n <= 12; ++n)
  {
    term = term * x2 / static_cast<double>((2 * n) * (2 * n + 1));
    sum = sum + term;
  }
  return sum;
}

inline DD laneCosh(const DD& x)
{
  const DD e = exponential(magnitude(x));
  return isFiniteValue(e.hi) ? 0.5 * (e + 1.0 / e) : e;
}
inline DD laneSinh(const DD& x)
{
  if (__builtin_fabs(x.hi) < 0.5)
  {
    return sinhSeries(x);
  }
  const DD e = exponential(magnitude(x));
  const DD s = isFiniteValue(e.hi) ? 0.5 * (e - 1.0 / e) : e;
  return x.hi < 0.0 ? -s : s;
}
inline DD laneTanh(const DD& x)
{
  if (__builtin_fabs(x.hi) < 0.5)
  {
    const DD s = sinhSeries(x);
    return s / laneSqrt(1.0 + s * s);
  }
  // 1 - 2 / (e^{2|x|} + 1) without cancellation: (1 - e^{-2|x|}) / (1 + e^{-2|x|}), e^{-2|x|} <= 1/e.
  const DD e = exponential(-2.0 * magnitude(x));
  const DD t = (1.0 - e) / (1.0 + e);
  return x.hi < 0.0 ? -t : t;
}

/// sin and cos of |r| <= pi/4 by their Taylor series (to the term below 2^-110).
inline void sinCosReduced(const DD& r, DD& s, DD& c)
{
  const DD r2 = r * r;
  DD sineTerm = r, cosineTerm = DD(1.0);
  s = r;
  c = DD(1.0);
  for (int n = 1; n <= 14; ++n)
  {
    cosineTerm = -(cosineTerm * r2) / static_cast<double>((2 * n - 1) * (2 * n));
    sineTerm = -(sineTerm * r2) / static_cast<double>((2 * n) * (2 * n + 1));
    c = c + cosineTerm;
    s = s + sineTerm;
  }
}

/// sin and cos by the reduction x = k pi/2 + r (pi/2 to 107 bits: r carries an error of about
/// |x| 2^-107, relative to the result |x| times the functions' own), double's above |x| = 2^30.
inline void laneSinCos(const DD& x, DD& s, DD& c)
{
  if (!isFiniteValue(x.hi))
  {
    s = c = DD(__builtin_nan(""));
    return;
  }
  if (__builtin_fabs(x.hi) > 0x1p30)
  {
    // The reduction would lose more than 30 bits; the angle itself is then known only to
    // ulp(x) >= 2^-22: double's functions (exact reduction) are as good.
    double sine, cosine;
    laneSinCos(x.hi, sine, cosine);
    s = DD(sine);
    c = DD(cosine);
    return;
  }
  const double k = __builtin_nearbyint(x.hi / kHalfPiHi);
  const DD r = x - DD(kHalfPiHi, kHalfPiLo) * DD(k);
  DD sr, cr;
  sinCosReduced(r, sr, cr);
  // k mod 4 by fmod (exact): k may exceed every integer type for a huge x
  const double modulo = __builtin_fmod(k, 4.0);
  sinCosOfQuadrant(static_cast<int>(modulo < 0.0 ? modulo + 4.0 : modulo), sr, cr, s, c);
}

/// The rounding unit of double-double for the test of what is rounding (PointMapCore.h's
/// dropRounding), with margin: its operations round to a few units of 2^-104.
template <>
struct RoundingUnit<DoubleDouble>
{
  static constexpr double value = 0x1p-100;
};
} // namespace
} // namespace core
} // namespace cga
