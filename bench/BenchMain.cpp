// BoostedBench: Google Benchmark's main, with the kernel's instruction set in the context lines,
// and one memory policy for every benchmark (BOOSTEDBENCH_MEMORY, see README.md here).
#include "cga/PointPairField.h"

#include <benchmark/benchmark.h>

#ifdef BOOSTEDBENCH_LARGE_ARRAYS
#include "vtkBoostedLargeArrays.h"
#endif

#include <cstdlib>
#include <cstring>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace
{
// Each update of a VTK filter allocates its output arrays (48 MB here) and frees the previous
// ones. Whether glibc hands back the same, already mapped pages or fresh ones that fault in page
// by page depends on its adaptive mmap threshold, i.e. on what ran before: the same filter then
// costs up to twice the CPU time. "reuse" (default) keeps freed memory in the heap, "fresh" maps
// every large array anew (the project's large arrays without their cache of freed mappings,
// vtkBoostedLargeArrays); both are deterministic. Returns the policy in use.
std::string setMemoryPolicy()
{
  const char* requested = std::getenv("BOOSTEDBENCH_MEMORY");
  const bool fresh = requested && std::strcmp(requested, "fresh") == 0;
#ifdef BOOSTEDBENCH_LARGE_ARRAYS
  if (fresh)
  {
    vtkBoostedLargeArrays::SetCacheLimit(0);
  }
#endif
#ifdef __GLIBC__
  if (fresh)
  {
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
  }
  else
  {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
  }
  return fresh ? "fresh (arrays over 1 MiB mapped anew)" : "reuse (freed memory kept in the heap)";
#else
  return "allocator default";
#endif
}
} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  std::string available;
  for (const std::string& set : cga::mapPointsInstructionSets())
  {
    available += (available.empty() ? "" : ", ") + set;
  }
  benchmark::AddCustomContext("memory", setMemoryPolicy());
  benchmark::AddCustomContext("kernel_isa", cga::mapPointsInstructionSet());
  benchmark::AddCustomContext("kernel_isa_available", available);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
