#include "vtkBoostedLargeArrays.h"

#include "vtkDataArray.h"

#include <cstdlib> // posix_memalign

#if defined(__linux__)
#include <sys/mman.h> // madvise
#endif

namespace
{
constexpr std::size_t HugePage = std::size_t(2) << 20;
}

void* vtkBoostedLargeArrays::Allocate(std::size_t bytes)
{
  bytes = bytes == 0 ? 1 : bytes;
  void* memory = nullptr;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= LargeBytes)
  {
    if (bytes > std::numeric_limits<std::size_t>::max() - HugePage ||
      posix_memalign(&memory, HugePage, bytes) != 0)
    {
      throw std::bad_alloc();
    }
    // Whole 2 MiB pages inside the block (malloc maps a block this large by itself, so its
    // pages belong to no other allocation); a refusal (a kernel without transparent huge
    // pages) leaves ordinary pages.
    madvise(memory, bytes / HugePage * HugePage, MADV_HUGEPAGE);
    return memory;
  }
#endif
  memory = std::malloc(bytes);
  if (!memory)
  {
    throw std::bad_alloc();
  }
  return memory;
}

void vtkBoostedLargeArrays::SetNumberOfTuples(vtkDataArray* array, vtkIdType tuples)
{
  const vtkIdType components = array->GetNumberOfComponents();
  const int valueSize = array->GetDataTypeSize();
  if (tuples < 0 || components < 1 ||
    tuples > std::numeric_limits<vtkIdType>::max() / components)
  {
    throw std::bad_alloc();
  }
  const vtkIdType values = tuples * components;
  if (!array->HasStandardMemoryLayout() || valueSize < 1 ||
    static_cast<std::size_t>(values) * static_cast<std::size_t>(valueSize) < LargeBytes)
  {
    array->SetNumberOfTuples(tuples);
    return;
  }
  if (static_cast<std::size_t>(values) > std::numeric_limits<std::size_t>::max() / valueSize)
  {
    throw std::bad_alloc();
  }
  void* memory = Allocate(static_cast<std::size_t>(values) * valueSize);
  // The array owns it from here and frees it with free() (VTK_DATA_ARRAY_FREE).
  array->SetVoidArray(memory, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
}
