// Logarithm of versors (Logarithm.h): exp(log K) = K for every kind of versor, and log(exp B) = B
// on the principal branch.
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/Logarithm.h"
#include "cga/PointPairs.h"

#include <limits>

namespace
{
using namespace cga;
using cgatest::Random;
using cgatest::relativeDifference;

// exp(log K) against K, relative to |K|.
::testing::AssertionResult logRoundTrip(const Even& k, double tolerance)
{
  Bivector log;
  if (!logVersor(k, log))
  {
    return ::testing::AssertionFailure() << "logVersor failed";
  }
  const double d = relativeDifference(expExact(log, ExpScaling::None), k);
  if (d <= tolerance)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "exp(log K) differs from K by " << d;
}

// log(exp B) against B.
::testing::AssertionResult expRoundTrip(const Bivector& b, double tolerance)
{
  Bivector log;
  if (!logVersor(expExact(b), log))
  {
    return ::testing::AssertionFailure() << "logVersor failed";
  }
  const double d = relativeDifference(log, b, 1e-3);
  if (d <= tolerance)
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "log(exp B) differs from B by " << d;
}

Bivector rotationPlane(Vec3 axis)
{
  return toBivector(vector(normalized(axis)) * euclideanPseudoscalar());
}

TEST(Logarithm, Rotors)
{
  Random random(51);
  for (int n = 0; n < 500; ++n)
  {
    const Vec3 axis = random.unit();
    const double angle = random.uniform(-6.2, 6.2);
    const Even r = toEven(rotor(axis, angle));
    EXPECT_TRUE(logRoundTrip(r, 1e-13));
    // R = exp(-angle/2 B): the principal value for |angle| < 2 pi.
    Bivector log;
    ASSERT_TRUE(logVersor(r, log));
    EXPECT_LE(relativeDifference(log, (-0.5 * angle) * rotationPlane(axis)), 1e-12)
      << "angle " << angle;
  }
  // The identity, and a rotation by 2 pi (R = -1 up to the plane: no unique logarithm).
  Bivector log;
  ASSERT_TRUE(logVersor(Even::identity(), log));
  EXPECT_EQ(log.maxAbs(), 0.0);
  EXPECT_FALSE(logVersor(-1.0 * Even::identity(), log));
  // A half turn: R = -e12, log = -pi/2 e12.
  ASSERT_TRUE(logVersor(toEven(rotor({ 0, 0, 1 }, M_PI)), log));
  EXPECT_NEAR(log[Bivector::E12], -0.5 * M_PI, 1e-15);
}

TEST(Logarithm, Translators)
{
  Random random(52);
  for (int n = 0; n < 500; ++n)
  {
    const Vec3 d = random.vec3(n % 2 ? 100.0 : 1.0);
    const Even t = toEven(translator(d));
    Bivector log;
    ASSERT_TRUE(logVersor(t, log));
    // T = 1 - d ni/2 = exp(-d ^ ni / 2).
    EXPECT_LE(relativeDifference(log, toBivector(-0.5 * (vector(d) ^ ni()))), 1e-15);
    EXPECT_TRUE(logRoundTrip(t, 1e-15));
  }
}

TEST(Logarithm, MotorsAndScrews)
{
  Random random(53);
  for (int n = 0; n < 500; ++n)
  {
    // Products of a translation and a rotation in either order.
    const Multivector t = translator(random.vec3(3.0));
    const Multivector r = rotor(random.unit(), random.uniform(-6.0, 6.0));
    EXPECT_TRUE(logRoundTrip(toEven(t * r), 1e-12));
    EXPECT_TRUE(logRoundTrip(toEven(r * t), 1e-12));
    // Screw bivectors: a rotation about a shifted axis plus a translation along it.
    const Vec3 axis = random.unit();
    const Multivector shift = translator(random.vec3(2.0));
    const Bivector screw = toBivector(random.uniform(-1.5, 1.5) *
                                      sandwich(shift, vector(axis) * euclideanPseudoscalar())) +
      toBivector(random.uniform(-2.0, 2.0) * (vector(axis) ^ ni()));
    EXPECT_TRUE(expRoundTrip(screw, 1e-12));
    // Pure rotations about shifted axes, small and large angles.
    const Bivector turn = toBivector(random.uniform(-3.0, 3.0) *
                                     sandwich(shift, vector(axis) * euclideanPseudoscalar()));
    EXPECT_TRUE(expRoundTrip(turn, 1e-12));
  }
}

TEST(Logarithm, BoostsAndDilators)
{
  Random random(54);
  for (int n = 0; n < 500; ++n)
  {
    // Round point pairs (hyperbolic), their duals' kind (imaginary pairs, elliptic), null pairs.
    const Vec3 a = random.vec3(2.0), b = random.vec3(2.0);
    const Bivector round = toBivector(pointPair(a, b));
    const Bivector unitRound = (1.0 / std::sqrt(scalarSquare(round))) * round;
    EXPECT_TRUE(expRoundTrip(random.uniform(-3.0, 3.0) * unitRound, 1e-12));
    const Bivector tau =
      nullPointPairCompact(random.vec3(2.0), random.uniform(0.01, 3.0) * random.unit());
    EXPECT_TRUE(expRoundTrip(tau, 1e-12));
    EXPECT_TRUE(expRoundTrip(-tau, 1e-12));
    EXPECT_TRUE(logRoundTrip(Even::identity() + Even::fromBivector(tau), 1e-13));
    const Bivector dilation = random.uniform(-3.0, 3.0) * toBivector(minkowskiPlane());
    EXPECT_TRUE(expRoundTrip(dilation, 1e-13));
    // Products: a boost after a motor.
    const Even motor =
      toEven(translator(random.vec3(1.0)) * rotor(random.unit(), random.uniform(-3.0, 3.0)));
    EXPECT_TRUE(logRoundTrip(expExact(random.uniform(0.1, 2.0) * unitRound) * motor, 1e-11));
  }
}

TEST(Logarithm, GeneralVersors)
{
  Random random(55);
  // Near the identity the logarithm is the principal one: log(exp B) = B.
  for (double scale : { 1e-9, 1e-3, 0.1, 0.3 })
  {
    for (int n = 0; n < 200; ++n)
    {
      EXPECT_TRUE(expRoundTrip(random.bivector(scale), 1e-13)) << "scale " << scale;
    }
  }
  // Farther out exp(log K) = K still holds, whatever branch was taken. Where two rotation planes
  // have angles adding up to about pi (normalized <K>_0 < 0 and nearly equal plane sines) the
  // logarithm is not unique at the limit and only approximately recovered (documented).
  int illConditioned = 0;
  for (double scale : { 1.0, 2.0 })
  {
    for (int n = 0; n < 1000; ++n)
    {
      const Even k = expExact(random.bivector(scale), ExpScaling::None);
      const Even unit = k / std::sqrt((k * reverse(k)).scalar);
      const double y2 = scalarSquare(unit.quadvector);
      const double sum = scalarSquare(unit.bivector) - 2.0 * y2;
      const double gap = std::sqrt(std::max(0.0, sum * sum - 4.0 * y2)); // |s1 - s2|
      const bool nearNonUnique = unit.scalar < 0.0 && gap < 0.05;
      illConditioned += nearNonUnique;
      EXPECT_TRUE(logRoundTrip(k, nearNonUnique ? 1e-6 : 1e-11)) << "scale " << scale;
    }
  }
  EXPECT_LT(illConditioned, 200);
  // Non-unit versors are normalized first: a positive factor does not change the logarithm.
  const Bivector b = random.bivector(0.3);
  Bivector a, c;
  ASSERT_TRUE(logVersor(expExact(b), a));
  ASSERT_TRUE(logVersor(7.5 * expExact(b), c));
  EXPECT_LE(relativeDifference(a, c), 1e-14);
}

TEST(Logarithm, NearlyIsoclinicRotations)
{
  Random random(56);
  for (double delta : { 0.0, 1e-9, 1e-4, 0.02, 0.1 })
  {
    for (int n = 0; n < 20; ++n)
    {
      const double t1 = random.uniform(0.5, 1.4);
      const Multivector b0 = t1 * Multivector::basisBlade(blade::e1 | blade::e2) +
        (t1 + delta) * Multivector::basisBlade(blade::e3 | blade::ep);
      const Multivector v =
        translator(random.vec3(1.0)) * rotor(random.unit(), random.uniform(-3.0, 3.0));
      const Bivector b = toBivector(sandwich(v, b0));
      const Even k = expExact(b);
      EXPECT_TRUE(logRoundTrip(k, 1e-11)) << "delta " << delta;
      if (delta > 0.0)
      {
        // Not isoclinic: the logarithm is unique on the principal branch.
        EXPECT_TRUE(expRoundTrip(b, 1e-11)) << "delta " << delta;
      }
    }
  }
}

TEST(Logarithm, MotorBetweenTwoLines)
{
  // docs/conventions.md section 4: the twist carrying one line onto another from the ratio of dual lines.
  // With unit dual lines (L^2 = -1), the motor M = exp(log(L2 L1^-1) / 2) has M L1 ~M = L2.
  Random random(57);
  for (int n = 0; n < 200; ++n)
  {
    Multivector l1 = dualLine(random.vec3(2.0), random.unit());
    Multivector l2 = dualLine(random.vec3(2.0), random.unit());
    l1 = l1 / std::sqrt(-scalarProduct(l1, l1));
    l2 = l2 / std::sqrt(-scalarProduct(l2, l2));
    const Even ratio = toBivector(l2) * toBivector(-1.0 * l1); // L1^-1 = -L1
    Bivector log;
    ASSERT_TRUE(logVersor(ratio, log));
    const Multivector m = toMultivector(expExact(0.5 * log));
    EXPECT_LE(relativeDifference(sandwich(m, l1), l2), 1e-11);
    // Halfway: the motor's square root, applied twice, is the motor.
    const Even half = expExact(0.25 * log);
    EXPECT_LE(relativeDifference(toMultivector(half * half), m), 1e-11);
  }
}

TEST(Logarithm, RejectsWhatHasNoLogarithm)
{
  Bivector log = nullPointPairCompact({ 1, 1, 1 }, { 1, 0, 0 });
  const Bivector untouched = log;
  // Not finite, zero, and K ~K < 0 (E = no ^ ni = e+ e- has E ~E = -1).
  Even nan = Even::identity();
  nan.quadvector[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(logVersor(nan, log));
  EXPECT_FALSE(logVersor(Even(), log));
  EXPECT_FALSE(logVersor(Even::fromBivector(toBivector(minkowskiPlane())), log));
  // -1 and -(1 + tau): the rotation by pi has no defined plane.
  EXPECT_FALSE(logVersor(-1.0 * Even::identity(), log));
  EXPECT_FALSE(logVersor(-1.0 * (Even::identity() + Even::fromBivector(untouched)), log));
  EXPECT_FALSE(logVersor(-1.0 * expExact(0.7 * toBivector(minkowskiPlane())), log));
  // The paper's exponential of pairs at different places is not a versor.
  const Bivector b = 0.5 * nullPointPairCompact({ 0, 0, 0 }, { 1, 0, 0 }) +
    0.5 * nullPointPairCompact({ 1, 0, 0 }, { 0, 1, 0 });
  EXPECT_FALSE(logVersor(expPaper(b), log));
  for (int i = 0; i < Bivector::Count; ++i)
  {
    EXPECT_EQ(log[i], untouched[i]);
  }
}
} // namespace
