// The project's worker threads (Common's vtkBoostedThreadPool, on which vtkBoostedBlockLoop runs
// every parallel block): started once and kept from one Run to the next, the job once on each of
// the asked threads while the calling thread waits, a Run nested in a job or in a vtkSMPTools
// parallel region and a Run while another thread runs the pool done on the calling thread, an
// exception thrown again on the calling thread once every thread has returned, and a child
// process made by fork() served by threads of its own; each pool thread keeps its index; the block
// loop's one block (RunBlock) covers every item once on those threads, each starting with its own
// share and taking the others' when done.
#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedSurfaceSource.h"
#include "vtkBoostedThreadPool.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <new>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace
{
// The threads that ran a job, and how many times it ran.
struct Calls
{
  std::mutex Mutex;
  std::multiset<std::thread::id> Threads;

  void Record()
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    this->Threads.insert(std::this_thread::get_id());
  }
  std::set<std::thread::id> Distinct() const
  {
    return std::set<std::thread::id>(this->Threads.begin(), this->Threads.end());
  }
};
} // namespace

TEST(ThreadPool, TheThreadsStartOnceAndRunEachJobOnEveryOneWhileTheCallerWaits)
{
  const int before = vtkBoostedThreadPool::Threads();
  std::set<std::thread::id> everyRun;
  for (int run = 0; run < 50; ++run)
  {
    Calls calls;
    vtkBoostedThreadPool::Run(3, [&] { calls.Record(); });
    ASSERT_EQ(calls.Threads.size(), 3u) << "run " << run << ": the job once per thread";
    const std::set<std::thread::id> threads = calls.Distinct();
    ASSERT_EQ(threads.size(), 3u) << "run " << run;
    EXPECT_EQ(threads.count(std::this_thread::get_id()), 0u) << "the calling thread waits";
    everyRun.insert(threads.begin(), threads.end());
  }
  EXPECT_EQ(everyRun.size(), 3u) << "the same three threads every time";
  EXPECT_EQ(vtkBoostedThreadPool::Threads(), std::max(before, 3)) << "started once, kept";
  // Fewer threads: the first of the pool's, none started.
  Calls two;
  vtkBoostedThreadPool::Run(2, [&] { two.Record(); });
  EXPECT_EQ(two.Threads.size(), 2u);
  EXPECT_EQ(vtkBoostedThreadPool::Threads(), std::max(before, 3));
  // One thread: the calling thread itself.
  Calls one;
  vtkBoostedThreadPool::Run(1, [&] { one.Record(); });
  ASSERT_EQ(one.Threads.size(), 1u);
  EXPECT_EQ(*one.Threads.begin(), std::this_thread::get_id());
}

TEST(ThreadPool, TheBlockLoopKeepsItsThreadsFromOneUpdateToTheNext)
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  vtkNew<vtkBoostedSurfaceSource> algorithm; // any algorithm: progress and abort
  const vtkIdType items = 3 * vtkBoostedBlockLoop::ItemsPerBlock(1) + 11;
  Calls calls;
  std::atomic<vtkIdType> done{ 0 };
  for (int update = 0; update < 20; ++update)
  {
    ASSERT_TRUE(vtkBoostedBlockLoop::For(algorithm, 0, items, 1, [&](vtkIdType first, vtkIdType last) {
      done += last - first;
      calls.Record();
    }));
  }
  EXPECT_EQ(done.load(), 20 * items);
  const std::set<std::thread::id> threads = calls.Distinct();
  EXPECT_EQ(threads.size(), 2u) << "60 blocks, two threads";
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 0u);
  EXPECT_GE(vtkBoostedThreadPool::Threads(), 2);
}

// ThreadIndex: 0 on the calling thread; on the pool's threads their indices 0 ... n - 1, each
// the same thread's from one Run to the next.
TEST(ThreadPool, EachPoolThreadKeepsItsIndex)
{
  EXPECT_EQ(vtkBoostedThreadPool::ThreadIndex(), 0);
  std::map<int, std::thread::id> threadOf;
  for (int run = 0; run < 20; ++run)
  {
    std::mutex mutex;
    std::map<int, std::thread::id> seen;
    vtkBoostedThreadPool::Run(2, [&] {
      const std::lock_guard<std::mutex> lock(mutex);
      seen[vtkBoostedThreadPool::ThreadIndex()] = std::this_thread::get_id();
    });
    ASSERT_EQ(seen.size(), 2u) << "run " << run;
    ASSERT_EQ(seen.begin()->first, 0);
    ASSERT_EQ(seen.rbegin()->first, 1);
    if (run == 0)
    {
      threadOf = seen;
    }
    EXPECT_EQ(seen, threadOf) << "run " << run;
  }
  EXPECT_EQ(vtkBoostedThreadPool::ThreadIndex(), 0);
}

