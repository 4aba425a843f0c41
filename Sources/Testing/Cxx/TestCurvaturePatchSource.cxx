// Tests of vtkCurvaturePatchSource against the closed forms of docs/conventions.md section 3 items 5-6 (the
// bent line is a circle, a zero curvature leaves the plane flat), and its arrays, pieces,
// clamping and bad input.
#include "vtkCurvaturePatchSource.h"

#include "BadParameterCases.h"
#include "GeneratorGlyphCacheChecks.h"
#include "GridSourceChecks.h"
#include "ProgressLog.h"
#include "TranslationChecks.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
bool allFinite(vtkPolyData* output)
{
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return false;
    }
  }
  return true;
}
}

TEST(CurvaturePatchSource, DefaultsGiveAGridWithAllArrays)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 33 * 33);
  EXPECT_EQ(output->GetNumberOfPolys(), 32 * 32);
  for (const char* name : { "u", "v", "GeneratorWeight" })
  {
    EXPECT_NE(output->GetPointData()->GetArray(name), nullptr) << name;
  }
  ASSERT_NE(output->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(output->GetPointData()->GetTCoords(), nullptr);
  double range[2];
  output->GetPointData()->GetArray("u")->GetRange(range);
  EXPECT_DOUBLE_EQ(range[0], -2.0);
  EXPECT_DOUBLE_EQ(range[1], 2.0);
  // eq 16: the weight is (kappa_u + kappa_v)/2 everywhere
  output->GetPointData()->GetArray("GeneratorWeight")->GetRange(range);
  EXPECT_DOUBLE_EQ(range[0], 0.5);
  EXPECT_DOUBLE_EQ(range[1], 0.5);
  // the umbilic default bends away from the normal +z: the origin is the highest point, and its
  // normal is +z
  double bounds[6];
  output->GetBounds(bounds);
  EXPECT_NEAR(bounds[5], 0.0, 1e-12);
  EXPECT_LT(bounds[4], -0.5);
  const vtkIdType center = 16 * 33 + 16;
  double n[3];
  output->GetPointData()->GetNormals()->GetTuple(center, n);
  EXPECT_NEAR(n[2], 1.0, 1e-6);
}

// Eq 15 through the VTK class: every row of a bent strip lies on a circle of radius 1/|kappa|
// centered at (0, b, 0) - n/kappa, for a tilted patch.
TEST(CurvaturePatchSource, BentStripRowsAreCircles)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetMethodToBentLine();
  source->SetOrigin(1, 2, 3);
  source->SetUDirection(0, 1, 1);
  source->SetVDirection(1, 0, 0);
  source->SetKappaU(0.5);
  source->SetSize(10, 2);
  source->SetVResolution(4);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  const double s = std::sqrt(0.5);
  const double u[3] = { 0, s, s }, v[3] = { 1, 0, 0 };
  double n[3];
  vtkMath::Cross(u, v, n);
  vtkDataArray* bs = output->GetPointData()->GetArray("v");
  ASSERT_EQ(output->GetNumberOfPoints(), 5 * 33);
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], c[3];
    output->GetPoint(i, p);
    const double b = bs->GetTuple1(i);
    for (int k = 0; k < 3; ++k)
    {
      c[k] = (k == 0 ? 1.0 : k == 1 ? 2.0 : 3.0) + b * v[k] - n[k] / 0.5;
    }
    EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(p, c)), 2.0, 1e-9);
  }
}

TEST(CurvaturePatchSource, ZeroCurvatureAndPresets)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetKappaU(0.0);
  source->SetKappaV(0.0);
  source->Update();
  double bounds[6];
  source->GetOutput()->GetBounds(bounds);
  EXPECT_DOUBLE_EQ(bounds[0], -2.0);
  EXPECT_DOUBLE_EQ(bounds[3], 2.0);
  EXPECT_EQ(bounds[4], 0.0);
  EXPECT_EQ(bounds[5], 0.0);

  // the hyperbolic preset overrides the zero curvatures: a saddle above and below the plane
  source->SetCurvaturePreset(vtkCurvaturePatchSource::HYPERBOLIC);
  source->Update();
  source->GetOutput()->GetBounds(bounds);
  EXPECT_LT(bounds[4], -0.1);
  EXPECT_GT(bounds[5], 0.1);
}

