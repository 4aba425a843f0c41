// mapPointsByExponentials (ExponentialMap.h), the batch map of the curvature patch: against the
// pointwise sandwichPoint(exponential(b, rule), p) (the Exact rule to the bit for the random,
// far-from-nilpotent exponents used here but those with a strong hyperbolic plane, Paper to
// round-off),
// the same bits on every instruction set and for every split into calls, and bad input; and
// mapJetsByExponential, its second-order jets, against the same template run on scalar
// second-order dual numbers in this test.
#include "PointMapCore.h"
#include "SurfaceJetDual.h"

#include "cga/Exponential.h"
#include "cga/ExponentialMap.h"
#include "cga/PointSandwich.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iomanip>
#include <memory>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace cga;
using namespace cgatest;

bool sameBits(Vec3 a, Vec3 b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Random exponents from small (the series) to large (the closed form and its scaling) and points.
void randomInput(Random& random, std::size_t count, std::vector<Bivector>& b, std::vector<Vec3>& p)
{
  b.clear();
  p.clear();
  for (std::size_t i = 0; i < count; ++i)
  {
    const double scale = std::vector<double>{ 1e-3, 0.3, 1.0, 4.0, 30.0 }[i % 5];
    b.push_back(random.bivector(scale));
    p.push_back(random.vec3(2.0));
  }
}

} // namespace

TEST(ExponentialMap, EqualsThePointwiseExponentialAndSandwich)
{
  Random random(20261202);
  std::vector<Bivector> b;
  std::vector<Vec3> p;
  randomInput(random, 1003, b, p);
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    const bool exact = rule == ExponentialRule::Exact;
    std::vector<Vec3> out(b.size());
    std::unique_ptr<bool[]> mapped(new bool[b.size()]);
    const std::size_t unmapped =
      mapPointsByExponentials(b.data(), p.data(), b.size(), rule, out.data(), mapped.get());
    std::size_t expectedUnmapped = 0, strongPlanes = 0;
    for (std::size_t i = 0; i < b.size(); ++i)
    {
      Vec3 expected;
      const bool expectedMapped = sandwichPoint(exponential(b[i], rule), p[i], expected);
      expectedUnmapped += !expectedMapped;
      ASSERT_EQ(mapped[i], expectedMapped) << i;
      if (!expectedMapped)
      {
        continue;
      }
      InvariantDecomposition planes;
      const double angle = invariantDecomposition(b[i], planes) && planes.firstSquare > 0.0
        ? std::sqrt(planes.firstSquare) : 0.0;
      if (exact && angle > 1.0)
      {
        // A strong hyperbolic plane: the batch map scales its null directions by their exact
        // factors (or maps through the fixed points) where the pointwise sandwich of K loses about
        // e^{2 angle} units of 2^-53 of the scale (docs/conventions.md section 2 item 12; their
        // accuracy is tested against independent references in GeneratorKinds.AStrong* and
        // Python.ExactAccuracy): here within the sandwich's own loss.
        ++strongPlanes;
        EXPECT_LE(distance(out[i], expected),
          (1e-12 + 64.0 * std::exp(2.0 * angle) * 0x1p-53) * (1.0 + maxNorm(expected))) << i;
      }
      else if (exact)
      {
        EXPECT_TRUE(sameBits(out[i], expected)) << i << ": " << distance(out[i], expected);
      }
      else
      {
        EXPECT_LE(distance(out[i], expected), 1e-12 * (1.0 + maxNorm(expected))) << i;
      }
    }
    EXPECT_EQ(unmapped, expectedUnmapped);
    EXPECT_LT(unmapped, b.size() / 10) << "most random points must map";
    if (exact)
    {
      EXPECT_LT(strongPlanes, b.size() / 2) << "most exponents are compared to the bit";
    }
  }
}

