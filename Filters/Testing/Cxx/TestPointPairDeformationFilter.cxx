// vtkPointPairDeformationFilter against independent references: the full multivector product with
// a series exponential (Exact) or eq 9-10 written out (Paper), the closed form of one generator
// (docs/conventions.md section 2), null image points and angle preservation; and its bad-input behaviour.
#include "vtkPointPairDeformationFilter.h"

#include "DeformedOutput.h"
#include "EventCounter.h"
#include "GeneratorGlyphCacheChecks.h"
#include "ProgressLog.h"
#include "TranslationChecks.h"
#include "vtkAOSDataArrayTemplate.h"
#include "vtkBoostedBlockLoop.h"
#include "TestSupport.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkStructuredGrid.h"

#include "cga/CompactConversion.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointPairField.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
using cga::Multivector;
using cga::Vec3;

struct Generator
{
  Vec3 location, direction;
  double weight;
};

using cgatest::Random; // the kernel tests' seeded inputs (CGA/Testing/TestSupport.h)
using cgatest::worseOf; // a running maximum that keeps a NaN

std::vector<Generator> randomGenerators(Random& random, int count, double maxWeight)
{
  std::vector<Generator> generators;
  for (int i = 0; i < count; ++i)
  {
    generators.push_back({ random.vec3(1.5), random.unit(), random.uniform(-maxWeight, maxWeight) });
  }
  return generators;
}

// The same generators as the kernel's type, for a cga::PointPairField reference.
std::vector<cga::PointPairGenerator> kernelGeneratorsOf(const std::vector<Generator>& generators)
{
  std::vector<cga::PointPairGenerator> kernelGenerators;
  for (const Generator& g : generators)
  {
    kernelGenerators.push_back({ g.location, g.direction, g.weight });
  }
  return kernelGenerators;
}

// Random points joined into triangles (every three consecutive points), with a scalar point
// array, a Normals array and a cell array, so that the passing of arrays can be checked.
vtkNew<vtkPolyData> randomMesh(Random& random, int triangles, double half, int pointType = VTK_DOUBLE)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("Scalars");
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> cellIds;
  cellIds->SetName("CellIds");
  for (int t = 0; t < triangles; ++t)
  {
    vtkIdType ids[3];
    for (vtkIdType& id : ids)
    {
      const Vec3 p = random.vec3(half);
      id = points->InsertNextPoint(p.x, p.y, p.z);
      scalars->InsertNextValue(static_cast<double>(id));
      normals->InsertNextTuple3(0, 0, 1);
    }
    cells->InsertNextCell(3, ids);
    cellIds->InsertNextValue(t);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->AddArray(scalars);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetCellData()->AddArray(cellIds);
  return mesh;
}

void addGenerators(vtkPointPairDeformationFilter* filter, const std::vector<Generator>& generators)
{
  for (const Generator& g : generators)
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
}

// B(p) on the full multivector, from the definition.
Multivector referenceField(const std::vector<Generator>& generators, Vec3 p, double k, double eps)
{
  Multivector b;
  for (const Generator& g : generators)
  {
    b += cga::nullPointPair(g.location, g.direction) *
      (g.weight / (k * cga::norm2(p - g.location) + eps));
  }
  return b;
}

// Eq 9-10 with s = <B B>_0, written out.
Multivector paperExp(const Multivector& b)
{
  const double s = (b * b).c[0];
  if (s > 0.0)
  {
    return Multivector::scalar(std::cosh(std::sqrt(s))) + b * (std::sinh(std::sqrt(s)) / std::sqrt(s));
  }
  if (s < 0.0)
  {
    return Multivector::scalar(std::cos(std::sqrt(-s))) + b * (std::sin(std::sqrt(-s)) / std::sqrt(-s));
  }
  return Multivector::scalar(1.0) + b;
}

Vec3 image(const Multivector& k, Vec3 p)
{
  Vec3 out{ std::nan(""), 0, 0 };
  EXPECT_TRUE(cga::normalizePoint(cga::sandwich(k, cga::up(p)).grade(1), out));
  return out;
}

// |Y.Y| / (ni.Y)^2 for Y = <K up(p) ~K>_1: 0 exactly when the image is a null vector (a point).
double nullDefect(const Multivector& k, Vec3 p)
{
  const Multivector y = cga::sandwich(k, cga::up(p)).grade(1);
  const double scale = (cga::ni() * y).c[0];
  return std::fabs((y * y).c[0]) / (scale * scale);
}

double angleAt(Vec3 a, Vec3 b, Vec3 c)
{
  const Vec3 u = b - a, v = c - a;
  return std::atan2(cga::norm(cga::cross(u, v)), cga::dot(u, v));
}

TEST(PointPairDeformationFilter, BothRulesMatchTheFullProductOnRandomMeshes)
{
  Random random(11);
  for (int trial = 0; trial < 6; ++trial)
  {
    const auto generators = randomGenerators(random, 1 + trial * 2, 0.4);
    const double k = random.uniform(0.2, 2.0), eps = random.uniform(0.02, 0.5);
    const double strength = random.uniform(0.3, 1.5);
    auto mesh = randomMesh(random, 40, 2.0);
    for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      filter->SetInputData(mesh);
      addGenerators(filter, generators);
      filter->SetFalloff(k);
      filter->SetEpsilon(eps);
      filter->SetStrength(strength);
      filter->SetExponentialRule(rule);
      filter->Update();
      vtkPointSet* output = filter->GetOutput();
      ASSERT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
      for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
      {
        const Vec3 p = pointOf(mesh, i);
        const Multivector b = referenceField(generators, p, k, eps) * -strength;
        const Multivector kk =
          rule == vtkPointPairDeformationFilter::EXACT ? cga::expSeries(b) : paperExp(b);
        const Vec3 expected = image(kk, p);
        EXPECT_LE(cga::norm(pointOf(output, i) - expected), 1e-10 * (1.0 + cga::norm(expected)))
          << "rule " << rule << " point " << i;
      }
    }
  }
}

TEST(PointPairDeformationFilter, ExactImagesAreNullPointsAndPaperImagesAreNot)
{
  Random random(12);
  const auto generators = randomGenerators(random, 6, 0.8);
  const cga::PointPairField field(kernelGeneratorsOf(generators), 1.0, 0.05);
  double exactDefect = 0.0, paperDefect = 0.0;
  for (int n = 0; n < 200; ++n)
  {
    const Vec3 p = random.vec3(2.0);
    const Multivector exact =
      cga::toMultivector(field.boostAt(p, 1.0, cga::ExponentialRule::Exact));
    const Multivector paper =
      cga::toMultivector(field.boostAt(p, 1.0, cga::ExponentialRule::Paper));
    exactDefect = worseOf(exactDefect, nullDefect(exact, p));
    paperDefect = worseOf(paperDefect, nullDefect(paper, p));
  }
  EXPECT_LT(exactDefect, 1e-12);
  EXPECT_GT(paperDefect, 1e-6); // the paper's K is not a versor for a sum of generators
}

