#include "vtkBoostedLargeArrays.h"

#include "vtkBoostedMemoryBudget.h"
#include "vtkDataArray.h"
#include "vtkSetGet.h" // vtkGenericWarningMacro

#include <cstdint>       // std::uintptr_t
#include <cstdlib>       // malloc, free
#include <deque>         // the kept mappings
#include <mutex>         // the mappings' lock
#include <string>        // the environment's value
#include <unordered_map> // the mappings' lengths
#include <utility>       // std::pair

#if defined(__linux__)
#include <pthread.h>  // pthread_atfork
#include <sys/mman.h> // mmap, munmap, madvise
#endif

namespace
{
constexpr std::size_t HugePage = std::size_t(2) << 20;

#if defined(__linux__) && defined(MADV_HUGEPAGE)
// The cache's limit: BOOSTEDSURFACES_ARRAY_CACHE when set and not empty, otherwise the default.
std::size_t limitFromEnvironment()
{
  const char* text = std::getenv(vtkBoostedLargeArrays::CacheEnvironmentVariable);
  if (!text || !*text)
  {
    return vtkBoostedLargeArrays::DefaultCacheLimit;
  }
  const std::string value(text);
  if (value.find_first_not_of("0. \t") == std::string::npos && value.find('0') != std::string::npos)
  {
    return 0; // "0", "0.0": no cache
  }
  const double bytes = vtkBoostedMemoryBudget::Parse(value);
  if (!(bytes >= 0.0) || bytes > 0x1p62)
  {
    vtkGenericWarningMacro(<< vtkBoostedLargeArrays::CacheEnvironmentVariable << "=\"" << value
                           << "\" is not a size: freed large arrays are not kept.");
    return 0;
  }
  return static_cast<std::size_t>(bytes);
}

// The length of each mapping Allocate handed out, by its start, and the mappings freed and kept
// for the next allocations (oldest first, CachedBytes of them, at most limit()).
struct Mappings
{
  std::mutex Lock;
  std::unordered_map<void*, std::size_t> Lengths;
  std::deque<std::pair<void*, std::size_t>> Cached;
  std::size_t CachedBytes = 0;

  // The cache's limit (under the lock): the environment's, read at the first use after the
  // library is loaded (a program may set the variable before it allocates), or SetCacheLimit's.
  std::size_t limit()
  {
    if (!this->LimitKnown)
    {
      this->Limit = limitFromEnvironment();
      this->LimitKnown = true;
    }
    return this->Limit;
  }
  void setLimit(std::size_t bytes)
  {
    this->Limit = bytes;
    this->LimitKnown = true;
  }

  // Gives back the oldest kept mappings beyond the limit (under the lock).
  void trim()
  {
    while (this->CachedBytes > this->limit())
    {
      munmap(this->Cached.front().first, this->Cached.front().second);
      this->CachedBytes -= this->Cached.front().second;
      this->Cached.pop_front();
    }
  }

private:
  std::size_t Limit = 0;
  bool LimitKnown = false;
};

Mappings& mappings();

// fork() with the lock held by another thread would leave the child's lock held for ever: the
// lock is taken around every fork and released on both sides.
void lockForFork()
{
  mappings().Lock.lock();
}

void unlockAfterFork()
{
  mappings().Lock.unlock();
}

Mappings& mappings()
{
  // Never destroyed: arrays may be freed by other static objects' destructors at exit.
  static Mappings* const all = [] {
    Mappings* made = new Mappings;
    pthread_atfork(lockForFork, unlockAfterFork, unlockAfterFork);
    return made;
  }();
  return *all;
}

// Made when the library is loaded, before a program's threads can race to the first use: a fork()
// while another thread was inside that first use (the static's initialization) left the child
// waiting for ever on the initialization's guard.
[[maybe_unused]] const bool MappingsMadeAtLoad = (mappings(), true);

// A kept mapping of at least `length` bytes and at most a quarter more, the smallest such (taken
// out of the cache and counted as handed out), or null.
void* takeCached(Mappings& all, std::size_t length)
{
  auto best = all.Cached.end();
  for (auto kept = all.Cached.begin(); kept != all.Cached.end(); ++kept)
  {
    if (kept->second >= length && kept->second - length <= length / 4 &&
      (best == all.Cached.end() || kept->second < best->second))
    {
      best = kept;
    }
  }
  if (best == all.Cached.end())
  {
    return nullptr;
  }
  const std::pair<void*, std::size_t> taken = *best;
  all.Lengths.emplace(taken.first, taken.second);
  all.Cached.erase(best);
  all.CachedBytes -= taken.second;
  return taken.first;
}

// A private anonymous mapping of `length` bytes (a multiple of HugePage) starting on a 2 MiB
// boundary, advised to use huge pages; null when the system refuses.
void* mapHugePages(std::size_t length)
{
  void* const base =
    mmap(nullptr, length + HugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (base == MAP_FAILED)
  {
    return nullptr;
  }
  // The 2 MiB boundary inside, and the parts before and after it given back.
  const auto first = reinterpret_cast<std::uintptr_t>(base);
  const std::uintptr_t aligned = (first + HugePage - 1) / HugePage * HugePage;
  if (aligned > first)
  {
    munmap(base, aligned - first);
  }
  const std::uintptr_t after = first + length + HugePage - (aligned + length);
  if (after > 0)
  {
    munmap(reinterpret_cast<void*>(aligned + length), after);
  }
  void* const memory = reinterpret_cast<void*>(aligned);
  // A refusal (a kernel without transparent huge pages) leaves ordinary pages.
  madvise(memory, length, MADV_HUGEPAGE);
  return memory;
}
#endif
} // namespace

void* vtkBoostedLargeArrays::Allocate(std::size_t bytes)
{
  bytes = bytes == 0 ? 1 : bytes;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= LargeBytes)
  {
    if (bytes > std::numeric_limits<std::size_t>::max() - 2 * HugePage)
    {
      throw std::bad_alloc();
    }
    const std::size_t length = (bytes + HugePage - 1) / HugePage * HugePage;
    Mappings& all = mappings();
    {
      const std::lock_guard<std::mutex> hold(all.Lock);
      if (void* const kept = takeCached(all, length))
      {
        return kept;
      }
    }
    void* const memory = mapHugePages(length);
    if (!memory)
    {
      throw std::bad_alloc();
    }
    try
    {
      const std::lock_guard<std::mutex> hold(all.Lock);
      all.Lengths.emplace(memory, length);
    }
    catch (...)
    {
      munmap(memory, length);
      throw std::bad_alloc();
    }
    return memory;
  }
#endif
  void* const memory = std::malloc(bytes);
  if (!memory)
  {
    throw std::bad_alloc();
  }
  return memory;
}

