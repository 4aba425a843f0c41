// The generator kinds of vtkPointPairDeformationFilter (docs/conventions.md section 2 item 11):
// rows of every kind, from the list and from the Generators input's Kind and Pitch arrays,
// against the full multivector product, and the kinds' bad input.
#include "vtkPointPairDeformationFilter.h"

#include "DeformedOutput.h"
#include "EventCounter.h"
#include "GeneratorKindReference.h"
#include "TestSupport.h"
#include "TranslationChecks.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
using cga::GeneratorKind;
using cga::GeneratorParameters;
using cga::Vec3;
using cgatest::Random;
using cgatest::worseOf;

// `count` random points in the cube [-half, half]^3, stored as `pointType`.
vtkNew<vtkPolyData> randomPoints(
  Random& random, int count, double half = 2.0, int pointType = VTK_DOUBLE)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  for (int i = 0; i < count; ++i)
  {
    const Vec3 p = random.vec3(half);
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  mesh->SetPoints(points);
  return mesh;
}

std::vector<GeneratorParameters> randomGenerators(Random& random, int count)
{
  std::vector<GeneratorParameters> generators;
  for (int i = 0; i < count; ++i)
  {
    generators.push_back({ cgatest::kAllKinds[i % 5], random.vec3(1.5), random.unit(),
      random.uniform(-1.0, 1.0), random.uniform(-0.6, 0.6) });
  }
  return generators;
}

void addRows(vtkPointPairDeformationFilter* filter, const std::vector<GeneratorParameters>& list)
{
  for (const GeneratorParameters& g : list)
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight, static_cast<double>(g.kind), g.pitch);
  }
}

// The generators as a point set with Direction, Weight, Kind (an int array) and Pitch arrays.
vtkNew<vtkPolyData> generatorPoints(const std::vector<GeneratorParameters>& generators)
{
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> directions, weights, pitches;
  vtkNew<vtkIntArray> kinds;
  directions->SetName("Direction");
  directions->SetNumberOfComponents(3);
  weights->SetName("Weight");
  kinds->SetName("Kind");
  pitches->SetName("Pitch");
  for (const GeneratorParameters& g : generators)
  {
    points->InsertNextPoint(g.location.x, g.location.y, g.location.z);
    directions->InsertNextTuple3(g.direction.x, g.direction.y, g.direction.z);
    weights->InsertNextValue(g.weight);
    kinds->InsertNextValue(static_cast<int>(g.kind));
    pitches->InsertNextValue(g.pitch);
  }
  data->SetPoints(points);
  for (vtkDataArray* array : { static_cast<vtkDataArray*>(directions), static_cast<vtkDataArray*>(weights),
         static_cast<vtkDataArray*>(kinds), static_cast<vtkDataArray*>(pitches) })
  {
    data->GetPointData()->AddArray(array);
  }
  return data;
}

Vec3 referenceImage(const cga::Multivector& k, Vec3 p)
{
  Vec3 out{ std::nan(""), 0, 0 };
  EXPECT_TRUE(cga::normalizePoint(cga::sandwich(k, cga::up(p)).grade(1), out));
  return out;
}

TEST(PointPairDeformationKinds, RowsOfEveryKindMatchTheFullProduct)
{
  Random random(41);
  auto mesh = randomPoints(random, 60);
  const auto generators = randomGenerators(random, 10);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  addRows(filter, generators);
  filter->SetFalloff(1.5);
  filter->SetEpsilon(0.05);
  filter->SetStrength(0.8);
  filter->Update();
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const Vec3 p = pointOf(mesh, i);
    const Vec3 expected =
      referenceImage(cga::expSeries(cgatest::referenceField(generators, p, 1.5, 0.05) * -0.8), p);
    EXPECT_LE(cga::norm(pointOf(filter->GetOutput(), i) - expected), 1e-12 * (1.0 + cga::norm(expected)));
  }
}

