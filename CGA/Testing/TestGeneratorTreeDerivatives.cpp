// The map's derivative with a generator tree (PointPairField::setTolerance):
// mapPointsWithJacobians and mapPointsWithDirectionalDerivatives differentiate the tree's own
// approximation of B (its local polynomials, multipole series and direct sums), so their images
// are mapPoints' with the same tree to the bit, and J is checked against the direct sum's J
// (itself tested against central differences: TestDerivatives.cpp). The bound of Tolerance is on
// the images; J's error is measured here, not bounded: within t max|J| / 100 on these fields
// (1e-4 to 1e-3 times t max|J| measured, here and on the bench's field).
#include "TestSupport.h"

#include "cga/PointPairField.h"

#include "../src/GeneratorTree.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace cgatest;

constexpr double kFalloff = 1.0;
constexpr double kEpsilon = 0.05;
// The tests build trees over a few thousand generators (the default crossover is far above).
constexpr std::size_t kTreeFrom = 256;

std::vector<FieldGenerator> randomPointPairs(Random& random, std::size_t count, double half)
{
  std::vector<FieldGenerator> generators;
  for (std::size_t i = 0; i < count; ++i)
  {
    generators.push_back(FieldGenerator::pointPair(
      random.vec3(half), random.vec3(1.0), random.uniform(0.1, 0.4) * 8.0 / count));
  }
  return generators;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(GeneratorTreeDerivatives, ImagesAreTheTreesAndJacobiansApproachTheDirectSumsWithTheTolerance)
{
  Random random(20261207);
  const auto generators = randomPointPairs(random, 2000, 1.0);
  const PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  const std::vector<double> in = wavySheet(24, 1.4);
  const std::size_t n = in.size() / 3;
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<double> directImages(in.size()), directJ(9 * n);
    ASSERT_EQ(direct.mapPointsWithJacobians(
                in.data(), directImages.data(), directJ.data(), n, 0.5, rule), 0u);
    double largestJ = 0.0;
    for (const double j : directJ)
    {
      largestJ = worseOf(largestJ, std::fabs(j));
    }
    double previous = std::numeric_limits<double>::infinity();
    // (At 1e-6 these 2,000 generators are summed directly nearly everywhere.)
    for (const double tolerance : { 1e-2, 1e-3, 1e-4 })
    {
      PointPairField tree(generators.data(), generators.size(), kFalloff, kEpsilon);
      ASSERT_TRUE(tree.setTolerance(tolerance, kTreeFrom, 0.0));
      ASSERT_GT(tree.treeDegree(), 0);
      std::vector<double> images(in.size()), withJ(in.size()), jacobians(9 * n);
      ASSERT_EQ(tree.mapPoints(in.data(), images.data(), n, 0.5, rule), 0u);
      ASSERT_EQ(
        tree.mapPointsWithJacobians(in.data(), withJ.data(), jacobians.data(), n, 0.5, rule), 0u);
      EXPECT_TRUE(sameBits(images, withJ)) << "tolerance " << tolerance;
      for (std::size_t i = 0; i < n; i += 97) // the pointwise form: the batch's bits
      {
        Vec3 single;
        double j[9];
        ASSERT_TRUE(tree.mapWithJacobian({ in[3 * i], in[3 * i + 1], in[3 * i + 2] }, 0.5, rule,
          single, j));
        EXPECT_EQ(single.x, images[3 * i]);
        EXPECT_EQ(single.z, images[3 * i + 2]);
        for (int e = 0; e < 9; ++e)
        {
          EXPECT_EQ(j[e], jacobians[9 * i + e]) << "point " << i;
        }
      }
      double error = 0.0;
      for (std::size_t e = 0; e < jacobians.size(); ++e)
      {
        error = worseOf(error, std::fabs(jacobians[e] - directJ[e]));
      }
      EXPECT_LE(error, 0.01 * tolerance * largestJ) << "tolerance " << tolerance;
      EXPECT_GT(error, 1e-12 * largestJ) << "the tree approximated (tolerance " << tolerance << ")";
      EXPECT_LT(error, previous) << "tolerance " << tolerance;
      previous = error;
      // J along two directions per point is J t_k.
      std::vector<double> directions(6 * n), alongImages(in.size()), along(6 * n);
      for (double& t : directions)
      {
        t = random.uniform(-1.0, 1.0);
      }
      ASSERT_EQ(tree.mapPointsWithDirectionalDerivatives(in.data(), directions.data(),
                  alongImages.data(), along.data(), n, 0.5, rule), 0u);
      EXPECT_TRUE(sameBits(images, alongImages));
      for (std::size_t i = 0; i < n; ++i)
      {
        for (int k = 0; k < 2; ++k)
        {
          for (int r = 0; r < 3; ++r)
          {
            double expected = 0.0;
            for (int c = 0; c < 3; ++c)
            {
              expected += jacobians[9 * i + 3 * r + c] * directions[6 * i + 3 * k + c];
            }
            ASSERT_NEAR(along[6 * i + 3 * k + r], expected, 1e-15 * (1.0 + std::fabs(expected)))
              << "point " << i;
          }
        }
      }
    }
  }
}

