// vtkDipoleFieldSource: its arrays against the closed form of one generator (docs/conventions.md section 2),
// sub-extents against the whole field, time steps, precision and bad input.
#include "vtkDipoleFieldSource.h"

#include "EventCounter.h"
#include "GeneratorGlyphCacheChecks.h"
#include "GridSourceChecks.h"
#include "ProgressLog.h"
#include "TranslationChecks.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
const char* const ArrayNames[] = { "DisplacementSummedGenerators",
  "DisplacementSummedDisplacements", "DisplacementDifference", "DisplacementDifferenceMagnitude",
  "DipolePotential" };

// The displacement of one generator in closed form: an SCT of weight
// u = -s w v / (k |p - x|^2 + eps) about x (docs/conventions.md section 2 and section 3 item 12).
std::array<double, 3> closedForm(const double x[3], const double v[3], double w, double k,
  double eps, double s, const double p[3])
{
  double y[3];
  vtkMath::Subtract(p, x, y);
  const double y2 = vtkMath::Dot(y, y);
  const double c = -s * w / (k * y2 + eps);
  const double u[3] = { c * v[0], c * v[1], c * v[2] };
  const double denominator = 1.0 + 2.0 * vtkMath::Dot(u, y) + vtkMath::Dot(u, u) * y2;
  std::array<double, 3> out;
  for (int i = 0; i < 3; ++i)
  {
    out[i] = x[i] + (y[i] + u[i] * y2) / denominator - p[i];
  }
  return out;
}

// Every array of two fields, value by value, to `tolerance`.
void expectEqualArrays(vtkImageData* a, vtkImageData* b, double tolerance)
{
  for (const char* name : ArrayNames)
  {
    vtkDataArray* x = a->GetPointData()->GetArray(name);
    vtkDataArray* y = b->GetPointData()->GetArray(name);
    ASSERT_EQ(x->GetNumberOfTuples(), y->GetNumberOfTuples()) << name;
    for (vtkIdType id = 0; id < x->GetNumberOfTuples(); ++id)
    {
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      {
        EXPECT_NEAR(x->GetComponent(id, c), y->GetComponent(id, c), tolerance) << name;
      }
    }
  }
}

void addFig14Generators(vtkDipoleFieldSource* source)
{
  source->RemoveAllGenerators();
  source->AddGenerator(-1, 0, 0, 0, 1, 0, 0.35);
  source->AddGenerator(1, 0, 0, 1, 0, 0, 0.35);
}
}

TEST(DipoleFieldSource, DefaultsAreOneDipoleOnA21By21SliceWithEveryArray)
{
  vtkNew<vtkDipoleFieldSource> source;
  source->Update();
  vtkImageData* output = source->GetOutput();
  int dimensions[3];
  output->GetDimensions(dimensions);
  EXPECT_EQ(dimensions[0], 21);
  EXPECT_EQ(dimensions[1], 21);
  EXPECT_EQ(dimensions[2], 1);
  EXPECT_EQ(source->GetNumberOfGenerators(), 1);
  for (const char* name : ArrayNames)
  {
    vtkDataArray* array = output->GetPointData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), 21 * 21) << name;
    EXPECT_TRUE(vtkDoubleArray::SafeDownCast(array) != nullptr) << name;
  }
  EXPECT_STREQ(output->GetPointData()->GetScalars()->GetName(), "DipolePotential");
  EXPECT_STREQ(output->GetPointData()->GetVectors()->GetName(), "DisplacementSummedGenerators");
}

