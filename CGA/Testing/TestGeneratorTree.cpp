// The far-field approximation of PointPairField::setTolerance (docs/conventions.md section 3
// item 14) against the direct sum (tolerance 0): the a-priori bound on the image's first-order
// error, |firstOrderMotion(B_tree(p) - B(p), p)| <= t V (V the field's displacement scale per
// unit strength), must hold at every point of random and adversarial configurations, and the
// images under the map must follow it.
#include "TestSupport.h"

#include "cga/PointPairField.h"
#include "cga/PointPairs.h"

#include "../src/GeneratorTree.h"
#include "../src/TreeRemainder.h"

#include <cstring>
#include <limits>

namespace
{
using namespace cgatest;

constexpr double kFalloff = 1.0;
// The tests build trees over a few hundred generators (the default crossover is far above).
constexpr std::size_t kTreeFrom = 256;
constexpr double kEpsilon = 0.05;

// The largest first-order image error per unit strength, |firstOrderMotion(B_tree - B, p)|, over
// t V (the bound: 1), and the largest one over t V plus the rounding the bound leaves out
// (kRounding A(p) times the motion of a bivector of unit components at r = |p - c|).
struct Worst
{
  double relativeError = 0.0;
  double boundedError = 0.0;
};

// The rounding the bound leaves out: sums of up to M terms and the moments' shifts.
constexpr double kRounding = 1e-12;

// A(p) = sum_i |w_i G_i|_max / (k |p - x_i|^2 + eps) for the generators of a field centered at c.
double absoluteSum(const std::vector<FieldGenerator>& generators, Vec3 c, Vec3 p, double falloff, double epsilon)
{
  double a = 0.0;
  for (const FieldGenerator& g : generators)
  {
    const Vec3 d = p - g.location;
    a += translatedBivector(g.weight * g.bivector, -1.0 * c).maxAbs() / (falloff * dot(d, d) + epsilon);
  }
  return a;
}

Worst worstRelativeError(const std::vector<FieldGenerator>& generators,
                         const std::vector<Vec3>& points,
                         double tolerance,
                         double falloff = kFalloff,
                         double epsilon = kEpsilon)
{
  const PointPairField direct(generators.data(), generators.size(), falloff, epsilon);
  PointPairField tree(generators.data(), generators.size(), falloff, epsilon);
  EXPECT_TRUE(tree.setTolerance(tolerance, kTreeFrom, 0.0));
  EXPECT_GT(tree.treeDegree(), 0) << "the tree must be in use (" << generators.size() << " generators)";
  const double budget = tree.tolerance() * tree.treeDisplacementScale();
  EXPECT_TRUE(std::isfinite(budget));
  const Vec3 c = direct.center();
  Worst worst;
  for (const Vec3& p : points)
  {
    // In the field's frame (generatorAt moves B back to space).
    const Bivector exact = translatedBivector(direct.generatorAt(p), -1.0 * c);
    const Bivector approximate = translatedBivector(tree.generatorAt(p), -1.0 * c);
    const double error = norm(firstOrderMotion(approximate - exact, p - c));
    EXPECT_TRUE(std::isfinite(error));
    const double r = norm(p - c);
    const double rounding = kRounding * absoluteSum(generators, c, p, falloff, epsilon) *
      (2.0 * std::sqrt(3.0) + 4.0 * r + std::sqrt(3.0) * r * r);
    worst.relativeError = worseOf(worst.relativeError, error / budget);
    worst.boundedError = worseOf(worst.boundedError, error / (budget + rounding));
  }
  return worst;
}

std::vector<FieldGenerator> randomPointPairs(Random& random, std::size_t count, Vec3 center, double half)
{
  std::vector<FieldGenerator> generators;
  for (std::size_t i = 0; i < count; ++i)
  {
    generators.push_back(FieldGenerator::pointPair(
      center + random.vec3(half), random.vec3(1.0), random.uniform(-0.4, 0.4)));
  }
  return generators;
}

std::vector<Vec3> randomPoints(Random& random, std::size_t count, Vec3 center, double half)
{
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < count; ++i)
  {
    points.push_back(center + random.vec3(half));
  }
  return points;
}

TEST(GeneratorTree, RandomGeneratorsMeetTheBoundAtEveryTolerance)
{
  Random random(20261202);
  const auto generators = randomPointPairs(random, 1200, { 0.5, -0.3, 0.2 }, 2.0);
  const auto points = randomPoints(random, 200, { 0.5, -0.3, 0.2 }, 3.0);
  for (const double tolerance : { 1e-2, 1e-4, 1e-6, 1e-9 })
  {
    const Worst worst = worstRelativeError(generators, points, tolerance);
    EXPECT_LE(worst.boundedError, 1.0) << "tolerance " << tolerance;
  }
  // (Scattered points over so few generators use few expansions; the dense points below check
  // that the bound is not vacuous.)
}

