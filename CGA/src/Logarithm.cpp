#include "cga/Logarithm.h"

#include "cga/CompactAlgebra.h"

#include "ExponentialScalars.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cga
{
namespace
{
// g = (angle of the plane)/sqrt|s| for a factor C + u with u^2 = s, C^2 = 1 + s: the rotation angle
// atan2(sqrt(-s), C) in [0, pi], or the rapidity asinh(sqrt s).
// False for a factor -1 or -exp(boost), which have no real logarithm of this form.
bool planeLogFactor(double s, double c, double& g)
{
  if (c > 0.0)
  {
    // q = s / C^2 is tanh^2 of the rapidity or -tan^2 of the angle; atanh(sqrt q)/sqrt q series.
    const double q = s / (c * c);
    if (std::fabs(q) < 1e-2)
    {
      double f = 0.0;
      for (int k = 8; k >= 0; --k)
      {
        f = 1.0 / (2 * k + 1) + q * f;
      }
      g = f / c;
    }
    else if (s > 0.0)
    {
      g = std::asinh(std::sqrt(s)) / std::sqrt(s);
    }
    else
    {
      g = std::atan2(std::sqrt(-s), c) / std::sqrt(-s);
    }
    return true;
  }
  if (!(s < 0.0))
  {
    return false;
  }
  g = std::atan2(std::sqrt(-s), c) / std::sqrt(-s);
  return true;
}

} // namespace

bool logVersor(const Even& k, Bivector& out, double versorTolerance)
{
  if (!k.isFinite())
  {
    return false;
  }
  const Even norm = k * reverse(k);
  const double size = k.maxAbs();
  const double roundoff = 64.0 * std::numeric_limits<double>::epsilon() * size * size;
  const double allowed = versorTolerance * norm.scalar + roundoff;
  if (!(norm.scalar > roundoff) || norm.quadvector.maxAbs() > allowed ||
      norm.bivector.maxAbs() > allowed)
  {
    return false;
  }
  const Even unit = k / std::sqrt(norm.scalar);
  const double a0 = unit.scalar;
  const Bivector& x = unit.bivector;
  const Quadvector& y = unit.quadvector;
  const double y2 = scalarSquare(y);
  const double sum = scalarSquare(x) - 2.0 * y2;
  const double prod = y2;
  // The squares s1 >= s2 of the two planes: the roots of s^2 - sum s + prod = 0.
  double s1 = 0.0, s2 = 0.0;
  detail::planeSquares(sum, 4.0 * prod, s1, s2);
  const double largest = std::max(std::fabs(s1), std::fabs(s2));

  double cX = 0.0, cXY = 0.0;
  if (a0 > 0.0 && largest <= 0.5)
  {
    // Both Ci > 0 and |si| <= 1/2: with E(s) = sum (-1)^n c_n s^n = asinh(sqrt s)/sqrt(s (1 + s)),
    // c_n = 4^n n!^2/(2n+1)!, and k(s) = s E(s): cX = a0 k[s1, s2], cXY = -(k[s1, s2] + E[s1, s2]).
    // The divided differences of s^(n+1) are the complete symmetric polynomials h_n(s1, s2),
    // h_n = sum h_(n-1) - prod h_(n-2). |h_n c_n| <= (n+1)/2^n: 64 terms reach double precision.
    double hPrevious = 0.0, h = 1.0, c = 1.0, sign = 1.0;
    double kDiff = 0.0, eDiff = 0.0;
    for (int n = 0; n < 64; ++n)
    {
      kDiff += sign * c * h;
      eDiff += sign * c * hPrevious;
      const double hNext = sum * h - prod * hPrevious;
      hPrevious = h;
      h = hNext;
      c *= (2.0 * n + 2.0) / (2.0 * n + 3.0);
      sign = -sign;
    }
    cX = a0 * kDiff;
    cXY = -(kDiff + eDiff);
  }
  else
  {
    // Plane 1 has the larger |Ci| and gets Ci > 0 (the branch choice); C1 C2 = <K>_0.
    const double c1 = std::sqrt(std::max(0.0, 1.0 + s1));
    const double c2 = c1 > 0.1 ? a0 / c1 : std::copysign(std::sqrt(std::max(0.0, 1.0 + s2)), a0);
    const double d = s1 - s2;
    if (a0 > 0.0 && s1 <= 0.0 && d < 0.05 * std::max(1.0, largest))
    {
      // Two rotations with nearly equal angles t1, t2 in (0, pi/2]; with sin ti = sqrt(-si):
      // cX = (sin t2 cos t1 / sinc(t2 - t1) + t1)/sin(t1 + t2),
      // cXY = (cos t1/(sin t1 sinc(t2 - t1)) - t2/(sin t1 sin t2))/sin(t1 + t2).
      const double sin1 = std::sqrt(-s1), sin2 = std::sqrt(-s2);
      const double t1 = std::atan2(sin1, c1), t2 = std::atan2(sin2, c2);
      const double sincDiff = detail::sinc(t2 - t1);
      const double sinSum = std::sin(t1 + t2);
      cX = (sin2 * c1 / sincDiff + t1) / sinSum;
      cXY = (c1 / (sin1 * sincDiff) - t2 / (sin1 * sin2)) / sinSum;
    }
    else
    {
      double g1 = 0.0, g2 = 0.0;
      if (!(d > 0.0) || !planeLogFactor(s1, c1, g1) || !planeLogFactor(s2, c2, g2))
      {
        return false;
      }
      cX = (g1 * s1 * c2 - g2 * s2 * c1) / d;
      cXY = (g2 * c2 - g1 * c1) / d;
    }
  }
  const Bivector result = cX * x + cXY * rightContraction(y, x);
  if (!result.isFinite())
  {
    return false;
  }
  out = result;
  return true;
}
} // namespace cga