TEST(DipoleFieldSource, OneGeneratorBothMethodsEqualTheClosedFormAtEveryGridPoint)
{
  const double x[3] = { 0.15, -0.3, 0.2 }, v[3] = { 0.6, 0.0, 0.8 };
  for (int rule : { vtkDipoleFieldSource::EXACT, vtkDipoleFieldSource::PAPER })
  {
    vtkNew<vtkDipoleFieldSource> source;
    source->RemoveAllGenerators();
    source->AddGenerator(x[0], x[1], x[2], v[0], v[1], v[2], 0.7);
    source->SetDimensions(6, 5, 4);
    source->SetOrigin(-1.0, -1.0, -0.5);
    source->SetSpacing(0.4, 0.5, 0.3);
    source->SetFalloff(1.3);
    source->SetEpsilon(0.05);
    source->SetExponentialRule(rule);
    source->Update();
    vtkImageData* output = source->GetOutput();
    ASSERT_EQ(output->GetNumberOfPoints(), 6 * 5 * 4);
    vtkPointData* pd = output->GetPointData();
    double largest = 0.0;
    for (vtkIdType id = 0; id < output->GetNumberOfPoints(); ++id)
    {
      double p[3];
      output->GetPoint(id, p);
      const auto expected = closedForm(x, v, 0.7, 1.3, 0.05, 1.0, p);
      double a[3], b[3];
      pd->GetArray("DisplacementSummedGenerators")->GetTuple(id, a);
      pd->GetArray("DisplacementSummedDisplacements")->GetTuple(id, b);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(a[c], expected[c], 1e-12);
        EXPECT_EQ(a[c], b[c]);
      }
      EXPECT_EQ(pd->GetArray("DisplacementDifferenceMagnitude")->GetTuple1(id), 0.0);
      largest = std::max(largest, vtkMath::Norm(a));
    }
    EXPECT_GT(largest, 0.1); // the field is not trivially zero
  }
}

TEST(DipoleFieldSource, TwoGeneratorsDifferenceArraysAreAMinusB)
{
  vtkNew<vtkDipoleFieldSource> source;
  addFig14Generators(source);
  source->Update();
  vtkPointData* pd = source->GetOutput()->GetPointData();
  double largest = 0.0;
  for (vtkIdType id = 0; id < source->GetOutput()->GetNumberOfPoints(); ++id)
  {
    double a[3], b[3], d[3];
    pd->GetArray("DisplacementSummedGenerators")->GetTuple(id, a);
    pd->GetArray("DisplacementSummedDisplacements")->GetTuple(id, b);
    pd->GetArray("DisplacementDifference")->GetTuple(id, d);
    double expected[3];
    vtkMath::Subtract(a, b, expected);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(d[c], expected[c]);
    }
    EXPECT_NEAR(pd->GetArray("DisplacementDifferenceMagnitude")->GetTuple1(id),
      vtkMath::Norm(expected), 1e-15);
    largest = std::max(largest, vtkMath::Norm(d));
  }
  EXPECT_GT(largest, 0.1); // Fig 14: the methods differ
}

TEST(DipoleFieldSource, SubExtentEqualsTheMatchingPartOfTheWholeField)
{
  vtkNew<vtkDipoleFieldSource> whole;
  addFig14Generators(whole);
  whole->SetDimensions(9, 7, 5);
  whole->SetSpacing(0.5, 0.6, 0.4);
  whole->SetOrigin(-2.0, -1.8, -0.8);
  whole->Update();
  vtkImageData* full = whole->GetOutput();

  vtkNew<vtkDipoleFieldSource> part;
  addFig14Generators(part);
  part->SetDimensions(9, 7, 5);
  part->SetSpacing(0.5, 0.6, 0.4);
  part->SetOrigin(-2.0, -1.8, -0.8);
  int extent[6] = { 2, 6, 1, 3, 3, 4 };
  part->UpdateExtent(extent);
  vtkImageData* sub = part->GetOutput();
  int got[6];
  sub->GetExtent(got);
  for (int c = 0; c < 6; ++c)
  {
    ASSERT_EQ(got[c], extent[c]);
  }
  ASSERT_EQ(sub->GetNumberOfPoints(), 5 * 3 * 2); // only the requested extent was computed
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i)
      {
        int ijk[3] = { i, j, k };
        const vtkIdType inFull = full->ComputePointId(ijk);
        const vtkIdType inSub = sub->ComputePointId(ijk);
        double pFull[3], pSub[3];
        full->GetPoint(inFull, pFull);
        sub->GetPoint(inSub, pSub);
        EXPECT_EQ(vtkMath::Distance2BetweenPoints(pFull, pSub), 0.0);
        for (const char* name : ArrayNames)
        {
          vtkDataArray* a = full->GetPointData()->GetArray(name);
          vtkDataArray* b = sub->GetPointData()->GetArray(name);
          for (int c = 0; c < a->GetNumberOfComponents(); ++c)
          {
            EXPECT_EQ(a->GetComponent(inFull, c), b->GetComponent(inSub, c)) << name;
          }
        }
      }
    }
  }
}