// B's central differences at p along axis k from `evaluateAt(point, bivectors)` (10 values).
template <typename Evaluate>
void centralDifference(Evaluate&& evaluateAt, const double* p, int k, double h, double* difference)
{
  double forward[3] = { p[0], p[1], p[2] }, backward[3] = { p[0], p[1], p[2] };
  forward[k] += h;
  backward[k] -= h;
  double plus[Bivector::Count], minus[Bivector::Count];
  evaluateAt(forward, plus);
  evaluateAt(backward, minus);
  for (int c = 0; c < Bivector::Count; ++c)
  {
    difference[c] = (plus[c] - minus[c]) / (2.0 * h);
  }
}

TEST(GeneratorTreeDerivatives, GradientsAreTheDerivativesOfTheSameApproximation)
{
  // Within one leaf cube of the lattice evaluatePoints uses the same expansions and direct sums
  // at every point (they are chosen per cube), and evaluate() with its eight lanes at one point
  // the same ones near it: B is a smooth function there, and its gradients must be its central
  // differences (not the direct sum's, from which the approximation differs by up to t V): the
  // cubes' local polynomials and the direct sums in evaluatePoints, the nodes' series in
  // evaluate().
  Random random(43);
  constexpr int kStride = kernel::kGeneratorStride;
  std::vector<double> generators;
  for (int i = 0; i < 4000; ++i)
  {
    const Vec3 x = random.vec3(1.0);
    generators.insert(generators.end(), { x.x, x.y, x.z });
    for (int c = 0; c < Bivector::Count; ++c)
    {
      generators.push_back(random.uniform(-1.0, 1.0) * 2e-3);
    }
  }
  const detail::GeneratorTree tree(generators.data(), generators.size() / kStride, kFalloff,
    kEpsilon, 1e-3);
  const double side = tree.leafSide();
  std::vector<detail::TreeBoundRecord> records;
  detail::treeBoundRecords = &records;
  int locals = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    // A leaf cube's center, inside the generators' box and beyond it.
    double p[3];
    for (double& x : p)
    {
      x = (std::floor(random.uniform(-1.5, 1.5) / side) + 0.5) * side;
    }
    double b[Bivector::Count], gradients[3 * Bivector::Count];
    records.clear();
    tree.evaluatePoints(p, 1, b, gradients);
    for (const detail::TreeBoundRecord& r : records)
    {
      locals += r.perPoint ? 0 : 1;
    }
    const double h = 1e-4 * side;
    for (int k = 0; k < 3; ++k)
    {
      double difference[Bivector::Count];
      centralDifference([&](const double* q, double* out) { tree.evaluatePoints(q, 1, out); }, p,
        k, h, difference);
      double largest = 0.0;
      for (int c = 0; c < Bivector::Count; ++c)
      {
        largest = worseOf(largest, std::fabs(gradients[3 * c + k]));
      }
      for (int c = 0; c < Bivector::Count; ++c)
      {
        EXPECT_NEAR(gradients[3 * c + k], difference[c], 1e-6 * (1.0 + largest))
          << "trial " << trial << ", axis " << k << ", component " << c;
      }
    }
  }
  EXPECT_GT(locals, 0) << "local expansions took part";
  // evaluate() (the points beyond the lattice): eight lanes at one point, at distances where the
  // nodes' series serve it from the root down.
  const auto atPoint = [&](const double* q, double* out, double* gradients) {
    alignas(64) double lanes[3 * kernel::kLanes], sums[Bivector::Count * kernel::kLanes],
      sumGradients[3 * Bivector::Count * kernel::kLanes];
    for (int k = 0; k < 3; ++k)
    {
      std::fill_n(lanes + k * kernel::kLanes, kernel::kLanes, q[k]);
    }
    tree.evaluate(lanes, sums, gradients ? sumGradients : nullptr);
    for (int c = 0; c < Bivector::Count; ++c)
    {
      out[c] = sums[c * kernel::kLanes];
      for (int k = 0; gradients && k < 3; ++k)
      {
        gradients[3 * c + k] = sumGradients[(3 * c + k) * kernel::kLanes];
      }
    }
  };
  records.clear();
  for (const double distance : { 2.5, 4.0, 9.0 })
  {
    const Vec3 direction = normalized(random.vec3(1.0));
    const double p[3] = { distance * direction.x, distance * direction.y, distance * direction.z };
    double b[Bivector::Count], gradients[3 * Bivector::Count];
    atPoint(p, b, gradients);
    for (int k = 0; k < 3; ++k)
    {
      double difference[Bivector::Count];
      centralDifference([&](const double* q, double* out) { atPoint(q, out, nullptr); }, p, k,
        1e-5, difference);
      for (int c = 0; c < Bivector::Count; ++c)
      {
        EXPECT_NEAR(gradients[3 * c + k], difference[c], 1e-7) << "distance " << distance;
      }
    }
  }
  EXPECT_FALSE(records.empty()) << "evaluate() used the nodes' series";
  for (const detail::TreeBoundRecord& r : records)
  {
    EXPECT_TRUE(r.perPoint);
  }
  detail::treeBoundRecords = nullptr;
}

