#include "vtkBoostedBlockLoop.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <new>

bool vtkBoostedBlockLoop::For(vtkAlgorithm* algorithm, vtkIdType begin, vtkIdType end,
  vtkIdType samplesPerItem, const std::function<void(vtkIdType, vtkIdType)>& work)
{
  vtkIdType samplesPerBlock = SamplesPerBlock;
  for (vtkIdType first = begin, last = begin; first < end; first = last)
  {
    if (vtkBoostedSurfacesCheckAbort(algorithm))
    {
      return false;
    }
    const vtkIdType itemsPerBlock =
      std::max<vtkIdType>(1, samplesPerBlock / std::max<vtkIdType>(1, samplesPerItem));
    last = std::min(end, first + itemsPerBlock);
    samplesPerBlock = std::min(2 * samplesPerBlock, MaximumSamplesPerBlock);
    std::atomic<bool> outOfMemory{ false };
    vtkSMPTools::For(first, last, [&work, &outOfMemory](vtkIdType a, vtkIdType b) {
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
    algorithm->UpdateProgress(static_cast<double>(last - begin) / (end - begin));
  }
  return true;
}