TEST(GeneratorTree, ClusteredGeneratorsOfEveryKindMeetTheBound)
{
  Random random(7);
  std::vector<FieldGenerator> generators;
  const Vec3 clusters[] = { { -3.0, 0.0, 0.0 }, { 3.0, 1.0, 0.0 }, { 0.0, 0.0, 4.0 } };
  for (int i = 0; i < 900; ++i)
  {
    const Vec3 at = clusters[i % 3] + random.vec3(i % 2 ? 1e-3 : 0.2);
    const auto kind = static_cast<GeneratorKind>(i % 5);
    generators.push_back(FieldGenerator::of(kind, at, random.unit(), 0.3, random.uniform(0.1, 1.0)));
  }
  // Points around the clusters, inside them and on generators.
  auto points = randomPoints(random, 150, { 0.0, 0.0, 1.0 }, 5.0);
  for (int i = 0; i < 60; ++i)
  {
    points.push_back(generators[static_cast<std::size_t>(i * 15)].location); // 60 of the 900
  }
  for (const double tolerance : { 1e-3, 1e-7 })
  {
    EXPECT_LE(worstRelativeError(generators, points, tolerance).boundedError, 1.0) << "tolerance " << tolerance;
  }
}

TEST(GeneratorTree, CoincidentGeneratorsMeetTheBound)
{
  Random random(11);
  std::vector<FieldGenerator> generators;
  for (int i = 0; i < 600; ++i)
  {
    generators.push_back(FieldGenerator::pointPair({ 1.0, 2.0, 3.0 }, random.vec3(1.0), 0.2));
  }
  auto points = randomPoints(random, 100, { 1.0, 2.0, 3.0 }, 2.0);
  points.push_back({ 1.0, 2.0, 3.0 });
  // One place: radius 0. The node's own expansion is exact, a cell's local expansion is not.
  for (const double tolerance : { 1e-2, 1e-8 })
  {
    EXPECT_LE(worstRelativeError(generators, points, tolerance).boundedError, 1.0) << "tolerance " << tolerance;
  }
}

// A cluster far smaller than the cubes of points (radius 1e-12): its multipole-to-local
// translations take the moments' copy scaled by powers of b (addSourceToLocal), since powers of
// the cube's radius over the node's would overflow; a cluster of radius 1e-3 beside it takes the
// stored moments as they are. Both must meet the bound at points near and far.
TEST(GeneratorTree, TinyClustersFarFromThePointsMeetTheBound)
{
  Random random(37);
  std::vector<FieldGenerator> generators;
  for (const double half : { 1e-12, 1e-3 })
  {
    const Vec3 center = half < 1e-6 ? Vec3{ 1.5, 0.5, 0.2 } : Vec3{ -1.0, 1.2, -0.3 };
    for (int i = 0; i < 700; ++i)
    {
      generators.push_back(
        FieldGenerator::pointPair(center + random.vec3(half), random.vec3(1.0), random.uniform(-0.4, 0.4)));
    }
  }
  const auto spread = randomPointPairs(random, 600, { 0.0, 0.0, 0.0 }, 1.0);
  generators.insert(generators.end(), spread.begin(), spread.end());
  auto points = randomPoints(random, 150, { 0.0, 0.0, 0.0 }, 2.5);
  points.push_back({ 1.5, 0.5, 0.2 });
  points.push_back({ 1.5, 0.5, 0.25 });
  for (const double tolerance : { 1e-2, 1e-8 })
  {
    EXPECT_LE(worstRelativeError(generators, points, tolerance).boundedError, 1.0) << "tolerance " << tolerance;
  }
}

// Points as dense as a mesh's (many per target cell, so that the cells' local expansions, their
// shifts to the cells below and the near field per point all take part) meet the bound, and
// each B(p) depends on p alone: the same bits from one call, from calls of other sizes and
// orders, and from map() of each point.
TEST(GeneratorTree, DensePointsMeetTheBoundAndDoNotDependOnTheCall)
{
  Random random(29);
  const auto generators = randomPointPairs(random, 8000, { 0.0, 0.0, 0.0 }, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 48; ++i)
  {
    for (int j = 0; j < 48; ++j)
    {
      // A wavy sheet through the generators and beyond them.
      const double x = -1.6 + 3.2 * i / 47.0, y = -1.6 + 3.2 * j / 47.0;
      points.push_back({ x, y, 0.2 * std::sin(3.0 * x) * std::cos(2.0 * y) });
    }
  }
  std::vector<Vec3> checked;
  for (std::size_t i = 0; i < points.size(); i += 41)
  {
    checked.push_back(points[i]);
  }
  for (const double tolerance : { 1e-2, 1e-6 })
  {
    const Worst worst = worstRelativeError(generators, checked, tolerance);
    EXPECT_LE(worst.boundedError, 1.0) << "tolerance " << tolerance;
    if (tolerance == 1e-2)
    {
      EXPECT_GT(worst.relativeError, 1e-6) << "the bound is not vacuous";
    }
  }
  PointPairField tree(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(tree.setTolerance(1e-3, kTreeFrom, 0.0));
  std::vector<double> in;
  for (const Vec3& p : points)
  {
    in.insert(in.end(), { p.x, p.y, p.z });
  }
  const std::size_t n = points.size();
  std::vector<double> whole(in.size()), chunked(in.size()), reversed(in.size());
  ASSERT_EQ(tree.mapPoints(in.data(), whole.data(), n, 0.5, ExponentialRule::Exact), 0u);
  for (std::size_t first = 0, size = 1; first < n; first += size, size = size * 3 + 1)
  {
    const std::size_t count = std::min(size, n - first);
    tree.mapPoints(in.data() + 3 * first, chunked.data() + 3 * first, count, 0.5, ExponentialRule::Exact);
  }
  std::vector<double> backwards(in.size());
  for (std::size_t i = 0; i < n; ++i)
  {
    std::copy_n(in.data() + 3 * (n - 1 - i), 3, backwards.data() + 3 * i);
  }
  tree.mapPoints(backwards.data(), reversed.data(), n, 0.5, ExponentialRule::Exact);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(whole[3 * i + k], chunked[3 * i + k]) << "point " << i;
      ASSERT_EQ(whole[3 * i + k], reversed[3 * (n - 1 - i) + k]) << "point " << i;
    }
    if (i % 97 == 0)
    {
      Vec3 single;
      ASSERT_TRUE(tree.map(points[i], 0.5, ExponentialRule::Exact, single));
      EXPECT_EQ(single.x, whole[3 * i]);
      EXPECT_EQ(single.y, whole[3 * i + 1]);
      EXPECT_EQ(single.z, whole[3 * i + 2]);
    }
  }
}