TEST(DipoleFieldSource, TimeStepsScaleTheWeightsFromZeroToOne)
{
  vtkNew<vtkDipoleFieldSource> timed;
  addFig14Generators(timed);
  timed->SetNumberOfTimeSteps(5);
  timed->UpdateInformation();
  vtkInformation* info = timed->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 5);
  const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  for (int k = 0; k < 5; ++k)
  {
    EXPECT_DOUBLE_EQ(times[k], 0.25 * k);
  }

  // t = 0.5 is the field of the weights halved, with no time.
  timed->UpdateTimeStep(0.5);
  vtkNew<vtkDipoleFieldSource> halved;
  halved->RemoveAllGenerators();
  halved->AddGenerator(-1, 0, 0, 0, 1, 0, 0.175);
  halved->AddGenerator(1, 0, 0, 1, 0, 0, 0.175);
  halved->Update();
  vtkDataArray* a = timed->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators");
  vtkDataArray* b = halved->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators");
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  for (vtkIdType id = 0; id < a->GetNumberOfTuples(); ++id)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(a->GetComponent(id, c), b->GetComponent(id, c), 1e-14);
    }
  }

  // t = 0: no displacement; without time steps the full weights are used.
  timed->UpdateTimeStep(0.0);
  EXPECT_EQ(timed->GetOutput()->GetPointData()->GetArray("DisplacementSummedDisplacements")->GetMaxNorm(), 0.0);
  vtkNew<vtkDipoleFieldSource> untimed;
  addFig14Generators(untimed);
  untimed->UpdateInformation();
  EXPECT_FALSE(untimed->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  untimed->Update();
  timed->UpdateTimeStep(1.0);
  EXPECT_EQ(untimed->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators")->GetMaxNorm(),
    timed->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators")->GetMaxNorm());
}

TEST(DipoleFieldSource, SinglePrecisionGivesFloatArrays)
{
  vtkNew<vtkDipoleFieldSource> source;
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  for (const char* name : ArrayNames)
  {
    EXPECT_TRUE(vtkFloatArray::SafeDownCast(source->GetOutput()->GetPointData()->GetArray(name)))
      << name;
  }
}

TEST(DipoleFieldSource, GeneratorOnAGridPointIsFiniteAndFixed)
{
  vtkNew<vtkDipoleFieldSource> source; // default: a generator at the origin, a grid point
  source->Update();
  vtkImageData* output = source->GetOutput();
  const double origin[3] = { 0, 0, 0 };
  const vtkIdType center = output->FindPoint(const_cast<double*>(origin));
  ASSERT_GE(center, 0);
  double p[3];
  output->GetPoint(center, p);
  ASSERT_EQ(vtkMath::Norm(p), 0.0);
  for (const char* name : ArrayNames)
  {
    vtkDataArray* array = output->GetPointData()->GetArray(name);
    for (vtkIdType id = 0; id < array->GetNumberOfTuples(); ++id)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        ASSERT_TRUE(std::isfinite(array->GetComponent(id, c))) << name;
      }
    }
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      EXPECT_EQ(array->GetComponent(center, c), 0.0) << name;
    }
  }
}

