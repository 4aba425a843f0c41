// vtkHopfFibrationSource: the three ways of sampling the base sphere, the fibers against the kernel
// (cga::HopfFibration, itself tested against the full product) and against plain geometry
// (circles, the poles, the clip radius), the twistor mesh, pieces, and bad input.
#include "vtkHopfFibrationSource.h"

#include "BadParameterCases.h"
#include "GeneratorGlyphCacheChecks.h"
#include "GridSourceChecks.h"
#include "ProgressLog.h"
#include "TestSupport.h"
#include "TranslationChecks.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "cga/surfaces/HopfFibration.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace
{
using cgatest::worseOf;

constexpr double kPi = 3.14159265358979323846;

using Point = std::array<double, 3>;

// Points of the output grouped by FiberId.
std::map<int, std::vector<Point>> pointsByFiber(vtkPolyData* output)
{
  std::map<int, std::vector<Point>> fibers;
  vtkDataArray* ids = output->GetPointData()->GetArray("FiberId");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    Point p;
    output->GetPoint(i, p.data());
    fibers[static_cast<int>(ids->GetTuple1(i))].push_back(p);
  }
  return fibers;
}

// Largest distance of the points from the circle through three of them, relative to its radius.
double cocircularity(const std::vector<Point>& points)
{
  const size_t n = points.size();
  double a[3], u[3], v[3], w[3];
  std::copy(points[0].begin(), points[0].end(), a);
  vtkMath::Subtract(points[n / 3].data(), a, u);
  vtkMath::Subtract(points[(2 * n) / 3].data(), a, v);
  vtkMath::Cross(u, v, w);
  double vw[3], wu[3], center[3];
  vtkMath::Cross(v, w, vw);
  vtkMath::Cross(w, u, wu);
  const double scale = 1.0 / (2.0 * vtkMath::Dot(w, w));
  for (int i = 0; i < 3; ++i)
  {
    center[i] = a[i] + scale * (vtkMath::Dot(u, u) * vw[i] + vtkMath::Dot(v, v) * wu[i]);
  }
  const double radius = std::sqrt(vtkMath::Distance2BetweenPoints(a, center));
  vtkMath::Normalize(w);
  double worst = 0.0;
  for (const Point& p : points)
  {
    double d[3];
    vtkMath::Subtract(p.data(), center, d);
    const double height = vtkMath::Dot(d, w);
    const double inPlane = std::sqrt(std::max(0.0, vtkMath::Dot(d, d) - height * height));
    worst = worseOf(worst, worseOf(std::fabs(height) / radius, std::fabs(inPlane - radius) / radius));
  }
  return worst;
}

TEST(HopfFibrationSource, DefaultsGiveClosedCircleFibersOverTheGrid)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->Update();
  vtkPolyData* output = source->GetOutput();
  const auto fibers = pointsByFiber(output);
  EXPECT_EQ(fibers.size(), 8u * 9u);
  ASSERT_NE(output->GetPointData()->GetArray("theta"), nullptr);
  ASSERT_NE(output->GetPointData()->GetArray("phi"), nullptr);
  int closed = 0;
  vtkCellArray* lines = output->GetLines();
  vtkIdType npts;
  const vtkIdType* ids;
  for (lines->InitTraversal(); lines->GetNextCell(npts, ids);)
  {
    closed += (npts == 129 && ids[0] == ids[npts - 1]) ? 1 : 0;
  }
  // Every fiber but the 8 north-pole ones (the axis line, clipped) is a whole closed circle.
  EXPECT_EQ(closed, 8 * 8);
  for (const auto& fiber : fibers)
  {
    if (fiber.second.size() == 128)
    {
      EXPECT_LE(cocircularity(fiber.second), 1e-9) << "fiber " << fiber.first;
    }
  }
  // Nothing beyond the clip radius (10 times the circle radius).
  double bounds[6];
  output->GetBounds(bounds);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_LE(std::fabs(bounds[i]), 10.0 + 1e-12);
  }
}

