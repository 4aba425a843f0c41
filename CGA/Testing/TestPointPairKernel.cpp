// The vectorized block kernel behind PointPairField::mapPoints (src/PointPairKernel.h) against the
// pointwise map(), on every instruction set this CPU runs: random fields of 1 to 64 generators,
// both rules, points on generators, NaN and infinite points, huge weights, strength 0; its
// generator sum against the fused formula and a long double sum.
#include "TestSupport.h"

#include "cga/PointPairField.h"

#include "PointPairKernelDispatch.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace cga;
using cgatest::InstructionSetScope;
using cgatest::Random;
using cgatest::worseOf;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Case
{
  std::vector<PointPairGenerator> generators;
  double falloff = 1.0, epsilon = 0.05, strength = 1.0;
  std::vector<double> points; // xyz interleaved
};

Case randomCase(Random& random, int generatorCount, double maxWeight, int pointCount)
{
  Case c;
  for (int i = 0; i < generatorCount; ++i)
  {
    c.generators.push_back(
      { random.vec3(1.5), random.uniform(0.2, 2.0) * random.unit(), random.uniform(-maxWeight, maxWeight) });
  }
  c.falloff = random.uniform(0.0, 3.0);
  c.epsilon = random.uniform(1e-3, 0.5);
  c.strength = random.uniform(-2.0, 2.0);
  for (int i = 0; i < pointCount; ++i)
  {
    const Vec3 p = random.vec3(3.0);
    c.points.insert(c.points.end(), { p.x, p.y, p.z });
  }
  // Points exactly on the first generators, and points that are not finite.
  for (std::size_t g = 0; g < c.generators.size() && g < 3; ++g)
  {
    const Vec3 x = c.generators[g].location;
    c.points.insert(c.points.end(), { x.x, x.y, x.z });
  }
  c.points.insert(c.points.end(), { kNaN, 0.5, 0.5, 0.1, kInf, 0.2, -kInf, kNaN, kInf });
  return c;
}

bool sameBits(double a, double b)
{
  return std::isnan(a) ? std::isnan(b) : a == b;
}

// mapPoints against map() point by point: both are core::mapPoint (PointMapCore.h), for lanes and
// for double, so every image is the same to the bit, the same points are left unchanged, and the
// count of those is returned.
void expectBatchEqualsPointwise(const Case& c, ExponentialRule rule, const char* label)
{
  const PointPairField field(c.generators, c.falloff, c.epsilon);
  const std::size_t count = c.points.size() / 3;
  std::vector<double> out(c.points.size(), kNaN);
  const std::size_t unchanged =
    field.mapPoints(c.points.data(), out.data(), count, c.strength, rule);
  std::size_t expectedUnchanged = 0, differing = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 p{ c.points[3 * i], c.points[3 * i + 1], c.points[3 * i + 2] };
    Vec3 expected = p;
    if (!field.map(p, c.strength, rule, expected) || !isFinite(expected))
    {
      expected = p;
      ++expectedUnchanged;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!sameBits((&expected.x)[k], out[3 * i + k]))
      {
        ++differing;
      }
    }
  }
  EXPECT_EQ(differing, 0u) << label;
  EXPECT_EQ(unchanged, expectedUnchanged) << label;
}

// BOOSTEDSURFACES_KERNEL_ISA names the instruction set to use where the CPU has it; without it, or
// with a name that is not available here, the kernel takes the widest one available (the last).
// ctest runs this test three times: as it finds it, and with the variable set to "baseline" and
// to "sse9", which is no instruction set (CGA/Testing/CMakeLists.txt).
TEST(PointPairKernel, TheEnvironmentChoosesTheInstructionSet)
{
  const std::vector<std::string> available = kernel::availableInstructionSets();
  ASSERT_FALSE(available.empty());
  EXPECT_EQ(available.front(), "baseline");
  const char* requested = std::getenv("BOOSTEDSURFACES_KERNEL_ISA");
  const bool usable =
    requested && std::find(available.begin(), available.end(), requested) != available.end();
  EXPECT_EQ(kernel::activeInstructionSet(), usable ? std::string(requested) : available.back())
    << "BOOSTEDSURFACES_KERNEL_ISA=" << (requested ? requested : "(not set)");
}

