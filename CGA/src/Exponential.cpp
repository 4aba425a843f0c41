#include "cga/Exponential.h"

#include "cga/CompactAlgebra.h"

#include "ExponentialScalars.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cga
{
static_assert(detail::kScalingThreshold == kExpScalingThreshold, "one scaling threshold");

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

// exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 from the power series in B^2 = s + W
// (detail::seriesCoefficients).
Even seriesExp(const Bivector& b)
{
  const Quadvector w = wedge(b, b);
  const detail::SeriesCoefficients<double> c =
    detail::seriesCoefficients(scalarSquare(b), scalarSquare(w));
  Even k;
  k.scalar = c.a0;
  k.quadvector = c.a4 * w;
  k.bivector = c.b0 * b + c.b4 * rightContraction(w, b);
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
  const detail::PlaneFunctions f =
    detail::planeFunctions(m, scalarSquare(unit), scaling == ExpScaling::AvoidOverflow);
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
  detail::planeSquares(scalarSquare(u), scalarSquare(w), l1, l2);
  if (detail::exactUsesSeries(m, l1, l2))
  {
    return seriesExp(b);
  }
  // In terms of u: exp(B) = a0 + a4' w + b0' u + b4' <w u>_2 with the primed coefficients carrying
  // the powers of m (a4 W = a4 m^2 w, ...), which planeFunctions' sHat = m S absorbs.
  const detail::ExactCoefficients c =
    detail::exactCoefficients(m, l1, l2, scaling == ExpScaling::AvoidOverflow);
  Even k;
  k.scalar = c.scalar;
  k.quadvector = c.quadvector * w;
  k.bivector = c.bivector * u + c.bivectorW * rightContraction(w, u);
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
  detail::planeSquares(scalarSquare(b), scalarSquare(w), l1, l2);
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