TEST(HopfFibrationSource, FibersMatchTheKernelInAnyFrame)
{
  for (int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    vtkNew<vtkHopfFibrationSource> source;
    source->SetMode(mode);
    source->SetCircleCenter(1.0, -2.0, 0.5);
    source->SetCircleNormal(1.0, 1.0, 0.0);
    source->SetCircleRadius(2.0);
    source->SetSamplingModeToBasePoints();
    source->AddBasePoint(0.3, -0.7);
    source->AddBasePoint(2.0, 0.2);
    source->AddBasePoint(-1.0, 1.0);
    source->SetFiberResolution(16);
    source->SetClipRadius(20.0); // about the circle's center: no fiber is cut
    source->Update();
    cga::HopfFibration hopf;
    hopf.center = { 1.0, -2.0, 0.5 };
    hopf.normal = { 1.0, 1.0, 0.0 };
    hopf.radius = 2.0;
    hopf.mode = mode == vtkHopfFibrationSource::CLASSICAL ? cga::HopfMode::Classical
                                                          : cga::HopfMode::Paper;
    const auto fibers = pointsByFiber(source->GetOutput());
    ASSERT_EQ(fibers.size(), 3u);
    const double base[3][2] = { { 0.3, -0.7 }, { 2.0, 0.2 }, { -1.0, 1.0 } };
    for (int f = 0; f < 3; ++f)
    {
      std::vector<cga::Vec3> expected;
      ASSERT_TRUE(hopf.fiberPoints(base[f][0], base[f][1], 16, expected));
      const std::vector<Point>& got = fibers.at(f);
      ASSERT_EQ(got.size(), 16u);
      for (int j = 0; j < 16; ++j)
      {
        EXPECT_NEAR(got[j][0], expected[j].x, 1e-12);
        EXPECT_NEAR(got[j][1], expected[j].y, 1e-12);
        EXPECT_NEAR(got[j][2], expected[j].z, 1e-12);
      }
      EXPECT_LE(cocircularity(got), 1e-9);
    }
  }
}

TEST(HopfFibrationSource, PolesGiveTheCircleAndTheAxis)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->SetCircleCenter(0.0, 0.0, 1.0);
  source->SetCircleRadius(0.5);
  source->SetThetaResolution(5);
  source->SetPhiResolution(2); // the two poles
  source->Update();
  vtkPolyData* output = source->GetOutput();
  vtkDataArray* phi = output->GetPointData()->GetArray("phi");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    if (phi->GetTuple1(i) < 0.0)
    {
      EXPECT_NEAR(p[2], 1.0, 1e-12);
      EXPECT_NEAR(std::hypot(p[0], p[1]), 0.5, 1e-12);
    }
    else
    {
      EXPECT_NEAR(std::hypot(p[0], p[1]), 0.0, 1e-12);
      EXPECT_LE(std::fabs(p[2] - 1.0), 10.0 + 1e-12); // the clip sphere: radius 10 about the center
    }
  }
}

TEST(HopfFibrationSource, GridSamplesMeridiansLatitudesAndBands)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->SetFiberResolution(8);
  source->SetThetaRange(1.0, 1.0);
  source->SetThetaResolution(1); // one meridian
  source->SetPhiRange(-kPi / 2, 0.0);
  source->SetPhiResolution(5);
  source->Update();
  auto fibers = pointsByFiber(source->GetOutput());
  ASSERT_EQ(fibers.size(), 5u);
  vtkDataArray* theta = source->GetOutput()->GetPointData()->GetArray("theta");
  vtkDataArray* phi = source->GetOutput()->GetPointData()->GetArray("phi");
  std::set<double> phis;
  for (vtkIdType i = 0; i < source->GetOutput()->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(theta->GetTuple1(i), 1.0);
    phis.insert(phi->GetTuple1(i));
  }
  EXPECT_EQ(phis, (std::set<double>{ -kPi / 2, -3 * kPi / 8, -kPi / 4, -kPi / 8, 0.0 }));

  // A latitude: theta half-open over the full turn.
  source->SetThetaRange(0.0, 2 * kPi);
  source->SetThetaResolution(4);
  source->SetPhiRange(0.25, 0.25);
  source->SetPhiResolution(1);
  source->Update();
  std::set<double> thetas;
  theta = source->GetOutput()->GetPointData()->GetArray("theta");
  for (vtkIdType i = 0; i < source->GetOutput()->GetNumberOfPoints(); ++i)
  {
    thetas.insert(theta->GetTuple1(i));
  }
  EXPECT_EQ(thetas, (std::set<double>{ 0.0, kPi / 2, kPi, 3 * kPi / 2 }));
}

