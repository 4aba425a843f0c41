#include "BenchSupport.h"

#ifdef BOOSTEDBENCH_LARGE_ARRAYS
#include "vtkBoostedLargeArrays.h"
#endif

#include <vtkAlgorithm.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <thread>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace boostedbench
{
namespace
{
// kMeshSide columns by `rows` rows over the square [-2, 2]^2.
vtkSmartPointer<vtkStructuredGrid> makeMesh(int rows)
{
  const auto count = static_cast<vtkIdType>(kMeshSide) * rows;
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(count);
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < kMeshSide; ++i)
    {
      const double x = -2.0 + 4.0 * i / (kMeshSide - 1);
      const double y = -2.0 + 4.0 * j / (rows - 1);
      const double z = 0.3 * std::sin(2.0 * x) * std::cos(3.0 * y);
      const vtkIdType id = static_cast<vtkIdType>(j) * kMeshSide + i;
      coordinates->SetTypedTuple(id, std::array<double, 3>{ x, y, z }.data());
      displacement->SetTypedTuple(id, std::array<double, 3>{ 0.1 * y, -0.1 * x, 0.05 }.data());
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(kMeshSide, rows, 1);
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(displacement);
  return grid;
}

// A number in kB from /proc/self/status ("VmRSS:", "VmHWM:"), or -1.
long long statusKilobytes(const char* field)
{
  std::ifstream status("/proc/self/status");
  const std::size_t length = std::strlen(field);
  for (std::string line; std::getline(status, line);)
  {
    if (line.compare(0, length, field) == 0)
    {
      return std::stoll(line.substr(length));
    }
  }
  return -1;
}
} // namespace

vtkStructuredGrid* benchmarkMesh()
{
  static const vtkSmartPointer<vtkStructuredGrid> mesh = makeMesh(kMeshSide);
  return mesh;
}

vtkStructuredGrid* sheetMesh(std::size_t points)
{
  if (points == kMeshPoints)
  {
    return benchmarkMesh();
  }
  // One other size at a time: the 10^7-point sheet alone holds 480 MB.
  static vtkSmartPointer<vtkStructuredGrid> mesh;
  if (!mesh || static_cast<std::size_t>(mesh->GetNumberOfPoints()) != points)
  {
    mesh = nullptr;
    mesh = makeMesh(static_cast<int>(points / kMeshSide));
  }
  return mesh;
}

const double* meshPoints(vtkStructuredGrid* mesh)
{
  return vtkDoubleArray::SafeDownCast(mesh->GetPoints()->GetData())->GetPointer(0);
}

const double* benchmarkPoints()
{
  return meshPoints(benchmarkMesh());
}

double peakMemoryGrowth(const std::function<void()>& work)
{
#ifdef __GLIBC__
  // Under BOOSTEDBENCH_MEMORY=reuse freed arrays stay mapped in the heap; work() would reuse their
  // pages without growing the resident set.
  malloc_trim(0);
#endif
#ifdef BOOSTEDBENCH_LARGE_ARRAYS
  vtkBoostedLargeArrays::ReleaseCached(); // the same for the large arrays' kept mappings
#endif
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5" << std::flush; // resets VmHWM to VmRSS (Linux 4.0)
    if (!clear)
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
  }
  const long long before = statusKilobytes("VmRSS:");
  work();
  const long long peak = statusKilobytes("VmHWM:");
  if (before < 0 || peak < 0)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return 1024.0 * static_cast<double>(peak - before);
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

void perPointCount(benchmark::internal::Benchmark* benchmark)
{
  benchmark->ArgsProduct({ { 16 }, pointCounts(), { 1, 2 } })->ArgNames({ "M", "N", "threads" });
  timedPerPoint(benchmark);
}

long long updateEachIteration(
  benchmark::State& state, vtkAlgorithm* algorithm, int threads, vtkAlgorithm* first)
{
  vtkAlgorithm* const modified = first ? first : algorithm;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    // One update before the timed ones: a new algorithm's first update may also pay for memory
    // the process touches for the first time (the kernel zeroing fresh pages), and a row whose
    // first update outlasts the minimum time would time that update alone. Reported apart.
    const auto start = std::chrono::steady_clock::now();
    algorithm->Update();
    state.counters["first update ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (auto _ : state)
    {
      modified->Modified();
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
  // As vtkBoostedBlockLoop: one share of the points per thread (whole blocks of the kernel's 8
  // lanes), thread t taking share t's chunks first (the calling thread share 0), then what is
  // left of the others, so that each core mostly rewrites the output it wrote the iteration
  // before. Chunks are handed out one by one, as vtkSMPTools does: the cost per point varies over
  // the mesh (near a generator the exponential takes its transcendental branch), so fixed halves
  // would leave one thread idle. Guided: a quarter of what is left of the share, at most 8192
  // points and at least 1024, so that at the end a thread waits for the other for about one
  // small chunk.
  const std::size_t shares = static_cast<std::size_t>(std::max(1, threads));
  const std::size_t blocks = (count + 7) / 8;
  struct alignas(64) Share
  {
    std::size_t begin = 0, end = 0;
    std::atomic<std::size_t> next{ 0 };
  };
  std::vector<Share> share(shares);
  for (std::size_t s = 0; s < shares; ++s)
  {
    share[s].begin = std::min(count, 8 * (blocks * s / shares));
    share[s].end = std::min(count, 8 * (blocks * (s + 1) / shares));
    share[s].next = share[s].begin;
  }
  auto take = [&](Share& from, std::size_t& first, std::size_t& last) {
    std::size_t begin = from.next.load();
    std::size_t size = 0;
    do
    {
      if (begin >= from.end)
      {
        return false;
      }
      const std::size_t left = from.end - begin;
      size = std::max<std::size_t>(1024, std::min<std::size_t>(8192, left / 4)) / 8 * 8;
      size = std::min(left, size);
    } while (!from.next.compare_exchange_weak(begin, begin + size));
    first = begin;
    last = begin + size;
    return true;
  };
  auto worker = [&](std::size_t own) {
    std::size_t first = 0, last = 0;
    for (std::size_t k = 0; k < shares; ++k)
    {
      Share& from = share[(own + k) % shares];
      while (take(from, first, last))
      {
        work(first, last);
      }
    }
  };
  std::vector<std::thread> others;
  for (std::size_t t = 1; t < shares; ++t)
  {
    others.emplace_back(worker, t);
  }
  worker(0);
  for (std::thread& thread : others)
  {
    thread.join();
  }
}
} // namespace boostedbench