// With Falloff 0, B is the same at every point, so the filter applies one K to the whole mesh:
// Exact gives a conformal map, so the angles of a small triangle of size h agree to first order
// (the difference shrinks with h), while Paper's map changes angles by O(1).
double largestAngleChange(const std::vector<Generator>& generators, int rule, double h)
{
  Random random(13); // the same triangles, scaled by h, for every call
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (int t = 0; t < 50; ++t)
  {
    const Vec3 p = random.vec3(1.5);
    const Vec3 a = p + h * random.unit(), b = p + h * random.unit();
    vtkIdType ids[3] = { points->InsertNextPoint(p.x, p.y, p.z),
      points->InsertNextPoint(a.x, a.y, a.z), points->InsertNextPoint(b.x, b.y, b.z) };
    cells->InsertNextCell(3, ids);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  addGenerators(filter, generators);
  filter->SetFalloff(0.0);
  filter->SetEpsilon(1.0);
  filter->SetExponentialRule(rule);
  filter->Update();
  vtkPointSet* output = filter->GetOutput();
  double largest = 0.0;
  for (vtkIdType t = 0; t < 50; ++t)
  {
    for (int corner = 0; corner < 3; ++corner)
    {
      const vtkIdType i = 3 * t + corner, j = 3 * t + (corner + 1) % 3, k = 3 * t + (corner + 2) % 3;
      const double before = angleAt(pointOf(mesh, i), pointOf(mesh, j), pointOf(mesh, k));
      const double after = angleAt(pointOf(output, i), pointOf(output, j), pointOf(output, k));
      largest = worseOf(largest, std::fabs(after - before));
    }
  }
  return largest;
}

TEST(PointPairDeformationFilter, ExactKeepsAnglesOfSmallTrianglesPaperDoesNot)
{
  Random random(13);
  const auto generators = randomGenerators(random, 4, 0.6);
  const double exactCoarse = largestAngleChange(generators, vtkPointPairDeformationFilter::EXACT, 1e-4);
  const double exactFine = largestAngleChange(generators, vtkPointPairDeformationFilter::EXACT, 1e-5);
  const double paperCoarse = largestAngleChange(generators, vtkPointPairDeformationFilter::PAPER, 1e-4);
  const double paperFine = largestAngleChange(generators, vtkPointPairDeformationFilter::PAPER, 1e-5);
  EXPECT_LT(exactFine, 0.15 * exactCoarse); // first order: ten times smaller for h ten times smaller
  EXPECT_LT(exactFine, 10.0 * 1e-5); // O(h) with a moderate constant (0.1 rad proved nothing)
  // Not conformal: the change stays as h shrinks.
  EXPECT_GT(paperFine, 1e-4);
  EXPECT_GT(paperFine, 0.5 * paperCoarse);
}

// With Falloff > 0 each point has its own K; that K (the one the filter applied to the point) is
// conformal: a small triangle around the point keeps its angles to first order under it.
TEST(PointPairDeformationFilter, EachPointsExactBoostKeepsAnglesAroundIt)
{
  Random random(14);
  const auto generators = randomGenerators(random, 5, 0.5);
  const cga::PointPairField field(kernelGeneratorsOf(generators), 1.0, 0.05);
  auto mesh = randomMesh(random, 20, 1.5);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  addGenerators(filter, generators);
  filter->SetEpsilon(0.05);
  filter->Update();
  const double h = 1e-5;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const Vec3 p = pointOf(mesh, i);
    const Multivector k = cga::toMultivector(field.boostAt(p, 1.0, cga::ExponentialRule::Exact));
    EXPECT_LE(cga::norm(image(k, p) - pointOf(filter->GetOutput(), i)), 1e-10);
    const Vec3 a = p + h * random.unit(), b = p + h * random.unit();
    const double before = angleAt(p, a, b);
    const double after = angleAt(image(k, p), image(k, a), image(k, b));
    EXPECT_LT(std::fabs(after - before), 1e3 * h);
  }
}

TEST(PointPairDeformationFilter, OneGeneratorIsTheTranslatedSpecialConformalTransformation)
{
  Random random(15);
  for (int n = 0; n < 20; ++n)
  {
    const Vec3 x = random.vec3(1.0), v = random.uniform(0.2, 2.0) * random.unit();
    const double w = random.uniform(-1.0, 1.0), k = random.uniform(0.0, 2.0);
    const double eps = random.uniform(0.01, 1.0);
    auto mesh = randomMesh(random, 5, 2.0);
    for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      filter->SetInputData(mesh);
      filter->AddGenerator(x.x, x.y, x.z, v.x, v.y, v.z, w);
      filter->SetFalloff(k);
      filter->SetEpsilon(eps);
      filter->SetExponentialRule(rule);
      filter->Update();
      for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
      {
        const Vec3 p = pointOf(mesh, i), y = p - x;
        const Vec3 u = (-w / (k * cga::norm2(y) + eps)) * v; // K = 1 + tau(x, u)
        const Vec3 expected =
          x + (y + cga::norm2(y) * u) / (1.0 + 2.0 * cga::dot(u, y) + cga::norm2(u) * cga::norm2(y));
        EXPECT_LE(cga::norm(pointOf(filter->GetOutput(), i) - expected),
          1e-12 * (1.0 + cga::norm(expected)));
      }
    }
  }
}

TEST(PointPairDeformationFilter, KeepsCellsAndArraysAddsDisplacementTransformsNormals)
{
  Random random(16);
  auto mesh = randomMesh(random, 30, 1.0);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  addGenerators(filter, randomGenerators(random, 3, 0.5));
  filter->Update();
  auto* output = vtkPolyData::SafeDownCast(filter->GetOutput());
  ASSERT_NE(output, nullptr);
  EXPECT_EQ(output->GetNumberOfCells(), mesh->GetNumberOfCells());
  EXPECT_EQ(output->GetPolys()->GetNumberOfConnectivityIds(),
    mesh->GetPolys()->GetNumberOfConnectivityIds());
  EXPECT_NE(output->GetPointData()->GetArray("Scalars"), nullptr);
  EXPECT_NE(output->GetCellData()->GetArray("CellIds"), nullptr);
  // The normals go through the map's derivative (TestPointPairDeformationDerivatives checks
  // their values): a new array, the output's active normals.
  ASSERT_NE(output->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(output->GetPointData()->GetArray("Normals"), output->GetPointData()->GetNormals());
  EXPECT_NE(output->GetPointData()->GetNormals(), mesh->GetPointData()->GetNormals());
  vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
  ASSERT_NE(displacement, nullptr);
  double moved = 0.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const Vec3 d = pointOf(output, i) - pointOf(mesh, i);
    double stored[3];
    displacement->GetTuple(i, stored);
    EXPECT_EQ(stored[0], d.x);
    EXPECT_EQ(stored[1], d.y);
    EXPECT_EQ(stored[2], d.z);
    moved = std::max(moved, cga::norm(d));
  }
  EXPECT_GT(moved, 1e-3);
}

