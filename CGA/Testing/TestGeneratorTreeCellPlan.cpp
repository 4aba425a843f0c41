// PointPairField::planTreeCells: the tree's target cells widened for sparse points. The plan must
// count the cells each lattice would expand (checked against the distinct floor(p / side)), pick
// wider cells for a sparse sheet and keep the field's own for a dense one, keep the a-priori
// bound |firstOrderMotion(B_tree(p) - B(p), p)| <= t V, and give every call the same bits.
#include "TestSupport.h"

#include "cga/PointPairField.h"
#include "cga/PointPairs.h"

#include "../src/GeneratorTree.h"

#include <array>
#include <cstring>
#include <set>

namespace
{
using namespace cgatest;

constexpr double kFalloff = 1.0;
constexpr double kEpsilon = 0.05;
constexpr std::size_t kTreeFrom = 256; // the tests' trees hold a few thousand generators

std::vector<FieldGenerator> randomPointPairs(Random& random, std::size_t count)
{
  std::vector<FieldGenerator> generators;
  for (std::size_t i = 0; i < count; ++i)
  {
    generators.push_back(
      FieldGenerator::pointPair(random.vec3(1.0), random.vec3(1.0), random.uniform(-0.4, 0.4)));
  }
  return generators;
}

PointPairField treeField(const std::vector<FieldGenerator>& generators, double tolerance)
{
  PointPairField field(generators.data(), generators.size(), kFalloff, kEpsilon);
  EXPECT_TRUE(field.setTolerance(tolerance, kTreeFrom, 0.0));
  EXPECT_GT(field.treeBytes(), 0u);
  return field;
}

TEST(GeneratorTreeCellPlan, CountedCellsAreTheDistinctCellsOfEachLattice)
{
  // A tree over random generators in the layout it takes: per generator its location (relative
  // to the field's center) and the ten components of its weighted bivector.
  Random random(41);
  std::vector<double> layout;
  for (int i = 0; i < 2000; ++i)
  {
    const Vec3 x = random.vec3(1.0);
    layout.insert(layout.end(), { x.x, x.y, x.z });
    for (int c = 0; c < 10; ++c)
    {
      layout.push_back(random.uniform(-0.01, 0.01));
    }
  }
  const detail::GeneratorTree tree(layout.data(), 2000, kFalloff, kEpsilon, 1e-3);
  ASSERT_GT(tree.levels(), 2);
  std::vector<double> points = wavySheet(60, 1.5);
  points.insert(points.end(), { std::nan(""), 0.0, 0.0, 0.0, HUGE_VAL, 0.0 }); // not counted
  const std::size_t count = points.size() / 3;
  const auto levels = static_cast<std::size_t>(tree.levels());
  std::vector<std::size_t> cells(levels + 1, 0);
  EXPECT_EQ(tree.countCells(points.data(), count, cells.data()), count - 2);
  for (std::size_t c = 0; c <= levels; ++c)
  {
    const double side = std::ldexp(tree.leafSide(), static_cast<int>(c));
    std::set<std::array<double, 3>> distinct;
    for (std::size_t i = 0; i + 2 < count; ++i)
    {
      distinct.insert({ std::floor(points[3 * i] / side), std::floor(points[3 * i + 1] / side),
                        std::floor(points[3 * i + 2] / side) });
    }
    EXPECT_EQ(cells[c], distinct.size()) << "the lattice " << c << " levels coarser";
  }
  EXPECT_GT(cells[0], cells[levels]);
  // Counts add up over calls.
  const std::vector<std::size_t> once = cells;
  EXPECT_EQ(tree.countCells(points.data(), count, cells.data()), count - 2);
  for (std::size_t c = 0; c <= levels; ++c)
  {
    EXPECT_EQ(cells[c], 2 * once[c]);
  }
}

TEST(GeneratorTreeCellPlan, SparsePointsGetWiderCellsDensePointsTheFieldsOwn)
{
  Random random(43);
  const auto generators = randomPointPairs(random, 4000);
  PointPairField field = treeField(generators, 1e-3);
  // 144 points over 3 x 3 (0.27 apart; the leaves are 0.03 wide): about one point per leaf.
  const std::vector<double> sparse = wavySheet(12, 1.5);
  const int k = field.planTreeCells(sparse.data(), sparse.size() / 3);
  EXPECT_GT(k, 2);
  EXPECT_EQ(field.treeCellsCoarser(), k);
  // The same points in float: the same plan.
  const std::vector<float> sparseFloat(sparse.begin(), sparse.end());
  EXPECT_EQ(field.planTreeCells(sparseFloat.data(), sparseFloat.size() / 3), k);
  // 40,000 points over 0.5 x 0.5 (0.0025 apart): well over treeCellPoints() per leaf.
  const std::vector<double> dense = wavySheet(200, 0.25);
  EXPECT_EQ(field.planTreeCells(dense.data(), dense.size() / 3), 0);
  // No points, or none finite: the field's own cells.
  const double nan = std::nan("");
  const double notFinite[6] = { nan, 0.0, 0.0, 0.0, nan, 0.0 };
  EXPECT_EQ(field.planTreeCells(sparse.data(), sparse.size() / 3), k);
  EXPECT_EQ(field.planTreeCells(notFinite, 2), 0);
  EXPECT_EQ(field.planTreeCells(sparse.data(), sparse.size() / 3), k);
  EXPECT_EQ(field.planTreeCells(sparse.data(), 0), 0);
  // A new tolerance, or a shared tree, starts from the field's own cells.
  EXPECT_EQ(field.planTreeCells(sparse.data(), sparse.size() / 3), k);
  ASSERT_TRUE(field.setTolerance(1e-3, kTreeFrom, 0.0));
  EXPECT_EQ(field.treeCellsCoarser(), 0);
  PointPairField sharing(generators.data(), generators.size(), kFalloff, kEpsilon);
  EXPECT_EQ(field.planTreeCells(sparse.data(), sparse.size() / 3), k);
  ASSERT_TRUE(sharing.shareTree(field, 1e-3, kTreeFrom, 0.0));
  EXPECT_EQ(sharing.treeCellsCoarser(), 0);
  // Without a tree there is nothing to plan.
  PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  EXPECT_EQ(direct.planTreeCells(sparse.data(), sparse.size() / 3), 0);
}

TEST(GeneratorTreeCellPlan, WiderCellsMeetTheBoundAndDoNotDependOnTheCall)
{
  Random random(47);
  const auto generators = randomPointPairs(random, 4000);
  const PointPairField direct(generators.data(), generators.size(), kFalloff, kEpsilon);
  const Vec3 c = direct.center();
  const std::vector<double> points = wavySheet(24, 1.6);
  const std::size_t n = points.size() / 3;
  for (const double tolerance : { 1e-2, 1e-5 })
  {
    PointPairField tree = treeField(generators, tolerance);
    std::vector<double> own(points.size()), planned(points.size());
    ASSERT_EQ(tree.mapPoints(points.data(), own.data(), n, 0.5, ExponentialRule::Exact), 0u);
    const int k = tree.planTreeCells(points.data(), n);
    ASSERT_GT(k, 0) << "tolerance " << tolerance;
    ASSERT_EQ(tree.mapPoints(points.data(), planned.data(), n, 0.5, ExponentialRule::Exact), 0u);
    EXPECT_NE(std::memcmp(own.data(), planned.data(), own.size() * sizeof(double)), 0)
      << "the plan's cells are in use";
    // The bound at every point, with the plan's cells (generatorAt uses them too).
    const double budget = tree.tolerance() * tree.treeDisplacementScale();
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      const Bivector exact = translatedBivector(direct.generatorAt(p), -1.0 * c);
      const Bivector approximate = translatedBivector(tree.generatorAt(p), -1.0 * c);
      worst = worseOf(worst, norm(firstOrderMotion(approximate - exact, p - c)) / budget);
    }
    EXPECT_LE(worst, 1.0) << "tolerance " << tolerance;
    EXPECT_GT(worst, 1e-9) << "tolerance " << tolerance << ": the check is not vacuous";
    // The same bits in calls of other sizes, in reverse order, and one point at a time.
    std::vector<double> chunked(points.size()), reversed(points.size()), backwards(points.size());
    for (std::size_t first = 0, size = 1; first < n; first += size, size = size * 3 + 1)
    {
      const std::size_t count = std::min(size, n - first);
      tree.mapPoints(points.data() + 3 * first, chunked.data() + 3 * first, count, 0.5,
                     ExponentialRule::Exact);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      std::copy_n(points.data() + 3 * (n - 1 - i), 3, backwards.data() + 3 * i);
    }
    tree.mapPoints(backwards.data(), reversed.data(), n, 0.5, ExponentialRule::Exact);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        ASSERT_EQ(planned[3 * i + j], chunked[3 * i + j]) << "point " << i;
        ASSERT_EQ(planned[3 * i + j], reversed[3 * (n - 1 - i) + j]) << "point " << i;
      }
      if (i % 37 == 0)
      {
        Vec3 single;
        ASSERT_TRUE(tree.map({ points[3 * i], points[3 * i + 1], points[3 * i + 2] }, 0.5,
                             ExponentialRule::Exact, single));
        EXPECT_EQ(single.x, planned[3 * i]);
        EXPECT_EQ(single.y, planned[3 * i + 1]);
        EXPECT_EQ(single.z, planned[3 * i + 2]);
      }
    }
    // The images with J take the same cells: their images are mapPoints' bits.
    std::vector<double> withJacobians(points.size()), jacobians(9 * n);
    ASSERT_EQ(tree.mapPointsWithJacobians(points.data(), withJacobians.data(), jacobians.data(), n,
                                          0.5, ExponentialRule::Exact),
              0u);
    EXPECT_EQ(std::memcmp(withJacobians.data(), planned.data(), planned.size() * sizeof(double)), 0);
  }
}
} // namespace
