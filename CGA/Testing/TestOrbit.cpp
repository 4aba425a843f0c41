// Orbits of exp(t B) (Orbit.h): the decomposition's closed form against Eigen's matrix
// exponential and the full product's series, the period, degenerate bivectors, and what
// step-by-step iteration does instead.
#include "MatrixExponentialReference.h"
#include "PointPairKernelDispatch.h"
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/Orbit.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace cga;
using cgatest::generator;
using cgatest::Matrix5;
using cgatest::matrixExponential;
using cgatest::Random;
using cgatest::relativeDifference;
using cgatest::vectorAction;

constexpr double kPi = 3.14159265358979323846;

double maxAbs(const Matrix5& m)
{
  return m.cwiseAbs().maxCoeff();
}

Multivector basis2(unsigned a, unsigned b)
{
  return Multivector::basisBlade(a | b);
}

// A unit versor that moves things around: a translation, a boost at the origin and a rotation.
Multivector randomVersor(Random& random)
{
  const Multivector t = translator(random.vec3(1.5));
  const Multivector boost = Multivector::scalar(1.0) + no() * vector(random.vec3(0.4));
  return t * boost * rotor(random.unit(), random.uniform(-3.0, 3.0));
}

// Two commuting rotations of rates r1, r2 (a e12 + b e3^e+, both planes Euclidean), conjugated by
// a random versor: a generic bivector with two elliptic parts.
Bivector rotations(Random& random, double r1, double r2)
{
  const Multivector v = randomVersor(random);
  const Multivector planes = r1 * basis2(blade::e1, blade::e2) + r2 * basis2(blade::e3, blade::ep);
  return toBivector((v * planes * v.reverse()).grade(2));
}

// exp(t G) = V exp(t Lambda) V^-1 from the eigendecomposition of the (diagonalizable) G in long
// double: its error does not grow with t beyond the angle t lambda's.
Matrix5 eigenExponential(const Matrix5& g, double t)
{
  using MatrixL = Eigen::Matrix<long double, 5, 5>;
  Eigen::ComplexEigenSolver<MatrixL> solver(g.cast<long double>());
  const auto v = solver.eigenvectors();
  auto lambda = solver.eigenvalues();
  for (int i = 0; i < 5; ++i)
  {
    lambda(i) = std::exp(static_cast<long double>(t) * lambda(i));
  }
  const auto e = v * lambda.asDiagonal() * v.inverse();
  return e.real().cast<double>();
}

double actionError(const Orbit& orbit, const Bivector& b, double t)
{
  const Matrix5 expected = matrixExponential(t * generator(toMultivector(b)));
  const Matrix5 actual = vectorAction(toMultivector(orbit.versor(t)));
  return maxAbs(actual - expected) / maxAbs(expected);
}

// B with every coefficient a multiple of 2^-24: its conversion to the orthonormal basis of the
// reference (no = (e- + e+)/2, ni = e- - e+) is then exact, so that the reference exponentiates
// the same bivector to the last bit (otherwise a rounded rate alone puts 1e-16 t into the angle).
Bivector dyadic(Bivector b)
{
  for (double& x : b.c)
  {
    x = std::ldexp(std::round(std::ldexp(x, 24)), -24);
  }
  return b;
}

TEST(Orbit, PartsAreTheInvariantDecomposition)
{
  Random random(71);
  for (int n = 0; n < 300; ++n)
  {
    const Bivector b = random.bivector(1.0);
    const Orbit orbit(b);
    InvariantDecomposition split;
    ASSERT_TRUE(invariantDecomposition(b, split));
    ASSERT_TRUE(orbit.problem().empty());
    EXPECT_TRUE(orbit.hasParts());
    // The squares from the extended-precision invariants equal the double decomposition's.
    EXPECT_NEAR(orbit.part(0).square, split.firstSquare,
      1e-12 * std::max(1.0, std::fabs(split.firstSquare)));
    EXPECT_NEAR(orbit.part(1).square, split.secondSquare,
      1e-12 * std::max(1.0, std::fabs(split.secondSquare)));
    EXPECT_LE(relativeDifference(orbit.part(0).blade + orbit.part(1).blade, b), 1e-12);
    for (int i = 0; i < 2; ++i)
    {
      const Even square = orbit.part(i).blade * orbit.part(i).blade;
      EXPECT_NEAR(square.scalar, orbit.part(i).square,
        1e-10 * std::max(1.0, std::fabs(orbit.part(i).square)));
    }
  }
}