TEST(PointPairDeformationKinds, KindAndPitchArraysOfTheGeneratorsInputAreTheRows)
{
  Random random(42);
  auto mesh = randomPoints(random, 30);
  const auto generators = randomGenerators(random, 10);
  vtkNew<vtkPointPairDeformationFilter> fromList, fromPort, withoutKinds, pointPairs;
  for (vtkPointPairDeformationFilter* filter :
    { fromList.Get(), fromPort.Get(), withoutKinds.Get(), pointPairs.Get() })
  {
    filter->SetInputData(mesh);
  }
  addRows(fromList, generators);
  fromPort->SetGeneratorsData(generatorPoints(generators));
  fromPort->UseGeneratorWeightArrayOn();
  // Without a Kind array (another name) every generator of the input is a point pair.
  withoutKinds->SetGeneratorsData(generatorPoints(generators));
  withoutKinds->UseGeneratorWeightArrayOn();
  withoutKinds->SetGeneratorKindArrayName("NoSuchArray");
  for (GeneratorParameters g : generators)
  {
    g.kind = GeneratorKind::PointPair;
    addRows(pointPairs, { g });
  }
  for (vtkPointPairDeformationFilter* filter :
    { fromList.Get(), fromPort.Get(), withoutKinds.Get(), pointPairs.Get() })
  {
    filter->Update();
  }
  double largestKindEffect = 0.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(cga::norm(pointOf(fromPort->GetOutput(), i) - pointOf(fromList->GetOutput(), i)), 0.0);
    EXPECT_EQ(
      cga::norm(pointOf(withoutKinds->GetOutput(), i) - pointOf(pointPairs->GetOutput(), i)), 0.0);
    largestKindEffect = worseOf(largestKindEffect,
      cga::norm(pointOf(fromList->GetOutput(), i) - pointOf(pointPairs->GetOutput(), i)));
  }
  EXPECT_GT(largestKindEffect, 1e-3); // the kinds reach the kernel
}

TEST(PointPairDeformationKinds, UnknownKindsAreErrorsWithAnEmptyOutput)
{
  Random random(43);
  auto mesh = randomPoints(random, 5);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double kind : { 5.0, -1.0, 1.5, nan, 1e300 })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
    filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5, kind, 0.0);
    filter->Update();
    EXPECT_EQ(events.errors, 1) << kind;
    EXPECT_NE(events.lastError.find("generator row 1 has the kind"), std::string::npos)
      << events.lastError;
    EXPECT_NE(events.lastError.find("4 (TRANSLATION)"), std::string::npos) << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << kind;
  }
  // In the Generators input's Kind array, and a Kind array of 3 components.
  auto generators = generatorPoints(randomGenerators(random, 3));
  vtkIntArray::SafeDownCast(generators->GetPointData()->GetArray("Kind"))->SetValue(2, 7);
  vtkNew<vtkDoubleArray> threeComponents;
  threeComponents->SetName("Kind3");
  threeComponents->SetNumberOfComponents(3);
  threeComponents->SetNumberOfTuples(3);
  threeComponents->Fill(1.0);
  generators->GetPointData()->AddArray(threeComponents);
  for (const char* name : { "Kind", "Kind3" })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->SetGeneratorsData(generators);
    filter->SetGeneratorKindArrayName(name);
    filter->Update();
    EXPECT_EQ(events.errors, 1) << name;
    EXPECT_NE(events.lastError.find(std::string(name) == "Kind" ? "point 2 ('Kind') has the kind 7"
                                                                 : "1 component (kinds)"),
      std::string::npos)
      << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << name;
  }
}

TEST(PointPairDeformationKinds, ZeroPitchTwistIsARotationAndBadTwistsAreIgnored)
{
  Random random(44);
  auto mesh = randomPoints(random, 20);
  vtkNew<vtkPointPairDeformationFilter> twist, rotation, badTwists;
  for (vtkPointPairDeformationFilter* filter : { twist.Get(), rotation.Get(), badTwists.Get() })
  {
    filter->SetInputData(mesh);
  }
  twist->AddGenerator(0.2, 0.1, 0, 0, 0.6, 0.8, 0.7, vtkPointPairDeformationFilter::TWIST, 0.0);
  rotation->AddGenerator(0.2, 0.1, 0, 0, 0.6, 0.8, 0.7, vtkPointPairDeformationFilter::ROTATION, 0.0);
  badTwists->AddGenerator(0.2, 0.1, 0, 0, 0.6, 0.8, 0.7, vtkPointPairDeformationFilter::ROTATION, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  badTwists->AddGenerator(0, 0, 0, 0, 0, 1, 0.5, vtkPointPairDeformationFilter::TWIST, nan);
  badTwists->AddGenerator(0, 0, 0, 0, 0, 1, 0.5, vtkPointPairDeformationFilter::TWIST, inf);
  badTwists->AddGenerator(0, 0, 0, 0, 0, 0, 0.5, vtkPointPairDeformationFilter::DILATION, 0.0);
  EventCounter events(badTwists);
  for (vtkPointPairDeformationFilter* filter : { twist.Get(), rotation.Get(), badTwists.Get() })
  {
    filter->Update();
  }
  EXPECT_EQ(events.errors, 0);
  EXPECT_EQ(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find("3 of 4 generators were ignored"), std::string::npos)
    << events.lastWarning;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(cga::norm(pointOf(twist->GetOutput(), i) - pointOf(rotation->GetOutput(), i)), 0.0);
    EXPECT_EQ(cga::norm(pointOf(badTwists->GetOutput(), i) - pointOf(rotation->GetOutput(), i)), 0.0);
  }
}
} // namespace

