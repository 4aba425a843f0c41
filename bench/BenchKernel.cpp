// The batch kernel, PointPairField::mapPoints, on the 1,000,000 points of the shared mesh:
// Kernel/<rule>/M:<generators>/threads:<n> (runOnThreads: a share per thread, guided chunks of
// 8192 to 1024 points);
// and on the same sheet at N = 10^4 ... 10^7 points, M = 16:
// KernelSize/Exact/M:16/N:<points>/threads:<n>; the images with their Jacobians
// (mapPointsWithJacobians, the derivative's cost per point):
// KernelJacobian/<rule>/M:<generators>/threads:<n>; the images with the derivatives along two
// directions per point (mapPointsWithDirectionalDerivatives, what the filter's normals take):
// KernelDirectional/<rule>/M:<generators>/threads:<n>; the images with the filter's
// displacements (mapPointsWithDisplacements): KernelDisplacements/<rule>/M:<generators>/threads:<n>.
#include "BenchSupport.h"

#include <algorithm>
#include <vector>

namespace
{
using namespace boostedbench;

// Times map(first, last), a batch map of the points first ... last - 1 that returns how many it
// left unchanged, over `count` points on `threads` threads, after checking once that it moves
// every point.
template <typename Map>
void timeBatchMap(benchmark::State& state, int threads, std::size_t count, const Map& map)
{
  if (map(0, count) != 0)
  {
    state.SkipWithError("some points were left unchanged: not the path to time");
    return;
  }
  for (auto _ : state)
  {
    runOnThreads(threads, count, [&](std::size_t first, std::size_t last) { map(first, last); });
    benchmark::ClobberMemory();
  }
  state.SetLabel(cga::mapPointsInstructionSet());
  reportPoints(state, count);
}

void timeKernel(benchmark::State& state, cga::ExponentialRule rule, int generators, int threads,
  vtkStructuredGrid* mesh)
{
  const auto count = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  const cga::PointPairField field(benchmarkGenerators(generators), kFalloff, kEpsilon);
  const double* in = meshPoints(mesh);
  std::vector<double> out(3 * count);
  timeBatchMap(state, threads, count, [&](std::size_t first, std::size_t last) {
    const std::size_t unchanged =
      field.mapPoints(in + 3 * first, out.data() + 3 * first, last - first, kStrength, rule);
    benchmark::DoNotOptimize(out.data());
    return unchanged;
  });
}

void KernelJacobian(benchmark::State& state, cga::ExponentialRule rule)
{
  vtkStructuredGrid* mesh = benchmarkMesh();
  const auto count = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  const cga::PointPairField field(
    benchmarkGenerators(static_cast<int>(state.range(0))), kFalloff, kEpsilon);
  const double* in = meshPoints(mesh);
  std::vector<double> out(3 * count), jacobians(9 * count);
  timeBatchMap(state, static_cast<int>(state.range(1)), count,
    [&](std::size_t first, std::size_t last) {
      const std::size_t unchanged = field.mapPointsWithJacobians(in + 3 * first,
        out.data() + 3 * first, jacobians.data() + 9 * first, last - first, kStrength, rule);
      benchmark::DoNotOptimize(jacobians.data());
      return unchanged;
    });
}

void KernelDirectional(benchmark::State& state, cga::ExponentialRule rule)
{
  vtkStructuredGrid* mesh = benchmarkMesh();
  const auto count = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  const cga::PointPairField field(
    benchmarkGenerators(static_cast<int>(state.range(0))), kFalloff, kEpsilon);
  const double* in = meshPoints(mesh);
  // The two unit tangents of the filter benchmark's normal (0, 0.6, 0.8) at every point.
  std::vector<double> directions(6 * count), out(3 * count), derivatives(6 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const double t[6] = { 1.0, 0.0, 0.0, 0.0, 0.8, -0.6 };
    std::copy(t, t + 6, directions.begin() + 6 * i);
  }
  timeBatchMap(state, static_cast<int>(state.range(1)), count,
    [&](std::size_t first, std::size_t last) {
      const std::size_t unchanged = field.mapPointsWithDirectionalDerivatives(in + 3 * first,
        directions.data() + 6 * first, out.data() + 3 * first, derivatives.data() + 6 * first,
        last - first, kStrength, rule);
      benchmark::DoNotOptimize(derivatives.data());
      return unchanged;
    });
}

// The filter's pass over the points (mapPointsWithDisplacements): the images and the
// Displacement array, 48 bytes written per point instead of 24; Filter/... ÷ this is the rest of
// an update (pipeline, output arrays).
void KernelDisplacements(benchmark::State& state, cga::ExponentialRule rule)
{
  vtkStructuredGrid* mesh = benchmarkMesh();
  const auto count = static_cast<std::size_t>(mesh->GetNumberOfPoints());
  const cga::PointPairField field(
    benchmarkGenerators(static_cast<int>(state.range(0))), kFalloff, kEpsilon);
  const double* in = meshPoints(mesh);
  std::vector<double> out(3 * count), displacements(3 * count);
  timeBatchMap(state, static_cast<int>(state.range(1)), count,
    [&](std::size_t first, std::size_t last) {
      const std::size_t unchanged = field.mapPointsWithDisplacements(in + 3 * first,
        out.data() + 3 * first, displacements.data() + 3 * first, last - first, kStrength, rule)
                                      .unchanged;
      benchmark::DoNotOptimize(displacements.data());
      return unchanged;
    });
}

void Kernel(benchmark::State& state, cga::ExponentialRule rule)
{
  timeKernel(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
    benchmarkMesh());
}

void KernelSize(benchmark::State& state, cga::ExponentialRule rule)
{
  timeKernel(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(2)),
    sheetMesh(static_cast<std::size_t>(state.range(1))));
}

BENCHMARK_CAPTURE(Kernel, Paper, cga::ExponentialRule::Paper)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(Kernel, Exact, cga::ExponentialRule::Exact)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelDisplacements, Paper, cga::ExponentialRule::Paper)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelDisplacements, Exact, cga::ExponentialRule::Exact)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelJacobian, Paper, cga::ExponentialRule::Paper)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelJacobian, Exact, cga::ExponentialRule::Exact)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelDirectional, Paper, cga::ExponentialRule::Paper)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelDirectional, Exact, cga::ExponentialRule::Exact)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(KernelSize, Exact, cga::ExponentialRule::Exact)->Apply(perPointCount);
} // namespace