TEST(PointPairDeformationFilter, OutputPrecisionFollowsTheInputOrTheSetting)
{
  Random random(17);
  auto floatMesh = randomMesh(random, 10, 1.0, VTK_FLOAT);
  vtkNew<vtkPolyData> doubleMesh;
  doubleMesh->DeepCopy(floatMesh);
  vtkNew<vtkPoints> doublePoints;
  doublePoints->SetDataTypeToDouble();
  doublePoints->DeepCopy(floatMesh->GetPoints());
  doubleMesh->SetPoints(doublePoints);
  const auto generators = randomGenerators(random, 3, 0.5);
  auto run = [&](vtkPolyData* mesh, int precision) {
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    addGenerators(filter, generators);
    filter->SetOutputPointsPrecision(precision);
    filter->Update();
    vtkSmartPointer<vtkPointSet> output = filter->GetOutput();
    return output;
  };
  auto sameAsFloat = run(floatMesh, vtkAlgorithm::DEFAULT_PRECISION);
  auto sameAsDouble = run(doubleMesh, vtkAlgorithm::DEFAULT_PRECISION);
  auto floatToDouble = run(floatMesh, vtkAlgorithm::DOUBLE_PRECISION);
  auto doubleToFloat = run(doubleMesh, vtkAlgorithm::SINGLE_PRECISION);
  EXPECT_EQ(sameAsFloat->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(sameAsDouble->GetPoints()->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(floatToDouble->GetPoints()->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(doubleToFloat->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(floatToDouble->GetPointData()->GetArray("Displacement")->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(sameAsFloat->GetPointData()->GetArray("Displacement")->GetDataType(), VTK_FLOAT);
  for (vtkIdType i = 0; i < floatMesh->GetNumberOfPoints(); ++i)
  {
    const Vec3 reference = pointOf(sameAsDouble, i); // the same float input values, in double
    EXPECT_EQ(cga::norm(pointOf(floatToDouble, i) - reference), 0.0);
    EXPECT_LE(cga::norm(pointOf(sameAsFloat, i) - reference), 1e-6 * (1.0 + cga::norm(reference)));
    EXPECT_LE(cga::norm(pointOf(doubleToFloat, i) - reference), 1e-6 * (1.0 + cga::norm(reference)));
  }
}

// An implicit point array: each value is computed when read, by a function of its index (VTK 9.2
// has no vtkImplicitArray; this is the smallest vtkGenericDataArray that is one). Read-only.
template <typename ValueT>
class FunctionArray : public vtkGenericDataArray<FunctionArray<ValueT>, ValueT>
{
  using GenericDataArrayType = vtkGenericDataArray<FunctionArray<ValueT>, ValueT>;

public:
  using SelfType = FunctionArray<ValueT>;
  vtkAbstractTemplateTypeMacro(SelfType, GenericDataArrayType);
  vtkAOSArrayNewInstanceMacro(SelfType);
  static FunctionArray* New() { VTK_STANDARD_NEW_BODY(FunctionArray); }

  std::function<ValueT(vtkIdType valueIndex)> Function;

  ValueT GetValue(vtkIdType valueIndex) const { return this->Function(valueIndex); }
  void GetTypedTuple(vtkIdType tuple, ValueT* values) const
  {
    for (int c = 0; c < this->NumberOfComponents; ++c)
    {
      values[c] = this->GetTypedComponent(tuple, c);
    }
  }
  ValueT GetTypedComponent(vtkIdType tuple, int c) const
  {
    return this->Function(tuple * this->NumberOfComponents + c);
  }
  void SetValue(vtkIdType, ValueT) { ADD_FAILURE() << "the input was written to"; }
  void SetTypedTuple(vtkIdType, const ValueT*) { ADD_FAILURE() << "the input was written to"; }
  void SetTypedComponent(vtkIdType, int, ValueT) { ADD_FAILURE() << "the input was written to"; }

protected:
  FunctionArray() = default;
  ~FunctionArray() override = default;
  bool AllocateTuples(vtkIdType) { return true; }
  bool ReallocateTuples(vtkIdType) { return true; }
  friend GenericDataArrayType;
};

// Coordinate `index` (xyz interleaved) of a scattered cloud in [-1.5, 1.5]^3, with a NaN point.
double cloudCoordinate(vtkIdType index)
{
  return index == 3 * 1234 + 1 ? std::numeric_limits<double>::quiet_NaN()
                               : 1.5 * std::sin(0.7 + 1.37 * static_cast<double>(index));
}

// A point cloud whose points are held by `array`.
vtkNew<vtkPolyData> cloudOf(vtkDataArray* array)
{
  vtkNew<vtkPoints> points;
  points->SetData(array);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  return cloud;
}

// The cloud's coordinates, rounded to T, in a new array of the given layout.
template <typename T>
vtkSmartPointer<vtkDataArray> cloudArray(vtkIdType points, const std::string& layout)
{
  auto value = [](vtkIdType index) { return static_cast<T>(cloudCoordinate(index)); };
  vtkSmartPointer<vtkDataArray> array;
  if (layout == "implicit")
  {
    auto function = vtkSmartPointer<FunctionArray<T>>::New();
    function->Function = value;
    array = function;
  }
  else if (layout == "SOA")
  {
    array = vtkSmartPointer<vtkSOADataArrayTemplate<T>>::New();
  }
  else
  {
    array = vtkSmartPointer<vtkAOSDataArrayTemplate<T>>::New();
  }
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(points);
  if (layout != "implicit")
  {
    for (vtkIdType i = 0; i < 3 * points; ++i)
    {
      array->SetComponent(i / 3, static_cast<int>(i % 3), value(i));
    }
  }
  return array;
}

// The kernel reads AOS float and double arrays in place and any other layout through a copy; the
// copy must not change a bit. 70,001 points: several progress steps, SMP chunks and copy buffers,
// none of them full at the end.
TEST(PointPairDeformationFilter, SOAAndImplicitPointArraysGiveTheAOSResultBitForBit)
{
  constexpr vtkIdType points = 70001;
  Random random(26);
  const auto generators = randomGenerators(random, 3, 0.5);
  auto run = [&](vtkDataArray* array, int rule, int precision) {
    auto cloud = cloudOf(array);
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(cloud);
    addGenerators(filter, generators);
    filter->SetExponentialRule(rule);
    filter->SetOutputPointsPrecision(precision);
    filter->Update();
    EXPECT_EQ(events.errors, 0);
    EXPECT_NE(events.lastWarning.find("1 of 70001 points"), std::string::npos)
      << events.lastWarning;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), points);
    return outputBytes(filter->GetOutput());
  };
  for (const bool isFloat : { true, false })
  {
    std::map<std::string, vtkSmartPointer<vtkDataArray>> arrays;
    for (const char* layout : { "AOS", "SOA", "implicit" })
    {
      arrays[layout] =
        isFloat ? cloudArray<float>(points, layout) : cloudArray<double>(points, layout);
      EXPECT_EQ(arrays[layout]->GetDataType(), isFloat ? VTK_FLOAT : VTK_DOUBLE);
    }
    ASSERT_EQ(vtkAOSDataArrayTemplate<double>::FastDownCast(arrays["SOA"]), nullptr);
    for (const int rule :
      { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
    {
      for (const int precision : { vtkAlgorithm::DEFAULT_PRECISION, vtkAlgorithm::SINGLE_PRECISION,
             vtkAlgorithm::DOUBLE_PRECISION })
      {
        const std::string reference = run(arrays["AOS"], rule, precision);
        for (const char* layout : { "SOA", "implicit" })
        {
          EXPECT_TRUE(run(arrays[layout], rule, precision) == reference)
            << layout << (isFloat ? " float" : " double") << ", rule " << rule << ", precision "
            << precision;
        }
      }
    }
  }
}

// Integer coordinates go through vtkDataArray's API: the result of the same values in double.
TEST(PointPairDeformationFilter, IntegerPointsGiveTheResultOfTheSameValuesInDouble)
{
  vtkNew<vtkIntArray> integers;
  vtkNew<vtkDoubleArray> doubles;
  for (vtkDataArray* array :
    { static_cast<vtkDataArray*>(integers), static_cast<vtkDataArray*>(doubles) })
  {
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(1000);
    for (vtkIdType i = 0; i < 3000; ++i)
    {
      array->SetComponent(i / 3, static_cast<int>(i % 3), std::round(4.0 * std::sin(1.37 * i)));
    }
  }
  std::string bytes[2];
  for (int k = 0; k < 2; ++k)
  {
    auto cloud = cloudOf(k == 0 ? static_cast<vtkDataArray*>(integers) : doubles.Get());
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(cloud);
    filter->AddGenerator(0.5, 0.25, 0, 0, 0.6, 0.8, 2.0);
    filter->Update();
    bytes[k] = outputBytes(filter->GetOutput());
  }
  EXPECT_TRUE(bytes[0] == bytes[1]);
  EXPECT_EQ(bytes[0].substr(0, 3), std::to_string(VTK_DOUBLE) + ":");
}

TEST(PointPairDeformationFilter, ImageDataBecomesAStructuredGridWithTheSamePoints)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 4, 3);
  image->SetSpacing(0.5, 0.5, 0.5);
  image->SetOrigin(-1, -1, -0.5);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(image);
  filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
  filter->Update();
  auto* grid = vtkStructuredGrid::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(grid->GetNumberOfPoints(), 60);
  EXPECT_EQ(grid->GetNumberOfCells(), 4 * 3 * 2);
  int dimensions[3];
  grid->GetDimensions(dimensions);
  EXPECT_EQ(dimensions[0], 5);
  // The same field applied to the image's points as a point cloud.
  cga::PointPairField field({ { { 0, 0, 0 }, { 0, 0, 1 }, 0.5 } }, 1.0, 0.01);
  for (vtkIdType i = 0; i < 60; ++i)
  {
    double p[3];
    image->GetPoint(i, p);
    Vec3 expected;
    ASSERT_TRUE(field.map({ p[0], p[1], p[2] }, 1.0, cga::ExponentialRule::Exact, expected));
    EXPECT_LE(cga::norm(pointOf(grid, i) - expected), 1e-14);
  }
}

// Images (here with a direction matrix and an extent not starting at 0) and rectilinear grids
// become structured grids of their extent and attributes, deformed as the cloud of their points
// in double is.
TEST(PointPairDeformationFilter, ImagesAndRectilinearGridsDeformAsTheirPointsInDouble)
{
  vtkNew<vtkImageData> image;
  image->SetExtent(-2, 3, 1, 4, 0, 2);
  image->SetSpacing(0.3, 0.25, 0.4);
  image->SetOrigin(-0.7, -1.0, -0.4);
  const double c = std::cos(0.3), s = std::sin(0.3);
  image->SetDirectionMatrix(c, -s, 0, s, c, 0, 0, 0, 1);
  vtkNew<vtkRectilinearGrid> rectilinear;
  rectilinear->SetExtent(1, 4, 0, 2, -1, 0);
  vtkNew<vtkFloatArray> x; // float coordinates: the points are still double
  vtkNew<vtkDoubleArray> y, z;
  for (double v : { -1.0, -0.2, 0.45, 1.3 })
  {
    x->InsertNextValue(static_cast<float>(v));
  }
  for (double v : { -0.8, 0.1, 0.9 })
  {
    y->InsertNextValue(v);
  }
  for (double v : { -0.3, 0.6 })
  {
    z->InsertNextValue(v);
  }
  rectilinear->SetXCoordinates(x);
  rectilinear->SetYCoordinates(y);
  rectilinear->SetZCoordinates(z);
  for (vtkDataSet* input :
    { static_cast<vtkDataSet*>(image), static_cast<vtkDataSet*>(rectilinear) })
  {
    vtkNew<vtkDoubleArray> pointIds, cellIds, tag;
    pointIds->SetName("PointIds");
    cellIds->SetName("CellIds");
    tag->SetName("Tag");
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      pointIds->InsertNextValue(static_cast<double>(i));
    }
    for (vtkIdType i = 0; i < input->GetNumberOfCells(); ++i)
    {
      cellIds->InsertNextValue(static_cast<double>(i));
    }
    tag->InsertNextValue(7);
    input->GetPointData()->AddArray(pointIds);
    input->GetCellData()->AddArray(cellIds);
    input->GetFieldData()->AddArray(tag);
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      coordinates->InsertNextTuple(input->GetPoint(i));
    }
    auto cloud = cloudOf(coordinates);
    std::string bytes[2];
    vtkSmartPointer<vtkDataObject> outputs[2];
    for (int k = 0; k < 2; ++k)
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      filter->SetInputData(k == 0 ? static_cast<vtkDataObject*>(input) : cloud.Get());
      filter->AddGenerator(0, 0, 0, 0, 0.6, 0.8, 0.5);
      filter->AddGenerator(0.5, -0.5, 0.2, 1, 0, 0, -0.3);
      filter->Update();
      outputs[k] = filter->GetOutputDataObject(0);
      bytes[k] = outputBytes(filter->GetOutput());
    }
    auto* grid = vtkStructuredGrid::SafeDownCast(outputs[0]);
    ASSERT_NE(grid, nullptr) << input->GetClassName();
    EXPECT_TRUE(bytes[0] == bytes[1]) << input->GetClassName();
    EXPECT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
    const int* inputExtent =
      input == image.Get() ? image->GetExtent() : rectilinear->GetExtent();
    int gridExtent[6];
    grid->GetExtent(gridExtent);
    EXPECT_TRUE(std::equal(inputExtent, inputExtent + 6, gridExtent)) << input->GetClassName();
    EXPECT_EQ(grid->GetNumberOfCells(), input->GetNumberOfCells());
    EXPECT_EQ(grid->GetPointData()->GetArray("PointIds"), pointIds.Get());
    EXPECT_EQ(grid->GetCellData()->GetArray("CellIds"), cellIds.Get());
    EXPECT_EQ(grid->GetFieldData()->GetArray("Tag"), tag.Get());
  }
}

