// Where the generator tree's a-priori bound loses against the error it bounds (docs/conventions.md
// section 3 item 14, "The bound's excess"): at sample points of a dense sheet through a field like
// the bench's, every expansion the tree used there (GeneratorTree::evaluatePoints, recorded through
// treeBoundRecords) is compared with the direct sum of its own generators. Checked: each node's
// first-order image error is within the bound its degree was chosen by, that bound within its
// share, and the shares of one point within t V (the enforced chain, node by node, where the other
// tests check only its sum). Printed: the factors between t V and the measured error.
#include "TestSupport.h"

#include "cga/PointPairField.h"
#include "cga/PointPairs.h"

#include "../src/GeneratorTree.h"
#include "../src/TreeRemainder.h"

#include <cstdio>
#include <map>
#include <tuple>

namespace cga
{
namespace detail
{
// The test's access to the tree's nodes (a friend of GeneratorTree).
struct TreeBoundSplit
{
  // Geometric means over the sample points of the factors between t V and the point's error:
  //   budget   t V over the sum of the shares of the nodes used (X/Phi below 1),
  //   degree   the shares over the bounds the chosen degrees give (degrees are whole),
  // and, beside them (not a factor of t V / error), sign: the absolute bound (the tail from p + 1 by
  // the generators' absolute moments) over the enforced one (the signed moments' terms to P);
  // the factors of the absolute bound over the error:
  //   motion   the absolute bound over sum_i |v_p(g_i)| w_i R_p(q, S)/D, the generators' motions at the
  //            cube's farthest point (A0 + A1 l + A2 l^2) against each generator's own at p,
  //   cube     that over sum_i |v_p(g_i)| R_p(q_i, S)/D with q_i from the generator's own |w|
  //            at p (the bound takes the worst point of the cube: |w| <= r_i + r),
  //   terms    that over sum_i |v_p(g_i)| |e_i|, e_i the generator's own truncation error (the
  //            per-term bound min(j + 1, S) of the Chebyshev U_j against their actual values),
  //   signs    that over the node's error |v_p(sum_i g_i e_i)| (cancellation within a node),
  //   nodes    the sum of the nodes' errors over the point's error (cancellation across nodes).
  struct Split
  {
    double budget = 0, degree = 0, sign = 0, motion = 0, cube = 0, terms = 0, signs = 0, nodes = 0, total = 0;
    std::size_t points = 0, uses = 0;
  };

