// The field of point-pair generators (PointPairField.h) against the full multivector product and
// against the closed form of one generator (docs/conventions.md section 2: p -> x + SCT(p - x)).
#include "TestSupport.h"

#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointPairField.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
using namespace cga;
using cgatest::Random;
using cgatest::worseOf;

// B(p) and fn(K up(p) ~K) through the full Multivector: the independent reference.
Multivector referenceGenerator(const std::vector<PointPairGenerator>& generators,
                               Vec3 p,
                               double k,
                               double eps)
{
  Multivector b;
  for (const PointPairGenerator& g : generators)
  {
    b += nullPointPair(g.location, g.direction) * (g.weight / (k * norm2(p - g.location) + eps));
  }
  return b;
}

// The paper's rule written out on the full multivector (eq 9-10), s = <B B>_0.
Multivector referencePaperExp(const Multivector& b)
{
  const double s = (b * b).c[0];
  if (s > 0.0)
  {
    const double r = std::sqrt(s);
    return Multivector::scalar(std::cosh(r)) + b * (std::sinh(r) / r);
  }
  if (s < 0.0)
  {
    const double r = std::sqrt(-s);
    return Multivector::scalar(std::cos(r)) + b * (std::sin(r) / r);
  }
  return Multivector::scalar(1.0) + b;
}

Vec3 referenceImage(const Multivector& k, Vec3 p)
{
  Vec3 out;
  EXPECT_TRUE(normalizePoint(sandwich(k, up(p)).grade(1), out));
  return out;
}

std::vector<PointPairGenerator> randomGenerators(Random& random, int count, double maxWeight)
{
  std::vector<PointPairGenerator> generators;
  for (int i = 0; i < count; ++i)
  {
    generators.push_back({ random.vec3(1.5), random.unit(), random.uniform(-maxWeight, maxWeight) });
  }
  return generators;
}

double distance(Vec3 a, Vec3 b)
{
  return norm(a - b);
}

// The batch map of one point is map() to the bit (one source, PointMapCore.h).
void expectBatchIsPointwise(const PointPairField& field, Vec3 p, ExponentialRule rule, Vec3 image)
{
  const double in[3] = { p.x, p.y, p.z };
  double out[3];
  ASSERT_EQ(field.mapPoints(in, out, 1, 1.0, rule), 0u);
  EXPECT_EQ(out[0], image.x);
  EXPECT_EQ(out[1], image.y);
  EXPECT_EQ(out[2], image.z);
}

TEST(PointPairField, ExactRuleMatchesTheSeriesExponentialOfTheFullProduct)
{
  Random random(71);
  for (int n = 0; n < 300; ++n)
  {
    const auto generators = randomGenerators(random, 1 + n % 8, 0.3);
    const PointPairField field(generators, 1.5, 0.05);
    const Vec3 p = random.vec3(2.0);
    Vec3 image;
    ASSERT_TRUE(field.map(p, 1.0, ExponentialRule::Exact, image));
    const Multivector k = expSeries(referenceGenerator(generators, p, 1.5, 0.05) * -1.0);
    EXPECT_LE(distance(image, referenceImage(k, p)), 1e-10 * (1.0 + norm(image)));
    expectBatchIsPointwise(field, p, ExponentialRule::Exact, image);
  }
}

TEST(PointPairField, PaperRuleMatchesEquation9Evaluated)
{
  Random random(72);
  double largestRuleDifference = 0.0;
  for (int n = 0; n < 300; ++n)
  {
    const auto generators = randomGenerators(random, 2 + n % 8, 0.3);
    const PointPairField field(generators, 1.0, 0.05);
    const Vec3 p = random.vec3(2.0);
    Vec3 paper, exact;
    ASSERT_TRUE(field.map(p, 1.0, ExponentialRule::Paper, paper));
    ASSERT_TRUE(field.map(p, 1.0, ExponentialRule::Exact, exact));
    const Multivector k = referencePaperExp(referenceGenerator(generators, p, 1.0, 0.05) * -1.0);
    EXPECT_LE(distance(paper, referenceImage(k, p)), 1e-10 * (1.0 + norm(paper)));
    expectBatchIsPointwise(field, p, ExponentialRule::Paper, paper);
    largestRuleDifference = worseOf(largestRuleDifference, distance(paper, exact));
  }
  // Sums of pairs at different places are not blades: the two rules must differ somewhere.
  EXPECT_GT(largestRuleDifference, 1e-4);
}

