// vtkPointPairFitFilter's discrete and screw unknowns: twists' pitches (FitPitches) and the
// generators' kinds (FitKinds) recovered from synthetic deformations of a sphere made by
// vtkPointPairDeformationFilter (an independent path: the batch kernel, no derivatives), the
// pitch bounds, and kinds that the target cannot tell apart.
#include "vtkPointPairFitFilter.h"

#include "EventCounter.h"
#include "FitTestSupport.h"
#include "vtkTable.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

namespace
{
constexpr int Weight = 6, Kind = 7, Pitch = 8;

double largestResidual(vtkPointPairFitFilter* fit)
{
  return largestResidual(vtkPolyData::SafeDownCast(fit->GetOutput()));
}

// The fit of `mesh` to `target` from the rows `start`.
void setUp(vtkPointPairFitFilter* fit, vtkPolyData* mesh, vtkPolyData* target,
  const std::vector<Row>& start)
{
  fit->SetInputData(mesh);
  fit->SetTargetData(target);
  addRows(fit, start);
}

double tableValue(vtkPointPairFitFilter* fit, int row, const char* column)
{
  return vtkTable::SafeDownCast(fit->GetOutputDataObject(2))->GetValueByName(row, column).ToDouble();
}

TEST(PointPairFitKinds, RecoversTheWeightsAndPitchesOfTwists)
{
  vtkSmartPointer<vtkPolyData> mesh = unitSphere();
  const std::vector<Row> truth = { { { 0.0, 0.0, 1.4, 0.0, 0.3, 1.0, 0.35, 2, 0.3 } },
    { { 1.3, -0.2, 0.2, 1.0, 0.0, 0.2, -0.25, 2, -0.45 } },
    { { -0.5, 0.9, -1.0, 0.2, 0.0, 1.0, 0.2, 0, 0 } } };
  vtkSmartPointer<vtkPolyData> target = deformed(mesh, truth);
  std::vector<Row> start = truth;
  for (Row& r : start)
  {
    r.values[Weight] *= 0.5;
    r.values[Pitch] = 0.0; // each twist starts as a rotation
  }
  vtkNew<vtkPointPairFitFilter> fit;
  setUp(fit, mesh, target, start);
  fit->FitPitchesOn();
  EventCounter events(fit);
  fit->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 0) << events.lastWarning;
  ASSERT_TRUE(fit->GetImproved());
  for (int g = 0; g < 3; ++g)
  {
    EXPECT_NEAR(tableValue(fit, g, "Weight"), truth[g].values[Weight], 1e-6) << g;
    // The point pair reads no pitch: its pitch is held where it started.
    EXPECT_NEAR(tableValue(fit, g, "Pitch"), truth[g].values[Pitch], 1e-6) << g;
  }
  EXPECT_EQ(tableValue(fit, 2, "Pitch"), 0.0);
  EXPECT_LE(largestResidual(fit), 1e-10);
  EXPECT_GT(fit->GetInitialRMS(), 0.05);

  // Without FitPitches the same start cannot reach the target.
  vtkNew<vtkPointPairFitFilter> without;
  setUp(without, mesh, target, start);
  without->Update();
  EXPECT_GT(without->GetFinalRMS(), 1e-3);
}

TEST(PointPairFitKinds, MaximumPitchChangeBoundsThePitches)
{
  vtkSmartPointer<vtkPolyData> mesh = unitSphere();
  const std::vector<Row> truth = { { { 0.0, 0.0, 1.4, 0.0, 0.3, 1.0, 0.35, 2, 0.5 } } };
  vtkSmartPointer<vtkPolyData> target = deformed(mesh, truth);
  std::vector<Row> start = truth;
  start[0].values[Pitch] = 0.0;
  vtkNew<vtkPointPairFitFilter> fit;
  setUp(fit, mesh, target, start);
  fit->FitPitchesOn();
  const double diagonal = mesh->GetLength(); // the bounding box's diagonal
  fit->SetMaximumPitchChange(0.05);
  fit->Update();
  EXPECT_TRUE(fit->GetImproved());
  EXPECT_NEAR(tableValue(fit, 0, "Pitch"), 0.05 * diagonal, 1e-9); // at its bound
  EXPECT_GT(fit->GetFinalRMS(), 1e-4);

  // FitPitches alone without a twist: nothing can move, and the filter says so.
  vtkNew<vtkPointPairFitFilter> none;
  none->SetInputData(mesh);
  none->SetTargetData(target);
  none->AddGenerator(0.0, 0.0, 1.4, 0.0, 0.3, 1.0, 0.35, vtkPointPairFitFilter::ROTATION, 0.0);
  none->FitWeightsOff();
  none->FitPitchesOn();
  EventCounter events(none);
  none->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 1);
  EXPECT_FALSE(none->GetImproved());
  EXPECT_NE(std::string(none->GetTerminationReason()).find("no unknown to fit"), std::string::npos)
    << none->GetTerminationReason();
}

