// vtkDipoleFieldSource with a Tolerance fits method (a)'s generator tree cells to its grid
// (cga::DipoleField::planTreeCells) before sampling it in chunks: its DisplacementSummedGenerators
// are the planned field's to the bit, and not the unplanned field's.
#include "vtkDipoleFieldSource.h"

#include "TestSupport.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include "cga/DipoleField.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
constexpr int kSide = 20;
constexpr double kStep = 4.0 / (kSide - 1);
constexpr double kEpsilon = 0.05;

// Method (a)'s displacements of the source's grid (x fastest) by the core field.
std::vector<double> methodA(const std::vector<cga::GeneratorParameters>& generators, bool planned)
{
  cga::DipoleField field(generators.data(), generators.size(), 1.0, kEpsilon);
  EXPECT_TRUE(field.setTolerance(1e-3));
  std::vector<double> points;
  for (int j = 0; j < kSide; ++j)
  {
    for (int i = 0; i < kSide; ++i)
    {
      points.insert(points.end(), { -2.0 + i * kStep, -2.0 + j * kStep, 0.0 });
    }
  }
  const std::size_t n = points.size() / 3;
  if (planned)
  {
    EXPECT_GT(field.planTreeCells(n,
                [&](std::size_t first, std::size_t count, double* xyz) {
                  std::copy_n(points.data() + 3 * first, 3 * count, xyz);
                }),
      0);
  }
  std::vector<double> a(3 * n), b(3 * n), phi(n), scratch(3 * n);
  EXPECT_EQ(field.sampleMany(points.data(), n, 1.0, a.data(), b.data(), phi.data(), scratch.data()),
    0u);
  return a;
}

TEST(DipoleFieldTreeCells, TheSourceFitsTheTreesCellsToItsGrid)
{
  cgatest::Random random(59);
  vtkNew<vtkDipoleFieldSource> source;
  source->RemoveAllGenerators();
  std::vector<cga::GeneratorParameters> generators;
  const std::size_t count = cga::PointPairField::treeMinimumGenerators();
  for (std::size_t i = 0; i < count; ++i)
  {
    cga::GeneratorParameters g;
    g.location = { random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-0.3, 0.3) };
    g.direction = random.unit();
    g.weight = random.uniform(0.1, 0.4) * 16.0 / static_cast<double>(count);
    generators.push_back(g);
    source->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x, g.direction.y,
      g.direction.z, g.weight);
  }
  source->SetOrigin(-2, -2, 0);
  source->SetSpacing(kStep, kStep, 1);
  source->SetDimensions(kSide, kSide, 1);
  source->SetFalloff(1.0);
  source->SetEpsilon(kEpsilon);
  source->SetTolerance(1e-3);
  source->Update();
  vtkDataArray* array =
    source->GetOutput()->GetPointData()->GetArray("DisplacementSummedGenerators");
  ASSERT_NE(array, nullptr);
  ASSERT_EQ(array->GetNumberOfTuples(), kSide * kSide);
  std::vector<double> values(static_cast<std::size_t>(3 * array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->GetTuple(i, values.data() + 3 * i);
  }
  const std::vector<double> planned = methodA(generators, true);
  EXPECT_NE(planned, methodA(generators, false)) << "the plan changes the bits";
  EXPECT_EQ(values, planned);
}
} // namespace
