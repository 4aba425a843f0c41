/**
 * @class   vtkBoostedBlockLoop
 * @brief   the one work loop of the project's algorithms: blocks, progress, abort, threads
 *
 * Work of many independent items (grid samples, rows of samples, points) runs in blocks
 * (ItemsPerBlock): on one thread of about SamplesPerBlock samples, run by the calling thread
 * itself; on more, of ThreadedBlocks times that per thread, each run by one job per thread on the
 * project's pool (vtkBoostedThreadPool: threads started at the first parallel block and kept, the
 * calling thread waiting as in vtkSMPTools' STDThread backend, whose pool VTK 9.2 starts and
 * joins at every For). The block is cut into one share per thread (ShareBounds), and pool
 * thread i claims the chunks (ChunkBounds) of share i from that share's counter, largest first,
 * down to MinimumChunkSamples, then what is left of the other shares, so that at a block's end a
 * thread waits for the others for about one small chunk. Pool thread i is the same thread at
 * every block and update, so each core mostly rewrites what it wrote the time before (the
 * orbits' update on two threads took 0.85 times as long as with one counter for the block). The
 * number of threads is vtkSMPTools': one on the Sequential backend,
 * GetEstimatedNumberOfThreads() on STDThread. With 8 x 65,536 samples per
 * thread an update of 10^6 points on two threads is one block. Between blocks, on the calling
 * thread only: the abort check (before each block) and the progress (after each block, the
 * fraction of items done). Each item must write only its own slots, so the result does not
 * depend on the blocks, the chunks or the threads.
 *
 * A std::bad_alloc in the work, on any thread, does not terminate the process: each worker
 * catches it and records it, no further chunk of the block is claimed and no further block run,
 * and For throws one std::bad_alloc on the calling thread after the block, for
 * vtkBoostedMemoryBudget::Run to turn into one error and an empty output.
 */
#ifndef vtkBoostedBlockLoop_h
#define vtkBoostedBlockLoop_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkType.h"                     // for vtkIdType

#include <functional> // for the work
#include <vector>     // for the chunks

class vtkAlgorithm;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedBlockLoop
{
public:
  /// About this many samples between two progress updates and abort checks on one thread.
  static constexpr vtkIdType SamplesPerBlock = 65536;

  /// With more threads, this many times SamplesPerBlock samples per thread between them.
  static constexpr vtkIdType ThreadedBlocks = 8;

  /// The smallest chunk a thread takes, in samples, where a block has that many per thread.
  static constexpr vtkIdType MinimumChunkSamples = 2048;

  /// The items of one block, each worth `samplesPerItem` samples, on vtkSMPTools' current
  /// number of threads.
  static vtkIdType ItemsPerBlock(vtkIdType samplesPerItem);

  /// Runs work(first, last) over the items [begin, end), each worth `samplesPerItem` samples
  /// (1 for a point, the columns of a row). Returns false when `algorithm` was aborted (the
  /// remaining blocks are not run); throws std::bad_alloc when the work ran out of memory.
  static bool For(vtkAlgorithm* algorithm, vtkIdType begin, vtkIdType end,
    vtkIdType samplesPerItem, const std::function<void(vtkIdType first, vtkIdType last)>& work);

  /// Runs work(first, last) over the items [begin, end) as one block, without progress or abort:
  /// for passes that must finish once started (the grid builder's, the clip's). On more than one
  /// thread the pool's threads claim the block's chunks as in For (a single item runs on the
  /// calling thread); throws std::bad_alloc as For.
  static void RunBlock(vtkIdType begin, vtkIdType end, vtkIdType samplesPerItem,
    const std::function<void(vtkIdType first, vtkIdType last)>& work);

  /// The chunks of [first, last) on `threads` threads, as bounds: first, ..., last, largest first
  /// (guided: a quarter of what is left per thread, at most a sixteenth of a thread's share, at
  /// least MinimumChunkSamples samples). RunBlock takes each share's on one thread.
  static std::vector<vtkIdType> ChunkBounds(
    vtkIdType first, vtkIdType last, vtkIdType samplesPerItem, int threads);

  /// The block [first, last) cut into `threads` shares as equal as can be (their sizes differ by
  /// at most one item), as bounds: first, ..., last; share i is pool thread i's.
  static std::vector<vtkIdType> ShareBounds(vtkIdType first, vtkIdType last, int threads);
};

#endif
