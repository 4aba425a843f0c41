// The memory of the large arrays (Common's vtkBoostedLargeArrays): sized as SetNumberOfTuples
// sizes them, 2 MiB aligned and advised to use transparent huge pages from 4 MiB on (the mapping's
// "hg" flag in /proc/self/smaps, where the kernel has transparent huge pages), freed and resized
// by VTK as its own arrays, kept when freed for the next update within a bound and given back
// beyond it, and refusals as std::bad_alloc before anything is allocated.
#include "vtkBoostedLargeArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSOADataArrayTemplate.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>  // MADV_HUGEPAGE: the systems with the cache
#include <sys/wait.h>  // waitpid
#include <unistd.h>    // fork
#endif

namespace
{
constexpr std::uintptr_t HugePage = std::uintptr_t(2) << 20;

bool kernelHasHugePages()
{
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

// The VmFlags line of the mapping that holds [memory, memory + bytes), "" when none does.
std::string mappingFlags(const void* memory, std::size_t bytes)
{
  const auto first = reinterpret_cast<std::uintptr_t>(memory);
  const std::uintptr_t last = first + bytes;
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> start >> dash >> end && dash == '-')
    {
      inside = start <= first && last <= end;
    }
    else if (inside && line.compare(0, 8, "VmFlags:") == 0)
    {
      return line + " ";
    }
  }
  return "";
}
} // namespace

TEST(LargeArrays, ALargeArrayIsSizedAlignedAndAdvisedToUseHugePages)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfComponents(3);
  const vtkIdType tuples = 1000003; // 24 MB
  vtkBoostedLargeArrays::SetNumberOfTuples(array, tuples);
  ASSERT_EQ(array->GetNumberOfTuples(), tuples);
  ASSERT_EQ(array->GetNumberOfComponents(), 3);
  ASSERT_EQ(array->GetNumberOfValues(), 3 * tuples);
  double* values = array->GetPointer(0);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values) % HugePage, 0u);
  for (vtkIdType i = 0; i < 3 * tuples; ++i)
  {
    values[i] = static_cast<double>(i);
  }
  EXPECT_EQ(array->GetComponent(tuples - 1, 2), static_cast<double>(3 * tuples - 1));
#if defined(__linux__)
  if (kernelHasHugePages())
  {
    // The whole array, its last part too (its mapping is whole 2 MiB pages).
    const std::string flags = mappingFlags(values, 3 * tuples * sizeof(double));
    ASSERT_FALSE(flags.empty()) << "no mapping holds the array";
    EXPECT_NE(flags.find(" hg "), std::string::npos) << flags;
  }
#endif
  // VTK grows it as its own (a copy, then Release of this memory), keeping the values.
  const double tuple[3] = { -1.0, -2.0, -3.0 };
  array->InsertNextTuple(tuple);
  ASSERT_EQ(array->GetNumberOfTuples(), tuples + 1);
  EXPECT_EQ(array->GetComponent(tuples - 1, 2), static_cast<double>(3 * tuples - 1));
  EXPECT_EQ(array->GetComponent(tuples, 1), -2.0);
  // And shrinks it.
  array->Resize(10);
  EXPECT_EQ(array->GetComponent(9, 0), 27.0);
}