TEST(DipoleFieldSource, BadInputGivesAnErrorAndAnEmptyOutput)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  enum Case
  {
    ZeroDimension,
    NegativeDimension,
    ZeroSpacing,
    NegativeSpacing,
    NaNOrigin,
    NaNGenerator,
    NaNEpsilon,
    NaNTranslation,
    NaNSelectedLocation,
    InfiniteAimedTip,
    HugeDimensions,
    GridOverflowsFromTheOrigin,
    GridSpanOverflows,
    Cases
  };
  for (int which = 0; which < Cases; ++which)
  {
    vtkNew<vtkDipoleFieldSource> source;
    EventCounter counter(source);
    switch (which)
    {
      case ZeroDimension: source->SetDimensions(0, 21, 1); break;
      case NegativeDimension: source->SetDimensions(21, -3, 1); break;
      case ZeroSpacing: source->SetSpacing(0.2, 0.0, 1.0); break;
      case NegativeSpacing: source->SetSpacing(-0.2, 0.2, 1.0); break;
      case NaNOrigin: source->SetOrigin(0, nan, 0); break;
      case NaNGenerator: source->AddGenerator(1, 1, 0, nan, 0, 0, 1); break;
      case NaNEpsilon: source->SetEpsilon(nan); break;
      case NaNTranslation: source->SetGeneratorsTranslation(0, 0, nan); break;
      case NaNSelectedLocation:
        source->SetSelectedGenerator(0);
        source->SetSelectedGeneratorLocation(nan, 0, 0);
        break;
      case InfiniteAimedTip:
        source->SetSelectedGenerator(0);
        source->AimSelectedGeneratorOn();
        source->SetSelectedGeneratorTip(0, std::numeric_limits<double>::infinity(), 0);
        break;
      // 8e27 points (their count overflows vtkIdType): refused before anything is allocated
      case HugeDimensions: source->SetDimensions(2000000000, 2000000000, 2000000000); break;
      // finite Origin and Spacing whose last grid point is not: 1.7e308 + 20 * 1e306
      case GridOverflowsFromTheOrigin:
        source->SetOrigin(0, 1.7e308, 0);
        source->SetSpacing(1, 1e306, 1);
        break;
      // 20 * 1e307 overflows although the sum with the origin would not
      case GridSpanOverflows:
        source->SetOrigin(-1e308, 0, 0);
        source->SetSpacing(1e307, 1, 1);
        break;
    }
    source->Update();
    EXPECT_EQ(counter.errors, 1) << "case " << which;
    EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0) << "case " << which;
  }
}

TEST(DipoleFieldSource, PointSentToInfinityGivesAWarningAndZero)
{
  // One generator at 0 along x with weight 2.5, k = 1, eps = 1: u = -0.5 x at r = (2, 0, 0), where
  // 1 + 2 u.r + |u|^2 |r|^2 = 0: the boost sends the grid point (2, 0, 0) to infinity.
  vtkNew<vtkDipoleFieldSource> source;
  source->RemoveAllGenerators();
  source->AddGenerator(0, 0, 0, 1, 0, 0, 2.5);
  source->SetEpsilon(1.0);
  source->SetOrigin(0, 0, 0);
  source->SetSpacing(1, 1, 1);
  source->SetDimensions(3, 1, 1);
  EventCounter counter(source);
  source->Update();
  EXPECT_EQ(counter.errors, 0);
  EXPECT_EQ(counter.warnings, 1);
  vtkDataArray* a = source->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators");
  ASSERT_EQ(a->GetNumberOfTuples(), 3);
  EXPECT_EQ(a->GetComponent(2, 0), 0.0);
  EXPECT_NE(a->GetComponent(1, 0), 0.0); // its neighbour moves
}

TEST(DipoleFieldSource, ReportsProgressAndStopsWithAnEmptyOutputWhenAborted)
{
  for (bool abort : { false, true })
  {
    vtkNew<vtkDipoleFieldSource> source;
    source->SetDimensions(64, 64, 40); // 163840 points: 3 blocks (vtkBoostedBlockLoop: 65536 a block)
    vtkNew<vtkCallbackCommand> onProgress;
    ProgressLog log;
    log.abortOnFirst = abort;
    onProgress->SetCallback(ProgressLog::Callback);
    onProgress->SetClientData(&log);
    source->AddObserver(vtkCommand::ProgressEvent, onProgress);
    source->Update();
    std::vector<double> blockProgress;
    for (double value : log.values)
    {
      if (value > 0.0 && value < 1.0 + 1e-12)
      {
        blockProgress.push_back(value);
      }
    }
    if (!abort)
    {
      EXPECT_EQ(blockProgress.size(), 3u + 1); // and the executive's 1 at the end
      EXPECT_DOUBLE_EQ(log.values.back(), 1.0);
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 64 * 64 * 40);
    }
    else
    {
      EXPECT_LT(blockProgress.size(), 3u);
      EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
    }
  }
}

