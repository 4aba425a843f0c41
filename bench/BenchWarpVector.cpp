// vtkWarpVector on the same 1,000,000-point mesh, with vtkSMPTools on the STDThread backend
// (Debian's VTK defaults to Sequential): WarpVector/threads:<n>. The pattern for a VTK filter.
#include "BenchSupport.h"

#include <vtkNew.h>
#include <vtkWarpVector.h>

namespace
{
using namespace boostedbench;

void WarpVector(benchmark::State& state)
{
  const int threads = static_cast<int>(state.range(0));
  vtkNew<vtkWarpVector> warp;
  warp->SetInputData(benchmarkMesh());
  warp->SetScaleFactor(1.0);
  if (updateEachIteration(state, warp, threads) != static_cast<long long>(kMeshPoints))
  {
    state.SkipWithError("vtkWarpVector produced the wrong number of points");
  }
  reportPoints(state, kMeshPoints);
}

BENCHMARK(WarpVector)
  ->ArgsProduct({ { 1, 2 } })
  ->ArgNames({ "threads" })
  ->Apply(timedPerPoint);
} // namespace