TEST(CurvaturePatchSource, SingleLineWhenTheWidthIsZero)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetMethodToBentLine();
  source->SetSize(6.0, 0.0);
  source->SetUResolution(60);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 61);
  EXPECT_EQ(source->GetOutput()->GetNumberOfLines(), 1);
}

TEST(CurvaturePatchSource, HugeCurvatureStaysFinite)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetMethodToBentLine();
  source->SetKappaU(1e8);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 33 * 33);
  EXPECT_TRUE(allFinite(source->GetOutput()));
}

TEST(CurvaturePatchSource, EveryMethodGivesFinitePoints)
{
  for (int method = vtkCurvaturePatchSource::BENT_LINE; method <= vtkCurvaturePatchSource::BILINEAR;
       ++method)
  {
    for (int rule : { vtkCurvaturePatchSource::EXACT, vtkCurvaturePatchSource::PAPER })
    {
      vtkNew<vtkCurvaturePatchSource> source;
      source->SetMethod(method);
      source->SetExponentialRule(rule);
      source->AddControlPoint(1, 1, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5);
      source->AddControlPoint(1, 1, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5); // coincident: they add
      source->AddControlPoint(-1, 0, 0, 0, 1, 1, 1, 0, 0, 1.0, 0.3);
      source->SetCorner2Direction(1, 0, 0);
      source->Update();
      EXPECT_GT(source->GetOutput()->GetNumberOfPolys(), 0) << method;
      EXPECT_TRUE(allFinite(source->GetOutput())) << method;
    }
  }
}

TEST(CurvaturePatchSource, SelectedControlPointMovesItsLocation)
{
  vtkNew<vtkCurvaturePatchSource> moved, selected;
  for (vtkCurvaturePatchSource* s : { moved.Get(), selected.Get() })
  {
    s->SetMethodToControlPoints();
    s->AddControlPoint(0, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5);
  }
  moved->SetControlPoint(0, 0.5, -0.5, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5);
  selected->SetSelectedControlPoint(0);
  selected->SetSelectedControlPointLocation(0.5, -0.5, 0);
  moved->Update();
  selected->Update();
  ASSERT_EQ(moved->GetOutput()->GetNumberOfPoints(), selected->GetOutput()->GetNumberOfPoints());
  for (vtkIdType i = 0; i < moved->GetOutput()->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    moved->GetOutput()->GetPoint(i, a);
    selected->GetOutput()->GetPoint(i, b);
    EXPECT_EQ(vtkMath::Distance2BetweenPoints(a, b), 0.0);
  }
  double values[11] = {};
  selected->GetControlPoint(0, values);
  EXPECT_EQ(values[9], 0.5);
  EXPECT_EQ(selected->GetNumberOfControlPoints(), 1);
}

TEST(CurvaturePatchSource, PiecesPartitionTheCells)
{
  for (int type : { vtkCurvaturePatchSource::SURFACE, vtkCurvaturePatchSource::LINES })
  {
    vtkNew<vtkCurvaturePatchSource> whole;
    whole->SetOutputType(type);
    whole->SetVResolution(13);
    whole->Update();
    for (int pieces : { 2, 3, 20 })
    {
      vtkIdType cells = 0, points = 0;
      for (int piece = 0; piece < pieces; ++piece)
      {
        vtkNew<vtkCurvaturePatchSource> part;
        part->SetOutputType(type);
        part->SetVResolution(13);
        part->UpdatePiece(piece, pieces, 0);
        cells += part->GetOutput()->GetNumberOfCells();
        points += part->GetOutput()->GetNumberOfPoints();
      }
      EXPECT_EQ(cells, whole->GetOutput()->GetNumberOfCells()) << pieces;
      if (type == vtkCurvaturePatchSource::LINES)
      {
        EXPECT_EQ(points, whole->GetOutput()->GetNumberOfPoints());
      }
    }
  }
}

TEST(CurvaturePatchSource, ClampsAndPrecision)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetUResolution(0);
  EXPECT_EQ(source->GetUResolution(), 1);
  source->SetMethod(42);
  EXPECT_EQ(source->GetMethod(), vtkCurvaturePatchSource::BILINEAR);
  source->SetCurvaturePreset(-3);
  EXPECT_EQ(source->GetCurvaturePreset(), vtkCurvaturePatchSource::CUSTOM);
  source->SetEpsilon(0.0);
  EXPECT_GT(source->GetEpsilon(), 0.0);
  source->SetFalloff(-1.0);
  EXPECT_EQ(source->GetFalloff(), 0.0);
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
  source->AddControlPoint(1, 2, 3, 0, 0, 1, 1, 0, 0, 0.5, 0.25);
  std::ostringstream printed;
  source->Print(printed);
  EXPECT_NE(printed.str().find("Method: BILINEAR"), std::string::npos);
  EXPECT_NE(printed.str().find("ControlPoint 0: (1, 2, 3, 0, 0, 1, 1, 0, 0, 0.5, 0.25)"), std::string::npos);
}