TEST(PointPairField, OneGeneratorIsATranslatedSpecialConformalTransformation)
{
  Random random(73);
  for (int n = 0; n < 500; ++n)
  {
    const Vec3 x = random.vec3(2.0);
    const Vec3 v = random.uniform(0.1, 2.0) * random.unit();
    const double w = random.uniform(-1.0, 1.0);
    const double k = random.uniform(0.0, 2.0), eps = random.uniform(0.01, 1.0);
    const PointPairField field({ { x, v, w } }, k, eps);
    const Vec3 p = random.vec3(3.0);
    // K = exp(-c tau(x, v)) = 1 + tau(x, -c v): an SCT of weight u = -c v about x.
    const Vec3 u = (-w / (k * norm2(p - x) + eps)) * v;
    const Vec3 y = p - x;
    const Vec3 expected =
      x + (y + norm2(y) * u) / (1.0 + 2.0 * dot(u, y) + norm2(u) * norm2(y));
    for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      Vec3 image;
      ASSERT_TRUE(field.map(p, 1.0, rule, image));
      EXPECT_LE(distance(image, expected), 1e-12 * (1.0 + norm(expected)));
    }
  }
}

TEST(PointPairField, AHugePointPairMovesPointsNextToItsLocation)
{
  // The transversion's closed form in long double (its 64-bit significand and its range to 1e4932:
  // |u|^2 |y|^2 reaches 1e616 here) against both paths: K = 1 + B then has components of size
  // |B| and its sandwich terms of size |B|^2 (beyond the doubles' range from w ~ 1e154), the image
  // x + O(1/|u|) (the limit of the transversion: every point but x's antipode -u/|u|^2 goes to x).
  Random random(91);
  for (const double magnitude : { 1e100, 1e154, 1e155, 1e160, 1e200, 1e300, 1e305 })
  {
    for (int n = 0; n < 40; ++n)
    {
      const Vec3 x = random.vec3(2.0);
      const Vec3 v = random.uniform(0.1, 1.0) * random.unit();
      const double w = (n % 2 == 0 ? 1.0 : -1.0) * magnitude * random.uniform(0.5, 1.0);
      const double k = random.uniform(0.5, 2.0), eps = random.uniform(0.01, 1.0);
      const PointPairField field({ { x, v, w } }, k, eps);
      const bool onLocation = n % 10 == 0;
      const Vec3 p = onLocation ? x : random.vec3(3.0);
      long double y[3], u[3], yy = 0, uy = 0, uu = 0;
      const long double c = -static_cast<long double>(w) /
        (static_cast<long double>(k) * static_cast<long double>(norm2(p - x)) + eps);
      for (int i = 0; i < 3; ++i)
      {
        y[i] = static_cast<long double>(p[i]) - x[i];
        u[i] = c * v[i];
        yy += y[i] * y[i];
        uy += u[i] * y[i];
        uu += u[i] * u[i];
      }
      const long double denominator = 1.0L + 2.0L * uy + uu * yy;
      const Vec3 expected{ static_cast<double>(x[0] + (y[0] + yy * u[0]) / denominator),
        static_cast<double>(x[1] + (y[1] + yy * u[1]) / denominator),
        static_cast<double>(x[2] + (y[2] + yy * u[2]) / denominator) };
      std::vector<double> batch(3);
      for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
      {
        const std::string label = "w " + std::to_string(w) + " case " + std::to_string(n) +
          (rule == ExponentialRule::Exact ? " Exact" : " Paper");
        Vec3 image;
        ASSERT_TRUE(field.map(p, 1.0, rule, image)) << label;
        EXPECT_LE(distance(image, expected), 1e-12 * (1.0 + norm(expected))) << label;
        if (onLocation)
        {
          EXPECT_EQ(distance(image, x), 0.0) << label; // the boost's fixed point, to the bit
        }
        const double point[3] = { p[0], p[1], p[2] };
        ASSERT_EQ(field.mapPoints(point, batch.data(), 1, 1.0, rule), 0u) << label;
        for (int i = 0; i < 3; ++i)
        {
          EXPECT_EQ(batch[i], image[i]) << label << " coordinate " << i; // the same source
        }
      }
    }
  }
}