TEST(PointPairFitKinds, RecoversAKnownMixOfKindsFromPointPairsOfZeroWeight)
{
  vtkSmartPointer<vtkPolyData> mesh = unitSphere();
  // One generator of each kind but the twist (a rotation with a pitch), 0.3 to 0.5 outside the
  // unit sphere on different sides.
  const std::vector<Row> truth = { { { 0.0, 0.0, 1.5, 0.0, 0.2, 1.0, 0.3, 0, 0 } },
    { { 1.4, 0.3, 0.0, 1.0, 0.0, 0.3, 0.35, 1, 0 } },
    { { -0.3, -1.3, -0.5, 0.0, 1.0, 0.0, 0.2, 3, 0 } },
    { { -1.2, 0.6, -0.6, 0.0, 0.0, 1.0, 0.25, 4, 0 } } };
  vtkSmartPointer<vtkPolyData> target = deformed(mesh, truth);
  std::vector<Row> start = truth;
  for (Row& r : start)
  {
    r.values[Weight] = 0.0; // the identity
    r.values[Kind] = vtkPointPairFitFilter::POINT_PAIR;
  }
  vtkNew<vtkPointPairFitFilter> fit;
  setUp(fit, mesh, target, start);
  fit->FitKindsOn();
  EventCounter events(fit);
  fit->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 0) << events.lastWarning;
  EXPECT_TRUE(fit->GetImproved());
  EXPECT_EQ(fit->GetNumberOfUnidentifiedKinds(), 0);
  EXPECT_GT(fit->GetNumberOfFits(), 1 + 4 * 4 - 1); // at least one sweep over the 4 generators
  vtkDataArray* identified = vtkPolyData::SafeDownCast(fit->GetOutputDataObject(1))
                               ->GetPointData()
                               ->GetArray("KindIdentified");
  ASSERT_NE(identified, nullptr);
  for (int g = 0; g < 4; ++g)
  {
    EXPECT_EQ(tableValue(fit, g, "Kind"), truth[g].values[Kind]) << g;
    EXPECT_NEAR(tableValue(fit, g, "Weight"), truth[g].values[Weight], 1e-6) << g;
    EXPECT_EQ(identified->GetComponent(g, 0), 1.0) << g;
  }
  EXPECT_LE(largestResidual(fit), 1e-10);
  EXPECT_GT(fit->GetInitialRMS(), 0.05);
  std::cout << "kinds recovered in " << fit->GetNumberOfFits() << " fits, "
            << fit->GetNumberOfIterations() << " iterations; RMS " << fit->GetInitialRMS()
            << " -> " << fit->GetFinalRMS() << "\n";
}

TEST(PointPairFitKinds, RecoversATwistAndItsPitchAmongOtherKinds)
{
  vtkSmartPointer<vtkPolyData> mesh = unitSphere();
  const std::vector<Row> truth = { { { 0.0, 0.0, 1.4, 0.0, 0.3, 1.0, 0.35, 2, 0.3 } },
    { { 1.4, 0.3, 0.0, 1.0, 0.0, 0.3, 0.3, 0, 0 } },
    { { -0.3, -1.3, -0.5, 0.0, 1.0, 0.0, 0.2, 3, 0 } } };
  vtkSmartPointer<vtkPolyData> target = deformed(mesh, truth);
  std::vector<Row> start = truth;
  for (Row& r : start)
  {
    r.values[Weight] = 0.0;
    r.values[Kind] = vtkPointPairFitFilter::ROTATION;
    r.values[Pitch] = 0.0;
  }
  vtkNew<vtkPointPairFitFilter> fit;
  setUp(fit, mesh, target, start);
  fit->FitKindsOn();
  fit->FitPitchesOn();
  EventCounter events(fit);
  fit->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 0) << events.lastWarning;
  EXPECT_EQ(fit->GetNumberOfUnidentifiedKinds(), 0);
  for (int g = 0; g < 3; ++g)
  {
    EXPECT_EQ(tableValue(fit, g, "Kind"), truth[g].values[Kind]) << g;
    EXPECT_NEAR(tableValue(fit, g, "Weight"), truth[g].values[Weight], 1e-6) << g;
    EXPECT_NEAR(tableValue(fit, g, "Pitch"), truth[g].values[Pitch], 1e-6) << g;
  }
  EXPECT_LE(largestResidual(fit), 1e-10);
}

