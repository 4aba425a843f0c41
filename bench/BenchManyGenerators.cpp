// Many generators: the direct sum against the generator tree (PointPairField::setTolerance) on
// the shared mesh, Many/Direct/M:<M> and Many/Tree/M:<M>/digits:<d> (Tolerance 10^-d), one thread,
// the Exact rule; Many/SparseTree (below), the tree on sparser points; and
// Many/Build/M:<M>/digits:<d>, the tree's build. The direct row maps evenly
// spaced whole rows of the mesh so that it takes about
// kPairs point-generator pairs per iteration at most (all 1,000,000 points up to M = 500; its cost
// per point does not depend on which points); the tree row maps the whole mesh in chunks of 65,536
// points, as the filter does (its target cells need the mesh's density). Both report the rate per
// point ("points timed": how many).
// The tree rows build the tree at every M and tolerance (setTolerance's crossovers,
// treeMinimumGenerators() and treeMinimumTolerance(M), are where the two rows cross). The weights are scaled by 16/M, so that B stays of the size of the M = 16 field at every M.
// The tree rows also report, against the direct sum on the same points:
//   "error/displacement": the largest image error over the largest displacement, the target;
//   "error/scale": the largest image error over s V (V = treeDisplacementScale()), which the
//   tolerance bounds to first order; "scale/displacement": s V over the largest displacement;
// and "tree MB" (the tree's memory) and "degree" (its expansion's).
#include "BenchSupport.h"

#include "cga/PointPairField.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
using namespace boostedbench;

constexpr double kPairs = 5e8;

std::vector<cga::PointPairGenerator> scaledGenerators(int count)
{
  auto generators = benchmarkGenerators(count);
  for (cga::PointPairGenerator& g : generators)
  {
    g.weight *= 16.0 / count;
  }
  return generators;
}

// About 1/stride of the mesh's points as whole rows of it, evenly spaced: blocks of consecutive
// points keep the full mesh's size, which the tree's acceptance test depends on.
std::vector<double> pointSubset(std::size_t stride)
{
  const double* all = benchmarkPoints();
  const std::size_t rows = std::max<std::size_t>(1, kMeshSide / stride);
  std::vector<double> subset;
  for (std::size_t r = 0; r < rows; ++r)
  {
    const std::size_t row = r * kMeshSide / rows;
    subset.insert(subset.end(), all + 3 * row * kMeshSide, all + 3 * (row + 1) * kMeshSide);
  }
  return subset;
}

// The points both rows of a given M time: every stride-th point of the mesh, at most kPairs
// point-generator pairs of the direct sum.
std::vector<double> timedPoints(int count)
{
  return pointSubset(std::max<std::size_t>(
    1, static_cast<std::size_t>(std::ceil(kMeshPoints * static_cast<double>(count) / kPairs))));
}

void ManyDirect(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const cga::PointPairField field(scaledGenerators(count), kFalloff, kEpsilon);
  const std::vector<double> points = timedPoints(count);
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

// The tree's counters against the direct sum on `points` (outside the timing).
void reportTreeErrors(benchmark::State& state, const cga::PointPairField& tree,
                      const cga::PointPairField& direct, const std::vector<double>& points)
{
  const std::size_t n = points.size() / 3;
  std::vector<double> out(points.size());
  tree.mapPoints(points.data(), out.data(), n, kStrength, cga::ExponentialRule::Exact);
  std::vector<double> exact(points.size());
  direct.mapPoints(points.data(), exact.data(), n, kStrength, cga::ExponentialRule::Exact);
  double largestDisplacement = 0.0, largestError = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* p = points.data() + 3 * i;
    const double* e = exact.data() + 3 * i;
    const double* a = out.data() + 3 * i;
    largestDisplacement = std::max(largestDisplacement, std::hypot(e[0] - p[0], e[1] - p[1], e[2] - p[2]));
    largestError = std::max(largestError, std::hypot(a[0] - e[0], a[1] - e[1], a[2] - e[2]));
  }
  const double scale = kStrength * tree.treeDisplacementScale();
  state.counters["error/displacement"] = largestError / largestDisplacement;
  state.counters["error/scale"] = largestError / scale;
  state.counters["scale/displacement"] = scale / largestDisplacement;
  state.counters["tree MB"] = static_cast<double>(tree.treeBytes()) / 1e6;
  state.counters["degree"] = tree.treeDegree();
}