// RunBlock on two threads: pool thread i starts with the first chunk of share i (ShareBounds),
// whichever thread wakes first. The first chunk each thread runs waits until both have started
// (or 10 s), so that neither can have finished its share and taken the other's first chunk.
TEST(ThreadPool, EachThreadStartsWithItsOwnShareOfTheBlock)
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  for (const vtkIdType count : { 2, 3, 4096, 65537, 300001 })
  {
    const std::vector<vtkIdType> shares = vtkBoostedBlockLoop::ShareBounds(5, 5 + count, 2);
    std::mutex mutex;
    std::map<int, vtkIdType> firstItem; // pool thread index -> first item of its first chunk
    std::atomic<int> started{ 0 };
    std::atomic<vtkIdType> covered{ 0 };
    vtkBoostedBlockLoop::RunBlock(5, 5 + count, 1, [&](vtkIdType first, vtkIdType last) {
      covered += last - first;
      thread_local int lastCount = -1;
      if (lastCount != static_cast<int>(count))
      {
        lastCount = static_cast<int>(count);
        {
          const std::lock_guard<std::mutex> lock(mutex);
          firstItem[vtkBoostedThreadPool::ThreadIndex()] = first;
        }
        ++started;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started < 2 && std::chrono::steady_clock::now() < deadline)
        {
          std::this_thread::yield();
        }
      }
    });
    EXPECT_EQ(covered.load(), count);
    ASSERT_EQ(firstItem.size(), 2u) << count;
    EXPECT_EQ(firstItem[0], shares[0]) << count;
    EXPECT_EQ(firstItem[1], shares[1]) << count;
  }
}

// A held-up thread holds up little: with pool thread 1 sleeping 2 ms in every chunk it takes,
// thread 0 finishes its own share and then takes most of share 1's chunks.
TEST(ThreadPool, AThreadDoneWithItsShareTakesTheOthers)
{
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  const vtkIdType count = 1 << 19;
  const std::vector<vtkIdType> shares = vtkBoostedBlockLoop::ShareBounds(0, count, 2);
  std::atomic<vtkIdType> covered{ 0 }, secondShareByThreadZero{ 0 };
  vtkBoostedBlockLoop::RunBlock(0, count, 1, [&](vtkIdType first, vtkIdType last) {
    covered += last - first;
    if (vtkBoostedThreadPool::ThreadIndex() == 1)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    else if (first >= shares[1])
    {
      secondShareByThreadZero += last - first;
    }
  });
  EXPECT_EQ(covered.load(), count);
  EXPECT_GT(secondShareByThreadZero.load(), (shares[2] - shares[1]) / 2);
}

TEST(ThreadPool, OneBlockCoversEveryItemOnceOnTheKeptThreads)
{
  // RunBlock: the grid builder's and the clip's passes (no progress, no abort).
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  for (const vtkIdType samplesPerItem : { 1, 700, 100000 })
  {
    for (const vtkIdType count : { 0, 1, 2, 3, 17, 4096, 65537, 300001 })
    {
      std::vector<std::atomic<int>> visits(static_cast<size_t>(count) + 2);
      Calls calls;
      vtkBoostedBlockLoop::RunBlock(1, count + 1, samplesPerItem,
        [&](vtkIdType first, vtkIdType last) {
          ASSERT_LE(1, first);
          ASSERT_LT(first, last);
          ASSERT_LE(last, count + 1);
          for (vtkIdType i = first; i < last; ++i)
          {
            ++visits[i];
          }
          calls.Record();
        });
      for (vtkIdType i = 0; i < count + 2; ++i)
      {
        ASSERT_EQ(visits[i].load(), i >= 1 && i <= count ? 1 : 0)
          << "item " << i << " of " << count << ", " << samplesPerItem << " samples each";
      }
      if (count >= 2)
      {
        // The pool's threads, not the calling thread (which of them takes the chunks depends on
        // which wakes first).
        EXPECT_EQ(calls.Distinct().count(std::this_thread::get_id()), 0u) << count;
      }
    }
  }
  // A std::bad_alloc in a worker: thrown again on the calling thread, and the pool still works.
  std::atomic<int> failedOffTheCallingThread{ 0 };
  const std::thread::id caller = std::this_thread::get_id();
  EXPECT_THROW(vtkBoostedBlockLoop::RunBlock(0, 1 << 20, 1,
                 [&](vtkIdType first, vtkIdType) {
                   if (first == 0)
                   {
                     failedOffTheCallingThread += std::this_thread::get_id() != caller;
                     throw std::bad_alloc();
                   }
                 }),
    std::bad_alloc);
  EXPECT_EQ(failedOffTheCallingThread.load(), 1);
  std::atomic<vtkIdType> after{ 0 };
  vtkBoostedBlockLoop::RunBlock(
    0, 1 << 20, 1, [&](vtkIdType first, vtkIdType last) { after += last - first; });
  EXPECT_EQ(after.load(), 1 << 20);
  // The Sequential backend: the calling thread alone, the whole range at once.
  vtkSMPTools::SetBackend("Sequential");
  Calls sequential;
  vtkIdType covered = 0;
  vtkBoostedBlockLoop::RunBlock(0, 300001, 1, [&](vtkIdType first, vtkIdType last) {
    covered += last - first;
    sequential.Record();
  });
  EXPECT_EQ(covered, 300001);
  ASSERT_EQ(sequential.Threads.size(), 1u);
  EXPECT_EQ(*sequential.Threads.begin(), std::this_thread::get_id());
  vtkSMPTools::SetBackend("STDThread");
}