TEST(PointPairKernel, EveryInstructionSetMatchesThePointwiseMap)
{
  InstructionSetScope scope;
  const std::vector<std::string> sets = mapPointsInstructionSets();
  ASSERT_FALSE(sets.empty());
  EXPECT_EQ(sets.front(), "baseline");
  for (const std::string& set : sets)
  {
    ASSERT_TRUE(useMapPointsInstructionSet(set));
    Random random(81);
    for (int generators : { 1, 2, 3, 4, 7, 16, 64 })
    {
      for (double maxWeight : { 0.01, 0.3, 2.0 })
      {
        const Case c = randomCase(random, generators, maxWeight, 501);
        for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
        {
          const std::string label = set + (rule == ExponentialRule::Exact ? " Exact" : " Paper") +
            " M=" + std::to_string(generators) + " w=" + std::to_string(maxWeight);
          expectBatchEqualsPointwise(c, rule, label.c_str());
        }
      }
    }
  }
}

TEST(PointPairKernel, IllConditionedFieldsStayAccurateAndEqualThePointwiseMap)
{
  // A strong generator close to the point: the image is a quotient of large, nearly cancelling
  // terms, and both the batch kernel and map() lose digits. They agree to the bit, and against
  // the closed form of one generator (x + SCT(p - x), as in TestPointPairField) lose no more than
  // the conditioning allows.
  InstructionSetScope scope;
  for (const std::string& set : mapPointsInstructionSets())
  {
    ASSERT_TRUE(useMapPointsInstructionSet(set));
    Random random(86);
    double worstError = 0.0;
    for (int n = 0; n < 3000; ++n)
    {
      const Vec3 x = random.vec3(1.5), v = random.uniform(0.2, 2.0) * random.unit();
      const double w = random.uniform(-100.0, 100.0), strength = random.uniform(-2.0, 2.0);
      const double k = n % 2 ? random.uniform(0.0, 3.0) : 0.0;
      const double eps = random.uniform(1e-3, 0.05);
      const PointPairField field({ { x, v, w } }, k, eps);
      const Vec3 p = random.vec3(3.0);
      const Vec3 u = (-strength * w / (k * norm2(p - x) + eps)) * v;
      const Vec3 y = p - x;
      const Vec3 expected =
        x + (y + norm2(y) * u) / (1.0 + 2.0 * dot(u, y) + norm2(u) * norm2(y));
      for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
      {
        Vec3 pointwise;
        ASSERT_TRUE(field.map(p, strength, rule, pointwise));
        double batch[3];
        const double in[3] = { p.x, p.y, p.z };
        ASSERT_EQ(field.mapPoints(in, batch, 1, strength, rule), 0u);
        for (int i = 0; i < 3; ++i)
        {
          ASSERT_TRUE(sameBits(batch[i], (&pointwise.x)[i])) << set << " case " << n;
        }
        const double scale = std::max(1.0, norm(expected));
        worstError = worseOf(worstError, norm(pointwise - expected) / scale);
      }
    }
    EXPECT_LE(worstError, 1e-9) << set; // 2.7e-11 seen

  }
}

TEST(PointPairKernel, InstructionSetsGiveIdenticalBits)
{
  // No multiply-add the compiler fuses, explicit fused ones correctly rounded: every instruction
  // set rounds alike.
  InstructionSetScope scope;
  Random random(82);
  const Case c = randomCase(random, 9, 1.0, 999);
  const PointPairField field(c.generators, c.falloff, c.epsilon);
  const std::size_t count = c.points.size() / 3;
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<double> reference;
    for (const std::string& set : mapPointsInstructionSets())
    {
      ASSERT_TRUE(useMapPointsInstructionSet(set));
      std::vector<double> out(c.points.size());
      field.mapPoints(c.points.data(), out.data(), count, c.strength, rule);
      if (reference.empty())
      {
        reference = out;
        continue;
      }
      for (std::size_t i = 0; i < out.size(); ++i)
      {
        const bool same = std::isnan(out[i]) ? std::isnan(reference[i]) : out[i] == reference[i];
        ASSERT_TRUE(same) << set << " value " << i;
      }
    }
  }
}

