// The project's worker threads, kept for the life of the process: vtkBoostedBlockLoop runs each
// parallel block on them instead of through vtkSMPTools::For, because VTK 9.2's STDThread backend
// (ParaView 5.11's VTK, whose only other backend is Sequential) builds a pool of new threads for
// every For and joins it at the end: an empty For on two threads took 60 us of wall clock
// (median; 30 us of the calling thread's CPU time), waking a waiting thread and being woken back
// 4 us (a throwaway timing on the 2-vCPU AMD EPYC of README Performance, Threads).
//
// Run(threads, job) runs job() once on each of `threads` pool threads while the calling thread
// waits, as it waits in VTK's pool; the job shares its work out itself (vtkBoostedBlockLoop's
// chunk counter). The calling thread runs the job alone, with the same result, when the pool
// cannot take it: Run is nested in a job or in a vtkSMPTools parallel region (as vtkSMPTools runs
// a nested For), or another thread is running the pool. An exception leaving a job is thrown
// again on the calling thread after every thread has returned (the first one, if several threw).
// In a child process made by fork() the pool starts afresh (its threads were not copied).
#ifndef vtkBoostedThreadPool_h
#define vtkBoostedThreadPool_h

#include "BoostedSurfacesCommonModule.h" // for export macro

#include <functional> // for the job

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedThreadPool
{
public:
  /// Runs job() on `threads` threads at once (the pool's, or the calling thread alone as above)
  /// and returns when every one has returned; threads <= 1 runs it on the calling thread.
  static void Run(int threads, const std::function<void()>& job);

  /// The pool's threads so far: the most that one Run has used (0 before the first).
  static int Threads();

  /// The index of the pool thread that calls it, in [0, Threads()), 0 on any other thread. Pool
  /// thread i stays the same thread from one Run to the next.
  static int ThreadIndex();
};

#endif
