// vtkPointPairDeformationFilter's outputs from the map's derivative J (normals, vectors,
// ConformalScale, ConformalityDefect) against independent references: central finite differences
// of the core's pointwise map (cga::PointPairField::map, which computes no derivative), linear
// solves by vtkMath, and the closed forms of a lone dilation and a lone rotation
// (docs/conventions.md section 3 item 15); the images with derivatives against those without,
// bit for bit; and bad input.
#include "vtkPointPairDeformationFilter.h"

#include "DeformedOutput.h"
#include "EventCounter.h"
#include "TestSupport.h"
#include "vtkCellArray.h"
#include "vtkDataArraySelection.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkStringArray.h"

#include "cga/PointPairField.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using cga::GeneratorKind;
using cga::GeneratorParameters;
using cga::Vec3;
using cgatest::Random;
using cgatest::worseOf;

constexpr int Exact = vtkPointPairDeformationFilter::EXACT;
constexpr int Paper = vtkPointPairDeformationFilter::PAPER;

struct FieldSetup
{
  std::vector<GeneratorParameters> generators;
  double falloff = 1.0;
  double epsilon = 0.1;
  double strength = 1.0;
  int rule = Exact;
};

// Generators of every kind (twists of non-zero pitch too) around the origin.
std::vector<GeneratorParameters> mixedGenerators(Random& random, int count, double maxWeight)
{
  std::vector<GeneratorParameters> generators;
  for (int i = 0; i < count; ++i)
  {
    GeneratorParameters g;
    g.kind = static_cast<GeneratorKind>(i % 5);
    g.location = random.vec3(1.2);
    g.direction = random.unit();
    g.weight = random.uniform(-maxWeight, maxWeight);
    g.pitch = g.kind == GeneratorKind::Twist ? random.uniform(-0.5, 0.5) : 0.0;
    generators.push_back(g);
  }
  return generators;
}

void configure(vtkPointPairDeformationFilter* filter, const FieldSetup& setup)
{
  for (const GeneratorParameters& g : setup.generators)
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight, static_cast<double>(g.kind), g.pitch);
  }
  filter->SetFalloff(setup.falloff);
  filter->SetEpsilon(setup.epsilon);
  filter->SetStrength(setup.strength);
  filter->SetExponentialRule(setup.rule);
}

// J by fourth-order central differences of the pointwise map, step h (error h^4 f^(5) / 30 plus
// rounding eps |f| / h): column j is d p' / d p_j.
void finiteDifferenceJacobian(const FieldSetup& setup, Vec3 p, double h, double jacobian[3][3])
{
  const cga::PointPairField field(
    setup.generators.data(), setup.generators.size(), setup.falloff, setup.epsilon);
  const auto rule = setup.rule == Paper ? cga::ExponentialRule::Paper : cga::ExponentialRule::Exact;
  auto image = [&](Vec3 q) {
    Vec3 out;
    EXPECT_TRUE(field.map(q, setup.strength, rule, out));
    return out;
  };
  for (int j = 0; j < 3; ++j)
  {
    Vec3 step{ 0, 0, 0 };
    (j == 0 ? step.x : j == 1 ? step.y : step.z) = h;
    const Vec3 d = (image(p + step) - image(p - step)) * 8.0 -
      (image(p + step * 2.0) - image(p - step * 2.0));
    jacobian[0][j] = d.x / (12 * h);
    jacobian[1][j] = d.y / (12 * h);
    jacobian[2][j] = d.z / (12 * h);
  }
}

// A point cloud of `count` random points with vertices, a double "Normals" array (active) of
// random unit vectors and a "Velocity" array of random vectors in the given layout.
vtkNew<vtkPolyData> cloud(Random& random, int count, bool soa = false)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkSmartPointer<vtkDataArray> velocity;
  if (soa)
  {
    velocity = vtkSmartPointer<vtkSOADataArrayTemplate<double>>::New();
  }
  else
  {
    velocity = vtkSmartPointer<vtkDoubleArray>::New();
  }
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(count);
  for (int i = 0; i < count; ++i)
  {
    const Vec3 p = random.vec3(1.5), n = random.unit(), v = random.vec3(2.0);
    const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
    vertices->InsertNextCell(1, &id);
    normals->InsertNextTuple3(n.x, n.y, n.z);
    velocity->SetTuple3(i, v.x, v.y, v.z);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetVerts(vertices);
  data->GetPointData()->SetNormals(normals);
  data->GetPointData()->AddArray(velocity);
  return data;
}

Vec3 tupleOf(vtkDataArray* array, vtkIdType i)
{
  double v[3];
  array->GetTuple(i, v);
  return { v[0], v[1], v[2] };
}

double angleBetween(Vec3 a, Vec3 b)
{
  return std::atan2(cga::norm(cga::cross(a, b)), cga::dot(a, b));
}

