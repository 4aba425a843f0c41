// Many generators: the direct sum against the generator tree (PointPairField::setTolerance) on
// the shared mesh, Many/Direct/M:<M> and Many/Tree/M:<M>/digits:<d> (Tolerance 10^-d), one thread,
// the Exact rule. The direct sum at large M maps every stride-th point only (kDirectPairs pairs
// per iteration at most) and reports the rate per point; the tree maps all 1,000,000 points.
// The weights are scaled by 16/M, so that B stays of the size of the M = 16 field at every M.
// The tree rows also report, on every 100th point against the direct sum:
//   "error/displacement": the largest image error over the largest displacement, the target;
//   "B error/A": the largest |B_tree - B|_max / A(p), which the tolerance bounds;
// and "tree MB" (the tree's memory) and "degree" (its expansion's).
#include "BenchSupport.h"

#include "cga/PointPairs.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
using namespace boostedbench;

constexpr double kDirectPairs = 2e9;
constexpr std::size_t kCheckStride = 100;

std::vector<cga::PointPairGenerator> scaledGenerators(int count)
{
  auto generators = benchmarkGenerators(count);
  for (cga::PointPairGenerator& g : generators)
  {
    g.weight *= 16.0 / count;
  }
  return generators;
}

// Every stride-th point of the mesh.
std::vector<double> pointSubset(std::size_t stride)
{
  const double* all = benchmarkPoints();
  std::vector<double> subset;
  for (std::size_t i = 0; i < kMeshPoints; i += stride)
  {
    subset.insert(subset.end(), all + 3 * i, all + 3 * i + 3);
  }
  return subset;
}

void ManyDirect(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const cga::PointPairField field(scaledGenerators(count), kFalloff, kEpsilon);
  const std::size_t stride =
    std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(kMeshPoints * double(count) / kDirectPairs)));
  const std::vector<double> points = pointSubset(stride);
  const std::size_t n = points.size() / 3;
  std::vector<double> out(points.size());
  for (auto _ : state)
  {
    field.mapPoints(points.data(), out.data(), n, kStrength, cga::ExponentialRule::Exact);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["points timed"] = static_cast<double>(n);
  reportPoints(state, n);
}

void ManyTree(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  const auto generators = scaledGenerators(count);
  const cga::PointPairField direct(generators, kFalloff, kEpsilon);
  cga::PointPairField tree(generators, kFalloff, kEpsilon);
  tree.setTolerance(tolerance);
  const double* in = benchmarkPoints();
  std::vector<double> out(3 * kMeshPoints);
  for (auto _ : state)
  {
    tree.mapPoints(in, out.data(), kMeshPoints, kStrength, cga::ExponentialRule::Exact);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  reportPoints(state, kMeshPoints);
  // The error against the direct sum, outside the timing.
  const std::vector<double> check = pointSubset(kCheckStride);
  const std::size_t n = check.size() / 3;
  std::vector<double> exact(check.size());
  direct.mapPoints(check.data(), exact.data(), n, kStrength, cga::ExponentialRule::Exact);
  double largestDisplacement = 0.0, largestError = 0.0, largestBError = 0.0;
  const cga::Vec3 c = direct.center();
  for (std::size_t i = 0; i < n; ++i)
  {
    const cga::Vec3 p{ check[3 * i], check[3 * i + 1], check[3 * i + 2] };
    const double* e = exact.data() + 3 * i;
    const double* a = out.data() + 3 * kCheckStride * i;
    largestDisplacement = std::max(largestDisplacement, std::hypot(e[0] - p.x, e[1] - p.y, e[2] - p.z));
    largestError = std::max(largestError, std::hypot(a[0] - e[0], a[1] - e[1], a[2] - e[2]));
    if (i % 10 == 0) // A(p) costs M products: every 1000th point of the mesh
    {
      double mass = 0.0;
      for (const cga::PointPairGenerator& g : generators)
      {
        const cga::Vec3 d = p - g.location;
        const cga::Bivector weighted = cga::translatedBivector(
          g.weight * cga::nullPointPairCompact(g.location, g.direction), -1.0 * c);
        mass += weighted.maxAbs() / (kFalloff * cga::dot(d, d) + kEpsilon);
      }
      const cga::Bivector difference = cga::translatedBivector(tree.generatorAt(p), -1.0 * c) -
        cga::translatedBivector(direct.generatorAt(p), -1.0 * c);
      largestBError = std::max(largestBError, difference.maxAbs() / mass);
    }
  }
  state.counters["error/displacement"] = largestError / largestDisplacement;
  state.counters["B error/A"] = largestBError;
  state.counters["tree MB"] = static_cast<double>(tree.treeBytes()) / 1e6;
  state.counters["degree"] = tree.treeDegree();
}

const std::vector<long> kManyCounts = { 256, 1000, 3000, 10000, 30000, 100000 };

BENCHMARK(ManyDirect)
  ->Name("Many/Direct")
  ->ArgsProduct({ kManyCounts })
  ->ArgNames({ "M" })
  ->Apply(timedPerPoint);
BENCHMARK(ManyTree)
  ->Name("Many/Tree")
  ->ArgsProduct({ kManyCounts, { 3, 6 } })
  ->ArgNames({ "M", "digits" })
  ->Apply(timedPerPoint);
} // namespace