TEST(HopfFibrationSource, InputPointsGiveTheirDirectionsFromTheSphereCenter)
{
  // Points on a sphere of radius 3 about (1, 1, 1) at known (theta, phi).
  const double base[4][2] = { { 0.0, 0.0 }, { 1.2, -0.4 }, { -2.5, 0.9 }, { 3.0, -1.3 } };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& b : base)
  {
    points->InsertNextPoint(1.0 + 3.0 * std::cos(b[1]) * std::cos(b[0]),
      1.0 + 3.0 * std::cos(b[1]) * std::sin(b[0]), 1.0 + 3.0 * std::sin(b[1]));
  }
  vtkNew<vtkPolyData> sphere;
  sphere->SetPoints(points);

  vtkNew<vtkHopfFibrationSource> fromInput;
  fromInput->SetInputData(sphere);
  fromInput->SetSamplingModeToInputPoints();
  fromInput->SetSphereCenter(1.0, 1.0, 1.0);
  fromInput->SetFiberResolution(12);
  fromInput->Update();
  vtkNew<vtkHopfFibrationSource> fromList;
  fromList->SetSamplingModeToBasePoints();
  for (const auto& b : base)
  {
    fromList->AddBasePoint(b[0], b[1]);
  }
  fromList->SetFiberResolution(12);
  fromList->Update();
  vtkPolyData* a = fromInput->GetOutput();
  vtkPolyData* b = fromList->GetOutput();
  ASSERT_EQ(a->GetNumberOfPoints(), 4 * 12);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    EXPECT_LE(std::sqrt(vtkMath::Distance2BetweenPoints(p, q)), 1e-12);
    EXPECT_NEAR(a->GetPointData()->GetArray("theta")->GetTuple1(i),
      b->GetPointData()->GetArray("theta")->GetTuple1(i), 1e-14);
    EXPECT_NEAR(a->GetPointData()->GetArray("phi")->GetTuple1(i),
      b->GetPointData()->GetArray("phi")->GetTuple1(i), 1e-14);
  }
}

TEST(HopfFibrationSource, TwistorMeshIsOneStripPerMeridianWithUnitNormals)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->SetOutputTypeToTwistorMesh();
  source->SetThetaResolution(3);
  source->SetPhiRange(-kPi / 2, 1.0); // stay clear of the clipped north pole
  source->SetPhiResolution(6);
  source->SetFiberResolution(20);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPolys(), 3 * 5 * 20);
  vtkDataArray* strips = output->GetPointData()->GetArray("StripId");
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  ASSERT_NE(strips, nullptr);
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(output->GetPointData()->GetTCoords(), nullptr);
  vtkCellArray* polys = output->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    ASSERT_EQ(npts, 4);
    for (int k = 1; k < 4; ++k)
    {
      EXPECT_EQ(strips->GetTuple1(ids[k]), strips->GetTuple1(ids[0])); // no quad joins strips
    }
  }
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(vtkMath::Norm(normals->GetTuple3(i)), 1.0, 1e-6);
  }

  // Latitudes: one closed strip per phi sample (theta0 .. theta1 inclusive).
  source->SetMeshSweepToLatitudes();
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPolys(), 6 * 3 * 20);
}