TEST(LargeArrays, EveryArrayTypeTheProjectAllocatesAndTheirPoints)
{
  vtkNew<vtkFloatArray> floats;
  floats->SetNumberOfComponents(2);
  vtkBoostedLargeArrays::SetNumberOfTuples(floats, 3000000);
  EXPECT_EQ(floats->GetNumberOfTuples(), 3000000);
  floats->SetTypedComponent(2999999, 1, 5.0f);
  EXPECT_EQ(floats->GetTypedComponent(2999999, 1), 5.0f);

  vtkNew<vtkIdTypeArray> ids;
  vtkBoostedLargeArrays::SetNumberOfTuples(ids, 4000000);
  EXPECT_EQ(ids->GetNumberOfValues(), 4000000);
  ids->SetValue(3999999, 7);
  EXPECT_EQ(ids->GetValue(3999999), 7);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkBoostedLargeArrays::SetNumberOfTuples(points->GetData(), 1000000);
  EXPECT_EQ(points->GetNumberOfPoints(), 1000000);
  points->SetPoint(999999, 1.0, 2.0, 3.0);
  double p[3];
  points->GetPoint(999999, p);
  EXPECT_EQ(p[2], 3.0);
  double bounds[6];
  points->SetPoint(0, -1.0, -1.0, -1.0);
  for (vtkIdType i = 1; i < 999999; ++i)
  {
    points->SetPoint(i, 0.0, 0.0, 0.0);
  }
  points->Modified();
  points->GetBounds(bounds);
  EXPECT_EQ(bounds[0], -1.0);
  EXPECT_EQ(bounds[5], 3.0);
}

TEST(LargeArrays, SmallAndEmptyArraysAndOtherLayoutsAreSizedAsVTKSizesThem)
{
  vtkNew<vtkDoubleArray> small;
  small->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(small, 100);
  EXPECT_EQ(small->GetNumberOfTuples(), 100);
  vtkBoostedLargeArrays::SetNumberOfTuples(small, 0);
  EXPECT_EQ(small->GetNumberOfTuples(), 0);
  // Not contiguous: VTK's own allocation.
  vtkNew<vtkSOADataArrayTemplate<double>> soa;
  soa->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(soa, 1000000);
  EXPECT_EQ(soa->GetNumberOfTuples(), 1000000);
  soa->SetTypedComponent(999999, 2, 4.0);
  EXPECT_EQ(soa->GetTypedComponent(999999, 2), 4.0);
}

#if defined(__linux__)
namespace
{
// The process's resident memory in bytes (/proc/self/statm), 0 when unknown.
std::size_t residentBytes()
{
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  return statm >> pages >> resident ? resident * 4096 : 0;
}
} // namespace

