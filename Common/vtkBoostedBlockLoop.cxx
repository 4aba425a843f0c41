#include "vtkBoostedBlockLoop.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkBoostedThreadPool.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <new>
#include <vector>

vtkIdType vtkBoostedBlockLoop::ItemsPerBlock(vtkIdType samplesPerItem)
{
  const vtkIdType threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const vtkIdType items = std::max<vtkIdType>(1, SamplesPerBlock / std::max<vtkIdType>(1, samplesPerItem));
  return threads == 1 ? items : ThreadedBlocks * threads * items;
}

std::vector<vtkIdType> vtkBoostedBlockLoop::ChunkBounds(
  vtkIdType first, vtkIdType last, vtkIdType samplesPerItem, int threads)
{
  // Guided: a thread's chunk is a quarter of what is left per thread, at most a sixteenth of its
  // share of the block (so that a thread held up by another job on the machine holds up little)
  // and at least MinimumChunkSamples samples (a chunk costs a claim and a call of the work).
  const vtkIdType perThread = (last - first + threads - 1) / threads;
  const vtkIdType largest = std::max<vtkIdType>(1, perThread / 16);
  const vtkIdType smallest = std::min(largest,
    std::max<vtkIdType>(1, MinimumChunkSamples / std::max<vtkIdType>(1, samplesPerItem)));
  std::vector<vtkIdType> bounds{ first };
  for (vtkIdType begin = first; begin < last;)
  {
    const vtkIdType left = last - begin;
    const vtkIdType size =
      std::min(left, std::max(smallest, std::min(largest, left / (4 * threads))));
    begin += size;
    bounds.push_back(begin);
  }
  return bounds;
}

std::vector<vtkIdType> vtkBoostedBlockLoop::ShareBounds(
  vtkIdType first, vtkIdType last, int threads)
{
  // The first (last - first) % threads shares take one item more.
  const vtkIdType items = last - first, each = items / threads, more = items % threads;
  std::vector<vtkIdType> bounds{ first };
  for (vtkIdType s = 1; s <= threads; ++s)
  {
    bounds.push_back(first + each * s + std::min(s, more));
  }
  return bounds;
}

void vtkBoostedBlockLoop::RunBlock(vtkIdType begin, vtkIdType end, vtkIdType samplesPerItem,
  const std::function<void(vtkIdType, vtkIdType)>& work)
{
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  if (threads == 1 || end - begin <= 1)
  {
    if (begin < end)
    {
      work(begin, end); // a std::bad_alloc leaves on the calling thread, as below
    }
    return;
  }
  // One job per thread of the project's pool (vtkBoostedThreadPool: threads kept from one block
  // and one update to the next). Pool thread i claims share i's chunks first, then the next
  // shares' from their counters, as their owners do, so that a held-up thread holds up little.
  const std::vector<vtkIdType> shares = ShareBounds(begin, end, threads);
  std::vector<std::vector<vtkIdType>> bounds(static_cast<size_t>(threads));
  for (int s = 0; s < threads; ++s)
  {
    bounds[s] = ChunkBounds(shares[s], shares[s + 1], samplesPerItem, 1);
  }
  struct alignas(64) Counter // one cache line each: the owners claim without sharing one
  {
    std::atomic<vtkIdType> Next{ 0 };
  };
  std::vector<Counter> nextChunk(static_cast<size_t>(threads));
  std::atomic<bool> outOfMemory{ false };
  vtkBoostedThreadPool::Run(threads, [&work, &bounds, &nextChunk, &outOfMemory, threads]() {
    try
    {
      const int own = vtkBoostedThreadPool::ThreadIndex() % threads;
      for (int k = 0; k < threads && !outOfMemory; ++k)
      {
        const int s = (own + k) % threads;
        const std::vector<vtkIdType>& b = bounds[s];
        const vtkIdType chunks = static_cast<vtkIdType>(b.size()) - 1;
        for (vtkIdType chunk = nextChunk[s].Next++; chunk < chunks && !outOfMemory;
             chunk = nextChunk[s].Next++)
        {
          work(b[chunk], b[chunk + 1]);
        }
      }
    }
    catch (const std::bad_alloc&)
    {
      outOfMemory = true; // reported once, on the calling thread; the others stop
    }
  });
  if (outOfMemory)
  {
    throw std::bad_alloc();
  }
}

bool vtkBoostedBlockLoop::For(vtkAlgorithm* algorithm, vtkIdType begin, vtkIdType end,
  vtkIdType samplesPerItem, const std::function<void(vtkIdType, vtkIdType)>& work)
{
  // Blocks (ItemsPerBlock) with the abort check before and the progress after each; each block
  // run by RunBlock (each thread its share's chunks first, largest first, then the others').
  const vtkIdType itemsPerBlock = ItemsPerBlock(samplesPerItem);
  for (vtkIdType first = begin; first < end; first += itemsPerBlock)
  {
    if (vtkBoostedSurfacesCheckAbort(algorithm))
    {
      return false;
    }
    const vtkIdType last = std::min(end, first + itemsPerBlock);
    RunBlock(first, last, samplesPerItem, work);
    algorithm->UpdateProgress(static_cast<double>(last - begin) / (end - begin));
  }
  return true;
}
