#include "BenchSupport.h"

#include <vtkAlgorithm.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <thread>

namespace boostedbench
{
namespace
{
vtkSmartPointer<vtkStructuredGrid> makeMesh()
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(kMeshPoints));
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(static_cast<vtkIdType>(kMeshPoints));
  for (int j = 0; j < kMeshSide; ++j)
  {
    for (int i = 0; i < kMeshSide; ++i)
    {
      const double x = -2.0 + 4.0 * i / (kMeshSide - 1);
      const double y = -2.0 + 4.0 * j / (kMeshSide - 1);
      const double z = 0.3 * std::sin(2.0 * x) * std::cos(3.0 * y);
      const vtkIdType id = static_cast<vtkIdType>(j) * kMeshSide + i;
      coordinates->SetTypedTuple(id, std::array<double, 3>{ x, y, z }.data());
      displacement->SetTypedTuple(id, std::array<double, 3>{ 0.1 * y, -0.1 * x, 0.05 }.data());
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(kMeshSide, kMeshSide, 1);
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(displacement);
  return grid;
}
} // namespace

vtkStructuredGrid* benchmarkMesh()
{
  static const vtkSmartPointer<vtkStructuredGrid> mesh = makeMesh();
  return mesh;
}

const double* benchmarkPoints()
{
  auto* coordinates = vtkDoubleArray::SafeDownCast(benchmarkMesh()->GetPoints()->GetData());
  return coordinates->GetPointer(0);
}

std::vector<cga::PointPairGenerator> benchmarkGenerators(int count)
{
  std::mt19937_64 engine(20140601);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0), unit(-1.0, 1.0), weight(0.1, 0.4);
  std::vector<cga::PointPairGenerator> generators;
  for (int i = 0; i < count; ++i)
  {
    const cga::Vec3 location{ coordinate(engine), coordinate(engine), 0.3 * unit(engine) };
    const cga::Vec3 direction{ unit(engine), unit(engine), unit(engine) };
    generators.push_back({ location, direction, weight(engine) });
  }
  return generators;
}

void reportPoints(benchmark::State& state, std::size_t pointsPerIteration)
{
  const double points = static_cast<double>(pointsPerIteration) * state.iterations();
  state.counters["points/s"] = benchmark::Counter(points, benchmark::Counter::kIsRate);
  state.SetItemsProcessed(static_cast<int64_t>(points));
}

void timedPerPoint(benchmark::internal::Benchmark* benchmark)
{
  benchmark->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();
}

void perGeneratorsAndThreads(benchmark::internal::Benchmark* benchmark)
{
  benchmark->ArgsProduct({ generatorCounts(), { 1, 2 } })->ArgNames({ "M", "threads" });
  timedPerPoint(benchmark);
}

long long updateEachIteration(benchmark::State& state, vtkAlgorithm* algorithm, int threads)
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    for (auto _ : state)
    {
      algorithm->Modified();
      algorithm->Update();
    }
  });
  auto* output = vtkDataSet::SafeDownCast(algorithm->GetOutputDataObject(0));
  return output ? static_cast<long long>(output->GetNumberOfPoints()) : -1;
}

void runOnThreads(int threads,
                  std::size_t count,
                  const std::function<void(std::size_t, std::size_t)>& work)
{
  // Chunks handed out one by one, as vtkSMPTools does: the cost per point varies over the mesh
  // (near a generator the exponential takes its transcendental branch), so fixed halves would
  // leave one thread idle.
  constexpr std::size_t chunk = 8192;
  std::atomic<std::size_t> next{ 0 };
  auto worker = [&]() {
    for (std::size_t first = next.fetch_add(chunk); first < count; first = next.fetch_add(chunk))
    {
      work(first, std::min(count, first + chunk));
    }
  };
  std::vector<std::thread> others;
  for (int t = 1; t < threads; ++t)
  {
    others.emplace_back(worker);
  }
  worker();
  for (std::thread& thread : others)
  {
    thread.join();
  }
}
} // namespace boostedbench
