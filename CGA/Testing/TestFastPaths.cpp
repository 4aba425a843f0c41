// The hot-loop paths (PointPairs.h, PointSandwich.h) against the full Multivector products.
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/Conformal.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace
{
using namespace cga;
using cgatest::pointsNear;
using cgatest::Random;
using cgatest::relativeDifference;

TEST(FastPaths, NullPointPairClosedFormMatchesTheWedge)
{
  Random random(31);
  for (int n = 0; n < 5000; ++n)
  {
    const Vec3 x = random.vec3(3.0);
    const Vec3 v = random.uniform(0.01, 3.0) * random.unit();
    const Multivector expected = nullPointPair(x, v);
    EXPECT_LE(relativeDifference(toMultivector(nullPointPairCompact(x, v)), expected), 1e-14);
  }
  // Degenerate inputs: zero direction gives zero, a pair at the origin is the tangent no ^ v.
  EXPECT_EQ(nullPointPairCompact({ 1, 2, 3 }, {}).maxAbs(), 0.0);
  EXPECT_EQ(toMultivector(nullPointPairCompact({}, { 0.5, -1, 2 })).c, tangent({ 0.5, -1, 2 }).c);
}

TEST(FastPaths, TranslatedBivectorClosedFormMatchesTheVersorProduct)
{
  // T(d) b ~T(d) in the full algebra, T(d) = 1 - d ni / 2 (Conformal.h's translator).
  Random random(34);
  double worst = 0.0;
  for (int n = 0; n < 5000; ++n)
  {
    const Bivector b = random.bivector(2.0);
    const Vec3 d = (n % 5 == 4 ? 1e3 : 3.0) * random.vec3(1.0);
    const Multivector t = translator(d);
    const Multivector expected = (t * toMultivector(b) * t.reverse()).grade(2);
    const double reach = 1.0 + norm(d);
    const double error =
      (toMultivector(translatedBivector(b, d)) - expected).coefficientNorm() /
      (b.maxAbs() * reach * reach);
    worst = cgatest::worseOf(worst, error);
  }
  EXPECT_LE(worst, 1e-15);
  // Exact cases: no move; the translation parts e_i^ni, which a translation keeps; and a null
  // point pair at the origin moved to x is the one at x.
  const Bivector b = random.bivector(2.0);
  EXPECT_EQ(translatedBivector(b, {}).c, b.c);
  Bivector moments;
  moments[Bivector::E1NI] = 0.5;
  moments[Bivector::E2NI] = -2.0;
  moments[Bivector::E3NI] = 3.0;
  EXPECT_EQ(translatedBivector(moments, { 1.5, -7.0, 0.25 }).c, moments.c);
  for (int n = 0; n < 1000; ++n)
  {
    const Vec3 x = random.vec3(3.0), v = random.vec3(2.0);
    EXPECT_LE(relativeDifference(translatedBivector(nullPointPairCompact({}, v), x),
                nullPointPairCompact(x, v)),
      1e-14);
  }
}

TEST(FastPaths, NullPointPairSquaresToZero)
{
  Random random(32);
  for (int n = 0; n < 1000; ++n)
  {
    const Bivector tau = nullPointPairCompact(random.vec3(3.0), random.vec3(2.0));
    const Even square = tau * tau;
    EXPECT_LE(square.maxAbs(), 1e-14 * tau.maxAbs() * tau.maxAbs());
  }
}

TEST(FastPaths, WeightedSumsMatchTheMultivectorSum)
{
  Random random(33);
  for (int n = 0; n < 200; ++n)
  {
    const int count = 1 + n % 16;
    std::vector<Vec3> locations, directions;
    std::vector<double> weights;
    std::vector<Bivector> pairs;
    Multivector expected;
    for (int i = 0; i < count; ++i)
    {
      locations.push_back(random.vec3(2.0));
      directions.push_back(random.unit());
      weights.push_back(random.uniform(-1.0, 1.0));
      pairs.push_back(nullPointPairCompact(locations.back(), directions.back()));
      expected += weights.back() * nullPointPair(locations.back(), directions.back());
    }
    const Bivector sum = weightedSum(pairs.data(), weights.data(), pairs.size());
    const Bivector direct =
      weightedNullPointPairSum(locations.data(), directions.data(), weights.data(), pairs.size());
    EXPECT_LE(relativeDifference(toMultivector(sum), expected), 1e-14);
    EXPECT_LE(relativeDifference(toMultivector(direct), expected), 1e-14);
  }
  EXPECT_EQ(weightedSum(nullptr, nullptr, 0).maxAbs(), 0.0);
}

// The reference: the full 32-coefficient products, K up(p) ~K, grade 1.
Multivector referenceImage(const Even& k, Vec3 p)
{
  return sandwich(toMultivector(k), up(p)).grade(1);
}

TEST(FastPaths, SandwichOfRandomEvenElementsMatchesTheFullProduct)
{
  // Random scalar + bivector + 4-vector: not versors, so the grade-1 projection matters.
  Random random(34);
  int comparedPoints = 0;
  const int cases = 5000;
  for (int n = 0; n < cases; ++n)
  {
    const Even k = random.even(1.0);
    const Vec3 p = random.vec3(2.0);
    const Multivector expected = referenceImage(k, p);
    const ConformalVector image = sandwichGrade1(k, ConformalVector::point(p));
    EXPECT_LE(relativeDifference(toMultivector(image), expected), 1e-13);
    // Points: compare where the weight is not a cancellation remnant.
    const double alpha = image.weight();
    if (std::fabs(alpha) > 1e-2 * expected.coefficientNorm())
    {
      ++comparedPoints;
      Vec3 fast;
      ASSERT_TRUE(sandwichPoint(k, p, fast));
      const Vec3 reference = down(expected);
      const double scale = expected.coefficientNorm() / std::fabs(alpha);
      EXPECT_LE(cgatest::distance(fast, reference),
                1e-13 * scale * std::max(1.0, cgatest::maxNorm(reference)));
    }
  }
  EXPECT_GT(comparedPoints, cases * 9 / 10);
}

TEST(FastPaths, PointMapMatchesTheSandwich)
{
  Random random(35);
  for (int n = 0; n < 300; ++n)
  {
    const Even k = random.even(1.0);
    const PointMap map(k);
    for (int i = 0; i < 10; ++i)
    {
      const Vec3 p = random.vec3(2.0);
      const ConformalVector viaMap = map.apply(ConformalVector::point(p));
      EXPECT_LE(relativeDifference(toMultivector(viaMap), referenceImage(k, p)), 1e-13);
      Vec3 a{ -7, -7, -7 }, b{ -7, -7, -7 };
      const bool okMap = map.apply(p, a);
      const bool okSandwich = sandwichPoint(k, p, b);
      EXPECT_EQ(okMap, okSandwich);
      if (okMap && std::fabs(viaMap.weight()) > 1e-2 * toMultivector(viaMap).coefficientNorm())
      {
        EXPECT_TRUE(pointsNear(a, b, 1e-12));
      }
    }
  }
}

TEST(FastPaths, PointMapHoldsEachBasisVectorsSandwichBitForBit)
{
  // Column j of the matrix is sandwichGrade1 of basis vector j, to the bit (the sign of zero too),
  // for versors of every size (entries from 1e-300 to 1e300, so that products underflow and
  // overflow), with zero and negative-zero components, NaN and infinity (NaN where the sandwich
  // gives NaN).
  Random random(36);
  std::vector<Even> versors;
  for (double size : { 1.0, 1e-5, 1e5, 1e-160, 1e150, 1e-300, 1e300 })
  {
    for (int n = 0; n < 40; ++n)
    {
      versors.push_back(random.even(size));
    }
  }
  Even sparse = Even::identity();
  sparse.scalar = -0.0;
  sparse.bivector[Bivector::E12] = -0.0;
  sparse.bivector[Bivector::E3NI] = 2.5;
  versors.push_back(sparse);
  Even notFinite = random.even(1.0);
  notFinite.bivector[Bivector::E1NO] = std::numeric_limits<double>::quiet_NaN();
  versors.push_back(notFinite);
  notFinite.bivector[Bivector::E1NO] = std::numeric_limits<double>::infinity();
  versors.push_back(notFinite);
  for (const Even& k : versors)
  {
    const PointMap map(k);
    for (int j = 0; j < ConformalVector::Count; ++j)
    {
      ConformalVector basis;
      basis[j] = 1.0;
      const ConformalVector image = sandwichGrade1(k, basis);
      for (int i = 0; i < ConformalVector::Count; ++i)
      {
        const double entry = map.matrix()[i * ConformalVector::Count + j];
        const double expected = image[i];
        if (std::isnan(expected)) // which NaN an operation passes on is the compiler's choice
        {
          EXPECT_TRUE(std::isnan(entry)) << "entry (" << i << ", " << j << ")";
          continue;
        }
        EXPECT_EQ(0, std::memcmp(&entry, &expected, sizeof entry))
          << "entry (" << i << ", " << j << "): " << entry << " against " << expected;
      }
    }
  }
}

TEST(FastPaths, PointMapsOfVersorsAreEachVersorsPointMapBitForBit)
{
  // PointMaps made from versors (eight maps side by side) hold PointMap(versor) for each, to the
  // bit (NaN where it has NaN), say which have only finite entries, and apply them as PointMaps
  // made from those maps do; 0 to 21 versors of sizes 1e-300 to 1e300, one with NaN and one with
  // infinity.
  Random random(38);
  const double sizes[] = { 1.0, 1e-300, 1e300, 1e-5, 1e150 };
  for (std::size_t count : { 0, 1, 7, 8, 9, 16, 21 })
  {
    std::vector<Even> versors;
    std::vector<PointMap> maps;
    for (std::size_t i = 0; i < count; ++i)
    {
      Even k = random.even(sizes[i % 5]);
      if (i == 4)
      {
        k.bivector[Bivector::E2NI] = std::numeric_limits<double>::quiet_NaN();
      }
      if (i == 6)
      {
        k.quadvector[0] = std::numeric_limits<double>::infinity();
      }
      versors.push_back(k);
      maps.emplace_back(k);
    }
    const PointMaps fromVersors(versors.data(), versors.size());
    const PointMaps fromMaps(maps.data(), maps.size());
    ASSERT_EQ(fromVersors.size(), count);
    for (std::size_t i = 0; i < count; ++i)
    {
      const std::array<double, 25> got = fromVersors.map(i).matrix();
      const std::array<double, 25>& expected = maps[i].matrix();
      const bool finite =
        std::all_of(expected.begin(), expected.end(), [](double v) { return std::isfinite(v); });
      EXPECT_EQ(fromVersors.isFinite(i), finite) << "map " << i;
      EXPECT_EQ(fromMaps.isFinite(i), finite) << "map " << i;
      for (std::size_t e = 0; e < 25; ++e)
      {
        if (std::isnan(expected[e]))
        {
          EXPECT_TRUE(std::isnan(got[e])) << "map " << i << " entry " << e;
          continue;
        }
        EXPECT_EQ(0, std::memcmp(&got[e], &expected[e], sizeof got[e])) << "map " << i << " entry " << e;
      }
    }
    for (int trial = 0; trial < 5; ++trial)
    {
      const Vec3 p = random.vec3(2.0);
      std::vector<Vec3> a(count + 1, Vec3{ 42, 42, 42 }), b(count + 1, Vec3{ 42, 42, 42 });
      std::unique_ptr<bool[]> mappedA(new bool[count + 1]), mappedB(new bool[count + 1]);
      fromVersors.apply(p, a.data(), mappedA.get());
      fromMaps.apply(p, b.data(), mappedB.get());
      for (std::size_t i = 0; i < count; ++i)
      {
        ASSERT_EQ(mappedA[i], mappedB[i]) << "map " << i;
        EXPECT_EQ(0, std::memcmp(&a[i], &b[i], sizeof a[i])) << "map " << i;
      }
    }
  }
}

TEST(FastPaths, SandwichFailsCleanlyAtInfinityAndOnNaN)
{
  // K = 1 + no e1 sends -e1 to infinity (docs/conventions.md section 2: -v/|v|^2).
  Even k = Even::identity();
  k.bivector = toBivector(no() * e1());
  Vec3 out{ 42, 42, 42 };
  EXPECT_FALSE(sandwichPoint(k, { -1, 0, 0 }, out));
  EXPECT_EQ(out.x, 42.0);
  EXPECT_FALSE(PointMap(k).apply({ -1, 0, 0 }, out));
  EXPECT_EQ(out.x, 42.0);
  // Elsewhere it works.
  EXPECT_TRUE(sandwichPoint(k, { 1, 0, 0 }, out));
  EXPECT_TRUE(pointsNear(out, { 0.5, 0, 0 }, 1e-15)); // (x + v|x|^2)/(1 + 2 v.x + |v|^2|x|^2)

  Even bad = k;
  bad.bivector[Bivector::E12] = std::numeric_limits<double>::quiet_NaN();
  out = { 42, 42, 42 };
  EXPECT_FALSE(sandwichPoint(bad, { 1, 2, 3 }, out));
  EXPECT_FALSE(PointMap(bad).apply({ 1, 2, 3 }, out));
  EXPECT_FALSE(sandwichPoint(k, { std::nan(""), 0, 0 }, out));
  EXPECT_EQ(out.x, 42.0);
}

TEST(FastPaths, PointMapsGiveEachMapsImageBitForBit)
{
  // PointMaps applies many maps at once (eight side by side): each image and flag is that map's
  // apply(p, out), to the bit, with out untouched where the flag is false; among the maps one
  // that sends the point to infinity (K = 1 + no e1 at p = -e1) and one with a NaN; 0 to 21 maps.
  Random random(37);
  Even toInfinity = Even::identity();
  toInfinity.bivector = toBivector(no() * e1());
  Even notANumber = toInfinity;
  notANumber.bivector[Bivector::E12] = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t count : { 0, 1, 7, 8, 9, 16, 21 })
  {
    std::vector<PointMap> maps;
    for (std::size_t i = 0; i < count; ++i)
    {
      maps.emplace_back(i == 3 ? toInfinity : i == 5 ? notANumber : random.even(1.0));
    }
    const PointMaps all(maps.data(), maps.size());
    EXPECT_EQ(all.size(), count);
    for (int trial = 0; trial < 20; ++trial)
    {
      const Vec3 p = trial == 0 ? Vec3{ -1, 0, 0 } : random.vec3(2.0);
      std::vector<Vec3> out(count + 1, Vec3{ 42, 42, 42 });
      std::unique_ptr<bool[]> mapped(new bool[count + 1]);
      all.apply(p, out.data(), mapped.get());
      for (std::size_t i = 0; i < count; ++i)
      {
        Vec3 expected{ 42, 42, 42 };
        ASSERT_EQ(mapped[i], maps[i].apply(p, expected)) << "map " << i << " of " << count;
        EXPECT_EQ(0, std::memcmp(&out[i], &expected, sizeof expected)) << "map " << i;
      }
      EXPECT_EQ(out[count].x, 42.0); // nothing written past the maps
      if (count > 5)
      {
        EXPECT_FALSE(mapped[5]);
        EXPECT_EQ(trial != 0, mapped[3]);
      }
    }
  }
}

TEST(FastPaths, NullBasisKeepsPrecisionFarFromTheOrigin)
{
  // A translation of a point at distance 1e5: the weight -ni.P stays exactly 1 in the null basis,
  // where the orthonormal path cancels e- and e+ coefficients of size 5e9.
  const Vec3 p{ 1e5, -2e4, 3e4 };
  const Vec3 d{ 0.125, 0.25, -0.5 };
  const Even t = toEven(translator(d));
  Vec3 out;
  ASSERT_TRUE(sandwichPoint(t, p, out));
  EXPECT_LE(cgatest::distance(out, p + d), 1e-10);
  EXPECT_EQ(sandwichGrade1(t, ConformalVector::point(p)).weight(), 1.0);
}
} // namespace
