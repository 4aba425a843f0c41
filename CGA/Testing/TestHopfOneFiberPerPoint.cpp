// "Exactly one fiber through every point" (the claim for the Hopf fibration of
// HopfFibration.h): for random points p of R^3 away from the axis and the base circle, the base
// point (theta, phi) whose fiber passes through p is found by Newton's method on
// fiber(theta, phi, t) = p from a grid of starts; every start that reaches a fiber through p
// (distance < 1e-9) must reach the same base point (up to the 2 pi period and the poles). The
// classical mode's base point is also found in closed form: inverse stereographic projection of
// p to S^3, then the Hopf map.
#include "TestSupport.h"

#include "cga/PointSandwich.h"
#include "cga/surfaces/HopfFibration.h"

#include <Eigen/Dense>

#include <complex>

namespace
{
using namespace cga;
using cgatest::Random;

constexpr double kPi = 3.14159265358979323846;

struct BasePoint
{
  double theta = 0.0, phi = 0.0;
};

/// The base point as a unit vector of the 2-sphere: equal vectors are the same base point whatever
/// the period of theta, and theta does not matter at the poles.
Vec3 baseVector(BasePoint b)
{
  return { std::cos(b.phi) * std::cos(b.theta), std::cos(b.phi) * std::sin(b.theta), std::sin(b.phi) };
}

/// A frame that is not the canonical one, to exercise toWorld.
HopfFibration tiltedHopf(HopfMode mode)
{
  HopfFibration hopf;
  hopf.center = { 0.5, -1.0, 2.0 };
  hopf.normal = { 1.0, 2.0, 2.0 };
  hopf.radius = 1.5;
  hopf.mode = mode;
  return hopf;
}

/// World to the canonical frame (inverse of HopfFibration::toWorld, written out independently).
Vec3 toCanonical(const HopfFibration& hopf, Vec3 x)
{
  const Vec3 n = normalized(hopf.normal);
  const Vec3 a = orthogonalUnit(n);
  const Vec3 b = cross(n, a);
  const Vec3 d = (x - hopf.center) / hopf.radius;
  return { dot(d, a), dot(d, b), dot(d, n) };
}

/// The point t of the fiber over (theta, phi): the image of (cos t, sin t, 0) of the canonical
/// circle, in world coordinates. False when the fiber cannot be formed or the point is at infinity.
bool fiberPoint(const HopfFibration& hopf, double theta, double phi, double t, Vec3& out)
{
  Even kh;
  if (!hopf.versor(theta, phi, kh))
  {
    return false;
  }
  Vec3 canonical;
  if (!PointMap(kh).apply(Vec3{ std::cos(t), std::sin(t), 0.0 }, canonical) || !isFinite(canonical))
  {
    return false;
  }
  out = hopf.toWorld(canonical);
  return true;
}

/// Classical mode in closed form: the canonical point x lifts to s = (2x, 1 - |x|^2)/(1 + |x|^2)
/// on S^3, i.e. (z1, z2) = (s1 + i s2, s3 - i s+); its Hopf image (2 z1 conj(z2), |z1|^2 - |z2|^2)
/// is (cos phi cos(theta + pi/2), cos phi sin(theta + pi/2), -sin phi).
BasePoint classicalBasePoint(Vec3 x)
{
  const double q = norm2(x);
  const std::complex<double> z1(2.0 * x.x / (1.0 + q), 2.0 * x.y / (1.0 + q));
  const std::complex<double> z2(2.0 * x.z / (1.0 + q), -(1.0 - q) / (1.0 + q));
  const std::complex<double> h = 2.0 * z1 * std::conj(z2);
  const double height = std::norm(z1) - std::norm(z2);
  return { std::arg(h) - 0.5 * kPi, std::atan2(-height, std::abs(h)) };
}

struct NewtonResult
{
  BasePoint base;
  double distance = std::numeric_limits<double>::infinity();
};

/// Newton's method on fiber(theta, phi, t) - p = 0 (central-difference Jacobian) with a
/// backtracking line search; phi is kept in [-pi/2, pi/2] by walking over the pole (phi -> +-pi -
/// phi, theta -> theta + pi), so every iterate is a base point of the 2-sphere.
NewtonResult solveForFiber(const HopfFibration& hopf, Vec3 p, Eigen::Vector3d x)
{
  auto residual = [&](const Eigen::Vector3d& v, Eigen::Vector3d& r) {
    Vec3 f;
    if (!fiberPoint(hopf, v[0], v[1], v[2], f))
    {
      return false;
    }
    r = { f.x - p.x, f.y - p.y, f.z - p.z };
    return r.allFinite();
  };
  auto overThePole = [](Eigen::Vector3d& v) {
    if (v[1] > 0.5 * kPi || v[1] < -0.5 * kPi)
    {
      v[1] = (v[1] > 0.0 ? kPi : -kPi) - v[1];
      v[0] += kPi;
    }
  };
  NewtonResult result;
  Eigen::Vector3d r;
  if (!residual(x, r))
  {
    return result;
  }
  const double h = 1e-7;
  for (int iteration = 0; iteration < 60 && r.norm() > 1e-14 * (1.0 + norm(p)); ++iteration)
  {
    Eigen::Matrix3d jacobian;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k)
    {
      Eigen::Vector3d plus = x, minus = x, rPlus, rMinus;
      plus[k] += h;
      minus[k] -= h;
      ok = residual(plus, rPlus) && residual(minus, rMinus);
      jacobian.col(k) = (rPlus - rMinus) / (2.0 * h);
    }
    if (!ok)
    {
      break;
    }
    const Eigen::Vector3d step = jacobian.colPivHouseholderQr().solve(-r);
    if (!step.allFinite())
    {
      break;
    }
    // Backtrack until the distance decreases (a stuck start is a local minimum, not a root).
    bool decreased = false;
    for (double lambda = 1.0; lambda > 1e-6 && !decreased; lambda *= 0.5)
    {
      Eigen::Vector3d trial = x + lambda * step, rTrial;
      overThePole(trial);
      if (residual(trial, rTrial) && rTrial.norm() < r.norm())
      {
        x = trial;
        r = rTrial;
        decreased = true;
      }
    }
    if (!decreased)
    {
      break;
    }
  }
  result.base = { x[0], x[1] };
  result.distance = r.norm();
  return result;
}

