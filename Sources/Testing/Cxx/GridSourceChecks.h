// Shared by the sources' GoogleTests: out-of-range piece requests, the exact cut at the clip
// sphere (vtkBoostedGridDriver), and outputs that must agree point for point.
#ifndef GridSourceChecks_h
#define GridSourceChecks_h

#include "EventCounter.h"
#include "TranslationChecks.h"
#include "vtkCellArray.h"
#include "vtkDataSet.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

// Every cell of a data set refers to points that exist.
inline void ExpectCellsUseExistingPoints(vtkDataSet* output)
{
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    output->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      ASSERT_GE(ids->GetId(k), 0);
      ASSERT_LT(ids->GetId(k), output->GetNumberOfPoints());
    }
  }
}

// A piece outside [0, pieces) is empty, without an error (as in VTK's sources), also where
// piece + 1 would overflow; the last valid piece of INT_MAX pieces is a valid (small) output.
template <class Source>
void ExpectOutOfRangePiecesEmpty(const std::function<void(Source*)>& setup)
{
  const int requests[][2] = { { 3, 2 }, { 2, 2 }, { -1, 2 }, { INT_MIN, 2 }, { INT_MAX, 2 },
    { INT_MAX, INT_MAX } };
  for (const auto& request : requests)
  {
    vtkNew<Source> source;
    setup(source);
    EventCounter events(source);
    source->UpdatePiece(request[0], request[1], 0);
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0)
      << "piece " << request[0] << " of " << request[1];
    EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0)
      << "piece " << request[0] << " of " << request[1];
    EXPECT_EQ(events.errors, 0) << "piece " << request[0] << " of " << request[1];
  }
  {
    vtkNew<Source> last;
    setup(last);
    EventCounter events(last);
    last->UpdatePiece(INT_MAX - 1, INT_MAX, 0);
    EXPECT_EQ(events.errors, 0);
    ExpectCellsUseExistingPoints(last->GetOutput());
  }
  vtkNew<Source> whole; // the same source still gives its whole output afterwards
  setup(whole);
  whole->UpdatePiece(3, 2, 0);
  whole->UpdatePiece(0, 1, 0);
  EXPECT_GT(whole->GetOutput()->GetNumberOfPoints(), 0);
}

// |p - center| / radius - 1: 0 on the sphere, negative inside.
inline double RelativeSphereExcess(const double p[3], const double center[3], double radius)
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(p, center)) / radius - 1.0;
}

// Every point of `output` lies in the clip ball, and every point where the output was cut lies
// on its sphere, to round-off. The cut points: the ends of open polylines that are not on the
// grid's own border (`onOwnBorder`), and the ends of polygon edges used by one polygon unless both
// ends lie on that border. At
// least `minimumCutPoints` of them (the sphere must cut this output).
inline void ExpectCutExactlyAtTheSphere(vtkPolyData* output, const double center[3], double radius,
  const std::function<bool(vtkIdType)>& onOwnBorder, size_t minimumCutPoints,
  const std::string& what)
{
  ASSERT_GT(output->GetNumberOfCells(), 0) << what;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    EXPECT_LE(RelativeSphereExcess(p, center, radius), 1e-12) << what << ": point " << i;
  }
  std::vector<vtkIdType> cut;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* lines = output->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(npts, ids);)
  {
    for (vtkIdType end : { ids[0], ids[npts - 1] })
    {
      if (ids[0] != ids[npts - 1] && !onOwnBorder(end))
      {
        cut.push_back(end);
      }
    }
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUses;
  vtkCellArray* polys = output->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % npts];
      ++edgeUses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  for (const auto& edge : edgeUses)
  {
    const vtkIdType a = edge.first.first, b = edge.first.second;
    if (edge.second == 1 && !(onOwnBorder(a) && onOwnBorder(b)))
    {
      cut.push_back(a);
      cut.push_back(b);
    }
  }
  EXPECT_GE(cut.size(), minimumCutPoints) << what << ": the sphere cuts this output";
  for (vtkIdType i : cut)
  {
    double p[3];
    output->GetPoint(i, p);
    EXPECT_LE(std::fabs(RelativeSphereExcess(p, center, radius)), 1e-12)
      << what << ": cut point " << i << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  }
}

// `actual` has the points of `expected`, in the same order, each within `tolerance`.
inline void ExpectSamePoints(vtkDataSet* expected, vtkDataSet* actual, double tolerance,
                             const std::string& what)
{
  ASSERT_GT(expected->GetNumberOfPoints(), 0) << what;
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints()) << what;
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    expected->GetPoint(i, p);
    actual->GetPoint(i, q);
    ASSERT_LE(std::sqrt(vtkMath::Distance2BetweenPoints(p, q)), tolerance) << what << ": point " << i;
  }
}

// Directions that only count as directions: `setDirections(source, length)` sets them `length`
// long, and every length must give the points that length 1 gives (a plain |d|^2 overflows beyond
// about 1e154 and underflows below about 1e-154).
template <class Source>
void ExpectTheSamePointsAtEveryDirectionLength(
  const std::function<void(Source*, double)>& setDirections)
{
  vtkNew<Source> unit;
  setDirections(unit, 1.0);
  unit->Update();
  for (const double length : { 1e-300, 1e-200, 1e160, 1e200, 1e307 })
  {
    vtkNew<Source> scaled;
    EventCounter events(scaled);
    setDirections(scaled, length);
    scaled->Update();
    EXPECT_EQ(events.errors, 0) << "length " << length << ": " << events.lastError;
    ExpectSamePoints(unit->GetOutput(), scaled->GetOutput(), 1e-12, "length " + std::to_string(length));
  }
}

// Single-precision points beyond the largest float (vtkBoostedSinglePrecision.h): `farAway`
// sets up the source; as floats its output is one error naming OutputPointsPrecision and empty,
// as doubles it has no error and its largest coordinate is `largest`.
template <class Source>
void ExpectSinglePrecisionBeyondTheLargestFloatIsAnError(
  const std::function<void(Source*)>& farAway, double largest)
{
  vtkNew<Source> source;
  farAway(source);
  EventCounter events(source);
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("OutputPointsPrecision"), std::string::npos) << events.lastError;
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  EXPECT_EQ(events.errors, 1) << events.lastError;
  EXPECT_GT(source->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_DOUBLE_EQ(LargestCoordinate(source->GetOutput()), largest);
}

#endif