TEST(PointPairKernel, HugeWeightsGiveFiniteImagesEqualToThePointwiseMap)
{
  InstructionSetScope scope;
  for (const std::string& set : mapPointsInstructionSets())
  {
    ASSERT_TRUE(useMapPointsInstructionSet(set));
    Random random(83);
    for (double weight : { 1e3, 1e8, 1e30, 1e150, 1e300 })
    {
      Case c = randomCase(random, 4, 1.0, 200);
      for (PointPairGenerator& g : c.generators)
      {
        g.weight *= weight;
      }
      for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
      {
        const std::string label = set + " weight " + std::to_string(weight);
        expectBatchEqualsPointwise(c, rule, label.c_str());
        const PointPairField field(c.generators, c.falloff, c.epsilon);
        std::vector<double> out(c.points.size());
        field.mapPoints(c.points.data(), out.data(), c.points.size() / 3, c.strength, rule);
        for (std::size_t i = 0; i + 9 < out.size(); ++i) // all but the three non-finite points
        {
          ASSERT_TRUE(std::isfinite(out[i])) << label << " value " << i;
        }
      }
    }
  }
}

TEST(PointPairKernel, NoGeneratorsOrZeroStrengthCopyThePoints)
{
  Random random(84);
  Case c = randomCase(random, 3, 1.0, 20);
  const PointPairField field(c.generators, c.falloff, c.epsilon);
  const PointPairField empty(std::vector<PointPairGenerator>{}, 1.0, 0.1);
  const PointPairField zeroOnly({ { { 0, 0, 0 }, { 0, 0, 0 }, 1.0 } }, 1.0, 0.1);
  const std::size_t count = c.points.size() / 3;
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (const PointPairField* f : { &empty, &zeroOnly, &field })
    {
      const double strength = f == &field ? 0.0 : 1.0;
      std::vector<float> out(c.points.size());
      EXPECT_EQ(f->mapPoints(c.points.data(), out.data(), count, strength, rule), 3u);
      for (std::size_t i = 0; i < out.size(); ++i)
      {
        const float p = static_cast<float>(c.points[i]);
        EXPECT_TRUE(std::isnan(p) ? std::isnan(out[i]) : out[i] == p) << i;
      }
    }
  }
}

TEST(PointPairKernel, InPlaceMapEqualsSeparateOutput)
{
  Random random(85);
  const Case c = randomCase(random, 5, 1.0, 77);
  const PointPairField field(c.generators, c.falloff, c.epsilon);
  const std::size_t count = c.points.size() / 3;
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<double> separate(c.points.size());
    std::vector<double> inPlace = c.points;
    const std::size_t a = field.mapPoints(c.points.data(), separate.data(), count, c.strength, rule);
    const std::size_t b = field.mapPoints(inPlace.data(), inPlace.data(), count, c.strength, rule);
    EXPECT_EQ(a, b);
    for (std::size_t i = 0; i < separate.size(); ++i)
    {
      EXPECT_TRUE(std::isnan(separate[i]) ? std::isnan(inPlace[i]) : separate[i] == inPlace[i]);
    }
  }
}

TEST(PointPairKernel, UnknownInstructionSetIsRefused)
{
  InstructionSetScope scope;
  const std::string before = mapPointsInstructionSet();
  EXPECT_FALSE(useMapPointsInstructionSet("no-such-isa"));
  EXPECT_EQ(mapPointsInstructionSet(), before);
}