TEST(HopfFibrationSource, TwistorMeshesAreContinuousAlongTheBaseSphere)
{
  // A fiber's sample t moves continuously with (theta, phi): on a fine grid the quads' edges
  // across fibers stay comparable to the edges along them (a jump of the motor logarithm's branch
  // would tear the strip).
  for (int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    for (int sweep : { vtkHopfFibrationSource::MERIDIANS, vtkHopfFibrationSource::LATITUDES })
    {
      vtkNew<vtkHopfFibrationSource> source;
      source->SetMode(mode);
      source->SetOutputTypeToTwistorMesh();
      source->SetMeshSweep(sweep);
      source->SetThetaResolution(48);
      source->SetPhiRange(-1.5, 1.2);
      source->SetPhiResolution(48);
      source->SetFiberResolution(48);
      source->SetClipRadius(1e5);
      source->Update();
      vtkPolyData* output = source->GetOutput();
      ASSERT_GT(output->GetNumberOfPolys(), 0);
      double worst = 0.0;
      vtkCellArray* polys = output->GetPolys();
      vtkIdType npts;
      const vtkIdType* ids;
      for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
      {
        double p0[3], p1[3], p3[3];
        output->GetPoint(ids[0], p0);
        output->GetPoint(ids[1], p1);
        output->GetPoint(ids[3], p3);
        worst = worseOf(worst,
          std::sqrt(vtkMath::Distance2BetweenPoints(p0, p3) / vtkMath::Distance2BetweenPoints(p0, p1)));
      }
      EXPECT_LT(worst, 3.0) << "mode " << mode << " sweep " << sweep;
    }
  }
}

TEST(HopfFibrationSource, PiecesPartitionTheFibersAndTheQuads)
{
  for (int type : { vtkHopfFibrationSource::FIBERS, vtkHopfFibrationSource::TWISTOR_MESH })
  {
    vtkNew<vtkHopfFibrationSource> whole;
    whole->SetOutputType(type);
    whole->SetFiberResolution(16);
    whole->Update();
    const vtkIdType wholeCells = whole->GetOutput()->GetNumberOfCells();
    const vtkIdType wholePoints = whole->GetOutput()->GetNumberOfPoints();
    EXPECT_GT(wholeCells, 0);
    for (int pieces : { 2, 3, 7, 100 })
    {
      vtkIdType cells = 0, points = 0;
      std::set<int> fiberIds;
      for (int piece = 0; piece < pieces; ++piece)
      {
        vtkNew<vtkHopfFibrationSource> part;
        part->SetOutputType(type);
        part->SetFiberResolution(16);
        part->UpdatePiece(piece, pieces, 0);
        cells += part->GetOutput()->GetNumberOfCells();
        points += part->GetOutput()->GetNumberOfPoints();
        if (type == vtkHopfFibrationSource::FIBERS)
        {
          for (const auto& fiber : pointsByFiber(part->GetOutput()))
          {
            EXPECT_TRUE(fiberIds.insert(fiber.first).second) << "fiber in two pieces";
          }
        }
      }
      EXPECT_EQ(cells, wholeCells) << pieces << " pieces";
      if (type == vtkHopfFibrationSource::FIBERS)
      {
        EXPECT_EQ(points, wholePoints); // fibers are partitioned exactly
        EXPECT_EQ(fiberIds.size(), 72u);
      }
      else
      {
        EXPECT_GE(points, wholePoints); // bands repeat their shared row
      }
    }
  }
}