  static Split measure(const GeneratorTree& tree, const std::vector<double>& xyz, std::size_t samples)
  {
    constexpr int L = kernel::kLanes;
    constexpr int kComponents = Bivector::Count;
    const std::size_t count = xyz.size() / 3;
    std::vector<double> out(count * kComponents);
    std::vector<TreeBoundRecord> records;
    treeBoundRecords = &records;
    tree.evaluatePoints(xyz.data(), count, out.data());
    treeBoundRecords = nullptr;
    // A per-point use is recorded once per block of lanes of its leaf: once each.
    std::map<std::tuple<int, double, double, double, bool>, TreeBoundRecord> uses;
    for (const TreeBoundRecord& r : records)
    {
      uses[{ r.node, r.center[0], r.center[1], r.center[2], r.perPoint }] = r;
    }
    const double k = tree.Falloff, eps = tree.Epsilon;
    Split split;
    for (std::size_t s = 0; s < samples; ++s)
    {
      const double* p = xyz.data() + 3 * ((count * (2 * s + 1)) / (2 * samples));
      const Vec3 at{ p[0], p[1], p[2] };
      Bivector exact;
      const std::size_t generators = tree.Nodes[0].count;
      for (std::size_t i = 0; i < generators; ++i)
      {
        const double* g = tree.Generators.data() + i * kernel::kGeneratorStride;
        const double f = 1.0 / (k * ((p[0] - g[0]) * (p[0] - g[0]) + (p[1] - g[1]) * (p[1] - g[1]) +
                                     (p[2] - g[2]) * (p[2] - g[2])) + eps);
        for (int c = 0; c < kComponents; ++c)
        {
          exact.c[static_cast<std::size_t>(c)] += f * g[3 + c];
        }
      }
      Bivector approximate;
      std::copy_n(out.data() + kComponents * (p - xyz.data()) / 3, kComponents, approximate.c.data());
      const double error = norm(firstOrderMotion(approximate - exact, at));
      double shares = 0, bounds = 0, absoluteBounds = 0, rims = 0, terms = 0, absolutes = 0, errors = 0;
      std::size_t used = 0;
      for (const auto& entry : uses)
      {
        const TreeBoundRecord& r = entry.second;
        // The use covers p when p lies in its cube of the lattice (the leaf's for a per-point use).
        const double side = r.perPoint ? tree.LeafSide : 2.0 * r.radius / std::sqrt(3.0);
        bool inside = true;
        for (int a = 0; a < 3; ++a)
        {
          inside = inside && (std::floor(p[a] / side) + 0.5) * side == r.center[a];
        }
        if (!inside)
        {
          continue;
        }
        ++used;
        const auto& node = tree.Nodes[static_cast<std::size_t>(r.node)];
        alignas(64) double lanes[3 * L], sums[kComponents * L] = {};
        for (int a = 0; a < 3; ++a)
        {
          std::fill_n(lanes + a * L, L, p[a]);
        }
        if (r.perPoint)
        {
          tree.addMultipole(node, tree.Moments.data() + node.moments, r.degree, lanes, sums);
        }
        else
        {
          std::vector<double> local(static_cast<std::size_t>(tree.MomentCount * kComponents), 0.0);
          tree.addSourceToLocal(node, r.center, r.radius, r.degree, local.data());
          tree.addLocal(local.data(), r.center, r.radius, lanes, sums);
        }
        // The series about the expansion's point (the cube's center, or p): d, D, u = sqrt(k/D) d;
        // generator i's variable w = (x_i - c) - (p - expansion point).
        const double* o = r.perPoint ? p : r.center;
        const double d[3] = { o[0] - node.center[0], o[1] - node.center[1], o[2] - node.center[2] };
        const double D = k * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + eps;
        const double rootKappa = std::sqrt(k / D);
        const double cubeRadius = r.perPoint ? 0.0 : r.radius;
        const double remainder = treeRemainderBound(r.degree, r.q, std::sqrt(r.D / eps)) / r.D;
        Bivector own;
        double rim = 0, term = 0, absolute = 0, rounding = 0;
        for (std::size_t i = node.first; i < node.first + node.count; ++i)
        {
          const double* g = tree.Generators.data() + i * kernel::kGeneratorStride;
          Bivector b;
          std::copy_n(g + 3, kComponents, b.c.data());
          const double f = 1.0 / (k * ((p[0] - g[0]) * (p[0] - g[0]) + (p[1] - g[1]) * (p[1] - g[1]) +
                                       (p[2] - g[2]) * (p[2] - g[2])) + eps);
          own = own + f * b;
          const double motion = norm(firstOrderMotion(b, at));
          double w[3], length = 0, along = 0, fromCenter = 0;
          for (int a = 0; a < 3; ++a)
          {
            w[a] = (g[a] - node.center[a]) - (p[a] - o[a]);
            length += w[a] * w[a];
            along += d[a] * w[a];
            fromCenter += (g[a] - node.center[a]) * (g[a] - node.center[a]);
          }
          length = std::sqrt(length);
          // The generator's own truncation: 1/(k|p - x|^2 + eps) - (1/D) sum_{j <= p} q^j U_j(x).
          const long double x = length > 0 ? rootKappa * along / length : 0.0L, q = rootKappa * length;
          long double previous = 1, current = 2 * x, series = 1, power = 1;
          for (int j = 1; j <= r.degree; ++j)
          {
            power *= q;
            series += power * current;
            const long double next = 2 * x * current - previous;
            previous = current;
            current = next;
          }
          const double truncation = static_cast<double>(static_cast<long double>(f) - series / D);
          absolute += motion * std::fabs(truncation);
          term += motion * treeRemainderBound(r.degree, static_cast<double>(q), std::sqrt(D / eps)) / D;
          rim += motion *
            std::pow((std::sqrt(fromCenter) + cubeRadius) / (node.radius + cubeRadius), r.degree + 1) * remainder;
          rounding += motion * f;
        }
        Bivector expansion;
        for (int c = 0; c < kComponents; ++c)
        {
          expansion.c[static_cast<std::size_t>(c)] = sums[c * L];
        }
        const double nodeError = norm(firstOrderMotion(expansion - own, at));
        // The bound degreeFor tested (docs/conventions.md section 3 item 14): the absolute tail
        // beyond the moments' degree P and, for p < j <= P, the smaller of the degree-j term's
        // absolute and signed bounds, the generators' motions (absolute) and the moments' trace-free
        // norms (signed) at the reach, the old bound (the absolute tail from p + 1) beside it.
        const int P = tree.Degree;
        const double* spread = tree.Spread.data() + node.spread;
        const double* harmonic = tree.Harmonic.data() + node.harmonic;
        double motions[GeneratorTree::kSpreadPowers], signedMotions[GeneratorTree::kHarmonicDegrees];
        for (int j = 0; j < GeneratorTree::kSpreadPowers; ++j)
        {
          motions[j] = spread[j] +
            (spread[GeneratorTree::kSpreadPowers + j] + spread[2 * GeneratorTree::kSpreadPowers + j] * r.reach) *
              r.reach;
        }
        for (int j = 0; j <= P; ++j)
        {
          signedMotions[j] = harmonic[j] +
            (harmonic[GeneratorTree::kHarmonicDegrees + j] + harmonic[2 * GeneratorTree::kHarmonicDegrees + j] * r.reach) *
              r.reach;
        }
        const double extent = node.radius + cubeRadius;
        const double a = extent > 0 ? node.radius / extent : 1.0, b = extent > 0 ? cubeRadius / extent : 0.0;
        const double S = std::sqrt(r.D / eps);
        double bound = treeRemainderBound(P, r.q, S) * treeSpreadMoment(motions, P + 1, a, b) / r.D;
        for (int j = r.degree + 1; j <= P; ++j)
        {
          bound += std::pow(r.q, j) / r.D *
            std::min(std::min(j + 1.0, S) * treeSpreadMoment(motions, j, a, b),
                     treeHarmonicTermNorm(j) * treeSpreadMoment(signedMotions, j, a, b));
        }
        const double absoluteBound = remainder * treeSpreadMoment(motions, r.degree + 1, a, b);
        EXPECT_LE(bound, absoluteBound * (1.0 + 1e-12));
        EXPECT_LE(nodeError, bound + 1e-12 * rounding) << "node " << r.node << " degree " << r.degree;
        EXPECT_LE(bound, r.share * (1.0 + 1e-12)) << "node " << r.node;
        shares += r.share;
        bounds += bound;
        absoluteBounds += absoluteBound;
        rims += rim;
        terms += term;
        absolutes += absolute;
        errors += nodeError;
      }
      EXPECT_LE(shares, tree.Budget * (1.0 + 1e-12));
      if (used == 0 || !(error > 0.0))
      {
        continue;
      }
      ++split.points;
      split.uses += used;
      split.budget += std::log(tree.Budget / shares);
      split.degree += std::log(shares / bounds);
      split.sign += std::log(absoluteBounds / bounds);
      split.motion += std::log(absoluteBounds / rims);
      split.cube += std::log(rims / terms);
      split.terms += std::log(terms / absolutes);
      split.signs += std::log(absolutes / errors);
      split.nodes += std::log(errors / error);
      split.total += std::log(tree.Budget / error);
    }
    for (double* f : { &split.budget, &split.degree, &split.sign, &split.motion, &split.cube, &split.terms, &split.signs,
                       &split.nodes, &split.total })
    {
      *f = split.points > 0 ? std::exp(*f / static_cast<double>(split.points)) : 0.0;
    }
    return split;
  }
};
} // namespace detail
} // namespace cga

