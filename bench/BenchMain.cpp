// BoostedBench: Google Benchmark's main, with the kernel's instruction set in the context lines.
#include "cga/PointPairField.h"

#include <benchmark/benchmark.h>

#include <string>

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
  benchmark::AddCustomContext("kernel_isa", cga::mapPointsInstructionSet());
  benchmark::AddCustomContext("kernel_isa_available", available);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
