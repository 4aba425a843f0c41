// Numerical tests of vtkBoostedSurfaceSource against the closed forms of docs/conventions.md section 3 items 1-3.
#include "vtkBoostedSurfaceSource.h"

#include "BadParameterCases.h"
#include "GridSourceChecks.h"
#include "ProgressLog.h"
#include "TranslationChecks.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <vector>

namespace
{
// Points of the output grouped by their "lambda" value.
std::map<double, std::vector<std::array<double, 3>>> pointsByLambda(vtkPolyData* output)
{
  std::map<double, std::vector<std::array<double, 3>>> groups;
  vtkDataArray* lambdas = output->GetPointData()->GetArray("lambda");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    output->GetPoint(i, p.data());
    groups[lambdas->GetTuple1(i)].push_back(p);
  }
  return groups;
}

// x' = x + SCT_u(p - x), SCT_u(y) = (y + u|y|^2) / (1 + 2 u.y + |u|^2 |y|^2) (docs/conventions.md section 2).
std::array<double, 3> homogeneousBoost(const double x[3], const double u[3], const double p[3])
{
  double y[3];
  vtkMath::Subtract(p, x, y);
  const double y2 = vtkMath::Dot(y, y);
  const double denominator = 1.0 + 2.0 * vtkMath::Dot(u, y) + vtkMath::Dot(u, u) * y2;
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i)
  {
    out[i] = x[i] + (y[i] + u[i] * y2) / denominator;
  }
  return out;
}
}

TEST(BoostedSurfaceSource, Fig1InPlaneBoostGivesCirclesWithClosedFormCenterAndRadius)
{
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetCircleNormal(0, 0, 1);
  source->SetBoostDirection(1, 0, 0);
  source->SetLambdaRange(-3.0, 3.0);
  source->SetLambdaResolution(24); // lambda steps of 0.25, hitting +-1 exactly
  source->SetThetaResolution(48);
  source->SetOutputTypeToCircles();
  source->Update();
  vtkPolyData* output = source->GetOutput();
  ASSERT_GT(output->GetNumberOfPoints(), 0);

  int checkedCircles = 0, checkedLines = 0;
  for (const auto& entry : pointsByLambda(output))
  {
    const double lambda = entry.first;
    const double d = lambda * lambda - 1.0;
    if (std::fabs(d) < 1e-9)
    {
      // lambda = +-1: the circle passes through the pole and becomes the line x = 1/(2 lambda).
      for (const auto& p : entry.second)
      {
        EXPECT_NEAR(p[0], 0.5 / lambda, 1e-9);
        EXPECT_NEAR(p[2], 0.0, 1e-12);
      }
      // The pole sample (theta = pi) was clipped away, the other 47 distinct samples remain.
      EXPECT_EQ(entry.second.size(), 47u);
      ++checkedLines;
      continue;
    }
    const double center = lambda / d;
    const double radius = 1.0 / std::fabs(d);
    for (const auto& p : entry.second)
    {
      const double distance = std::hypot(p[0] - center, p[1]);
      EXPECT_NEAR(distance, radius, 1e-9 * std::max(1.0, radius)) << "lambda " << lambda;
      EXPECT_NEAR(p[2], 0.0, 1e-12);
    }
    ++checkedCircles;
  }
  EXPECT_EQ(checkedLines, 2);
  EXPECT_EQ(checkedCircles, 23);
}

TEST(BoostedSurfaceSource, Fig2NormalBoostShrinksCircleIntoParallelPlanes)
{
  vtkNew<vtkBoostedSurfaceSource> source; // defaults: yz circle, boost along x
  source->SetLambdaRange(0.0, 4.0);
  source->SetLambdaResolution(16);
  source->SetThetaResolution(32);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 17 * 33);
  EXPECT_EQ(output->GetNumberOfCells(), 16 * 32);
  for (const auto& entry : pointsByLambda(output))
  {
    const double lambda = entry.first;
    const double plane = lambda / (1.0 + lambda * lambda);
    const double radius = 1.0 / (1.0 + lambda * lambda);
    for (const auto& p : entry.second)
    {
      EXPECT_NEAR(p[0], plane, 1e-12);
      EXPECT_NEAR(std::hypot(p[1], p[2]), radius, 1e-12);
    }
  }
}

