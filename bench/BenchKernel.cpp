// The batch kernel, PointPairField::mapPoints, on the 1,000,000 points of the shared mesh:
// Kernel/<rule>/M:<generators>/threads:<n> (runOnThreads: chunks of 8192 points).
#include "BenchSupport.h"

#include <vector>

namespace
{
using namespace boostedbench;

void Kernel(benchmark::State& state, cga::ExponentialRule rule)
{
  const int generators = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const cga::PointPairField field(benchmarkGenerators(generators), kFalloff, kEpsilon);
  const double* in = benchmarkPoints();
  std::vector<double> out(3 * kMeshPoints);
  if (field.mapPoints(in, out.data(), kMeshPoints, kStrength, rule) != 0)
  {
    state.SkipWithError("some points were left unchanged: not the path to time");
    return;
  }
  for (auto _ : state)
  {
    runOnThreads(threads, kMeshPoints, [&](std::size_t first, std::size_t last) {
      field.mapPoints(in + 3 * first, out.data() + 3 * first, last - first, kStrength, rule);
    });
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(cga::mapPointsInstructionSet());
  reportPoints(state, kMeshPoints);
}

BENCHMARK_CAPTURE(Kernel, Paper, cga::ExponentialRule::Paper)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(Kernel, Exact, cga::ExponentialRule::Exact)
  ->Apply(perGeneratorsAndThreads);
} // namespace
