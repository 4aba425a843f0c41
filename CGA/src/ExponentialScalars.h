// Internal: the scalar arithmetic of the closed-form exponentials: the squares of the two
// commuting planes of a bivector, each plane's cosh/sinh (cos/sin) factors, the coefficients of
// expExact and of its power series, sinc. Templates over the number type T of PointMapCore.h
// (double, or the block kernel's vector of lanes): what differs from lane to lane is a selection
// (LaneMath.h), and each elementary function runs only when some lane needs it, so that a block
// whose lanes agree pays for one branch. Logarithm.cpp and Exponential.cpp use planeSquares and
// sinc for double.
//
// Everything has internal linkage (an unnamed namespace): the kernel includes this file in
// translation units compiled for AVX2 and AVX-512, whose copies of a shared inline function the
// linker could otherwise hand to code running on any CPU.
#pragma once

#include "LaneMath.h"

namespace cga
{
namespace detail
{
namespace
{
using core::Mask;
using core::splat;
// Unqualified calls: the lane vector's overloads come by argument-dependent lookup.
using core::allLanes;
using core::anyLane;
using core::equalTo;
using core::lessEqual;
using core::lessThan;
using core::magnitude;
using core::maskAnd;
using core::maskNot;
using core::maskOr;
using core::select;
using core::laneCosh;
using core::laneSinCos;
using core::laneSinh;
using core::laneSqrt;
using core::laneTanh;

/// sqrt(l) of a hyperbolic factor above which the AvoidOverflow scaling divides by cosh
/// (kExpScalingThreshold of Exponential.h; there tanh(x) rounds to 1).
constexpr double kScalingThreshold = 20.0;

// The squares l1 >= l2 of the two commuting planes of a bivector with <B B>_0 = s and
// (B ^ B)^2 = w2: the roots of l^2 - s l + w2/4 = 0, since B^2 = l1 + l2 + 2 B1 B2 and
// (2 B1 B2)^2 = 4 l1 l2. In R^{4,1} the roots are real; a negative discriminant is the rounding
// of a double root. The larger root in size comes from the sum without cancellation, the other
// from the product of the roots.
template <typename T>
inline void planeSquares(const T& s, const T& w2, T& l1, T& l2)
{
  const T zero{};
  const T disc = s * s - w2;
  const Mask<T> doubleRoot = maskNot(lessThan(zero, disc));
  const Mask<T> sPositive = lessEqual(zero, s);
  const T r = laneSqrt(select(doubleRoot, zero, disc));
  const T big = 0.5 * (s + select(sPositive, r, -r));
  const Mask<T> bigZero = equalTo(big, zero);
  const T small = select(bigZero, zero, 0.25 * w2 / select(bigZero, splat<T>(1.0), big));
  const T half = 0.5 * s;
  l1 = select(doubleRoot, half, select(sPositive, big, small));
  l2 = select(doubleRoot, half, select(sPositive, small, big));
}

/// x = m sqrt|lh| below which planeFunctions uses the power series.
constexpr double kPlaneSeriesLimit = 1e-2;

// For one plane of square l = m^2 lh: c = cosh sqrt(l) (cos sqrt(-l) when l < 0) and
// sHat = m sinh(sqrt l)/sqrt(l) (m sin(sqrt -l)/sqrt(-l)), i.e. the sinh factor of the plane
// measured against the unit-scaled bivector B/m, so that a huge m does not overflow.
// With divideByCosh and a hyperbolic sqrt(l) above the threshold both are divided by cosh.
template <typename T>
struct PlaneFunctions
{
  T c, sHat;
};

// Power series in l = +-x^2 of both functions (x < kPlaneSeriesLimit): the result does not jump
// at l = 0. Next term: l^5/10!.
template <typename T>
inline void planeSeries(const T& m, const T& lh, T& c, T& sHat)
{
  // l = m^2 lh = +-x^2, from m and lh (no overflow where the series is taken: m (m |lh|) = x^2 <
  // 1e-4), not from x: a Dual's tangents of x = m sqrt|lh| are lost where lh = 0, those of l not.
  // Products by the reciprocals, not divisions (a division costs several multiplications; the
  // reciprocals' rounding, half an ulp of each factor, is below the series' own).
  const T l = m * (m * lh);
  c = 1.0 + l * 0.5 * (1.0 + l * (1.0 / 12.0) * (1.0 + l * (1.0 / 30.0) * (1.0 + l * (1.0 / 56.0))));
  sHat = m * (1.0 + l * (1.0 / 6.0) *
    (1.0 + l * (1.0 / 20.0) * (1.0 + l * (1.0 / 42.0) * (1.0 + l * (1.0 / 72.0)))));
}

template <typename T>
inline PlaneFunctions<T> planeFunctions(const T& m, const T& lh, bool divideByCosh)
{
  const T r = laneSqrt(magnitude(lh));
  const T x = m * r;
  PlaneFunctions<T> f;
  planeSeries(m, lh, f.c, f.sHat);
  const Mask<T> series = lessThan(x, splat<T>(kPlaneSeriesLimit));
  // NaN lanes (B not finite) take no branch: the caller replaces them.
  const Mask<T> positive = lessThan(T{}, lh);
  const Mask<T> negative = lessEqual(lh, T{});
  const Mask<T> large = divideByCosh ? lessThan(splat<T>(kScalingThreshold), x) : lessThan(x, x);
  const Mask<T> hyperbolic = maskAnd(maskAnd(maskNot(series), positive), maskNot(large));
  const Mask<T> scaled = maskAnd(maskAnd(maskNot(series), positive), large);
  const Mask<T> trigonometric = maskAnd(maskNot(series), negative);
  const bool anyHyperbolic = anyLane(hyperbolic), anyScaled = anyLane(scaled);
  const bool anyTrigonometric = anyLane(trigonometric);
  if (!(anyHyperbolic || anyScaled || anyTrigonometric))
  {
    return f;
  }
  T c = f.c, numerator = T{};
  if (anyHyperbolic)
  {
    c = select(hyperbolic, laneCosh(x), c);
    numerator = select(hyperbolic, laneSinh(x), numerator);
  }
  if (anyScaled)
  {
    c = select(scaled, splat<T>(1.0), c);
    numerator = select(scaled, laneTanh(x), numerator);
  }
  if (anyTrigonometric)
  {
    T sine, cosine;
    laneSinCos(x, sine, cosine);
    c = select(trigonometric, cosine, c);
    numerator = select(trigonometric, sine, numerator);
  }
  f.c = c;
  f.sHat = select(series, f.sHat, numerator / r);
  return f;
}

/// sin(x)/x.
template <typename T>
inline T sinc(const T& x)
{
  T sine, cosine;
  laneSinCos(x, sine, cosine);
  return select(lessThan(magnitude(x), splat<T>(1e-4)), 1.0 - x * x / 6.0, sine / x);
}

// exp(B) = scalar + quadvector w + bivector u + bivectorW <w u>_2 for the unit-scaled u = B/m,
// w = u ^ u, outside the series range: the closed form of expExact (Exponential.h).
template <typename T>
struct ExactCoefficients
{
  T scalar, quadvector, bivector, bivectorW;
};

template <typename T>
inline ExactCoefficients<T> exactCoefficients(const T& m, const T& l1, const T& l2, bool divideByCosh)
{
  const T largest = select(lessThan(magnitude(l1), magnitude(l2)), magnitude(l2), magnitude(l1));
  const Mask<T> separated = maskOr(lessEqual(0.05 * largest, l1 - l2), lessThan(T{}, l1));
  ExactCoefficients<T> k{ T{}, T{}, T{}, T{} };
  if (anyLane(separated))
  {
    // Well separated squares: the divided differences are accurate as written.
    const PlaneFunctions<T> f1 = planeFunctions(m, l1, divideByCosh);
    const PlaneFunctions<T> f2 = planeFunctions(m, l2, divideByCosh);
    const T d = l1 - l2;
    k.scalar = f1.c * f2.c;
    k.quadvector = 0.5 * f1.sHat * f2.sHat;
    k.bivector = (l1 * f1.sHat * f2.c - l2 * f2.sHat * f1.c) / d;
    k.bivectorW = 0.5 * (f1.c * f2.sHat - f2.c * f1.sHat) / d;
    if (allLanes(separated))
    {
      return k;
    }
  }
  // Two rotations with nearly equal angles t1, t2 (both squares negative, at least one below -1):
  // b0 = (sinc(t1 + t2) + sinc(t1 - t2))/2, b4 = (sinc(t1 - t2) - sinc(t1 + t2))/(4 t1 t2).
  const T r1 = laneSqrt(-l1), r2 = laneSqrt(-l2);
  const T t1 = m * r1, t2 = m * r2;
  T sin1, cos1, sin2, cos2, sinSum, cosSum;
  laneSinCos(t1, sin1, cos1);
  laneSinCos(t2, sin2, cos2);
  laneSinCos(t1 + t2, sinSum, cosSum);
  const T mSincSum = sinSum / (r1 + r2); // m sinc(t1 + t2)
  const T mSincDiff = m * sinc(t1 - t2);
  k.scalar = select(separated, k.scalar, cos1 * cos2);
  k.quadvector = select(separated, k.quadvector, 0.5 * (sin1 / r1) * (sin2 / r2));
  k.bivector = select(separated, k.bivector, 0.5 * (mSincSum + mSincDiff));
  k.bivectorW = select(separated, k.bivectorW, 0.25 * (mSincDiff - mSincSum) / (r1 * r2));
  return k;
}

// Per lane, whether expExact takes the power series in B^2 = s + W (both squares of B at most 1
// in size), for the scale m of B and the plane squares l1, l2 of B/m.
template <typename T>
inline Mask<T> exactUsesSeries(const T& m, const T& l1, const T& l2)
{
  const T a1 = magnitude(l1), a2 = magnitude(l2);
  const T largest = select(lessThan(a1, a2), a2, a1);
  return maskOr(equalTo(largest, T{}), lessEqual((m * largest) * m, splat<T>(1.0)));
}

// The power series of expExact: exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 with B^2k = ak + bk W,
// (ak+1, bk+1) = (s ak + (W W) bk, ak + s bk), s = <B B>_0. For |l1|, |l2| <= 1 the terms fall
// below 4^k/(2k)!, so 16 of them reach double precision.
template <typename T>
struct SeriesCoefficients
{
  T a0, a4, b0, b4;
};

// 1/(2n)! and 1/(2n+1)! of the series' terms, each the one before divided by the next integer
// (the roundings of the division at run time, done by the compiler), so that the loop divides
// nothing at run time whether or not the compiler unrolls it: on 16 lanes GCC did not, and its
// 32 chained scalar divisions took more time than the series' vector arithmetic.
constexpr int kSeriesTerms = 16;
struct SeriesFactorials
{
  double even[kSeriesTerms], odd[kSeriesTerms];
};
constexpr SeriesFactorials seriesFactorials()
{
  SeriesFactorials f{};
  double even = 1.0;
  for (int n = 0; n < kSeriesTerms; ++n)
  {
    f.even[n] = even;
    f.odd[n] = even / (2 * n + 1);
    even = f.odd[n] / (2 * n + 2);
  }
  return f;
}
constexpr SeriesFactorials kSeriesFactorials = seriesFactorials();

template <typename T>
inline SeriesCoefficients<T> seriesCoefficients(T s, T w2)
{
  T alpha = T{} + 1.0, beta = T{};
  SeriesCoefficients<T> k{ T{}, T{}, T{}, T{} };
  for (int n = 0; n < kSeriesTerms; ++n)
  {
    const double evenFactorial = kSeriesFactorials.even[n]; // 1/(2n)!
    const double oddFactorial = kSeriesFactorials.odd[n];   // 1/(2n+1)!
    k.a0 = k.a0 + alpha * evenFactorial;
    k.a4 = k.a4 + beta * evenFactorial;
    k.b0 = k.b0 + alpha * oddFactorial;
    k.b4 = k.b4 + beta * oddFactorial;
    const T nextAlpha = s * alpha + w2 * beta;
    beta = alpha + s * beta;
    alpha = nextAlpha;
  }
  return k;
}
} // namespace
} // namespace detail
} // namespace cga