TEST(ExponentialMap, SameBitsOnEveryInstructionSetAndEverySplit)
{
  InstructionSetScope scope;
  Random random(7);
  std::vector<Bivector> b;
  std::vector<Vec3> p;
  randomInput(random, 203, b, p);
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<Vec3> reference(b.size());
    std::unique_ptr<bool[]> referenceMapped(new bool[b.size()]);
    ASSERT_TRUE(useMapPointsInstructionSet("baseline"));
    mapPointsByExponentials(
      b.data(), p.data(), b.size(), rule, reference.data(), referenceMapped.get());
    for (const std::string& set : mapPointsInstructionSets())
    {
      ASSERT_TRUE(useMapPointsInstructionSet(set));
      // Calls of 1 to 13 points: every position in a block of eight, and the padded tails.
      for (std::size_t step : { std::size_t(1), std::size_t(5), std::size_t(13), b.size() })
      {
        std::vector<Vec3> out(b.size());
        std::unique_ptr<bool[]> mapped(new bool[b.size()]);
        for (std::size_t first = 0; first < b.size(); first += step)
        {
          const std::size_t n = std::min(step, b.size() - first);
          mapPointsByExponentials(
            &b[first], &p[first], n, rule, &out[first], &mapped[first]);
        }
        for (std::size_t i = 0; i < b.size(); ++i)
        {
          ASSERT_EQ(mapped[i], referenceMapped[i]) << set << " step " << step << " point " << i;
          if (mapped[i])
          {
            ASSERT_TRUE(sameBits(out[i], reference[i])) << set << " step " << step << " point " << i;
          }
        }
      }
    }
  }
}

TEST(ExponentialMap, NonFiniteInputIsNotMappedAndLeavesTheOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Bivector finite;
  finite.c[Bivector::E12] = 0.5;
  Bivector bad = finite;
  bad.c[Bivector::E1NI] = nan;
  Bivector huge = finite;
  huge.c[Bivector::E3NO] = inf;
  const std::vector<Bivector> b = { finite, bad, huge, finite, finite };
  const std::vector<Vec3> p = { { 1, 0, 0 }, { 1, 0, 0 }, { 1, 0, 0 }, { nan, 0, 0 }, { 0, inf, 0 } };
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    const Vec3 sentinel{ 7, 8, 9 };
    std::vector<Vec3> out(b.size(), sentinel);
    bool mapped[5];
    EXPECT_EQ(mapPointsByExponentials(b.data(), p.data(), b.size(), rule, out.data(), mapped), 4u);
    EXPECT_TRUE(mapped[0]);
    // exp(0.5 e12) turns (1, 0, 0) by one radian in the e1e2 plane.
    EXPECT_NEAR(std::hypot(out[0].x, out[0].y), 1.0, 1e-15);
    EXPECT_NEAR(std::fabs(out[0].y), std::sin(1.0), 1e-15);
    for (int i = 1; i < 5; ++i)
    {
      EXPECT_FALSE(mapped[i]) << i;
      EXPECT_TRUE(sameBits(out[i], sentinel)) << i;
    }
  }
}

namespace
{
// Jets of exponents and points: values as randomInput's, first and second derivatives random
// (a tenth of the value's scale), some lanes with no derivatives, zero exponents, and non-finite
// parts (not mapped).
void randomJets(Random& random, std::size_t count, std::vector<SurfaceJet>& b, std::vector<SurfaceJet>& p)
{
  std::vector<Bivector> values;
  std::vector<Vec3> points;
  randomInput(random, count, values, points);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto jet = [&](double value, double scale, bool constant) {
    SurfaceJet x{ value, 0.0, 0.0, 0.0, 0.0, 0.0 };
    if (!constant)
    {
      x.da = random.uniform(-scale, scale);
      x.db = random.uniform(-scale, scale);
      x.daa = random.uniform(-scale, scale);
      x.dab = random.uniform(-scale, scale);
      x.dbb = random.uniform(-scale, scale);
    }
    return x;
  };
  b.clear();
  p.clear();
  for (std::size_t i = 0; i < count; ++i)
  {
    const bool zero = i % 17 == 3, constant = i % 11 == 5;
    const double scale = std::vector<double>{ 1e-3, 0.3, 1.0, 4.0, 30.0 }[i % 5];
    for (int c = 0; c < Bivector::Count; ++c)
    {
      b.push_back(jet(zero ? 0.0 : values[i].c[c], 0.1 * scale, constant));
    }
    p.push_back(jet(points[i].x, 0.3, constant));
    p.push_back(jet(points[i].y, 0.3, constant));
    p.push_back(jet(points[i].z, 0.3, constant));
    if (i % 29 == 7)
    {
      b[b.size() - 4].dab = nan; // a non-finite derivative of the exponent
    }
    if (i % 31 == 9)
    {
      p[p.size() - 2].da = nan; // of the point
    }
  }
}

// The reference: core::mapPointBy on SurfaceJetDual (double), one sample at a time, the image's
// jets where mapped and every part finite.
bool scalarJets(const SurfaceJet* b, const SurfaceJet* p, ExponentialRule rule, SurfaceJet* image)
{
  kernel::FieldArgs args;
  args.exactRule = rule == ExponentialRule::Exact;
  core::SurfaceJetDual bd[Bivector::Count], pd[3], out[3];
  for (int c = 0; c < Bivector::Count; ++c)
  {
    bd[c] = core::secondOf(b[c]);
  }
  for (int i = 0; i < 3; ++i)
  {
    pd[i] = core::secondOf(p[i]);
  }
  bool mapped = false;
  core::mapPointBy(args, bd, pd, out, &mapped);
  bool finite = mapped;
  for (int i = 0; i < 3; ++i)
  {
    finite = core::jetOf(out[i], image[i]) && finite;
  }
  return finite;
}
} // namespace

