// The fit filter's costs (vtkPointPairFitFilter) on 10^4 points of the shared sheet, one thread,
// Exact, the kernel benchmark's first M generators:
// GeneratorJacobian/M:<generators>/fit:<unknowns per generator> times the fit's Jacobian rows,
// cga::mapWithGeneratorDerivatives (the image and d image / d theta per point: 1 = the weights,
// 7 = weights, locations and directions, 8 = those and the pitches of generators made twists of
// pitch 0.1); FitIteration/<PointToPoint|PointToSurface>/M/fit times
// one solver iteration of the filter (an update of 1 iteration minus one of 0 iterations: the
// Jacobian evaluation, Ceres's step and the trial point's residuals). Both report the time per
// point and per unknown (counter "time/point/unknown"); FitIteration's time is the process's CPU
// time of the difference.
#include "BenchSupport.h"

#include "vtkPointPairDeformationFilter.h"
#include "vtkPointPairFitFilter.h"

#include "cga/GeneratorDerivatives.h"

#include <vtkNew.h>
#include <vtkSMPTools.h>

#include <ctime>
#include <initializer_list>
#include <vector>

namespace
{
using namespace boostedbench;
constexpr std::size_t kFitPoints = 10000;

// The kernel benchmark's point pairs; with the pitches fitted (8 unknowns each), twists of pitch
// 0.1 along the same directions.
std::vector<cga::GeneratorParameters> fitGenerators(int count, int perGenerator)
{
  std::vector<cga::GeneratorParameters> generators;
  for (const cga::PointPairGenerator& g : benchmarkGenerators(count))
  {
    cga::GeneratorParameters row;
    row.location = g.location;
    row.direction = g.direction;
    row.weight = g.weight;
    if (perGenerator == cga::kGeneratorParameters)
    {
      row.kind = cga::GeneratorKind::Twist;
      row.pitch = 0.1;
    }
    generators.push_back(row);
  }
  return generators;
}

cga::FittedParameters fitted(int perGenerator)
{
  return perGenerator == 1 ? cga::FittedParameters{ true, false, false, false }
                           : cga::FittedParameters{ true, true, true, perGenerator == 8 };
}

void GeneratorJacobian(benchmark::State& state)
{
  const int generators = static_cast<int>(state.range(0));
  const cga::FittedParameters fit = fitted(static_cast<int>(state.range(1)));
  const std::vector<cga::GeneratorParameters> rows =
    fitGenerators(generators, static_cast<int>(state.range(1)));
  const cga::PointPairField field(rows.data(), rows.size(), kFalloff, kEpsilon);
  const double* points = meshPoints(sheetMesh(kFitPoints));
  const int unknowns = generators * fit.perGenerator();
  std::vector<double> derivatives(3 * static_cast<std::size_t>(unknowns));
  for (auto _ : state)
  {
    for (std::size_t i = 0; i < kFitPoints; ++i)
    {
      cga::Vec3 out;
      const double* p = points + 3 * i;
      if (!cga::mapWithGeneratorDerivatives(field, rows.data(), rows.size(), fit,
            { p[0], p[1], p[2] }, kStrength, cga::ExponentialRule::Exact, out, derivatives.data()))
      {
        state.SkipWithError("a point was not mapped");
        return;
      }
      benchmark::DoNotOptimize(derivatives.data());
    }
  }
  reportPoints(state, kFitPoints);
  state.counters["time/point/unknown"] = benchmark::Counter(
    static_cast<double>(kFitPoints) * unknowns,
    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void FitIteration(benchmark::State& state, int mode)
{
  const int generators = static_cast<int>(state.range(0));
  const int perGenerator = static_cast<int>(state.range(1));
  vtkStructuredGrid* mesh = sheetMesh(kFitPoints);
  vtkNew<vtkPointPairDeformationFilter> target;
  target->SetInputData(mesh);
  vtkNew<vtkPointPairFitFilter> fit;
  fit->SetInputData(mesh);
  fit->SetTargetConnection(target->GetOutputPort());
  for (const cga::GeneratorParameters& g : fitGenerators(generators, perGenerator))
  {
    const double kind = static_cast<double>(g.kind);
    target->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x,
      g.direction.y, g.direction.z, g.weight, kind, g.pitch);
    fit->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, 0.5 * g.weight, kind, 0.5 * g.pitch); // a start the first iteration improves
  }
  target->SetFalloff(kFalloff);
  target->SetEpsilon(kEpsilon);
  target->SetStrength(kStrength);
  fit->SetFalloff(kFalloff);
  fit->SetEpsilon(kEpsilon);
  fit->SetStrength(kStrength);
  fit->SetTargetMode(mode);
  fit->SetFitLocations(perGenerator >= 7);
  fit->SetFitDirections(perGenerator >= 7);
  fit->SetFitPitches(perGenerator == 8);
  target->Update();
  const auto seconds = [&](int iterations) {
    fit->SetMaximumNumberOfIterations(iterations);
    fit->Modified();
    // The process's CPU time (one thread here): steadier than the wall clock on a shared machine.
    const std::clock_t start = std::clock();
    fit->Update();
    return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  };
  bool oneIteration = true;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 1, "Sequential", false }, [&]() {
    for (auto _ : state)
    {
      const double one = seconds(1);
      oneIteration = oneIteration && fit->GetNumberOfIterations() == 1 && fit->GetImproved();
      const double iteration = one - seconds(0);
      state.SetIterationTime(iteration > 0.0 ? iteration : 0.0);
    }
  });
  if (!oneIteration)
  {
    state.SkipWithError("the fit did not run one improving iteration");
    return;
  }
  const int unknowns = generators * perGenerator;
  reportPoints(state, kFitPoints);
  state.counters["time/point/unknown"] = benchmark::Counter(
    static_cast<double>(kFitPoints) * unknowns,
    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void fitArguments(benchmark::internal::Benchmark* benchmark, std::initializer_list<long> counts,
  std::initializer_list<long> unknownsPerGenerator = { 1, 7 })
{
  benchmark->ArgNames({ "M", "fit" });
  for (long generators : counts)
  {
    for (long perGenerator : unknownsPerGenerator)
    {
      benchmark->Args({ generators, perGenerator });
    }
  }
  benchmark->Unit(benchmark::kMillisecond);
}
} // namespace

BENCHMARK(GeneratorJacobian)
  ->Apply([](benchmark::internal::Benchmark* b) { fitArguments(b, { 4, 16, 64 }, { 1, 7, 8 }); });
BENCHMARK_CAPTURE(FitIteration, PointToPoint, vtkPointPairFitFilter::POINT_TO_POINT)
  ->Apply([](benchmark::internal::Benchmark* b) { fitArguments(b, { 4, 16, 64 }, { 1, 7, 8 }); })
  ->UseManualTime();
// The target's cell locator dominates here (README, Performance): fewer rows, fewer repetitions.
BENCHMARK_CAPTURE(FitIteration, PointToSurface, vtkPointPairFitFilter::POINT_TO_SURFACE)
  ->Apply([](benchmark::internal::Benchmark* b) { fitArguments(b, { 4, 16 }); })
  ->Iterations(3)
  ->UseManualTime();