// A target the mesh already matches: every kind fits it with weight 0, so no kind can be told
// from another. The filter says so (a warning, KindIdentified 0) and keeps the start.
TEST(PointPairFitKinds, KindsTheTargetCannotTellApartAreReported)
{
  vtkSmartPointer<vtkPolyData> mesh = unitSphere();
  vtkNew<vtkPointPairFitFilter> fit;
  fit->SetInputData(mesh);
  fit->SetTargetData(mesh);
  fit->AddGenerator(0.0, 0.0, 1.5, 0.0, 0.0, 1.0, 0.0, vtkPointPairFitFilter::DILATION, 0.0);
  fit->AddGenerator(1.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, vtkPointPairFitFilter::POINT_PAIR, 0.0);
  fit->FitKindsOn();
  EventCounter events(fit);
  fit->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_GE(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find("cannot be identified"), std::string::npos)
    << events.lastWarning;
  EXPECT_EQ(fit->GetNumberOfUnidentifiedKinds(), 2);
  vtkDataArray* identified = vtkPolyData::SafeDownCast(fit->GetOutputDataObject(1))
                               ->GetPointData()
                               ->GetArray("KindIdentified");
  ASSERT_NE(identified, nullptr);
  EXPECT_EQ(identified->GetComponent(0, 0), 0.0);
  EXPECT_EQ(identified->GetComponent(1, 0), 0.0);
  EXPECT_EQ(tableValue(fit, 0, "Kind"), vtkPointPairFitFilter::DILATION); // the start's
  EXPECT_EQ(tableValue(fit, 1, "Kind"), vtkPointPairFitFilter::POINT_PAIR);

  // Without FitKinds there is no KindIdentified array and no count.
  fit->FitKindsOff();
  fit->Update();
  EXPECT_EQ(fit->GetNumberOfUnidentifiedKinds(), -1);
  EXPECT_EQ(vtkPolyData::SafeDownCast(fit->GetOutputDataObject(1))
              ->GetPointData()
              ->GetArray("KindIdentified"),
    nullptr);
}
} // namespace

namespace
{
// The bound of the search's work that MaximumKindSearchWork limits, written out here from its
// documented terms: (1 + 16 M) fits x (iterations + 1) x points x M generators.
double searchWorkBound(double generators, double points, double iterations)
{
  return (1.0 + 16.0 * generators) * (iterations + 1.0) * points * generators;
}

// The unit sphere, its deformation by `truth` (the target) and `truth` with every weight 0 (the
// start: the identity).
struct ZeroWeightStart
{
  vtkSmartPointer<vtkPolyData> mesh, target;
  std::vector<Row> start;
};

ZeroWeightStart zeroWeightStart(const std::vector<Row>& truth)
{
  ZeroWeightStart c{ unitSphere(), nullptr, truth };
  c.target = deformed(c.mesh, truth);
  for (Row& r : c.start)
  {
    r.values[Weight] = 0.0;
  }
  return c;
}

// Rows of `count` point pairs of weight 0 around the unit sphere.
std::vector<Row> pointPairs(int count)
{
  std::vector<Row> rows;
  for (int g = 0; g < count; ++g)
  {
    const double a = 0.7 * g;
    rows.push_back({ { 1.5 * std::cos(a), 1.5 * std::sin(a), 0.1 * g, 0.0, 0.0, 1.0, 0.0, 0, 0 } });
  }
  return rows;
}
}