TEST(Orbit, ClosedFormMatchesTheMatrixExponentialAndTheSeries)
{
  Random random(72);
  for (double scale : { 0.05, 0.3, 1.0, 2.0 })
  {
    for (int n = 0; n < 60; ++n)
    {
      const Bivector b = dyadic(random.bivector(scale));
      const Orbit orbit(b);
      // exp(t B) stays below the overflow scaling (t sqrt(l1) <= 15), so it is exp(t B) itself.
      const double limit = 15.0 / std::max(1e-3, std::sqrt(std::max(0.0, orbit.part(0).square)));
      for (double t : { -1.3, 0.01, 0.5, 1.0, 4.0, 20.0 })
      {
        if (std::fabs(t) > limit)
        {
          continue;
        }
        EXPECT_LE(actionError(orbit, b, t), 1e-12) << "scale " << scale << " t " << t;
        if (std::fabs(t) * scale <= 2.0)
        {
          EXPECT_LE(
            relativeDifference(toMultivector(orbit.versor(t)), expSeries(toMultivector(t * b))),
            1e-12)
            << "scale " << scale << " t " << t;
        }
      }
    }
  }
}

TEST(Orbit, ClosedFormStaysExactForLongTimes)
{
  // Two rotations at generic rates: every t up to 1e4 directly, against exp(t G) from the
  // eigendecomposition of G in long double (Eigen's Pade exponential squares 13 times at
  // |t G| ~ 3e4, which amplifies its own rounding of these non-normal G to ~1e-12).
  Random random(73);
  for (int n = 0; n < 40; ++n)
  {
    const Bivector b =
      dyadic(rotations(random, random.uniform(0.2, 1.0), random.uniform(0.2, 1.0)));
    const Orbit orbit(b);
    ASSERT_EQ(orbit.part(0).kind, OrbitPartKind::Elliptic);
    ASSERT_EQ(orbit.part(1).kind, OrbitPartKind::Elliptic);
    for (double t : { 1.0, 10.0, 100.0, 1000.0, 5000.0, 10000.0 })
    {
      const Matrix5 expected = eigenExponential(generator(toMultivector(b)), t);
      const Matrix5 actual = vectorAction(toMultivector(orbit.versor(t)));
      EXPECT_LE(maxAbs(actual - expected) / maxAbs(expected), 1e-12) << "t " << t;
    }
  }
}

TEST(Orbit, PeriodOfRationalRatesIsFoundAndClosesTheOrbit)
{
  Random random(74);
  const int ratios[][2] = { { 1, 2 }, { 2, 3 }, { 3, 5 }, { 5, 8 }, { 7, 4 }, { 13, 21 },
    { 1, 1 } };
  for (const auto& ratio : ratios)
  {
    const double unit = random.uniform(0.3, 1.5);
    const Bivector b = rotations(random, ratio[0] * unit, ratio[1] * unit);
    const Orbit orbit(b);
    // Rotor angle rates m u and n u: periods pi/(m u), pi/(n u), together pi/u.
    ASSERT_GT(orbit.period(), 0.0) << ratio[0] << "/" << ratio[1];
    EXPECT_NEAR(orbit.period(), kPi / unit, 1e-12 * kPi / unit);
    for (int k = 0; k < 5; ++k)
    {
      const Vec3 p = random.vec3(2.0);
      Vec3 start, end, half;
      ASSERT_TRUE(orbit.point(p, 0.0, start));
      ASSERT_TRUE(orbit.point(p, orbit.period(), end));
      EXPECT_TRUE(cgatest::pointsNear(end, p, 1e-12));
      EXPECT_TRUE(cgatest::pointsNear(start, p, 1e-15));
      ASSERT_TRUE(orbit.point(p, 0.5 * orbit.period(), half));
      EXPECT_GT(cgatest::distance(half, p), 1e-3); // it does move
    }
  }
  // Irrational ratios (sqrt 2, the golden ratio) have no period below the winding cap.
  for (double ratio : { std::sqrt(2.0), 0.5 * (1.0 + std::sqrt(5.0)), kPi })
  {
    const Orbit orbit(rotations(random, ratio, 1.0));
    EXPECT_EQ(orbit.period(), 0.0) << ratio;
    EXPECT_EQ(orbit.windings(0), 0);
  }
}