TEST(BoostedSurfaceSource, GeneralBoostMatchesHomogeneousClosedForm)
{
  const double center[3] = { 0.3, -0.2, 0.5 };
  const double normal[3] = { 0.2, 0.4, 1.0 };
  const double location[3] = { -0.1, 0.7, 0.9 };
  const double direction[3] = { 0.3, -0.5, 0.4 };
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetCircleCenter(center);
  source->SetCircleNormal(normal);
  source->SetCircleRadius(0.8);
  source->SetBoostAtCircleCenter(false);
  source->SetBoostLocation(location);
  source->SetBoostDirection(direction);
  source->SetLambdaRange(0.0, 1.5);
  source->SetLambdaResolution(10);
  source->SetThetaResolution(20);
  source->SetClipRadius(1e6);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  vtkDataArray* lambdas = output->GetPointData()->GetArray("lambda");
  vtkDataArray* thetas = output->GetPointData()->GetArray("theta");
  ASSERT_NE(lambdas, nullptr);
  ASSERT_NE(thetas, nullptr);

  // The undeformed circle point at theta, in the source's documented frame: a = unit vector in the
  // plane of the normal and x (here), b = n x a.
  double n[3] = { normal[0], normal[1], normal[2] };
  vtkMath::Normalize(n);
  double a[3] = { 1.0 - n[0] * n[0], -n[0] * n[1], -n[0] * n[2] };
  vtkMath::Normalize(a);
  double b[3];
  vtkMath::Cross(n, a, b);
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    const double lambda = lambdas->GetTuple1(i);
    const double theta = thetas->GetTuple1(i);
    double p[3], u[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = center[k] + 0.8 * (std::cos(theta) * a[k] + std::sin(theta) * b[k]);
      u[k] = lambda * direction[k];
    }
    const auto expected = homogeneousBoost(location, u, p);
    double actual[3];
    output->GetPoint(i, actual);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(actual[k], expected[k], 1e-9);
    }
  }
}

TEST(BoostedSurfaceSource, SurfaceHasUnitNormalsAndTextureCoordinatesInRange)
{
  vtkNew<vtkBoostedSurfaceSource> source;
  source->Update();
  vtkPolyData* output = source->GetOutput();
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  vtkDataArray* tcoords = output->GetPointData()->GetTCoords();
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(tcoords, nullptr);
  double minU = 1, maxU = 0, minV = 1, maxV = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(vtkMath::Norm(normals->GetTuple3(i)), 1.0, 1e-6);
    const double* uv = tcoords->GetTuple2(i);
    EXPECT_TRUE(std::isfinite(uv[0]) && std::isfinite(uv[1])) << i; // std::min/max drop a NaN
    minU = std::min(minU, uv[0]);
    maxU = std::max(maxU, uv[0]);
    minV = std::min(minV, uv[1]);
    maxV = std::max(maxV, uv[1]);
  }
  EXPECT_DOUBLE_EQ(minU, 0.0);
  EXPECT_DOUBLE_EQ(maxU, 1.0);
  EXPECT_DOUBLE_EQ(minV, 0.0);
  EXPECT_DOUBLE_EQ(maxV, 1.0);

  // Fig 2 at lambda = 0 is the unit yz circle itself: the normal there is radial (+-).
  vtkDataArray* lambdas = output->GetPointData()->GetArray("lambda");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (lambdas->GetTuple1(i) == 0.0)
    {
      double p[3];
      output->GetPoint(i, p);
      const double* nrm = normals->GetTuple3(i);
      EXPECT_NEAR(std::fabs(p[1] * nrm[1] + p[2] * nrm[2]), std::hypot(nrm[1], nrm[2]), 1e-3);
    }
  }
}

TEST(BoostedSurfaceSource, PassingThroughALineStaysFiniteAndInsideTheClipSphere)
{
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetCircleNormal(0, 0, 1);
  source->SetLambdaRange(0.5, 1.5);
  source->SetLambdaResolution(40);
  source->SetClipRadius(10.0);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  ASSERT_GT(output->GetNumberOfCells(), 0);
  EXPECT_LT(output->GetNumberOfCells(), 40 * 64); // the surface was cut open near lambda = 1
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    EXPECT_LE(vtkMath::Norm(p), 10.0 + 1e-12);
  }
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    const double* nrm = normals->GetTuple3(i);
    ASSERT_TRUE(std::isfinite(nrm[0]) && std::isfinite(nrm[1]) && std::isfinite(nrm[2]));
  }
}