// An image or rectilinear grid of an empty extent, VTK's (0, -1, ...) or an inverted one (whose
// point count VTK reports as a negative product), gives an empty structured grid without a
// message, as an empty input does: before, an inverted extent gave a grid of -24 points whose
// bounds aborted.
TEST(PointPairDeformationFilter, ImagesAndRectilinearGridsOfEmptyOrInvertedExtentsGiveEmptyOutputs)
{
  const int extents[][6] = { { 0, -1, 0, -1, 0, -1 }, { 5, 0, 0, 5, 0, 0 }, { 0, 3, 2, 1, 0, 0 },
    { 0, 3, 0, 3, 4, -4 } };
  for (const auto& extent : extents)
  {
    vtkNew<vtkImageData> image;
    image->SetExtent(const_cast<int*>(extent));
    vtkNew<vtkRectilinearGrid> rectilinear;
    rectilinear->SetExtent(const_cast<int*>(extent));
    for (vtkDataSet* input :
      { static_cast<vtkDataSet*>(image), static_cast<vtkDataSet*>(rectilinear) })
    {
      SCOPED_TRACE(std::string(input->GetClassName()) + " of extent " + std::to_string(extent[0]) +
        " " + std::to_string(extent[1]) + " " + std::to_string(extent[2]) + " " +
        std::to_string(extent[3]) + " " + std::to_string(extent[4]) + " " + std::to_string(extent[5]));
      vtkNew<vtkPointPairDeformationFilter> filter;
      filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
      filter->SetInputData(input);
      EventCounter events(filter);
      filter->Update();
      EXPECT_EQ(events.errors, 0) << events.lastError;
      EXPECT_EQ(events.warnings, 0) << events.lastWarning;
      vtkStructuredGrid* output = vtkStructuredGrid::SafeDownCast(filter->GetOutputDataObject(0));
      ASSERT_NE(output, nullptr);
      EXPECT_EQ(output->GetNumberOfPoints(), 0);
      EXPECT_EQ(output->GetNumberOfCells(), 0);
      double bounds[6];
      output->GetBounds(bounds); // aborted before
      EXPECT_GT(bounds[0], bounds[1]); // VTK's uninitialized bounds: an empty data set
    }
  }
}

// A vtkStructuredGrid whose extent does not count its points (VTK does not check it) is an error
// with an empty output: before, it passed through, and its cells indexed points that do not exist.
// A consistent grid, and an empty one, still deform.
TEST(PointPairDeformationFilter, AStructuredGridWhoseExtentDoesNotCountItsPointsIsAnError)
{
  struct Case
  {
    int dimensions[3];
    int points;
    bool valid;
  };
  const Case cases[] = { { { 2, 2, 2 }, 5, false }, { { 2, 2, 2 }, 9, false },
    { { 3, 1, 1 }, 0, false }, { { 2, 2, 2 }, 8, true }, { { 0, 0, 0 }, 0, true } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(std::to_string(c.dimensions[0]) + "x" + std::to_string(c.dimensions[1]) + "x" +
      std::to_string(c.dimensions[2]) + " with " + std::to_string(c.points) + " points");
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(c.dimensions[0], c.dimensions[1], c.dimensions[2]);
    vtkNew<vtkPoints> points;
    for (int i = 0; i < c.points; ++i)
    {
      points->InsertNextPoint(0.1 * i, 0.2, 0.3);
    }
    grid->SetPoints(points);
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
    filter->SetInputData(grid);
    EventCounter events(filter);
    filter->Update();
    vtkStructuredGrid* output = vtkStructuredGrid::SafeDownCast(filter->GetOutputDataObject(0));
    ASSERT_NE(output, nullptr);
    if (c.valid)
    {
      EXPECT_EQ(events.errors, 0) << events.lastError;
      EXPECT_EQ(output->GetNumberOfPoints(), c.points);
    }
    else
    {
      EXPECT_EQ(events.errors, 1);
      EXPECT_NE(events.lastError.find("counts"), std::string::npos) << events.lastError;
      EXPECT_EQ(output->GetNumberOfPoints(), 0);
      EXPECT_EQ(output->GetNumberOfCells(), 0);
    }
  }
}