void vtkBoostedLargeArrays::Release(void* memory)
{
  if (!memory)
  {
    return;
  }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Kept for the next allocations when it fits in the cache (the oldest kept ones make room),
  // otherwise unmapped.
  Mappings& all = mappings();
  const std::lock_guard<std::mutex> hold(all.Lock);
  const auto found = all.Lengths.find(memory);
  if (found != all.Lengths.end())
  {
    const std::pair<void*, std::size_t> freed = *found;
    all.Lengths.erase(found);
    bool kept = false;
    if (freed.second <= all.limit())
    {
      try
      {
        all.Cached.push_back(freed);
        all.CachedBytes += freed.second;
        kept = true;
      }
      catch (const std::bad_alloc&)
      {
        // no room to note it: given back at once
      }
    }
    if (!kept)
    {
      munmap(freed.first, freed.second);
    }
    all.trim();
    return;
  }
#endif
  std::free(memory);
}

void vtkBoostedLargeArrays::ReleaseCached()
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  Mappings& all = mappings();
  const std::lock_guard<std::mutex> hold(all.Lock);
  for (const auto& mapping : all.Cached)
  {
    munmap(mapping.first, mapping.second);
  }
  all.Cached.clear();
  all.CachedBytes = 0;
#endif
}

void vtkBoostedLargeArrays::SetCacheLimit(std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  Mappings& all = mappings();
  const std::lock_guard<std::mutex> hold(all.Lock);
  all.setLimit(bytes);
  all.trim();
#else
  (void)bytes;
#endif
}

std::size_t vtkBoostedLargeArrays::GetCacheLimit()
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  Mappings& all = mappings();
  const std::lock_guard<std::mutex> hold(all.Lock);
  return all.limit();
#else
  return 0;
#endif
}

std::size_t vtkBoostedLargeArrays::CachedMemory()
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  Mappings& all = mappings();
  const std::lock_guard<std::mutex> hold(all.Lock);
  return all.CachedBytes;
#else
  return 0;
#endif
}

void vtkBoostedLargeArrays::SetNumberOfTuples(vtkDataArray* array, vtkIdType tuples)
{
  const vtkIdType components = array->GetNumberOfComponents();
  const int valueSize = array->GetDataTypeSize();
  if (tuples < 0 || components < 1 ||
    tuples > std::numeric_limits<vtkIdType>::max() / components)
  {
    throw std::bad_alloc();
  }
  const vtkIdType values = tuples * components;
  if (!array->HasStandardMemoryLayout() || valueSize < 1 ||
    static_cast<std::size_t>(values) * static_cast<std::size_t>(valueSize) < LargeBytes)
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  if (static_cast<std::size_t>(values) > std::numeric_limits<std::size_t>::max() / valueSize)
  {
    throw std::bad_alloc();
  }
  Adopt(array, Allocate(static_cast<std::size_t>(values) * valueSize), values);
}

void vtkBoostedLargeArrays::Adopt(vtkDataArray* array, void* memory, vtkIdType values)
{
  array->SetVoidArray(memory, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&vtkBoostedLargeArrays::Release);
}
