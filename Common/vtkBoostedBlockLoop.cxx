#include "vtkBoostedBlockLoop.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <new>

vtkIdType vtkBoostedBlockLoop::ItemsPerBlock(vtkIdType samplesPerItem)
{
  const vtkIdType threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const vtkIdType items = std::max<vtkIdType>(1, SamplesPerBlock / std::max<vtkIdType>(1, samplesPerItem));
  return threads == 1 ? items : ThreadedBlocks * threads * items;
}

bool vtkBoostedBlockLoop::For(vtkAlgorithm* algorithm, vtkIdType begin, vtkIdType end,
  vtkIdType samplesPerItem, const std::function<void(vtkIdType, vtkIdType)>& work)
{
  // One thread: the work on the calling thread, without a parallel region (VTK 9.2's STDThread
  // backend starts and joins a pool of threads for every vtkSMPTools::For, even of one thread).
  // More: larger blocks (ItemsPerBlock), each split into 16 chunks per thread, taken in turn, so
  // that at a block's end a thread waits for the others for about 1/32 of its share.
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const vtkIdType itemsPerBlock = ItemsPerBlock(samplesPerItem);
  const vtkIdType grain = std::max<vtkIdType>(1, itemsPerBlock / (16 * threads));
  for (vtkIdType first = begin; first < end; first += itemsPerBlock)
  {
    if (vtkBoostedSurfacesCheckAbort(algorithm))
    {
      return false;
    }
    const vtkIdType last = std::min(end, first + itemsPerBlock);
    if (threads == 1)
    {
      work(first, last); // a std::bad_alloc leaves on the calling thread, as below
    }
    else
    {
      std::atomic<bool> outOfMemory{ false };
      vtkSMPTools::For(first, last, grain, [&work, &outOfMemory](vtkIdType a, vtkIdType b) {
        try
        {
          work(a, b);
        }
        catch (const std::bad_alloc&)
        {
          outOfMemory = true; // reported once, on the calling thread
        }
      });
      if (outOfMemory)
      {
        throw std::bad_alloc();
      }
    }
    algorithm->UpdateProgress(static_cast<double>(last - begin) / (end - begin));
  }
  return true;
}
