#include "cga/surfaces/TorusKnot.h"

#include "cga/CompactConversion.h"
#include "cga/Conformal.h"

#include <cmath>
#include <numeric>

namespace cga
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

Vec3 unitNormal(const TorusKnot& knot)
{
  return normalized(knot.normal);
}

// The direction made orthogonal to the normal (zero when they are parallel).
Vec3 unitDirection(const TorusKnot& knot)
{
  const Vec3 n = unitNormal(knot);
  const Vec3 d = normalized(knot.direction);
  return normalized(d - dot(d, n) * n);
}
} // namespace

std::string TorusKnot::validate() const
{
  if (!isFinite(center) || !isFinite(normal) || !isFinite(direction) || !std::isfinite(radius))
  {
    return "the torus knot's parameters must be finite numbers (a NaN or an infinity was given)";
  }
  if (!(norm(normal) > 0.0))
  {
    return "KnotNormal must not be zero";
  }
  if (!(norm(direction) > 0.0))
  {
    return "KnotDirection must not be zero";
  }
  const Vec3 n = normalized(normal), d = normalized(direction);
  if (norm(d - dot(d, n) * n) < 1e-6)
  {
    return "KnotDirection must not be parallel to KnotNormal";
  }
  if (!(radius > 0.0) || !(radius < 1e150))
  {
    return "KnotRadius must be positive (and below 1e150)";
  }
  if (p < 1 || q < 1 || p > kMaximumWinding || q > kMaximumWinding)
  {
    return "KnotP and KnotQ must be integers from 1 to 1000";
  }
  return {};
}

int TorusKnot::commonDivisor() const
{
  return std::gcd(p, q);
}

TorusKnot::Circle TorusKnot::coreA() const
{
  const Vec3 u = unitDirection(*this);
  return { center - (radius / std::sqrt(2.0)) * u, unitNormal(*this), radius };
}

TorusKnot::Circle TorusKnot::coreC() const
{
  const Vec3 u = unitDirection(*this);
  return { center + (radius / std::sqrt(2.0)) * u, cross(unitNormal(*this), u), radius };
}

Bivector TorusKnot::rotationAbout(const Circle& circle)
{
  // The dual circle sigma ^ pi: sigma = up(c) - r^2/2 ni the dual sphere, pi = n + (n.c) ni the
  // dual plane; sigma.pi = 0 and sigma^2 = r^2, pi^2 = 1, so (sigma ^ pi)^2 = -r^2.
  const Multivector sigma = up(circle.center) - 0.5 * circle.radius * circle.radius * ni();
  const Multivector plane = vector(circle.normal) + dot(circle.normal, circle.center) * ni();
  // The order plane ^ sigma makes the knot link both counter-clockwise circles positively.
  return toBivector((plane ^ sigma) / circle.radius);
}

Orbit TorusKnot::orbit() const
{
  return Orbit((kPi / p) * rotationAbout(coreA()), (kPi / q) * rotationAbout(coreC()));
}

void circlePoints(const TorusKnot::Circle& circle, int count, Vec3* points)
{
  const Vec3 e = orthogonalUnit(circle.normal);
  const Vec3 f = cross(circle.normal, e);
  for (int i = 0; i < count; ++i)
  {
    const double a = 2.0 * kPi * i / count;
    points[i] = circle.center + circle.radius * (std::cos(a) * e + std::sin(a) * f);
  }
}
} // namespace cga
