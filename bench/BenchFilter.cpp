// vtkPointPairDeformationFilter with the kernel benchmark's field, vtkSMPTools on the STDThread
// backend: on the shared 1,000,000-point mesh, Filter/<rule>/M:<generators>/threads:<n>, and on
// the same sheet at N = 10^4 ... 10^7 points, M = 16, one and two threads,
// FilterSize/Exact/M:16/N:<points>/threads:<n>.
// The target: within 1.3 times the bare kernel's time (Kernel/...). Every row also reports
// the peak memory of one update of a fresh filter per point (bench/README.md).
// Through the derivative (mapPointsWithJacobians): FilterNormals/<rule>/M/threads, the same mesh
// with float unit Normals transformed (TransformNormals, the default; the target: within
// 1.3 times Filter/...), and FilterDerivatives/<rule>/M:16/threads:1 with every output from J
// (the normals, a vector array, ConformalScale, ConformalityDefect).
#include "BenchSupport.h"

#include "vtkPointPairDeformationFilter.h"

#include <vtkDataArray.h>
#include <vtkDataArraySelection.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <array>
#include <map>
#include <string>
#include <tuple>

namespace
{
using namespace boostedbench;

// What a row asks of the derivative.
enum class Derivatives
{
  None,    // the mesh without normals: mapPoints
  Normals, // the mesh with Normals, TransformNormals on
  All      // and "Velocity" as a vector, ConformalScale, ConformalityDefect
};

// The shared mesh with float point arrays "Normals" (active, the sheet's up direction, unit) and
// "Velocity" (the same values): built once.
vtkStructuredGrid* meshWithNormals()
{
  static vtkSmartPointer<vtkStructuredGrid> mesh;
  if (!mesh)
  {
    mesh = vtkSmartPointer<vtkStructuredGrid>::New();
    mesh->ShallowCopy(benchmarkMesh());
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      normals->SetTypedTuple(i, std::array<float, 3>{ 0.0f, 0.6f, 0.8f }.data());
    }
    vtkNew<vtkFloatArray> velocity;
    velocity->DeepCopy(normals);
    velocity->SetName("Velocity");
    mesh->GetPointData()->SetNormals(normals);
    mesh->GetPointData()->AddArray(velocity);
  }
  return mesh;
}

vtkSmartPointer<vtkPointPairDeformationFilter> makeFilter(
  vtkStructuredGrid* mesh, int generators, int rule, Derivatives derivatives = Derivatives::None)
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
  if (derivatives == Derivatives::All)
  {
    filter->GetVectorArraySelection()->EnableArray("Velocity");
    filter->ComputeConformalScaleOn();
    filter->ComputeConformalityDefectOn();
  }
  return filter;
}

struct MemoryPerPoint
{
  double peak = 0.0;   // growth of the peak resident set during the update
  double output = 0.0; // the output's points and "Displacement" arrays (GetActualMemorySize)
};

// One Update of a fresh filter on `mesh` with `threads` threads; measured once per size and
// thread count (the rule and M do not change what is allocated).
MemoryPerPoint measureMemory(vtkStructuredGrid* mesh, int generators, int rule, int threads,
  Derivatives derivatives)
{
  static std::map<std::tuple<vtkIdType, int, Derivatives>, MemoryPerPoint> measured;
  const vtkIdType count = mesh->GetNumberOfPoints();
  const auto key = std::make_tuple(count, threads, derivatives);
  auto found = measured.find(key);
  if (found != measured.end())
  {
    return found->second;
  }
  MemoryPerPoint memory;
  vtkSmartPointer<vtkPointPairDeformationFilter> filter =
    makeFilter(mesh, generators, rule, derivatives);
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false },
    [&]() { memory.peak = peakMemoryGrowth([&]() { filter->Update(); }) / count; });
  vtkPointSet* output = filter->GetOutput();
  double kibibytes = output->GetPoints()->GetData()->GetActualMemorySize();
  for (const char* name :
    { "Displacement", "Normals", "Velocity", "ConformalScale", "ConformalityDefect" })
  {
    vtkDataArray* array = output->GetPointData()->GetArray(name);
    // (without derivatives the output's Velocity is the input's, not allocated by the update)
    if (array && (derivatives == Derivatives::All || std::string(name) != "Velocity"))
    {
      kibibytes += array->GetActualMemorySize();
    }
  }
  memory.output = 1024.0 * kibibytes / count;
  measured[key] = memory;
  return memory;
}

void timeFilter(benchmark::State& state, int rule, int generators, int threads,
  vtkStructuredGrid* mesh, Derivatives derivatives = Derivatives::None)
{
  const MemoryPerPoint memory = measureMemory(mesh, generators, rule, threads, derivatives);
  vtkSmartPointer<vtkPointPairDeformationFilter> filter =
    makeFilter(mesh, generators, rule, derivatives);
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

void FilterNormals(benchmark::State& state, int rule)
{
  timeFilter(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
    meshWithNormals(), Derivatives::Normals);
}

void FilterDerivatives(benchmark::State& state, int rule)
{
  timeFilter(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
    meshWithNormals(), Derivatives::All);
}

void FilterSize(benchmark::State& state, int rule)
{
  timeFilter(state, rule, static_cast<int>(state.range(0)), static_cast<int>(state.range(2)),
    sheetMesh(static_cast<std::size_t>(state.range(1))));
}

void atSixteenGeneratorsOneThread(benchmark::internal::Benchmark* benchmark)
{
  benchmark->Args({ 16, 1 })->ArgNames({ "M", "threads" });
  timedPerPoint(benchmark);
}

BENCHMARK_CAPTURE(Filter, Paper, vtkPointPairDeformationFilter::PAPER)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(Filter, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(FilterNormals, Paper, vtkPointPairDeformationFilter::PAPER)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(FilterNormals, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perGeneratorsAndThreads);
BENCHMARK_CAPTURE(FilterDerivatives, Paper, vtkPointPairDeformationFilter::PAPER)
  ->Apply(atSixteenGeneratorsOneThread);
BENCHMARK_CAPTURE(FilterDerivatives, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(atSixteenGeneratorsOneThread);
BENCHMARK_CAPTURE(FilterSize, Exact, vtkPointPairDeformationFilter::EXACT)
  ->Apply(perPointCount);
} // namespace