namespace
{
using namespace cgatest;

// A field like the bench's (BenchSupport.cpp: point pairs over [-2, 2]^2 x [-0.3, 0.3], weights
// 0.1 ... 0.4 scaled by 16/M, k = 1, eps = 0.05) and 8 rows of its 1000 x 1000 sheet.
TEST(GeneratorTreeBoundSplit, EveryNodeMeetsItsOwnBoundAndTheExcessIsSplit)
{
  constexpr std::size_t kGenerators = 20000;
  Random random(20140601);
  std::vector<double> generators;
  for (std::size_t i = 0; i < kGenerators; ++i)
  {
    const Vec3 location{ random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0), random.uniform(-0.3, 0.3) };
    const FieldGenerator g = FieldGenerator::pointPair(location, random.vec3(1.0), random.uniform(0.1, 0.4) * 16.0 / kGenerators);
    const Bivector weighted = g.weight * g.bivector;
    generators.insert(generators.end(), { location.x, location.y, location.z });
    generators.insert(generators.end(), weighted.c.begin(), weighted.c.end());
  }
  std::vector<double> sheet;
  for (int row = 458; row < 466; ++row)
  {
    for (int column = 0; column < 1000; ++column)
    {
      const double x = -2.0 + 4.0 * column / 999, y = -2.0 + 4.0 * row / 999;
      sheet.insert(sheet.end(), { x, y, 0.3 * std::sin(2.0 * x) * std::cos(3.0 * y) });
    }
  }
  for (const double tolerance : { 1e-2, 1e-4, 1e-6 })
  {
    const cga::detail::GeneratorTree tree(generators.data(), kGenerators, 1.0, 0.05, tolerance);
    const auto split = cga::detail::TreeBoundSplit::measure(tree, sheet, 16);
    EXPECT_GT(split.points, 8u) << "expansions in use at tolerance " << tolerance;
    std::printf("tolerance %g: %zu points, %.1f expansions each; t V / error %.3g = budget %.2f x degree %.2f x "
                "(absolute bound / error: motion %.2f x cube %.2f x terms %.2f x signs %.2f x nodes %.2f) / "
                "(absolute / enforced bound %.2f) (geometric means)\n",
                tolerance, split.points, static_cast<double>(split.uses) / static_cast<double>(split.points),
                split.total, split.budget, split.degree, split.motion, split.cube, split.terms, split.signs,
                split.nodes, split.sign);
  }
}
} // namespace
