// vtkConformalOrbitSource: the torus knot's polylines against the kernel (cga::Orbit, itself
// tested against the matrix exponential) and against plain geometry (closure, linking numbers of
// the output polylines with the output cores, the transversion's closed form), seeds, pieces,
// degenerate and bad input.
#include "vtkBoostedGridDriver.h"
#include "vtkConformalOrbitSource.h"

#include "BadParameterCases.h"
#include "GeneratorGlyphCacheChecks.h"
#include "GridSourceChecks.h"
#include "LinkingNumber.h"
#include "ProgressLog.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "cga/PointPairField.h"
#include "cga/surfaces/TorusKnot.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace
{
using cga::Vec3;

// The points of each polyline (a closed one without its repeated first point), in order.
std::vector<std::vector<Vec3>> polylines(vtkPolyData* output, bool* allClosed = nullptr)
{
  std::vector<std::vector<Vec3>> result;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* lines = output->GetLines();
  bool closed = lines->GetNumberOfCells() > 0;
  for (lines->InitTraversal(); lines->GetNextCell(npts, ids);)
  {
    const bool isClosed = npts > 2 && ids[0] == ids[npts - 1];
    closed = closed && isClosed;
    std::vector<Vec3> points;
    for (vtkIdType k = 0; k < (isClosed ? npts - 1 : npts); ++k)
    {
      double p[3];
      output->GetPoint(ids[k], p);
      points.push_back({ p[0], p[1], p[2] });
    }
    result.push_back(points);
  }
  if (allClosed)
  {
    *allClosed = closed;
  }
  return result;
}

double period(vtkPolyData* output)
{
  vtkDataArray* array = output->GetFieldData()->GetArray("Period");
  return array ? array->GetTuple1(0) : -1.0;
}

double distance(Vec3 a, Vec3 b)
{
  return cga::norm(a - b);
}

TEST(ConformalOrbitSource, DefaultIsTheTrefoilClosedAfterItsPeriod)
{
  vtkNew<vtkConformalOrbitSource> source;
  EventCounter events(source);
  source->Update();
  EXPECT_EQ(events.errors + events.warnings, 0);
  vtkPolyData* output = source->GetOutput();
  bool closed = false;
  const auto lines = polylines(output, &closed);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(closed);
  EXPECT_EQ(lines[0].size(), 512u);
  EXPECT_NEAR(period(output), 6.0, 1e-14); // lcm(2, 3)
  // Every point is the kernel's orbit point at its t.
  cga::TorusKnot knot;
  const cga::Orbit orbit = knot.orbit();
  vtkDataArray* t = output->GetPointData()->GetArray("t");
  vtkDataArray* id = output->GetPointData()->GetArray("OrbitId");
  ASSERT_TRUE(t && id);
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    Vec3 expected;
    ASSERT_TRUE(orbit.point({ 0.15, 0, 0 }, t->GetTuple1(i), expected));
    // The source applies exp(t B) as a 5 x 5 point map, the reference as a sandwich: a few ulps.
    EXPECT_LE(distance({ p[0], p[1], p[2] }, expected), 1e-14);
    EXPECT_EQ(id->GetTuple1(i), 0.0);
    EXPECT_GE(t->GetTuple1(i), 0.0);
    EXPECT_LT(t->GetTuple1(i), 6.0);
  }
}

TEST(ConformalOrbitSource, KnotsLinkTheOutputCoresQAndPTimes)
{
  const int pairs[][2] = { { 2, 3 }, { 3, 5 }, { 5, 8 }, { 7, 3 } };
  cga::TorusKnot knot;
  knot.center = { 1, -2, 0.5 };
  knot.normal = { 0.2, 1, 0.3 };
  knot.direction = { 1, 0, 1 };
  knot.radius = 2.5;
  const Vec3 u = cga::normalized(knot.coreC().center - knot.coreA().center);
  for (const auto& pq : pairs)
  {
    vtkNew<vtkConformalOrbitSource> source;
    source->SetKnotP(pq[0]);
    source->SetKnotQ(pq[1]);
    source->SetKnotCenter(1, -2, 0.5);
    source->SetKnotNormal(0.2, 1, 0.3);
    source->SetKnotDirection(1, 0, 1);
    source->SetKnotRadius(2.5);
    source->SetTResolution(100 * pq[0] * pq[1]);
    source->SetCoreResolution(200);
    source->SetSeedModeToSeedList();
    // Seeds 0.15 and 0.2 radii from the center towards C, on tori about A (not on the middle
    // torus through the center, which passes through infinity).
    for (double offset : { 0.15, 0.2 })
    {
      const Vec3 seed = knot.center + (offset * knot.radius) * u;
      source->AddSeed(seed.x, seed.y, seed.z);
    }
    source->Update();
    EXPECT_NEAR(period(source->GetOutput()), pq[0] * pq[1], 1e-13);
    const auto knots = polylines(source->GetOutput());
    ASSERT_EQ(knots.size(), 2u);
    vtkPolyData* coreOutput = vtkPolyData::SafeDownCast(source->GetOutputDataObject(1));
    bool closed = false;
    const auto cores = polylines(coreOutput, &closed);
    ASSERT_EQ(cores.size(), 2u);
    EXPECT_TRUE(closed);
    EXPECT_EQ(coreOutput->GetPointData()->GetArray("CoreId")->GetRange()[1], 1.0);
    for (const auto& points : knots)
    {
      EXPECT_NEAR(cgatest::polygonLinkingNumber(points, cores[0]), pq[1], 1e-9);
      EXPECT_NEAR(cgatest::polygonLinkingNumber(points, cores[1]), pq[0], 1e-9);
    }
    // The cores are the knot's circles A and C, of radius 2.5.
    const cga::TorusKnot::Circle expected[2] = { knot.coreA(), knot.coreC() };
    for (int c = 0; c < 2; ++c)
    {
      for (const Vec3& p : cores[c])
      {
        EXPECT_NEAR(distance(p, expected[c].center), 2.5, 1e-12);
        EXPECT_NEAR(cga::dot(p - expected[c].center, expected[c].normal), 0.0, 1e-12);
      }
    }
  }
}