TEST(Orbit, DegenerateBivectors)
{
  // B = 0: the identity.
  const Orbit zero{ Bivector() };
  EXPECT_TRUE(zero.isIdentity());
  EXPECT_EQ(zero.period(), 0.0);
  Vec3 out;
  ASSERT_TRUE(zero.point({ 1, 2, 3 }, 7.0, out));
  EXPECT_EQ(cgatest::distance(out, { 1, 2, 3 }), 0.0);

  // A blade: a rotation about the z axis, one elliptic part, period pi/r.
  const Bivector rotation = toBivector(0.25 * basis2(blade::e1, blade::e2));
  const Orbit turn(rotation);
  EXPECT_EQ(turn.part(0).kind, OrbitPartKind::Elliptic);
  EXPECT_EQ(turn.part(1).kind, OrbitPartKind::Zero);
  EXPECT_NEAR(turn.period(), kPi / 0.25, 1e-12);
  ASSERT_TRUE(turn.point({ 1, 0, 0.5 }, 0.5 * turn.period(), out));
  EXPECT_TRUE(cgatest::pointsNear(out, { -1, 0, 0.5 }, 1e-14)); // half a period: half a turn

  // A null point pair: parabolic, exp(t tau) = 1 + t tau exactly, no period.
  const Bivector tau = nullPointPairCompact({ 1, -1, 0.5 }, { 0, 0.3, 0.4 });
  const Orbit drift(tau);
  EXPECT_EQ(drift.part(0).kind, OrbitPartKind::Parabolic);
  EXPECT_EQ(drift.period(), 0.0);
  for (double t : { -3.0, 0.5, 40.0 })
  {
    const Even expected = Even::identity() + Even::fromBivector(t * tau);
    EXPECT_LE(relativeDifference(drift.versor(t), expected), 1e-14);
  }

  // A boost between two points (a real point pair): hyperbolic, no period; far along, the
  // overflow scaling keeps the points finite and at the attracting fixed point.
  const Bivector pair = toBivector(pointPair({ -1, 0, 0 }, { 1, 0, 0 }));
  const Orbit boost(pair);
  EXPECT_EQ(boost.part(0).kind, OrbitPartKind::Hyperbolic);
  EXPECT_EQ(boost.period(), 0.0);
  Vec3 early, late;
  ASSERT_TRUE(boost.point({ 0, 1, 0 }, 200.0, early));
  ASSERT_TRUE(boost.point({ 0, 1, 0 }, 1e4, late));
  EXPECT_TRUE(isFinite(late));
  EXPECT_LT(
    std::min(cgatest::distance(late, { 1, 0, 0 }), cgatest::distance(late, { -1, 0, 0 })), 1e-12);
  EXPECT_LT(cgatest::distance(early, late), 1e-12);

  // Equal invariants: an isoclinic double rotation has no unique split; it is evaluated without
  // one, exactly, and is periodic with the common rate.
  // The planes are translated by dyadic vectors with dyadic rates, so that B is exactly isoclinic
  // in double precision (a rotated copy would be rounded off isoclinic, its rates split by ~1e-8).
  Random random(75);
  for (int n = 0; n < 20; ++n)
  {
    const double rate = std::round(random.uniform(0.2, 1.2) * 16.0) / 16.0;
    const Vec3 shift{ std::round(random.uniform(-8, 8)) / 8.0,
      std::round(random.uniform(-8, 8)) / 8.0, std::round(random.uniform(-8, 8)) / 8.0 };
    const Multivector t = translator(shift);
    const Bivector isoclinic = toBivector(
      (t * (rate * (basis2(blade::e1, blade::e2) + basis2(blade::e3, blade::ep))) * t.reverse())
        .grade(2));
    const Orbit orbit(isoclinic);
    EXPECT_FALSE(orbit.hasParts());
    EXPECT_EQ(orbit.part(0).kind, OrbitPartKind::Elliptic);
    EXPECT_EQ(orbit.part(1).kind, OrbitPartKind::Elliptic);
    EXPECT_NEAR(orbit.period(), kPi / rate, 1e-10 * kPi / rate);
    for (double t : { 0.3, 2.0, 50.0 })
    {
      EXPECT_LE(actionError(orbit, isoclinic, t), 1e-11) << "t " << t;
    }
  }

  // Non-finite or huge B: a problem, and no point.
  Bivector bad;
  bad[Bivector::E12] = std::numeric_limits<double>::quiet_NaN();
  const Orbit nan(bad);
  EXPECT_FALSE(nan.problem().empty());
  EXPECT_FALSE(nan.point({ 0, 0, 0 }, 1.0, out));
  bad[Bivector::E12] = 1e200;
  EXPECT_FALSE(Orbit(bad).problem().empty());
  EXPECT_FALSE(turn.point({ 0, 0, 0 }, std::numeric_limits<double>::infinity(), out));
}

