// Compatibility for aborting long work: vtkAlgorithm::CheckAbort() exists from VTK 9.2's late
// 2022 snapshots (ParaView 5.11's bundled VTK has it); older VTK only has the AbortExecute flag.
#ifndef vtkBoostedSurfacesAbort_h
#define vtkBoostedSurfacesAbort_h

#include "vtkAlgorithm.h"
#include "vtkVersionMacros.h"

inline bool vtkBoostedSurfacesCheckAbort(vtkAlgorithm* algorithm)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20221201)
  return algorithm->CheckAbort();
#else
  return algorithm->GetAbortExecute() != 0;
#endif
}

#endif