TEST(ConformalOrbitSource, OpenRangeOfAPeriodicOrbitEndsWhereItStarted)
{
  vtkNew<vtkConformalOrbitSource> source;
  source->ClosePeriodicOrbitsOff();
  source->SetTRange(0, 6);
  source->Update();
  bool closed = true;
  const auto lines = polylines(source->GetOutput(), &closed);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FALSE(closed);
  ASSERT_EQ(lines[0].size(), 513u);
  EXPECT_LE(distance(lines[0].front(), lines[0].back()), 1e-12);
}

TEST(ConformalOrbitSource, OnePointPairIsTheTransversionAboutItsLocation)
{
  // B = -w tau(x, v): exp(t B) = 1 + tau(x, -t w v), p -> x + SCT_{-t w v}(p - x)
  // (docs/conventions.md section 2 item 2), not periodic.
  const Vec3 x{ 0.5, -0.25, 1 }, v{ 0.3, 0.1, -0.2 };
  const double w = 1.5;
  vtkNew<vtkConformalOrbitSource> source;
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(x.x, x.y, x.z, v.x, v.y, v.z, w);
  source->SetSeedPoint(1, 1, 1);
  source->SetTRange(-2, 3);
  source->SetTResolution(50);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(period(output), 0.0);
  ASSERT_EQ(output->GetNumberOfPoints(), 51);
  vtkDataArray* t = output->GetPointData()->GetArray("t");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    const Vec3 u = (-t->GetTuple1(i) * w) * v, y = Vec3{ 1, 1, 1 } - x;
    const Vec3 expected =
      x + (1.0 / (1.0 + 2.0 * cga::dot(u, y) + cga::dot(u, u) * cga::dot(y, y))) * (y + cga::dot(y, y) * u);
    double p[3];
    output->GetPoint(i, p);
    EXPECT_LE(distance({ p[0], p[1], p[2] }, expected), 1e-13) << "t " << t->GetTuple1(i);
  }
  // A point pair has no rotating part: no cores.
  EXPECT_EQ(vtkPolyData::SafeDownCast(source->GetOutputDataObject(1))->GetNumberOfPoints(), 0);
}

TEST(ConformalOrbitSource, HugeTimesReachTheFixedPointOrWarnWhereTBOverflows)
{
  // The transversion about x sends every point to x as |t| grows: |p(t) - x| is about
  // 1/(|t| w |v| |y|^2)... of order 1/|t|. At |t| = 1e160 exp(t B) = 1 + t B is finite but its
  // point map's entries (products of two components) were 1e320: every sample but the seed was
  // lost without a word. exp(t B) is now scaled by a power of two (the map does not change).
  const Vec3 x{ 0.5, -0.25, 1 }, v{ 0.3, 0.1, -0.2 };
  for (const double T : { 1e160, 1e300 })
  {
    vtkNew<vtkConformalOrbitSource> source;
    EventCounter events(source);
    source->SetGeneratorTypeToGeneratorList();
    source->AddGenerator(x.x, x.y, x.z, v.x, v.y, v.z, 1.5);
    source->SetSeedPoint(1, 1, 1);
    source->SetTRange(0, T);
    source->SetTResolution(4);
    source->Update();
    EXPECT_EQ(events.errors + events.warnings, 0) << T;
    vtkPolyData* output = source->GetOutput();
    ASSERT_EQ(output->GetNumberOfPoints(), 5) << T;
    double p[3];
    output->GetPoint(0, p); // t = 0: the seed
    EXPECT_EQ(distance({ p[0], p[1], p[2] }, { 1, 1, 1 }), 0.0);
    for (vtkIdType i = 1; i < 5; ++i)
    {
      output->GetPoint(i, p);
      EXPECT_LE(distance({ p[0], p[1], p[2] }, x), 1e-14) << T << " sample " << i;
    }
  }
  // Where t B itself overflows there is no image: the samples are dropped with a warning.
  vtkNew<vtkConformalOrbitSource> overflowing;
  EventCounter events(overflowing);
  overflowing->SetGeneratorTypeToGeneratorList();
  overflowing->AddGenerator(x.x, x.y, x.z, v.x, v.y, v.z, 1e10);
  overflowing->SetSeedPoint(1, 1, 1);
  overflowing->SetTRange(0, 1e300);
  overflowing->SetTResolution(4);
  overflowing->Update();
  EXPECT_EQ(events.errors, 0);
  EXPECT_EQ(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find("samples dropped"), std::string::npos) << events.lastWarning;
  EXPECT_EQ(overflowing->GetOutput()->GetNumberOfPoints(), 1); // the seed at t = 0
}

