#include "cga/surfaces/HopfFibration.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/Logarithm.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "../ConformalLanes.h"
#include "../LaneClones.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace cga
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
// Relative weight below which an image point counts as the point at infinity (about 1e7 units
// from the origin for the unit circle: far beyond any useful clip radius).
constexpr double kInfinityWeight = 1e-13;

// fiberPoints' loop over the circle's points, eight at a time (ConformalLanes.h), with the
// operations of the one-point code in its order (up(x), applyMatrix's sums from 0, maxAbs,
// normalizePoint's divisions, the frame's sums): the same bits. Points sent to infinity (or not
// finite) are NaN.
BOOSTED_LANE_CLONES
void circleImages(const std::array<double, 25>& matrix, const Vec3* circle, std::size_t count,
  Vec3 center, double radius, Vec3 a, Vec3 b, Vec3 n, Vec3* out)
{
  using detail::Eight;
  constexpr int L = 8, C = ConformalVector::Count;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t first = 0; first < count; first += L)
  {
    const int lanes = static_cast<int>(std::min<std::size_t>(L, count - first));
    alignas(64) double xyz[3][L];
    for (int l = 0; l < L; ++l)
    {
      const Vec3& p = circle[first + static_cast<std::size_t>(std::min(l, lanes - 1))];
      xyz[0][l] = p.x;
      xyz[1][l] = p.y;
      xyz[2][l] = p.z;
    }
    Eight x[C];
    std::memcpy(&x[ConformalVector::E1], xyz, sizeof xyz);
    x[ConformalVector::NO] = Eight{} + 1.0;
    const Eight& px = x[ConformalVector::E1];
    const Eight& py = x[ConformalVector::E2];
    const Eight& pz = x[ConformalVector::E3];
    x[ConformalVector::NI] = 0.5 * (px * px + py * py + pz * pz);
    Eight r[C];
    detail::conformalProduct(
      [&matrix](int i, int j) { return matrix[static_cast<std::size_t>(i * C + j)]; }, x, r);
    Eight largest = Eight{};
    for (int i = 0; i < C; ++i)
    {
      const Eight magnitude = detail::magnitude(r[i]);
      largest = (magnitude > largest) | (magnitude != magnitude) ? magnitude : largest;
    }
    Eight p[3];
    const auto kept = (detail::magnitude(r[ConformalVector::NO]) > kInfinityWeight * largest) &
      detail::normalizedLanes(r, p);
    const double frame[3][3] = { { a.x, b.x, n.x }, { a.y, b.y, n.y }, { a.z, b.z, n.z } };
    const double origin[3] = { center.x, center.y, center.z };
    Eight world[3];
    for (int k = 0; k < 3; ++k)
    {
      world[k] = origin[k] + radius * (p[0] * frame[k][0] + p[1] * frame[k][1] + p[2] * frame[k][2]);
    }
    for (int l = 0; l < lanes; ++l)
    {
      Vec3& o = out[first + static_cast<std::size_t>(l)];
      o = kept[l] ? Vec3{ world[0][l], world[1][l], world[2][l] } : Vec3{ nan, nan, nan };
    }
  }
}

Vec3 boostDirection(double theta)
{
  return { std::cos(theta), std::sin(theta), 0.0 };
}

/// A dual line scaled to L^2 = -1.
Multivector unitDualLine(Vec3 point, Vec3 direction)
{
  const Multivector l = dualLine(point, direction);
  return l / std::sqrt(-scalarProduct(l, l));
}

// The bivectors of the classical closed form.
Multivector e12()
{
  return Multivector::basisBlade(blade::e1 | blade::e2);
}
Multivector classicalPlanes()
{
  // e1^e3 - e2^e+
  return Multivector::basisBlade(blade::e1 | blade::e3) -
    Multivector::basisBlade(blade::e2 | blade::ep);
}

/// exp(a U) of a unit 2-blade U, U^2 = -1: cos a + sin a U (expPaper is exact on a 2-blade).
Even rotation(const Bivector& unitPlane, double angle)
{
  return expPaper(angle * unitPlane);
}
} // namespace

std::string HopfFibration::validate() const
{
  if (!isFinite(center) || !isFinite(normal) || !std::isfinite(radius))
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
  return {};
}

void HopfFibration::worldFrame(Vec3& a, Vec3& b, Vec3& n) const
{
  n = normalized(normal);
  a = orthogonalUnit(n);
  b = cross(n, a);
}

Vec3 HopfFibration::toWorld(Vec3 p) const
{
  Vec3 a, b, n;
  this->worldFrame(a, b, n);
  return center + radius * (p.x * a + p.y * b + p.z * n);
}

Multivector HopfFibration::baseCircle()
{
  return circle({ 0, 0, 0 }, { 0, 0, 1 }, 1.0);
}

