// Internal: sin and cos of a long double angle, its argument reduced by π/2 here (Cody and Waite:
// π/2 in three parts) for |x| <= 2^30, glibc's sincosl for the rest. glibc reduces every 80-bit
// argument beyond π/4 with its Payne–Hanek kernel (__kernel_rem_pio2), which was 10 % of the
// orbit source's update (the angles t r of Orbit's extended form); SLEEF has no long double
// functions.
//
// Error: P1 and P2 hold 33 bits of π/2 each, so n P1 and n P2 are exact for |n| <= 2^31, and
// x - n P1 is exact (Sterbenz); P3 leaves π/2's error below 1.5e-41 relative. The reduced
// r = ((x - n P1) - n P2) - n P3 errs by two roundings of r and, for |n| <= 2^30, less than
// 2^-102 from P3 and its product, so sin and cos err by a few units of 2^-64 beyond sincosl's own
// (ReducedSinCos.* tests them against sincosl, which reduces exactly).
//
// The reduced angle's sine and cosine: where long double has a 64-bit significand (x87), their
// Taylor polynomials to r^21/21! and r^22/22! (Horner in z = r^2; the terms from r^7 and r^8 on,
// below 2^-11 of the brackets they enter, in double), 13 ns against sincosl's 59 on the README's
// machine (glibc's kernels, 35 % of an orbit update with one seed, run the 80-bit arithmetic
// through tables and longer polynomials). For |r| <= π/4 the first omitted terms are below 2^-72
// and 2^-70 of the results; the coefficients' rounding (2^-65 in 64 bits, 2^-53 in double) and
// Horner's roundings enter the results below 2^-67, and z's rounding to double below 2^-70: within
// one unit in the last place of sincosl's results (over 8·10^6 angles; ReducedSinCos.* checks it
// on 200,000). Elsewhere sincosl, whose precision the polynomials do not reach.
//
// Internal linkage only.
#pragma once

#include "LaneMath.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace cga
{
namespace detail
{
namespace
{
#if LDBL_MANT_DIG == 64
// c[0] + z (c[1] + z (... + z c[N - 1])).
template <typename T, int N>
inline T horner(T z, const T (&c)[N])
{
  T p = c[N - 1];
  for (int i = N - 2; i >= 0; --i)
  {
    p = c[i] + z * p;
  }
  return p;
}

// The polynomials' coefficients -1/3!, 1/5!, -1/7!, ... (sine) and 1/4!, -1/6!, 1/8!, ...
// (cosine) to 1/21! and 1/22!: the first two of each in 64 bits, the rest in double, the
// nearest values.
constexpr long double kSineLeading[] = { -0x1.5555555555555556p-3L, 0x1.1111111111111112p-7L };
constexpr double kSineRest[] = { -0x1.a01a01a01a01ap-13, 0x1.71de3a556c734p-19,
  -0x1.ae64567f544e4p-26, 0x1.6124613a86d09p-33, -0x1.ae7f3e733b81fp-41, 0x1.952c77030ad4ap-49,
  -0x1.2f49b46814157p-57, 0x1.71b8ef6dcf572p-66 };
constexpr long double kCosineLeading[] = { 0x1.5555555555555556p-5L, -0x1.6c16c16c16c16c16p-10L };
constexpr double kCosineRest[] = { 0x1.a01a01a01a01ap-16, -0x1.27e4fb7789f5cp-22,
  0x1.1eed8eff8d898p-29, -0x1.93974a8c07c9dp-37, 0x1.ae7f3e733b81fp-45, -0x1.6827863b97d97p-53,
  0x1.e542ba4020225p-62, -0x1.0ce396db7f853p-70 };
#endif

// sin r and cos r for |r| <= π/4 (up to the reduction's rounding).
inline void sinCosOfReduced(long double r, long double& s, long double& c)
{
#if LDBL_MANT_DIG == 64
  const long double z = r * r;
  // sin r = r + r z (-1/3! + z (1/5! + z R(z))), cos r = 1 - (z/2 - z^2 (1/4! + z (-1/6! +
  // z C(z)))): the leading terms added last, so that the tails' roundings shrink with them, and
  // R and C, below 2^-11 of their brackets, in double (SSE instead of x87: the kernels' time
  // 21.5 -> 12.8 ns).
  const long double sineRest = horner(static_cast<double>(z), kSineRest);
  const long double cosineRest = horner(static_cast<double>(z), kCosineRest);
  const long double sineTail = kSineLeading[0] + z * (kSineLeading[1] + z * sineRest);
  const long double cosineTail = kCosineLeading[0] + z * (kCosineLeading[1] + z * cosineRest);
  s = z == 0.0L ? r : r + r * z * sineTail; // r itself where z underflows (-0 stays)
  c = 1.0L - (0.5L * z - z * z * cosineTail);
#else
  ::sincosl(r, &s, &c);
#endif
}

inline void reducedSinCos(long double x, long double& s, long double& c)
{
  if (!(std::fabs(x) <= 0x1p30L)) // also NaN and infinity
  {
    ::sincosl(x, &s, &c);
    return;
  }
  constexpr long double twoOverPi = 0x1.45f306dc9c882a54p-1L;
  constexpr long double p1 = 0x1.921fb544p+0L;
  constexpr long double p2 = 0x1.0b4611a6p-34L;
  constexpr long double p3 = 0x1.3198a2e03707344ap-69L;
  // The nearest integer to x 2/π: adding 1.5 2^63 leaves no fraction bits in the 64-bit significand
  // (nearbyintl, which saves and restores the floating-point environment, cost as much as glibc's
  // reduction).
  constexpr long double rounder = 0x1.8p63L;
  const long double shifted = x * twoOverPi + rounder;
  const long double n = shifted - rounder;
  const long double r = ((x - n * p1) - n * p2) - n * p3;
  long double sr, cr;
  sinCosOfReduced(r, sr, cr); // |r| <= π/4 (up to rounding)
#if LDBL_MANT_DIG == 64
  // n mod 4 from the shifted sum's significand (the x87 format's first 8 bytes), whose integer is
  // 1.5 2^63 + n: the conversion to an integer switches the x87 rounding mode twice (fldcw), which
  // cost a quarter of Orbit's extended form.
  std::uint64_t significand;
  std::memcpy(&significand, &shifted, sizeof significand);
  const int quadrant = static_cast<int>(significand & 3);
#else
  const int quadrant = static_cast<int>(static_cast<long long>(n) & 3);
#endif
  core::sinCosOfQuadrant(quadrant, sr, cr, s, c);
}
} // namespace
} // namespace detail
} // namespace cga