// Bivectors that take every branch of the closed form: two rotations at generic and at nearly
// equal rates, a rotation with a boost (a loxodrome), a boost alone (large angles scaled), a
// translation, a generic bivector.
std::vector<Bivector> everyBranch(Random& random)
{
  Bivector translation;
  translation[Bivector::E1NI] = 0.7;
  return { rotations(random, 0.4, 0.9), rotations(random, 0.8, 0.79),
    toBivector((0.5 * basis2(blade::e1, blade::e2) + 0.3 * basis2(blade::e3, blade::em)).grade(2)),
    toBivector((0.6 * basis2(blade::e3, blade::em)).grade(2)), translation, random.bivector(1.0) };
}

// Times at which exp(t B) takes each branch: small angles, every quadrant of the rotations, large
// hyperbolic angles, long times, and bad ones.
std::vector<double> everyTime()
{
  std::vector<double> times = { 0.0, -0.0, 1e-3, -0.7, 1.9,
    std::numeric_limits<double>::quiet_NaN(), 40.0, -55.5, 1e4 + 0.25, 1e6, -3e9, 1e300,
    std::numeric_limits<double>::infinity() };
  for (int i = 0; i < 24; ++i)
  {
    times.push_back(0.37 * i - 2.0);
  }
  return times;
}