// The unit normal of the image of the plane normal to n: J^-T n solved by vtkMath (Gaussian
// elimination: not the filter's cofactors or tangents), turned where det J < 0 (there the normal
// follows the mapped cells' winding: cof(J) n = det(J) J^-T n).
Vec3 normalBySolve(double j[3][3], Vec3 n)
{
  double jt[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      jt[r][c] = j[c][r];
    }
  }
  double x[3] = { n.x, n.y, n.z };
  vtkMath::LinearSolve3x3(jt, x, x);
  return cga::normalized(Vec3{ x[0], x[1], x[2] }) * (vtkMath::Determinant3x3(j) < 0.0 ? -1.0 : 1.0);
}

// Normals as J^-T n, solved by vtkMath (Gaussian elimination: not the filter's cofactors), turned
// where det J < 0, and
// vectors as J v, with J from finite differences of the map, for every kind and both rules.
TEST(PointPairDeformationDerivatives, NormalsAndVectorsMatchFiniteDifferencesOfTheMap)
{
  Random random(131);
  for (const int rule : { Exact, Paper })
  {
    for (const bool soa : { false, true })
    {
      FieldSetup setup;
      setup.generators = mixedGenerators(random, 6, 0.4);
      setup.rule = rule;
      auto data = cloud(random, 200, soa);
      vtkNew<vtkPointPairDeformationFilter> filter;
      EventCounter events(filter);
      filter->SetInputData(data);
      configure(filter, setup);
      filter->GetVectorArraySelection()->EnableArray("Velocity");
      filter->Update();
      ASSERT_EQ(events.errors, 0) << events.lastError;
      EXPECT_EQ(events.warnings, 0) << events.lastWarning;
      vtkPointSet* output = filter->GetOutput();
      vtkDataArray* normals = output->GetPointData()->GetNormals();
      vtkDataArray* velocity = output->GetPointData()->GetArray("Velocity");
      ASSERT_NE(normals, nullptr);
      ASSERT_NE(velocity, nullptr);
      EXPECT_EQ(normals->GetDataType(), VTK_DOUBLE);
      double worstAngle = 0.0, worstVector = 0.0;
      int folded = 0;
      for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
      {
        double j[3][3];
        finiteDifferenceJacobian(setup, pointOf(data, i), 1e-3, j);
        double size = 0.0;
        for (int r = 0; r < 3; ++r)
        {
          for (int c = 0; c < 3; ++c)
          {
            size = worseOf(size, std::fabs(j[r][c]));
          }
        }
        const Vec3 n = tupleOf(data->GetPointData()->GetNormals(), i);
        folded += vtkMath::Determinant3x3(j) < 0.0 ? 1 : 0;
        const Vec3 expected = normalBySolve(j, n);
        const Vec3 got = tupleOf(normals, i);
        EXPECT_NEAR(cga::norm(got), 1.0, 1e-14);
        worstAngle = worseOf(worstAngle, angleBetween(got, expected));
        const Vec3 v = tupleOf(data->GetPointData()->GetArray("Velocity"), i);
        const Vec3 jv{ j[0][0] * v.x + j[0][1] * v.y + j[0][2] * v.z,
          j[1][0] * v.x + j[1][1] * v.y + j[1][2] * v.z,
          j[2][0] * v.x + j[2][1] * v.y + j[2][2] * v.z };
        worstVector =
          worseOf(worstVector, cga::norm(tupleOf(velocity, i) - jv) / (size * cga::norm(v)));
      }
      EXPECT_LE(worstAngle, 1e-8) << "rule " << rule << (soa ? " SOA" : " AOS");
      EXPECT_LE(worstVector, 1e-8) << "rule " << rule << (soa ? " SOA" : " AOS");
      std::cout << "rule " << rule << (soa ? ", SOA velocity" : ", AOS velocity")
                << ": largest normal angle " << worstAngle << " rad, largest relative J v error "
                << worstVector << " (" << folded << " of 200 points where the map folds)\n";
    }
  }
}

