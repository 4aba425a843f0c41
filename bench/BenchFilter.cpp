// vtkPointPairDeformationFilter on the shared 1,000,000-point mesh, with the kernel benchmark's
// field, vtkSMPTools on the STDThread backend: Filter/<rule>/M:<generators>/threads:<n>. The
// issue's target: within 1.3 times the bare kernel's time (Kernel/<rule>/M:<generators>/threads:<n>).
#include "BenchSupport.h"

#include "vtkPointPairDeformationFilter.h"

#include <vtkNew.h>

namespace
{
using namespace boostedbench;

void Filter(benchmark::State& state, int rule)
{
  const int threads = static_cast<int>(state.range(1));
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(benchmarkMesh());
  for (const cga::PointPairGenerator& g : benchmarkGenerators(static_cast<int>(state.range(0))))
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
  filter->SetFalloff(kFalloff);
  filter->SetEpsilon(kEpsilon);
  filter->SetStrength(kStrength);
  filter->SetExponentialRule(rule);
  if (updateEachIteration(state, filter, threads) != static_cast<long long>(kMeshPoints))
  {
    state.SkipWithError("the filter produced the wrong number of points");
  }
  state.SetLabel(cga::mapPointsInstructionSet());
  reportPoints(state, kMeshPoints);
}

BENCHMARK_CAPTURE(Filter, Paper, vtkPointPairDeformationFilter::PAPER)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(Filter, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perGeneratorsAndThreads);
} // namespace