bool sameBits(const Even& a, const Even& b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(Orbit, VersorsAreEachTimesVersorWhateverItsNeighbours)
{
  // Eight times share the lanes of one closed form, the rest take versor's scalar branches: each
  // time's versor has the same bits however many times come with it and in which lane it lands.
  Random random(77);
  const std::vector<double> times = everyTime();
  for (const Bivector& b : everyBranch(random))
  {
    const Orbit orbit(b);
    std::vector<Even> all(times.size()), shifted(times.size());
    orbit.versors(times.data(), times.size(), all.data());
    orbit.versors(times.data() + 3, times.size() - 5, shifted.data());
    for (size_t i = 0; i < times.size(); ++i)
    {
      const Even one = orbit.versor(times[i]);
      EXPECT_TRUE(sameBits(all[i], one)) << "t " << times[i];
      if (i >= 3 && i < times.size() - 2)
      {
        EXPECT_TRUE(sameBits(shifted[i - 3], one)) << "t " << times[i];
      }
    }
  }
}

TEST(Orbit, VersorsHaveTheSameBitsOnEveryInstructionSet)
{
  // The lanes' sines and cosines are the kernel's deterministic vector functions: every
  // instruction set gives the baseline's bits.
  Random random(78);
  const std::vector<double> times = everyTime();
  const std::string active = kernel::activeInstructionSet();
  for (const Bivector& b : everyBranch(random))
  {
    const Orbit orbit(b);
    std::vector<Even> baseline(times.size()), other(times.size());
    ASSERT_TRUE(kernel::useInstructionSet("baseline"));
    orbit.versors(times.data(), times.size(), baseline.data());
    for (const std::string& set : kernel::availableInstructionSets())
    {
      ASSERT_TRUE(kernel::useInstructionSet(set));
      orbit.versors(times.data(), times.size(), other.data());
      for (size_t i = 0; i < times.size(); ++i)
      {
        EXPECT_TRUE(sameBits(other[i], baseline[i])) << set << " t " << times[i];
      }
    }
  }
  ASSERT_TRUE(kernel::useInstructionSet(active));
}

TEST(Orbit, EightTimesSideBySideStayWithinAFewUnitsOfTheReference)
{
  // The closed form against exp(t G) from the eigendecomposition in long double, at times from
  // small angles to 100 (beyond, the reference's own error grows to hundreds of units), for
  // rotations at rates 0.2 to 2.55 apart by a factor of 1.16 to 3 (most take the lanes: squares a
  // quarter of the larger apart and not small against B's coefficients) and a rotation with a
  // boost: the action's largest error over its largest entry. Measured: 7 units of 2^-53 (the
  // extended form on the same bivectors: 7).
  Random random(79);
  double worst = 0.0;
  std::vector<Bivector> bivectors;
  for (int n = 0; n < 30; ++n)
  {
    const double r1 = random.uniform(0.2, 0.85);
    bivectors.push_back(dyadic(rotations(random, r1, r1 * random.uniform(1.16, 3.0))));
  }
  bivectors.push_back(
    toBivector((0.5 * basis2(blade::e1, blade::e2) + 0.3 * basis2(blade::e3, blade::em)).grade(2)));
  for (const Bivector& b : bivectors)
  {
    const Orbit orbit(b);
    for (double t : { 1e-3, 0.4, 2.0, 13.0, 100.0 })
    {
      if (orbit.part(0).kind == OrbitPartKind::Hyperbolic && t > 13.0)
      {
        continue; // beyond the scaling threshold: the extended form
      }
      const Matrix5 expected = eigenExponential(generator(toMultivector(b)), t);
      const Matrix5 actual = vectorAction(toMultivector(orbit.versor(t)));
      worst = std::max(worst, maxAbs(actual - expected) / maxAbs(expected));
    }
  }
  std::cout << "largest error " << worst << " (" << worst / 0x1p-53 << " units of 2^-53)\n";
  EXPECT_LE(worst, 16 * 0x1p-53);
}

TEST(Orbit, StepByStepIterationDriftsWhileTheClosedFormDoesNot)
{
  // One period of a (3, 5) double rotation in 10^6 steps: the iteration p <- K(dt) p ~K(dt)
  // with the exact small-step versor (the best any stepping can do) accumulates the rounding of
  // every step; the closed form evaluates every t afresh.
  Random random(76);
  const Orbit orbit(rotations(random, 3.0 * 0.4, 5.0 * 0.4));
  ASSERT_GT(orbit.period(), 0.0);
  const int steps = 1000000;
  const double dt = orbit.period() / steps;
  const PointMap step(orbit.versor(dt));
  const Vec3 start{ 0.3, -0.2, 0.5 };
  ConformalVector x = ConformalVector::point(start);
  for (int i = 0; i < steps; ++i)
  {
    x = step.apply(x);
  }
  Vec3 iterated, closed;
  ASSERT_TRUE(normalizePoint(x, iterated));
  ASSERT_TRUE(orbit.point(start, steps * dt, closed));
  const double iterationGap = cgatest::distance(iterated, start);
  const double closedGap = cgatest::distance(closed, start);
  std::cout << "after one period in " << steps << " steps: iterated gap " << iterationGap
            << ", closed-form gap " << closedGap << "\n";
  EXPECT_LE(closedGap, 1e-13);
  EXPECT_GE(iterationGap, 1e-11);
  EXPECT_GE(iterationGap, 100.0 * closedGap);
}
} // namespace