// The generator sum B(p) of the kernel's pair loop (core::fieldBivector through
// kernel::AddFieldBlock), on every instruction set: the same bits as the documented formula of
// explicit fused multiply-adds (std::fma, correctly rounded: the test's own, not the kernel's),
//   d2 = fma(dz, dz, fma(dy, dy, dx dx)), f = 1 / fma(d2, k, eps), sum_c = fma(f, g_c, sum_c),
// and within its rounding bound of the sum in long double (the independent reference).
TEST(PointPairKernel, GeneratorSumIsFusedAndTheSameOnEveryInstructionSet)
{
  InstructionSetScope scope;
  constexpr int L = kernel::kLanes, kStride = kernel::kGeneratorStride, kComponents = 10;
  Random random(83);
  for (int generatorCount : { 1, 5, 64 })
  {
    std::vector<double> generators;
    for (int i = 0; i < generatorCount; ++i)
    {
      const Vec3 x = random.vec3(1.5);
      generators.insert(generators.end(), { x.x, x.y, x.z });
      for (int c = 0; c < kComponents; ++c)
      {
        generators.push_back(random.uniform(-2.0, 2.0));
      }
    }
    kernel::FieldArgs args;
    args.generators = generators.data();
    args.generatorCount = static_cast<std::size_t>(generatorCount);
    args.falloff = random.uniform(0.1, 3.0);
    args.epsilon = random.uniform(1e-3, 0.5);
    double xyz[3 * L];
    for (int l = 0; l < L; ++l)
    {
      const Vec3 p = random.vec3(2.0);
      xyz[l] = p.x;
      xyz[L + l] = p.y;
      xyz[2 * L + l] = p.z;
    }
    // One lane on the first generator: d2 = 0.
    for (int k = 0; k < 3; ++k)
    {
      xyz[k * L + L - 1] = generators[k];
    }
    double fused[kComponents * L] = {}, bound[kComponents * L] = {};
    long double exact[kComponents * L] = {};
    for (int l = 0; l < L; ++l)
    {
      for (int i = 0; i < generatorCount; ++i)
      {
        const double* g = generators.data() + i * kStride;
        const double dx = xyz[l] - g[0], dy = xyz[L + l] - g[1], dz = xyz[2 * L + l] - g[2];
        const double f = 1.0 / std::fma(std::fma(dz, dz, std::fma(dy, dy, dx * dx)), args.falloff, args.epsilon);
        const long double dxe = static_cast<long double>(xyz[l]) - g[0];
        const long double dye = static_cast<long double>(xyz[L + l]) - g[1];
        const long double dze = static_cast<long double>(xyz[2 * L + l]) - g[2];
        const long double fe = 1.0L / (args.falloff * (dxe * dxe + dye * dye + dze * dze) + args.epsilon);
        for (int c = 0; c < kComponents; ++c)
        {
          fused[c * L + l] = std::fma(f, g[3 + c], fused[c * L + l]);
          exact[c * L + l] += fe * g[3 + c];
          bound[c * L + l] += std::fabs(f * g[3 + c]);
        }
      }
    }
    for (const std::string& set : kernel::availableInstructionSets())
    {
      ASSERT_TRUE(kernel::useInstructionSet(set));
      double sums[kComponents * L] = {};
      kernel::activeAddFieldBlock()(args, xyz, sums);
      int differing = 0;
      double worst = 0.0;
      for (int j = 0; j < kComponents * L; ++j)
      {
        differing += sums[j] == fused[j] ? 0 : 1;
        // Each term errs by a few units of 2^-53 (distance, denominator, division, product), the
        // running sum by one per generator: (M + 8) 2^-53 of the sum of the terms' magnitudes.
        const double error = static_cast<double>(std::fabs(sums[j] - exact[j]));
        worst = worseOf(worst, error / ((generatorCount + 8) * 0x1p-53 * bound[j]));
      }
      EXPECT_EQ(differing, 0) << set << " M=" << generatorCount;
      EXPECT_LE(worst, 1.0) << set << " M=" << generatorCount;
    }
  }
}
// The pair loop's p - x_i is the difference of the doubles given, though both are taken relative
// to the field's center c (p - c and x_i - c): where c is the mean of three locations far from
// the origin (inexact, each x_i within [0.6, 1.6] of it, so x_i - c is exact) and where the
// locations straddle the origin (c = 0). Before the center kept its exact differences, p - c and
// x_i - c each rounded by up to half an ulp of |p - c|, which moved the near term by 2^-53
// |p - c| / |p - x_i| of itself, 5e4 units of 2^-53 at 1e-5 from x_i (docs/conventions.md section
// 2 item 12). The no^ni component of B(p) for dilations is exactly sum_i -w_i / 2 / (k |p -
// x_i|^2 + eps) in space (a dilation has no e_i^no part, so moving it to c and back leaves no^ni
// alone): against that sum in long double from the same doubles (each difference exact there),
// within (M + 8) 2^-53 of the sum (its terms have one sign), on every instruction set, at 0 and
// 1e-12 ... 1e-2 from each generator and at 0.3 and 1 from the first.
TEST(PointPairKernel, PairDifferenceIsTheGivenDoublesWhereverTheCenterIs)
{
  InstructionSetScope scope;
  const Vec3 shifts[2] = { { 0.0, 0.0, 0.0 }, { 100.1, -50.3, 20.7 } };
  for (const Vec3& shift : shifts)
  {
    const bool far = shift.x != 0.0;
    Vec3 locations[3] = { { 0.3, -0.2, 0.1 }, { 0.7, -0.1, -0.1 }, { 0.9, 0.4, -0.5 } };
    for (Vec3& x : locations)
    {
      x = x + shift;
    }
    const double weights[3] = { 0.6, 0.3, 0.5 }, falloff = 1.3, epsilon = 1e-10;
    std::vector<FieldGenerator> generators;
    for (int i = 0; i < 3; ++i)
    {
      generators.push_back(FieldGenerator::dilation(locations[i], weights[i]));
    }
    const PointPairField field(generators.data(), generators.size(), falloff, epsilon);
    const Vec3 c = field.center();
    if (far)
    {
      // the mean kept, and it is not exact: the case the frame's choice is for
      const long double exactMeanX =
        (static_cast<long double>(locations[0].x) + locations[1].x + locations[2].x) / 3.0L;
      EXPECT_NE(static_cast<long double>(c.x), exactMeanX);
      EXPECT_GT(c.x, 100.0);
    }
    else
    {
      EXPECT_TRUE(c.x == 0.0 && c.y == 0.0 && c.z == 0.0);
    }
    const Vec3 direction = normalized(Vec3{ 0.6, -0.3, 0.7 });
    for (const std::string& set : kernel::availableInstructionSets())
    {
      ASSERT_TRUE(kernel::useInstructionSet(set));
      double worst = 0.0;
      std::vector<Vec3> points;
      for (int i = 0; i < 3; ++i)
      {
        for (const double d : { 0.0, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3, 1e-2 })
        {
          points.push_back(locations[i] + d * direction);
        }
      }
      for (const double d : { 0.3, 1.0 })
      {
        points.push_back(locations[0] + d * direction);
      }
      for (const Vec3& p : points)
      {
        long double sum = 0.0L;
        for (int j = 0; j < 3; ++j)
        {
          const long double dx = static_cast<long double>(p.x) - locations[j].x;
          const long double dy = static_cast<long double>(p.y) - locations[j].y;
          const long double dz = static_cast<long double>(p.z) - locations[j].z;
          sum += -0.5L * weights[j] / (falloff * (dx * dx + dy * dy + dz * dz) + epsilon);
        }
        const double noni = field.generatorAt(p).c[Bivector::NONI];
        const double error = static_cast<double>(std::fabs((noni - sum) / sum)) / ((3 + 8) * 0x1p-53);
        EXPECT_LE(error, 1.0) << set << " shift " << shift.x << " point " << p.x << " " << p.y
                              << " " << p.z;
        worst = worseOf(worst, error);
      }
      RecordProperty("worst_" + set + (far ? "_far" : "_near_origin"), std::to_string(worst));
    }
  }
}
} // namespace