// A float normal keeps its length, which may exceed the largest float: (3e38, 3e38, 3e38) turned
// can have a component beyond it. Such a normal passes unchanged and is counted in the warning,
// as a vector whose image overflows (before, it was written as infinity), through both paths:
// the normals alone (from two tangents' images) and with a vector array (from J).
TEST(PointPairDeformationFilter, FloatNormalsWhoseImagesOverflowPassUnchangedWithAWarning)
{
  Random random(23);
  vtkNew<vtkPolyData> mesh = randomMesh(random, 30, 1.5);
  vtkDataArray* normals = mesh->GetPointData()->GetArray("Normals");
  ASSERT_EQ(normals->GetDataType(), VTK_FLOAT);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    normals->SetTuple3(i, 3e38, 3e38, 3e38);
  }
  mesh->GetPointData()->SetNormals(normals);
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(mesh->GetNumberOfPoints());
  velocity->Fill(1.0);
  mesh->GetPointData()->AddArray(velocity);
  for (const bool withVector : { false, true })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    filter->AddGenerator(0, 0, 0.5, 1, 0, 1, 0.8);
    filter->SetTransformNormals(true);
    if (withVector)
    {
      filter->GetVectorArraySelection()->EnableArray("Velocity");
    }
    EventCounter events(filter);
    filter->Update();
    EXPECT_EQ(events.errors, 0) << events.lastError;
    EXPECT_EQ(events.warnings, 1) << withVector;
    EXPECT_NE(events.lastWarning.find("overflow their type"), std::string::npos) << events.lastWarning;
    vtkDataArray* out = filter->GetOutput()->GetPointData()->GetNormals();
    ASSERT_NE(out, nullptr);
    vtkIdType unchanged = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfTuples(); ++i)
    {
      double n[3];
      out->GetTuple(i, n);
      ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) << i;
      unchanged += n[0] == 3e38f && n[1] == 3e38f && n[2] == 3e38f ? 1 : 0;
    }
    EXPECT_GT(unchanged, 0) << withVector; // the turned normals that would overflow
  }
}

TEST(PointPairDeformationFilter, NoGeneratorsOrZeroStrengthIsTheIdentity)
{
  Random random(18);
  auto mesh = randomMesh(random, 10, 1.0);
  for (bool withGenerators : { false, true })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    if (withGenerators)
    {
      addGenerators(filter, randomGenerators(random, 3, 1.0));
      filter->SetStrength(0.0);
    }
    filter->Update();
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      EXPECT_EQ(cga::norm(pointOf(filter->GetOutput(), i) - pointOf(mesh, i)), 0.0);
    }
  }
}

TEST(PointPairDeformationFilter, TimeStepsGrowStrengthFromTheIdentityToItsValue)
{
  // NumberOfTimeSteps (vtkBoostedTimeSweep): off by default, the input's time steps pass; with
  // N steps the filter reports its own, and the frame at t is the static output of t Strength
  // (frame 0 the identity, the last frame the static output), point for point.
  Random random(31);
  auto mesh = randomMesh(random, 20, 1.0);
  const auto generators = randomGenerators(random, 3, 1.0);
  vtkNew<vtkPointPairDeformationFilter> timed;
  timed->SetInputData(mesh);
  addGenerators(timed, generators);
  timed->SetStrength(1.5);
  timed->UpdateInformation();
  EXPECT_FALSE(timed->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  timed->SetNumberOfTimeSteps(3);
  timed->UpdateInformation();
  vtkInformation* info = timed->GetOutputInformation(0);
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 3);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[1], 0.5);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE())[1], 1.0);
  for (double t : { 0.0, 0.5, 1.0 })
  {
    timed->UpdateTimeStep(t);
    EXPECT_EQ(timed->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), t);
    vtkNew<vtkPointPairDeformationFilter> still;
    still->SetInputData(mesh);
    addGenerators(still, generators);
    still->SetStrength(t * 1.5);
    still->Update();
    ASSERT_EQ(timed->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      ASSERT_EQ(cga::norm(pointOf(timed->GetOutput(), i) - pointOf(still->GetOutput(), i)), 0.0)
        << "t = " << t << ", point " << i;
      if (t == 0.0)
      {
        ASSERT_EQ(cga::norm(pointOf(timed->GetOutput(), i) - pointOf(mesh, i)), 0.0);
      }
    }
  }
}

TEST(PointPairDeformationFilter, NonFinitePointsPassThroughWithOneWarning)
{
  Random random(19);
  auto mesh = randomMesh(random, 10, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  mesh->GetPoints()->SetPoint(2, nan, 0, 0);
  mesh->GetPoints()->SetPoint(7, 0, inf, 0);
  mesh->GetPoints()->SetPoint(11, 0, 0, -inf);
  vtkNew<vtkPointPairDeformationFilter> filter;
  EventCounter events(filter);
  filter->SetInputData(mesh);
  addGenerators(filter, randomGenerators(random, 3, 0.5));
  filter->Update();
  EXPECT_EQ(events.warnings, 1);
  EXPECT_EQ(events.errors, 0);
  EXPECT_NE(events.lastWarning.find("3 of 30 points"), std::string::npos) << events.lastWarning;
  vtkPointSet* output = filter->GetOutput();
  EXPECT_TRUE(std::isnan(pointOf(output, 2).x));
  EXPECT_EQ(pointOf(output, 7).y, inf);
  EXPECT_EQ(pointOf(output, 11).z, -inf);
  vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
  for (vtkIdType i : { 2, 7, 11 })
  {
    EXPECT_EQ(displacement->GetTuple3(i)[0], 0.0);
    EXPECT_EQ(displacement->GetTuple3(i)[1], 0.0);
    EXPECT_EQ(displacement->GetTuple3(i)[2], 0.0);
  }
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (i != 2 && i != 7 && i != 11)
    {
      const Vec3 p = pointOf(output, i);
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
  }
}

TEST(PointPairDeformationFilter, ZeroDirectionsAreIgnoredWithAWarning)
{
  Random random(20);
  auto mesh = randomMesh(random, 10, 1.0);
  vtkNew<vtkPointPairDeformationFilter> withZero, without;
  EventCounter events(withZero);
  for (vtkPointPairDeformationFilter* filter : { withZero.Get(), without.Get() })
  {
    filter->SetInputData(mesh);
    filter->AddGenerator(0.2, 0.1, 0, 0, 1, 0, 0.7);
  }
  withZero->AddGenerator(0.5, 0.5, 0.5, 0, 0, 0, 3.0);
  withZero->Update();
  without->Update();
  EXPECT_EQ(events.warnings, 1);
  EXPECT_NE(events.lastWarning.find("1 of 2 generators"), std::string::npos) << events.lastWarning;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(cga::norm(pointOf(withZero->GetOutput(), i) - pointOf(without->GetOutput(), i)), 0.0);
  }
}

TEST(PointPairDeformationFilter, AGeneratorOnAMeshPointKeepsItFixedAndFinite)
{
  Random random(21);
  auto mesh = randomMesh(random, 4, 1.0);
  const Vec3 on = pointOf(mesh, 5);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  filter->AddGenerator(on.x, on.y, on.z, 1, 0, 0, 2.0);
  filter->Update(); // default epsilon 0.01: the generator's location is its fixed point
  EXPECT_LE(cga::norm(pointOf(filter->GetOutput(), 5) - on), 1e-11);
  filter->SetEpsilon(0.0); // clamped to the smallest allowed epsilon
  EXPECT_EQ(filter->GetEpsilon(), 1e-10);
  filter->Update();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const Vec3 p = pointOf(filter->GetOutput(), i);
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
}