TEST(ConformalOrbitSource, AHugeTranslationIsCutOnTheClipSphere)
{
  // A translation's exp(t B) = 1 + t B is scaled by a power of two for its point map; the image's
  // weight is the square of its scalar times that factor, which rounded to 0 from |t| ~ 1e297:
  // every sample but the seed was dropped as if at infinity, and nothing was cut on the sphere.
  for (const double T : { 1e160, 1e300 })
  {
    vtkNew<vtkConformalOrbitSource> source;
    EventCounter events(source);
    source->SetGeneratorTypeToGeneratorList();
    source->AddGenerator(0, 0, 0, 1, 0, 0, 1.0, vtkConformalOrbitSource::TRANSLATION, 0.0);
    source->SetClosePeriodicOrbits(false);
    source->SetSeedPoint(0.5, 0.25, 0);
    source->SetTRange(0, T);
    source->SetTResolution(4);
    source->Update();
    EXPECT_EQ(events.errors + events.warnings, 0) << T << events.lastWarning;
    vtkPolyData* output = source->GetOutput();
    ASSERT_EQ(output->GetNumberOfPoints(), 2) << T; // the seed and the crossing
    EXPECT_EQ(output->GetNumberOfCells(), 1) << T;
    double p[3];
    output->GetPoint(1, p);
    EXPECT_NEAR(distance({ p[0], p[1], p[2] }, { 0, 0, 0 }), source->GetClipRadius(),
      1e-12 * source->GetClipRadius())
      << T;
    EXPECT_NEAR(p[1], 0.25, 1e-12) << T; // along the translation's direction from the seed
  }
}

// A growing dilation's samples beyond the largest double are dropped (their images' weights
// underflow); where such a sample follows one inside the clip sphere the orbit cannot be cut on
// the sphere there, and that is now a warning (it was silent). Sampled finely enough, the same
// orbit crosses the sphere within the doubles' range and is cut there without one.
TEST(ConformalOrbitSource, ADilationBeyondTheDoublesWarnsWhereItCannotBeCut)
{
  for (const int resolution : { 2, 20000 })
  {
    vtkNew<vtkConformalOrbitSource> source;
    EventCounter events(source);
    source->SetGeneratorTypeToGeneratorList();
    source->AddGenerator(0, 0, 0, 1, 0, 0, 1.0, vtkConformalOrbitSource::DILATION, 0.0);
    source->SetSeedPoint(1, 0, 0);
    source->SetTRange(-1000, 1000); // one way the seed grows beyond 1e308, the other it shrinks
    source->SetTResolution(resolution);
    source->Update();
    vtkPolyData* output = source->GetOutput();
    EXPECT_EQ(events.errors, 0) << events.lastError;
    // The largest distance from the center: on the sphere when cut, the seed's 1 when not.
    double largest = 0;
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      largest = std::max(largest, distance({ p[0], p[1], p[2] }, { 0, 0, 0 }));
    }
    if (resolution == 2)
    {
      EXPECT_EQ(events.warnings, 1);
      EXPECT_NE(events.lastWarning.find("1 samples next to the clip sphere's inside dropped"),
        std::string::npos)
        << events.lastWarning;
      EXPECT_EQ(output->GetNumberOfPoints(), 2); // the seed and its image shrunk to the center
      EXPECT_EQ(largest, 1.0);
    }
    else
    {
      EXPECT_EQ(events.warnings, 0) << events.lastWarning;
      EXPECT_NEAR(largest, source->GetClipRadius(), 1e-12 * source->GetClipRadius());
    }
  }
}

namespace
{
// A dilation about the origin (weight +1 or -1) of the seed (1, 0, 0), clip radius 10, 101
// columns from t = tMin in steps of 710 (e^710 is beyond the largest double): expects exactly one
// dropped sample next to the clip sphere's inside, warned, and no error.
void expectOneDroppedSampleWarned(double weight, double tMin)
{
  vtkNew<vtkConformalOrbitSource> source;
  EventCounter events(source);
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(0, 0, 0, 1, 0, 0, weight, vtkConformalOrbitSource::DILATION, 0.0);
  source->SetSeedPoint(1, 0, 0);
  source->SetClipRadius(10.0);
  source->SetTRange(tMin, tMin + 100 * 710.0);
  source->SetTResolution(100);
  source->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_NE(events.lastWarning.find("1 samples next to the clip sphere's inside dropped"),
    std::string::npos)
    << events.lastWarning;
}
} // namespace

// The same warning where the sample inside the sphere and the one beyond the doubles fall in two
// runs of vtkBoostedGridDriver::SampleColumns (columns 63 and 64, t = 0 and 710), so that the
// dropped sample's neighbour is a column outside its own run.
TEST(ConformalOrbitSource, ADroppedSampleLooksAtItsNeighbourInTheRunBefore)
{
  constexpr int kRun = vtkBoostedGridDriver::ColumnsPerRun;
  expectOneDroppedSampleWarned(1.0, -(kRun - 1) * 710.0); // column c at t = (c - 63) 710
}

// The mirror case: the sample beyond the doubles at column 63, the last of its run, and the one
// inside the sphere at column 64, the first of the next run (weight -1: the seed shrinks as t
// grows; column c at t = (c - 64) 710), so that the neighbour is a column of the run after.
TEST(ConformalOrbitSource, ADroppedSampleLooksAtItsNeighbourInTheRunAfter)
{
  constexpr int kRun = vtkBoostedGridDriver::ColumnsPerRun;
  expectOneDroppedSampleWarned(-1.0, -kRun * 710.0);
}

