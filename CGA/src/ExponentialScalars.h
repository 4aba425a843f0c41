// Internal: the scalar arithmetic of the closed-form exponentials: the squares of the two
// commuting planes of a bivector, each plane's cosh/sinh (cos/sin) factors, the coefficients of
// expExact and of its power series, sinc. The templates of PointMapCore.h call these per lane;
// Logarithm.cpp uses planeSquares and sinc.
//
// Everything has internal linkage (an unnamed namespace) and uses only builtins and libm: the
// kernel includes this file in translation units compiled for AVX2 and AVX-512, whose copies of a
// shared inline function the linker could otherwise hand to code running on any CPU.
#pragma once

#include <math.h>

namespace cga
{
namespace detail
{
namespace
{
/// sqrt(l) of a hyperbolic factor above which the AvoidOverflow scaling divides by cosh
/// (kExpScalingThreshold of Exponential.h; there tanh(x) rounds to 1).
constexpr double kScalingThreshold = 20.0;

// The squares l1 >= l2 of the two commuting planes of a bivector with <B B>_0 = s and
// (B ^ B)^2 = w2: the roots of l^2 - s l + w2/4 = 0, since B^2 = l1 + l2 + 2 B1 B2 and
// (2 B1 B2)^2 = 4 l1 l2. In R^{4,1} the roots are real; a negative discriminant is the rounding
// of a double root.
inline void planeSquares(double s, double w2, double& l1, double& l2)
{
  const double disc = s * s - w2;
  if (!(disc > 0.0))
  {
    // A double root, possibly split into a complex pair by rounding.
    l1 = l2 = 0.5 * s;
    return;
  }
  const double r = __builtin_sqrt(disc);
  if (s >= 0.0)
  {
    l1 = 0.5 * (s + r);
    l2 = l1 != 0.0 ? 0.25 * w2 / l1 : 0.0;
  }
  else
  {
    l2 = 0.5 * (s - r);
    l1 = 0.25 * w2 / l2;
  }
}

// For one plane of square l = m^2 lh: c = cosh sqrt(l) (cos sqrt(-l) when l < 0) and
// sHat = m sinh(sqrt l)/sqrt(l) (m sin(sqrt -l)/sqrt(-l)), i.e. the sinh factor of the plane
// measured against the unit-scaled bivector B/m, so that a huge m does not overflow.
// With divideByCosh and a hyperbolic sqrt(l) above the threshold both are divided by cosh.
struct PlaneFunctions
{
  double c = 1.0;
  double sHat = 0.0;
};

/// x = m sqrt|lh| below which planeFunctions uses the power series.
constexpr double kPlaneSeriesLimit = 1e-2;

// Power series in l = +-x^2 of both functions (x < kPlaneSeriesLimit): the result does not jump
// at l = 0. Next term: l^5/10!.
inline void planeSeries(double m, double lh, double x, double& c, double& sHat)
{
  const double l = lh >= 0.0 ? x * x : -x * x;
  c = 1.0 + l / 2.0 * (1.0 + l / 12.0 * (1.0 + l / 30.0 * (1.0 + l / 56.0)));
  sHat = m * (1.0 + l / 6.0 * (1.0 + l / 20.0 * (1.0 + l / 42.0 * (1.0 + l / 72.0))));
}

// The same outside the series range (x >= kPlaneSeriesLimit), with r = sqrt|lh|.
inline void planeTranscendental(double lh, double r, double x, bool divideByCosh, double& c,
                                double& sHat)
{
  if (lh > 0.0)
  {
    if (divideByCosh && x > kScalingThreshold)
    {
      c = 1.0;
      sHat = tanh(x) / r;
    }
    else
    {
      c = cosh(x);
      sHat = sinh(x) / r;
    }
  }
  else
  {
    c = cos(x);
    sHat = sin(x) / r;
  }
}

inline PlaneFunctions planeFunctions(double m, double lh, bool divideByCosh)
{
  const double r = __builtin_sqrt(__builtin_fabs(lh));
  const double x = m * r;
  PlaneFunctions f;
  if (x < kPlaneSeriesLimit)
  {
    planeSeries(m, lh, x, f.c, f.sHat);
  }
  else
  {
    planeTranscendental(lh, r, x, divideByCosh, f.c, f.sHat);
  }
  return f;
}

inline double sinc(double x)
{
  return __builtin_fabs(x) < 1e-4 ? 1.0 - x * x / 6.0 : sin(x) / x;
}

// exp(B) = scalar + quadvector w + bivector u + bivectorW <w u>_2 for the unit-scaled u = B/m,
// w = u ^ u, outside the series range: the closed form of expExact (Exponential.h).
struct ExactCoefficients
{
  double scalar = 1.0, quadvector = 0.0, bivector = 0.0, bivectorW = 0.0;
};

inline ExactCoefficients exactCoefficients(double m, double l1, double l2, bool divideByCosh)
{
  const double largest = __builtin_fabs(l1) < __builtin_fabs(l2) ? __builtin_fabs(l2)
                                                                  : __builtin_fabs(l1);
  ExactCoefficients k;
  if (l1 - l2 >= 0.05 * largest || l1 > 0.0)
  {
    // Well separated squares: the divided differences are accurate as written.
    const PlaneFunctions f1 = planeFunctions(m, l1, divideByCosh);
    const PlaneFunctions f2 = planeFunctions(m, l2, divideByCosh);
    const double d = l1 - l2;
    k.scalar = f1.c * f2.c;
    k.quadvector = 0.5 * f1.sHat * f2.sHat;
    k.bivector = (l1 * f1.sHat * f2.c - l2 * f2.sHat * f1.c) / d;
    k.bivectorW = 0.5 * (f1.c * f2.sHat - f2.c * f1.sHat) / d;
    return k;
  }
  // Two rotations with nearly equal angles t1, t2 (both squares negative, at least one below -1):
  // b0 = (sinc(t1 + t2) + sinc(t1 - t2))/2, b4 = (sinc(t1 - t2) - sinc(t1 + t2))/(4 t1 t2).
  const double r1 = __builtin_sqrt(-l1), r2 = __builtin_sqrt(-l2);
  const double t1 = m * r1, t2 = m * r2;
  const double mSincSum = sin(t1 + t2) / (r1 + r2); // m sinc(t1 + t2)
  const double mSincDiff = m * sinc(t1 - t2);
  k.scalar = cos(t1) * cos(t2);
  k.quadvector = 0.5 * (sin(t1) / r1) * (sin(t2) / r2);
  k.bivector = 0.5 * (mSincSum + mSincDiff);
  k.bivectorW = 0.25 * (mSincDiff - mSincSum) / (r1 * r2);
  return k;
}

// Whether expExact takes the power series in B^2 = s + W (both squares of B at most 1 in size).
inline bool exactUsesSeries(double m, double l1, double l2)
{
  const double largest = __builtin_fabs(l1) < __builtin_fabs(l2) ? __builtin_fabs(l2)
                                                                  : __builtin_fabs(l1);
  return largest == 0.0 || m * largest * m <= 1.0;
}

// The power series of expExact: exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 with B^2k = ak + bk W,
// (ak+1, bk+1) = (s ak + (W W) bk, ak + s bk), s = <B B>_0. For |l1|, |l2| <= 1 the terms fall
// below 4^k/(2k)!, so 16 of them reach double precision.
// T is double, or the block kernel's vector of lanes (anything with +, * and / by a double).
template <typename T>
struct SeriesCoefficients
{
  T a0, a4, b0, b4;
};

template <typename T>
inline SeriesCoefficients<T> seriesCoefficients(T s, T w2)
{
  T alpha = T{} + 1.0, beta = T{};
  SeriesCoefficients<T> k{ T{}, T{}, T{}, T{} };
  double evenFactorial = 1.0; // 1/(2n)!
  for (int n = 0; n < 16; ++n)
  {
    const double oddFactorial = evenFactorial / (2 * n + 1); // 1/(2n+1)!
    k.a0 = k.a0 + alpha * evenFactorial;
    k.a4 = k.a4 + beta * evenFactorial;
    k.b0 = k.b0 + alpha * oddFactorial;
    k.b4 = k.b4 + beta * oddFactorial;
    const T nextAlpha = s * alpha + w2 * beta;
    beta = alpha + s * beta;
    alpha = nextAlpha;
    evenFactorial = oddFactorial / (2 * n + 2);
  }
  return k;
}
} // namespace
} // namespace detail
} // namespace cga
