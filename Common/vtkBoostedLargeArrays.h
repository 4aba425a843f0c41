/**
 * @class   vtkBoostedLargeArrays
 * @brief   the memory of the project's large arrays: on transparent huge pages where Linux has them
 *
 * An update of a million points writes about 100 MB of new arrays, and neither VTK nor glibc's
 * malloc keeps freed memory of that size for the next update: it is mapped anew and faults in
 * page by page. On 4 KiB pages that costs more than the update's arithmetic (18 us per fault
 * on the 2-vCPU virtual machine of README Performance: 128 MiB touched in 580 ms, against 8 ms
 * on 2 MiB pages; docs/performance.md, *Memory and page faults*). So the sources and filters
 * allocate their large arrays here: from LargeBytes on, 2 MiB aligned and advised to use huge
 * pages (madvise(MADV_HUGEPAGE), honoured where /sys/kernel/mm/transparent_hugepage/enabled is
 * "always" or "madvise", as NumPy does for its large arrays); smaller ones, and other systems,
 * get malloc's memory. Either way the memory is freed with free(), as VTK frees an array it
 * allocated itself, so the arrays behave as any other (resizing included). Pages are not touched
 * here: the threads that write an array fault its pages in.
 */
#ifndef vtkBoostedLargeArrays_h
#define vtkBoostedLargeArrays_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkType.h"                     // for vtkIdType

#include <cstddef>     // for std::size_t
#include <cstdlib>     // for std::free
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

  /// At least `bytes` bytes (one when `bytes` is 0), freed with free(); throws std::bad_alloc
  /// when the process cannot have them.
  static void* Allocate(std::size_t bytes);

  /// Sizes `array` to `tuples` tuples of its components, as SetNumberOfTuples does (values
  /// undefined), in memory from Allocate when the array stores its values contiguously (VTK's
  /// usual arrays); throws std::bad_alloc instead of VTK's abort when there is none.
  static void SetNumberOfTuples(vtkDataArray* array, vtkIdType tuples);

  struct Free
  {
    void operator()(void* memory) const { std::free(memory); }
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