namespace
{
// The wide block (kernel::MapDisplacedWideBlock, AVX-512 only) is the same source on kWideLanes
// lanes: each point's image, displacement, mapped flag and the count of images beyond range are
// those of two calls of the instruction set's MapDisplacedBlock, for both rules, random fields
// with raw bivectors, points on a generator, NaN and infinite points, huge weights, also in place.
TEST(PointPairKernel, TheWideBlockGivesTheBitsOfTwoBlocks)
{
  InstructionSetScope scope;
  constexpr int L = kernel::kLanes, W = kernel::kWideLanes, kStride = kernel::kGeneratorStride;
  int wideSets = 0;
  for (const std::string& set : kernel::availableInstructionSets())
  {
    ASSERT_TRUE(kernel::useInstructionSet(set));
    const kernel::MapDisplacedWideBlock wide = kernel::activeMapDisplacedWideBlock();
    EXPECT_EQ(wide != nullptr, set == "avx512") << set;
    if (!wide)
    {
      continue;
    }
    ++wideSets;
    const kernel::MapDisplacedBlock single = kernel::activeMapDisplacedBlock();
    Random random(84);
    for (int trial = 0; trial < 200; ++trial)
    {
      const int generatorCount = 1 + trial % 7;
      const double weightScale = trial % 10 == 9 ? 1e150 : 1.0;
      std::vector<double> generators;
      for (int i = 0; i < generatorCount; ++i)
      {
        const Vec3 x = random.vec3(1.5);
        generators.insert(generators.end(), { x.x, x.y, x.z });
        for (int c = 0; c < kStride - 3; ++c)
        {
          generators.push_back(weightScale * random.uniform(-2.0, 2.0));
        }
      }
      kernel::FieldArgs args;
      args.generators = generators.data();
      args.generatorCount = static_cast<std::size_t>(generatorCount);
      args.falloff = random.uniform(0.0, 3.0);
      args.epsilon = random.uniform(1e-3, 0.5);
      args.strength = random.uniform(-2.0, 2.0);
      args.exactRule = trial % 2 == 0;
      const double center[3] = { 0.1, -0.2, 0.05 };
      std::vector<double> points(3 * W);
      for (double& v : points)
      {
        v = random.uniform(-2.0, 2.0);
      }
      // On a generator (relative to the center), and not finite, in either half.
      for (int k = 0; k < 3; ++k)
      {
        points[3 * (trial % W) + k] = generators[k] + center[k];
      }
      points[3 * ((trial + 5) % W)] = kNaN;
      points[3 * ((trial + 11) % W) + 2] = trial % 3 ? kInf : -kInf;
      std::vector<double> wideOut(3 * W), wideShift(3 * W), out(3 * W), shift(3 * W);
      std::uint8_t wideMapped[W], mapped[W];
      const int wideBeyond =
        wide(args, center, points.data(), wideOut.data(), wideShift.data(), wideMapped);
      const int beyond =
        single(args, center, points.data(), out.data(), shift.data(), mapped) +
        single(args, center, points.data() + 3 * L, out.data() + 3 * L, shift.data() + 3 * L,
          mapped + L);
      const std::string label = "trial " + std::to_string(trial);
      EXPECT_EQ(wideBeyond, beyond) << label;
      EXPECT_EQ(std::memcmp(wideOut.data(), out.data(), out.size() * sizeof(double)), 0) << label;
      EXPECT_EQ(std::memcmp(wideShift.data(), shift.data(), shift.size() * sizeof(double)), 0)
        << label;
      EXPECT_EQ(std::memcmp(wideMapped, mapped, W), 0) << label;
      // In place, images only.
      std::vector<double> inPlace = points;
      wide(args, center, inPlace.data(), inPlace.data(), nullptr, wideMapped);
      EXPECT_EQ(std::memcmp(inPlace.data(), out.data(), out.size() * sizeof(double)), 0) << label;
    }
  }
  RecordProperty("instruction_sets_with_a_wide_block", wideSets);
}
} // namespace