TEST(BoostedSurfaceSource, PiecesPartitionTheCellsAndCoverTheBounds)
{
  for (int type : { vtkBoostedSurfaceSource::SURFACE, vtkBoostedSurfaceSource::CIRCLES })
  {
    vtkNew<vtkBoostedSurfaceSource> whole;
    whole->SetOutputType(type);
    whole->SetLambdaResolution(13);
    whole->Update();
    const vtkIdType wholeCells = whole->GetOutput()->GetNumberOfCells();
    double wholeBounds[6];
    whole->GetOutput()->GetBounds(wholeBounds);
    for (int pieces : { 2, 3, 5, 20 })
    {
      vtkIdType cells = 0, points = 0;
      double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
        VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
      for (int piece = 0; piece < pieces; ++piece)
      {
        vtkNew<vtkBoostedSurfaceSource> part;
        part->SetOutputType(type);
        part->SetLambdaResolution(13);
        part->UpdatePiece(piece, pieces, 0);
        vtkPolyData* out = part->GetOutput();
        cells += out->GetNumberOfCells();
        points += out->GetNumberOfPoints();
        if (out->GetNumberOfPoints() > 0)
        {
          double b[6];
          out->GetBounds(b);
          for (int k = 0; k < 3; ++k)
          {
            bounds[2 * k] = std::min(bounds[2 * k], b[2 * k]);
            bounds[2 * k + 1] = std::max(bounds[2 * k + 1], b[2 * k + 1]);
          }
        }
      }
      EXPECT_EQ(cells, wholeCells) << pieces << " pieces";
      if (type == vtkBoostedSurfaceSource::CIRCLES)
      {
        EXPECT_EQ(points, whole->GetOutput()->GetNumberOfPoints());
      }
      for (int k = 0; k < 6; ++k)
      {
        EXPECT_NEAR(bounds[k], wholeBounds[k], 1e-12);
      }
    }
  }
}

TEST(BoostedSurfaceSource, SinglePrecisionOutput)
{
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetDataType(), VTK_DOUBLE);

  // Large enough for the floats to be one of the project's large arrays (over 4 MiB): each the
  // double point rounded to float.
  source->SetLambdaResolution(599);
  source->SetThetaResolution(599);
  source->Update();
  vtkNew<vtkDoubleArray> doubles;
  doubles->DeepCopy(source->GetOutput()->GetPoints()->GetData());
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  vtkFloatArray* floats =
    vtkFloatArray::SafeDownCast(source->GetOutput()->GetPoints()->GetData());
  ASSERT_NE(floats, nullptr);
  ASSERT_EQ(floats->GetNumberOfTuples(), doubles->GetNumberOfTuples());
  ASSERT_GT(floats->GetNumberOfValues() * sizeof(float), std::size_t(4) << 20); // LargeBytes
  const double* expected = doubles->GetPointer(0);
  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < floats->GetNumberOfValues(); ++i)
  {
    differing += floats->GetValue(i) == static_cast<float>(expected[i]) ? 0 : 1;
  }
  EXPECT_EQ(differing, 0);
}

TEST(BoostedSurfaceSource, BadParametersGiveAnErrorAndAnEmptyOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::function<void(vtkBoostedSurfaceSource*)>> breakers = {
    [](vtkBoostedSurfaceSource* s) { s->SetCircleNormal(0, 0, 0); },
    [](vtkBoostedSurfaceSource* s) { s->SetBoostDirection(0, 0, 0); },
    [](vtkBoostedSurfaceSource* s) { s->SetCircleRadius(0.0); },
    [](vtkBoostedSurfaceSource* s) { s->SetCircleRadius(-1.0); },
    [nan](vtkBoostedSurfaceSource* s) { s->SetCircleCenter(nan, 0, 0); },
    [nan](vtkBoostedSurfaceSource* s) { s->SetLambdaRange(0, nan); },
    [](vtkBoostedSurfaceSource* s) { s->SetLambdaRange(2, 1); },
    [](vtkBoostedSurfaceSource* s) {
      s->SetBoostAtCircleCenter(false);
      s->SetBoostLocation(std::numeric_limits<double>::infinity(), 0, 0);
    },
    [nan](vtkBoostedSurfaceSource* s) { s->SetClipRadius(nan); },
    // 1e10 samples: refused before anything is allocated
    [](vtkBoostedSurfaceSource* s) {
      s->SetLambdaResolution(100000);
      s->SetThetaResolution(100000);
    },
  };
  ExpectOneErrorEach(breakers, EmptyOutput::NoPointsNoCells);
}