TEST(DipoleFieldSource, GeneratorsTranslationMovesEveryGenerator)
{
  vtkNew<vtkDipoleFieldSource> moved;
  addFig14Generators(moved);
  moved->SetGeneratorsTranslation(0.3, -0.4, 0.1);
  moved->Update();
  vtkNew<vtkDipoleFieldSource> placed;
  placed->RemoveAllGenerators();
  placed->AddGenerator(-0.7, -0.4, 0.1, 0, 1, 0, 0.35);
  placed->AddGenerator(1.3, -0.4, 0.1, 1, 0, 0, 0.35);
  placed->Update();
  expectEqualArrays(moved->GetOutput(), placed->GetOutput(), 1e-13);
}

// The line widget's row: at SelectedGeneratorLocation (not moved by GeneratorsTranslation) and
// aimed at SelectedGeneratorTip, it gives the field and the Generators port of a list whose row
// is written out there (translated back), with the direction tip - location.
TEST(DipoleFieldSource, TheSelectedGeneratorIsAtTheLinesStartAndAimedAtItsEnd)
{
  const double translation[3] = { 0.3, -0.4, 0.1 };
  const double location[3] = { 0.6, 0.5, 0.0 };
  const double tip[3] = { 0.2, 1.5, 0.5 };
  vtkNew<vtkDipoleFieldSource> selected, written;
  for (vtkDipoleFieldSource* source : { selected.Get(), written.Get() })
  {
    source->RemoveAllGenerators();
    source->SetGeneratorsTranslation(translation);
    source->AddGenerator(-1, 0, 0, 0, 1, 0, 0.35);
  }
  selected->AddGenerator(1, 0, 0, 1, 0, 0, 0.35);
  selected->SetSelectedGenerator(1);
  selected->SetSelectedGeneratorLocation(location);
  selected->AimSelectedGeneratorOn();
  selected->SetSelectedGeneratorTip(tip);
  written->AddGenerator(location[0] - translation[0], location[1] - translation[1],
    location[2] - translation[2], tip[0] - location[0], tip[1] - location[1], tip[2] - location[2],
    0.35);
  selected->Update();
  written->Update();
  expectEqualArrays(selected->GetOutput(), written->GetOutput(), 1e-13);
  // The Generators port: the selected row at the line's start, along the line.
  auto* glyphs = vtkPolyData::SafeDownCast(selected->GetOutputDataObject(1));
  ASSERT_EQ(glyphs->GetNumberOfPoints(), 2);
  double point[3];
  glyphs->GetPoint(1, point);
  vtkDataArray* direction = glyphs->GetPointData()->GetArray("Direction");
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(point[c], location[c]);
    EXPECT_EQ(direction->GetComponent(1, c), tip[c] - location[c]);
  }
  // Without the aim the table's direction stays; the list itself is unchanged either way.
  selected->AimSelectedGeneratorOff();
  selected->Update();
  glyphs = vtkPolyData::SafeDownCast(selected->GetOutputDataObject(1));
  direction = glyphs->GetPointData()->GetArray("Direction");
  EXPECT_EQ(direction->GetComponent(1, 0), 1.0);
  EXPECT_EQ(direction->GetComponent(1, 1), 0.0);
  double values[9];
  ASSERT_TRUE(selected->GetGenerator(1, values));
  EXPECT_EQ(values[0], 1.0);
  EXPECT_EQ(values[3], 1.0);
}