// A search whose bound exceeds MaximumKindSearchWork is refused before any fit, with an error
// that names the bound; at the bound it runs.
TEST(PointPairFitKinds, MaximumKindSearchWorkRefusesLargerSearches)
{
  const auto [mesh, target, start] =
    zeroWeightStart({ { { 1.4, 0.3, 0.0, 1.0, 0.0, 0.3, 0.3, 0, 0 } },
      { { -0.3, -1.3, -0.5, 0.0, 1.0, 0.0, 0.2, 3, 0 } } });
  const double points = static_cast<double>(mesh->GetNumberOfPoints());
  const double bound = searchWorkBound(2.0, points, 20.0);
  for (const double budget : { std::nextafter(bound, 0.0), bound })
  {
    vtkNew<vtkPointPairFitFilter> fit;
    setUp(fit, mesh, target, start);
    fit->FitKindsOn();
    fit->SetMaximumNumberOfIterations(20);
    fit->SetMaximumKindSearchWork(budget);
    EventCounter events(fit);
    fit->Update();
    if (budget < bound)
    {
      EXPECT_EQ(events.errors, 1);
      EXPECT_NE(events.lastError.find("MaximumKindSearchWork"), std::string::npos)
        << events.lastError;
      EXPECT_NE(events.lastError.find("33 fits"), std::string::npos) << events.lastError;
      EXPECT_EQ(fit->GetNumberOfFits(), -1); // refused before the first fit
      EXPECT_EQ(vtkPolyData::SafeDownCast(fit->GetOutput())->GetNumberOfPoints(), 0);
      EXPECT_EQ(vtkPolyData::SafeDownCast(fit->GetOutputDataObject(1))->GetNumberOfPoints(), 0);
    }
    else
    {
      EXPECT_EQ(events.errors, 0) << events.lastError;
      EXPECT_TRUE(fit->GetImproved());
      EXPECT_LE(largestResidual(fit), 1e-10);
    }
  }

  // The default (1e8) refuses the search the property fuzz found running for hours (seed 104729
  // trial 6502: 38 generators on 4 points at 22,653 iterations, a bound of 2.1e9), and a NaN
  // budget is an error too. Without FitKinds the property does not apply.
  vtkNew<vtkPolyData> four;
  vtkNew<vtkPoints> fourPoints;
  for (int i = 0; i < 4; ++i)
  {
    fourPoints->InsertNextPoint(0.3 * i, 1.0 - 0.2 * i, 0.1 * i * i);
  }
  four->SetPoints(fourPoints);
  vtkNew<vtkPointPairFitFilter> fuzzed;
  setUp(fuzzed, four, four, pointPairs(38));
  fuzzed->FitKindsOn();
  fuzzed->SetMaximumNumberOfIterations(22653);
  EXPECT_EQ(fuzzed->GetMaximumKindSearchWork(), 1e8);
  EXPECT_GT(searchWorkBound(38.0, 4.0, 22653.0), 1e9);
  EventCounter events(fuzzed);
  fuzzed->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("MaximumKindSearchWork (1e+08)"), std::string::npos)
    << events.lastError;
  EXPECT_EQ(fuzzed->GetNumberOfFits(), -1);
  fuzzed->SetMaximumKindSearchWork(std::nan(""));
  fuzzed->Update();
  EXPECT_EQ(events.errors, 2);
  EXPECT_NE(events.lastError.find("must be numbers"), std::string::npos) << events.lastError;
  fuzzed->SetMaximumKindSearchWork(1e8);
  fuzzed->FitKindsOff();
  fuzzed->SetMaximumNumberOfIterations(5);
  fuzzed->Update();
  EXPECT_EQ(events.errors, 2) << events.lastError;
  EXPECT_EQ(fuzzed->GetNumberOfFits(), 1);
}

// Each sweep fits the 4 kinds other than the one a generator has when its turn begins, also when
// another replaces it during the turn (the search once fitted the replaced kind again: 5 fits a
// generator, beyond the documented 1 + 16 M).
TEST(PointPairFitKinds, AReplacedKindIsNotFittedAgainInItsTurn)
{
  auto [mesh, target, start] = zeroWeightStart({ { { 1.4, 0.3, 0.0, 1.0, 0.0, 0.3, 0.3, 0, 0 } } });
  start[0].values[Kind] = vtkPointPairFitFilter::TRANSLATION; // the last kind: the point pair,
                                                             // first, replaces it in its turn
  vtkNew<vtkPointPairFitFilter> fit;
  setUp(fit, mesh, target, start);
  fit->FitKindsOn();
  EventCounter events(fit);
  fit->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(tableValue(fit, 0, "Kind"), vtkPointPairFitFilter::POINT_PAIR);
  EXPECT_EQ(fit->GetNumberOfUnidentifiedKinds(), 0);
  // The first fit, the sweep that finds the point pair, the sweep that changes nothing.
  EXPECT_EQ(fit->GetNumberOfFits(), 1 + 4 + 4);
}
