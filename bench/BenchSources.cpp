// Every source of this project at 1,000,000 output points beside VTK's torus
// (vtkParametricFunctionSource with vtkParametricTorus) of the same size, vtkSMPTools on the
// STDThread backend: Source/<name>/threads:<n>. The targets: each source at least as fast
// as the torus on one thread, and at least 1.8 times its own one-thread rate on two. Beside the
// rows with curvatures, the torus with VTK's discrete ones (TorusCurvatures): context, not a target.
#include "BenchSupport.h"

#include "vtkBoostedSurfaceSource.h"
#include "vtkConformalOrbitSource.h"
#include "vtkCurvaturePatchSource.h"
#include "vtkDipoleFieldSource.h"
#include "vtkHopfFibrationSource.h"

#include <vtkCurvatures.h>
#include <vtkNew.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>

#include <ctime>

namespace
{
using namespace boostedbench;

double cpuSeconds(clockid_t clock)
{
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Updates `source` each iteration on `threads` threads and reports its output points per second;
// an error when the output does not have kMeshPoints points (the sizes below are chosen for it).
// Counter `serial`: the calling thread's share of the process's CPU time over the timed updates.
// vtkSMPTools' STDThread backend runs every parallel loop on its pool's threads while the
// calling thread waits, so this is the update's serial share, measured in CPU time (which the
// other jobs of a shared machine do not inflate as they do wall clock): by Amdahl's law two
// threads give at most 1 / (serial + (1 - serial) / 2) times one.
// For a pipeline, `source` is its last stage and `first` its source (updateEachIteration).
void timeSource(benchmark::State& state, vtkAlgorithm* source, long threads, vtkAlgorithm* first = nullptr)
{
  const double threadBefore = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
  const double processBefore = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
  const long long points = updateEachIteration(state, source, static_cast<int>(threads), first);
  state.counters["serial"] = (cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - threadBefore) /
    (cpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - processBefore);
  if (points != static_cast<long long>(kMeshPoints))
  {
    state.SkipWithError(("the source made " + std::to_string(points) + " points").c_str());
  }
  reportPoints(state, kMeshPoints);
}

// The torus of 1000 x 1000 points: the source samples UResolution x VResolution (the seams
// repeated).
void setTorus(vtkParametricFunctionSource* source, vtkParametricTorus* torus)
{
  source->SetParametricFunction(torus);
  source->SetUResolution(kMeshSide);
  source->SetVResolution(kMeshSide);
}

void Torus(benchmark::State& state)
{
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkParametricFunctionSource> source;
  setTorus(source, torus);
  timeSource(state, source, state.range(0));
}

void TorusCurvatures(benchmark::State& state)
{
  // The torus, then vtkCurvatures for the Gaussian and then the mean curvature (one type per
  // pass): VTK's discrete curvatures at the mesh's points, where the rows with curvatures compute
  // both exactly, with the principal curvatures and directions.
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkParametricFunctionSource> source;
  setTorus(source, torus);
  vtkNew<vtkCurvatures> gaussian;
  gaussian->SetInputConnection(source->GetOutputPort());
  gaussian->SetCurvatureTypeToGaussian();
  vtkNew<vtkCurvatures> mean;
  mean->SetInputConnection(gaussian->GetOutputPort());
  mean->SetCurvatureTypeToMean();
  timeSource(state, mean, state.range(0), source);
}

void BoostedSurface(benchmark::State& state, bool computeCurvatures)
{
  // Fig 2's family, 1000 lambda rows of 1000 theta samples (the seam repeated).
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetCircleNormal(0.0, 0.0, 1.0);
  source->SetBoostDirection(1.0, 0.0, 0.0);
  source->SetLambdaResolution(kMeshSide - 1);
  source->SetThetaResolution(kMeshSide - 1);
  source->SetClipRadius(1e6);
  source->SetComputeCurvatures(computeCurvatures);
  timeSource(state, source, state.range(0));
}

void HopfFibration(benchmark::State& state)
{
  // The twistor mesh of 40 meridian strips of 25 fibers, 1000 points each; the latitudes stop
  // short of the pole, whose fiber (the axis line) has a point at infinity.
  vtkNew<vtkHopfFibrationSource> source;
  source->SetOutputTypeToTwistorMesh();
  source->SetThetaResolution(40);
  source->SetPhiResolution(25);
  source->SetPhiRange(-1.5, 1.5);
  source->SetFiberResolution(kMeshSide - 1);
  source->SetClipRadius(1e6);
  timeSource(state, source, state.range(0));
}

void CurvaturePatch(benchmark::State& state, int method, bool computeCurvatures)
{
  // A 1000 x 1000 patch: the default curvatures (0.5, 0.5), the default corners for Bilinear,
  // four control points (Fig 10's kind) for ControlPoints; Curvatures: Translated Tangents with
  // ComputeCurvatures on.
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetMethod(method);
  source->AddControlPoint(-1, -1, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5);
  source->AddControlPoint(1, -1, 0, 0, 0, 1, 1, 0, 0, -0.5, 0.5);
  source->AddControlPoint(-1, 1, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5);
  source->AddControlPoint(1, 1, 0, 0, 0, 1, 1, 0, 0, 0.25, 0.25);
  source->SetUResolution(kMeshSide - 1);
  source->SetVResolution(kMeshSide - 1);
  source->SetClipRadius(1e6);
  source->SetComputeCurvatures(computeCurvatures);
  timeSource(state, source, state.range(0));
}

// The (2, 3) torus knot: `seeds` seeds, each orbit one closed period of 10^6 / seeds samples.
// exp(t B) and its point map are made once per sample time and shared by the seeds, so few
// seeds pay them for few points.
void orbitOfSeeds(benchmark::State& state, int seeds)
{
  vtkNew<vtkConformalOrbitSource> source;
  source->SetSeedMode(vtkConformalOrbitSource::SEED_LIST);
  for (int i = 0; i < seeds; ++i)
  {
    source->AddSeed(0.1 + 0.002 * i, 0.01 * (i % 10), 0.0);
  }
  source->SetTResolution(static_cast<int>(kMeshPoints / seeds)); // the last sample closes the orbit
  source->SetClipRadius(1e6);
  timeSource(state, source, state.range(0));
}

void ConformalOrbit(benchmark::State& state)
{
  orbitOfSeeds(state, 100);
}

void DipoleField(benchmark::State& state)
{
  // A 100 x 100 x 100 grid over [-2, 2]^2 x [-0.3, 0.3], the kernel benchmark's first M
  // generators: M + 1 fields mapped per point (the summed one and each generator's own).
  vtkNew<vtkDipoleFieldSource> source;
  source->SetDimensions(100, 100, 100);
  source->SetOrigin(-2.0, -2.0, -0.3);
  source->SetSpacing(4.0 / 99, 4.0 / 99, 0.6 / 99);
  for (const cga::PointPairGenerator& g : benchmarkGenerators(static_cast<int>(state.range(0))))
  {
    source->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
  source->SetFalloff(kFalloff);
  source->SetEpsilon(kEpsilon);
  timeSource(state, source, state.range(1));
}

void perThreads(benchmark::internal::Benchmark* benchmark)
{
  benchmark->ArgsProduct({ { 1, 2 } })->ArgNames({ "threads" });
  timedPerPoint(benchmark);
}

BENCHMARK(Torus)->Apply(perThreads);
BENCHMARK(TorusCurvatures)->Apply(perThreads);
BENCHMARK_CAPTURE(BoostedSurface, Surface, false)->Apply(perThreads);
BENCHMARK_CAPTURE(BoostedSurface, Curvatures, true)->Apply(perThreads);
BENCHMARK(HopfFibration)->Apply(perThreads);
BENCHMARK_CAPTURE(
  CurvaturePatch, TranslatedTangents, vtkCurvaturePatchSource::TRANSLATED_TANGENTS, false)
  ->Apply(perThreads);
BENCHMARK_CAPTURE(CurvaturePatch, ControlPoints, vtkCurvaturePatchSource::CONTROL_POINTS, false)
  ->Apply(perThreads);
BENCHMARK_CAPTURE(CurvaturePatch, Bilinear, vtkCurvaturePatchSource::BILINEAR, false)
  ->Apply(perThreads);
BENCHMARK_CAPTURE(CurvaturePatch, Curvatures, vtkCurvaturePatchSource::TRANSLATED_TANGENTS, true)
  ->Apply(perThreads);
BENCHMARK(ConformalOrbit)->Apply(perThreads);
BENCHMARK_CAPTURE(orbitOfSeeds, OneSeed, 1)->Name("ConformalOrbit/OneSeed")->Apply(perThreads);
BENCHMARK(DipoleField)->ArgsProduct({ { 1, 4 }, { 1, 2 } })->ArgNames({ "M", "threads" })->Apply(timedPerPoint);
} // namespace