TEST(ThreadPool, ARunInAJobOrInAnSMPRegionRunsOnTheCallingThread)
{
  std::atomic<int> inner{ 0 }, elsewhere{ 0 };
  vtkBoostedThreadPool::Run(2, [&] {
    const std::thread::id outer = std::this_thread::get_id();
    vtkBoostedThreadPool::Run(2, [&] {
      ++inner;
      elsewhere += std::this_thread::get_id() != outer;
    });
  });
  EXPECT_EQ(inner.load(), 2) << "once in each of the two outer jobs";
  EXPECT_EQ(elsewhere.load(), 0);

  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  inner = 0;
  elsewhere = 0;
  vtkSMPTools::For(0, 2, 1, [&](vtkIdType, vtkIdType) {
    const std::thread::id outer = std::this_thread::get_id();
    vtkBoostedThreadPool::Run(2, [&] {
      ++inner;
      elsewhere += std::this_thread::get_id() != outer;
    });
  });
  EXPECT_EQ(inner.load(), 2);
  EXPECT_EQ(elsewhere.load(), 0);
}

TEST(ThreadPool, TwoThreadsRunningAtOnceEachGetTheirJobsDone)
{
  // One of them may find the pool busy and run its job alone: either way every job runs as
  // often as asked and neither waits for ever.
  std::atomic<int> jobs[2] = { { 0 }, { 0 } };
  auto caller = [&jobs](int which) {
    for (int run = 0; run < 300; ++run)
    {
      std::atomic<int> calls{ 0 };
      vtkBoostedThreadPool::Run(2, [&] {
        ++calls;
        std::this_thread::sleep_for(std::chrono::microseconds(20));
      });
      jobs[which] += calls.load() >= 1 && calls.load() <= 2;
    }
  };
  std::thread first(caller, 0), second(caller, 1);
  first.join();
  second.join();
  EXPECT_EQ(jobs[0].load(), 300);
  EXPECT_EQ(jobs[1].load(), 300);
}

TEST(ThreadPool, AnExceptionIsThrownOnTheCallingThreadOnceEveryThreadHasReturned)
{
  std::atomic<int> started{ 0 };
  std::atomic<bool> slowOneReturned{ false };
  EXPECT_THROW(vtkBoostedThreadPool::Run(2,
                 [&] {
                   if (started++ == 0)
                   {
                     throw std::runtime_error("a job failed");
                   }
                   std::this_thread::sleep_for(std::chrono::milliseconds(30));
                   slowOneReturned = true;
                 }),
    std::runtime_error);
  EXPECT_EQ(started.load(), 2);
  EXPECT_TRUE(slowOneReturned.load()) << "Run returned before the other thread did";
  // The pool still works.
  std::atomic<int> calls{ 0 };
  vtkBoostedThreadPool::Run(2, [&] { ++calls; });
  EXPECT_EQ(calls.load(), 2);
}

#if defined(__unix__) || defined(__APPLE__)
TEST(ThreadPool, AForkedChildRunsOnThreadsOfItsOwn)
{
  vtkBoostedThreadPool::Run(2, [] {}); // the parent's pool exists
  ASSERT_GE(vtkBoostedThreadPool::Threads(), 2);
  const pid_t child = fork();
  ASSERT_NE(child, -1);
  if (child == 0)
  {
    // The parent's pool threads do not exist here: without a pool of its own the child would wait
    // for them for ever (the alarm ends it then, and the parent sees a signal).
    alarm(20);
    std::atomic<int> calls{ 0 }, onCaller{ 0 };
    const std::thread::id caller = std::this_thread::get_id();
    vtkBoostedThreadPool::Run(2, [&] {
      ++calls;
      onCaller += std::this_thread::get_id() == caller;
    });
    _exit(calls.load() == 2 && onCaller.load() == 0 && vtkBoostedThreadPool::Threads() == 2 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child hung or crashed (signal "
                                 << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << ")";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the child's Run did not use two threads of its own";
}
#endif
