#include "cga/Exponential.h"

#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "ExponentialScalars.h"
#include "PointMapCore.h"

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
} // namespace

// Both rules are the templates of PointMapCore.h, instantiated for double: the block kernel
// computes K through the same source.
Even expPaper(const Bivector& b, ExpScaling scaling)
{
  if (!b.isFinite())
  {
    return nanEven();
  }
  Even k;
  k.bivector = b;
  core::paperExponential(k.bivector.c.data(), k.scalar, scaling == ExpScaling::AvoidOverflow);
  return k;
}

Even expExact(const Bivector& b, ExpScaling scaling)
{
  detail::EvenArray k;
  core::exactExponential(b.c.data(), scaling == ExpScaling::AvoidOverflow, k.data());
  return detail::unpack(k);
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