TEST(PointPairField, ZeroStrengthAndNoGeneratorsAreTheIdentity)
{
  Random random(74);
  const PointPairField empty(std::vector<PointPairGenerator>{}, 1.0, 0.1);
  const PointPairField field(randomGenerators(random, 4, 1.0), 1.0, 0.1);
  const Vec3 p{ 0.3, -0.2, 1.7 };
  Vec3 out;
  ASSERT_TRUE(empty.map(p, 1.0, ExponentialRule::Exact, out));
  EXPECT_EQ(distance(out, p), 0.0);
  ASSERT_TRUE(field.map(p, 0.0, ExponentialRule::Paper, out));
  EXPECT_EQ(distance(out, p), 0.0);
}

TEST(PointPairField, BadGeneratorsAreSkippedAndBadPointsRejected)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PointPairGenerator> generators = {
    { { 0, 0, 0 }, { 0, 0, 0 }, 1.0 },   // zero direction
    { { nan, 0, 0 }, { 1, 0, 0 }, 1.0 }, // NaN location
    { { 0, 0, 0 }, { 1, 0, 0 }, nan },   // NaN weight
    { { 1, 0, 0 }, { 0, 1, 0 }, 0.5 },
  };
  const PointPairField field(generators, 1.0, 0.1);
  EXPECT_EQ(field.size(), 1u);
  EXPECT_EQ(field.skippedGenerators(), 3u);
  Vec3 out{ 7, 7, 7 };
  EXPECT_FALSE(field.map({ nan, 0, 0 }, 1.0, ExponentialRule::Exact, out));
  EXPECT_EQ(out.x, 7.0);
  // A point exactly on a generator stays finite (epsilon) and is the fixed point x.
  ASSERT_TRUE(field.map({ 1, 0, 0 }, 1.0, ExponentialRule::Exact, out));
  EXPECT_LE(distance(out, { 1, 0, 0 }), 1e-15);
}

TEST(PointPairField, GeneratorsOfAnyBivectorMatchTheFullProduct)
{
  // FieldGenerator: any bivector placed at a location (here random ones, not point pairs), with
  // the same skipping rules; a point pair given either way is the same field to the bit.
  Random random(76);
  for (int n = 0; n < 200; ++n)
  {
    std::vector<FieldGenerator> generators;
    Multivector reference;
    const Vec3 p = random.vec3(2.0);
    for (int i = 0; i < 1 + n % 4; ++i)
    {
      FieldGenerator g;
      g.location = random.vec3(1.5);
      for (double& c : g.bivector.c)
      {
        c = random.uniform(-0.3, 0.3);
      }
      g.weight = random.uniform(-1.0, 1.0);
      generators.push_back(g);
      reference += toMultivector(g.bivector) * (g.weight / (1.5 * norm2(p - g.location) + 0.05));
    }
    const PointPairField field(generators.data(), generators.size(), 1.5, 0.05);
    Vec3 image;
    ASSERT_TRUE(field.map(p, 1.0, ExponentialRule::Exact, image));
    const Vec3 expected = referenceImage(expSeries(reference * -1.0), p);
    EXPECT_LE(distance(image, expected), 1e-10 * (1.0 + norm(expected)));
    expectBatchIsPointwise(field, p, ExponentialRule::Exact, image);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const FieldGenerator pair = FieldGenerator::pointPair({ 1, 0, 0 }, { 0, 2, 0 }, 0.5);
  FieldGenerator zero, infinite = pair, notANumber = pair;
  infinite.bivector[Bivector::E12] = inf;
  notANumber.location.y = nan;
  const FieldGenerator list[] = { zero, infinite, notANumber, pair };
  const PointPairField field(list, 4, 1.0, 0.1);
  EXPECT_EQ(field.size(), 1u);
  EXPECT_EQ(field.skippedGenerators(), 3u);
  const PointPairField samePair({ { { 1, 0, 0 }, { 0, 2, 0 }, 0.5 } }, 1.0, 0.1);
  const Bivector a = field.generatorAt({ 0.3, -0.2, 0.7 });
  const Bivector b = samePair.generatorAt({ 0.3, -0.2, 0.7 });
  for (int i = 0; i < Bivector::Count; ++i)
  {
    EXPECT_EQ(a[i], b[i]);
  }
}
} // namespace

