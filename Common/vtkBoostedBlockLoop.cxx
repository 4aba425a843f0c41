#include "vtkBoostedBlockLoop.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkSMPTools.h"

#include <algorithm>

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
    vtkSMPTools::For(first, last, [&work](vtkIdType a, vtkIdType b) { work(a, b); });
    algorithm->UpdateProgress(static_cast<double>(last - begin) / (end - begin));
  }
  return true;
}