TEST(GeneratorTree, GeneratorsFarFromThePointsAndSmallSofteningMeetTheBound)
{
  Random random(13);
  const auto generators = randomPointPairs(random, 1000, { 1e4, -2e4, 5e3 }, 50.0);
  const auto points = randomPoints(random, 100, { 0.0, 0.0, 0.0 }, 10.0);
  EXPECT_LE(worstRelativeError(generators, points, 1e-6).boundedError, 1.0);
  // eps near its floor: the kernel's peaks are 1e10 high, points on generators.
  const auto near = randomPointPairs(random, 800, { 0.0, 0.0, 0.0 }, 1.0);
  std::vector<Vec3> onThem;
  for (std::size_t i = 0; i < near.size(); i += 10)
  {
    onThem.push_back(near[i].location);
  }
  EXPECT_LE(worstRelativeError(near, onThem, 1e-5, 1.0, 1e-10).boundedError, 1.0);
  // No falloff: B is the same everywhere and the root's expansion is exact.
  EXPECT_LE(worstRelativeError(near, onThem, 1e-2, 0.0, 0.5).relativeError, 1e-9);
}

TEST(GeneratorTree, PointsBeyondTheCellLatticeMeetTheBound)
{
  // Beyond 2^50 leaf cubes from the center a point is evaluated alone (GeneratorTree::evaluate);
  // nearer ones in the lattice, at any distance.
  Random random(31);
  const auto generators = randomPointPairs(random, 2000, {}, 1.0);
  const std::vector<Vec3> points = { { 1e100, 0.0, 0.0 }, { -3e40, 2.0, -1e30 }, { 1e12, -1e12, 5.0 },
                                     { 0.0, 0.0, -4e6 }, { 0.1, 0.2, 0.3 } };
  for (const double tolerance : { 1e-2, 1e-6 })
  {
    EXPECT_LE(worstRelativeError(generators, points, tolerance).boundedError, 1.0) << "tolerance " << tolerance;
  }
}