void ManyTree(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  const auto generators = scaledGenerators(count);
  const cga::PointPairField direct(generators, kFalloff, kEpsilon);
  cga::PointPairField tree(generators, kFalloff, kEpsilon);
  tree.setTolerance(tolerance, 1, 0.0); // the tree at every M and tolerance, below the crossovers too
  // Timed: the whole mesh, in the filter's chunks (vtkBoostedBlockLoop::SamplesPerBlock points).
  const double* mesh = benchmarkPoints();
  std::vector<double> meshOut(3 * kMeshPoints);
  constexpr std::size_t kChunk = 65536;
  for (auto _ : state)
  {
    for (std::size_t first = 0; first < kMeshPoints; first += kChunk)
    {
      const std::size_t chunk = std::min(kChunk, kMeshPoints - first);
      tree.mapPoints(mesh + 3 * first, meshOut.data() + 3 * first, chunk, kStrength,
                     cga::ExponentialRule::Exact);
    }
    benchmark::DoNotOptimize(meshOut.data());
    benchmark::ClobberMemory();
  }
  state.counters["points timed"] = static_cast<double>(kMeshPoints);
  reportPoints(state, kMeshPoints);
  // The error against the direct sum on the direct row's points, outside the timing. The tree's
  // B(p) depends on p alone (GeneratorTree::evaluatePoints), so mapping these points again gives
  // the bits the timed run gave them.
  reportTreeErrors(state, tree, direct, timedPoints(count));
}

// Many/SparseTree/M:<M>/digits:<d>/stride:<s>/plan:<0|1>: the tree on a sparse sheet, every
// stride-th point of every stride-th row of the mesh ((1000/s)^2 points), in one call, without
// and with its cells fitted to the points (PointPairField::planTreeCells, as the filter and the
// dipole source do); the counter "coarser" is the plan's k. Compare with Many/Direct: the direct
// sum's cost per point does not depend on the density.
void ManySparseTree(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  const auto stride = static_cast<std::size_t>(state.range(2));
  const auto generators = scaledGenerators(count);
  const cga::PointPairField direct(generators, kFalloff, kEpsilon);
  cga::PointPairField tree(generators, kFalloff, kEpsilon);
  tree.setTolerance(tolerance, 1, 0.0);
  const double* mesh = benchmarkPoints();
  std::vector<double> points;
  for (std::size_t row = 0; row < static_cast<std::size_t>(kMeshSide); row += stride)
  {
    for (std::size_t column = 0; column < static_cast<std::size_t>(kMeshSide); column += stride)
    {
      const double* p = mesh + 3 * (row * kMeshSide + column);
      points.insert(points.end(), p, p + 3);
    }
  }
  const std::size_t n = points.size() / 3;
  const int coarser = state.range(3) ? tree.planTreeCells(points.data(), n) : 0;
  std::vector<double> out(points.size());
  for (auto _ : state)
  {
    tree.mapPoints(points.data(), out.data(), n, kStrength, cga::ExponentialRule::Exact);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["points timed"] = static_cast<double>(n);
  state.counters["coarser"] = coarser;
  reportPoints(state, n);
  std::vector<double> checked; // at most about 5,000 of the points: the direct sum is slow
  for (std::size_t i = 0; i < n; i += std::max<std::size_t>(1, n / 5000))
  {
    checked.insert(checked.end(), points.begin() + 3 * i, points.begin() + 3 * i + 3);
  }
  reportTreeErrors(state, tree, direct, checked);
}

// Building the tree (setTolerance), what the filter pays before any point moves when the
// generators change: "generators/s" (items per second) of wall time.
void ManyBuild(benchmark::State& state)
{
  const int count = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  cga::PointPairField tree(scaledGenerators(count), kFalloff, kEpsilon);
  for (auto _ : state)
  {
    tree.setTolerance(tolerance, 1, 0.0);
    benchmark::DoNotOptimize(tree.treeBytes());
  }
  const double generators = static_cast<double>(count) * static_cast<double>(state.iterations());
  state.counters["generators/s"] = benchmark::Counter(generators, benchmark::Counter::kIsRate);
  state.SetItemsProcessed(static_cast<int64_t>(generators));
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
  ->ArgsProduct({ kManyCounts, { 1, 3, 4, 6 } })
  ->ArgNames({ "M", "digits" })
  ->Apply(timedPerPoint);
BENCHMARK(ManySparseTree)
  ->Name("Many/SparseTree")
  ->ArgsProduct({ { 100000 }, { 3, 6 }, { 10, 3 }, { 0, 1 } })
  ->ArgNames({ "M", "digits", "stride", "plan" })
  ->Apply(timedPerPoint);
BENCHMARK(ManyBuild)
  ->Name("Many/Build")
  ->ArgsProduct({ { 100000, 1000000 }, { 3, 6 } })
  ->ArgNames({ "M", "digits" })
  ->Apply(timedPerPoint);
} // namespace