TEST(BoostedSurfaceSource, ReportsProgressAndAnAbortedUpdateIsEmpty)
{
  for (bool abort : { false, true })
  {
    // 4032 rows of 65 samples: 4 blocks of 1008 rows (vtkBoostedBlockLoop: 65536 samples a block)
    vtkNew<vtkBoostedSurfaceSource> source;
    source->SetLambdaResolution(4031);
    ProgressLog log;
    log.abortAfterFirstStep = abort; // after the first block
    log.Observe(source);
    source->Update();
    if (!abort)
    {
      EXPECT_EQ(log.Steps().size(), 4u + 1); // and the executive's 1 at the end
      EXPECT_GT(source->GetOutput()->GetNumberOfPolys(), 0);
    }
    else
    {
      EXPECT_LT(log.Steps().size(), 4u);
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
    }
  }
}

TEST(BoostedSurfaceSource, OutputIsCutExactlyAtTheClipSphereAboutTheCircleCenter)
{
  // Fig 1: circles boosted in their plane pass through the boost's pole near lambda = +-1. No
  // sample is the pole itself (lambda steps of 0.24 miss +-1): a sample at infinity drops its
  // cells before the cut (README, Clipping), which would leave a notch inside the sphere.
  const double center[3] = { 0.3, -0.2, 0.1 };
  const double clipRadius = 4.0;
  for (int type : { vtkBoostedSurfaceSource::CIRCLES, vtkBoostedSurfaceSource::SURFACE })
  {
    vtkNew<vtkBoostedSurfaceSource> source;
    source->SetCircleCenter(center[0], center[1], center[2]);
    source->SetCircleNormal(0, 0, 1);
    source->SetLambdaRange(-3, 3);
    source->SetLambdaResolution(25);
    source->SetThetaResolution(256);
    source->SetClipRadius(clipRadius);
    source->SetOutputType(type);
    source->Update();
    vtkPolyData* output = source->GetOutput();
    vtkDataArray* lambda = output->GetPointData()->GetArray("lambda");
    vtkDataArray* tcoords = output->GetPointData()->GetTCoords();
    // The surface's own border: the first and last lambda, the texture seam u = 0 or 1.
    auto onOwnBorder = [&](vtkIdType i) {
      if (!tcoords)
      {
        return false; // circles: every open end is a cut
      }
      const double u = tcoords->GetComponent(i, 0);
      return std::fabs(std::fabs(lambda->GetTuple1(i)) - 3.0) < 1e-9 || u < 1e-6 || u > 1.0 - 1e-6;
    };
    ExpectCutExactlyAtTheSphere(output, center, clipRadius, onOwnBorder, 8,
      type == vtkBoostedSurfaceSource::CIRCLES ? "circles" : "surface");
  }
}

TEST(BoostedSurfaceSource, OutOfRangePiecesAreEmpty)
{
  for (int type : { vtkBoostedSurfaceSource::SURFACE, vtkBoostedSurfaceSource::CIRCLES })
  {
    ExpectOutOfRangePiecesEmpty<vtkBoostedSurfaceSource>(
      [type](vtkBoostedSurfaceSource* s) { s->SetOutputType(type); });
  }
}

