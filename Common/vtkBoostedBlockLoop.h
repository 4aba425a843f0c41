/**
 * @class   vtkBoostedBlockLoop
 * @brief   the one work loop of the project's algorithms: blocks, progress, abort, threads
 *
 * Work of many independent items (grid samples, rows of samples, points) runs in blocks: the
 * first of about SamplesPerBlock samples, each next one twice the one before, up to
 * MaximumSamplesPerBlock; vtkSMPTools spreads each block over the threads. Between blocks, on the
 * calling thread only: the abort check (before each block) and the progress (after each block,
 * the fraction of items done). Each item must write only its own slots, so the result does not
 * depend on the blocks or the threads. The blocks grow because every vtkSMPTools::For of VTK 9.2's
 * STDThread backend starts and joins its threads (about 40 microseconds of the calling thread's
 * time each): a million samples take 6 blocks instead of 16, while the first progress and abort
 * check still come after 65,536 samples.
 *
 * A std::bad_alloc in the work, on any thread, does not terminate the process (an exception
 * leaving a worker thread would): each worker catches it and records it, the remaining blocks
 * are not run, and For throws one std::bad_alloc on the calling thread after the block, for
 * vtkBoostedMemoryBudget::Run to turn into one error and an empty output.
 */
#ifndef vtkBoostedBlockLoop_h
#define vtkBoostedBlockLoop_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkType.h"                     // for vtkIdType

#include <functional> // for the work

class vtkAlgorithm;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedBlockLoop
{
public:
  /// About this many samples in the first block (before the first progress update and the
  /// second abort check), and at most MaximumSamplesPerBlock in any block.
  static constexpr vtkIdType SamplesPerBlock = 65536;
  static constexpr vtkIdType MaximumSamplesPerBlock = 4 * SamplesPerBlock;

  /// Runs work(first, last) over the items [begin, end), each worth `samplesPerItem` samples
  /// (1 for a point, the columns of a row). Returns false when `algorithm` was aborted (the
  /// remaining blocks are not run); throws std::bad_alloc when the work ran out of memory.
  static bool For(vtkAlgorithm* algorithm, vtkIdType begin, vtkIdType end,
    vtkIdType samplesPerItem, const std::function<void(vtkIdType first, vtkIdType last)>& work);
};

#endif