// When the normals are the only output the filter computes J along two tangents of each normal
// (mapPointsWithDirectionalDerivatives) instead of J: the normals must be those of the cofactor
// form (the filter with ConformalScale as well, which takes J) to rounding, and match finite
// differences of the map as those do. Normals of any length and direction (n_z of both signs,
// +-z exactly, where the tangent construction switches), a zero and a NaN normal, a NaN point.
TEST(PointPairDeformationDerivatives, NormalsAloneFromTwoTangentsEqualTheCofactorNormals)
{
  Random random(136);
  for (const int rule : { Exact, Paper })
  {
    FieldSetup setup;
    setup.generators = mixedGenerators(random, 6, 0.4);
    setup.rule = rule;
    auto data = cloud(random, 203);
    vtkDataArray* input = data->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < 203; ++i)
    {
      const double length = std::pow(10.0, random.uniform(-3.0, 3.0));
      const Vec3 n = tupleOf(input, i) * length;
      input->SetTuple3(i, n.x, n.y, n.z);
    }
    input->SetTuple3(0, 0.0, 0.0, 1.0);
    input->SetTuple3(1, 0.0, 0.0, -2.0);
    input->SetTuple3(2, 0.0, 0.0, 0.0);
    input->SetTuple3(3, std::nan(""), 0.0, 1.0);
    data->GetPoints()->SetPoint(4, std::nan(""), 0.0, 0.0);
    vtkSmartPointer<vtkPointSet> outputs[2];
    for (const bool withScale : { false, true })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      EventCounter events(filter);
      filter->SetInputData(data);
      configure(filter, setup);
      filter->SetComputeConformalScale(withScale);
      filter->Update();
      ASSERT_EQ(events.errors, 0) << events.lastError;
      outputs[withScale] = filter->GetOutput();
    }
    EXPECT_TRUE(outputBytes(outputs[0]) == outputBytes(outputs[1]));
    vtkDataArray* twoTangents = outputs[0]->GetPointData()->GetNormals();
    vtkDataArray* cofactor = outputs[1]->GetPointData()->GetNormals();
    ASSERT_NE(twoTangents, nullptr);
    ASSERT_NE(cofactor, nullptr);
    double worstAngle = 0.0, worstLength = 0.0, worstDifference = 0.0;
    for (vtkIdType i = 0; i < 203; ++i)
    {
      const Vec3 n = tupleOf(input, i), got = tupleOf(twoTangents, i);
      if (i == 2 || i == 3 || i == 4) // zero normal, NaN normal, NaN point: unchanged
      {
        EXPECT_EQ(0, std::memcmp(&n, &got, sizeof n)) << i;
        continue;
      }
      const Vec3 expected = tupleOf(cofactor, i);
      const double angle = angleBetween(got, expected);
      const double length = std::fabs(cga::norm(got) / cga::norm(n) - 1.0);
      EXPECT_LE(angle, 1e-12) << i;
      EXPECT_LE(length, 1e-14) << i;
      worstAngle = worseOf(worstAngle, angle);
      worstLength = worseOf(worstLength, length);
      double j[3][3];
      finiteDifferenceJacobian(setup, pointOf(data, i), 1e-3, j);
      const double difference = angleBetween(got, normalBySolve(j, n));
      EXPECT_LE(difference, 1e-8) << i;
      worstDifference = worseOf(worstDifference, difference);
    }
    std::cout << "rule " << rule << ": two tangents against the cofactor form: largest angle "
              << worstAngle << " rad, largest relative length error " << worstLength
              << "; against finite differences: " << worstDifference << " rad\n";
  }
}

// mapPointsWithJacobians replaces mapPoints when a derivative is asked for: the images must not
// change a bit, for float and double points (AOS and SOA), both rules, both output precisions,
// over several blocks, SMP chunks and Jacobian buffers (70,001 points, one of them NaN).
TEST(PointPairDeformationDerivatives, ImagesAreTheSameBitForBitWithDerivatives)
{
  constexpr vtkIdType count = 70001;
  Random random(132);
  FieldSetup setup;
  setup.generators = mixedGenerators(random, 3, 0.5); // a point pair, a rotation, a twist
  for (const int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    for (const bool soa : { false, true })
    {
      vtkSmartPointer<vtkDataArray> coordinates;
      if (soa)
      {
        coordinates = type == VTK_FLOAT
          ? vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkSOADataArrayTemplate<float>>::New())
          : vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkSOADataArrayTemplate<double>>::New());
      }
      else
      {
        coordinates = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type));
      }
      coordinates->SetNumberOfComponents(3);
      coordinates->SetNumberOfTuples(count);
      vtkNew<vtkFloatArray> normals;
      normals->SetNumberOfComponents(3);
      normals->SetNumberOfTuples(count);
      for (vtkIdType i = 0; i < count; ++i)
      {
        const Vec3 p = random.vec3(1.5), n = random.unit();
        coordinates->SetTuple3(i, p.x, i == 1234 ? std::nan("") : p.y, p.z);
        normals->SetTuple3(i, n.x, n.y, n.z);
      }
      vtkNew<vtkPoints> points;
      points->SetData(coordinates);
      vtkNew<vtkPolyData> data;
      data->SetPoints(points);
      data->GetPointData()->SetNormals(normals);
      for (const int rule : { Exact, Paper })
      {
        for (const int precision : { vtkAlgorithm::DEFAULT_PRECISION,
               type == VTK_FLOAT ? vtkAlgorithm::DOUBLE_PRECISION : vtkAlgorithm::SINGLE_PRECISION })
        {
          setup.rule = rule;
          // 0: no derivative; 1: the normals alone (two tangents); 2: and ConformalScale (J).
          std::string images[3];
          for (const int derivatives : { 0, 1, 2 })
          {
            vtkNew<vtkPointPairDeformationFilter> filter;
            EventCounter events(filter);
            filter->SetInputData(data);
            configure(filter, setup);
            filter->SetOutputPointsPrecision(precision);
            filter->SetTransformNormals(derivatives > 0);
            filter->SetComputeConformalScale(derivatives == 2);
            filter->Update();
            EXPECT_EQ(events.errors, 0) << events.lastError;
            EXPECT_EQ(filter->GetOutput()->GetPointData()->GetNormals() != nullptr, derivatives > 0);
            images[derivatives] = outputBytes(filter->GetOutput());
          }
          EXPECT_TRUE(images[0] == images[1] && images[0] == images[2])
            << (type == VTK_FLOAT ? "float" : "double") << (soa ? " SOA" : " AOS") << ", rule "
            << rule << ", precision " << precision;
        }
      }
    }
  }
}