TEST(GeneratorTree, ToleranceDomainAndSmallFields)
{
  Random random(17);
  const auto generators = randomPointPairs(random, 400, {}, 1.0);
  PointPairField field(generators.data(), generators.size(), kFalloff, kEpsilon);
  EXPECT_FALSE(field.setTolerance(std::nan("")));
  EXPECT_FALSE(field.setTolerance(-1e-3));
  EXPECT_EQ(field.tolerance(), 0.0);
  EXPECT_EQ(field.treeBytes(), 0u);
  EXPECT_TRUE(field.setTolerance(std::numeric_limits<double>::infinity(), kTreeFrom));
  EXPECT_EQ(field.tolerance(), PointPairField::maximumTolerance());
  EXPECT_GT(field.treeBytes(), 0u);
  EXPECT_TRUE(field.setTolerance(0.0));
  EXPECT_EQ(field.treeBytes(), 0u);
  // Below the crossover (M = 1 included) the field sums directly: bit for bit the direct sum.
  EXPECT_TRUE(field.setTolerance(1e-3));
  EXPECT_EQ(field.treeBytes(), 0u) << "400 generators are below the default crossover";
  for (const std::size_t count : { std::size_t{ 1 }, kTreeFrom - 1 })
  {
    const std::vector<FieldGenerator> few(generators.begin(), generators.begin() + static_cast<long>(count));
    PointPairField direct(few.data(), few.size(), kFalloff, kEpsilon);
    PointPairField withTolerance(few.data(), few.size(), kFalloff, kEpsilon);
    EXPECT_TRUE(withTolerance.setTolerance(1e-3, kTreeFrom, 0.0));
    EXPECT_EQ(withTolerance.treeBytes(), 0u);
    const Vec3 p{ 0.3, 0.1, -0.2 };
    EXPECT_EQ(direct.generatorAt(p).c, withTolerance.generatorAt(p).c);
  }
  // Below the tolerance crossover (treeMinimumTolerance(M), where the tree stops paying on the
  // bench's field) the field sums directly too, bit for bit, with the tolerance kept; at it the
  // tree is built and meets its bound. The crossover falls with M (1e-4 at 10,000 generators).
  EXPECT_EQ(PointPairField::treeMinimumTolerance(10000), 1e-4);
  EXPECT_NEAR(PointPairField::treeMinimumTolerance(100000), 1e-7, 1e-21);
  EXPECT_EQ(PointPairField::treeMinimumTolerance(0), PointPairField::maximumTolerance());
  const double crossover = PointPairField::treeMinimumTolerance(generators.size());
  const PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  PointPairField fine(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(fine.setTolerance(0.5 * crossover, kTreeFrom));
  EXPECT_EQ(fine.tolerance(), 0.5 * crossover);
  EXPECT_EQ(fine.treeBytes(), 0u);
  Random pick(3);
  for (const Vec3& p : randomPoints(pick, 20, {}, 1.5))
  {
    EXPECT_EQ(direct.generatorAt(p).c, fine.generatorAt(p).c);
  }
  ASSERT_TRUE(fine.setTolerance(crossover, kTreeFrom));
  EXPECT_GT(fine.treeBytes(), 0u);
  // Below kHighDegreeFrom generators the largest degree is kDegree at every tolerance.
  using Tree = cga::detail::GeneratorTree;
  EXPECT_EQ(fine.treeDegree(), Tree::kDegree);
  ASSERT_TRUE(fine.setTolerance(1e-9, kTreeFrom, 0.0));
  EXPECT_EQ(fine.treeDegree(), Tree::kDegree);
  const auto points = randomPoints(pick, 50, {}, 1.5);
  EXPECT_LE(worstRelativeError(generators, points, crossover).boundedError, 1.0);
}

// shareTree takes a previous field's tree only where setTolerance would build the same one, and
// a field that shares it maps to the same bits as one with a tree of its own.
TEST(GeneratorTree, ShareTreeOnlyWhereTheTreeWouldBeTheSame)
{
  Random random(23);
  const auto generators = randomPointPairs(random, 400, {}, 1.0);
  const auto make = [](const std::vector<FieldGenerator>& g, double falloff = kFalloff,
                       double epsilon = kEpsilon) {
    return PointPairField(g.data(), g.size(), falloff, epsilon);
  };
  PointPairField previous = make(generators);
  ASSERT_TRUE(previous.setTolerance(1e-3, kTreeFrom, 0.0));
  ASSERT_GT(previous.treeBytes(), 0u);

  PointPairField shared = make(generators), own = make(generators);
  EXPECT_FALSE(shared.sharesTreeWith(previous));
  ASSERT_TRUE(shared.shareTree(previous, 1e-3, kTreeFrom, 0.0));
  EXPECT_TRUE(shared.sharesTreeWith(previous));
  EXPECT_EQ(shared.tolerance(), 1e-3);
  ASSERT_TRUE(own.setTolerance(1e-3, kTreeFrom, 0.0));
  EXPECT_FALSE(own.sharesTreeWith(previous));
  std::vector<double> in;
  for (const Vec3& p : randomPoints(random, 200, {}, 1.5))
  {
    in.insert(in.end(), { p.x, p.y, p.z });
  }
  std::vector<double> a(in.size()), b(in.size());
  shared.mapPoints(in.data(), a.data(), in.size() / 3, 0.7, ExponentialRule::Exact);
  own.mapPoints(in.data(), b.data(), in.size() / 3, 0.7, ExponentialRule::Exact);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  // A tolerance above the largest is used as the largest, as setTolerance does.
  PointPairField largest = make(generators), clamped = make(generators);
  ASSERT_TRUE(largest.setTolerance(PointPairField::maximumTolerance(), kTreeFrom, 0.0));
  EXPECT_TRUE(clamped.shareTree(largest, 5.0, kTreeFrom, 0.0));

  // Every input of the tree changed alone, and calls that would build no tree: refused, and the
  // field left as it was (no tolerance, no tree).
  auto nudged = generators;
  nudged[17].weight = std::nextafter(nudged[17].weight, 1.0);
  const std::vector<FieldGenerator> fewer(generators.begin(), generators.end() - 1);
  struct Refusal
  {
    const char* what;
    PointPairField field;
    double tolerance;
    std::size_t minimumGenerators;
  };
  Refusal refusals[] = {
    { "another tolerance", make(generators), 2e-3, kTreeFrom },
    { "one weight one ulp away", make(nudged), 1e-3, kTreeFrom },
    { "one generator fewer", make(fewer), 1e-3, kTreeFrom },
    { "another falloff", make(generators, 2.0 * kFalloff), 1e-3, kTreeFrom },
    { "another epsilon", make(generators, kFalloff, std::nextafter(kEpsilon, 1.0)), 1e-3,
      kTreeFrom },
    { "below the generators' crossover", make(generators), 1e-3, generators.size() + 1 },
    { "a NaN tolerance", make(generators), std::nan(""), kTreeFrom },
    { "a negative tolerance", make(generators), -1e-3, kTreeFrom },
  };
  for (Refusal& refusal : refusals)
  {
    EXPECT_FALSE(refusal.field.shareTree(previous, refusal.tolerance, refusal.minimumGenerators,
                                          0.0))
      << refusal.what;
    EXPECT_EQ(refusal.field.tolerance(), 0.0) << refusal.what;
    EXPECT_EQ(refusal.field.treeBytes(), 0u) << refusal.what;
    EXPECT_FALSE(refusal.field.sharesTreeWith(previous)) << refusal.what;
  }
  // A previous field without a tree has none to share.
  PointPairField direct = make(generators), next = make(generators);
  EXPECT_FALSE(next.shareTree(direct, 1e-3, kTreeFrom, 0.0));
  EXPECT_FALSE(next.sharesTreeWith(direct)) << "two fields without a tree share none";
}

TEST(GeneratorTree, NonFiniteGeneratorsAreSkippedAndNonFinitePointsLeftInPlace)
{
  Random random(19);
  auto generators = randomPointPairs(random, 500, {}, 1.0);
  generators[3].location.x = std::nan("");
  generators[7].weight = std::numeric_limits<double>::infinity();
  PointPairField field(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(field.setTolerance(1e-4, kTreeFrom, 0.0));
  EXPECT_EQ(field.skippedGenerators(), 2u);
  std::vector<double> points = { 0.1, 0.2, 0.3, std::nan(""), 0.0, 0.0, 1.0, -1.0, 0.5 };
  std::vector<double> images(points.size());
  EXPECT_EQ(field.mapPoints(points.data(), images.data(), 3, 0.5, ExponentialRule::Exact), 1u);
  EXPECT_TRUE(std::isnan(images[3]));
  for (int i : { 0, 1, 2, 6, 7, 8 })
  {
    EXPECT_TRUE(std::isfinite(images[static_cast<std::size_t>(i)]));
  }
}

TEST(GeneratorTree, ImagesFollowTheBoundThroughTheMap)
{
  // To first order in the error of B (docs/conventions.md section 3 item 14) an image moves by
  // s firstOrderMotion(dB, p), which the tree keeps within s t V: checked with a factor 2 for
  // the higher orders in fields of moderate s B, against the direct sum's images, and the largest
  // image error against the largest displacement (the measure). The batch map and the
  // pointwise map agree bit for bit.
  Random random(23);
  auto generators = randomPointPairs(random, 600, {}, 2.0);
  for (FieldGenerator& g : generators)
  {
    g.weight *= 0.03;
  }
  // Duplicates: coincident generators among the others.
  for (int i = 0; i < 100; ++i)
  {
    generators.push_back(generators[static_cast<std::size_t>(i % 7)]);
  }
  PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  const auto points = randomPoints(random, 300, {}, 2.5);
  std::vector<double> in;
  for (const Vec3& p : points)
  {
    in.insert(in.end(), { p.x, p.y, p.z });
  }
  for (const double tolerance : { 1e-3, 1e-6 })
  {
    PointPairField tree(generators.data(), generators.size(), kFalloff, kEpsilon);
    ASSERT_TRUE(tree.setTolerance(tolerance, kTreeFrom, 0.0));
    for (const double strength : { 0.5, 2.0 })
    {
      const double scale = strength * tree.treeDisplacementScale();
      for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
      {
        std::vector<double> exact(in.size()), approximate(in.size());
        ASSERT_EQ(direct.mapPoints(in.data(), exact.data(), points.size(), strength, rule), 0u);
        ASSERT_EQ(tree.mapPoints(in.data(), approximate.data(), points.size(), strength, rule), 0u);
        double largestDisplacement = 0.0, largestError = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i)
        {
          const Vec3 e{ exact[3 * i], exact[3 * i + 1], exact[3 * i + 2] };
          const Vec3 a{ approximate[3 * i], approximate[3 * i + 1], approximate[3 * i + 2] };
          largestDisplacement = worseOf(largestDisplacement, norm(e - points[i]));
          largestError = worseOf(largestError, norm(a - e));
          if (i % 10 == 0)
          {
            Vec3 single;
            ASSERT_TRUE(tree.map(points[i], strength, rule, single));
            EXPECT_EQ(single.x, a.x);
            EXPECT_EQ(single.y, a.y);
            EXPECT_EQ(single.z, a.z);
          }
        }
        EXPECT_GT(largestDisplacement, 0.05 * strength);
        EXPECT_LE(largestError, 2.0 * tolerance * scale) << "tolerance " << tolerance << ", strength " << strength;
        EXPECT_LE(largestError, tolerance * largestDisplacement);
        EXPECT_GT(largestError, 0.0); // the tree did approximate
      }
    }
  }
}

// The motion the budget is expressed in: firstOrderMotion(b, p) against central differences of
// the map under a constant B = b (falloff 0), and the bound the tree's nodes use,
// |v| <= 2 |C| + 2 sqrt(|E|^2 + d^2) |p| + |A| |p|^2 with b's parts in the frame of its origin.
TEST(GeneratorTree, FirstOrderMotionIsTheMapsDerivativeAndMeetsItsBound)
{
  Random random(37);
  double largestShare = 0.0;
  for (int trial = 0; trial < 200; ++trial)
  {
    Bivector b;
    for (double& c : b.c)
    {
      c = random.uniform(-1.0, 1.0);
    }
    if (trial % 4 == 1) // single parts
    {
      for (std::size_t c = 0; c < b.c.size(); ++c)
      {
        if (c != static_cast<std::size_t>(trial / 4) % b.c.size())
        {
          b.c[c] = 0.0;
        }
      }
    }
    const Vec3 p = random.vec3(3.0);
    const FieldGenerator constant{ {}, b, 1.0 };
    const PointPairField field(&constant, 1, 0.0, 1.0); // B(p) = b / eps = b everywhere
    const double h = 1e-5;
    Vec3 forward, backward;
    ASSERT_TRUE(field.map(p, h, ExponentialRule::Exact, forward));
    ASSERT_TRUE(field.map(p, -h, ExponentialRule::Exact, backward));
    const Vec3 difference = (1.0 / (2.0 * h)) * (forward - backward);
    const Vec3 motion = firstOrderMotion(b, p);
    EXPECT_LE(norm(motion - difference), 1e-8 * (1.0 + norm(motion))) << "trial " << trial;
    const auto& c = b.c;
    const double r = norm(p);
    const double bound = 2.0 * std::hypot(c[Bivector::E1NI], c[Bivector::E2NI], c[Bivector::E3NI]) +
      2.0 * std::sqrt(c[Bivector::E12] * c[Bivector::E12] + c[Bivector::E13] * c[Bivector::E13] +
                      c[Bivector::E23] * c[Bivector::E23] + c[Bivector::NONI] * c[Bivector::NONI]) * r +
      std::hypot(c[Bivector::E1NO], c[Bivector::E2NO], c[Bivector::E3NO]) * r * r;
    EXPECT_LE(norm(motion), bound * (1.0 + 1e-14)) << "trial " << trial;
    largestShare = worseOf(largestShare, norm(motion) / bound);
  }
  EXPECT_GT(largestShare, 0.999); // attained (single parts)
}

// M = 1 with a tree, all generators in one place, generators far from the points (images too),
// and huge weights: finite, within the bound or the direct sum.
TEST(GeneratorTree, BadInputsKeepTheBound)
{
  Random random(41);
  const FieldGenerator lone = FieldGenerator::pointPair({ 0.2, 0.1, -0.3 }, { 0.0, 1.0, 0.5 }, 0.7);
  PointPairField one(&lone, 1, kFalloff, kEpsilon);
  PointPairField oneDirect(&lone, 1, kFalloff, kEpsilon);
  ASSERT_TRUE(one.setTolerance(1e-6, 1, 0.0));
  EXPECT_GT(one.treeDegree(), 0);
  for (const Vec3& p : randomPoints(random, 50, {}, 2.0))
  {
    Vec3 a, e;
    ASSERT_TRUE(one.map(p, 0.5, ExponentialRule::Exact, a));
    ASSERT_TRUE(oneDirect.map(p, 0.5, ExponentialRule::Exact, e));
    EXPECT_LE(norm(a - e), 1e-6 * 0.5 * one.treeDisplacementScale() + 1e-15);
  }
  // Huge weights: the masses overflow, every node is opened (the direct sum, no NaN).
  auto huge = randomPointPairs(random, 400, {}, 1.0);
  for (FieldGenerator& g : huge)
  {
    g.weight *= 1e306;
  }
  PointPairField hugeTree(huge.data(), huge.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(hugeTree.setTolerance(1e-3, kTreeFrom, 0.0));
  for (const Vec3& p : randomPoints(random, 20, {}, 1.5))
  {
    for (const double c : hugeTree.generatorAt(p).c)
    {
      EXPECT_FALSE(std::isnan(c));
    }
  }
  // A generator near the largest doubles (a translation: its bivector does not grow with its
  // location) makes the tree's extent overflow; its levels were an infinity converted to int
  // (undefined behaviour, found by the property fuzz under the sanitizers). The images stay finite.
  auto vast = randomPointPairs(random, 400, {}, 1.0);
  vast.push_back(FieldGenerator::translation({ 1e300, -1e300, 1e300 }, { 0.0, 1.0, 0.5 }, 0.01));
  PointPairField vastTree(vast.data(), vast.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(vastTree.setTolerance(1e-3, kTreeFrom, 0.0));
  EXPECT_EQ(vastTree.skippedGenerators(), 0u);
  for (const Vec3& p : randomPoints(random, 20, {}, 1.5))
  {
    Vec3 a;
    ASSERT_TRUE(vastTree.map(p, 0.5, ExponentialRule::Exact, a));
    EXPECT_TRUE(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z));
  }
  // Far from the mesh: the points' images within the bound.
  const auto far = randomPointPairs(random, 500, { 40.0, -30.0, 20.0 }, 1.0);
  PointPairField farDirect(far.data(), far.size(), kFalloff, kEpsilon);
  PointPairField farTree(far.data(), far.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(farTree.setTolerance(1e-4, kTreeFrom, 0.0));
  for (const Vec3& p : randomPoints(random, 50, {}, 2.0))
  {
    Vec3 a, e;
    ASSERT_TRUE(farTree.map(p, 0.5, ExponentialRule::Exact, a));
    ASSERT_TRUE(farDirect.map(p, 0.5, ExponentialRule::Exact, e));
    EXPECT_LE(norm(a - e), 2.0 * 1e-4 * 0.5 * farTree.treeDisplacementScale());
  }
}
// The remainder bound of the expansions (src/TreeRemainder.h) against the series' tail itself:
// 1/(1 - 2 x q + q^2) minus its partial sums over the Chebyshev polynomials U_j (recurrence in
// long double), for |x| <= |u| and S = 1/sqrt(1 - |u|^2), at every degree the tree uses. The tail
// must never exceed the bound, and the bound must be attained within a factor where it is sharp
// (x = 1 at q -> 0: the tail is about (p + 2) q^(p+1), the Chebyshev form's leading term).
TEST(GeneratorTree, RemainderBoundHoldsForTheSeriesTail)
{
  for (int degree = 0; degree <= cga::detail::GeneratorTree::kMaxDegree; ++degree)
  {
    for (const double q : { 0.01, 0.1, 0.3, 0.5, 0.7, 0.9 })
    {
      for (const double u : { 0.0, 0.3, 0.7, 0.95, 0.999, 1.0 })
      {
        const double S = u < 1.0 ? 1.0 / std::sqrt(1.0 - u * u) : HUGE_VAL;
        const double bound = cga::detail::treeRemainderBound(degree, q, S);
        double worst = 0.0;
        for (int k = -50; k <= 50; ++k)
        {
          const long double x = static_cast<long double>(u) * k / 50.0L;
          const long double qq = q;
          // The tail summed term by term (no cancellation against the closed form where it is
          // tiny) until its terms' bound (j + 1) q^j is below 1e-60 (the bound itself is 1e-33 at
          // degree 16, q = 0.01), and the closed form minus the partial sum as the check of the
          // recurrence.
          long double tail = 0.0L, partial = 0.0L;
          long double previous = 0.0L, current = 1.0L, power = 1.0L; // U_0 = 1
          for (int j = 0; j <= degree || (j + 1) * power > 1e-60L; ++j)
          {
            (j <= degree ? partial : tail) += power * current;
            const long double next = 2.0L * x * current - previous;
            previous = current;
            current = next;
            power *= qq;
          }
          EXPECT_NEAR(static_cast<double>(1.0L / (1.0L - 2.0L * x * qq + qq * qq) - partial),
                      static_cast<double>(tail), 1e-15 / (1.0 - q));
          worst = worseOf(worst, static_cast<double>(std::fabs(tail)));
        }
        EXPECT_LE(worst, bound * (1.0 + 1e-12)) << "degree " << degree << " q " << q << " |u| " << u;
        if (u == 1.0 && q == 0.01)
        {
          EXPECT_GE(worst, 0.9 * bound) << "degree " << degree;
        }
        if (u == 0.0)
        {
          // S = 1: the geometric form, at most q^(p+1)/(1 - q).
          EXPECT_LE(bound, std::pow(q, degree + 1) / (1.0 - q) * (1.0 + 1e-12));
        }
      }
    }
  }
}
} // namespace

namespace
{
// sum_{j > degree} q^j U_j(x) term by term in long double, until the terms' bound (j + 1) q^j is
// below 1e-60 (the Chebyshev polynomials by their recurrence).
long double chebyshevTail(int degree, long double q, long double x)
{
  long double tail = 0.0L, previous = 0.0L, current = 1.0L, power = 1.0L;
  for (int j = 0; j <= degree || (j + 1) * power > 1e-60L; ++j)
  {
    if (j > degree)
    {
      tail += power * current;
    }
    const long double next = 2.0L * x * current - previous;
    previous = current;
    current = next;
    power *= q;
  }
  return tail;
}
} // namespace

// The absolute moments' combination (src/TreeRemainder.h) against the sum it stands for,
// sum_i m_i (a s_i + b)^n, summed per generator in long double.
TEST(GeneratorTree, SpreadMomentIsTheSumOverTheGenerators)
{
  Random random(11);
  // Every power the tree uses (up to kMaxDegree + 1).
  constexpr int kPowers = cga::detail::GeneratorTree::kMaxDegree + 2;
  std::vector<double> s(300), m(300);
  double moments[kPowers] = {};
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    s[i] = i == 0 ? 1.0 : (i == 1 ? 0.0 : random.uniform(0.0, 1.0));
    m[i] = random.uniform(0.0, 2.0);
    for (int k = 0; k < kPowers; ++k)
    {
      moments[k] += m[i] * std::pow(s[i], k);
    }
  }
  for (const double r : { 0.0, 0.25, 1.0, 3.0 })
  {
    const double a = 1.0 / (1.0 + r), b = r / (1.0 + r);
    for (int n = 0; n < kPowers; ++n)
    {
      long double direct = 0.0L;
      for (std::size_t i = 0; i < s.size(); ++i)
      {
        direct += m[i] * std::pow(static_cast<long double>(a) * s[i] + b, n);
      }
      EXPECT_NEAR(cga::detail::treeSpreadMoment(moments, n, a, b), static_cast<double>(direct),
                  1e-13 * static_cast<double>(direct))
        << "power " << n << " r " << r;
    }
  }
  // Coincident generators (radius 0): a = 0, b = 1 gives the plain sum at every power.
  EXPECT_EQ(cga::detail::treeSpreadMoment(moments, 7, 0.0, 1.0), moments[0]);
  // One table of the powers of a and b for several powers (degreeFor's form) gives each power's
  // sum to the bit.
  const cga::detail::TreeSpreadWeights weights(0.8, 0.2, kPowers - 1);
  for (int n = 0; n < kPowers; ++n)
  {
    EXPECT_EQ(weights.moment(moments, n), cga::detail::treeSpreadMoment(moments, n, 0.8, 0.2)) << "power " << n;
  }
}

// The binomial table behind the spread's sums (Pascal's rule) against the product formula in
// long double: exact integers through n = 56 (below 2^53), the powers the tree takes and more.
TEST(GeneratorTree, SpreadBinomialsAreExact)
{
  for (int n = 0; n <= 56; ++n)
  {
    long double binomial = 1.0L;
    for (int k = 0; k <= n; ++k)
    {
      EXPECT_EQ(static_cast<long double>(cga::detail::kTreeBinomials.row(n)[k]), binomial) << "C(" << n << ", " << k << ")";
      binomial = binomial * (n - k) / (k + 1);
    }
  }
}

// The node's bound with its generators' spread: for generators y_i within rho of a node's center
// and a point y_t within r of a cube's center (d between the centers), each kernel
// 1/(k |d - w_i|^2 + eps), w_i = y_i - y_t, is D^-1 sum_j (sqrt(kappa) |w_i|)^j U_j(x_i); the
// weighted sum of the degree-p tails (long double, term by term) must stay within
// R_p(q, S) treeSpreadMoment(A, p + 1, rho/(rho + r), r/(rho + r)), q = (rho + r) sqrt(kappa), and
// for generators spread through the node the spread must be well below the plain sum of weights
// the bound used before (sum_i m_i, a node of all its generators at its rim).
TEST(GeneratorTree, SpreadRemainderBoundHoldsForTheGeneratorsTails)
{
  Random random(5);
  constexpr int kPowers = cga::detail::GeneratorTree::kMaxDegree + 2;
  const double rho = 1.0, falloff = 1.0;
  for (const double epsilon : { 0.05, 1e-3 })
  {
    for (const double r : { 0.0, 0.3, 1.2 })
    {
      for (const double distance : { 2.0, 3.5, 8.0 })
      {
        const Vec3 d = distance * random.unit();
        const double D = falloff * dot(d, d) + epsilon;
        const double rootKappa = std::sqrt(falloff / D);
        const double q = (rho + r) * rootKappa;
        if (q > 0.9)
        {
          continue;
        }
        const double S = std::sqrt(D / epsilon);
        const Vec3 target = r * random.uniform(0.0, 1.0) * random.unit();
        std::vector<Vec3> y;
        std::vector<double> m;
        double moments[kPowers] = {}, plain = 0.0;
        for (int i = 0; i < 200; ++i)
        {
          // One generator at the rim, toward the point (the collinear worst case), the others spread.
          const Vec3 at = i == 0 ? -rho * d / norm(d) : rho * std::cbrt(random.uniform(0.0, 1.0)) * random.unit();
          y.push_back(at);
          m.push_back(random.uniform(0.1, 1.0));
          for (int k = 0; k < kPowers; ++k)
          {
            moments[k] += m.back() * std::pow(norm(at) / rho, k);
          }
          plain += m.back();
        }
        for (int degree = 0; degree <= cga::detail::GeneratorTree::kMaxDegree; ++degree)
        {
          long double tails = 0.0L;
          for (std::size_t i = 0; i < y.size(); ++i)
          {
            const Vec3 w = y[i] - target;
            const double length = norm(w);
            const long double x = length > 0.0 ? rootKappa * dot(d, w) / length : 0.0;
            tails += m[i] * std::fabs(chebyshevTail(degree, static_cast<long double>(rootKappa) * length, x));
          }
          const double remainder = cga::detail::treeRemainderBound(degree, q, S);
          const double spread = cga::detail::treeSpreadMoment(moments, degree + 1, rho / (rho + r), r / (rho + r));
          EXPECT_LE(static_cast<double>(tails), remainder * spread * (1.0 + 1e-12))
            << "degree " << degree << " r " << r << " |d| " << distance << " eps " << epsilon;
          if (r == 0.0 && degree >= 5)
          {
            EXPECT_LT(spread, 0.5 * plain) << "degree " << degree;
          }
        }
      }
    }
  }
}

// From kHighDegreeFrom generators and below kHighDegreeBelow the tree expands to kMaxDegree: the
// bound at points through and around the generators, against the direct sum.
TEST(GeneratorTree, ManyGeneratorsAtTightTolerancesUseTheHighDegreeAndMeetTheBound)
{
  using Tree = cga::detail::GeneratorTree;
  Random random(100);
  const auto generators = randomPointPairs(random, Tree::kHighDegreeFrom, {}, 1.5);
  std::vector<Vec3> points = randomPoints(random, 8, {}, 2.0);
  for (int i = 0; i < 4; ++i)
  {
    points.push_back(generators[static_cast<std::size_t>(i * 997)].location);
  }
  PointPairField field(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(field.setTolerance(Tree::kHighDegreeBelow, kTreeFrom, 0.0));
  EXPECT_EQ(field.treeDegree(), Tree::kDegree);
  for (const double tolerance : { 1e-4, 1e-7 })
  {
    ASSERT_TRUE(field.setTolerance(tolerance, kTreeFrom, 0.0));
    EXPECT_EQ(field.treeDegree(), Tree::kMaxDegree);
    EXPECT_LE(worstRelativeError(generators, points, tolerance).boundedError, 1.0) << "tolerance " << tolerance;
  }
}