TEST(CurvaturePatchSource, BadParametersGiveAnErrorAndAnEmptyOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::function<void(vtkCurvaturePatchSource*)>> breakers = {
    [](vtkCurvaturePatchSource* s) { s->SetSize(0, 4); },
    [](vtkCurvaturePatchSource* s) { s->SetSize(-1, 4); },
    [](vtkCurvaturePatchSource* s) { s->SetSize(4, -1); },
    [nan](vtkCurvaturePatchSource* s) { s->SetOrigin(nan, 0, 0); },
    [nan](vtkCurvaturePatchSource* s) { s->SetKappaV(nan); },
    [](vtkCurvaturePatchSource* s) { s->SetKappaU(std::numeric_limits<double>::infinity()); },
    [](vtkCurvaturePatchSource* s) { s->SetUDirection(0, 0, 0); },
    [](vtkCurvaturePatchSource* s) { s->SetVDirection(2, 0, 0); },
    [](vtkCurvaturePatchSource* s) { s->SetMethodToControlPoints(); },
    [](vtkCurvaturePatchSource* s) {
      s->SetMethodToControlPoints();
      s->AddControlPoint(0, 0, 0, 0, 0, 1, 0, 0, 3, 0.5, 0.5); // u along the normal
    },
    [nan](vtkCurvaturePatchSource* s) {
      s->SetMethodToControlPoints();
      s->AddControlPoint(0, 0, 0, 0, 0, 1, 1, 0, 0, nan, 0.5);
    },
    [nan](vtkCurvaturePatchSource* s) {
      s->SetMethodToBilinear();
      s->SetCorner3Direction(nan, 0, 1);
    },
    [nan](vtkCurvaturePatchSource* s) { s->SetClipRadius(nan); },
    // 1e10 samples: refused before anything is allocated
    [](vtkCurvaturePatchSource* s) {
      s->SetUResolution(100000);
      s->SetVResolution(100000);
    },
  };
  ExpectOneErrorEach(breakers, EmptyOutput::NoPoints);
}

TEST(CurvaturePatchSource, ReportsProgressAndAnAbortedUpdateIsEmpty)
{
  for (bool abort : { false, true })
  {
    vtkNew<vtkCurvaturePatchSource> source;
    // 4001 rows of 33 samples: 3 blocks (vtkBoostedBlockLoop: 65536 samples a block)
    source->SetVResolution(4000);
    ProgressLog log;
    log.abortAfterFirstStep = abort; // after the first block: a part of the patch is computed
    log.Observe(source);
    source->Update();
    if (!abort)
    {
      EXPECT_EQ(log.Steps().size(), 3u + 1); // and the executive's 1 at the end
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 33 * 4001);
    }
    else
    {
      EXPECT_LT(log.Steps().size(), 3u);
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_EQ(source->GetOutput()->GetNumberOfCells(), 0);
    }
  }
}

TEST(CurvaturePatchSource, OutputIsCutExactlyAtTheClipSphereAboutTheOrigin)
{
  const double origin[3] = { 0.5, -1.0, 2.0 };
  const double clipRadius = 1.7; // inside the 4 x 4 patch: cuts every side
  for (int type : { vtkCurvaturePatchSource::LINES, vtkCurvaturePatchSource::SURFACE })
  {
    vtkNew<vtkCurvaturePatchSource> source;
    source->SetOrigin(origin);
    source->SetUDirection(1, 1, 0);
    source->SetVDirection(0, 1, 1);
    source->SetClipRadius(clipRadius);
    source->SetOutputType(type);
    source->Update();
    vtkPolyData* output = source->GetOutput();
    vtkDataArray* u = output->GetPointData()->GetArray("u");
    vtkDataArray* v = output->GetPointData()->GetArray("v");
    auto onOwnBorder = [&](vtkIdType i) {
      return std::fabs(std::fabs(u->GetTuple1(i)) - 2.0) < 1e-9 ||
        std::fabs(std::fabs(v->GetTuple1(i)) - 2.0) < 1e-9;
    };
    ExpectCutExactlyAtTheSphere(output, origin, clipRadius, onOwnBorder, 20,
      type == vtkCurvaturePatchSource::LINES ? "lines" : "surface");
  }
}