TEST(PointPairField, BatchMapEqualsThePointwiseMapInEveryPrecision)
{
  Random random(75);
  const PointPairField field(randomGenerators(random, 5, 1.0), 1.0, 0.05);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> points;
  for (int i = 0; i < 40; ++i)
  {
    points.push_back(random.uniform(-2.0, 2.0));
  }
  points[4] = nan; // point 1 is not finite and must come through unchanged
  const std::size_t count = points.size() / 3;
  const std::vector<float> pointsFloat(points.begin(), points.end());
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<double> outDouble(points.size());
    std::vector<float> outFloat(points.size());
    std::vector<double> outFromFloat(points.size());
    std::vector<float> outToFloat(points.size());
    EXPECT_EQ(field.mapPoints(points.data(), outDouble.data(), count, 0.7, rule), 1u);
    EXPECT_EQ(field.mapPoints(pointsFloat.data(), outFloat.data(), count, 0.7, rule), 1u);
    EXPECT_EQ(field.mapPoints(pointsFloat.data(), outFromFloat.data(), count, 0.7, rule), 1u);
    EXPECT_EQ(field.mapPoints(points.data(), outToFloat.data(), count, 0.7, rule), 1u);
    for (std::size_t i = 0; i < count; ++i)
    {
      const Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      Vec3 expected = p;
      const bool mapped = field.map(p, 0.7, rule, expected);
      EXPECT_EQ(mapped, i != 1);
      for (int c = 0; c < 3; ++c)
      {
        const double e = (&expected.x)[c];
        if (i == 1)
        {
          EXPECT_EQ(std::isnan(outDouble[3 * i + c]), std::isnan(points[3 * i + c]));
          continue;
        }
        // The batch map is map() to the bit, then rounded to float for float output.
        EXPECT_EQ(outDouble[3 * i + c], e);
        EXPECT_EQ(outToFloat[3 * i + c], static_cast<float>(e));
        // float input: the point itself differs by a rounding, so compare loosely
        EXPECT_NEAR(outFloat[3 * i + c], e, 1e-4 * (1.0 + std::abs(e)));
        EXPECT_NEAR(outFromFloat[3 * i + c], e, 1e-4 * (1.0 + std::abs(e)));
      }
    }
  }
}

// mapPointsWithDisplacements writes mapPoints' images to the bit and, per point, the image less
// the point computed in double and rounded to the output type (what the deformation filter's
// Displacement array held when it was computed in a second pass); 0 for a point that is not
// finite; the counts: points unchanged, not finite, and finite ones beyond the output's range.
template <typename In, typename Out>
void checkDisplacements(const PointPairField& field, const std::vector<In>& points, double strength,
  ExponentialRule rule, std::size_t expectUnchanged, std::size_t expectNotFinite,
  std::size_t expectBeyond)
{
  const std::size_t count = points.size() / 3;
  std::vector<Out> images(points.size()), out(points.size()), displacements(points.size(), Out(7));
  const std::size_t unchanged =
    field.mapPoints(points.data(), images.data(), count, strength, rule);
  const PointPairField::DisplacementCounts counts = field.mapPointsWithDisplacements(
    points.data(), out.data(), displacements.data(), count, strength, rule);
  EXPECT_EQ(counts.unchanged, unchanged);
  EXPECT_EQ(counts.unchanged, expectUnchanged);
  EXPECT_EQ(counts.notFinite, expectNotFinite);
  EXPECT_EQ(counts.beyondRange, expectBeyond);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double p = points[i];
    // The same bits (NaN compares unequal: compare the bytes)
    EXPECT_EQ(std::memcmp(&out[i], &images[i], sizeof(Out)), 0) << i;
    const bool finitePoint = std::isfinite(double(points[i - i % 3])) &&
      std::isfinite(double(points[i - i % 3 + 1])) && std::isfinite(double(points[i - i % 3 + 2]));
    const Out expected = finitePoint ? static_cast<Out>(out[i] - p) : Out(0);
    EXPECT_EQ(std::memcmp(&displacements[i], &expected, sizeof(Out)), 0)
      << i << ": " << displacements[i] << " against " << expected;
  }
}

