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
  const vtkIdType itemsPerBlock = std::max<vtkIdType>(1, SamplesPerBlock / std::max<vtkIdType>(1, samplesPerItem));
  for (vtkIdType first = begin; first < end; first += itemsPerBlock)
  {
    if (vtkBoostedSurfacesCheckAbort(algorithm))
    {
      return false;
    }
    const vtkIdType last = std::min(end, first + itemsPerBlock);
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
