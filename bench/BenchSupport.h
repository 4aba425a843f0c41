// Shared by the benchmarks of BoostedBench: the one 1,000,000-point mesh every benchmark deforms
// (and the same sheet at other point counts), the generator fields, the points-per-second counter,
// the peak memory of one piece of work, and running work on N threads.
//
// A new benchmark (e.g. the VTK deformation filter) is one function in its own file that takes
// benchmarkMesh(), loops over the state, and calls reportPoints(); see BenchWarpVector.cpp.
#pragma once

#include "cga/PointPairField.h"

#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>

class vtkAlgorithm;

#include <benchmark/benchmark.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace boostedbench
{
/// Points of the shared mesh: a 1000 x 1000 wavy sheet.
constexpr int kMeshSide = 1000;
constexpr std::size_t kMeshPoints = static_cast<std::size_t>(kMeshSide) * kMeshSide;

/// Generator counts M of the figures.
inline const std::vector<long>& generatorCounts()
{
  static const std::vector<long> counts = { 1, 4, 16, 64 };
  return counts;
}

/// Point counts N of the size rows (KernelSize, FilterSize): 10^4 to 10^7.
inline const std::vector<long>& pointCounts()
{
  static const std::vector<long> counts = { 10000, 100000, 1000000, 10000000 };
  return counts;
}

/// The 1,000,000-point mesh (double points), with a point vector array "displacement" for
/// vtkWarpVector. Built once.
vtkStructuredGrid* benchmarkMesh();

/// The same sheet (the same square, kMeshSide columns) with `points` / kMeshSide rows, `points` a
/// multiple of kMeshSide of at least 2 rows: benchmarkMesh() for kMeshPoints, otherwise built on
/// the first call for that size and kept until a call for another size.
vtkStructuredGrid* sheetMesh(std::size_t points);

/// The mesh points as xyz doubles (the mesh's own array).
const double* benchmarkPoints();
const double* meshPoints(vtkStructuredGrid* mesh);

/// M generators spread over the mesh's bounds, fixed seed.
std::vector<cga::PointPairGenerator> benchmarkGenerators(int count);

/// The field of M generators the kernel, reference and filter benchmarks share.
constexpr double kFalloff = 1.0;
constexpr double kEpsilon = 0.05;
constexpr double kStrength = 0.5;

/// Reports points per second ("points/s") and items per second, over real (wall) time.
void reportPoints(benchmark::State& state, std::size_t pointsPerIteration);

/// The growth of the process's peak resident set while work() runs, in bytes: freed heap pages are
/// returned to the system first (malloc_trim), the peak is reset to the current resident set
/// (writing 5 to /proc/self/clear_refs), and the peak after work() (VmHWM) minus the resident set
/// before it (VmRSS) is returned. So memory allocated and touched by work() counts, memory that
/// existed before (its input) does not. NaN where /proc/self does not allow it (not Linux).
double peakMemoryGrowth(const std::function<void()>& work);

/// Registration settings shared by every benchmark (->Apply(...)): milliseconds, wall-clock time
/// for the rates, the whole process's CPU time.
void timedPerPoint(benchmark::internal::Benchmark* benchmark);

/// timedPerPoint, over M = generatorCounts() and 1 or 2 threads (arguments "M" and "threads").
void perGeneratorsAndThreads(benchmark::internal::Benchmark* benchmark);

/// timedPerPoint, at M = 16 over N = pointCounts(), one thread (arguments "M" and "N").
void perPointCount(benchmark::internal::Benchmark* benchmark);

/// Updates a VTK algorithm once per benchmark iteration (Modified() first) with vtkSMPTools on the
/// STDThread backend and `threads` threads: Debian's VTK defaults to Sequential, which ignores
/// threads. Returns the algorithm's output point count. For a pipeline, `algorithm` is its last
/// stage and `first` its source (the one modified, so that every stage runs again).
long long updateEachIteration(
  benchmark::State& state, vtkAlgorithm* algorithm, int threads, vtkAlgorithm* first = nullptr);

/// Runs work(first, last) over [0, count) on `threads` threads (the calling thread and
/// threads - 1 std::threads), which take chunks in turn: a quarter of what is left per thread,
/// from 8192 points down to 1024.
void runOnThreads(int threads,
                  std::size_t count,
                  const std::function<void(std::size_t, std::size_t)>& work);
} // namespace boostedbench