TEST(PointPairField, DisplacementsAreTheImagesLessThePointsInEveryPrecision)
{
  Random random(76);
  const PointPairField field(randomGenerators(random, 5, 1.0), 1.0, 0.05);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> points;
  for (int i = 0; i < 3 * 21; ++i) // 21 points: two whole blocks and a part
  {
    points.push_back(random.uniform(-2.0, 2.0));
  }
  points[4] = nan; // point 1
  points[3 * 9 + 2] = -inf; // point 9
  const std::vector<float> pointsFloat(points.begin(), points.end());
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    checkDisplacements<double, double>(field, points, 0.7, rule, 2, 2, 0);
    checkDisplacements<double, float>(field, points, 0.7, rule, 2, 2, 0);
    checkDisplacements<float, float>(field, pointsFloat, 0.7, rule, 2, 2, 0);
    checkDisplacements<float, double>(field, pointsFloat, 0.7, rule, 2, 2, 0);
    // Strength 0 copies the points (the path without the kernel): displacements 0, or the
    // rounding of a double point to float.
    checkDisplacements<double, double>(field, points, 0.0, rule, 2, 2, 0);
    checkDisplacements<double, float>(field, points, 0.0, rule, 2, 2, 0);
  }
  // A double point beyond the largest float: finite, its float image is not.
  std::vector<double> huge = { 1e300, 0.5, 0.25, 0.1, 0.2, 0.3 };
  checkDisplacements<double, float>(field, huge, 0.0, ExponentialRule::Exact, 0, 0, 1);
  checkDisplacements<double, double>(field, huge, 0.0, ExponentialRule::Exact, 0, 0, 0);
}

// Double points go through the kernel's own block with displacements (kernel::MapDisplacedBlock)
// in whole blocks (on AVX-512 two at a time, kernel::MapDisplacedWideBlock, then one),
// the rest (the last partial block, the tree) through the lanes' generic pass: all give
// mapPoints' images and out - in on every instruction set, also in place (out = in), with points
// that are not finite inside whole blocks and in the last one.
TEST(PointPairField, DisplacementsOfWholeBlocksOnEveryInstructionSetAndInPlace)
{
  Random random(77);
  PointPairField field(randomGenerators(random, 4, 1.0), 1.0, 0.05);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> points;
  for (int i = 0; i < 3 * 45; ++i) // 45 points: five whole blocks (two wide ones and one) and 5
  {
    points.push_back(random.uniform(-2.0, 2.0));
  }
  points[3 * 8] = nan;       // point 8, the first of the second block
  points[3 * 23 + 1] = inf;  // point 23, the last of the third block
  points[3 * 43 + 2] = -inf; // point 43, in the last partial block
  const std::string active = mapPointsInstructionSet();
  for (const std::string& isa : mapPointsInstructionSets())
  {
    ASSERT_TRUE(useMapPointsInstructionSet(isa));
    for (const double tolerance : { 0.0, 1e-3 })
    {
      // (with a tolerance, the generator tree: the generic pass for every point)
      ASSERT_TRUE(field.setTolerance(tolerance, 1, 0.0));
      for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
      {
        SCOPED_TRACE(isa + (tolerance > 0.0 ? " with the tree" : "") +
          (rule == ExponentialRule::Exact ? " Exact" : " Paper"));
        checkDisplacements<double, double>(field, points, 0.7, rule, 3, 3, 0);
        std::vector<double> out(points.size()), displacements(points.size());
        field.mapPointsWithDisplacements(
          points.data(), out.data(), displacements.data(), 45, 0.7, rule);
        std::vector<double> inPlace = points, inPlaceDisplacements(points.size());
        const PointPairField::DisplacementCounts counts = field.mapPointsWithDisplacements(
          inPlace.data(), inPlace.data(), inPlaceDisplacements.data(), 45, 0.7, rule);
        EXPECT_EQ(counts.unchanged, 3u);
        EXPECT_EQ(counts.notFinite, 3u);
        EXPECT_EQ(std::memcmp(inPlace.data(), out.data(), out.size() * sizeof(double)), 0);
        EXPECT_EQ(std::memcmp(inPlaceDisplacements.data(), displacements.data(),
                    out.size() * sizeof(double)),
          0);
      }
    }
  }
  ASSERT_TRUE(useMapPointsInstructionSet(active));
}