// At a tiny radius the boost barely moves the circle (its motion grows like the radius squared),
// so every sample is degenerate and takes its row's fallback normal, the image circle's plane:
// unit at any scale (it came from the circle's blade, whose radius^2 underflows below about
// 1e-154, and was (0, 0, 0) at 1e-200).
TEST(BoostedSurfaceSource, ATinyCircleHasUnitNormals)
{
  for (double radius : { 1e-160, 1e-200, 1e-300 })
  {
    for (double offset : { 0.0, 1.0 })
    {
      vtkNew<vtkBoostedSurfaceSource> source;
      source->SetCircleRadius(radius);
      source->SetCircleCenter(offset, offset, offset);
      source->Update();
      vtkPolyData* output = source->GetOutput();
      vtkDataArray* normals = output->GetPointData()->GetNormals();
      ASSERT_NE(normals, nullptr);
      ASSERT_GT(output->GetNumberOfPoints(), 0);
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        ASSERT_NEAR(vtkMath::Norm(normals->GetTuple3(i)), 1.0, 1e-6) << radius << " " << i;
      }
    }
  }
}

TEST(BoostedSurfaceSource, CircleNormalOfAnyNonZeroLengthGivesTheSameSurface)
{
  ExpectTheSamePointsAtEveryDirectionLength<vtkBoostedSurfaceSource>(
    [](vtkBoostedSurfaceSource* s, double length) {
      s->SetCircleNormal(length / 3, 2 * length / 3, 2 * length / 3); // 1e200 flattened the surface
    });
}

TEST(BoostedSurfaceSource, AnOverflowingBoostIsAnErrorNotASurfaceOfOneRow)
{
  for (const double length : { 1e160, 1e200, 1e300 })
  {
    vtkNew<vtkBoostedSurfaceSource> source;
    EventCounter events(source);
    source->SetBoostDirection(length, 0, 0);
    source->Update();
    EXPECT_EQ(events.errors, 1) << "length " << length;
    EXPECT_NE(events.lastError.find("the boost overflows"), std::string::npos) << events.lastError;
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
  }
  // A finite lambda range far too wide for a unit boost is the same overflow.
  vtkNew<vtkBoostedSurfaceSource> wide;
  EventCounter events(wide);
  wide->SetLambdaRange(-1e200, 1e200);
  wide->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_EQ(wide->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(BoostedSurfaceSource, ATinyBoostDirectionIsAWeakBoostNotAZeroVector)
{
  // |d| = 1e-200: K(lambda) = 1 + lambda tau moves the circle by about 1e-200, every row remains.
  vtkNew<vtkBoostedSurfaceSource> source;
  EventCounter events(source);
  source->SetBoostDirection(1e-200, 0, 0);
  source->SetLambdaRange(-3, 3);
  source->SetLambdaResolution(6);
  source->SetOutputTypeToCircles();
  source->Update();
  EXPECT_EQ(events.errors, 0) << events.lastError;
  const auto rows = pointsByLambda(source->GetOutput());
  EXPECT_EQ(rows.size(), 7u);
  const double* center = source->GetCircleCenter();
  for (const auto& row : rows)
  {
    for (const auto& p : row.second)
    {
      EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(p.data(), center)), source->GetCircleRadius(), 1e-15);
    }
  }
}

TEST(BoostedSurfaceSource, TranslatingTheConfigurationTranslatesTheSurface)
{
  // Circle, boost location and direction off-axis; lambda kept where the surface stays bounded,
  // so that no point comes near the (large) clip sphere. The bound: TranslationChecks.h.
  ExpectTranslationCovariant([](const double t[3]) {
    vtkNew<vtkBoostedSurfaceSource> source;
    source->SetCircleCenter(0.1 + t[0], 0.2 + t[1], -0.3 + t[2]);
    source->SetCircleNormal(1, 0.3, 0.2);
    source->SetCircleRadius(0.8);
    source->SetBoostDirection(0.4, 1, 0.2);
    source->SetBoostAtCircleCenter(false);
    source->SetBoostLocation(0.4 + t[0], 0.0 + t[1], 0.2 + t[2]);
    source->SetLambdaRange(-0.3, 0.3);
    source->SetLambdaResolution(12);
    source->SetThetaResolution(24);
    source->SetClipRadius(1e3);
    source->Update();
    return vtkSmartPointer<vtkDataSet>(source->GetOutput());
  });
}

TEST(BoostedSurfaceSource, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  ExpectSinglePrecisionBeyondTheLargestFloatIsAnError<vtkBoostedSurfaceSource>(
    [](vtkBoostedSurfaceSource* source) { source->SetCircleCenter(1e39, 0, 0); }, 1e39);
}
