// Exponentials (Exponential.h): the exact closed form against a matrix exponential and a series,
// the paper's rule against the exact one, numerical edge cases.
#include "MatrixExponentialReference.h"
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <limits>

namespace
{
using namespace cga;
using cgatest::Random;
using cgatest::relativeDifference;
using cgatest::generator;
using cgatest::Matrix5;
using cgatest::matrixExponential;
using cgatest::vectorAction;

double maxAbs(const Matrix5& m)
{
  return m.cwiseAbs().maxCoeff();
}

// |<P P>_0| / |P|^2 for the image P of up(p): 0 for a conformal map.
double nullness(const Even& k, Vec3 p)
{
  const ConformalVector image = sandwichGrade1(k, ConformalVector::point(p));
  const double size = image.maxAbs();
  return std::fabs(dot(image, image)) / (size * size);
}

// K ~K - 1 relative to |K|^2: 0 for a unit versor.
double versorDefect(const Even& k)
{
  const Even n = k * reverse(k) - Even::identity();
  const double size = k.maxAbs();
  return n.maxAbs() / (size * size);
}

// A unit versor that moves things around: a translation, a boost at the origin and a rotation.
Multivector randomVersor(Random& random)
{
  const Multivector t = translator(random.vec3(2.0));
  const Multivector boost = Multivector::scalar(1.0) + no() * vector(random.vec3(0.5));
  return t * boost * rotor(random.unit(), random.uniform(-3.0, 3.0));
}

TEST(Exponential, ExactMatchesTheMatrixExponential)
{
  Random random(41);
  for (double scale : { 0.05, 0.3, 1.0, 2.0 })
  {
    for (int n = 0; n < 100; ++n)
    {
      const Bivector b = random.bivector(scale);
      const Matrix5 expected = matrixExponential(generator(toMultivector(b)));
      const Matrix5 actual = vectorAction(toMultivector(expExact(b)));
      EXPECT_LE(maxAbs(actual - expected), 1e-12 * maxAbs(expected)) << "scale " << scale;
    }
  }
}

TEST(Exponential, ExactMatchesTheSeriesAndIsAVersor)
{
  Random random(42);
  for (double scale : { 1e-6, 0.05, 0.3, 1.0, 2.0 })
  {
    for (int n = 0; n < 100; ++n)
    {
      const Bivector b = random.bivector(scale);
      const Even k = expExact(b);
      EXPECT_LE(relativeDifference(toMultivector(k), expSeries(toMultivector(b))), 1e-12)
        << "scale " << scale;
      EXPECT_LE(versorDefect(k), 1e-13);
      for (int i = 0; i < 5; ++i)
      {
        EXPECT_LE(nullness(k, random.vec3(2.0)), 1e-12);
      }
    }
  }
}

TEST(Exponential, SeriesReferenceMatchesTheMatrixExponential)
{
  Random random(43);
  for (int n = 0; n < 50; ++n)
  {
    const Multivector b = toMultivector(random.bivector(1.0));
    const Matrix5 expected = matrixExponential(generator(b));
    EXPECT_LE(maxAbs(vectorAction(expSeries(b)) - expected), 1e-12 * maxAbs(expected));
  }
  // Non-finite input.
  Multivector bad;
  bad[3] = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(expSeries(bad).isFinite());
}

TEST(Exponential, InvariantDecompositionSplitsIntoCommutingBlades)
{
  Random random(44);
  for (int n = 0; n < 300; ++n)
  {
    const Bivector b = random.bivector(1.0);
    InvariantDecomposition split;
    ASSERT_TRUE(invariantDecomposition(b, split));
    EXPECT_GE(split.firstSquare, split.secondSquare);
    // Real bivectors of R^{4,1}: at most one plane is hyperbolic.
    EXPECT_LE(split.secondSquare, 1e-12);
    EXPECT_LE(relativeDifference(split.first + split.second, b), 1e-12);
    const Even ab = split.first * split.second, ba = split.second * split.first;
    EXPECT_LE(relativeDifference(ab, ba, 1.0), 1e-11);
    const Even s1 = split.first * split.first, s2 = split.second * split.second;
    EXPECT_NEAR(s1.scalar, split.firstSquare, 1e-11 * std::max(1.0, std::fabs(split.firstSquare)));
    EXPECT_NEAR(
      s2.scalar, split.secondSquare, 1e-11 * std::max(1.0, std::fabs(split.secondSquare)));
    EXPECT_LE(s1.bivector.maxAbs() + s1.quadvector.maxAbs(), 1e-11 * std::max(1.0, s1.maxAbs()));
    EXPECT_LE(s2.bivector.maxAbs() + s2.quadvector.maxAbs(), 1e-11 * std::max(1.0, s2.maxAbs()));
    // exp(B) = exp(B1) exp(B2), with the paper's rule exact on each blade.
    const Even product =
      expPaper(split.first, ExpScaling::None) * expPaper(split.second, ExpScaling::None);
    EXPECT_LE(relativeDifference(product, expExact(b, ExpScaling::None)), 1e-10);
  }
  // A 2-blade is its own decomposition; an isoclinic rotation has no unique one.
  InvariantDecomposition split;
  const Bivector tau = nullPointPairCompact({ 1, 2, 3 }, { 0, 1, 0 });
  ASSERT_TRUE(invariantDecomposition(tau, split));
  EXPECT_EQ(relativeDifference(split.first, tau), 0.0);
  EXPECT_EQ(split.second.maxAbs(), 0.0);
  const Bivector isoclinic = toBivector(Multivector::basisBlade(blade::e1 | blade::e2) +
                                        Multivector::basisBlade(blade::e3 | blade::ep));
  EXPECT_FALSE(invariantDecomposition(isoclinic, split));
}

// Blades: a round point pair, a null point pair, a rotation about a shifted axis, a translation,
// a dilation, a transversion.
std::vector<Bivector> randomBlades(Random& random)
{
  std::vector<Bivector> blades;
  const Vec3 a = random.vec3(2.0), b = random.vec3(2.0);
  blades.push_back(toBivector(random.uniform(0.05, 0.8) * pointPair(a, b)));
  blades.push_back(
    nullPointPairCompact(random.vec3(2.0), random.uniform(0.1, 2.0) * random.unit()));
  const Multivector t = translator(random.vec3(2.0));
  const Multivector plane = vector(random.unit()) * euclideanPseudoscalar();
  blades.push_back(toBivector(random.uniform(-3.0, 3.0) * sandwich(t, plane)));
  blades.push_back(toBivector(vector(random.vec3(2.0)) ^ ni()));
  blades.push_back(toBivector(random.uniform(-2.0, 2.0) * minkowskiPlane()));
  blades.push_back(toBivector(no() ^ vector(random.vec3(2.0))));
  return blades;
}

TEST(Exponential, PaperRuleIsExactForBlades)
{
  Random random(45);
  for (int n = 0; n < 200; ++n)
  {
    for (const Bivector& b : randomBlades(random))
    {
      // A 2-blade has B ^ B = 0 and B^2 = <B B>_0.
      EXPECT_LE(wedge(b, b).maxAbs(), 1e-13 * std::max(1.0, b.maxAbs() * b.maxAbs()));
      const Even paper = expPaper(b);
      EXPECT_LE(relativeDifference(paper, expExact(b)), 1e-12);
      EXPECT_LE(relativeDifference(toMultivector(paper), expSeries(toMultivector(b))), 1e-12);
      EXPECT_LE(versorDefect(paper), 1e-13);
    }
  }
}

TEST(Exponential, PaperRuleIsNotAVersorForPairsAtDifferentPlaces)
{
  Random random(46);
  for (int n = 0; n < 100; ++n)
  {
    const Vec3 x1 = random.vec3(1.0), x2 = x1 + random.uniform(0.5, 1.0) * random.unit();
    const Bivector b =
      0.5 * nullPointPairCompact(x1, random.unit()) + 0.5 * nullPointPairCompact(x2, random.unit());
    // Not a blade: B ^ B != 0 ...
    EXPECT_GT(wedge(b, b).maxAbs(), 1e-3);
    const Even paper = expPaper(b), exact = expExact(b);
    // ... so the paper's K has K ~K = 1 + a grade-4 part, and K up(p) ~K is not null.
    const Even norm = paper * reverse(paper);
    EXPECT_GT(norm.quadvector.maxAbs(), 1e-3 * norm.scalar);
    EXPECT_LE(norm.bivector.maxAbs(), 1e-14);
    EXPECT_LE(versorDefect(exact), 1e-13);
    const Vec3 p = x1 + random.vec3(1.0);
    EXPECT_GT(nullness(paper, p), 1e-7);
    EXPECT_LE(nullness(exact, p), 1e-13);
    // And the two rules move the point to different places.
    Vec3 viaPaper, viaExact;
    ASSERT_TRUE(sandwichPoint(paper, p, viaPaper));
    ASSERT_TRUE(sandwichPoint(exact, p, viaExact));
    EXPECT_GT(cgatest::distance(viaPaper, viaExact), 1e-6);
  }
}

TEST(Exponential, SeriesNearZeroIsContinuousAcrossZero)
{
  // Blades with s = <B B>_0 of either sign: a b E (s = b^2), b e12 (s = -b^2), b e1 ^ ni (s = 0).
  const auto hyperbolic = [](double b) { return b * toBivector(minkowskiPlane()); };
  const auto elliptic = [](double b) { return b * toBivector(e1() ^ e2()); };
  const Bivector null = toBivector(e1() ^ ni());
  for (double s : { 1e-20, 1e-8, 1e-4 })
  {
    const double b = std::sqrt(s);
    for (bool exact : { false, true })
    {
      const Even plus = exact ? expExact(hyperbolic(b)) : expPaper(hyperbolic(b));
      const Even minus = exact ? expExact(elliptic(b)) : expPaper(elliptic(b));
      EXPECT_NEAR(plus.scalar, std::cosh(b), 1e-16);
      EXPECT_NEAR(minus.scalar, std::cos(b), 1e-16);
      EXPECT_NEAR(plus.bivector[Bivector::NONI] / b, std::sinh(b) / b, 3e-16);
      EXPECT_NEAR(minus.bivector[Bivector::E12] / b, std::sin(b) / b, 3e-16);
      // Continuity: the two sides differ by cosh - cos = s + s^3/360 + ..., not by a jump.
      EXPECT_NEAR(plus.scalar - minus.scalar, s + s * s * s / 360.0, 1e-16);
    }
    const Even zero = expPaper(b * null);
    EXPECT_EQ(zero.scalar, 1.0);
    EXPECT_EQ(zero.bivector[Bivector::E1NI], b);
  }
  const Even zero = expPaper(Bivector());
  EXPECT_EQ(relativeDifference(zero, Even::identity()), 0.0);
  // Across the switch from the series to cosh/cos (sqrt|s| = 1e-2).
  for (double root : { 1e-2 * (1.0 - 1e-12), 1e-2 * (1.0 + 1e-12) })
  {
    EXPECT_NEAR(expPaper(hyperbolic(root)).scalar, std::cosh(root), 2e-16);
    EXPECT_NEAR(expPaper(elliptic(root)).scalar, std::cos(root), 2e-16);
    EXPECT_NEAR(expPaper(hyperbolic(root)).bivector[Bivector::NONI], std::sinh(root), 3e-16 * root);
    EXPECT_NEAR(expPaper(elliptic(root)).bivector[Bivector::E12], std::sin(root), 3e-16 * root);
  }
  // Tiny general bivectors: exp(B) = 1 + B + B^2/2 + B^3/6 to double precision.
  Random random(47);
  for (double scale : { 1e-12, 1e-7, 1e-5 })
  {
    for (int n = 0; n < 50; ++n)
    {
      const Multivector b = toMultivector(random.bivector(scale));
      const Multivector expected =
        Multivector::scalar(1.0) + b + 0.5 * (b * b) + (1.0 / 6.0) * (b * b * b);
      EXPECT_LE(relativeDifference(toMultivector(expExact(toBivector(b))), expected), 1e-15);
    }
  }
}

TEST(Exponential, ExactIsAccurateAcrossItsInternalPaths)
{
  Random random(48);
  // Around |l|max = 1, where the power series hands over to the closed form.
  for (int n = 0; n < 100; ++n)
  {
    const Bivector b = random.bivector(1.0);
    InvariantDecomposition split;
    ASSERT_TRUE(invariantDecomposition(b, split));
    const double largest = std::max(std::fabs(split.firstSquare), std::fabs(split.secondSquare));
    for (double factor : { 1.0 - 1e-9, 1.0 + 1e-9 })
    {
      const Bivector scaled = (std::sqrt(factor / largest)) * b;
      const Even k = expExact(scaled);
      EXPECT_LE(relativeDifference(toMultivector(k), expSeries(toMultivector(scaled))), 1e-12);
      EXPECT_LE(versorDefect(k), 1e-13);
    }
  }
  // Nearly isoclinic rotations (t1 e12 + t2 e3e+), moved by a random versor so that all
  // coefficients are non-zero: exp(V B ~V) = V exp(B) ~V.
  for (double delta : { 0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.05, 0.2 })
  {
    for (int n = 0; n < 20; ++n)
    {
      const double t1 = random.uniform(1.1, 3.0);
      const Multivector b0 = t1 * Multivector::basisBlade(blade::e1 | blade::e2) +
        (t1 + delta) * Multivector::basisBlade(blade::e3 | blade::ep);
      const Multivector v = randomVersor(random);
      const Multivector b = sandwich(v, b0);
      const Multivector expected = sandwich(v, expSeries(b0));
      const Even k = expExact(toBivector(b));
      EXPECT_LE(relativeDifference(toMultivector(k), expected), 1e-12) << "delta " << delta;
      const Matrix5 reference = matrixExponential(generator(b));
      EXPECT_LE(maxAbs(vectorAction(toMultivector(k)) - reference), 1e-12 * maxAbs(reference))
        << "delta " << delta;
    }
  }
}

TEST(Exponential, HugeBivectorsDoNotOverflow)
{
  Random random(49);
  for (double scale : { 1e3, 1e6, 1e100, 1e200 })
  {
    for (int n = 0; n < 20; ++n)
    {
      const Bivector b = random.bivector(scale);
      const Even paper = expPaper(b), exact = expExact(b);
      EXPECT_TRUE(paper.isFinite()) << "scale " << scale;
      EXPECT_TRUE(exact.isFinite()) << "scale " << scale;
      Vec3 out;
      if (sandwichPoint(exact, random.vec3(2.0), out))
      {
        EXPECT_TRUE(isFinite(out));
      }
    }
  }
  // A large boost keeps mapping points conformally (null images) after the scaling.
  for (int n = 0; n < 20; ++n)
  {
    const Bivector b = random.bivector(100.0);
    const Even k = expExact(b);
    ASSERT_TRUE(k.isFinite());
    EXPECT_LE(nullness(k, random.vec3(2.0)), 1e-10);
  }
}

TEST(Exponential, ScalingIsAPositiveFactor)
{
  const Bivector dilation = toBivector(minkowskiPlane());
  for (double mu : { 5.0, 19.0, 25.0, 300.0 })
  {
    const Even unscaledPaper = expPaper(mu * dilation, ExpScaling::None);
    const Even unscaledExact = expExact(mu * dilation, ExpScaling::None);
    const double factor = mu > kExpScalingThreshold ? std::cosh(mu) : 1.0;
    EXPECT_LE(relativeDifference(factor * expPaper(mu * dilation), unscaledPaper), 1e-14);
    EXPECT_LE(relativeDifference(factor * expExact(mu * dilation), unscaledExact), 1e-14);
  }
  // Beyond cosh's range only the scaled value exists; the unscaled one overflows (documented).
  EXPECT_TRUE(expPaper(800.0 * dilation).isFinite());
  EXPECT_TRUE(expExact(800.0 * dilation).isFinite());
  EXPECT_FALSE(expPaper(800.0 * dilation, ExpScaling::None).isFinite());
  // A scaled boost still maps points like the unscaled one.
  Random random(50);
  for (int n = 0; n < 50; ++n)
  {
    const Bivector b =
      toBivector(random.uniform(0.3, 1.0) * pointPair(random.vec3(1.0), random.vec3(1.0)));
    const double s = scalarSquare(b);
    ASSERT_GT(s, 0.0);
    const Bivector big = (30.0 / std::sqrt(s)) * b; // sqrt(s) = 30 > threshold
    Vec3 scaled, unscaled;
    const Vec3 p = random.vec3(2.0);
    ASSERT_TRUE(sandwichPoint(expExact(big), p, scaled));
    ASSERT_TRUE(sandwichPoint(expExact(big, ExpScaling::None), p, unscaled));
    EXPECT_TRUE(cgatest::pointsNear(scaled, unscaled, 1e-9));
  }
}

TEST(Exponential, NonFiniteInputGivesNaN)
{
  Bivector b;
  b[Bivector::E1NO] = std::numeric_limits<double>::quiet_NaN();
  for (const Even& k : { expPaper(b), expExact(b) })
  {
    EXPECT_TRUE(std::isnan(k.scalar));
    for (double x : k.bivector.c)
    {
      EXPECT_TRUE(std::isnan(x));
    }
    for (double x : k.quadvector.c)
    {
      EXPECT_TRUE(std::isnan(x));
    }
    Vec3 out{ 1, 2, 3 };
    EXPECT_FALSE(sandwichPoint(k, { 0.5, 0.5, 0.5 }, out));
    EXPECT_EQ(out.x, 1.0);
  }
  b[Bivector::E1NO] = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(expExact(b).isFinite());
  InvariantDecomposition split;
  EXPECT_FALSE(invariantDecomposition(b, split));
}
} // namespace

