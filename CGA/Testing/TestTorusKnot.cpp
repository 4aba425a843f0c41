// Torus knots as orbits (surfaces/TorusKnot.h): the core circles' rotations commute, the knot
// closes after its period, and its linking numbers with the two core circles are Q and P.
#include "LinkingNumber.h"
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/surfaces/TorusKnot.h"

#include <numeric>
#include <vector>

namespace
{
using namespace cga;
using cgatest::gaussLinkingIntegral;
using cgatest::polygonLinkingNumber;
using cgatest::Random;
using cgatest::relativeDifference;
using cgatest::worseOf;

std::vector<Vec3> circle(const TorusKnot::Circle& c, int count)
{
  std::vector<Vec3> points(count);
  circlePoints(c, count, points.data());
  return points;
}

// The knot through `seed` over one period, `count` samples (the period's end left out).
std::vector<Vec3> knotPoints(const TorusKnot& knot, Vec3 seed, int count)
{
  const Orbit orbit = knot.orbit();
  std::vector<Vec3> points(count);
  for (int i = 0; i < count; ++i)
  {
    EXPECT_TRUE(orbit.point(seed, orbit.period() * i / count, points[i]));
  }
  return points;
}

TorusKnot randomKnot(Random& random, int p, int q)
{
  TorusKnot knot;
  knot.center = random.vec3(3.0);
  knot.normal = random.unit();
  knot.direction = random.unit();
  knot.radius = random.uniform(0.3, 3.0);
  knot.p = p;
  knot.q = q;
  return knot;
}

TEST(TorusKnot, CoreRotationsCommuteSquareToMinusOneAndFixTheirCircles)
{
  Random random(81);
  for (int n = 0; n < 50; ++n)
  {
    const TorusKnot knot = randomKnot(random, 2, 3);
    ASSERT_EQ(knot.validate(), "");
    const Multivector a = toMultivector(TorusKnot::rotationAbout(knot.coreA()));
    const Multivector c = toMultivector(TorusKnot::rotationAbout(knot.coreC()));
    EXPECT_LE(relativeDifference(a * a, Multivector::scalar(-1.0), 1.0), 1e-12);
    EXPECT_LE(relativeDifference(c * c, Multivector::scalar(-1.0), 1.0), 1e-12);
    EXPECT_LE(relativeDifference(a * c, c * a, 1.0), 1e-12);
    EXPECT_LE(std::fabs(scalarProduct(a, c)), 1e-12); // orthogonal planes
    // exp(t A*) leaves every point of A where it is, and moves C's points.
    const Orbit aboutA(TorusKnot::rotationAbout(knot.coreA()));
    for (const Vec3& p : circle(knot.coreA(), 7))
    {
      Vec3 image;
      ASSERT_TRUE(aboutA.point(p, 0.7, image));
      EXPECT_TRUE(cgatest::pointsNear(image, p, 1e-12));
    }
    Vec3 moved;
    const Vec3 onC = circle(knot.coreC(), 3)[0];
    ASSERT_TRUE(aboutA.point(onC, 0.7, moved));
    EXPECT_GT(cgatest::distance(moved, onC), 1e-3 * knot.radius);
    // The orbit's cores (read from the undual parts) are A and C, oriented alike.
    RoundInfo round;
    const Orbit orbit = knot.orbit();
    const TorusKnot::Circle cores[2] = { knot.coreA(), knot.coreC() };
    for (int i = 0; i < 2; ++i)
    {
      ASSERT_TRUE(orbit.core(i, round));
      ASSERT_FALSE(round.isLine);
      EXPECT_TRUE(cgatest::pointsNear(round.center, cores[i].center, 1e-9));
      EXPECT_TRUE(cgatest::pointsNear(round.normal, cores[i].normal, 1e-9));
      EXPECT_NEAR(round.radius, cores[i].radius, 1e-9 * knot.radius);
    }
    // The cores are linked once.
    EXPECT_NEAR(polygonLinkingNumber(circle(knot.coreA(), 400), circle(knot.coreC(), 400)), 1.0, 1e-9);
  }
}

TEST(TorusKnot, ClosesAfterItsPeriodWithLinkingNumbersQAndP)
{
  Random random(82);
  // (2, 3), (3, 5), (5, 8), and a coprime pair drawn at random (seeded: the same every run).
  std::vector<std::pair<int, int>> pairs = { { 2, 3 }, { 3, 5 }, { 5, 8 } };
  for (;;)
  {
    const int p = static_cast<int>(random.uniform(2, 12)), q = static_cast<int>(random.uniform(2, 12));
    if (std::gcd(p, q) == 1 && p != q)
    {
      pairs.emplace_back(p, q);
      break;
    }
  }
  for (const auto& [p, q] : pairs)
  {
    for (int n = 0; n < 3; ++n)
    {
      TorusKnot knot = n == 0 ? TorusKnot() : randomKnot(random, p, q);
      knot.p = p;
      knot.q = q;
      const Orbit orbit = knot.orbit();
      // The period is lcm(P, Q) = P Q, and the knot winds Q times about A and P times about C.
      ASSERT_NEAR(orbit.period(), p * q, 1e-12 * p * q) << p << ", " << q;
      EXPECT_EQ(orbit.windings(0), q);
      EXPECT_EQ(orbit.windings(1), p);
      // Seeds on tori about A (0.15) and about C (-0.15), off the middle torus through
      // the center, which passes through infinity.
      const Vec3 u = normalized(knot.coreC().center - knot.coreA().center);
      for (double offset : { 0.15, -0.15 })
      {
        const Vec3 seed = knot.center + offset * knot.radius * u;
        Vec3 start, end;
        ASSERT_TRUE(orbit.point(seed, 0.0, start));
        ASSERT_TRUE(orbit.point(seed, orbit.period(), end));
        EXPECT_TRUE(cgatest::pointsNear(end, start, 1e-12)) << p << ", " << q;
        const std::vector<Vec3> points = knotPoints(knot, seed, 80 * p * q);
        const std::vector<Vec3> coreA = circle(knot.coreA(), 256), coreC = circle(knot.coreC(), 256);
        const double withA = polygonLinkingNumber(points, coreA);
        const double withC = polygonLinkingNumber(points, coreC);
        EXPECT_NEAR(withA, q, 1e-6) << "(" << p << ", " << q << ") with A";
        EXPECT_NEAR(withC, p, 1e-6) << "(" << p << ", " << q << ") with C";
        if (n == 0 && offset == 0.15)
        {
          // The midpoint sum of the Gauss integral converges to the same numbers.
          EXPECT_NEAR(gaussLinkingIntegral(points, coreA), q, 0.02);
          EXPECT_NEAR(gaussLinkingIntegral(points, coreC), p, 0.02);
        }
      }
    }
  }
}

TEST(TorusKnot, TheMiddleTorusThroughTheCenterPassesThroughInfinity)
{
  // The (3, 5) orbit of the center comes far out (it runs through infinity between two samples);
  // a seed 0.15 r from it stays on a compact torus about A.
  TorusKnot knot;
  knot.p = 3;
  knot.q = 5;
  const Orbit orbit = knot.orbit();
  auto reach = [&](Vec3 seed) {
    double largest = 0.0;
    for (int i = 0; i < 2400; ++i)
    {
      Vec3 p;
      // A sample exactly at infinity has no point: count it as out of reach.
      largest = worseOf(largest, orbit.point(seed, orbit.period() * i / 2400, p) ? norm(p) : 1e300);
    }
    return largest;
  };
  EXPECT_GT(reach(knot.center), 20.0 * knot.radius);
  EXPECT_LT(reach(knot.center + Vec3{ 0.15, 0, 0 }), 5.0 * knot.radius);
}

TEST(TorusKnot, CommonDivisorsGiveTheReducedKnot)
{
  TorusKnot knot;
  knot.p = 4;
  knot.q = 6;
  EXPECT_EQ(knot.commonDivisor(), 2);
  const Orbit orbit = knot.orbit();
  EXPECT_NEAR(orbit.period(), 12.0, 1e-12); // lcm(4, 6), not 24
  EXPECT_EQ(orbit.windings(0), 3);
  EXPECT_EQ(orbit.windings(1), 2);
  // P = Q = 1: equal invariants, exact through the given split.
  knot.p = knot.q = 1;
  const Orbit hopf = knot.orbit();
  EXPECT_TRUE(hopf.hasParts());
  EXPECT_NEAR(hopf.period(), 1.0, 1e-15);
}

TEST(TorusKnot, InvalidParametersAreNamed)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto problem = [](auto change) {
    TorusKnot knot;
    change(knot);
    return knot.validate();
  };
  EXPECT_EQ(problem([](TorusKnot&) {}), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.normal = { 0, 0, 0 }; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.direction = { 0, 0, 0 }; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.direction = { 0, 0, 2 }; }), "");
  EXPECT_NE(problem([&](TorusKnot& k) { k.center.x = nan; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.radius = 0; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.p = 0; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.q = -3; }), "");
  EXPECT_NE(problem([](TorusKnot& k) { k.q = 1001; }), "");
}
} // namespace