TEST(PointPairDeformationFilter, HugeWeightsGiveFiniteOutput)
{
  Random random(22);
  auto mesh = randomMesh(random, 20, 1.0);
  for (double weight : { 1e6, 1e12, 1e50, 1e100, 1e200, 1e300, 1.7e308 })
  {
    for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      EventCounter events(filter); // a warning about points left in place is allowed
      filter->SetInputData(mesh);
      filter->AddGenerator(0.1, 0, 0, 0, 0, 1, weight);
      filter->AddGenerator(0, 0.3, 0, 1, 0, 0, -weight);
      filter->SetExponentialRule(rule);
      filter->Update();
      vtkPointSet* output = filter->GetOutput();
      ASSERT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
      vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        const Vec3 p = pointOf(output, i);
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
          << "weight " << weight << " rule " << rule << " point " << i;
        for (int c = 0; c < 3; ++c)
        {
          ASSERT_TRUE(std::isfinite(displacement->GetComponent(i, c)));
        }
      }
      EXPECT_EQ(events.errors, 0);
    }
  }
}

// A lone point pair of weight beyond ~1e154 (K = 1 + B, whose sandwich's terms |B|^2 overflow
// unless scaled): the transversion moves every point to within O(1/|u|) of its location (the
// closed form, PointPairDeformationFilter.OneGeneratorIsTheTranslatedSpecialConformalTransformation),
// the location itself staying put, with no point left in place and no warning about images.
TEST(PointPairDeformationFilter, AHugePointPairGathersEveryPointAtItsLocation)
{
  Random random(23);
  auto mesh = randomMesh(random, 20, 1.0);
  const Vec3 x{ 0.1, -0.2, 0.05 };
  for (double weight : { 1e160, -1e250, 1e300 })
  {
    for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      filter->SetInputData(mesh);
      filter->AddGenerator(x.x, x.y, x.z, 0.3, -0.6, 0.7, weight);
      filter->SetEpsilon(0.01);
      filter->SetExponentialRule(rule);
      filter->SetTransformNormals(false);
      EventCounter events(filter);
      filter->Update();
      EXPECT_EQ(events.errors + events.warnings, 0) << events.lastError << events.lastWarning;
      vtkPointSet* output = filter->GetOutput();
      ASSERT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
      vtkDataArray* displacement = output->GetPointData()->GetArray("Displacement");
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        const Vec3 image = pointOf(output, i);
        EXPECT_LE(cga::norm(image - x), 1e-12)
          << "weight " << weight << " rule " << rule << " point " << i;
        for (int c = 0; c < 3; ++c)
        {
          EXPECT_EQ(displacement->GetComponent(i, c), image[c] - pointOf(mesh, i)[c]);
        }
      }
    }
  }
}

// A vtkPolyData of generator points with direction and weight arrays.
vtkNew<vtkPolyData> generatorPoints(const std::vector<Generator>& generators)
{
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> directions;
  directions->SetName("Direction");
  directions->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> weights;
  weights->SetName("Weight");
  for (const Generator& g : generators)
  {
    points->InsertNextPoint(g.location.x, g.location.y, g.location.z);
    directions->InsertNextTuple3(g.direction.x, g.direction.y, g.direction.z);
    weights->InsertNextValue(static_cast<float>(g.weight));
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(directions);
  data->GetPointData()->AddArray(weights);
  return data;
}

TEST(PointPairDeformationFilter, TheGeneratorsPortAddsToTheList)
{
  Random random(23);
  auto mesh = randomMesh(random, 10, 1.0);
  auto generators = randomGenerators(random, 4, 0.5);
  for (Generator& g : generators)
  {
    g.weight = static_cast<float>(g.weight); // the port's weights are stored as float
  }
  const std::vector<Generator> fromList(generators.begin(), generators.begin() + 1);
  const std::vector<Generator> fromPort(generators.begin() + 1, generators.end());
  vtkNew<vtkPointPairDeformationFilter> reference, combined, unitWeights, unitReference;
  for (vtkPointPairDeformationFilter* filter :
    { reference.Get(), combined.Get(), unitWeights.Get(), unitReference.Get() })
  {
    filter->SetInputData(mesh);
  }
  addGenerators(reference, generators);
  addGenerators(combined, fromList);
  combined->SetGeneratorsData(generatorPoints(fromPort));
  combined->UseGeneratorWeightArrayOn();
  unitWeights->SetGeneratorsData(generatorPoints(fromPort));
  for (Generator g : fromPort)
  {
    unitReference->AddGenerator(
      g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y, g.direction.z, 1.0);
  }
  for (vtkPointPairDeformationFilter* filter :
    { reference.Get(), combined.Get(), unitWeights.Get(), unitReference.Get() })
  {
    filter->Update();
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    EXPECT_LE(cga::norm(pointOf(combined->GetOutput(), i) - pointOf(reference->GetOutput(), i)), 1e-14);
    EXPECT_LE(
      cga::norm(pointOf(unitWeights->GetOutput(), i) - pointOf(unitReference->GetOutput(), i)), 1e-14);
  }
}

TEST(PointPairDeformationFilter, BadGeneratorArraysAreErrorsWithEmptyOutput)
{
  Random random(24);
  auto mesh = randomMesh(random, 4, 1.0);
  auto generators = generatorPoints(randomGenerators(random, 2, 0.5));
  vtkNew<vtkStringArray> text;
  text->SetName("Text");
  text->InsertNextValue("a");
  text->InsertNextValue("b");
  generators->GetPointData()->AddArray(text);
  struct Case
  {
    const char* direction;
    const char* weight;
    bool useWeights;
    const char* expectedWords;
  };
  for (const Case& c : { Case{ "Missing", "Weight", false, "no point array named 'Missing'" },
         Case{ "Weight", "Weight", false, "3 components" },
         Case{ "Text", "Weight", false, "vtkStringArray" },
         Case{ "Direction", "Absent", true, "no point array named 'Absent'" },
         Case{ "Direction", "Direction", true, "1 component" } })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->SetGeneratorsData(generators);
    filter->SetGeneratorDirectionArrayName(c.direction);
    filter->SetGeneratorWeightArrayName(c.weight);
    filter->SetUseGeneratorWeightArray(c.useWeights);
    filter->Update();
    EXPECT_EQ(events.errors, 1) << c.expectedWords;
    EXPECT_NE(events.lastError.find(c.expectedWords), std::string::npos) << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << c.expectedWords;
  }
}

// Issue 15: a Direction or Weight array shorter than the generator points was read past its end
// (garbage generators; SIGSEGV at 2,000,000 points).
TEST(PointPairDeformationFilter, GeneratorArraysOfAnotherLengthThanThePointsAreErrors)
{
  Random random(28);
  auto mesh = randomMesh(random, 4, 1.0);
  struct Case
  {
    vtkIdType points;
    const char* array;
    vtkIdType tuples;
  };
  for (const Case& c : { Case{ 3, "Direction", 2 }, Case{ 3, "Weight", 1 },
         Case{ 3, "Direction", 4 }, Case{ 2000000, "Direction", 1 }, Case{ 2000000, "Weight", 1 } })
  {
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(c.points);
    points->GetData()->Fill(0.5);
    vtkNew<vtkDoubleArray> directions;
    directions->SetName("Direction");
    directions->SetNumberOfComponents(3);
    directions->SetNumberOfTuples(std::string(c.array) == "Direction" ? c.tuples : c.points);
    directions->Fill(1.0);
    vtkNew<vtkDoubleArray> weights;
    weights->SetName("Weight");
    weights->SetNumberOfTuples(std::string(c.array) == "Weight" ? c.tuples : c.points);
    weights->Fill(0.25);
    vtkNew<vtkPolyData> generators;
    generators->SetPoints(points);
    generators->GetPointData()->AddArray(directions);
    generators->GetPointData()->AddArray(weights);
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->SetGeneratorsData(generators);
    filter->UseGeneratorWeightArrayOn();
    filter->Update();
    const std::string expected = std::string("array '") + c.array + "' has " +
      std::to_string(c.tuples) + " tuples for " + std::to_string(c.points) + " points";
    EXPECT_EQ(events.errors, 1) << expected;
    EXPECT_NE(events.lastError.find(expected), std::string::npos) << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << expected;
  }
}

