// vtkPointPairDeformationFilter with a Tolerance fits the generator tree's cells to its whole
// input (cga::PointPairField::planTreeCells) before mapping it in chunks: its images are the
// planned field's to the bit, for double, float and SOA points, and not the unplanned field's.
#include "vtkPointPairDeformationFilter.h"

#include "TestSupport.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSOADataArrayTemplate.h"

#include "cga/PointPairField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

namespace
{
using cga::GeneratorParameters;
using cgatest::Random;

constexpr double kEpsilon = 0.05;
constexpr double kStrength = 0.5;
constexpr double kTolerance = 1e-3;

// A sparse wavy sheet: side x side points over [-2, 2]^2, far sparser than the tree's leaves.
std::vector<double> sparseSheet(int side)
{
  std::vector<double> xyz;
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      const double x = -2.0 + 4.0 * i / (side - 1), y = -2.0 + 4.0 * j / (side - 1);
      xyz.insert(xyz.end(), { x, y, 0.3 * std::sin(2.0 * x) * std::cos(3.0 * y) });
    }
  }
  return xyz;
}

// The filter's images of `points` (stored as given) under `generators` at kTolerance.
template <typename Array>
std::vector<double> filterImages(const std::vector<GeneratorParameters>& generators,
                                 const std::vector<double>& xyz)
{
  vtkNew<Array> array;
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(xyz.size() / 3));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      array->SetTypedComponent(i, k, static_cast<typename Array::ValueType>(xyz[3 * i + k]));
    }
  }
  vtkNew<vtkPoints> points;
  points->SetData(array);
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  vtkNew<vtkPointPairDeformationFilter> filter;
  filter->SetInputData(mesh);
  for (const GeneratorParameters& g : generators)
  {
    filter->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
  filter->SetEpsilon(kEpsilon);
  filter->SetStrength(kStrength);
  filter->SetTolerance(kTolerance);
  filter->Update();
  vtkDataArray* out = filter->GetOutput()->GetPoints()->GetData();
  std::vector<double> images(static_cast<std::size_t>(3 * out->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < out->GetNumberOfTuples(); ++i)
  {
    out->GetTuple(i, images.data() + 3 * i);
  }
  return images;
}

// The core field's images, planned for `xyz` or not, in the points' type T.
template <typename T>
std::vector<double> fieldImages(const std::vector<GeneratorParameters>& generators,
                                const std::vector<double>& xyz, bool planned)
{
  cga::PointPairField field(generators.data(), generators.size(), 1.0, kEpsilon);
  EXPECT_TRUE(field.setTolerance(kTolerance));
  EXPECT_GT(field.treeBytes(), 0u);
  const std::vector<T> in(xyz.begin(), xyz.end());
  if (planned)
  {
    EXPECT_GT(field.planTreeCells(in.data(), in.size() / 3), 0);
  }
  std::vector<T> out(in.size());
  EXPECT_EQ(field.mapPoints(in.data(), out.data(), in.size() / 3, kStrength,
              cga::ExponentialRule::Exact),
    0u);
  return std::vector<double>(out.begin(), out.end());
}

TEST(PointPairDeformationTreeCells, TheFilterFitsTheTreesCellsToItsWholeInput)
{
  Random random(53);
  std::vector<GeneratorParameters> generators;
  const std::size_t count = cga::PointPairField::treeMinimumGenerators();
  for (std::size_t i = 0; i < count; ++i)
  {
    GeneratorParameters g;
    g.location = { random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-0.3, 0.3) };
    g.direction = random.unit();
    g.weight = random.uniform(0.1, 0.4) * 16.0 / static_cast<double>(count);
    generators.push_back(g);
  }
  const std::vector<double> sheet = sparseSheet(40);
  const std::vector<double> planned = fieldImages<double>(generators, sheet, true);
  ASSERT_EQ(planned.size(), sheet.size());
  EXPECT_NE(planned, fieldImages<double>(generators, sheet, false)) << "the plan changes the bits";
  EXPECT_EQ(filterImages<vtkDoubleArray>(generators, sheet), planned) << "double points";
  EXPECT_EQ(filterImages<vtkSOADataArrayTemplate<double>>(generators, sheet), planned)
    << "SOA points (planned through a copy)";
  EXPECT_EQ(filterImages<vtkFloatArray>(generators, sheet), fieldImages<float>(generators, sheet, true))
    << "float points";
}
} // namespace
