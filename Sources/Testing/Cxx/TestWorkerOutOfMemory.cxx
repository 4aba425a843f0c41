// A std::bad_alloc in a vtkSMPTools worker thread (an allocation failing inside a source's or the
// filter's per-block work) is one error and an empty output, not std::terminate: the project's
// work loop (vtkBoostedBlockLoop) catches it in the worker and throws it again on the calling
// thread, where vtkBoostedMemoryBudget::Run (the grid driver, the dipole field, the filter) turns
// it into the error. Threads: the STDThread backend with two threads, so the failing block runs
// in a worker thread (an exception leaving one terminates the process).
#include "EventCounter.h"
#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedGridDriver.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedSurfaceSource.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <new>
#include <set>
#include <thread>
#include <vector>

namespace
{
void useThreads()
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
}
}

TEST(WorkerOutOfMemory, TheBlockLoopRethrowsOnTheCallingThreadAndRunMakesOneError)
{
  useThreads();
  vtkNew<vtkBoostedSurfaceSource> algorithm; // any algorithm: it reports the error
  EventCounter events(algorithm);
  std::atomic<int> chunksOfLaterBlocks{ 0 }, failedOffTheCallingThread{ 0 };
  const std::thread::id caller = std::this_thread::get_id();
  // 4 blocks; every chunk of the second one fails, on whichever thread runs it.
  const vtkIdType block = vtkBoostedBlockLoop::ItemsPerBlock(1);
  const bool ran = vtkBoostedMemoryBudget::Run(algorithm, [&] {
    vtkBoostedBlockLoop::For(algorithm, 0, 4 * block, 1, [&](vtkIdType first, vtkIdType) {
      if (first >= 2 * block)
      {
        ++chunksOfLaterBlocks;
      }
      else if (first >= block)
      {
        failedOffTheCallingThread += std::this_thread::get_id() != caller;
        throw std::bad_alloc();
      }
    });
  });
  EXPECT_FALSE(ran);
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("out of memory"), std::string::npos) << events.lastError;
  EXPECT_GT(failedOffTheCallingThread.load(), 0) << "the failure must happen in a worker thread";
  EXPECT_EQ(chunksOfLaterBlocks.load(), 0) << "no block runs after the failing one";
}

TEST(WorkerOutOfMemory, AGridSampleThatFailsToAllocateLeavesTheOutputEmpty)
{
  useThreads();
  vtkNew<vtkBoostedSurfaceSource> source;
  EventCounter events(source);
  vtkNew<vtkInformation> request;
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  request->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  const double center[3] = { 0, 0, 0 };
  vtkBoostedGridDriver driver(source, request, center, 10.0, vtkAlgorithm::DOUBLE_PRECISION);
  ASSERT_TRUE(driver.Prepare("", 512, 512, false, true));
  vtkBoostedGridBuilder& grid = driver.Grid();
  EXPECT_FALSE(driver.SampleGrid([&grid](int r, int c) {
    if (r == 300 && c == 7)
    {
      throw std::bad_alloc();
    }
    const double p[3] = { 0.01 * c, 0.01 * r, 0.0 };
    grid.SetPoint(r, c, p);
  }));
  vtkNew<vtkPolyData> output;
  driver.Build(output);
  EXPECT_EQ(events.errors, 1) << events.lastError;
  EXPECT_EQ(output->GetNumberOfPoints(), 0);
  EXPECT_EQ(output->GetNumberOfCells(), 0);
}

// The chunks the threads take in turn (vtkBoostedBlockLoop::ChunkBounds): they cover the block
// once, in order, largest first, none larger than a sixteenth of a thread's share nor smaller
// than MinimumChunkSamples (but the last), for points, rows of samples, small and odd blocks.
TEST(WorkerOutOfMemory, TheBlockLoopsChunksCoverTheBlockLargestFirst)
{
  struct Case
  {
    vtkIdType first, last, samplesPerItem;
    int threads;
  };
  for (const Case& c : { Case{ 0, 1048576, 1, 2 }, Case{ 1000, 524288 + 1003, 1, 2 },
         Case{ 0, 1049, 1000, 2 }, Case{ 0, 7, 1, 2 }, Case{ 5, 6, 1, 4 },
         Case{ 0, 3000001, 1, 3 }, Case{ 0, 100, 65536, 2 } })
  {
    const std::vector<vtkIdType> bounds =
      vtkBoostedBlockLoop::ChunkBounds(c.first, c.last, c.samplesPerItem, c.threads);
    ASSERT_GE(bounds.size(), 2u);
    EXPECT_EQ(bounds.front(), c.first);
    EXPECT_EQ(bounds.back(), c.last);
    const vtkIdType largest =
      std::max<vtkIdType>(1, (c.last - c.first + c.threads - 1) / c.threads / 16);
    const vtkIdType smallest = std::min(largest,
      std::max<vtkIdType>(1, vtkBoostedBlockLoop::MinimumChunkSamples / c.samplesPerItem));
    for (std::size_t i = 1; i < bounds.size(); ++i)
    {
      const vtkIdType size = bounds[i] - bounds[i - 1];
      EXPECT_GE(size, i + 1 == bounds.size() ? 1 : smallest) << i;
      EXPECT_LE(size, largest) << i;
      if (i > 1)
      {
        EXPECT_LE(size, bounds[i - 1] - bounds[i - 2]) << "chunk " << i << " of " << c.last;
      }
    }
    if (c.last - c.first >= 1048576)
    {
      // Guided: the last chunks are the smallest, far below the largest.
      EXPECT_EQ(bounds[bounds.size() - 2] - bounds[bounds.size() - 3], smallest);
    }
  }
}

