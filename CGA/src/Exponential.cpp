#include "cga/Exponential.h"

#include "cga/CompactAlgebra.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cga
{
namespace
{
Even nanEven()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Even k;
  k.scalar = nan;
  k.bivector.c.fill(nan);
  k.quadvector.c.fill(nan);
  return k;
}

// The squares l1 >= l2 of the two commuting planes of a bivector with <B B>_0 = s and
// (B ^ B)^2 = w2: the roots of l^2 - s l + w2/4 = 0, since B^2 = l1 + l2 + 2 B1 B2 and
// (2 B1 B2)^2 = 4 l1 l2. In R^{4,1} the roots are real; a negative discriminant is the rounding
// of a double root.
void planeSquares(double s, double w2, double& l1, double& l2)
{
  const double disc = s * s - w2;
  if (!(disc > 0.0))
  {
    // A double root, possibly split into a complex pair by rounding.
    l1 = l2 = 0.5 * s;
    return;
  }
  const double r = std::sqrt(disc);
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

PlaneFunctions planeFunctions(double m, double lh, bool divideByCosh)
{
  const double r = std::sqrt(std::fabs(lh));
  const double x = m * r;
  PlaneFunctions f;
  if (x < 1e-2)
  {
    // Power series in l (both signs): the result does not jump at l = 0. Next term: l^5/10!.
    const double l = lh >= 0.0 ? x * x : -x * x;
    f.c = 1.0 + l / 2.0 * (1.0 + l / 12.0 * (1.0 + l / 30.0 * (1.0 + l / 56.0)));
    f.sHat = m * (1.0 + l / 6.0 * (1.0 + l / 20.0 * (1.0 + l / 42.0 * (1.0 + l / 72.0))));
  }
  else if (lh > 0.0)
  {
    if (divideByCosh && x > kExpScalingThreshold)
    {
      f.c = 1.0;
      f.sHat = std::tanh(x) / r;
    }
    else
    {
      f.c = std::cosh(x);
      f.sHat = std::sinh(x) / r;
    }
  }
  else
  {
    f.c = std::cos(x);
    f.sHat = std::sin(x) / r;
  }
  return f;
}

double sinc(double x)
{
  return std::fabs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x;
}

// exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 from the power series in B^2 = s + W: B^2k = ak + bk W
// with (ak+1, bk+1) = (s ak + (W W) bk, ak + s bk). For |l1|, |l2| <= 1 the terms fall below
// 4^k/(2k)!, so 16 of them reach double precision.
Even seriesExp(const Bivector& b)
{
  const double s = scalarSquare(b);
  const Quadvector w = wedge(b, b);
  const double w2 = scalarSquare(w);
  double alpha = 1.0, beta = 0.0;
  double a0 = 0.0, a4 = 0.0, b0 = 0.0, b4 = 0.0;
  double evenFactorial = 1.0; // 1/(2k)!
  for (int k = 0; k < 16; ++k)
  {
    const double oddFactorial = evenFactorial / (2 * k + 1); // 1/(2k+1)!
    a0 += alpha * evenFactorial;
    a4 += beta * evenFactorial;
    b0 += alpha * oddFactorial;
    b4 += beta * oddFactorial;
    const double nextAlpha = s * alpha + w2 * beta;
    beta = alpha + s * beta;
    alpha = nextAlpha;
    evenFactorial = oddFactorial / (2 * k + 2);
  }
  Even k;
  k.scalar = a0;
  k.quadvector = a4 * w;
  k.bivector = b0 * b + b4 * rightContraction(w, b);
  return k;
}
} // namespace

Even expPaper(const Bivector& b, ExpScaling scaling)
{
  const double m = b.maxAbs();
  if (!std::isfinite(m))
  {
    return nanEven();
  }
  if (m == 0.0)
  {
    return Even::identity();
  }
  const Bivector unit = b / m;
  const PlaneFunctions f =
    planeFunctions(m, scalarSquare(unit), scaling == ExpScaling::AvoidOverflow);
  Even k;
  k.scalar = f.c;
  k.bivector = f.sHat * unit;
  return k;
}

Even expExact(const Bivector& b, ExpScaling scaling)
{
  const double m = b.maxAbs();
  if (!std::isfinite(m))
  {
    return nanEven();
  }
  if (m == 0.0)
  {
    return Even::identity();
  }
  // Invariants of the unit-scaled u = B/m: squares of B are m^2 times those of u.
  const Bivector u = b / m;
  const Quadvector w = wedge(u, u);
  double l1 = 0.0, l2 = 0.0;
  planeSquares(scalarSquare(u), scalarSquare(w), l1, l2);
  const double largest = std::max(std::fabs(l1), std::fabs(l2));
  if (largest == 0.0 || m * largest * m <= 1.0)
  {
    return seriesExp(b);
  }

  // In terms of u: exp(B) = a0 + a4' w + b0' u + b4' <w u>_2 with the primed coefficients carrying
  // the powers of m (a4 W = a4 m^2 w, ...), which planeFunctions' sHat = m S absorbs.
  const Bivector wu = rightContraction(w, u);
  const bool avoidOverflow = scaling == ExpScaling::AvoidOverflow;
  Even k;
  if (l1 - l2 >= 0.05 * largest || l1 > 0.0)
  {
    // Well separated squares: the divided differences are accurate as written.
    const PlaneFunctions f1 = planeFunctions(m, l1, avoidOverflow);
    const PlaneFunctions f2 = planeFunctions(m, l2, avoidOverflow);
    const double d = l1 - l2;
    k.scalar = f1.c * f2.c;
    k.quadvector = (0.5 * f1.sHat * f2.sHat) * w;
    k.bivector = ((l1 * f1.sHat * f2.c - l2 * f2.sHat * f1.c) / d) * u +
      (0.5 * (f1.c * f2.sHat - f2.c * f1.sHat) / d) * wu;
    return k;
  }
  // Two rotations with nearly equal angles t1, t2 (both squares negative, at least one below -1):
  // b0 = (sinc(t1 + t2) + sinc(t1 - t2))/2, b4 = (sinc(t1 - t2) - sinc(t1 + t2))/(4 t1 t2).
  const double r1 = std::sqrt(-l1), r2 = std::sqrt(-l2);
  const double t1 = m * r1, t2 = m * r2;
  const double mSincSum = std::sin(t1 + t2) / (r1 + r2); // m sinc(t1 + t2)
  const double mSincDiff = m * sinc(t1 - t2);
  k.scalar = std::cos(t1) * std::cos(t2);
  k.quadvector = (0.5 * (std::sin(t1) / r1) * (std::sin(t2) / r2)) * w;
  k.bivector =
    (0.5 * (mSincSum + mSincDiff)) * u + (0.25 * (mSincDiff - mSincSum) / (r1 * r2)) * wu;
  return k;
}

bool invariantDecomposition(const Bivector& b, InvariantDecomposition& out)
{
  if (!b.isFinite())
  {
    return false;
  }
  const Quadvector w = wedge(b, b);
  double l1 = 0.0, l2 = 0.0;
  planeSquares(scalarSquare(b), scalarSquare(w), l1, l2);
  const double d = l1 - l2;
  if (w.maxAbs() == 0.0 && !(d > 0.0))
  {
    // A null 2-blade: one plane, square 0.
    out.first = b;
    out.second = Bivector();
    out.firstSquare = out.secondSquare = 0.0;
    return true;
  }
  if (!(d > 0.0))
  {
    return false;
  }
  // W B = 2 B1 B2 (B1 + B2) = 2 (l1 B2 + l2 B1), so B1 = (l1 B - W B / 2)/(l1 - l2).
  const Bivector halfWB = 0.5 * rightContraction(w, b);
  out.first = (l1 * b - halfWB) / d;
  out.second = (halfWB - l2 * b) / d;
  out.firstSquare = l1;
  out.secondSquare = l2;
  return true;
}

Multivector expSeries(const Multivector& b)
{
  double n = b.coefficientNorm();
  if (!std::isfinite(n))
  {
    Multivector r;
    r.c.fill(std::numeric_limits<double>::quiet_NaN());
    return r;
  }
  Multivector x = b;
  int squarings = 0;
  while (n > 1.0 / 16.0)
  {
    x *= 0.5;
    n *= 0.5;
    ++squarings;
  }
  Multivector sum = Multivector::scalar(1.0);
  Multivector term = sum;
  for (int i = 1; i <= 60; ++i)
  {
    term = term * x / static_cast<double>(i);
    sum += term;
    if (term.coefficientNorm() < 1e-19 * sum.coefficientNorm())
    {
      break;
    }
  }
  for (; squarings > 0; --squarings)
  {
    sum = sum * sum;
  }
  return sum;
}
} // namespace cga