// The README's DipolePotential, phi(p) = s sum_i w_i (v_i . (p - x_i)) / (|p - x_i|^2 + eps),
// written out at every grid point: with the translation, a time step's weight scale, and the
// same values whatever the falloff, the method and the exponential rule.
TEST(DipoleFieldSource, PotentialIsTheClosedFormSumOfDipolePotentials)
{
  const double generators[3][7] = { { -1, 0, 0, 0, 1, 0, 0.35 }, { 1, 0, 0, 1, 0, 0, 0.35 },
    { 0.2, 0.7, 0.1, 0.5, -2.0, 1.0, -1.25 } };
  const double translation[3] = { 0.3, -0.4, 0.1 };
  const double eps = 0.07, s = 0.5;
  for (int rule : { vtkDipoleFieldSource::EXACT, vtkDipoleFieldSource::PAPER })
  {
    for (double falloff : { 0.0, 2.5 })
    {
      vtkNew<vtkDipoleFieldSource> source;
      source->RemoveAllGenerators();
      for (const auto& g : generators)
      {
        source->AddGenerator(g[0], g[1], g[2], g[3], g[4], g[5], g[6]);
      }
      source->SetGeneratorsTranslation(translation[0], translation[1], translation[2]);
      source->SetEpsilon(eps);
      source->SetFalloff(falloff);
      source->SetExponentialRule(rule);
      source->SetDimensions(9, 7, 3);
      source->SetSpacing(0.5, 0.5, 0.5);
      source->SetOrigin(-2, -1.5, -0.5);
      source->SetNumberOfTimeSteps(3); // t = 0, 0.5, 1
      source->UpdateTimeStep(s);
      vtkImageData* output = source->GetOutput();
      vtkDataArray* phi = output->GetPointData()->GetArray("DipolePotential");
      ASSERT_NE(phi, nullptr);
      ASSERT_EQ(phi->GetNumberOfTuples(), 9 * 7 * 3);
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        double p[3];
        output->GetPoint(i, p);
        double expected = 0.0, size = 0.0;
        for (const auto& g : generators)
        {
          double r[3];
          for (int c = 0; c < 3; ++c)
          {
            r[c] = p[c] - (g[c] + translation[c]);
          }
          const double term = s * g[6] * vtkMath::Dot(g + 3, r) / (vtkMath::Dot(r, r) + eps);
          expected += term;
          size += std::fabs(term);
        }
        EXPECT_NEAR(phi->GetTuple1(i), expected, 1e-13 * (1.0 + size)) << "point " << i;
      }
    }
  }
}

TEST(DipoleFieldSource, OutOfRangePiecesAreEmpty)
{
  ExpectOutOfRangePiecesEmpty<vtkDipoleFieldSource>([](vtkDipoleFieldSource*) {});
}

TEST(DipoleFieldSource, AGridNearTheLargestDoubleIsAnErrorOnlyWhereItOverflows)
{
  // Origin -1e308, 20 steps of 5e306: the grid ends at 0, every point finite.
  vtkNew<vtkDipoleFieldSource> source;
  EventCounter counter(source);
  source->SetOrigin(-1e308, 0, 0);
  source->SetSpacing(5e306, 0.2, 1);
  source->Update();
  EXPECT_EQ(counter.errors, 0) << counter.lastError;
  vtkImageData* output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 21 * 21);
  double bounds[6];
  output->GetBounds(bounds);
  for (double b : bounds)
  {
    EXPECT_TRUE(std::isfinite(b));
  }
  EXPECT_EQ(bounds[0], -1e308);
  EXPECT_EQ(bounds[1], -1e308 + 20 * 5e306);

  // One step more overflows: an error naming it, and an empty output with no bounds.
  source->SetDimensions(22, 21, 1);
  source->SetSpacing(1e307, 0.2, 1);
  source->SetOrigin(-1e308, 0, 0);
  source->Update();
  EXPECT_EQ(counter.errors, 1);
  EXPECT_NE(counter.lastError.find("the grid overflows"), std::string::npos) << counter.lastError;
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
}

