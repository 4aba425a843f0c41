#include "cga/surfaces/BoostedCircle.h"

#include "cga/Conformal.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "../ConformalLanes.h"
#include "../ForceInline.h"
#include "../LaneClones.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// compute<false> and surfaceNormal (scaledFirst's common case: squared lengths within
// [2^-200, 2^200]) on eight samples, in their operations and order (ConformalLanes.h: times' sums
// from 0 are conformalProduct's, normalizePoint is normalizedLanes); a lane outside that range
// takes surfaceNormal itself.
BOOSTED_LANE_CLONES
void BoostedCircleRow::pointsAndNormals(const BoostedCircle::CircleSample* samples,
  std::size_t count, Vec3* points, Vec3* normals, unsigned char* state) const
{
  using detail::Eight;
  constexpr int L = 8, C = ConformalVector::Count;
  constexpr int NO = ConformalVector::NO, E1 = ConformalVector::E1, NI = ConformalVector::NI;
  const std::array<double, 25>& boost = this->BoostColumns;
  const std::array<double, 25>& commutator = this->CommutatorColumns;
  auto boostEntry = [&boost](int i, int j) { return boost[static_cast<std::size_t>(j * C + i)]; };
  auto commutatorEntry = [&commutator](
                           int i, int j) { return commutator[static_cast<std::size_t>(j * C + i)]; };
  for (std::size_t first = 0; first < count; first += L)
  {
    const int lanes = static_cast<int>(std::min<std::size_t>(L, count - first));
    // The samples' points and tangents by component (a partial block repeats its last sample).
    alignas(64) double in[2][3][L];
    for (int l = 0; l < L; ++l)
    {
      const BoostedCircle::CircleSample& s =
        samples[first + static_cast<std::size_t>(std::min(l, lanes - 1))];
      const Vec3 from[2] = { s.point, s.tangent };
      for (int v = 0; v < 2; ++v)
      {
        in[v][0][l] = from[v].x;
        in[v][1][l] = from[v].y;
        in[v][2][l] = from[v].z;
      }
    }
    Eight p[3], t[3];
    std::memcpy(p, in[0], sizeof p);
    std::memcpy(t, in[1], sizeof t);
    Eight x[C], xTheta[C];
    x[NO] = Eight{} + 1.0;
    xTheta[NO] = Eight{};
    for (int k = 0; k < 3; ++k)
    {
      x[E1 + k] = p[k];
      xTheta[E1 + k] = t[k];
    }
    x[NI] = 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    xTheta[NI] = p[0] * t[0] + p[1] * t[1] + p[2] * t[2];
    Eight y[C], yU[C], yV[C];
    detail::conformalProduct(boostEntry, x, y);
    Eight point[3];
    const auto mapped = detail::normalizedLanes(y, point);
    detail::conformalProduct(boostEntry, xTheta, yU);
    detail::conformalProduct(commutatorEntry, y, yV);
    const Eight inverseW = 1.0 / y[NO];
    Eight du[3], dv[3];
    for (int k = 0; k < 3; ++k)
    {
      du[k] = (yU[E1 + k] - yU[NO] * point[k]) * inverseW;
      dv[k] = (yV[E1 + k] - yV[NO] * point[k]) * inverseW;
    }
    const Eight uu = du[0] * du[0] + du[1] * du[1] + du[2] * du[2];
    const Eight vv = dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2];
    const Eight larger = uu < vv ? vv : uu; // std::max(uu, vv)
    const auto inRange = (larger >= 0x1p-200) & (larger <= 0x1p200);
    const Eight area[3] = { du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
      du[0] * dv[1] - du[1] * dv[0] };
    const Eight areaSquared = area[0] * area[0] + area[1] * area[1] + area[2] * area[2];
    const auto regular = areaSquared > 1e-24 * larger * larger;
    const Eight scale = 1.0 / detail::squareRoot(areaSquared);
    for (int l = 0; l < lanes; ++l)
    {
      const std::size_t i = first + static_cast<std::size_t>(l);
      if (!mapped[l])
      {
        state[i] = 0;
        continue;
      }
      points[i] = { point[0][l], point[1][l], point[2][l] };
      bool normal = regular[l] != 0;
      if (inRange[l])
      {
        if (normal)
        {
          normals[i] = { area[0][l] * scale[l], area[1][l] * scale[l], area[2][l] * scale[l] };
        }
      }
      else
      {
        normal = surfaceNormal(
          { du[0][l], du[1][l], du[2][l] }, { dv[0][l], dv[1][l], dv[2][l] }, normals[i]);
      }
      state[i] = normal ? 2 : 1;
    }
  }
}
} // namespace cga