// The output of the filter on `data` with ConformalScale and ConformalityDefect, and those.
struct ConformalArrays
{
  vtkSmartPointer<vtkPointSet> output;
  vtkDataArray* scale;
  vtkDataArray* defect;
};

ConformalArrays withConformalArrays(vtkPolyData* data, const FieldSetup& setup)
{
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(data);
  configure(filter, setup);
  filter->ComputeConformalScaleOn();
  filter->ComputeConformalityDefectOn();
  filter->Update();
  vtkPointData* arrays = filter->GetOutput()->GetPointData();
  return { filter->GetOutput(), arrays->GetArray("ConformalScale"),
    arrays->GetArray("ConformalityDefect") };
}

// A lone dilation about x: p' = x + e^c (p - x), c = S w / (k r^2 + eps), r = |p - x|. Then
// J = e^c (I + g r^ r^T) with g = grad c . (p - x) = -2 S w k r^2 / (k r^2 + eps)^2, so
// det J = e^(3c) (1 + g) and the singular values are e^c |1 + g| (radially) and e^c twice.
TEST(PointPairDeformationDerivatives, ALoneDilationHasItsClosedFormScaleAndDefect)
{
  Random random(133);
  for (const double falloff : { 0.0, 1.0, 3.0 })
  {
    FieldSetup setup;
    const Vec3 x{ 0.2, -0.1, 0.3 };
    setup.generators = { { GeneratorKind::Dilation, x, { 0, 0, 2 }, 0.0, 0.3 } }; // w |v| = 0.6
    setup.falloff = falloff;
    setup.epsilon = 0.5;
    setup.strength = 0.7;
    for (const int rule : { Exact, Paper })
    {
      setup.rule = rule;
      auto data = cloud(random, 300);
      const auto [output, scale, defect] = withConformalArrays(data, setup);
      ASSERT_NE(scale, nullptr);
      ASSERT_NE(defect, nullptr);
      EXPECT_EQ(scale->GetDataType(), VTK_DOUBLE); // as the points
      double worstScale = 0.0, worstDefect = 0.0;
      for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
      {
        const double r2 = cga::norm2(pointOf(data, i) - x);
        const double d = falloff * r2 + setup.epsilon;
        const double c = setup.strength * 0.6 / d;
        const double g = -2.0 * setup.strength * 0.6 * falloff * r2 / (d * d);
        const double s = std::exp(c) * std::cbrt(std::fabs(1.0 + g));
        const double radial = std::fabs(1.0 + g);
        const double expectedDefect = 1.0 - std::min(radial, 1.0) / std::max(radial, 1.0);
        worstScale = worseOf(worstScale, std::fabs(scale->GetComponent(i, 0) / s - 1.0));
        worstDefect = worseOf(worstDefect, std::fabs(defect->GetComponent(i, 0) - expectedDefect));
      }
      EXPECT_LE(worstScale, 1e-13) << "falloff " << falloff << ", rule " << rule;
      EXPECT_LE(worstDefect, 1e-12) << "falloff " << falloff << ", rule " << rule;
      if (falloff > 0.0)
      {
        EXPECT_GT(defect->GetRange()[1], 0.05); // a varying B is not conformal
      }
    }
  }
}

// A lone rotation by the angle c(p) = S w / (k r^2 + eps) about an axis through x along a:
// J = R + R [a]x (p - x) grad c^T, so det J = 1 + grad c . (a x (p - x)) = 1, as grad c is along
// p - x: the map keeps volumes, ConformalScale 1 everywhere (on the axis too), while its defect
// is 0 only for a constant angle (k = 0).
TEST(PointPairDeformationDerivatives, ALoneRotationKeepsVolumes)
{
  Random random(134);
  for (const double falloff : { 0.0, 2.0 })
  {
    FieldSetup setup;
    setup.generators = { { GeneratorKind::Rotation, { 0.1, 0.2, -0.3 }, cga::normalized(Vec3{ 1, 2, 2 }), 0.0, 1.1 } };
    setup.falloff = falloff;
    setup.epsilon = 0.3;
    auto data = cloud(random, 300);
    data->GetPoints()->SetPoint(0, 0.1, 0.2, -0.3); // on the axis, at the generator
    const auto [output, scale, defect] = withConformalArrays(data, setup);
    double worst = 0.0;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      worst = worseOf(worst, std::fabs(scale->GetComponent(i, 0) - 1.0));
    }
    EXPECT_LE(worst, 1e-13) << "falloff " << falloff;
    if (falloff == 0.0)
    {
      EXPECT_LE(defect->GetRange()[1], 1e-13);
    }
    else
    {
      EXPECT_GT(defect->GetRange()[1], 0.05);
    }
  }
}

