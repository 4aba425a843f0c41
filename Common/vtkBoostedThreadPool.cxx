#include "vtkBoostedThreadPool.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h> // pthread_atfork
#define BOOSTED_THREAD_POOL_FORK 1
#endif

namespace
{
// True on the pool's threads: a Run inside a job runs on the job's thread.
thread_local bool onPoolThread = false;
// The pool thread's index (ThreadIndex), 0 on any other thread.
thread_local int poolThreadIndex = 0;

class Pool
{
public:
  // Runs the job on `threads` pool threads and waits for them; false when another thread is
  // running the pool or no thread could be started (the caller then runs the job itself).
  bool TryRun(int threads, const std::function<void()>& job)
  {
    std::unique_lock<std::mutex> busy(this->Busy, std::try_to_lock);
    if (!busy.owns_lock())
    {
      return false;
    }
    std::unique_lock<std::mutex> lock(this->Mutex);
    try
    {
      for (; this->Workers < threads; ++this->Workers)
      {
        std::thread(&Pool::Work, this, this->Workers, this->Generation).detach();
      }
    }
    catch (const std::system_error&)
    {
      // Out of threads (a process or system limit): the ones there are do the work.
    }
    if (this->Workers == 0)
    {
      return false;
    }
    this->Job = &job;
    this->Participants = std::min(threads, this->Workers);
    this->Running = this->Participants;
    ++this->Generation;
    this->Wake.notify_all();
    this->Done.wait(lock, [this] { return this->Running == 0; });
    this->Job = nullptr;
    std::exception_ptr failure = this->Failure;
    this->Failure = nullptr;
    lock.unlock();
    busy.unlock();
    if (failure)
    {
      std::rethrow_exception(failure);
    }
    return true;
  }

  int Size()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    return this->Workers;
  }

  Pool* Abandoned = nullptr; // the pool a fork() left before this one (see abandonPoolInChild)

private:
  // A pool thread: waits for the next generation, runs the job when it is one of the first
  // Participants, and the last one to finish wakes the caller.
  void Work(int index, std::uint64_t seen)
  {
    onPoolThread = true;
    poolThreadIndex = index;
    std::unique_lock<std::mutex> lock(this->Mutex);
    for (;;)
    {
      this->Wake.wait(lock, [&] { return this->Generation != seen; });
      seen = this->Generation;
      if (index >= this->Participants)
      {
        continue;
      }
      const std::function<void()>& job = *this->Job;
      lock.unlock();
      std::exception_ptr failure;
      try
      {
        job();
      }
      catch (...)
      {
        failure = std::current_exception();
      }
      lock.lock();
      if (failure && !this->Failure)
      {
        this->Failure = failure;
      }
      if (--this->Running == 0)
      {
        this->Done.notify_one();
      }
    }
  }

  std::mutex Busy; // held by the one Run in progress
  std::mutex Mutex;
  std::condition_variable Wake, Done;
  int Workers = 0;
  const std::function<void()>* Job = nullptr;
  std::uint64_t Generation = 0;
  int Participants = 0;
  int Running = 0;
  std::exception_ptr Failure;
};

// The process's pool, made at the first Run and never destroyed: its threads wait for work until
// the process ends (joining them in a static destructor would race with other libraries' exit).
std::atomic<Pool*> current{ nullptr };

#ifdef BOOSTED_THREAD_POOL_FORK
// The pools that fork() left without threads in this process, newest first: kept reachable (not
// a leak) and never used again.
std::atomic<Pool*> abandoned{ nullptr };

// In the child of a fork() only the forking thread exists: the next Run makes a new pool.
void abandonPoolInChild()
{
  Pool* old = current.exchange(nullptr);
  if (old)
  {
    old->Abandoned = abandoned.exchange(old);
  }
}
#endif

Pool& pool()
{
  Pool* existing = current.load(std::memory_order_acquire);
  if (existing)
  {
    return *existing;
  }
  static std::once_flag registered;
  std::call_once(registered, [] {
#ifdef BOOSTED_THREAD_POOL_FORK
    pthread_atfork(nullptr, nullptr, abandonPoolInChild);
#endif
  });
  Pool* fresh = new Pool;
  if (current.compare_exchange_strong(existing, fresh))
  {
    return *fresh;
  }
  delete fresh; // another thread made it first
  return *existing;
}
} // namespace

void vtkBoostedThreadPool::Run(int threads, const std::function<void()>& job)
{
  if (threads <= 1 || onPoolThread || vtkSMPTools::IsParallelScope() ||
    !pool().TryRun(threads, job))
  {
    job();
  }
}

int vtkBoostedThreadPool::ThreadIndex()
{
  return poolThreadIndex;
}

int vtkBoostedThreadPool::Threads()
{
  return current.load() ? pool().Size() : 0;
}
