#include "cga/surfaces/BoostedCircle.h"

#include "cga/Conformal.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "../ConformalLanes.h"
#include "../ForceInline.h"
#include "../LaneClones.h"
#include "../SurfaceCurvatureSteps.h"

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

namespace
{
using detail::Eight;
using detail::EightMask;
constexpr int kLanes = 8;

// dot and cross (Vec3.h) on eight lanes, in their order of operations.
BOOSTED_LANE_INLINE Eight dotLanes(const Eight* a, const Eight* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

BOOSTED_LANE_INLINE void crossLanes(const Eight* a, const Eight* b, Eight* r)
{
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

// compute<Second>'s results on eight samples.
struct DerivativeLanes
{
  Eight point[3], du[3], dv[3], duu[3], duv[3], dvv[3];
};

// compute<Second> on the samples first .. first + lanes - 1 (a partial block repeats its last
// sample), in its operations and order (ConformalLanes.h: times' sums from 0 are
// conformalProduct's, normalizePoint is normalizedLanes): all ones where it is true.
template <bool Second>
BOOSTED_LANE_INLINE EightMask derivativeLanes(const std::array<double, 25>& boost,
  const std::array<double, 25>& commutator, const BoostedCircle::CircleSample* samples, int lanes,
  DerivativeLanes& d)
{
  constexpr int C = ConformalVector::Count;
  constexpr int NO = ConformalVector::NO, E1 = ConformalVector::E1, NI = ConformalVector::NI;
  auto boostEntry = [&boost](int i, int j) { return boost[static_cast<std::size_t>(j * C + i)]; };
  auto commutatorEntry = [&commutator](
                           int i, int j) { return commutator[static_cast<std::size_t>(j * C + i)]; };
  // The samples' points, tangents and second derivatives by component.
  alignas(64) double in[3][3][kLanes];
  for (int l = 0; l < kLanes; ++l)
  {
    const BoostedCircle::CircleSample& s = samples[std::min(l, lanes - 1)];
    const Vec3 from[3] = { s.point, s.tangent, s.second };
    for (int v = 0; v < 3; ++v)
    {
      in[v][0][l] = from[v].x;
      in[v][1][l] = from[v].y;
      in[v][2][l] = from[v].z;
    }
  }
  Eight p[3], t[3], tt[3];
  std::memcpy(p, in[0], sizeof p);
  std::memcpy(t, in[1], sizeof t);
  std::memcpy(tt, in[2], sizeof tt);
  Eight x[C], xTheta[C];
  x[NO] = Eight{} + 1.0;
  xTheta[NO] = Eight{};
  for (int k = 0; k < 3; ++k)
  {
    x[E1 + k] = p[k];
    xTheta[E1 + k] = t[k];
  }
  x[NI] = 0.5 * dotLanes(p, p);
  xTheta[NI] = dotLanes(p, t);
  Eight y[C], yU[C], yV[C];
  detail::conformalProduct(boostEntry, x, y);
  const EightMask mapped = detail::normalizedLanes(y, d.point);
  detail::conformalProduct(boostEntry, xTheta, yU);
  detail::conformalProduct(commutatorEntry, y, yV);
  const Eight inverseW = 1.0 / y[NO];
  for (int k = 0; k < 3; ++k)
  {
    d.du[k] = (yU[E1 + k] - yU[NO] * d.point[k]) * inverseW;
    d.dv[k] = (yV[E1 + k] - yV[NO] * d.point[k]) * inverseW;
  }
  if (Second)
  {
    Eight xThetaTheta[C];
    xThetaTheta[NO] = Eight{};
    for (int k = 0; k < 3; ++k)
    {
      xThetaTheta[E1 + k] = tt[k];
    }
    xThetaTheta[NI] = dotLanes(t, t) + dotLanes(p, tt);
    Eight yUU[C], yVV[C], yUV[C];
    detail::conformalProduct(boostEntry, xThetaTheta, yUU);
    detail::conformalProduct(commutatorEntry, yV, yVV);
    detail::conformalProduct(commutatorEntry, yU, yUV);
    for (int k = 0; k < 3; ++k)
    {
      d.duu[k] = ((yUU[E1 + k] - (2.0 * yU[NO]) * d.du[k]) - yUU[NO] * d.point[k]) * inverseW;
      d.duv[k] = (((yUV[E1 + k] - yU[NO] * d.dv[k]) - yV[NO] * d.du[k]) - yUV[NO] * d.point[k]) *
        inverseW;
      d.dvv[k] = ((yVV[E1 + k] - (2.0 * yV[NO]) * d.dv[k]) - yVV[NO] * d.point[k]) * inverseW;
    }
  }
  return mapped;
}

// scaledFirst's common case on eight lanes: where `inRange` (the larger squared length in
// [2^-200, 2^200]; elsewhere scaledFirst rescales) it is true exactly where `regular`, with
// this unit normal.
struct FirstFormLanes
{
  Eight lengthU2, larger, normal[3];
  EightMask inRange, regular;
};

BOOSTED_LANE_INLINE void firstFormLanes(const Eight* du, const Eight* dv, FirstFormLanes& f)
{
  f.lengthU2 = dotLanes(du, du);
  const Eight vv = dotLanes(dv, dv);
  f.larger = f.lengthU2 < vv ? vv : f.lengthU2; // std::max(uu, vv)
  f.inRange = (f.larger >= 0x1p-200) & (f.larger <= 0x1p200);
  Eight area[3];
  crossLanes(du, dv, area);
  const Eight areaSquared = dotLanes(area, area);
  f.regular = areaSquared > 1e-24 * f.larger * f.larger;
  const Eight scale = 1.0 / detail::squareRoot(areaSquared);
  for (int k = 0; k < 3; ++k)
  {
    f.normal[k] = area[k] * scale;
  }
}

Vec3 laneOf(const Eight* v, int l)
{
  return { v[0][l], v[1][l], v[2][l] };
}
} // namespace

// compute<false> and surfaceNormal on eight samples at a time; a lane outside scaledFirst's
// common range takes surfaceNormal itself.
BOOSTED_LANE_CLONES
void BoostedCircleRow::pointsAndNormals(const BoostedCircle::CircleSample* samples,
  std::size_t count, Vec3* points, Vec3* normals, unsigned char* state) const
{
  for (std::size_t first = 0; first < count; first += kLanes)
  {
    const int lanes = static_cast<int>(std::min<std::size_t>(kLanes, count - first));
    DerivativeLanes d;
    const EightMask mapped = derivativeLanes<false>(
      this->BoostColumns, this->CommutatorColumns, samples + first, lanes, d);
    FirstFormLanes f;
    firstFormLanes(d.du, d.dv, f);
    for (int l = 0; l < lanes; ++l)
    {
      const std::size_t i = first + static_cast<std::size_t>(l);
      if (!mapped[l])
      {
        state[i] = 0;
        continue;
      }
      points[i] = laneOf(d.point, l);
      bool normal = f.regular[l] != 0;
      if (!f.inRange[l])
      {
        normal = surfaceNormal(laneOf(d.du, l), laneOf(d.dv, l), normals[i]);
      }
      else if (normal)
      {
        normals[i] = laneOf(f.normal, l);
      }
      state[i] = normal ? 2 : 1;
    }
  }
}

// compute<true> and surfaceCurvature on eight samples at a time, in their operations and order
// where surfaceCurvature takes its common path (no rescaling of the first or second derivatives,
// the eigenvalues' radius without hypot, finite curvatures; its principalDirections per lane);
// another lane takes surfaceCurvature itself.
BOOSTED_LANE_CLONES
void BoostedCircleRow::curvatures(const BoostedCircle::CircleSample* samples, std::size_t count,
  Vec3* points, SurfaceCurvature* out, bool* mapped) const
{
  for (std::size_t first = 0; first < count; first += kLanes)
  {
    const int lanes = static_cast<int>(std::min<std::size_t>(kLanes, count - first));
    DerivativeLanes d;
    const EightMask imaged = derivativeLanes<true>(
      this->BoostColumns, this->CommutatorColumns, samples + first, lanes, d);
    FirstFormLanes f;
    firstFormLanes(d.du, d.dv, f);
    // The second derivatives: finite, and their largest component 0 or in [2^-100, 2^100]
    // (scaleExponent 0: no rescaling). Outside, surfaceCurvature rescales them by a power of two,
    // which is exact: its bits could differ from these only where a product here is subnormal,
    // but the lane takes surfaceCurvature itself.
    Eight second = Eight{};
    EightMask finiteSecond = Eight{} == Eight{}; // all ones
    for (const Eight* v : { d.duu, d.duv, d.dvv })
    {
      for (int k = 0; k < 3; ++k)
      {
        finiteSecond &= detail::finiteLanes(v[k]);
        const Eight size = detail::magnitude(v[k]);
        second = second < size ? size : second;
      }
    }
    const EightMask unscaled = (second == 0.0) | ((second >= 0x1p-100) & (second <= 0x1p100));
    const Eight* n = f.normal;
    const Eight lengthU = detail::squareRoot(f.lengthU2);
    Eight t1[3];
    for (int k = 0; k < 3; ++k)
    {
      t1[k] = d.du[k] / lengthU;
    }
    Eight t2[3];
    crossLanes(n, t1, t2);
    const Eight alpha = lengthU, beta = dotLanes(d.dv, t1), gamma = dotLanes(d.dv, t2);
    const Eight l = -dotLanes(d.duu, n), m = -dotLanes(d.duv, n), nn = -dotLanes(d.dvv, n);
    const Eight w11 = l / (alpha * alpha);
    const Eight w12 = (m * alpha - l * beta) / (alpha * alpha * gamma);
    const Eight w22 = (l * beta * beta - 2.0 * m * alpha * beta + nn * alpha * alpha) /
      (alpha * alpha * gamma * gamma);
    const Eight half = 0.5 * (w11 - w22);
    const Eight halfSize = detail::magnitude(half), w12Size = detail::magnitude(w12);
    const Eight largerOfTwo = halfSize < w12Size ? w12Size : halfSize;
    // radiusOf's square root (its other case, hypot, is surfaceCurvature's own).
    const EightMask plainRadius =
      ((largerOfTwo >= 0x1p-450) | (largerOfTwo == 0.0)) & (largerOfTwo <= 0x1p450);
    const Eight radius = detail::squareRoot(half * half + w12 * w12);
    const Eight center = 0.5 * (w11 + w22);
    const Eight k1 = center + radius, k2 = center - radius;
    const Eight gaussian = k1 * k2;
    const EightMask common = f.inRange & f.regular & finiteSecond & unscaled & plainRadius &
      detail::finiteLanes(k1) & detail::finiteLanes(k2) & detail::finiteLanes(gaussian);
    for (int lane = 0; lane < lanes; ++lane)
    {
      const std::size_t i = first + static_cast<std::size_t>(lane);
      mapped[i] = imaged[lane] != 0;
      if (!mapped[i])
      {
        continue;
      }
      points[i] = laneOf(d.point, lane);
      if (!common[lane])
      {
        SurfaceDerivatives x;
        x.point = points[i];
        x.du = laneOf(d.du, lane);
        x.dv = laneOf(d.dv, lane);
        x.duu = laneOf(d.duu, lane);
        x.duv = laneOf(d.duv, lane);
        x.dvv = laneOf(d.dvv, lane);
        out[i] = surfaceCurvature(x);
        continue;
      }
      SurfaceCurvature& c = out[i];
      c.regular = true;
      c.normal = laneOf(n, lane);
      c.k1 = k1[lane];
      c.k2 = k2[lane];
      principalDirections(c.normal, laneOf(t1, lane), laneOf(t2, lane), w11[lane], w12[lane],
        w22[lane], half[lane], radius[lane], c.direction1, c.direction2);
      c.gaussian = gaussian[lane];
      c.mean = center[lane];
    }
  }
}
} // namespace cga
