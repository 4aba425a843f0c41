// The compact null-basis types: their layout, conversions and products against the Multivector.
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/Conformal.h"

namespace
{
using namespace cga;
using cgatest::Random;
using cgatest::relativeDifference;

TEST(Compact, BivectorComponentsAreTheNamedWedges)
{
  const Multivector expected[Bivector::Count] = { e1() ^ e2(), e1() ^ e3(), e2() ^ e3(),
                                                  e1() ^ no(), e2() ^ no(), e3() ^ no(),
                                                  e1() ^ ni(), e2() ^ ni(), e3() ^ ni(),
                                                  no() ^ ni() };
  for (int i = 0; i < Bivector::Count; ++i)
  {
    Bivector b;
    b[i] = 1.0;
    EXPECT_EQ(toMultivector(b).c, expected[i].c) << "component " << i;
  }
}

TEST(Compact, QuadvectorAndVectorComponentsAreTheNamedWedges)
{
  const Multivector e123 = e1() ^ e2() ^ e3();
  const Multivector quads[Quadvector::Count] = { e123 ^ no(),
                                                 e123 ^ ni(),
                                                 e1() ^ e2() ^ no() ^ ni(),
                                                 e1() ^ e3() ^ no() ^ ni(),
                                                 e2() ^ e3() ^ no() ^ ni() };
  for (int i = 0; i < Quadvector::Count; ++i)
  {
    Quadvector q;
    q[i] = 1.0;
    EXPECT_EQ(toMultivector(q).c, quads[i].c) << "component " << i;
  }
  const Multivector vectors[ConformalVector::Count] = { no(), e1(), e2(), e3(), ni() };
  for (int i = 0; i < ConformalVector::Count; ++i)
  {
    ConformalVector v;
    v[i] = 1.0;
    EXPECT_EQ(toMultivector(v).c, vectors[i].c) << "component " << i;
  }
  Random random(21);
  for (int n = 0; n < 100; ++n)
  {
    const Vec3 p = random.vec3(5.0);
    EXPECT_LE(relativeDifference(toMultivector(ConformalVector::point(p)), up(p)), 1e-15);
  }
}

TEST(Compact, ConversionsRoundTrip)
{
  Random random(22);
  for (int n = 0; n < 500; ++n)
  {
    const Multivector m = random.multivector(2.0);
    EXPECT_LE(relativeDifference(toMultivector(toBivector(m)), m.grade(2)), 1e-15);
    EXPECT_LE(relativeDifference(toMultivector(toQuadvector(m)), m.grade(4)), 1e-15);
    EXPECT_LE(relativeDifference(toMultivector(toConformalVector(m)), m.grade(1)), 1e-15);
    EXPECT_LE(relativeDifference(toMultivector(toEven(m)), m.grade(0) + m.grade(2) + m.grade(4)),
              1e-15);
    const Even k = random.even(2.0);
    const Even back = toEven(toMultivector(k));
    EXPECT_LE(relativeDifference(back, k), 1e-15);
    const Bivector b = random.bivector(2.0);
    EXPECT_LE(relativeDifference(toBivector(toMultivector(b)), b), 1e-15);
  }
}

TEST(Compact, ArithmeticIsComponentWise)
{
  Random random(23);
  const Bivector a = random.bivector(1.0), b = random.bivector(1.0);
  const Bivector c = 2.0 * a - b / 4.0 + (-a);
  for (int i = 0; i < Bivector::Count; ++i)
  {
    EXPECT_DOUBLE_EQ(c[i], a[i] - b[i] / 4.0);
  }
  const Even k = random.even(1.0), l = random.even(1.0);
  EXPECT_LE(
    relativeDifference(toMultivector(3.0 * k - l), 3.0 * toMultivector(k) - toMultivector(l)),
    1e-15);
  Bivector withNan = a;
  withNan[Bivector::E2NI] = std::nan("");
  EXPECT_FALSE(withNan.isFinite());
  EXPECT_TRUE(std::isnan(withNan.maxAbs()));
  EXPECT_TRUE(a.isFinite());
}

TEST(Compact, ProductsMatchTheFullAlgebra)
{
  Random random(24);
  for (int n = 0; n < 1000; ++n)
  {
    const Even a = random.even(1.5), b = random.even(1.5);
    const Multivector ma = toMultivector(a), mb = toMultivector(b);
    EXPECT_LE(relativeDifference(a * b, toEven(ma * mb)), 1e-14);
    // The product of even elements has no odd part.
    EXPECT_LE((ma * mb).grade(1).maxAbs() + (ma * mb).grade(3).maxAbs() +
                (ma * mb).grade(5).maxAbs(),
              1e-14);
    EXPECT_LE(relativeDifference(reverse(a), toEven(ma.reverse())), 1e-15);

    const Bivector x = random.bivector(1.5), y = random.bivector(1.5);
    const Multivector mx = toMultivector(x), my = toMultivector(y);
    EXPECT_LE(relativeDifference(x * y, toEven(mx * my)), 1e-14);
    EXPECT_NEAR(scalarSquare(x), scalarProduct(mx, mx), 1e-14);
    EXPECT_LE(relativeDifference(toMultivector(wedge(x, y)), mx ^ my), 1e-14);

    const Quadvector q = random.quadvector(1.5);
    const Multivector mq = toMultivector(q);
    EXPECT_NEAR(scalarSquare(q), (mq * mq).scalarPart(), 1e-14);
    // In five dimensions a 4-vector squares to a scalar.
    EXPECT_LE((mq * mq - Multivector::scalar((mq * mq).scalarPart())).maxAbs(), 1e-14);
    EXPECT_LE(relativeDifference(toMultivector(rightContraction(q, x)), (mq * mx).grade(2)), 1e-14);

    const ConformalVector p = toConformalVector(random.multivector(2.0));
    const ConformalVector r = toConformalVector(random.multivector(2.0));
    EXPECT_NEAR(dot(p, r), dot(toMultivector(p), toMultivector(r)), 1e-14);
  }
}
} // namespace