// A seed whose conformal point overflows (|p|^2 beyond the largest double) has no orbit: it was
// dropped without a word, now with a warning; the other seeds' orbits are as without it.
TEST(ConformalOrbitSource, SeedsTooFarFromTheGeneratorsWarnAndAreDropped)
{
  vtkNew<vtkConformalOrbitSource> alone, withFarSeed;
  for (vtkConformalOrbitSource* source : { alone.Get(), withFarSeed.Get() })
  {
    source->SetGeneratorTypeToGeneratorList();
    source->AddGenerator(0, 0, 0, 0, 0, 1, 1.0, vtkConformalOrbitSource::ROTATION, 0.0);
    source->SetSeedModeToSeedList();
    source->AddSeed(1, 0, 0);
  }
  withFarSeed->AddSeed(1e160, 0, 0);
  EventCounter events(withFarSeed);
  alone->Update();
  withFarSeed->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find("1 of 2 seeds are too far"), std::string::npos)
    << events.lastWarning;
  vtkPolyData* a = alone->GetOutput();
  vtkPolyData* b = withFarSeed->GetOutput();
  ASSERT_GT(a->GetNumberOfPoints(), 0);
  ASSERT_EQ(b->GetNumberOfPoints(), a->GetNumberOfPoints());
  EXPECT_EQ(b->GetNumberOfCells(), a->GetNumberOfCells());
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    EXPECT_EQ(distance({ p[0], p[1], p[2] }, { q[0], q[1], q[2] }), 0.0) << i;
  }
}

// TRange spanning nearly the whole range of doubles: t = t0 + span c / TResolution overflowed in
// span c, giving infinite t (dropped with a warning); each t is now finite and evenly spaced.
TEST(ConformalOrbitSource, ASpanNearTheLargestDoubleIsSampledEvenly)
{
  vtkNew<vtkConformalOrbitSource> source;
  EventCounter events(source);
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(0, 0, 0, 0, 0, 1, 1.0, vtkConformalOrbitSource::ROTATION, 0.0);
  source->SetClosePeriodicOrbits(false);
  source->SetSeedPoint(1, 0, 0);
  source->SetTRange(-8e307, 8e307);
  source->SetTResolution(4);
  source->Update();
  EXPECT_EQ(events.errors + events.warnings, 0) << events.lastError << events.lastWarning;
  vtkPolyData* output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 5);
  vtkDataArray* t = output->GetPointData()->GetArray("t");
  ASSERT_NE(t, nullptr);
  const double expected[5] = { -8e307, -4e307, 0.0, 4e307, 8e307 };
  for (vtkIdType i = 0; i < 5; ++i)
  {
    EXPECT_NEAR(t->GetTuple1(i), expected[i], 1e-15 * 8e307) << i;
    double p[3];
    output->GetPoint(i, p);
    EXPECT_NEAR(distance({ p[0], p[1], p[2] }, { 0, 0, 0 }), 1.0, 1e-12) << i; // on the circle
  }
}

// The line widget's row: at SelectedGeneratorLocation and aimed at SelectedGeneratorTip, it gives
// the orbits, cores and Generators port of a list whose row is written out there, with the
// direction tip - location; the list itself is unchanged.
TEST(ConformalOrbitSource, TheSelectedGeneratorIsAtTheLinesStartAndAimedAtItsEnd)
{
  const double location[3] = { 0.25, -0.5, 0.125 };
  const double tip[3] = { 0.25, 0.5, 1.125 };
  vtkNew<vtkConformalOrbitSource> selected, written;
  for (vtkConformalOrbitSource* source : { selected.Get(), written.Get() })
  {
    source->SetGeneratorTypeToGeneratorList();
    source->AddGenerator(0, 0, 0, 0, 0, 1, 1.0, vtkConformalOrbitSource::ROTATION, 0);
    source->SetTResolution(40);
  }
  selected->AddGenerator(2, 0, 0, 1, 0, 0, 0.5);
  selected->SetSelectedGenerator(1);
  selected->SetSelectedGeneratorLocation(location);
  selected->AimSelectedGeneratorOn();
  selected->SetSelectedGeneratorTip(tip);
  written->AddGenerator(location[0], location[1], location[2], tip[0] - location[0],
    tip[1] - location[1], tip[2] - location[2], 0.5);
  selected->Update();
  written->Update();
  for (int port = 0; port < 3; ++port)
  {
    auto* a = vtkPolyData::SafeDownCast(selected->GetOutputDataObject(port));
    auto* b = vtkPolyData::SafeDownCast(written->GetOutputDataObject(port));
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << "port " << port;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      a->GetPoint(i, p);
      b->GetPoint(i, q);
      EXPECT_EQ(distance({ p[0], p[1], p[2] }, { q[0], q[1], q[2] }), 0.0) << "port " << port;
    }
  }
  EXPECT_GT(selected->GetOutput()->GetNumberOfPoints(), 0);
  auto* glyphs = vtkPolyData::SafeDownCast(selected->GetOutputDataObject(2));
  ASSERT_EQ(glyphs->GetNumberOfPoints(), 2);
  vtkDataArray* direction = glyphs->GetPointData()->GetArray("Direction");
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(glyphs->GetPoint(1)[c], location[c]);
    EXPECT_EQ(direction->GetComponent(1, c), tip[c] - location[c]);
  }
  double values[9];
  ASSERT_TRUE(selected->GetGenerator(1, values));
  EXPECT_EQ(values[0], 2.0);
  EXPECT_EQ(values[3], 1.0);
}

