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