TEST(CurvaturePatchSource, OutOfRangePiecesAreEmpty)
{
  for (int type : { vtkCurvaturePatchSource::SURFACE, vtkCurvaturePatchSource::LINES })
  {
    ExpectOutOfRangePiecesEmpty<vtkCurvaturePatchSource>(
      [type](vtkCurvaturePatchSource* s) { s->SetOutputType(type); });
  }
}

TEST(CurvaturePatchSource, DirectionsOfAnyNonZeroLengthGiveTheSamePatch)
{
  ExpectTheSamePointsAtEveryDirectionLength<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* s, double length) {
      s->SetUDirection(0, 0.6 * length, 0.8 * length); // 1e160 was "the u direction must not be zero"
      s->SetVDirection(length, 0, 0);
    });
}

TEST(CurvaturePatchSource, TranslatingTheConfigurationTranslatesThePatch)
{
  // Every method, both rules, a tilted frame and control points off the origin, all moved by t
  // (the bound: TranslationChecks.h). A clip sphere large enough to cut nothing.
  for (int method = vtkCurvaturePatchSource::BENT_LINE; method <= vtkCurvaturePatchSource::BILINEAR;
       ++method)
  {
    for (int rule : { vtkCurvaturePatchSource::EXACT, vtkCurvaturePatchSource::PAPER })
    {
      SCOPED_TRACE("method " + std::to_string(method) + " rule " + std::to_string(rule));
      ExpectTranslationCovariant([method, rule](const double t[3]) {
        vtkNew<vtkCurvaturePatchSource> source;
        source->SetMethod(method);
        source->SetExponentialRule(rule);
        source->SetOrigin(0.3 + t[0], -0.2 + t[1], 0.1 + t[2]);
        source->SetUDirection(1, 0.2, 0.1);
        source->SetVDirection(-0.1, 1, 0.3);
        source->AddControlPoint(1 + t[0], 1 + t[1], 0 + t[2], 0, 0, 1, 1, 0, 0, 0.5, -0.5);
        source->AddControlPoint(-1 + t[0], 0 + t[1], 0 + t[2], 0, 1, 1, 1, 0, 0, 1.0, 0.3);
        source->SetCorner2Direction(1, 0, 1);
        source->SetUResolution(16);
        source->SetVResolution(12);
        source->SetClipRadius(1e6);
        source->Update();
        return vtkSmartPointer<vtkDataSet>(source->GetOutput());
      });
    }
  }
}

TEST(CurvaturePatchSource, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  ExpectSinglePrecisionBeyondTheLargestFloatIsAnError<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* source) { source->SetOrigin(0, -2e39, 0); }, 2e39);
}

TEST(CurvaturePatchSource, ATinyPatchHasUnitNormals)
{
  // The default patch (Translated Tangents, umbilic curvatures 0.5) scaled by 1e-160: size
  // 4e-160, curvatures 0.5e160. The squares of its central differences (1e-322) underflow; its
  // normals are still unit vectors, along the unit patch's to 1e-2 (unscaled they were the
  // fallback plane normal, up to 45 degrees off at the edges, or not finite). Not closer: the
  // tiny samples themselves are less accurate, up(p) holding |p|^2 / 2 as a subnormal double.
  vtkNew<vtkCurvaturePatchSource> unit, tiny;
  tiny->SetSize(4e-160, 4e-160);
  tiny->SetKappaU(0.5e160);
  tiny->SetKappaV(0.5e160);
  tiny->SetEpsilon(1e-12);
  unit->SetEpsilon(1e-12);
  unit->Update();
  tiny->Update();
  vtkDataArray* expected = unit->GetOutput()->GetPointData()->GetNormals();
  vtkDataArray* normals = tiny->GetOutput()->GetPointData()->GetNormals();
  ASSERT_TRUE(expected && normals);
  ASSERT_EQ(normals->GetNumberOfTuples(), expected->GetNumberOfTuples());
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    const double* n = normals->GetTuple3(i);
    ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) << i;
    EXPECT_NEAR(vtkMath::Norm(n), 1.0, 1e-6) << i;
    double e[3];
    expected->GetTuple(i, e);
    EXPECT_LE(std::sqrt(vtkMath::Distance2BetweenPoints(n, e)), 1e-2) << i;
  }
}

