#include "cga/surfaces/BoostedCircle.h"

#include "cga/Conformal.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "../ForceInline.h"

#include <cmath>
#include <sstream>

namespace cga
{
namespace
{
// applyMatrix inlined, on the transposed matrix: each entry of the result is the same sum in the
// same order (so the same bits), the five of them side by side in vector registers, and without a
// call and its result in memory per product (the derivatives take six of them per sample).
BOOSTED_FORCE_INLINE ConformalVector times(const std::array<double, 25>& columns, const ConformalVector& x)
{
  constexpr int n = ConformalVector::Count;
  ConformalVector r;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      r[i] += columns[j * n + i] * x[j];
    }
  }
  return r;
}

std::array<double, 25> transposed(const std::array<double, 25>& m)
{
  constexpr int n = ConformalVector::Count;
  std::array<double, 25> t{};
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      t[j * n + i] = m[i * n + j];
    }
  }
  return t;
}
} // namespace

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
  return this->circleSample(theta).point;
}

BoostedCircle::CircleSample BoostedCircle::circleSample(double theta) const
{
  Vec3 a, b;
  this->planeFrame(a, b);
  const double c = std::cos(theta), s = std::sin(theta);
  const Vec3 offset = c * a + s * b;
  return { center + radius * offset, radius * (c * b - s * a), -radius * offset };
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

BoostedCircleRow::BoostedCircleRow(const BoostedCircle& family, double lambda)
  : Boost(family.boostCompact(lambda))
  , BoostColumns(transposed(Boost.matrix()))
  , CommutatorColumns(transposed(
      commutatorMatrix(nullPointPairCompact(family.boostLocation, family.boostDirection))))
{
}

bool BoostedCircleRow::derivatives(
  const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const
{
  return this->compute<true>(sample, out);
}

bool BoostedCircleRow::firstDerivatives(
  const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const
{
  return this->compute<false>(sample, out);
}

template <bool Second>
bool BoostedCircleRow::compute(
  const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const
{
  const Vec3 p = sample.point, pTheta = sample.tangent, pThetaTheta = sample.second;
  // up(p) = no + p + |p|^2/2 ni and its derivatives in theta.
  const std::array<double, 25>& boost = this->BoostColumns;
  const ConformalVector y = times(boost, ConformalVector::point(p));
  Vec3 point;
  if (!normalizePoint(y, point))
  {
    return false;
  }
  ConformalVector xTheta;
  xTheta.c = { 0.0, pTheta.x, pTheta.y, pTheta.z, dot(p, pTheta) };
  // The image's derivatives: Y_lambda = C Y, Y_lambda lambda = C C Y, Y_theta lambda = C Y_theta.
  const ConformalVector yU = times(boost, xTheta);
  const ConformalVector yV = times(this->CommutatorColumns, y);
  // fn: x = e / w with e the Euclidean part and w = Y_no; e = x w differentiated. One division:
  // the derivatives are multiplied by 1 / w (within an ulp of dividing, five vectors a sample).
  const double inverseW = 1.0 / y.weight();
  const Vec3 xU = (yU.euclidean() - yU.weight() * point) * inverseW;
  const Vec3 xV = (yV.euclidean() - yV.weight() * point) * inverseW;
  out.point = point;
  out.du = xU;
  out.dv = xV;
  if (Second)
  {
    ConformalVector xThetaTheta;
    xThetaTheta.c = { 0.0, pThetaTheta.x, pThetaTheta.y, pThetaTheta.z,
      dot(pTheta, pTheta) + dot(p, pThetaTheta) };
    const ConformalVector yUU = times(boost, xThetaTheta);
    const ConformalVector yVV = times(this->CommutatorColumns, yV);
    const ConformalVector yUV = times(this->CommutatorColumns, yU);
    out.duu = (yUU.euclidean() - 2.0 * yU.weight() * xU - yUU.weight() * point) * inverseW;
    out.duv =
      (yUV.euclidean() - yU.weight() * xV - yV.weight() * xU - yUV.weight() * point) * inverseW;
    out.dvv = (yVV.euclidean() - 2.0 * yV.weight() * xV - yVV.weight() * point) * inverseW;
  }
  return true;
}
} // namespace cga
