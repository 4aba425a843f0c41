// Internal: sin and cos of a long double angle, its argument reduced by π/2 here (Cody and Waite:
// π/2 in three parts) for |x| <= 2^30, glibc's sincosl for the rest. glibc reduces every 80-bit
// argument beyond π/4 with its Payne–Hanek kernel (__kernel_rem_pio2), which was 10 % of the
// orbit source's update (Orbit::versor's angles t r); SLEEF has no long double functions.
//
// Error: P1 and P2 hold 33 bits of π/2 each, so n P1 and n P2 are exact for |n| <= 2^31, and
// x - n P1 is exact (Sterbenz); P3 leaves π/2's error below 1.5e-41 relative. The reduced
// r = ((x - n P1) - n P2) - n P3 errs by two roundings of r and, for |n| <= 2^30, less than
// 2^-102 from P3 and its product, so sin and cos err by a few units of 2^-64 beyond sincosl's own
// (ReducedSinCos.* tests them against sincosl, which reduces exactly).
//
// Internal linkage only.
#pragma once

#include "LaneMath.h"

#include <cmath>

namespace cga
{
namespace detail
{
namespace
{
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
  const long double n = (x * twoOverPi + rounder) - rounder;
  const long double r = ((x - n * p1) - n * p2) - n * p3;
  long double sr, cr;
  ::sincosl(r, &sr, &cr); // |r| <= π/4 (up to rounding): glibc's kernels without a reduction
  core::sinCosOfQuadrant(static_cast<int>(static_cast<long long>(n) & 3), sr, cr, s, c);
}
} // namespace
} // namespace detail
} // namespace cga