// Found by the property fuzz (Testing/Python/test_property_fuzz.py --seed 7 --trial 116 and
// --seed 2 --trial 2681): a patch far from the origin whose origin is a subnormal off its own
// sample points gave (NaN, inf, NaN) points where the clip sphere cut it (the crossing rounded
// onto the sphere's center, cga::segmentSphereExitPoint). Every point is finite and in the ball.
TEST(CurvaturePatchSource, FarFromTheOriginTheCutAtTheClipSphereIsFinite)
{
  const double origins[][3] = { { -0.6395685885419589, -5e-324, -1e20 },
    { -0.6395685885419589, -5e-324, -1e39 }, { -5e-324, -1e-300, -1e39 } };
  for (const auto& origin : origins)
  {
    vtkNew<vtkCurvaturePatchSource> source;
    source->SetOrigin(origin);
    source->Update();
    vtkPolyData* output = source->GetOutput();
    ASSERT_GT(output->GetNumberOfPoints(), 0) << origin[2];
    EXPECT_TRUE(allFinite(output)) << origin[2];
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      EXPECT_LE(RelativeSphereExcess(p, origin, source->GetClipRadius()), 1e-12) << i;
    }
    ExpectCellsUseExistingPoints(output);
  }
}

// Found by the property fuzz (Testing/Python/test_property_fuzz.py --seed 20261202 --trial 4664):
// curvatures near the largest double with two far control points left one sample whose image was
// finite but whose GeneratorWeight was -inf. A sample whose weight overflows is dropped like one
// at infinity: every array of the output is finite.
TEST(CurvaturePatchSource, CurvaturesNearTheLargestDoubleGiveFiniteArrays)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetKappaU(-1.7976931348623157e+308);
  source->SetKappaV(-1e+300);
  source->SetUDirection(1e-12, -1e-12, -0.0);
  source->AddControlPoint(3.4028234663852886e+38, 9007199254740992.0, 9007199254740992.0, -1e8,
    1e+150, 3.4028234663852886e+38, 0.6650668322065414, 1.958667459959993, -0.02681592389012667,
    -0.7528703529345799, -646.0976534921266);
  source->AddControlPoint(-1e+300, -2.5297679010214047, -0.3417903160704956, -1e8, -1e8,
    1.4020733617949805, 192.99167319548576, 3.4028234663852886e+38, -0.014078698438040304,
    -8.451064111369455, 0.0);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_TRUE(allFinite(output));
  vtkPointData* pointData = output->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      EXPECT_TRUE(std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
        static_cast<int>(i % array->GetNumberOfComponents()))))
        << array->GetName() << " " << i;
    }
  }
  ExpectCellsUseExistingPoints(output);
}

TEST(CurvaturePatchSource, TheGeneratorsOutputIsBuiltAnewOnlyWhenTheControlPointsChange)
{
  // The resolution changes the patch, not its control points; a control point's curvature does.
  ExpectGeneratorGlyphsCached(1,
    [] {
      auto source = vtkSmartPointer<vtkCurvaturePatchSource>::New();
      source->SetMethodToControlPoints();
      source->AddControlPoint(1, 1, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5);
      source->AddControlPoint(-1, 0, 0, 0, 1, 1, 1, 0, 0, 1.0, 0.3);
      return source;
    },
    [](vtkCurvaturePatchSource* source) { source->SetUResolution(7); },
    [](vtkCurvaturePatchSource* source) {
      source->SetControlPoint(1, -1, 0, 0, 0, 1, 1, 1, 0, 0, 1.0, 0.4);
    });
  // The corners of BILINEAR: ClipRadius is not theirs, a corner's direction is.
  ExpectGeneratorGlyphsCached(1,
    [] {
      auto source = vtkSmartPointer<vtkCurvaturePatchSource>::New();
      source->SetMethodToBilinear();
      return source;
    },
    [](vtkCurvaturePatchSource* source) { source->SetClipRadius(1.5); },
    [](vtkCurvaturePatchSource* source) { source->SetCorner3Direction(0.25, 0, 1); });
}