namespace
{
// Huge weights and directions of every kind: translations, twists and dilations send points
// far away. In double the output stays finite (points sent beyond the largest double are left in
// place and counted in the one warning); float points (the default precision keeps floats) give
// the same images as floats, or the single-precision error and an empty output exactly when the
// double images or displacements go beyond the largest float.
TEST(PointPairDeformationKinds, HugeWeightsOfEveryKindGiveFiniteOutputOrTheSinglePrecisionError)
{
  Random random(45);
  for (int pointType : { VTK_FLOAT, VTK_DOUBLE })
  {
    auto mesh = randomPoints(random, 20, 2.0, pointType);
    for (GeneratorKind kind : cgatest::kAllKinds)
    {
      for (double weight : { 1e308, -1e308, 1e150, 1e40, 1e-3 })
      {
        for (double length : { 1.0, 1e200, 1e-200 })
        {
          SCOPED_TRACE("kind " + std::to_string(static_cast<int>(kind)) + " weight " +
            std::to_string(weight) + " length " + std::to_string(length) + " points " +
            std::to_string(pointType));
          double largestInDouble = 0.0;
          for (int precision : { vtkAlgorithm::DOUBLE_PRECISION, vtkAlgorithm::DEFAULT_PRECISION })
          {
            vtkNew<vtkPointPairDeformationFilter> filter;
            EventCounter events(filter);
            filter->SetInputData(mesh);
            filter->SetOutputPointsPrecision(precision);
            filter->AddGenerator(0.1, 0.2, 0.3, 0, 0.6 * length, 0.8 * length, weight,
              static_cast<double>(kind), 0.5);
            filter->Update();
            vtkPointSet* output = filter->GetOutput();
            const bool single = precision == vtkAlgorithm::DEFAULT_PRECISION && pointType == VTK_FLOAT;
            if (single && largestInDouble > std::numeric_limits<float>::max())
            {
              EXPECT_EQ(events.errors, 1);
              EXPECT_NE(events.lastError.find("OutputPointsPrecision"), std::string::npos)
                << events.lastError;
              EXPECT_EQ(output->GetNumberOfPoints(), 0);
              continue;
            }
            ASSERT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
            EXPECT_EQ(events.errors, 0) << events.lastError;
            vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
            for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
            {
              const Vec3 p = pointOf(output, i);
              EXPECT_TRUE(cga::isFinite(p));
              double d[3];
              displacement->GetTuple(i, d);
              EXPECT_TRUE(std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2]));
              for (double value : { p.x, p.y, p.z, d[0], d[1], d[2] })
              {
                largestInDouble = worseOf(largestInDouble, std::fabs(value));
              }
            }
          }
        }
      }
    }
  }
}
} // namespace

namespace
{
// Rows of every kind, mixed, on a mesh, all moved by t: the output moves by t and Displacement
// stays (the field builds every kind at its location relative to the field's center; the bound:
// TranslationChecks.h, the derivative bounded by sum_i |w_i| max(1, |pitch|) |v_i| / eps < 40).
TEST(PointPairDeformationKinds, TranslatingRowsOfEveryKindAndTheMeshTranslatesTheOutput)
{
  Random random(91);
  auto mesh = randomPoints(random, 30, 1.5);
  struct Row
  {
    Vec3 location, direction;
    double weight, kind, pitch;
  };
  std::vector<Row> rows;
  for (GeneratorKind kind : cgatest::kAllKinds)
  {
    rows.push_back({ random.vec3(1.0), random.vec3(1.0), 0.2, static_cast<double>(kind), 0.3 });
  }
  for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
  {
    SCOPED_TRACE("rule " + std::to_string(rule));
    ExpectTranslationCovariant(
      [&](const double t[3]) {
        vtkNew<vtkPointPairDeformationFilter> filter;
        filter->SetInputData(TranslatedCopy(mesh, t));
        filter->SetEpsilon(0.05);
        for (const Row& r : rows)
        {
          filter->AddGenerator(r.location.x + t[0], r.location.y + t[1], r.location.z + t[2],
            r.direction.x, r.direction.y, r.direction.z, r.weight, r.kind, r.pitch);
        }
        filter->SetExponentialRule(rule);
        filter->Update();
        return vtkSmartPointer<vtkDataSet>(filter->GetOutput());
      },
      { "Displacement" }, 40.0);
  }
}
} // namespace