TEST(ConformalOrbitSource, GeneratorRowsOfEveryKindAreTheFieldAtStrengthT)
{
  // exp(t B) with B = -sum w G is cga::PointPairField's boost exp(-t B(p)) without falloff (k 0,
  // eps 1), a separate code path (the field's exponential and sandwich), for rows of every kind.
  const double rows[][9] = { { 0.5, 0, 0, 0, 0.3, 0.2, 0.7, 0, 0 }, { 0, 1, 0, 0, 0, 1, 0.4, 1, 0 },
    { 1, 0, 0, 1, 1, 0, 0.3, 2, 0.5 }, { 0, 0, 1, 1, 0, 0, -0.2, 3, 0 }, { 0, 0, 0, 0, 1, 1, 0.6, 4, 0 } };
  vtkNew<vtkConformalOrbitSource> source;
  source->SetGeneratorTypeToGeneratorList();
  std::vector<cga::GeneratorParameters> generators;
  for (const auto& row : rows)
  {
    source->AddGenerator(row[0], row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8]);
    generators.push_back({ static_cast<cga::GeneratorKind>(row[7]), { row[0], row[1], row[2] },
      { row[3], row[4], row[5] }, row[8], row[6] });
  }
  source->SetSeedPoint(0.3, -0.4, 0.2);
  source->SetTRange(-1.5, 2.5);
  source->SetTResolution(40);
  source->Update();
  std::vector<cga::FieldGenerator> fieldGenerators;
  for (const auto& g : generators)
  {
    fieldGenerators.push_back(g.field());
  }
  const cga::PointPairField field(fieldGenerators.data(), fieldGenerators.size(), 0.0, 1.0);
  vtkPolyData* output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 41);
  vtkDataArray* t = output->GetPointData()->GetArray("t");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    Vec3 expected;
    ASSERT_TRUE(field.map({ 0.3, -0.4, 0.2 }, t->GetTuple1(i), cga::ExponentialRule::Exact, expected));
    double p[3];
    output->GetPoint(i, p);
    EXPECT_LE(distance({ p[0], p[1], p[2] }, expected), 1e-12) << "t " << t->GetTuple1(i);
  }
}

TEST(ConformalOrbitSource, ARotationRowTurnsRightHandedWithThePeriodTwoPiOverItsWeight)
{
  vtkNew<vtkConformalOrbitSource> source;
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(0, 0, 0, 0, 0, 2, 0.25, vtkConformalOrbitSource::ROTATION, 0); // w |d| = 0.5
  source->SetSeedPoint(1, 0, 0.5);
  source->SetTResolution(8);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_NEAR(period(output), 4.0 * 3.14159265358979323846, 1e-12);
  bool closed = false;
  const auto lines = polylines(output, &closed);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(closed);
  ASSERT_EQ(lines[0].size(), 8u);
  // An eighth of the period: 45 degrees counter-clockwise about +z.
  EXPECT_LE(distance(lines[0][1], { std::sqrt(0.5), std::sqrt(0.5), 0.5 }), 1e-14);
  // Its core is the z axis, cut at the clip sphere.
  vtkPolyData* cores = vtkPolyData::SafeDownCast(source->GetOutputDataObject(1));
  ASSERT_GT(cores->GetNumberOfPoints(), 0);
  for (vtkIdType i = 0; i < cores->GetNumberOfPoints(); ++i)
  {
    double p[3];
    cores->GetPoint(i, p);
    EXPECT_LE(std::hypot(p[0], p[1]), 1e-12);
    EXPECT_LE(std::fabs(p[2]), 100.0 * (1.0 + 1e-12));
  }
  EXPECT_NEAR(cores->GetBounds()[5], 100.0, 1e-9);
  // Oriented along +z, the axis the row turns about right-handed: the polyline runs upwards.
  double first[3], last[3];
  cores->GetPoint(0, first);
  cores->GetPoint(cores->GetNumberOfPoints() - 1, last);
  EXPECT_LT(first[2], last[2]);
}

TEST(ConformalOrbitSource, OrbitsThroughInfinityAreCutExactlyAtTheClipSphere)
{
  // The transversion by -t e1 sends e1/t to infinity: the seed on the x axis at 0.5 goes there at
  // t = 2, so the orbit over [0, 4] leaves the sphere and comes back.
  vtkNew<vtkConformalOrbitSource> source;
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(0, 0, 0, 1, 0, 0, 1);
  source->SetSeedModeToSeedList();
  source->AddSeed(0.5, 0, 0);
  source->AddSeed(0.5, 0.2, 0);
  source->SetTRange(0, 4);
  source->SetTResolution(400);
  source->SetClipRadius(5);
  source->Update();
  const double center[3] = { 0, 0, 0 };
  vtkDataArray* t = source->GetOutput()->GetPointData()->GetArray("t");
  ExpectCutExactlyAtTheSphere(source->GetOutput(), center, 5.0,
    [t](vtkIdType i) { return t->GetTuple1(i) == 0.0 || t->GetTuple1(i) == 4.0; }, 2, "orbits");
}

TEST(ConformalOrbitSource, SeedsFromTheInputAndPieces)
{
  vtkNew<vtkPolyData> seeds;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 5; ++i)
  {
    points->InsertNextPoint(0.1 * i, 0.05, -0.1 * i);
  }
  seeds->SetPoints(points);
  vtkNew<vtkConformalOrbitSource> whole;
  whole->SetInputData(seeds);
  whole->SetSeedModeToInputPoints();
  whole->SetTResolution(64);
  whole->Update();
  ASSERT_EQ(polylines(whole->GetOutput()).size(), 5u);
  EXPECT_EQ(whole->GetOutput()->GetNumberOfPoints(), 5 * 64);
  // Two pieces: each orbit whole on one of them, together the whole output.
  vtkIdType total = 0;
  std::map<int, int> orbitsSeen;
  for (int piece = 0; piece < 2; ++piece)
  {
    vtkNew<vtkConformalOrbitSource> part;
    part->SetInputData(seeds);
    part->SetSeedModeToInputPoints();
    part->SetTResolution(64);
    part->UpdatePiece(piece, 2, 0);
    vtkPolyData* output = part->GetOutput();
    total += output->GetNumberOfPoints();
    vtkDataArray* ids = output->GetPointData()->GetArray("OrbitId");
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      orbitsSeen[static_cast<int>(ids->GetTuple1(i))] |= 1 << piece;
    }
    const vtkIdType cores = vtkPolyData::SafeDownCast(part->GetOutputDataObject(1))->GetNumberOfPoints();
    EXPECT_EQ(cores > 0, piece == 0);
  }
  EXPECT_EQ(total, whole->GetOutput()->GetNumberOfPoints());
  EXPECT_EQ(orbitsSeen.size(), 5u);
  for (const auto& seen : orbitsSeen)
  {
    EXPECT_TRUE(seen.second == 1 || seen.second == 2) << "orbit " << seen.first;
  }
  ExpectOutOfRangePiecesEmpty<vtkConformalOrbitSource>([](vtkConformalOrbitSource*) {});
}