// With k = 0, B is the same at every point and the Exact rule's K a versor: the map is conformal,
// J = s R, for any mix of kinds; the Paper rule's is not when B is not a blade. The scale matches
// |det| of the finite-difference J.
TEST(PointPairDeformationDerivatives, AConstantFieldIsConformalForTheExactRule)
{
  Random random(135);
  FieldSetup setup;
  setup.generators = mixedGenerators(random, 7, 0.3);
  setup.falloff = 0.0;
  setup.epsilon = 1.0;
  for (const int rule : { Exact, Paper })
  {
    setup.rule = rule;
    auto data = cloud(random, 200);
    const auto [output, scale, defect] = withConformalArrays(data, setup);
    double worstScale = 0.0;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      double j[3][3];
      finiteDifferenceJacobian(setup, pointOf(data, i), 1e-3, j);
      const double s = std::cbrt(std::fabs(vtkMath::Determinant3x3(j)));
      worstScale = worseOf(worstScale, std::fabs(scale->GetComponent(i, 0) / s - 1.0));
    }
    EXPECT_LE(worstScale, 1e-9) << "rule " << rule;
    if (rule == Exact)
    {
      EXPECT_LE(defect->GetRange()[1], 1e-12);
    }
    else
    {
      EXPECT_GT(defect->GetRange()[1], 1e-3);
    }
    std::cout << (rule == Exact ? "Exact" : "Paper") << ", constant B: ConformalityDefect up to "
              << defect->GetRange()[1] << "\n";
  }
}

// Normals keep their length (unit stay unit, zero stay zero) and their type; the output normals
// are the active normals, a transformed active vectors array stays active; the scalars follow the
// output points' precision; TransformNormals off drops the normals.
TEST(PointPairDeformationDerivatives, ArraysKeepTheirTypesNamesAndRoles)
{
  Random random(136);
  FieldSetup setup;
  setup.generators = mixedGenerators(random, 3, 0.4);
  auto data = cloud(random, 50);
  vtkNew<vtkFloatArray> floatNormals;
  floatNormals->SetName("Shading");
  floatNormals->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 50; ++i)
  {
    const Vec3 n = random.unit() * (i == 7 ? 0.0 : 2.5);
    floatNormals->InsertNextTuple3(n.x, n.y, n.z);
  }
  data->GetPointData()->AddArray(floatNormals);
  data->GetPointData()->SetActiveVectors("Velocity");
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(data);
  configure(filter, setup);
  filter->GetVectorArraySelection()->EnableArray("Velocity");
  filter->GetNormalArraySelection()->EnableArray("Shading");
  filter->ComputeConformalScaleOn();
  filter->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  filter->Update();
  vtkPointData* out = filter->GetOutput()->GetPointData();
  ASSERT_NE(out->GetNormals(), nullptr);
  EXPECT_STREQ(out->GetNormals()->GetName(), "Normals");
  ASSERT_NE(out->GetVectors(), nullptr);
  EXPECT_STREQ(out->GetVectors()->GetName(), "Velocity");
  EXPECT_NE(out->GetVectors(), data->GetPointData()->GetVectors()); // transformed, not passed
  vtkDataArray* shading = out->GetArray("Shading");
  ASSERT_NE(shading, nullptr);
  EXPECT_EQ(shading->GetDataType(), VTK_FLOAT);
  for (vtkIdType i = 0; i < 50; ++i)
  {
    EXPECT_NEAR(cga::norm(tupleOf(shading, i)), i == 7 ? 0.0 : 2.5, 1e-6);
  }
  EXPECT_EQ(out->GetArray("ConformalScale")->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(out->GetArray("ConformalityDefect"), nullptr);

  // Changing a selection re-executes the filter.
  filter->GetNormalArraySelection()->DisableArray("Shading");
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray("Shading")->GetTuple3(0)[0],
    floatNormals->GetTuple3(0)[0]);

  filter->TransformNormalsOff();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetArray("Normals"), nullptr);
}