TEST(PointPairDeformationFilter, TheSelectedGeneratorTakesTheHandlesLocation)
{
  Random random(25);
  auto mesh = randomMesh(random, 6, 1.0);
  vtkNew<vtkPointPairDeformationFilter> selected, moved;
  for (vtkPointPairDeformationFilter* filter : { selected.Get(), moved.Get() })
  {
    filter->SetInputData(mesh);
    filter->AddGenerator(0, 0, 0, 1, 0, 0, 0.4);
  }
  selected->AddGenerator(0.5, 0, 0, 0, 1, 0, 0.6);
  selected->SetSelectedGenerator(1);
  selected->SetSelectedGeneratorLocation(-0.3, 0.2, 0.1);
  moved->AddGenerator(-0.3, 0.2, 0.1, 0, 1, 0, 0.6);
  selected->Update();
  moved->Update();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    EXPECT_EQ(cga::norm(pointOf(selected->GetOutput(), i) - pointOf(moved->GetOutput(), i)), 0.0);
  }
  double values[9];
  ASSERT_TRUE(selected->GetGenerator(1, values));
  EXPECT_EQ(values[0], 0.5); // the list itself is unchanged
  EXPECT_FALSE(selected->GetGenerator(2, values));
}

TEST(PointPairDeformationFilter, NonFiniteStrengthOrNaNParametersAreErrors)
{
  Random random(26);
  auto mesh = randomMesh(random, 4, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int which = 0; which < 3; ++which)
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->AddGenerator(0, 0, 0, 1, 0, 0, 0.4);
    if (which == 0)
    {
      filter->SetStrength(std::numeric_limits<double>::infinity());
    }
    else if (which == 1)
    {
      filter->SetFalloff(nan);
    }
    else
    {
      filter->SetEpsilon(nan);
    }
    filter->Update();
    EXPECT_EQ(events.errors, 1) << which;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << which;
  }
}
} // namespace

TEST(PointPairDeformationFilter, ReportsProgressAndAnAbortedUpdateIsEmpty)
{
  // 200000 points: 4 steps of 65536 points.
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(200000);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, 1e-5 * i, 0.5, 0.0);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  for (bool abort : { false, true })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
    ProgressLog log;
    log.abortAfterFirstStep = abort; // after the first step: a part of the mesh is moved
    log.Observe(filter);
    filter->Update();
    vtkPointSet* output = vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0));
    if (!abort)
    {
      EXPECT_GE(log.Steps().size(), 4u);
      EXPECT_EQ(output->GetNumberOfPoints(), 200000);
      EXPECT_NE(output->GetPointData()->GetArray("Displacement"), nullptr);
    }
    else
    {
      EXPECT_LT(log.Steps().size(), 4u);
      EXPECT_EQ(output->GetNumberOfPoints(), 0);
    }
  }
}

TEST(PointPairDeformationFilter, HugeGeneratorCountIsRefusedWithOneErrorAndAnEmptyOutput)
{
  Random random(27);
  auto mesh = randomMesh(random, 4, 1.0);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  EventCounter events(filter);
  filter->AddGenerator(0, 0, 0, 0, 0, 1, 0.5);
  filter->SetNumberOfGenerators(2000000000); // 112 GB of generators: not allocated
  for (int i = 0; i < 1000; ++i)
  {
    filter->SetGenerator(i, 0, 0, 0, 0, 0, 1, 0.5); // as a ParaView table pushes its rows
  }
  EXPECT_EQ(events.errors, 1);
  EXPECT_EQ(filter->GetNumberOfGenerators(), 1); // the rows are kept
  filter->Update();
  EXPECT_EQ(events.errors, 2);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetNumberOfGenerators(1); // within the cap: usable again
  filter->Update();
  EXPECT_EQ(events.errors, 2);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
}

TEST(PointPairDeformationFilter, TranslatingMeshAndGeneratorsTranslatesTheOutput)
{
  // Four random generators on a random mesh, both moved by t (the mesh's points as doubles):
  // the output moves by t, Displacement stays (the bound: TranslationChecks.h). Both rules.
  Random random(77);
  const auto generators = randomGenerators(random, 4, 0.4);
  auto mesh = randomMesh(random, 40, 1.5);
  for (int rule : { vtkPointPairDeformationFilter::EXACT, vtkPointPairDeformationFilter::PAPER })
  {
    SCOPED_TRACE("rule " + std::to_string(rule));
    ExpectTranslationCovariant(
      [&](const double t[3]) {
        vtkNew<vtkPointPairDeformationFilter> filter;
        filter->SetInputData(TranslatedCopy(mesh, t));
        for (const Generator& g : generators)
        {
          filter->AddGenerator(g.location.x + t[0], g.location.y + t[1], g.location.z + t[2],
            g.direction.x, g.direction.y, g.direction.z, g.weight);
        }
        filter->SetExponentialRule(rule);
        filter->Update();
        return vtkSmartPointer<vtkDataSet>(filter->GetOutput());
      },
      { "Displacement" });
  }
}

TEST(PointPairDeformationFilter, ALoneGeneratorOnAMeshPointFarAwayKeepsItExactly)
{
  // The field computes relative to its generators' mean, here the generator itself: the point
  // on it is exactly the origin of that frame, the boost's fixed point, at 1e6 as at 0.
  for (const double far : { 0.0, 1e6, 1e12 })
  {
    vtkNew<vtkPolyData> mesh;
    vtkNew<vtkPoints> points;
    points->SetDataType(VTK_DOUBLE);
    points->InsertNextPoint(far + 0.3, -far + 0.7, 0.1);
    points->InsertNextPoint(far + 0.5, -far + 0.7, 0.1);
    mesh->SetPoints(points);
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    filter->AddGenerator(far + 0.3, -far + 0.7, 0.1, 0.3, 1, -0.2, 2.0);
    filter->Update();
    const Vec3 p = pointOf(filter->GetOutput(), 0);
    EXPECT_EQ(p.x, far + 0.3) << far;
    EXPECT_EQ(p.y, -far + 0.7) << far;
    EXPECT_EQ(p.z, 0.1) << far;
    EXPECT_NE(pointOf(filter->GetOutput(), 1).x, far + 0.5) << "the neighbour moves";
  }
}

TEST(PointPairDeformationFilter, SinglePrecisionBeyondTheLargestFloatIsAnError)
{
  // Double points at 1e39 (strength 0: the identity) written as floats would be inf: an error and
  // an empty output instead; in double they pass.
  Random random(5);
  auto mesh = randomMesh(random, 3, 1.0);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    mesh->GetPoints()->SetPoint(i, p[0] + 1e39, p[1], p[2]);
  }
  for (const double strength : { 0.0, 1.0 })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(mesh);
    filter->AddGenerator(1e39, 0, 0, 1, 0, 0, 0.5);
    filter->SetStrength(strength);
    filter->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
    filter->Update();
    EXPECT_EQ(events.errors, 1) << strength;
    EXPECT_NE(events.lastError.find("OutputPointsPrecision"), std::string::npos) << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << strength;
    filter->SetOutputPointsPrecision(vtkAlgorithm::DEFAULT_PRECISION); // double, as the input
    filter->Update();
    EXPECT_EQ(events.errors, 1) << events.lastError;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << strength;
  }
}