TEST(ConformalOrbitSource, DirectionsOfAnyLength)
{
  ExpectTheSamePointsAtEveryDirectionLength<vtkConformalOrbitSource>(
    [](vtkConformalOrbitSource* source, double length) {
      source->SetKnotNormal(0, 0.6 * length, 0.8 * length);
      source->SetKnotDirection(length, 0, 0);
    });
}

TEST(ConformalOrbitSource, DegenerateGeneratorsWarn)
{
  // B = 0 (no generators, or only a zero weight): the identity, each orbit its seed.
  vtkNew<vtkConformalOrbitSource> identity;
  EventCounter events(identity);
  identity->SetGeneratorTypeToGeneratorList();
  identity->AddGenerator(0, 0, 0, 1, 0, 0, 0);
  identity->SetSeedPoint(1, 2, 3);
  identity->Update();
  EXPECT_EQ(events.errors, 0);
  EXPECT_EQ(events.warnings, 2); // the zero weight, and B = 0
  vtkPolyData* output = identity->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 1);
  EXPECT_EQ(output->GetNumberOfVerts(), 1);
  double p[3];
  output->GetPoint(0, p);
  EXPECT_EQ(p[0], 1.0);
  EXPECT_EQ(p[2], 3.0);
  // The identity's seeds are still cut by the clip sphere, so a bad one is the same error as with
  // any B: the warnings, then one error and an empty output.
  identity->SetClipRadius(std::numeric_limits<double>::quiet_NaN());
  identity->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("ClipRadius must be a positive number"), std::string::npos)
    << events.lastError;
  EXPECT_EQ(identity->GetOutput()->GetNumberOfPoints(), 0);

  // P and Q not coprime: one warning, the reduced knot's period.
  vtkNew<vtkConformalOrbitSource> multiple;
  EventCounter multipleEvents(multiple);
  multiple->SetKnotP(4);
  multiple->SetKnotQ(6);
  multiple->Update();
  EXPECT_EQ(multipleEvents.warnings, 1);
  EXPECT_NE(multipleEvents.lastWarning.find("not coprime"), std::string::npos);
  EXPECT_NEAR(period(multiple->GetOutput()), 12.0, 1e-13);

  // P = Q = 1: equal invariants, the Hopf link's fibers; period 1.
  vtkNew<vtkConformalOrbitSource> hopf;
  hopf->SetKnotP(1);
  hopf->SetKnotQ(1);
  hopf->Update();
  EXPECT_NEAR(period(hopf->GetOutput()), 1.0, 1e-15);
  EXPECT_EQ(polylines(hopf->GetOutput()).size(), 1u);
}

TEST(ConformalOrbitSource, BadParametersGiveOneErrorAndEmptyOutputs)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  using S = vtkConformalOrbitSource;
  ExpectOneErrorEach<S>(
    {
      [](S* s) { s->SetKnotP(0); },
      [](S* s) { s->SetKnotQ(-4); },
      [](S* s) { s->SetKnotNormal(0, 0, 0); },
      [](S* s) { s->SetKnotDirection(0, 0, 0); },
      [](S* s) { s->SetKnotDirection(0, 0, -3); },
      [](S* s) { s->SetKnotRadius(0); },
      [](S* s) { s->SetKnotRadius(-1); },
      [=](S* s) { s->SetKnotCenter(nan, 0, 0); },
      [=](S* s) { s->SetKnotNormal(0, inf, 1); },
      [](S* s) { s->SetTRange(1, 0); },
      [=](S* s) { s->SetTRange(nan, 1); },
      [=](S* s) {
        s->ClosePeriodicOrbitsOff();
        s->SetTRange(-1e308, 1e308);
      },
      [=](S* s) {
        s->SetGeneratorTypeToGeneratorList();
        s->AddGenerator(0, 0, 0, 1, nan, 0, 1);
      },
      [](S* s) {
        s->SetGeneratorTypeToGeneratorList();
        s->AddGenerator(0, 0, 0, 1, 0, 0, 1e200);
      },
      [](S* s) {
        s->SetGeneratorTypeToGeneratorList();
        s->AddGenerator(0, 0, 0, 1, 0, 0, 1, 7, 0); // no such kind
      },
      [=](S* s) {
        s->SetGeneratorTypeToGeneratorList();
        s->AddGenerator(0, 0, 0, 1, 0, 0, 1);
        s->SetSelectedGenerator(0);
        s->SetSelectedGeneratorLocation(0, nan, 0);
      },
      [=](S* s) {
        s->SetGeneratorTypeToGeneratorList();
        s->AddGenerator(0, 0, 0, 1, 0, 0, 1);
        s->SetSelectedGenerator(0);
        s->AimSelectedGeneratorOn();
        s->SetSelectedGeneratorTip(inf, 0, 0);
      },
      [=](S* s) { s->SetSeedPoint(0, nan, 0); },
      [=](S* s) {
        s->SetSeedModeToSeedList();
        s->AddSeed(0, 0, inf);
      },
      [](S* s) { s->SetSeedModeToInputPoints(); },
      [=](S* s) { s->SetClipRadius(nan); },
      [=](S* s) { s->SetClipCenter(0, inf, 0); },
      [](S* s) {
        s->SetSeedModeToSeedList();
        s->SetNumberOfSeeds(1000);
        s->SetTResolution(1000000); // beyond 10^8 samples
      },
    },
    EmptyOutput::NoPointsNoCells);
  // A seed list refused at 2 10^6 rows (one error then): every update one error more.
  {
    vtkNew<S> refused;
    refused->SetSeedModeToSeedList();
    refused->SetNumberOfSeeds(2000000);
    EventCounter events(refused);
    refused->Update();
    EXPECT_EQ(events.errors, 1);
    EXPECT_EQ(refused->GetOutput()->GetNumberOfPoints(), 0);
  }
  // The cores output stays empty too.
  vtkNew<S> source;
  EventCounter events(source);
  source->SetKnotRadius(0);
  source->Update();
  EXPECT_EQ(vtkPolyData::SafeDownCast(source->GetOutputDataObject(1))->GetNumberOfPoints(), 0);
}
} // namespace