// The shares of a block (vtkBoostedBlockLoop::ShareBounds): they cover it once, in order, one per
// thread, their sizes at most one item apart, for blocks smaller than the thread count too.
TEST(WorkerOutOfMemory, TheBlockLoopsSharesCoverTheBlockEvenly)
{
  for (const vtkIdType first : { 0, 17 })
  {
    for (const vtkIdType size : { 0, 1, 2, 3, 7, 1048576, 3000001 })
    {
      for (const int threads : { 1, 2, 3, 4 })
      {
        const std::vector<vtkIdType> bounds =
          vtkBoostedBlockLoop::ShareBounds(first, first + size, threads);
        ASSERT_EQ(bounds.size(), static_cast<std::size_t>(threads) + 1);
        EXPECT_EQ(bounds.front(), first);
        EXPECT_EQ(bounds.back(), first + size);
        for (int s = 0; s < threads; ++s)
        {
          const vtkIdType share = bounds[s + 1] - bounds[s];
          EXPECT_GE(share, size / threads) << size << " on " << threads;
          EXPECT_LE(share, (size + threads - 1) / threads) << size << " on " << threads;
        }
      }
    }
  }
}

// On more than one thread the threads claim the chunks of their shares, then the others' (one job
// per thread, not one per chunk): every item of every block runs exactly once, whichever thread
// claims it, on one and two STDThread threads and on the Sequential backend, for a range of
// several blocks that starts and ends off a block's bound, and the work of two threads is
// shared between two threads.
TEST(WorkerOutOfMemory, TheBlockLoopRunsEveryItemOnceOnEveryBackendAndThreadCount)
{
  struct Setting
  {
    const char* backend;
    int threads;
  };
  for (const Setting& setting :
    { Setting{ "STDThread", 2 }, Setting{ "STDThread", 1 }, Setting{ "Sequential", 1 } })
  {
    vtkSMPTools::SetBackend(setting.backend);
    vtkSMPTools::Initialize(setting.threads);
    vtkNew<vtkBoostedSurfaceSource> algorithm;
    const vtkIdType block = vtkBoostedBlockLoop::ItemsPerBlock(1);
    const vtkIdType begin = 17, end = 2 * block + block / 3 + 5;
    std::vector<std::atomic<int>> runs(static_cast<std::size_t>(end));
    std::atomic<int> chunks{ 0 };
    std::mutex mutex;
    std::set<std::thread::id> threads;
    ASSERT_TRUE(
      vtkBoostedBlockLoop::For(algorithm, begin, end, 1, [&](vtkIdType first, vtkIdType last) {
        ASSERT_LT(first, last);
        ++chunks;
        for (vtkIdType i = first; i < last; ++i)
        {
          ++runs[static_cast<std::size_t>(i)];
        }
        // Long enough that the other thread starts before the chunks run out.
        std::this_thread::sleep_for(std::chrono::microseconds(50));
        const std::lock_guard<std::mutex> lock(mutex);
        threads.insert(std::this_thread::get_id());
      }))
      << setting.backend << " " << setting.threads;
    for (vtkIdType i = 0; i < end; ++i)
    {
      ASSERT_EQ(runs[static_cast<std::size_t>(i)].load(), i < begin ? 0 : 1)
        << "item " << i << ", " << setting.backend << " " << setting.threads;
    }
    if (setting.threads == 1)
    {
      EXPECT_EQ(chunks.load(), 3) << "one thread: each block is one call";
      EXPECT_EQ(threads.size(), 1u);
    }
    else
    {
      EXPECT_GT(chunks.load(), 3 * 16) << "two threads: every block in chunks";
      EXPECT_EQ(threads.size(), 2u) << "both threads take chunks";
    }
  }
  useThreads();
}
