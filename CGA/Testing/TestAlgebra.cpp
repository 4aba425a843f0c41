// Identities of the reference algebra (Multivector.h, Conformal.h) and of the null basis.
#include "TestSupport.h"

#include "cga/Conformal.h"
#include "cga/NullBasis.h"

namespace
{
using namespace cga;
using cgatest::Random;
using cgatest::relativeDifference;

Multivector ep()
{
  return Multivector::basisBlade(blade::ep);
}
Multivector em()
{
  return Multivector::basisBlade(blade::em);
}

TEST(Algebra, SquaresOfTheOrthonormalBasis)
{
  EXPECT_EQ((e1() * e1()).c, Multivector::scalar(1.0).c);
  EXPECT_EQ((e2() * e2()).c, Multivector::scalar(1.0).c);
  EXPECT_EQ((e3() * e3()).c, Multivector::scalar(1.0).c);
  EXPECT_EQ((ep() * ep()).c, Multivector::scalar(1.0).c);
  EXPECT_EQ((em() * em()).c, Multivector::scalar(-1.0).c);
  // Distinct basis vectors anticommute.
  EXPECT_EQ((e1() * em()).c, (-(em() * e1())).c);
  EXPECT_EQ((ep() * em()).c, (-(em() * ep())).c);
}

TEST(Algebra, NullVectors)
{
  EXPECT_EQ(dot(no(), ni()), -1.0);
  EXPECT_EQ((no() * ni()).scalarPart(), -1.0);
  EXPECT_EQ((no() * no()).maxAbs(), 0.0);
  EXPECT_EQ((ni() * ni()).maxAbs(), 0.0);
  // no = (e- + e+)/2, ni = e- - e+, and no ^ ni = e+ e-.
  EXPECT_EQ(no().c, (0.5 * (em() + ep())).c);
  EXPECT_EQ(ni().c, (em() - ep()).c);
  EXPECT_EQ(minkowskiPlane().c, (ep() * em()).c);
}

TEST(Algebra, InnerProductOfPointsIsMinusHalfSquaredDistance)
{
  Random random(11);
  for (int i = 0; i < 1000; ++i)
  {
    const Vec3 p = random.vec3(3.0), q = random.vec3(3.0);
    const double expected = -0.5 * norm2(p - q);
    EXPECT_NEAR(dot(up(p), up(q)), expected, 1e-13 * (1.0 + norm2(p) + norm2(q)));
    EXPECT_LE((up(p) * up(p)).maxAbs(), 1e-14 * (1.0 + norm2(p) * norm2(p)));
  }
}

TEST(Algebra, GeometricProductIsAssociative)
{
  Random random(12);
  for (int i = 0; i < 200; ++i)
  {
    const Multivector a = random.multivector(1.0), b = random.multivector(1.0),
                      c = random.multivector(1.0);
    EXPECT_LE(relativeDifference((a * b) * c, a * (b * c)), 1e-14);
  }
}

TEST(Algebra, ReverseOfAProduct)
{
  Random random(13);
  for (int i = 0; i < 200; ++i)
  {
    const Multivector a = random.multivector(1.0), b = random.multivector(1.0);
    EXPECT_LE(relativeDifference((a * b).reverse(), b.reverse() * a.reverse()), 1e-14);
  }
  // Reverse signs by grade: + + - - + +.
  const int expected[6] = { 1, 1, -1, -1, 1, 1 };
  for (unsigned mask = 0; mask < kBladeCount; ++mask)
  {
    EXPECT_EQ(Multivector::basisBlade(mask).reverse()[mask], expected[bladeGrade(mask)]);
  }
}

TEST(Algebra, OuterAndContractionAreGradedPartsOfTheProduct)
{
  Random random(14);
  for (int i = 0; i < 200; ++i)
  {
    const Multivector a = random.multivector(1.0).grade(1), b = random.multivector(1.0).grade(1);
    const Multivector bv = random.multivector(1.0).grade(2);
    const Multivector ab = a * b;
    // Vectors: a b = a.b + a ^ b.
    EXPECT_LE(relativeDifference(ab, Multivector::scalar(dot(a, b)) + (a ^ b)), 1e-14);
    EXPECT_LE(relativeDifference(leftContraction(a, b), ab.grade(0)), 1e-14);
    EXPECT_LE(relativeDifference(a ^ b, ab.grade(2)), 1e-14);
    EXPECT_LE(relativeDifference(a ^ b, -(b ^ a)), 1e-15);
    // Vector and bivector: a B = a _| B + a ^ B.
    const Multivector aB = a * bv;
    EXPECT_LE(relativeDifference(leftContraction(a, bv), aB.grade(1)), 1e-14);
    EXPECT_LE(relativeDifference(a ^ bv, aB.grade(3)), 1e-14);
    EXPECT_NEAR(scalarProduct(a, b), ab.scalarPart(), 1e-14);
  }
}

TEST(Algebra, DualAndUndualRoundTrip)
{
  const Multivector i = Multivector::basisBlade(blade::pseudoscalar);
  EXPECT_EQ((i * i).c, Multivector::scalar(-1.0).c);
  Random random(15);
  for (int n = 0; n < 100; ++n)
  {
    const Multivector m = random.multivector(1.0);
    EXPECT_LE(relativeDifference(m.dual().undual(), m), 1e-15);
    EXPECT_LE(relativeDifference(m.undual().dual(), m), 1e-15);
  }
  // The dual of a basis blade is +-1 times its complement.
  for (unsigned mask = 0; mask < kBladeCount; ++mask)
  {
    const Multivector d = Multivector::basisBlade(mask).dual();
    EXPECT_EQ(std::fabs(d[mask ^ blade::pseudoscalar]), 1.0);
    EXPECT_EQ(d.coefficientNorm(), 1.0);
  }
}

TEST(NullBasis, BladeProductsMatchTheOrthonormalAlgebra)
{
  for (unsigned a = 0; a < kBladeCount; ++a)
  {
    for (unsigned b = 0; b < kBladeCount; ++b)
    {
      NullTerm terms[2];
      const int count = nullBladeProduct(a, b, terms);
      Multivector product;
      for (int t = 0; t < count; ++t)
      {
        product += terms[t].coefficient * nullBladeToMultivector(terms[t].blade);
      }
      const Multivector expected = nullBladeToMultivector(a) * nullBladeToMultivector(b);
      EXPECT_EQ(product.c, expected.c) << "blades " << a << " " << b;
    }
  }
}

TEST(NullBasis, BladesAreTheNamedWedges)
{
  EXPECT_EQ(nullBladeToMultivector(nullblade::no).c, no().c);
  EXPECT_EQ(nullBladeToMultivector(nullblade::ni).c, ni().c);
  EXPECT_EQ(nullBladeToMultivector(nullblade::E).c, (no() ^ ni()).c);
  EXPECT_EQ(nullBladeToMultivector(nullblade::e1 | nullblade::no).c, (e1() ^ no()).c);
  EXPECT_EQ(nullBladeToMultivector(nullblade::e2 | nullblade::e3 | nullblade::ni).c,
            (e2() ^ e3() ^ ni()).c);
  EXPECT_EQ(nullBladeToMultivector(31u).c, (e1() ^ e2() ^ e3() ^ no() ^ ni()).c);
}

TEST(NullBasis, CoefficientConversionRoundTrip)
{
  Random random(16);
  for (int n = 0; n < 100; ++n)
  {
    const Multivector m = random.multivector(1.0);
    double null[kBladeCount];
    Multivector back;
    orthonormalToNull(m.c.data(), null);
    nullToOrthonormal(null, back.c.data());
    EXPECT_LE(relativeDifference(back, m), 1e-15);
    // The null coefficients rebuild m blade by blade.
    Multivector rebuilt;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      rebuilt += null[i] * nullBladeToMultivector(i);
    }
    EXPECT_LE(relativeDifference(rebuilt, m), 1e-15);
  }
}
} // namespace