Multivector HopfFibration::baseAxis()
{
  return unitDualLine({ 0, 0, 0 }, { 0, 0, 1 });
}

Multivector HopfFibration::boostedLine(double theta)
{
  return unitDualLine(0.5 * boostDirection(theta), { -std::sin(theta), std::cos(theta), 0.0 });
}

Multivector HopfFibration::paperBoost(double theta, double phi)
{
  const double k = hopfBoostParameter(phi);
  return Multivector::scalar(1.0) + k * (no() * vector(boostDirection(theta)));
}

bool HopfFibration::paperTwist(double theta, double phi, Multivector& out)
{
  const Multivector ratio = baseAxis() * versorInverse(boostedLine(theta));
  Bivector log;
  if (!logVersor(toEven(ratio), log))
  {
    return false;
  }
  out = expSeries((0.5 * hopfBoostParameter(phi)) * toMultivector(log));
  return true;
}

Multivector HopfFibration::classicalVersor(double theta, double phi)
{
  const double eta = 0.5 * (phi + 0.5 * kPi);
  return expSeries((-0.5 * (theta + 0.5 * kPi)) * e12()) * expSeries((-0.5 * eta) * classicalPlanes());
}

bool HopfFibration::versorReference(double theta, double phi, Multivector& out) const
{
  if (mode == HopfMode::Classical)
  {
    out = classicalVersor(theta, phi);
    return true;
  }
  Multivector twist;
  if (!paperTwist(theta, phi, twist))
  {
    return false;
  }
  out = twist * paperBoost(theta, phi);
  return true;
}

bool HopfFibration::fiberBladeReference(double theta, double phi, Multivector& out) const
{
  Multivector k;
  if (!versorReference(theta, phi, k))
  {
    return false;
  }
  out = sandwich(k, baseCircle());
  return true;
}

bool HopfFibration::versor(double theta, double phi, Even& out) const
{
  if (!std::isfinite(theta) || !std::isfinite(phi))
  {
    return false;
  }
  if (mode == HopfMode::Classical)
  {
    // R_z(theta + pi/2) (cos(eta/2) - sin(eta/2) e13)(cos(eta/2) + sin(eta/2) e2+): the two
    // planes of the second factor commute, so its exponential is the product of two rotations.
    const double eta = 0.5 * (phi + 0.5 * kPi);
    const Even rz = rotation(toBivector(e12()), -0.5 * (theta + 0.5 * kPi));
    const Even r13 = rotation(toBivector(Multivector::basisBlade(blade::e1 | blade::e3)), -0.5 * eta);
    const Even r2p = rotation(toBivector(Multivector::basisBlade(blade::e2 | blade::ep)), 0.5 * eta);
    out = rz * (r13 * r2p);
    return true;
  }
  // Paper: L_theta^-1 = -L_theta for a unit dual line, so L L_theta^-1 = -L L_theta.
  static const Bivector axis = toBivector(baseAxis());
  const Bivector line = toBivector(boostedLine(theta));
  const Even ratio = -1.0 * (axis * line);
  Bivector log;
  if (!logVersor(ratio, log))
  {
    return false;
  }
  const double k = hopfBoostParameter(phi);
  const Even twist = expExact((0.5 * k) * log, ExpScaling::None);
  // 1 + k tau: the null pair at the origin has exactly zero squares, so expExact sums its series
  // to 1 + B to the bit.
  const Even boost = expExact(k * nullPointPairCompact({ 0, 0, 0 }, boostDirection(theta)));
  out = twist * boost;
  return true;
}

bool HopfFibration::fiberPoints(double theta, double phi, int count, std::vector<Vec3>& out) const
{
  out.clear();
  if (count < 1)
  {
    return false;
  }
  out.resize(count);
  if (!this->fiberPoints(theta, phi, circleSamples(count), out.data()))
  {
    out.clear();
    return false;
  }
  return true;
}

std::vector<Vec3> HopfFibration::circleSamples(int count)
{
  std::vector<Vec3> circle(std::max(count, 0));
  for (int j = 0; j < count; ++j)
  {
    const double t = 2.0 * kPi * j / count;
    circle[j] = { std::cos(t), std::sin(t), 0.0 };
  }
  return circle;
}

bool HopfFibration::fiberPoints(
  double theta, double phi, const std::vector<Vec3>& circle, Vec3* out) const
{
  Even kh;
  if (circle.empty() || !this->versor(theta, phi, kh))
  {
    return false;
  }
  const PointMap map(kh);
  Vec3 a, b, n; // toWorld's frame, once per fiber
  this->worldFrame(a, b, n);
  // A point sent to infinity has weight -ni.P = 0; round-off leaves about 1e-16 |P|, which would
  // normalize to a meaningless finite point, so such weights count as zero (circleImages).
  circleImages(map.matrix(), circle.data(), circle.size(), center, radius, a, b, n, out);
  return true;
}
} // namespace cga