TEST(ConformalOrbitSource, APeriodicOrbitSweptInTimeClosesOnlyAtThePeriod)
{
  // The default trefoil, animated: at time s < 1 the orbit is the open arc over [0, s T], from
  // the seed; at s = 1 it is the closed orbit of the static output.
  vtkNew<vtkConformalOrbitSource> source;
  source->SetTResolution(60);
  source->SetNumberOfTimeSteps(5);
  source->Update();
  const double T = period(source->GetOutput());
  ASSERT_GT(T, 0.0);
  for (const double s : { 0.25, 0.5, 0.75, 0.99, 1.0 })
  {
    source->UpdateTimeStep(s);
    vtkPolyData* output = source->GetOutput();
    bool closed = false;
    const auto lines = polylines(output, &closed);
    ASSERT_EQ(lines.size(), 1u) << "s " << s;
    EXPECT_EQ(closed, s == 1.0) << "s " << s;
    ASSERT_EQ(lines[0].size(), s == 1.0 ? 60u : 61u) << "s " << s;
    EXPECT_LE(distance(lines[0].front(), { 0.15, 0, 0 }), 1e-15) << "starts at the seed, s " << s;
    vtkDataArray* t = output->GetPointData()->GetArray("t");
    double range[2];
    t->GetRange(range);
    EXPECT_EQ(range[0], 0.0);
    EXPECT_DOUBLE_EQ(range[1], s == 1.0 ? T * 59 / 60 : s * T) << "s " << s;
    // The open arc does not come back to the seed before the period.
    if (s < 1.0)
    {
      EXPECT_GT(distance(lines[0].back(), lines[0].front()), 1e-3) << "s " << s;
    }
    EXPECT_EQ(period(output), T) << "the period of B, whatever the time";
    EXPECT_GT(vtkPolyData::SafeDownCast(source->GetOutputDataObject(1))->GetNumberOfPoints(), 0);
  }
}

TEST(ConformalOrbitSource, MovingEverythingByTMovesTheOrbitsAndCoresByT)
{
  // Rows of several kinds away from the origin, seeds around them, the clip sphere with them. The
  // bound: TranslationChecks.h. Built in place, B holds |t|^2 and the error grows like eps |t|^2.
  for (const int port : { 0, 1 })
  {
    ExpectTranslationCovariant([port](const double t[3]) {
      vtkNew<vtkConformalOrbitSource> source;
      source->SetGeneratorTypeToGeneratorList();
      source->AddGenerator(0.5 + t[0], 0.1 + t[1], -0.2 + t[2], 0.2, 0.1, 1, 0.9, 1, 0);
      source->AddGenerator(-0.3 + t[0], 0.4 + t[1], 0.1 + t[2], 1, 1, 0.2, 0.4, 2, 0.3);
      source->AddGenerator(0.2 + t[0], -0.3 + t[1], 0.3 + t[2], 0, 0.3, 0.2, 0.5);
      source->SetSeedModeToSeedList();
      source->AddSeed(0.3 + t[0], -0.4 + t[1], 0.2 + t[2]);
      source->AddSeed(-0.6 + t[0], 0.2 + t[1], 0.5 + t[2]);
      source->SetTRange(-1.0, 1.5);
      source->SetTResolution(48);
      source->SetClipCenter(t);
      source->SetClipRadius(1e3);
      source->Update();
      return vtkSmartPointer<vtkDataSet>(vtkPolyData::SafeDownCast(source->GetOutputDataObject(port)));
    });
    // The (3, 5) knot: its circles about KnotCenter, a seed on a torus about each circle.
    ExpectTranslationCovariant([port](const double t[3]) {
      vtkNew<vtkConformalOrbitSource> source;
      source->SetKnotP(3);
      source->SetKnotQ(5);
      source->SetKnotCenter(0.2 + t[0], -0.1 + t[1], 0.3 + t[2]);
      source->SetKnotNormal(0.2, 0.1, 1);
      source->SetKnotDirection(1, 0.3, 0);
      source->SetKnotRadius(0.7);
      source->SetSeedModeToSeedList();
      source->AddSeed(0.2 - 0.45 + t[0], -0.1 + t[1], 0.3 + t[2]);
      source->AddSeed(0.2 + 0.45 + t[0], -0.1 + t[1], 0.3 + t[2]);
      source->SetTResolution(120);
      source->SetCoreResolution(32);
      source->SetClipCenter(t);
      source->SetClipRadius(1e3);
      source->Update();
      return vtkSmartPointer<vtkDataSet>(vtkPolyData::SafeDownCast(source->GetOutputDataObject(port)));
    });
  }
}