TEST(HopfFibrationSource, BadInputGivesAnErrorAndAnEmptyOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkPolyData> nanPoints;
  vtkNew<vtkPoints> p;
  p->InsertNextPoint(nan, 0.0, 1.0);
  nanPoints->SetPoints(p);
  std::vector<std::function<void(vtkHopfFibrationSource*)>> breakers = {
    [](vtkHopfFibrationSource* s) { s->SetThetaResolution(0); },
    [](vtkHopfFibrationSource* s) { s->SetPhiResolution(0); },
    [](vtkHopfFibrationSource* s) { s->SetFiberResolution(0); },
    [](vtkHopfFibrationSource* s) { s->SetThetaRange(1.0, 0.0); },
    [](vtkHopfFibrationSource* s) { s->SetPhiRange(0.5, -0.5); },
    [](vtkHopfFibrationSource* s) { s->SetPhiRange(-2.0, 0.0); },
    [](vtkHopfFibrationSource* s) { s->SetCircleRadius(0.0); },
    [](vtkHopfFibrationSource* s) { s->SetCircleNormal(0.0, 0.0, 0.0); },
    [nan](vtkHopfFibrationSource* s) { s->SetCircleCenter(nan, 0.0, 0.0); },
    [nan](vtkHopfFibrationSource* s) { s->SetThetaRange(0.0, nan); },
    [nan](vtkHopfFibrationSource* s) {
      s->SetSamplingModeToBasePoints();
      s->AddBasePoint(nan, 0.0);
    },
    [](vtkHopfFibrationSource* s) {
      s->SetSamplingModeToBasePoints();
      s->AddBasePoint(0.0, 2.0);
    },
    [](vtkHopfFibrationSource* s) { s->SetSamplingModeToInputPoints(); },
    [&nanPoints](vtkHopfFibrationSource* s) {
      s->SetSamplingModeToInputPoints();
      s->SetInputData(nanPoints);
    },
    [nan](vtkHopfFibrationSource* s) { s->SetClipRadius(nan); },
    // 1e10 fibers, and 1e6 fibers of 1e6 points: refused before anything is allocated
    [](vtkHopfFibrationSource* s) {
      s->SetThetaResolution(100000);
      s->SetPhiResolution(100000);
    },
    [](vtkHopfFibrationSource* s) {
      s->SetThetaResolution(1000);
      s->SetPhiResolution(1000);
      s->SetFiberResolution(1000000);
    },
  };
  ExpectOneErrorEach(breakers, EmptyOutput::NoPointsNoCells);
}

TEST(HopfFibrationSource, SinglePrecisionPoints)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
}
// Distance from the clip sphere, relative to its radius (negative inside).
TEST(HopfFibrationSource, ClippedOutputEndsExactlyOnTheClipSphere)
{
  const double center[3] = { 0.3, -0.2, 0.1 };
  const double circleRadius = 1.3, sphereRadius = 3.25;
  const double phiRange[2] = { -1.2, kPi / 2 };
  for (int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    for (int type : { vtkHopfFibrationSource::FIBERS, vtkHopfFibrationSource::TWISTOR_MESH })
    {
      vtkNew<vtkHopfFibrationSource> source;
      source->SetMode(mode);
      source->SetOutputType(type);
      source->SetCircleCenter(center[0], center[1], center[2]);
      source->SetCircleNormal(0.2, -0.4, 1.0);
      source->SetCircleRadius(circleRadius);
      source->SetClipRadius(sphereRadius);
      source->SetThetaResolution(6);
      source->SetPhiRange(phiRange[0], phiRange[1]);
      source->SetPhiResolution(24);
      source->SetFiberResolution(48);
      source->Update();
      vtkPolyData* output = source->GetOutput();
      const std::string what = std::string(mode == vtkHopfFibrationSource::PAPER ? "paper" : "classical") +
        (type == vtkHopfFibrationSource::FIBERS ? " fibers" : " mesh");
      // The strip's own border: its first and last fiber, the texture seam u = 0 or 1.
      vtkDataArray* phi = output->GetPointData()->GetArray("phi");
      vtkDataArray* tcoords = output->GetPointData()->GetTCoords();
      auto onStripBorder = [&](vtkIdType i) {
        if (!tcoords)
        {
          return false; // fibers: every open end is a cut
        }
        const double u = tcoords->GetComponent(i, 0);
        return std::fabs(phi->GetTuple1(i) - phiRange[0]) < 1e-9 ||
          std::fabs(phi->GetTuple1(i) - phiRange[1]) < 1e-9 || u < 1e-6 || u > 1.0 - 1e-6;
      };
      ExpectCutExactlyAtTheSphere(output, center, sphereRadius, onStripBorder, 20, what);
    }
  }
}