TEST(ExponentialMap, JetsInBlocksAreTheScalarJetsBitForBit)
{
  // Every instruction set, calls of 1 to 13 samples (every position in a block of eight, the
  // padded tails) and all at once, both rules: the bits of the scalar template, the same mapped
  // flags, the images untouched where not mapped.
  InstructionSetScope scope;
  Random random(2026120501);
  std::vector<SurfaceJet> b, p;
  const std::size_t count = 203;
  randomJets(random, count, b, p);
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<SurfaceJet> reference(3 * count);
    std::unique_ptr<bool[]> referenceMapped(new bool[count]);
    std::size_t unmapped = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
      referenceMapped[i] = scalarJets(&b[10 * i], &p[3 * i], rule, &reference[3 * i]);
      unmapped += referenceMapped[i] ? 0 : 1;
    }
    ASSERT_GE(unmapped, 10u); // the non-finite parts
    ASSERT_LE(unmapped, 20u);
    for (const std::string& set : mapPointsInstructionSets())
    {
      ASSERT_TRUE(useMapPointsInstructionSet(set));
      for (std::size_t step : { std::size_t(1), std::size_t(5), std::size_t(13), count })
      {
        const SurfaceJet sentinel{ 7, 8, 9, 10, 11, 12 };
        std::vector<SurfaceJet> out(3 * count, sentinel);
        std::unique_ptr<bool[]> mapped(new bool[count]);
        std::size_t notMapped = 0;
        for (std::size_t first = 0; first < count; first += step)
        {
          const std::size_t n = std::min(step, count - first);
          notMapped +=
            mapJetsByExponential(&b[10 * first], &p[3 * first], n, rule, &out[3 * first], &mapped[first]);
        }
        EXPECT_EQ(notMapped, unmapped) << set << " step " << step;
        for (std::size_t i = 0; i < count; ++i)
        {
          ASSERT_EQ(mapped[i], referenceMapped[i]) << set << " step " << step << " sample " << i;
          const SurfaceJet* expected = mapped[i] ? &reference[3 * i] : nullptr;
          for (int k = 0; k < 3; ++k)
          {
            const SurfaceJet& want = expected ? expected[k] : sentinel;
            const SurfaceJet& got = out[3 * i + k];
            ASSERT_EQ(0, std::memcmp(&got, &want, sizeof want))
              << set << " step " << step << " sample " << i << " coordinate " << k << std::setprecision(17)
              << "\n got " << got.value << " " << got.da << " " << got.db << " " << got.daa << " " << got.dab << " " << got.dbb
              << "\n want " << want.value << " " << want.da << " " << want.db << " " << want.daa << " " << want.dab << " " << want.dbb;
          }
        }
        // One sample: mapJetByExponential is the same.
        SurfaceJet one[3] = { sentinel, sentinel, sentinel };
        const std::size_t i = 42;
        ASSERT_EQ(mapJetByExponential(&b[10 * i], &p[3 * i], rule, one), referenceMapped[i]);
        const SurfaceJet untouched[3] = { sentinel, sentinel, sentinel };
        EXPECT_EQ(0, std::memcmp(one, referenceMapped[i] ? &reference[3 * i] : untouched, sizeof one));
      }
    }
  }
}