TEST(ConformalOrbitSource, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  // The orbits: a rotation about the z axis of a seed at 1e39, over angles that keep it inside
  // the clip sphere about the seed.
  ExpectSinglePrecisionBeyondTheLargestFloatIsAnError<vtkConformalOrbitSource>(
    [](vtkConformalOrbitSource* source) {
      source->SetGeneratorTypeToGeneratorList();
      source->AddGenerator(0, 0, 0, 0, 0, 1, 1, vtkConformalOrbitSource::ROTATION, 0);
      source->SetSeedPoint(1e39, 0, 0);
      source->SetClosePeriodicOrbits(false);
      source->SetClipCenter(1e39, 0, 0);
      source->SetClipRadius(1e12);
      source->SetTRange(0, 1e-28);
      source->SetTResolution(4);
    },
    1e39);
  // The identity's vertices: B = 0 and a seed at 1e39.
  ExpectSinglePrecisionBeyondTheLargestFloatIsAnError<vtkConformalOrbitSource>(
    [](vtkConformalOrbitSource* source) {
      source->SetGeneratorTypeToGeneratorList();
      source->SetSeedPoint(-1e39, 0, 0);
      source->SetClipCenter(-1e39, 0, 0);
    },
    1e39);
  // The cores alone: a rotation axis through 1e39 inside the clip sphere there, and an orbit
  // about it of radius 1e39 that stays outside (empty without an error): both outputs empty.
  vtkNew<vtkConformalOrbitSource> source;
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(1e39, 0, 0, 0, 0, 1, 1, vtkConformalOrbitSource::ROTATION, 0);
  source->SetSeedPoint(0, 0, 0);
  source->SetClosePeriodicOrbits(false);
  source->SetTRange(0.5, 1.0);
  source->SetClipCenter(1e39, 0, 0);
  source->SetClipRadius(1e12);
  EventCounter events(source);
  source->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  auto cores = [&] { return vtkPolyData::SafeDownCast(source->GetOutputDataObject(1)); };
  ASSERT_GT(cores()->GetNumberOfPoints(), 0);
  EXPECT_GT(LargestCoordinate(cores()), 3.5e38);
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("vtkConformalOrbitSource"), std::string::npos) << events.lastError;
  EXPECT_NE(events.lastError.find("OutputPointsPrecision"), std::string::npos) << events.lastError;
  EXPECT_EQ(cores()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  // Within the float range single precision gives floats on both outputs.
  source->SetClipCenter(0, 0, 0);
  source->SetClipRadius(100);
  source->SetGenerator(0, 1, 0, 0, 0, 0, 1, 1, vtkConformalOrbitSource::ROTATION, 0);
  source->Update();
  EXPECT_EQ(events.errors, 1) << events.lastError;
  ASSERT_GT(source->GetOutput()->GetNumberOfPoints(), 0);
  ASSERT_GT(cores()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(cores()->GetPoints()->GetDataType(), VTK_FLOAT);
}

TEST(ConformalOrbitSource, ReportsProgressAndAnAbortedUpdateIsEmpty)
{
  for (bool abort : { false, true })
  {
    // One seed, 262,144 t columns: 4 blocks of 65,536 columns (vtkBoostedBlockLoop: 65,536
    // samples a block; vtkBoostedGridDriver::SampleColumns counts a column as its rows' samples).
    vtkNew<vtkConformalOrbitSource> source;
    source->SetTResolution(4 * 65536 - 1);
    ProgressLog log;
    log.abortAfterFirstStep = abort; // after the first block
    log.Observe(source);
    source->Update();
    vtkPolyData* orbits = source->GetOutput(0);
    if (!abort)
    {
      EXPECT_EQ(log.Steps().size(), 4u + 1); // and the executive's 1 at the end
      EXPECT_EQ(orbits->GetNumberOfPoints(), 4 * 65536 - 1); // the last t closes the orbit
    }
    else
    {
      EXPECT_LT(log.Steps().size(), 4u);
      EXPECT_EQ(orbits->GetNumberOfPoints(), 0);
      EXPECT_EQ(orbits->GetNumberOfCells(), 0);
    }
  }
}

TEST(ConformalOrbitSource, TheGeneratorsOutputIsBuiltAnewOnlyWhenTheGeneratorsChange)
{
  // The orbits' sampling changes the orbits, not the generators: the torus knot's core circles,
  // then the list's rows.
  ExpectGeneratorGlyphsCached(2, [] { return vtkSmartPointer<vtkConformalOrbitSource>::New(); },
    [](vtkConformalOrbitSource* source) { source->SetTResolution(33); },
    [](vtkConformalOrbitSource* source) { source->SetKnotRadius(1.5); });
  ExpectGeneratorGlyphsCached(2,
    [] {
      auto source = vtkSmartPointer<vtkConformalOrbitSource>::New();
      source->SetGeneratorTypeToGeneratorList();
      source->AddGenerator(0, 0, 0, 0, 0, 1, 1.0, vtkConformalOrbitSource::ROTATION, 0);
      source->AddGenerator(0.5, 0, 0, 1, 0, 0, 0.25);
      return source;
    },
    [](vtkConformalOrbitSource* source) {
      source->SetTResolution(33);
      source->SetSeedPoint(0.5, 0.5, 0.25);
    },
    [](vtkConformalOrbitSource* source) {
      source->SetGenerator(1, 0.5, 0, 0, 1, 0, 0, 0.5);
    });
}