// Bad input: clear errors with an empty output, or warnings with documented behaviour.
TEST(PointPairDeformationDerivatives, BadArraysAreErrorsOrWarnings)
{
  Random random(137);
  FieldSetup setup;
  setup.generators = mixedGenerators(random, 3, 0.4);
  struct Case
  {
    const char* what;
    std::function<void(vtkPolyData*)> data;
    std::function<void(vtkPointPairDeformationFilter*)> set;
    const char* message; // in the error (or, for warnings, the warning)
    bool error;
  };
  const std::vector<Case> cases = {
    { "active normals of 2 components",
      [](vtkPolyData* d) { d->GetPointData()->GetNormals()->SetNumberOfComponents(2); },
      [](vtkPointPairDeformationFilter*) {}, "must be a numeric array of 3 components", true },
    { "a named normal array of 2 components",
      [](vtkPolyData* d) {
        vtkNew<vtkDoubleArray> flat;
        flat->SetName("Flat");
        flat->SetNumberOfComponents(2);
        flat->SetNumberOfTuples(d->GetNumberOfPoints());
        flat->Fill(1.0);
        d->GetPointData()->AddArray(flat);
      },
      [](vtkPointPairDeformationFilter* f) { f->GetNormalArraySelection()->EnableArray("Flat"); },
      "'Flat' cannot be transformed as a normal", true },
    { "a named vector array of strings",
      [](vtkPolyData* d) {
        vtkNew<vtkStringArray> text;
        text->SetName("Text");
        text->SetNumberOfTuples(d->GetNumberOfPoints());
        d->GetPointData()->AddArray(text);
      },
      [](vtkPointPairDeformationFilter* f) { f->GetVectorArraySelection()->EnableArray("Text"); },
      "'Text' cannot be transformed as a vector", true },
    { "an array asked as a vector and as a normal", [](vtkPolyData*) {},
      [](vtkPointPairDeformationFilter* f) {
        f->GetVectorArraySelection()->EnableArray("Velocity");
        f->GetNormalArraySelection()->EnableArray("Velocity");
      },
      "both as a vector", true },
    { "the active normals asked as vectors", [](vtkPolyData*) {},
      [](vtkPointPairDeformationFilter* f) {
        f->GetVectorArraySelection()->EnableArray("Normals");
      },
      "the active normals, TransformNormals", true },
    { "a name the input does not have", [](vtkPolyData*) {},
      [](vtkPointPairDeformationFilter* f) { f->GetVectorArraySelection()->EnableArray("Nope"); },
      "no point array named 'Nope'", false },
    { "NaN normals and vectors",
      [](vtkPolyData* d) {
        d->GetPointData()->GetNormals()->SetComponent(3, 1, std::nan(""));
        d->GetPointData()->GetArray("Velocity")->SetComponent(4, 0, std::nan(""));
      },
      [](vtkPointPairDeformationFilter* f) {
        f->GetVectorArraySelection()->EnableArray("Velocity");
      },
      "2 are NaN or infinite", false },
  };
  for (const Case& c : cases)
  {
    auto data = cloud(random, 20);
    c.data(data);
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter counter(filter);
    EventCounter* events = &counter;
    filter->SetInputData(data);
    configure(filter, setup);
    c.set(filter);
    filter->Update();
    if (c.error)
    {
      EXPECT_EQ(events->errors, 1) << c.what;
      EXPECT_NE(events->lastError.find(c.message), std::string::npos)
        << c.what << ": " << events->lastError;
      EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << c.what;
    }
    else
    {
      EXPECT_EQ(events->errors, 0) << c.what << ": " << events->lastError;
      EXPECT_EQ(events->warnings, 1) << c.what;
      EXPECT_NE(events->lastWarning.find(c.message), std::string::npos)
        << c.what << ": " << events->lastWarning;
      EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 20) << c.what;
    }
    if (std::string(c.what) == "NaN normals and vectors")
    {
      vtkPointData* out = filter->GetOutput()->GetPointData();
      EXPECT_TRUE(std::isnan(out->GetNormals()->GetComponent(3, 1)));
      EXPECT_EQ(out->GetNormals()->GetComponent(3, 0), data->GetPointData()->GetNormals()->GetComponent(3, 0));
      EXPECT_TRUE(std::isnan(out->GetArray("Velocity")->GetComponent(4, 0)));
      for (vtkIdType i = 0; i < 20; ++i) // the others are finite
      {
        if (i != 3)
        {
          EXPECT_TRUE(std::isfinite(cga::norm(tupleOf(out->GetNormals(), i))));
        }
      }
    }
  }
}
// A translation of weight 1.5e308 at distance 1 (eps 0.01) moves a point by 1.49e308, finite,
// while its derivative, about 2.9e308, is not: the image is still mapPoints' (bit for bit), J is
// the identity there, with one warning.
TEST(PointPairDeformationDerivatives, WhereTheDerivativeOverflowsTheImageIsStillMapped)
{
  FieldSetup setup;
  setup.generators = { { GeneratorKind::Translation, { 0, 0, 0 }, { 1, 0, 0 }, 0.0, 1.5e308 } };
  setup.epsilon = 0.01;
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->InsertNextPoint(1.0, 0.0, 0.0);
  points->InsertNextPoint(0.0, 30.0, 0.0); // far: finite J
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  normals->InsertNextTuple3(0, 0, 1);
  normals->InsertNextTuple3(0.6, 0, 0.8);
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->GetPointData()->SetNormals(normals);
  // 0: no derivative; 1: the normals alone (two tangents: J t1 = t1, J t2 = (G, 1, 0) at the far
  // point, the same normal); 2: and ConformalScale (J).
  std::string images[3];
  for (const int derivatives : { 0, 1, 2 })
  {
    vtkNew<vtkPointPairDeformationFilter> filter;
    EventCounter events(filter);
    filter->SetInputData(data);
    configure(filter, setup);
    filter->SetTransformNormals(derivatives > 0);
    filter->SetComputeConformalScale(derivatives == 2);
    filter->Update();
    EXPECT_EQ(events.errors, 0) << events.lastError;
    images[derivatives] = outputBytes(filter->GetOutput());
    EXPECT_GT(filter->GetOutput()->GetPoint(0)[0], 1e308);
    if (derivatives > 0)
    {
      EXPECT_EQ(events.warnings, 1);
      EXPECT_NE(events.lastWarning.find("overflows at 1 of 2 points"), std::string::npos)
        << events.lastWarning;
      if (derivatives == 2)
      {
        EXPECT_EQ(
          filter->GetOutput()->GetPointData()->GetArray("ConformalScale")->GetComponent(0, 0), 1.0);
      }
      EXPECT_EQ(filter->GetOutput()->GetPointData()->GetNormals()->GetComponent(0, 2), 1.0);
      // At the far point J = I + e1 g^T, g = (0, G, 0), G = -2 w 30 / 900.01^2 = -1.1e304:
      // cof(J) n = n - g n_x = (0.6, -0.6 G, 0.8), whose squared length (4e607) overflows: the
      // scaled columns give its direction, (0, 1, 0) to 1e-304.
      const Vec3 n = tupleOf(filter->GetOutput()->GetPointData()->GetNormals(), 1);
      EXPECT_EQ(n.y, 1.0);
      EXPECT_LE(std::fabs(n.x) + std::fabs(n.z), 1e-300);
    }
  }
  EXPECT_TRUE(images[0] == images[1] && images[0] == images[2]);
}

