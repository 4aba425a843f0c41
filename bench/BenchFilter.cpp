// vtkPointPairDeformationFilter with the kernel benchmark's field, vtkSMPTools on the STDThread
// backend: on the shared 1,000,000-point mesh, Filter/<rule>/M:<generators>/threads:<n>, and on
// the same sheet at N = 10^4 ... 10^7 points, M = 16, one and two threads,
// FilterSize/Exact/M:16/N:<points>/threads:<n>.
// The target: within 1.3 times the bare kernel's time (Kernel/...). Every row also reports
// the peak memory of one update of a fresh filter per point (bench/README.md).
#include "BenchSupport.h"

#include "vtkPointPairDeformationFilter.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <map>
#include <utility>

namespace
{
using namespace boostedbench;

vtkSmartPointer<vtkPointPairDeformationFilter> makeFilter(
  vtkStructuredGrid* mesh, int generators, int rule)
{
  auto filter = vtkSmartPointer<vtkPointPairDeformationFilter>::New();
  filter->SetInputData(mesh);
  for (const cga::PointPairGenerator& g : benchmarkGenerators(generators))
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
  filter->SetFalloff(kFalloff);
  filter->SetEpsilon(kEpsilon);
  filter->SetStrength(kStrength);
  filter->SetExponentialRule(rule);
  return filter;
}

struct MemoryPerPoint
{
  double peak = 0.0;   // growth of the peak resident set during the update
  double output = 0.0; // the output's points and "Displacement" arrays (GetActualMemorySize)
};

// One Update of a fresh filter on `mesh` with `threads` threads; measured once per size and
// thread count (the rule and M do not change what is allocated).
MemoryPerPoint measureMemory(vtkStructuredGrid* mesh, int generators, int rule, int threads)
{
  static std::map<std::pair<vtkIdType, int>, MemoryPerPoint> measured;
  const vtkIdType count = mesh->GetNumberOfPoints();
  const auto key = std::make_pair(count, threads);
  auto found = measured.find(key);
  if (found != measured.end())
  {
    return found->second;
  }
  MemoryPerPoint memory;
  vtkSmartPointer<vtkPointPairDeformationFilter> filter = makeFilter(mesh, generators, rule);
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false },
    [&]() { memory.peak = peakMemoryGrowth([&]() { filter->Update(); }) / count; });
  vtkPointSet* output = filter->GetOutput();
  const double kibibytes = output->GetPoints()->GetData()->GetActualMemorySize() +
    output->GetPointData()->GetArray("Displacement")->GetActualMemorySize();
  memory.output = 1024.0 * kibibytes / count;
  measured[key] = memory;
  return memory;
}

void timeFilter(benchmark::State& state, int rule, int generators, int threads,
  vtkStructuredGrid* mesh)
{
  const MemoryPerPoint memory = measureMemory(mesh, generators, rule, threads);
  vtkSmartPointer<vtkPointPairDeformationFilter> filter = makeFilter(mesh, generators, rule);
  const long long count = mesh->GetNumberOfPoints();
  if (updateEachIteration(state, filter, threads) != count)
  {
    state.SkipWithError("the filter produced the wrong number of points");
  }
  state.SetLabel(cga::mapPointsInstructionSet());
  state.counters["peak B/point"] = memory.peak;
  state.counters["output B/point"] = memory.output;
  reportPoints(state, static_cast<std::size_t>(count));
}

void Filter(benchmark::State& state, int rule)
{
  timeFilter(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
    benchmarkMesh());
}

void FilterSize(benchmark::State& state, int rule)
{
  timeFilter(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(2)),
    sheetMesh(static_cast<std::size_t>(state.range(1))));
}

BENCHMARK_CAPTURE(Filter, Paper, vtkPointPairDeformationFilter::PAPER)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(Filter, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(FilterSize, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perPointCount);
} // namespace
