// Shared by the sources' GoogleTests: settings that must each be refused with one error.
#ifndef BadParameterCases_h
#define BadParameterCases_h

#include "EventCounter.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <vector>

enum class EmptyOutput
{
  NoPoints,
  NoPointsNoCells
};

// Applies each of `breakers` to a new Source: its update must give exactly one error and an
// output as empty as `empty` says.
template <class Source>
void ExpectOneErrorEach(
  const std::vector<std::function<void(Source*)>>& breakers, EmptyOutput empty)
{
  for (std::size_t k = 0; k < breakers.size(); ++k)
  {
    vtkNew<Source> source;
    EventCounter events(source);
    breakers[k](source);
    source->Update();
    EXPECT_EQ(events.errors, 1) << "case " << k;
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0) << "case " << k;
    if (empty == EmptyOutput::NoPointsNoCells)
    {
      EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0) << "case " << k;
    }
  }
}

#endif
