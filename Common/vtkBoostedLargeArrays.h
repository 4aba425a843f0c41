/**
 * @class   vtkBoostedLargeArrays
 * @brief   the memory of the project's large arrays: on transparent huge pages where Linux has them
 *
 * An update of a million points writes about 100 MB of new arrays, and neither VTK nor glibc's
 * malloc keeps freed memory of that size for the next update: it is mapped anew and faults in
 * page by page. On 4 KiB pages that costs more than the update's arithmetic (18 us per fault
 * on the 2-vCPU virtual machine of README Performance: 128 MiB touched in 580 ms, against 8 ms
 * on 2 MiB pages; docs/performance.md, *Memory and page faults*). So the sources and filters
 * allocate their large arrays here: from LargeBytes on, a mapping of their own, whole 2 MiB pages
 * advised to be huge (madvise(MADV_HUGEPAGE), honoured where
 * /sys/kernel/mm/transparent_hugepage/enabled is "always" or "madvise", as NumPy does for its
 * large arrays); smaller ones, and other systems, get malloc's memory.
 * Not malloc's 2 MiB aligned blocks (posix_memalign): their last part, under 2 MiB, faulted in
 * 4 KiB pages (about 6,600 faults per update of a million-point surface), and rounded up to whole
 * pages they left the heap unable to reuse the blocks (a Python session grew by 30 MB per update).
 * Either way Release frees the memory; the arrays get it as their free function
 * (VTK_DATA_ARRAY_USER_DEFINED), so they behave as any other (VTK resizes one by a copy). A freed
 * mapping is kept for the next allocations of about its size (at most DefaultCacheLimit in all,
 * SetCacheLimit, the oldest given back first; ReleaseCached gives them all back): an update like
 * the last one then writes pages already in place instead of having the kernel clear new ones.
 * Pages are not touched here: the threads that write an array fault its pages in.
 */
#ifndef vtkBoostedLargeArrays_h
#define vtkBoostedLargeArrays_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkType.h"                     // for vtkIdType

#include <cstddef>     // for std::size_t
#include <limits>      // for the size check
#include <memory>      // for Buffer
#include <new>         // for std::bad_alloc
#include <type_traits> // for Buffer's element types

class vtkDataArray;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedLargeArrays
{
public:
  /// From this many bytes on, memory is 2 MiB aligned and advised to use huge pages.
  static constexpr std::size_t LargeBytes = std::size_t(4) << 20;

  /// At least `bytes` bytes (one when `bytes` is 0), freed with Release; throws std::bad_alloc
  /// when the process cannot have them.
  static void* Allocate(std::size_t bytes);

  /// Freed mappings kept for the next allocations, in all at most this many bytes by default.
  static constexpr std::size_t DefaultCacheLimit = std::size_t(256) << 20;

  /// The environment variable that sets the cache's limit, read once (at the first large
  /// allocation or the first call here): a size as BOOSTEDSURFACES_MEMORY_BUDGET reads it
  /// ("512M", "1GiB", "3e8") or 0 for no cache; a value that cannot be read is warned about and
  /// turns the cache off.
  static constexpr const char* CacheEnvironmentVariable = "BOOSTEDSURFACES_ARRAY_CACHE";

  /// The most bytes of freed mappings kept (0: none, every freed mapping given back at once);
  /// lowering it gives back the oldest kept ones beyond it.
  static void SetCacheLimit(std::size_t bytes);
  static std::size_t GetCacheLimit();

  /// Frees memory from Allocate (null: nothing). VTK's free function for the arrays it sizes.
  static void Release(void* memory);

  /// Gives back every kept mapping (the next allocations map new ones).
  static void ReleaseCached();

  /// The bytes of the mappings kept now.
  static std::size_t CachedMemory();

  /// Sizes `array` to `tuples` tuples of its components, as SetNumberOfTuples does (values
  /// undefined), in memory from Allocate when the array stores its values contiguously (VTK's
  /// usual arrays); throws std::bad_alloc instead of VTK's abort when there is none.
  static void SetNumberOfTuples(vtkDataArray* array, vtkIdType tuples);

  /// Makes `memory` (from Allocate, `values` values of the array's type) the values of `array`,
  /// which owns it from then on and frees it with Release. For an array of VTK's usual
  /// contiguous layout (HasStandardMemoryLayout) whose components are set.
  static void Adopt(vtkDataArray* array, void* memory, vtkIdType values);

  struct Free
  {
    void operator()(void* memory) const { Release(memory); }
  };

  /// A buffer of `count` values of a trivial type (values undefined) from Allocate.
  template <typename T>
  using Buffer = std::unique_ptr<T[], Free>;
  template <typename T>
  static Buffer<T> New(std::size_t count)
  {
    static_assert(std::is_trivial<T>::value, "values are left undefined");
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(T))
    {
      throw std::bad_alloc();
    }
    return Buffer<T>(static_cast<T*>(Allocate(count * sizeof(T))));
  }
};

#endif