TEST(LargeArrays, FreedArraysAreKeptForTheNextUpdateWithinABoundAndGivenBack)
{
  vtkBoostedLargeArrays::ReleaseCached();
  ASSERT_EQ(vtkBoostedLargeArrays::CachedMemory(), 0u);
  // As a source's updates: arrays of a few sizes written whole, then freed, forty times over.
  std::size_t before = 0;
  const void* lastPoints = nullptr;
  std::set<const void*> last;
  for (int update = 0; update < 40; ++update)
  {
    vtkNew<vtkDoubleArray> points, normals;
    vtkNew<vtkFloatArray> tcoords;
    points->SetNumberOfComponents(3);
    normals->SetNumberOfComponents(3);
    tcoords->SetNumberOfComponents(2);
    const vtkIdType tuples = 1000000 + 1000 * update;
    vtkBoostedLargeArrays::SetNumberOfTuples(points, tuples);
    vtkBoostedLargeArrays::SetNumberOfTuples(normals, tuples);
    vtkBoostedLargeArrays::SetNumberOfTuples(tcoords, tuples);
    for (vtkIdType i = 0; i < 3 * tuples; ++i)
    {
      points->SetValue(i, 1.0);
      normals->SetValue(i, 2.0);
    }
    for (vtkIdType i = 0; i < 2 * tuples; ++i)
    {
      tcoords->SetValue(i, 3.0f);
    }
    const std::set<const void*> these = { points->GetVoidPointer(0), normals->GetVoidPointer(0),
      tcoords->GetVoidPointer(0) };
    if (update == 0)
    {
      before = residentBytes();
    }
    else
    {
      // The last update's mappings again (their sizes within a quarter of these).
      EXPECT_EQ(these, last) << "update " << update;
    }
    last = these;
    lastPoints = points->GetVoidPointer(0);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lastPoints) % HugePage, 0u);
  }
  // 56 MB written per update: forty of them kept would be 2.2 GB.
  EXPECT_LT(residentBytes(), before + (std::size_t(16) << 20));
  // The three freed mappings kept (25 MB twice and 8.3 MB, in whole 2 MiB pages).
  EXPECT_EQ(vtkBoostedLargeArrays::CachedMemory(), std::size_t(2 * 12 + 4) * HugePage);
  if (kernelHasHugePages())
  {
    EXPECT_FALSE(mappingFlags(lastPoints, 1).empty()) << "kept, still mapped";
  }
  vtkBoostedLargeArrays::ReleaseCached();
  EXPECT_EQ(vtkBoostedLargeArrays::CachedMemory(), 0u);
  if (kernelHasHugePages())
  {
    EXPECT_TRUE(mappingFlags(lastPoints, 1).empty()) << "given back, still mapped";
  }

  // Freed beyond the bound: the oldest are given back, never more than CachedBytes kept.
  {
    std::vector<vtkBoostedLargeArrays::Buffer<char>> buffers;
    const std::size_t size = vtkBoostedLargeArrays::DefaultCacheLimit / 3;
    for (int i = 0; i < 5; ++i)
    {
      buffers.push_back(vtkBoostedLargeArrays::New<char>(size));
    }
    const void* oldest = buffers.front().get();
    buffers.clear(); // freed in order, oldest first
    EXPECT_LE(vtkBoostedLargeArrays::CachedMemory(), vtkBoostedLargeArrays::DefaultCacheLimit);
    EXPECT_GE(vtkBoostedLargeArrays::CachedMemory(), 2 * size);
    if (kernelHasHugePages())
    {
      EXPECT_TRUE(mappingFlags(oldest, 1).empty()) << "the oldest is still mapped";
    }
    // A much smaller request does not take a kept mapping of more than a quarter above it.
    const std::size_t kept = vtkBoostedLargeArrays::CachedMemory();
    vtkBoostedLargeArrays::Buffer<char> small = vtkBoostedLargeArrays::New<char>(size / 2);
    EXPECT_EQ(vtkBoostedLargeArrays::CachedMemory(), kept);
  }
  vtkBoostedLargeArrays::ReleaseCached();

  // No cache: every freed mapping given back at once.
  vtkBoostedLargeArrays::SetCacheLimit(0);
  EXPECT_EQ(vtkBoostedLargeArrays::GetCacheLimit(), 0u);
  {
    const void* memory = vtkBoostedLargeArrays::New<char>(vtkBoostedLargeArrays::LargeBytes).get();
    EXPECT_EQ(vtkBoostedLargeArrays::CachedMemory(), 0u);
    if (kernelHasHugePages())
    {
      EXPECT_TRUE(mappingFlags(memory, 1).empty()) << "kept without a cache";
    }
  }
  vtkBoostedLargeArrays::SetCacheLimit(vtkBoostedLargeArrays::DefaultCacheLimit);

  // A buffer from malloc (under LargeBytes) and one of its own mapping, both released.
  vtkBoostedLargeArrays::Buffer<double> small = vtkBoostedLargeArrays::New<double>(100);
  vtkBoostedLargeArrays::Buffer<double> large =
    vtkBoostedLargeArrays::New<double>(vtkBoostedLargeArrays::LargeBytes / 8);
  small[99] = 1.0;
  large[vtkBoostedLargeArrays::LargeBytes / 8 - 1] = 2.0;
  EXPECT_EQ(small[99] + large[vtkBoostedLargeArrays::LargeBytes / 8 - 1], 3.0);
  vtkBoostedLargeArrays::Release(nullptr); // nothing
}
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
namespace
{
// Exits with 0 when the cache's limit, read from `value` at the first use, is `expected`.
[[noreturn]] void exitWithCacheLimitFor(const char* value, std::size_t expected)
{
  setenv(vtkBoostedLargeArrays::CacheEnvironmentVariable, value, 1);
  std::exit(vtkBoostedLargeArrays::GetCacheLimit() == expected ? 0 : 1);
}
} // namespace

