// The cache of the "Generators" output port (vtkBoostedGeneratorGlyphs::Write with a cache),
// checked the same way for every class that has the port: an update after a change that leaves
// the generators as they were re-executes (the port's data object is written again) but shares
// the last update's arrays (the same objects, their MTimes unchanged: nothing was rebuilt); an
// update after a change of the generators writes new arrays. Both outputs hold, to the bit, what
// a new instance (no cache) gives for the same parameters, so the cache never shows stale values.
#ifndef GeneratorGlyphCacheChecks_h
#define GeneratorGlyphCacheChecks_h

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

// The arrays the Generators port shares with the cache: the points, every point array, the
// vertices' offsets and connectivity. Held by reference, so that no new array can take an old
// one's address.
struct GeneratorGlyphArrays
{
  std::vector<vtkSmartPointer<vtkAbstractArray>> Arrays;
  std::vector<vtkMTimeType> MTimes;

  explicit GeneratorGlyphArrays(vtkPolyData* glyphs)
  {
    this->Add(glyphs->GetPoints() ? glyphs->GetPoints()->GetData() : nullptr);
    for (int a = 0; a < glyphs->GetPointData()->GetNumberOfArrays(); ++a)
    {
      this->Add(glyphs->GetPointData()->GetAbstractArray(a));
    }
    this->Add(glyphs->GetVerts()->GetOffsetsArray());
    this->Add(glyphs->GetVerts()->GetConnectivityArray());
  }
  void Add(vtkAbstractArray* array)
  {
    this->Arrays.emplace_back(array);
    this->MTimes.push_back(array ? array->GetMTime() : 0);
  }
};

// The differences between two Generators outputs, "" when they hold the same points, vertices and
// point arrays (names, components, values) to the bit (-0 is not 0).
inline std::string GeneratorGlyphDifferences(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfVerts() != b->GetNumberOfVerts() ||
    a->GetPointData()->GetNumberOfArrays() != b->GetPointData()->GetNumberOfArrays())
  {
    return "other numbers of points, vertices or point arrays";
  }
  std::vector<std::pair<vtkDataArray*, vtkDataArray*>> pairs;
  if (a->GetNumberOfPoints() > 0)
  {
    pairs.emplace_back(a->GetPoints()->GetData(), b->GetPoints()->GetData());
  }
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* first = a->GetPointData()->GetArray(i);
    vtkDataArray* second =
      first ? b->GetPointData()->GetArray(first->GetName()) : nullptr;
    if (!first || !second || first->GetNumberOfComponents() != second->GetNumberOfComponents() ||
      first->GetDataType() != second->GetDataType())
    {
      return std::string("point array ") + (first ? first->GetName() : "?") + " differs in kind";
    }
    pairs.emplace_back(first, second);
  }
  for (const auto& pair : pairs)
  {
    for (vtkIdType t = 0; t < pair.first->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < pair.first->GetNumberOfComponents(); ++c)
      {
        const double x = pair.first->GetComponent(t, c), y = pair.second->GetComponent(t, c);
        if (std::memcmp(&x, &y, sizeof x) != 0)
        {
          return std::string(pair.first->GetName() ? pair.first->GetName() : "the points") +
            "[" + std::to_string(t) + "][" + std::to_string(c) + "]: " + std::to_string(x) +
            " and " + std::to_string(y);
        }
      }
    }
  }
  return "";
}

// make() returns a new algorithm, set up, whose output `port` is its Generators port;
// otherChange(algorithm) changes parameters that the generators do not depend on (the output
// itself must still be computed anew), generatorChange(algorithm) changes the generators.
template <typename Make, typename OtherChange, typename GeneratorChange>
void ExpectGeneratorGlyphsCached(
  int port, Make make, OtherChange otherChange, GeneratorChange generatorChange)
{
  auto algorithm = make();
  auto glyphsOf = [port](decltype(algorithm)& a) {
    return vtkPolyData::SafeDownCast(a->GetOutputDataObject(port));
  };
  algorithm->Update();
  ASSERT_NE(glyphsOf(algorithm), nullptr);
  ASSERT_GT(glyphsOf(algorithm)->GetNumberOfPoints(), 0);
  const GeneratorGlyphArrays first(glyphsOf(algorithm));
  auto before = vtkSmartPointer<vtkPolyData>::New();
  before->DeepCopy(glyphsOf(algorithm));
  const vtkMTimeType written = glyphsOf(algorithm)->GetMTime();

  otherChange(algorithm.Get());
  algorithm->Update();
  EXPECT_GT(glyphsOf(algorithm)->GetMTime(), written) << "the update did not run";
  const GeneratorGlyphArrays second(glyphsOf(algorithm));
  ASSERT_EQ(second.Arrays.size(), first.Arrays.size());
  for (std::size_t i = 0; i < first.Arrays.size(); ++i)
  {
    const char* name = first.Arrays[i] && first.Arrays[i]->GetName()
      ? first.Arrays[i]->GetName()
      : "(the points or vertices)";
    EXPECT_EQ(second.Arrays[i], first.Arrays[i]) << "array " << i << " " << name << " was built anew";
    EXPECT_EQ(second.MTimes[i], first.MTimes[i])
      << "array " << i << " " << name << " was written again";
  }
  auto fresh = make();
  otherChange(fresh.Get());
  fresh->Update();
  EXPECT_EQ(GeneratorGlyphDifferences(glyphsOf(algorithm), glyphsOf(fresh)), "");

  generatorChange(algorithm.Get());
  algorithm->Update();
  ASSERT_GT(glyphsOf(algorithm)->GetNumberOfPoints(), 0);
  const GeneratorGlyphArrays third(glyphsOf(algorithm));
  EXPECT_NE(third.Arrays.front(), first.Arrays.front()) << "the points were not built anew";
  EXPECT_NE(GeneratorGlyphDifferences(glyphsOf(algorithm), before), "")
    << "the change left the generators as they were";
  auto changed = make();
  otherChange(changed.Get());
  generatorChange(changed.Get());
  changed->Update();
  EXPECT_EQ(GeneratorGlyphDifferences(glyphsOf(algorithm), glyphsOf(changed)), "");
}

#endif
