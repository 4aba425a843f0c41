"""The serial share of vtkPointPairDeformationFilter's update, and what it allows two threads.

    PYTHONPATH=build/lib/python3.11/site-packages \\
      /usr/bin/python3 bench/serial_share.py [Paper|Exact] [M] [side] [updates]

On a machine shared with other jobs the wall clock cannot show how two threads scale; CPU time
can. The calling thread waits, without CPU time, while the project's worker threads
(vtkBoostedThreadPool, as many as vtkSMPTools' STDThread backend gives) run a parallel block,
so the calling thread's CPU time during an update
(time.thread_time) is the update's serial part s, and the process's CPU time less it is the
parallel part p. Amdahl's law bounds two threads at (s + p) / (s + p / 2) times one, less what the
threads lose to each other (the CPU time at two threads over the CPU time at one, "cost", which
also counts the caches and the memory bus shared with the other jobs). The sheet is
bench/callgrind_filter.py's (side x side points, default 1000: the benchmarks' 10^6 points).
Freed memory stays in the heap, as under BoostedBench's default BOOSTEDBENCH_MEMORY=reuse
(bench/README.md): otherwise glibc may unmap each update's old output arrays on the calling thread
and map the new ones afresh, a cost of the heap's state rather than of the filter.
"""
import ctypes
import sys
import time

from callgrind_filter import deformation
from vtkmodules.vtkCommonCore import vtkSMPTools


def measure(rule, generators, side, updates, threads):
    vtkSMPTools.SetBackend("STDThread")
    vtkSMPTools.Initialize(threads)
    filter = deformation(rule, generators, "plain", side)
    filter.Update()  # the first update allocates; the timed ones replace its output
    serial = total = wall = 0.0
    for _ in range(updates):
        filter.Modified()
        t0, p0, w0 = time.thread_time(), time.process_time(), time.perf_counter()
        filter.Update()
        serial += time.thread_time() - t0
        total += time.process_time() - p0
        wall += time.perf_counter() - w0
    return serial / updates, total / updates, wall / updates


def keep_freed_memory():
    libc = ctypes.CDLL("libc.so.6")
    M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3  # malloc.h
    libc.mallopt(M_MMAP_THRESHOLD, 1 << 30)
    libc.mallopt(M_TRIM_THRESHOLD, 1 << 30)


def main():
    keep_freed_memory()
    rule = sys.argv[1] if len(sys.argv) > 1 else "Paper"
    generators = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    side = int(sys.argv[3]) if len(sys.argv) > 3 else 1000
    updates = int(sys.argv[4]) if len(sys.argv) > 4 else 10
    one = measure(rule, generators, side, updates, 1)
    serial, total, wall = measure(rule, generators, side, updates, 2)
    parallel = total - serial
    bound = (serial + parallel) / (serial + parallel / 2)
    print(f"{rule} M = {generators}, {side * side} points, mean of {updates} updates, ms: "
          f"1 thread CPU {1e3 * one[1]:.2f} (wall {1e3 * one[2]:.2f}); 2 threads CPU "
          f"{1e3 * total:.2f} (wall {1e3 * wall:.2f}), of it serial {1e3 * serial:.3f} "
          f"({100 * serial / total:.2f} %); Amdahl bound {bound:.3f}; cost {total / one[1]:.3f}; "
          f"bound / cost {bound / (total / one[1]):.3f}")


if __name__ == "__main__":
    main()
