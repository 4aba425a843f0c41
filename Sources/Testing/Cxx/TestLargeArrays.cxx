// The memory of the large arrays (Common's vtkBoostedLargeArrays): sized as SetNumberOfTuples
// sizes them, 2 MiB aligned and advised to use transparent huge pages from 4 MiB on (the mapping's
// "hg" flag in /proc/self/smaps, where the kernel has transparent huge pages), freed and resized
// by VTK as its own arrays, and refusals as std::bad_alloc before anything is allocated.
#include "vtkBoostedLargeArrays.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSOADataArrayTemplate.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <string>

namespace
{
constexpr std::uintptr_t HugePage = std::uintptr_t(2) << 20;

bool kernelHasHugePages()
{
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

// The VmFlags line of the mapping that holds [memory, memory + bytes), "" when none does.
std::string mappingFlags(const void* memory, std::size_t bytes)
{
  const auto first = reinterpret_cast<std::uintptr_t>(memory);
  const std::uintptr_t last = first + bytes;
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> start >> dash >> end && dash == '-')
    {
      inside = start <= first && last <= end;
    }
    else if (inside && line.compare(0, 8, "VmFlags:") == 0)
    {
      return line + " ";
    }
  }
  return "";
}
} // namespace

TEST(LargeArrays, ALargeArrayIsSizedAlignedAndAdvisedToUseHugePages)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfComponents(3);
  const vtkIdType tuples = 1000003; // 24 MB
  vtkBoostedLargeArrays::SetNumberOfTuples(array, tuples);
  ASSERT_EQ(array->GetNumberOfTuples(), tuples);
  ASSERT_EQ(array->GetNumberOfComponents(), 3);
  ASSERT_EQ(array->GetNumberOfValues(), 3 * tuples);
  double* values = array->GetPointer(0);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values) % HugePage, 0u);
  for (vtkIdType i = 0; i < 3 * tuples; ++i)
  {
    values[i] = static_cast<double>(i);
  }
  EXPECT_EQ(array->GetComponent(tuples - 1, 2), static_cast<double>(3 * tuples - 1));
#if defined(__linux__)
  if (kernelHasHugePages())
  {
    // The whole 2 MiB pages of the array (the rest, under 2 MiB, could not be a huge page).
    const std::string flags =
      mappingFlags(values, 3 * tuples * sizeof(double) / HugePage * HugePage);
    ASSERT_FALSE(flags.empty()) << "no mapping holds the array";
    EXPECT_NE(flags.find(" hg "), std::string::npos) << flags;
  }
#endif
  // VTK grows it as its own (a copy, then free() of this memory), keeping the values.
  const double tuple[3] = { -1.0, -2.0, -3.0 };
  array->InsertNextTuple(tuple);
  ASSERT_EQ(array->GetNumberOfTuples(), tuples + 1);
  EXPECT_EQ(array->GetComponent(tuples - 1, 2), static_cast<double>(3 * tuples - 1));
  EXPECT_EQ(array->GetComponent(tuples, 1), -2.0);
  // And shrinks it.
  array->Resize(10);
  EXPECT_EQ(array->GetComponent(9, 0), 27.0);
}

TEST(LargeArrays, EveryArrayTypeTheProjectAllocatesAndTheirPoints)
{
  vtkNew<vtkFloatArray> floats;
  floats->SetNumberOfComponents(2);
  vtkBoostedLargeArrays::SetNumberOfTuples(floats, 3000000);
  EXPECT_EQ(floats->GetNumberOfTuples(), 3000000);
  floats->SetTypedComponent(2999999, 1, 5.0f);
  EXPECT_EQ(floats->GetTypedComponent(2999999, 1), 5.0f);

  vtkNew<vtkIdTypeArray> ids;
  vtkBoostedLargeArrays::SetNumberOfTuples(ids, 4000000);
  EXPECT_EQ(ids->GetNumberOfValues(), 4000000);
  ids->SetValue(3999999, 7);
  EXPECT_EQ(ids->GetValue(3999999), 7);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkBoostedLargeArrays::SetNumberOfTuples(points->GetData(), 1000000);
  EXPECT_EQ(points->GetNumberOfPoints(), 1000000);
  points->SetPoint(999999, 1.0, 2.0, 3.0);
  double p[3];
  points->GetPoint(999999, p);
  EXPECT_EQ(p[2], 3.0);
  double bounds[6];
  points->SetPoint(0, -1.0, -1.0, -1.0);
  for (vtkIdType i = 1; i < 999999; ++i)
  {
    points->SetPoint(i, 0.0, 0.0, 0.0);
  }
  points->Modified();
  points->GetBounds(bounds);
  EXPECT_EQ(bounds[0], -1.0);
  EXPECT_EQ(bounds[5], 3.0);
}

TEST(LargeArrays, SmallAndEmptyArraysAndOtherLayoutsAreSizedAsVTKSizesThem)
{
  vtkNew<vtkDoubleArray> small;
  small->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(small, 100);
  EXPECT_EQ(small->GetNumberOfTuples(), 100);
  vtkBoostedLargeArrays::SetNumberOfTuples(small, 0);
  EXPECT_EQ(small->GetNumberOfTuples(), 0);
  // Not contiguous: VTK's own allocation.
  vtkNew<vtkSOADataArrayTemplate<double>> soa;
  soa->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(soa, 1000000);
  EXPECT_EQ(soa->GetNumberOfTuples(), 1000000);
  soa->SetTypedComponent(999999, 2, 4.0);
  EXPECT_EQ(soa->GetTypedComponent(999999, 2), 4.0);
}

TEST(LargeArrays, ImpossibleSizesAreRefusedBeforeAllocating)
{
  vtkNew<vtkDoubleArray> array;
  array->SetNumberOfComponents(3);
  EXPECT_THROW(vtkBoostedLargeArrays::SetNumberOfTuples(array, -1), std::bad_alloc);
  EXPECT_THROW(vtkBoostedLargeArrays::SetNumberOfTuples(
                 array, std::numeric_limits<vtkIdType>::max() / 2),
    std::bad_alloc);
  EXPECT_EQ(array->GetNumberOfTuples(), 0) << "left as it was";
  EXPECT_THROW(vtkBoostedLargeArrays::New<double>(std::numeric_limits<std::size_t>::max() / 4),
    std::bad_alloc);
  // A buffer: aligned from 4 MiB on, freed by its owner.
  auto buffer = vtkBoostedLargeArrays::New<long long>(vtkBoostedLargeArrays::LargeBytes / 8);
  ASSERT_TRUE(buffer);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.get()) % HugePage, 0u);
  buffer[vtkBoostedLargeArrays::LargeBytes / 8 - 1] = 3;
  EXPECT_EQ(buffer[vtkBoostedLargeArrays::LargeBytes / 8 - 1], 3);
  EXPECT_TRUE(vtkBoostedLargeArrays::New<char>(0)) << "a buffer of nothing is still a buffer";
}
