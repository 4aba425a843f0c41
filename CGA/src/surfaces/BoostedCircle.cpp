#include "cga/surfaces/BoostedCircle.h"

#include "cga/Conformal.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <cmath>
#include <sstream>

namespace cga
{
std::string BoostedCircle::validate() const
{
  if (!isFinite(center) || !isFinite(normal) || !std::isfinite(radius) ||
    !isFinite(boostLocation) || !isFinite(boostDirection))
  {
    return "parameters must be finite numbers (a NaN or an infinity was given)";
  }
  if (!(norm(normal) > 0.0))
  {
    return "the circle normal must not be the zero vector";
  }
  if (!(radius > 0.0))
  {
    return "the circle radius must be positive";
  }
  if (!(norm(boostDirection) > 0.0))
  {
    return "the boost direction must not be the zero vector";
  }
  return {};
}

BoostedCircle BoostedCircle::centered() const
{
  BoostedCircle family = *this;
  family.center = Vec3{};
  family.boostLocation = boostLocation - center;
  return family;
}

std::string BoostedCircle::boostProblem(double lambdaMin, double lambdaMax) const
{
  // The map's entries are sums of products of 1 and lambda tau's components, so they are largest
  // (and overflow first) at the ends of the range.
  for (const double lambda : { lambdaMin, lambdaMax })
  {
    const PointMap map(this->boostCompact(lambda)); // named: a temporary's matrix() would dangle
    for (const double entry : map.matrix())
    {
      if (!std::isfinite(entry))
      {
        std::ostringstream message;
        message << "the boost overflows at lambda = " << lambda << ": |lambda| times the boost "
                << "direction's length " << norm(boostDirection)
                << " (its weight) is too large; shorten the boost direction or the lambda range";
        return message.str();
      }
    }
  }
  return {};
}

void BoostedCircle::planeFrame(Vec3& a, Vec3& b) const
{
  const Vec3 n = normalized(normal);
  a = orthogonalUnit(n);
  b = cross(n, a);
}

Vec3 BoostedCircle::circlePoint(double theta) const
{
  Vec3 a, b;
  this->planeFrame(a, b);
  return center + radius * (std::cos(theta) * a + std::sin(theta) * b);
}

Multivector BoostedCircle::boost(double lambda) const
{
  return Multivector::scalar(1.0) + lambda * nullPointPair(boostLocation, boostDirection);
}

Even BoostedCircle::boostCompact(double lambda) const
{
  // exp(lambda tau) = 1 + lambda tau exactly, tau^2 = 0. Not expExact: tau's components are
  // rounded, so its computed square is about eps instead of 0 and the series adds terms of size
  // lambda^2 eps (1e-13 relative at |lambda| = 10 about a point away from the origin).
  Even k = Even::fromBivector(lambda * nullPointPairCompact(boostLocation, boostDirection));
  k.scalar = 1.0;
  return k;
}

Multivector BoostedCircle::imageBlade(double lambda) const
{
  return sandwich(this->boost(lambda), circle(center, normal, radius));
}
} // namespace cga