// A lone dilation of weight w about the origin along z (eps 0.01), the field of the tests below.
FieldSetup loneDilation(double weight)
{
  FieldSetup setup;
  setup.generators = { { GeneratorKind::Dilation, { 0, 0, 0 }, { 0, 0, 1 }, 0.0, weight } };
  setup.epsilon = 0.01;
  return setup;
}

// A lone dilation of weight w about the origin scales a point p next to it by about
// e^(S w / eps) (the closed form of ALoneDilationHasItsClosedFormScaleAndDefect at r ~ 0): with
// w = 0.9, eps = 0.01, 1.2e39, beyond the largest float, while the images of p = 1e-30 and 1e-20,
// 1.2e9 and 1.2e19, are not.
TEST(PointPairDeformationDerivatives, ASingleScaleBeyondTheLargestFloatIsAnError)
{
  const FieldSetup setup = loneDilation(0.9);
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_FLOAT);
  points->InsertNextPoint(1e-30, 0.0, 0.0);
  points->InsertNextPoint(0.0, 1e-20, 0.0);
  points->InsertNextPoint(0.0, 0.0, 3.0); // far: a scale of e^0.1
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  const double expectedScale = std::exp(0.9 / 0.01);
  ASSERT_GT(expectedScale, static_cast<double>(std::numeric_limits<float>::max()));
  for (const bool scale : { false, true })
  {
    for (const int precision : { vtkAlgorithm::DEFAULT_PRECISION, vtkAlgorithm::DOUBLE_PRECISION })
    {
      vtkNew<vtkPointPairDeformationFilter> filter;
      EventCounter events(filter);
      filter->SetInputData(data);
      configure(filter, setup);
      filter->SetComputeConformalScale(scale);
      filter->SetOutputPointsPrecision(precision);
      filter->Update();
      vtkPointSet* output = filter->GetOutput();
      const std::string what = std::string(scale ? "with" : "without") + " ConformalScale, " +
        (precision == vtkAlgorithm::DOUBLE_PRECISION ? "double" : "float") + " output";
      if (scale && precision == vtkAlgorithm::DEFAULT_PRECISION)
      {
        EXPECT_EQ(events.errors, 1) << what;
        EXPECT_NE(events.lastError.find("the ConformalScale of 2 of 3 points is beyond the "
                                        "largest single-precision value"),
          std::string::npos)
          << events.lastError;
        EXPECT_EQ(output->GetNumberOfPoints(), 0) << what;
        continue;
      }
      EXPECT_EQ(events.errors, 0) << what << ": " << events.lastError;
      ASSERT_EQ(output->GetNumberOfPoints(), 3) << what;
      EXPECT_NEAR(output->GetPoint(0)[0] / (1e-30 * expectedScale), 1.0, 1e-6) << what;
      EXPECT_NEAR(output->GetPoint(1)[1] / (1e-20 * expectedScale), 1.0, 1e-6) << what;
      if (scale)
      {
        vtkDataArray* scales = output->GetPointData()->GetArray("ConformalScale");
        ASSERT_NE(scales, nullptr);
        EXPECT_EQ(scales->GetDataType(), VTK_DOUBLE);
        EXPECT_NEAR(scales->GetComponent(0, 0) / expectedScale, 1.0, 1e-12) << what;
      }
    }
  }
}