// The output is the same, bit for bit, on vtkSMPTools' Sequential backend and on STDThread with
// one and two threads (vtkBoostedBlockLoop's blocks and chunks depend on the thread count), with
// and without the normals' derivative path, on a mesh of more than one block of two threads
// (vtkBoostedBlockLoop: 8 x 65,536 points per thread, 1,048,576) and of seventeen of one thread.
TEST(PointPairDeformationFilter, TheOutputIsTheSameOnEveryBackendAndThreadCount)
{
  Random random(91);
  const vtkIdType blocks =
    2 * vtkBoostedBlockLoop::ThreadedBlocks * vtkBoostedBlockLoop::SamplesPerBlock;
  vtkNew<vtkPolyData> mesh = randomMesh(random, static_cast<int>(blocks / 3 + 10000), 2.0);
  const std::vector<Generator> generators = randomGenerators(random, 3, 0.4);
  for (const bool normals : { false, true })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    filter->SetInputData(mesh);
    addGenerators(filter, generators);
    filter->SetExponentialRule(vtkPointPairDeformationFilter::EXACT);
    filter->SetTransformNormals(normals);
    std::vector<vtkSmartPointer<vtkPointSet>> outputs;
    // Two threads twice (the second update on the pool's threads of the first) and three
    // threads, on machines with three or more hardware threads (VTK 9.2's STDThread backend
    // clamps the count to the hardware's: on two cores the last run has two threads too).
    for (const auto& [backend, threads] :
      { std::make_pair("Sequential", 1), std::make_pair("STDThread", 1),
        std::make_pair("STDThread", 2), std::make_pair("STDThread", 2),
        std::make_pair("STDThread", 3) })
    {
      vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, backend, false }, [&] {
        filter->Modified();
        filter->Update();
      });
      outputs.push_back(vtkSmartPointer<vtkPointSet>::Take(
        vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0))->NewInstance()));
      outputs.back()->DeepCopy(filter->GetOutputDataObject(0));
    }
    ASSERT_GT(outputs[0]->GetNumberOfPoints(), blocks);
    for (std::size_t run = 1; run < outputs.size(); ++run)
    {
      for (const std::string name : { "points", "Displacement", "Normals" })
      {
        if (name == "Normals" && !normals)
        {
          continue; // dropped when not transformed
        }
        vtkDataArray* expected = name == "points" ? outputs[0]->GetPoints()->GetData()
                                                  : outputs[0]->GetPointData()->GetArray(name.c_str());
        vtkDataArray* actual = name == "points" ? outputs[run]->GetPoints()->GetData()
                                                : outputs[run]->GetPointData()->GetArray(name.c_str());
        ASSERT_NE(expected, nullptr) << name;
        ASSERT_NE(actual, nullptr) << name;
        ASSERT_EQ(expected->GetDataType(), actual->GetDataType()) << name;
        ASSERT_EQ(expected->GetDataSize(), actual->GetDataSize()) << name;
        EXPECT_EQ(std::memcmp(expected->GetVoidPointer(0), actual->GetVoidPointer(0),
                    expected->GetDataSize() * expected->GetDataTypeSize()),
          0)
          << name << " of run " << run << (normals ? " with normals" : "");
      }
    }
  }
}

TEST(PointPairDeformationFilter, TheGeneratorsOutputIsBuiltAnewOnlyWhenTheGeneratorsChange)
{
  // The "Generators" output of an update whose generators did not change shares the last one's
  // arrays (vtkBoostedGeneratorGlyphs::Write through the filter's cache); any change (a row, the
  // sign of a zero, the Generators input, the shared arrays written by a consumer) writes it
  // anew, with the values as used; an error leaves it empty.
  Random random(31);
  auto mesh = randomMesh(random, 50, 1.0);
  vtkNew<vtkPointPairDeformationFilter> filter;
  EventCounter events(filter);
  filter->SetInputData(mesh);
  filter->AddGenerator(0.25, 0.0, 0.0, 0, 0, 1, 0.5, vtkPointPairDeformationFilter::TWIST, 0.1);
  filter->AddGenerator(-0.5, 0.5, 0.0, 1, 0, 0, 0.25);
  auto glyphs = [&] { return vtkPolyData::SafeDownCast(filter->GetOutputDataObject(1)); };
  auto weights = [&] { return glyphs()->GetPointData()->GetArray("Weight"); };
  auto update = [&] {
    filter->Modified();
    filter->Update();
  };
  update();
  ASSERT_EQ(glyphs()->GetNumberOfPoints(), 2);
  ASSERT_NE(weights(), nullptr);
  EXPECT_EQ(glyphs()->GetPointData()->GetArray("Kind")->GetTuple1(0),
    vtkPointPairDeformationFilter::TWIST);
  EXPECT_EQ(glyphs()->GetPointData()->GetArray("Pitch")->GetTuple1(0), 0.1);
  // Kept alive, so that a new array cannot take its address.
  vtkSmartPointer<vtkDataArray> first = weights();
  update();
  EXPECT_EQ(weights(), first.Get()) << "the same generators: the same arrays";
  EXPECT_EQ(glyphs()->GetNumberOfPoints(), 2);
  EXPECT_EQ(glyphs()->GetNumberOfVerts(), 2);

  filter->SetGenerator(1, -0.5, 0.5, 0.0, 1, 0, 0, 0.75);
  filter->Update();
  EXPECT_NE(weights(), first.Get());
  EXPECT_EQ(weights()->GetTuple1(1), 0.75);

  weights()->SetTuple1(1, 9.0); // a consumer writing into the shared array
  update();
  EXPECT_EQ(weights()->GetTuple1(1), 0.75);

  filter->SetGeneratorsData(generatorPoints({ Generator{ { 0.1, 0.2, 0.0 }, { 0, 1, 0 }, 1.0 } }));
  filter->UseGeneratorWeightArrayOn();
  filter->Update();
  ASSERT_EQ(glyphs()->GetNumberOfPoints(), 3);
  EXPECT_EQ(glyphs()->GetPoint(2)[1], 0.2);
  EXPECT_EQ(weights()->GetTuple1(2), 1.0);
  EXPECT_FALSE(std::signbit(glyphs()->GetPoint(2)[2]));

  // (The list's rows take -0 for 0 as no change; the input's points keep the sign.)
  vtkSmartPointer<vtkDataArray> positiveZero = weights();
  filter->SetGeneratorsData(generatorPoints({ Generator{ { 0.1, 0.2, -0.0 }, { 0, 1, 0 }, 1.0 } }));
  filter->Update();
  EXPECT_NE(weights(), positiveZero.Get()) << "-0 is another location's bits";
  ASSERT_EQ(glyphs()->GetNumberOfPoints(), 3);
  EXPECT_TRUE(std::signbit(glyphs()->GetPoint(2)[2]));

  filter->SetEpsilon(std::numeric_limits<double>::quiet_NaN());
  filter->Update();
  EXPECT_EQ(events.errors, 1);
  EXPECT_EQ(glyphs()->GetNumberOfPoints(), 0) << "empty after an error";
  filter->SetEpsilon(0.05);
  filter->Update();
  ASSERT_EQ(glyphs()->GetNumberOfPoints(), 3);
  EXPECT_EQ(weights()->GetTuple1(1), 0.75);
  EXPECT_EQ(events.errors, 1);

  // The check every class with the port shares (GeneratorGlyphCacheChecks.h): Strength and the
  // falloff are not the generators', a row's pitch is.
  ExpectGeneratorGlyphsCached(1,
    [&] {
      auto deformation = vtkSmartPointer<vtkPointPairDeformationFilter>::New();
      deformation->SetInputData(mesh);
      deformation->AddGenerator(
        0.25, 0.0, 0.0, 0, 0, 1, 0.5, vtkPointPairDeformationFilter::TWIST, 0.1);
      return deformation;
    },
    [](vtkPointPairDeformationFilter* deformation) {
      deformation->SetStrength(0.5);
      deformation->SetFalloff(2.0);
    },
    [](vtkPointPairDeformationFilter* deformation) {
      deformation->SetGenerator(
        0, 0.25, 0.0, 0.0, 0, 0, 1, 0.5, vtkPointPairDeformationFilter::TWIST, 0.2);
    });
}