namespace
{
// |a| in long double, whose exponent range holds the squares of 1e+-300 (an independent reference).
long double longDoubleNorm(Vec3 a)
{
  const long double x = a.x, y = a.y, z = a.z;
  return std::sqrt(x * x + y * y + z * z);
}
} // namespace

TEST(Vec3, LengthsAndDirectionsOfHugeAndTinyVectorsDoNotOverflowOrUnderflow)
{
  if (std::numeric_limits<long double>::max_exponent < 4 * std::numeric_limits<double>::max_exponent)
  {
    GTEST_SKIP() << "long double cannot hold the squares of the reference";
  }
  Random random(15);
  for (const double scale : { 1e-320, 1e-300, 1e-200, 1e-160, 1e160, 1e200, 1e300 })
  {
    for (int k = 0; k < 50; ++k)
    {
      const Vec3 a = scale * random.vec3(1.0);
      const long double length = longDoubleNorm(a);
      ASSERT_GT(length, 0.0L);
      const double tolerance = 4e-16;
      // A subnormal length is rounded to the subnormal grid: at most half its spacing off.
      const long double lengthTolerance =
        std::max<long double>(tolerance * length, 0.5L * std::numeric_limits<double>::denorm_min());
      EXPECT_LE(std::fabs(norm(a) - length), lengthTolerance) << "scale " << scale;
      const Vec3 u = normalized(a);
      EXPECT_NEAR(norm(u), 1.0, tolerance) << "scale " << scale;
      for (int i = 0; i < 3; ++i)
      {
        EXPECT_NEAR(u[i], static_cast<double>(a[i] / length), tolerance) << "scale " << scale;
      }
    }
  }
  // The largest finite vector and the smallest subnormal have a length and a direction.
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(norm(Vec3{ big, 0, 0 }), big);
  EXPECT_EQ(norm(Vec3{ big, big, big }), std::numeric_limits<double>::infinity()); // |a| itself overflows
  EXPECT_NEAR(normalized(Vec3{ big, big, big }).x, 1.0 / std::sqrt(3.0), 1e-16);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(norm(Vec3{ 0, tiny, 0 }), tiny);
  EXPECT_EQ(normalized(Vec3{ 0, 0, -tiny }).z, -1.0);
}

TEST(Vec3, OrdinaryLengthsKeepThePlainFormulaBitForBit)
{
  Random random(16);
  for (const double scale : { 1e-130, 1e-3, 1.0, 1e6, 1e150 })
  {
    for (int k = 0; k < 200; ++k)
    {
      const Vec3 a = scale * random.vec3(1.0);
      const double plain = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
      EXPECT_EQ(norm(a), plain);
      const Vec3 u = normalized(a);
      EXPECT_EQ(u.x, a.x / plain);
      EXPECT_EQ(u.y, a.y / plain);
      EXPECT_EQ(u.z, a.z / plain);
    }
  }
}

TEST(Vec3, ZeroAndNonFiniteVectorsHaveNoDirection)
{
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec3 a : { Vec3{}, Vec3{ NAN, 1, 0 }, Vec3{ inf, 0, 0 }, Vec3{ 1e300, -inf, 1 } })
  {
    const Vec3 u = normalized(a);
    EXPECT_EQ(u.x, 0.0);
    EXPECT_EQ(u.y, 0.0);
    EXPECT_EQ(u.z, 0.0);
  }
  EXPECT_EQ(norm(Vec3{}), 0.0);
}