TEST(HopfFibrationSource, OutOfRangePiecesAreEmpty)
{
  for (int type : { vtkHopfFibrationSource::FIBERS, vtkHopfFibrationSource::TWISTOR_MESH })
  {
    ExpectOutOfRangePiecesEmpty<vtkHopfFibrationSource>(
      [type](vtkHopfFibrationSource* s) { s->SetOutputType(type); });
  }
}
} // namespace

TEST(HopfFibrationSource, ReportsProgressAndAnAbortedUpdateIsEmpty)
{
  for (bool abort : { false, true })
  {
    vtkNew<vtkHopfFibrationSource> source;
    // 1200 fibers of 129 samples: 3 blocks of 508 fibers (vtkBoostedBlockLoop: 65536 samples)
    source->SetThetaResolution(20);
    source->SetPhiResolution(60);
    ProgressLog log;
    log.abortAfterFirstStep = abort; // after the first block: some fibers are computed
    log.Observe(source);
    source->Update();
    if (!abort)
    {
      EXPECT_EQ(log.Steps().size(), 3u + 1); // and the executive's 1 at the end
      EXPECT_GT(source->GetOutput()->GetNumberOfLines(), 1140);
    }
    else
    {
      EXPECT_LT(log.Steps().size(), 3u);
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
    }
  }
}

TEST(HopfFibrationSource, HugeBasePointIndexOrCountIsAnErrorAndChangesNothing)
{
  vtkNew<vtkHopfFibrationSource> source;
  EventCounter events(source);
  source->AddBasePoint(0.5, 0.25);
  source->SetBasePoint(2000000000, 0.0, 0.0); // 2 index + 2 overflows an int
  source->SetNumberOfBasePoints(2000000000);  // 32 GB of pairs
  EXPECT_EQ(events.errors, 2);
  EXPECT_EQ(source->GetNumberOfBasePoints(), 1);
}

// An input point at SphereCenter has no direction: it is skipped with one warning that counts
// the skipped points, and the others give their fibers as without it. All of them there: the
// warning and an empty output, no error.
TEST(HopfFibrationSource, InputPointsAtTheSphereCenterAreSkippedWithAWarning)
{
  const double center[3] = { 0.5, -1.0, 2.0 };
  auto sourceOf = [&center](const std::vector<std::array<double, 3>>& offsets) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& d : offsets)
    {
      points->InsertNextPoint(center[0] + d[0], center[1] + d[1], center[2] + d[2]);
    }
    vtkNew<vtkPolyData> input;
    input->SetPoints(points);
    vtkSmartPointer<vtkHopfFibrationSource> source = vtkSmartPointer<vtkHopfFibrationSource>::New();
    source->SetInputData(input);
    source->SetSamplingModeToInputPoints();
    source->SetSphereCenter(center[0], center[1], center[2]);
    source->SetFiberResolution(12);
    return source;
  };
  vtkSmartPointer<vtkHopfFibrationSource> withCenter =
    sourceOf({ { 0, 0, 0 }, { 1, 0.5, 0 }, { 0, 0, 0 }, { -0.2, 0.3, 2 } });
  vtkSmartPointer<vtkHopfFibrationSource> without = sourceOf({ { 1, 0.5, 0 }, { -0.2, 0.3, 2 } });
  EventCounter events(withCenter);
  withCenter->Update();
  without->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  EXPECT_EQ(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find(
              "2 input point(s) at SphereCenter have no direction and were skipped"),
    std::string::npos)
    << events.lastWarning;
  vtkPolyData* a = withCenter->GetOutput();
  vtkPolyData* b = without->GetOutput();
  ASSERT_EQ(b->GetNumberOfLines(), 2); // the two fibers
  ASSERT_EQ(a->GetNumberOfLines(), 2);
  ExpectSamePoints(b, a, 0.0, "the fibers with the points at the center skipped");

  vtkSmartPointer<vtkHopfFibrationSource> allAtCenter = sourceOf({ { 0, 0, 0 } });
  EventCounter allEvents(allAtCenter);
  allAtCenter->Update();
  EXPECT_EQ(allEvents.errors, 0) << allEvents.lastError;
  EXPECT_EQ(allEvents.warnings, 1);
  EXPECT_NE(allEvents.lastWarning.find("1 input point(s) at SphereCenter"), std::string::npos)
    << allEvents.lastWarning;
  EXPECT_EQ(allAtCenter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(HopfFibrationSource, TwistorMeshOfOneFiberPerStripWarnsAndIsEmpty)
{
  // Meridian strips of one latitude, and one base point: no quads can be made (the points came
  // out without cells before).
  const std::vector<std::function<void(vtkHopfFibrationSource*)>> cases = {
    [](vtkHopfFibrationSource* s) { s->SetPhiResolution(1); },
    [](vtkHopfFibrationSource* s) {
      s->SetSamplingModeToBasePoints();
      s->AddBasePoint(0.5, 0.25);
    },
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
  {
    vtkNew<vtkHopfFibrationSource> source;
    source->SetOutputTypeToTwistorMesh();
    cases[k](source);
    EventCounter events(source);
    source->Update();
    EXPECT_EQ(events.errors, 0) << "case " << k;
    EXPECT_EQ(events.warnings, 1) << "case " << k;
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0) << "case " << k;
    EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0) << "case " << k;
  }
}