namespace
{
// One rotation row (docs/conventions.md section 2 item 11): both methods are the turn of every
// grid point by w |v| / (k |p - x|^2 + eps) about the axis (Rodrigues' formula), and the
// potential, which only point pairs have, is zero. An unknown kind is an error.
TEST(DipoleFieldSource, ARotationRowTurnsTheGridAndHasNoPotential)
{
  vtkNew<vtkDipoleFieldSource> source;
  source->RemoveAllGenerators();
  const double x[3] = { 0.3, -0.2, 0.1 }, v[3] = { 0.0, 0.6, 0.8 };
  const double w = 0.9, k = 1.5, eps = 0.05;
  source->AddGenerator(x[0], x[1], x[2], v[0], v[1], v[2], w, vtkDipoleFieldSource::ROTATION, 0.0);
  source->SetFalloff(k);
  source->SetEpsilon(eps);
  source->SetDimensions(9, 7, 2);
  source->Update();
  vtkImageData* output = source->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 9 * 7 * 2);
  vtkDataArray* summed = output->GetPointData()->GetArray("DisplacementSummedGenerators");
  vtkDataArray* single = output->GetPointData()->GetArray("DisplacementSummedDisplacements");
  vtkDataArray* potential = output->GetPointData()->GetArray("DipolePotential");
  double largest = 0.0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], y[3], axisCrossY[3];
    output->GetPoint(i, p);
    vtkMath::Subtract(p, x, y);
    const double angle = w * vtkMath::Norm(v) / (k * vtkMath::Dot(y, y) + eps);
    double axis[3] = { v[0], v[1], v[2] };
    vtkMath::Normalize(axis);
    vtkMath::Cross(axis, y, axisCrossY);
    const double along = vtkMath::Dot(axis, y);
    for (int c = 0; c < 3; ++c)
    {
      const double turned = std::cos(angle) * y[c] + std::sin(angle) * axisCrossY[c] +
        (1.0 - std::cos(angle)) * along * axis[c];
      const double expected = turned - y[c];
      EXPECT_NEAR(summed->GetComponent(i, c), expected, 1e-12);
      EXPECT_NEAR(single->GetComponent(i, c), expected, 1e-12);
      largest = std::max(largest, std::fabs(expected));
    }
    EXPECT_EQ(potential->GetComponent(i, 0), 0.0);
  }
  EXPECT_GT(largest, 0.1);

  source->SetGenerator(0, x[0], x[1], x[2], v[0], v[1], v[2], w, 5, 0.0);
  EventCounter counter(source);
  source->Update();
  EXPECT_EQ(counter.errors, 1);
  EXPECT_NE(counter.lastError.find("generator row 0 has the kind"), std::string::npos)
    << counter.lastError;
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
}
} // namespace

namespace
{
// Two generators of each kind with huge weights and directions: in double every array stays
// finite (values saturate at the largest double) and nothing is an error; in single precision
// the same arrays are either the double ones as floats (no error) or, when the double ones go
// beyond the largest float, the single-precision error and an empty output.
TEST(DipoleFieldSource, HugeWeightsOfEveryKindGiveFiniteArraysOrTheSinglePrecisionError)
{
  for (int kind = vtkDipoleFieldSource::POINT_PAIR; kind <= vtkDipoleFieldSource::TRANSLATION; ++kind)
  {
    for (double weight : { 1e308, -1e308, 1e150, 1e40, 1e-3 })
    {
      for (double length : { 1.0, 1e200 })
      {
        double largestInDouble = 0.0;
        for (int precision : { vtkAlgorithm::DOUBLE_PRECISION, vtkAlgorithm::SINGLE_PRECISION })
        {
          SCOPED_TRACE("kind " + std::to_string(kind) + " weight " + std::to_string(weight) +
            " length " + std::to_string(length) + " precision " + std::to_string(precision));
          vtkNew<vtkDipoleFieldSource> source;
          EventCounter counter(source);
          source->RemoveAllGenerators();
          source->AddGenerator(0.1, 0.2, 0.3, 0, 0, length, weight, kind, 0.5);
          source->AddGenerator(0.1, 0.25, 0.3, 0, 0, length, weight, kind, 0.5);
          source->SetDimensions(6, 5, 1);
          source->SetOutputPointsPrecision(precision);
          source->Update();
          vtkPointData* pointData = source->GetOutput()->GetPointData();
          const bool beyondFloat = largestInDouble > std::numeric_limits<float>::max();
          if (precision == vtkAlgorithm::SINGLE_PRECISION && beyondFloat)
          {
            EXPECT_EQ(counter.errors, 1);
            EXPECT_NE(counter.lastError.find("OutputPointsPrecision"), std::string::npos);
            EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
            continue;
          }
          EXPECT_EQ(counter.errors, 0) << counter.lastError;
          ASSERT_EQ(pointData->GetNumberOfArrays(), 5);
          for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
          {
            vtkDataArray* array = pointData->GetArray(a);
            for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
            {
              const double value = array->GetComponent(i / array->GetNumberOfComponents(),
                static_cast<int>(i % array->GetNumberOfComponents()));
              EXPECT_TRUE(std::isfinite(value)) << array->GetName();
              largestInDouble = std::max(largestInDouble, std::fabs(value));
            }
          }
        }
      }
    }
  }
}
} // namespace