/// Random world points whose canonical position is at least 0.15 (circle radii) from the axis and
/// from the base circle, within a box of half-width 2.5 circle radii.
std::vector<Vec3> pointsAwayFromAxisAndCircle(const HopfFibration& hopf, int count, Random& random)
{
  std::vector<Vec3> points;
  while (static_cast<int>(points.size()) < count)
  {
    const Vec3 q = random.vec3(2.5);
    const double rho = std::hypot(q.x, q.y);
    if (rho > 0.15 && std::hypot(rho - 1.0, q.z) > 0.15)
    {
      points.push_back(hopf.toWorld(q));
    }
  }
  return points;
}

/// Every start of a 4 x 3 x 3 grid over (theta, phi, t) is refined; the ones reaching a fiber
/// through p must all agree. Returns that base point (the first root), with `found` = false if no
/// start reached one.
BasePoint uniqueBasePointThrough(const HopfFibration& hopf, Vec3 p, bool& found)
{
  found = false;
  BasePoint first;
  int roots = 0;
  for (int i = 0; i < 4; ++i)
  {
    for (double phi : { -0.9, 0.0, 0.9 })
    {
      for (int j = 0; j < 3; ++j)
      {
        const NewtonResult result =
          solveForFiber(hopf, p, { 2.0 * kPi * (i + 0.25) / 4, phi, 2.0 * kPi * j / 3 });
        if (!(result.distance < 1e-9))
        {
          continue; // did not reach a fiber through p
        }
        ++roots;
        if (!found)
        {
          first = result.base;
          found = true;
        }
        EXPECT_LE(norm(baseVector(result.base) - baseVector(first)), 1e-7)
          << "a second fiber through p = (" << p.x << ", " << p.y << ", " << p.z << "): ("
          << first.theta << ", " << first.phi << ") and (" << result.base.theta << ", "
          << result.base.phi << ")";
      }
    }
  }
  return first;
}

TEST(HopfFibration, PaperModeHasExactlyOneFiberThroughEachPoint)
{
  const HopfFibration hopf = tiltedHopf(HopfMode::Paper);
  Random random(2014);
  for (Vec3 p : pointsAwayFromAxisAndCircle(hopf, 200, random))
  {
    bool found = false;
    uniqueBasePointThrough(hopf, p, found);
    EXPECT_TRUE(found) << "no fiber found through (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
}

TEST(HopfFibration, ClassicalModeBasePointInClosedFormIsTheOnlyFiberThroughEachPoint)
{
  const HopfFibration hopf = tiltedHopf(HopfMode::Classical);
  Random random(1931);
  for (Vec3 p : pointsAwayFromAxisAndCircle(hopf, 200, random))
  {
    const BasePoint closedForm = classicalBasePoint(toCanonical(hopf, p));
    // The closed form's fiber passes through p: distance to the circle through three of its points.
    std::vector<Vec3> fiber;
    ASSERT_TRUE(hopf.fiberPoints(closedForm.theta, closedForm.phi, 3, fiber));
    const Vec3 u = fiber[1] - fiber[0], v = fiber[2] - fiber[0];
    const Vec3 w = cross(u, v);
    const Vec3 center = fiber[0] + (norm2(u) * cross(v, w) + norm2(v) * cross(w, u)) / (2.0 * norm2(w));
    const Vec3 d = p - center;
    const double height = dot(d, normalized(w));
    const double distance =
      std::hypot(height, norm(d - height * normalized(w)) - norm(fiber[0] - center));
    EXPECT_LE(distance, 1e-9 * (1.0 + norm(p)));
    // ... and it is the only one.
    bool found = false;
    const BasePoint numeric = uniqueBasePointThrough(hopf, p, found);
    ASSERT_TRUE(found);
    EXPECT_LE(norm(baseVector(numeric) - baseVector(closedForm)), 1e-7);
  }
}
} // namespace