TEST(HopfFibrationSource, AnOverflowingThetaSpanSaysSo)
{
  vtkNew<vtkHopfFibrationSource> source;
  EventCounter events(source);
  source->SetThetaRange(-1e308, 1e308); // finite ends, infinite span
  source->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("span (maximum - minimum) overflows"), std::string::npos) << events.lastError;
  EXPECT_EQ(events.lastError.find("NaN"), std::string::npos) << events.lastError;
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(HopfFibrationSource, CircleNormalOfAnyNonZeroLengthGivesTheSameFibers)
{
  ExpectTheSamePointsAtEveryDirectionLength<vtkHopfFibrationSource>(
    [](vtkHopfFibrationSource* s, double length) {
      s->SetCircleNormal(length / 3, 2 * length / 3, 2 * length / 3);
    });
}

TEST(HopfFibrationSource, TranslatingTheCircleTranslatesTheFibration)
{
  // Computed for the unit circle and carried to the base circle by a similarity, so exact up to
  // the final translation: the bound of TranslationChecks.h holds, fibers and meshes, both modes.
  for (int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    for (int type : { vtkHopfFibrationSource::FIBERS, vtkHopfFibrationSource::TWISTOR_MESH })
    {
      SCOPED_TRACE("mode " + std::to_string(mode) + " type " + std::to_string(type));
      ExpectTranslationCovariant([mode, type](const double t[3]) {
        vtkNew<vtkHopfFibrationSource> source;
        source->SetMode(mode);
        source->SetOutputType(type);
        source->SetCircleCenter(0.2 + t[0], -0.1 + t[1], 0.3 + t[2]);
        source->SetCircleNormal(0.3, 0.4, 1);
        source->SetCircleRadius(0.7);
        source->SetPhiRange(-1.5, 1.2); // fibers of a bounded size
        source->SetClipRadius(1e3);     // cuts nothing
        source->Update();
        return vtkSmartPointer<vtkDataSet>(source->GetOutput());
      });
    }
  }
}

TEST(HopfFibrationSource, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  ExpectSinglePrecisionBeyondTheLargestFloatIsAnError<vtkHopfFibrationSource>(
    [](vtkHopfFibrationSource* source) { source->SetCircleCenter(0, 0, 1e39); }, 1e39);
}

TEST(HopfFibrationSource, TheGeneratorsOutputIsBuiltAnewOnlyWhenTheBasePointsChange)
{
  // The fibers' sampling and the output type change the fibration's mesh, not its base points;
  // the number of latitudes does.
  ExpectGeneratorGlyphsCached(1, [] { return vtkSmartPointer<vtkHopfFibrationSource>::New(); },
    [](vtkHopfFibrationSource* source) {
      source->SetFiberResolution(16);
      source->SetOutputTypeToTwistorMesh();
    },
    [](vtkHopfFibrationSource* source) { source->SetPhiResolution(5); });
}