TEST(DipoleFieldSource, TranslatingGridAndGeneratorsLeavesTheFieldAsItIs)
{
  // The Fig 14 pair and a tilted third generator, the grid origin and the generators moved by t
  // (GeneratorsTranslation): every displacement and the potential
  // stay what they were (the bound: TranslationChecks.h, with the field's derivative bounded by
  // sum_i |w_i v_i| / eps = (0.35 + 0.35 + 0.4 |(0.5, -2, 1)|) / 0.1 < 16). Both rules.
  for (int rule : { vtkDipoleFieldSource::EXACT, vtkDipoleFieldSource::PAPER })
  {
    SCOPED_TRACE("rule " + std::to_string(rule));
    ExpectTranslationCovariant(
      [rule](const double t[3]) {
        vtkNew<vtkDipoleFieldSource> source;
        addFig14Generators(source);
        source->AddGenerator(0.2, 0.7, 0.1, 0.5, -2.0, 1.0, -0.4);
        source->SetGeneratorsTranslation(t[0], t[1], t[2]);
        source->SetOrigin(-2 + t[0], -2 + t[1], -0.2 + t[2]);
        source->SetDimensions(21, 21, 3);
        source->SetSpacing(0.2, 0.2, 0.2);
        source->SetExponentialRule(rule);
        source->Update();
        return vtkSmartPointer<vtkDataSet>(source->GetOutput());
      },
      { std::begin(ArrayNames), std::end(ArrayNames) }, 16.0);
  }
}

TEST(DipoleFieldSource, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  // A weight of 1e300 saturates the potential near 1e300 (documented, in double): as floats the
  // arrays would hold inf, so single precision is an error and an empty output.
  vtkNew<vtkDipoleFieldSource> source;
  EventCounter events(source);
  source->RemoveAllGenerators();
  source->AddGenerator(0.1, 0, 0, 1, 0, 0, 1e300);
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_NE(events.lastError.find("OutputPointsPrecision"), std::string::npos) << events.lastError;
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(source->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  EXPECT_EQ(events.errors, 1) << events.lastError;
  vtkDataArray* potential = source->GetOutput()->GetPointData()->GetArray("DipolePotential");
  ASSERT_TRUE(potential);
  EXPECT_GT(LargestValue(potential), 1e300);
}

TEST(DipoleFieldSource, TheGeneratorsOutputIsBuiltAnewOnlyWhenTheGeneratorsChange)
{
  // The grid and the falloff change the field, not the generators; GeneratorsTranslation moves
  // them.
  ExpectGeneratorGlyphsCached(1,
    [] {
      auto source = vtkSmartPointer<vtkDipoleFieldSource>::New();
      source->AddGenerator(0.5, 0.25, 0, 0, 1, 0, 0.75, vtkDipoleFieldSource::TWIST, 0.2);
      return source;
    },
    [](vtkDipoleFieldSource* source) {
      source->SetDimensions(9, 7, 1);
      source->SetFalloff(0.5);
    },
    [](vtkDipoleFieldSource* source) { source->SetGeneratorsTranslation(0, 0, 0.125); });
}