namespace
{
bool sameEven(const Even& a, const Even& b)
{
  bool same = a.scalar == b.scalar;
  for (int i = 0; i < Bivector::Count; ++i)
  {
    same = same && a.bivector[i] == b.bivector[i];
  }
  for (int i = 0; i < Quadvector::Count; ++i)
  {
    same = same && a.quadvector[i] == b.quadvector[i];
  }
  return same;
}

TEST(Exponential, OfANullPairAtTheOriginIsOnePlusItToTheBit)
{
  // The Hopf boost 1 + k tau(0, v) goes through expExact: its squares vanish exactly.
  Random random(95);
  for (int n = 0; n < 1000; ++n)
  {
    const double k = std::ldexp(random.uniform(-1.0, 1.0), static_cast<int>(random.uniform(-20, 20)));
    const Bivector b = k * nullPointPairCompact({ 0, 0, 0 }, random.unit());
    Even onePlus = Even::fromBivector(b);
    onePlus.scalar = 1.0;
    ASSERT_TRUE(sameEven(expExact(b), onePlus)) << "k " << k;
  }
}

TEST(Exponential, PaperRuleOfARotationIsCosPlusSinToTwoUlps)
{
  // The Hopf rotations cos a + sin a U go through expPaper: from x = 0.01 on the kernel's cos and
  // sin (SLEEF's 1-ulp functions, or libm without SLEEF), the power series of both below; libm's
  // std::cos and std::sin, also within an ulp, are the reference: two ulps of a number <= 1.
  const Bivector planes[] = { toBivector(Multivector::basisBlade(blade::e1 | blade::e2)),
                              toBivector(Multivector::basisBlade(blade::e1 | blade::e3)),
                              toBivector(Multivector::basisBlade(blade::e2 | blade::ep)) };
  Random random(96);
  for (const Bivector& u : planes)
  {
    ASSERT_EQ(scalarSquare(u), -1.0);
    for (int n = 0; n < 2000; ++n)
    {
      const double a = n % 2 ? random.uniform(-7.0, 7.0) : random.uniform(-0.02, 0.02);
      const Even k = expPaper(a * u);
      Even expected = Even::fromBivector(std::sin(a) * u);
      expected.scalar = std::cos(a);
      EXPECT_LE((k - expected).maxAbs(), 4.5e-16) << "a " << a;
    }
  }
}
} // namespace