TEST(LargeArrays, TheCacheLimitIsReadFromTheEnvironment)
{
  // Each in a process of its own where nothing has allocated yet (the "threadsafe" style runs the
  // test binary again), since the variable is read once.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  using testing::ExitedWithCode;
  EXPECT_EXIT(exitWithCacheLimitFor("512M", std::size_t(512) << 20), ExitedWithCode(0), "");
  EXPECT_EXIT(exitWithCacheLimitFor("1.5GiB", std::size_t(1536) << 20), ExitedWithCode(0), "");
  EXPECT_EXIT(exitWithCacheLimitFor("3e8", 300000000), ExitedWithCode(0), "");
  EXPECT_EXIT(exitWithCacheLimitFor("0", 0), ExitedWithCode(0), "");
  EXPECT_EXIT(
    exitWithCacheLimitFor("", vtkBoostedLargeArrays::DefaultCacheLimit), ExitedWithCode(0), "");
  EXPECT_EXIT(exitWithCacheLimitFor("plenty", 0), ExitedWithCode(0), "is not a size");
  EXPECT_EXIT(exitWithCacheLimitFor("-5M", 0), ExitedWithCode(0), "is not a size");
}
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
TEST(LargeArrays, AForkWhileAnotherThreadAllocatesLeavesTheChildAbleToAllocate)
{
  // One thread allocates and frees without pause while this one forks; each child allocates,
  // writes and frees a large array and exits (a lock left held would hang it: the parent waits
  // with a timeout and kills it).
  std::atomic<bool> stop{ false };
  std::thread churn([&] {
    while (!stop)
    {
      vtkBoostedLargeArrays::Buffer<char> buffer =
        vtkBoostedLargeArrays::New<char>(vtkBoostedLargeArrays::LargeBytes);
      buffer[0] = 1;
    }
  });
  int hung = 0, failed = 0;
  for (int i = 0; i < 20; ++i)
  {
    const pid_t child = fork();
    if (child == 0)
    {
      vtkBoostedLargeArrays::Buffer<char> buffer =
        vtkBoostedLargeArrays::New<char>(2 * vtkBoostedLargeArrays::LargeBytes);
      buffer[2 * vtkBoostedLargeArrays::LargeBytes - 1] = 1;
      buffer.reset();
      _exit(0);
    }
    ASSERT_GT(child, 0);
    int status = 0;
    pid_t done = 0;
    for (int wait = 0; wait < 500 && done == 0; ++wait) // 5 s
    {
      done = waitpid(child, &status, WNOHANG);
      if (done == 0)
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    }
    if (done == 0)
    {
      ++hung;
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
    }
    else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
      ++failed;
    }
  }
  stop = true;
  churn.join();
  EXPECT_EQ(hung, 0);
  EXPECT_EQ(failed, 0);
}
#endif

TEST(LargeArrays, ImpossibleSizesAreRefusedBeforeAllocating)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfComponents(3);
  EXPECT_THROW(vtkBoostedLargeArrays::SetNumberOfTuples(array, -1), std::bad_alloc);
  EXPECT_THROW(vtkBoostedLargeArrays::SetNumberOfTuples(
                 array, std::numeric_limits<vtkIdType>::max() / 2),
    std::bad_alloc);
  EXPECT_EQ(array->GetNumberOfTuples(), 0) << "left as it was";
  EXPECT_THROW(vtkBoostedLargeArrays::New<double>(std::numeric_limits<std::size_t>::max() / 4),
    std::bad_alloc);
  // A buffer: aligned from 4 MiB on, freed by its owner.
  auto buffer = vtkBoostedLargeArrays::New<long long>(vtkBoostedLargeArrays::LargeBytes / 8);
  ASSERT_TRUE(buffer);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.get()) % HugePage, 0u);
  buffer[vtkBoostedLargeArrays::LargeBytes / 8 - 1] = 3;
  EXPECT_EQ(buffer[vtkBoostedLargeArrays::LargeBytes / 8 - 1], 3);
  EXPECT_TRUE(vtkBoostedLargeArrays::New<char>(0)) << "a buffer of nothing is still a buffer";
}