// At the point (1e-3, -2e-3, 0.5e-3), next to the center of the dilations below, with the normal n:
// the deformed normal n', and with `jacobian` ConformalScale and ConformalityDefect (else NaN); no
// error or warning expected.
struct NextToTheCenter
{
  Vec3 normal;
  double scale, defect;
};
const Vec3 kNextToTheCenter{ 1e-3, -2e-3, 0.5e-3 };

NextToTheCenter normalNextToTheCenter(const FieldSetup& setup, Vec3 n, bool jacobian)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->InsertNextPoint(kNextToTheCenter.x, kNextToTheCenter.y, kNextToTheCenter.z);
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  normals->InsertNextTuple3(n.x, n.y, n.z);
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->GetPointData()->SetNormals(normals);
  vtkNew<vtkPointPairDeformationFilter> filter;
  EventCounter events(filter);
  filter->SetInputData(data);
  configure(filter, setup);
  filter->SetComputeConformalScale(jacobian);
  filter->SetComputeConformalityDefect(jacobian);
  filter->Update();
  EXPECT_EQ(events.errors + events.warnings, 0) << events.lastError << events.lastWarning;
  vtkPointData* out = filter->GetOutput()->GetPointData();
  const double none = std::numeric_limits<double>::quiet_NaN();
  return { tupleOf(out->GetNormals(), 0),
    jacobian ? out->GetArray("ConformalScale")->GetComponent(0, 0) : none,
    jacobian ? out->GetArray("ConformalityDefect")->GetComponent(0, 0) : none };
}

// n' = |n| cof(J) n / |cof(J) n| is linear in |n|: a normal of any length comes out as the unit
// normal's image times that length. Here where J is about s I with s = e^(w / 0.01) (a lone
// dilation's center), so cof(J) n and J t1 x J t2 are about s^2 |n|: with s = 1e-80, |n| = 1e38 the
// ratio of the squared lengths (1e76 / 1e-244) overflowed to an infinite normal, and with s = 1e80,
// |n| = 1e-135 it underflowed (n' from cof(J), with ConformalScale, which needs J); s = 1e-30 and
// 1e30 with |n| = 1e100 and 1e-100 did the same for n' from the images of two tangents (the
// normals alone).
TEST(PointPairDeformationDerivatives, NormalsOfExtremeLengthKeepTheirLengthWhereJIsExtreme)
{
  const Vec3 unit = cga::normalized(Vec3{ 0.3, -0.5, 0.8 });
  for (const double weight : { -1.84, 1.84, -0.69, 0.69 })
  {
    const FieldSetup setup = loneDilation(weight);
    for (const bool jacobian : { false, true })
    {
      const Vec3 expected = normalNextToTheCenter(setup, unit, jacobian).normal;
      ASSERT_NEAR(cga::norm(expected), 1.0, 1e-15);
      for (const double length : { 1e38, 1e-135, 1e100, 1e-100, 1e150, 1e-150 })
      {
        const Vec3 n = normalNextToTheCenter(setup, unit * length, jacobian).normal;
        std::ostringstream what;
        what << "weight " << weight << ", |n| " << length
             << (jacobian ? ", from J" : ", from two tangents");
        EXPECT_TRUE(cga::isFinite(n)) << what.str();
        EXPECT_LE(cga::norm(n / length - expected), 1e-14) << what.str();
      }
    }
  }
}

// Next to the center of a lone dilation of weight -7.14 J is about e^-714 I = 1.4e-310 I, a
// subnormal with about 45 bits. The normal from cof(J) (with J's arrays) once took each column's
// 1 / 1.4e-310, which overflows, and left n unchanged as if J flattened the tangent plane, while
// the two tangents' images (the normals alone) gave the normal; ConformalityDefect took J's
// 1 / 1.4e-310 and gave 1. Now both normals agree, and the scale and the defect are
// ALoneDilationHasItsClosedFormScaleAndDefect's closed forms, to J's own precision.
TEST(PointPairDeformationDerivatives, WhereJIsSubnormalTheNormalsScaleAndDefectStayRight)
{
  const double weight = -7.14;
  const FieldSetup setup = loneDilation(weight);
  const Vec3 n{ 0.6, 0.0, 0.8 };
  const Vec3 fromTangents = normalNextToTheCenter(setup, n, false).normal;
  const NextToTheCenter fromJ = normalNextToTheCenter(setup, n, true);
  EXPECT_GT(cga::norm(fromTangents - n), 0.1); // the map turns it
  EXPECT_LE(cga::norm(fromJ.normal - fromTangents), 1e-12);
  const double r2 = cga::norm2(kNextToTheCenter);
  const double d = r2 + setup.epsilon;
  const double g = -2.0 * weight * r2 / (d * d);
  const double scale = std::exp(weight / d) * std::cbrt(std::fabs(1.0 + g));
  EXPECT_LT(scale, std::numeric_limits<double>::min()); // subnormal
  EXPECT_NEAR(fromJ.scale / scale, 1.0, 1e-12);
  EXPECT_NEAR(fromJ.defect, 1.0 - 1.0 / std::fabs(1.0 + g), 1e-12); // 0.43
}
} // namespace