TEST(PointPairField, TranslatingPointsAndGeneratorsTranslatesTheImages)
{
  // The map is translation covariant in the algebra; the field computes relative to its center
  // (the generators' mean location, which moves with them), so a configuration moved by t maps
  // to its images moved by t within a few roundings at |t|: 64 eps (|t| + |image|) (the map's
  // derivative is of order one here, see Testing/Support/TranslationChecks.h for the count).
  // Computed in space the error grew like eps |t|^2: 3e-4 at |t| = 1e4.
  Random random(78);
  const double eps = std::numeric_limits<double>::epsilon();
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (int n = 0; n < 50; ++n)
    {
      const std::vector<PointPairGenerator> generators = randomGenerators(random, 1 + n % 5, 0.6);
      const Vec3 p = random.vec3(2.0);
      const PointPairField field(generators, 1.0, 0.1);
      Vec3 image;
      ASSERT_TRUE(field.map(p, 1.0, rule, image));
      for (const double length : { 1e2, 1e4, 1e6 })
      {
        const Vec3 t = length * random.unit();
        std::vector<PointPairGenerator> moved = generators;
        for (PointPairGenerator& g : moved)
        {
          g.location = g.location + t;
        }
        const PointPairField movedField(moved, 1.0, 0.1);
        Vec3 movedImage;
        ASSERT_TRUE(movedField.map(p + t, 1.0, rule, movedImage));
        EXPECT_LE(distance(movedImage - t, image), 64.0 * eps * (length + norm(image)))
          << "|t| = " << length << ", " << generators.size() << " generators";
      }
    }
  }
}

// Per coordinate the mean of the kept locations where each lies within [0.6, 1.6] times it (there
// every x_i - c is exact), else 0.
TEST(PointPairField, TheCenterIsTheMeanWhereItKeepsDifferencesExactAndAPointOnALoneOneIsFixed)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PointPairField field({ { { 1, 2, 3 }, { 0, 1, 0 }, 1.0 }, { { 3, 2, 1 }, { 1, 0, 0 }, 1.0 },
                               { { nan, 0, 0 }, { 1, 0, 0 }, 1.0 } },
    1.0, 0.1);
  EXPECT_EQ(field.size(), 2u);
  // x and z: 1 and 3 about the mean 2, 1 below 0.6 * 2; y: both 2
  EXPECT_EQ(distance(field.center(), { 0, 2, 0 }), 0.0);
  // 0.6 m and 1.6 m themselves are kept (3, 4.5, 4.5 and 8 about m = 5, either sign); 8.01 is not
  const PointPairField edges({ { { 3, -3, 3 }, { 0, 1, 0 }, 1.0 }, { { 4.5, -4.5, 4.5 }, { 0, 1, 0 }, 1.0 },
                               { { 4.5, -4.5, 4.5 }, { 0, 1, 0 }, 1.0 }, { { 8, -8, 8.01 }, { 1, 0, 0 }, 1.0 } },
    1.0, 0.1);
  EXPECT_EQ(edges.center().x, 5.0);
  EXPECT_EQ(edges.center().y, -5.0);
  EXPECT_EQ(edges.center().z, 0.0); // 8.01 > 1.6 * 5.0025
  for (const double far : { 0.0, 1e6, 1e150 })
  {
    const Vec3 x{ far + 0.25, -far, 0.5 * far + 1.0 };
    const PointPairField lone({ { x, { 0.3, 1, -0.2 }, 3.0 } }, 1.0, 1e-3);
    EXPECT_EQ(distance(lone.center(), x), 0.0);
    for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      Vec3 image;
      ASSERT_TRUE(lone.map(x, 1.0, rule, image)) << far;
      EXPECT_EQ(image.x, x.x) << far;
      EXPECT_EQ(image.y, x.y) << far;
      EXPECT_EQ(image.z, x.z) << far;
    }
  }
}