TEST(GeneratorTreeDerivatives, EveryInstructionSetGivesTheSameBits)
{
  // The tree's lane loops are compiled per instruction set (chosen by the CPU) and the kernel's
  // map by the exponent with its tangents by the instruction set in use: no multiply-add fused
  // by the compiler anywhere, so the images and J are the same bits on every one.
  InstructionSetScope scope;
  Random random(47);
  const auto generators = randomPointPairs(random, 1000, 1.0);
  PointPairField tree(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(tree.setTolerance(1e-2, kTreeFrom, 0.0));
  const std::vector<double> in = wavySheet(10, 1.3);
  const std::size_t n = in.size() / 3;
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    std::vector<double> firstImages, firstJ;
    for (const std::string& set : mapPointsInstructionSets())
    {
      ASSERT_TRUE(useMapPointsInstructionSet(set));
      std::vector<double> images(in.size()), jacobians(9 * n);
      ASSERT_EQ(tree.mapPointsWithJacobians(in.data(), images.data(), jacobians.data(), n, 0.5,
                  rule), 0u);
      if (firstImages.empty())
      {
        firstImages = images;
        firstJ = jacobians;
        continue;
      }
      EXPECT_TRUE(sameBits(images, firstImages)) << set;
      EXPECT_TRUE(sameBits(jacobians, firstJ)) << set;
    }
  }
}

TEST(GeneratorTreeDerivatives, PointsBeyondTheCellLatticeAndNonFinitePoints)
{
  // Beyond 2^50 leaf cubes a point is evaluated alone (GeneratorTree::evaluate with gradients);
  // a point that is not finite is left in place with the identity as its J.
  Random random(41);
  const auto generators = randomPointPairs(random, 2000, 1.0);
  const PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  PointPairField tree(generators.data(), generators.size(), kFalloff, kEpsilon);
  ASSERT_TRUE(tree.setTolerance(1e-6, kTreeFrom, 0.0));
  const double nan = std::nan("");
  const std::vector<double> in = { 1e17, 3.0, -2.0, -3e40, 2.0, -1e30, 0.1, 0.2, 0.3,
                                   nan, 0.0, 0.0, 0.4, -0.3, 0.05 };
  const std::size_t n = in.size() / 3;
  std::vector<double> images(in.size()), withJ(in.size()), jacobians(9 * n), directJ(9 * n),
    directImages(in.size());
  EXPECT_EQ(tree.mapPoints(in.data(), images.data(), n, 0.5, ExponentialRule::Exact), 1u);
  EXPECT_EQ(tree.mapPointsWithJacobians(in.data(), withJ.data(), jacobians.data(), n, 0.5,
              ExponentialRule::Exact), 1u);
  EXPECT_EQ(direct.mapPointsWithJacobians(in.data(), directImages.data(), directJ.data(), n, 0.5,
              ExponentialRule::Exact), 1u);
  for (std::size_t e = 0; e < in.size(); ++e)
  {
    if (!std::isnan(in[e]))
    {
      EXPECT_EQ(images[e], withJ[e]) << e;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int e = 0; e < 9; ++e)
    {
      EXPECT_NEAR(jacobians[9 * i + e], directJ[9 * i + e], 1e-6) << "point " << i;
    }
  }
  for (int e = 0; e < 9; ++e)
  {
    EXPECT_EQ(jacobians[9 * 3 + e], e % 4 == 0 ? 1.0 : 0.0); // the NaN point: the identity
  }
}
} // namespace
