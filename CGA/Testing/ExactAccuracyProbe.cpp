// Maps point sets through PointPairField's Exact rule for test_exact_accuracy.py, which compares
// them with a high-precision reference (Testing/Python/exact_reference.py). Reads from stdin, for
// each configuration:
//   falloff epsilon strength generators points
//   kind x y z dx dy dz pitch weight     (one line per generator, kind 0 ... 4: GeneratorKind)
//   5 x y z c0 ... c9 weight             (or a bivector given in space: its ten components)
//   px py pz                             (one line per point)
// and builds the field twice where it can: from FieldGenerator::of (the named constructors, which
// the field moves from about the origin) or the given bivector, and from GeneratorParameters rows
// (as the VTK classes pass them, built at x - c) when every generator has a kind. It prints per
// point the first field's batch image (mapPoints), pointwise image (map) and Jacobian
// d image / d p (mapWithJacobian, row-major), then the rows field's batch and pointwise images
// (when there is one), 17 digits each, or "unmapped" for a point any image leaves unchanged (a
// refused Jacobian is written as nine NaNs).
//
// With the argument "exponents" it maps given exponents instead (mapPointsByExponentials, the
// curvature patch's map), reading "count" and then per point the ten Bivector components of b and
// p, and prints per point the batch image (mapPointsByExponentials) and the pointwise one
// (sandwichPoint(exponential(b, Exact), p)), or "unmapped".
//
// With the argument "derivatives" it reads configurations as above (FieldGenerator::of or the
// given bivector) and prints per point B(p) (generatorAt: the ten components, in space), the image
// and d out / d B of mapWithBivectorDerivative (30 numbers, byBivector[10 j + c]), then
// d out / d w_i of mapWithWeightDerivatives (3 per generator), or "unmapped" where either refuses
// the point (test_strong_derivatives.py).
#include "cga/ExponentialMap.h"
#include "cga/PointPairField.h"
#include "cga/PointSandwich.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace
{
int mapExponents()
{
  int count;
  if (std::scanf("%d", &count) != 1 || count < 0)
  {
    return 2;
  }
  std::vector<cga::Bivector> exponents(count);
  std::vector<cga::Vec3> points(count), batch(count);
  for (int i = 0; i < count; ++i)
  {
    for (double& c : exponents[i].c)
    {
      if (std::scanf("%lf", &c) != 1)
      {
        return 2;
      }
    }
    if (std::scanf("%lf %lf %lf", &points[i].x, &points[i].y, &points[i].z) != 3)
    {
      return 2;
    }
  }
  const std::unique_ptr<bool[]> ok(new bool[count]);
  cga::mapPointsByExponentials(
    exponents.data(), points.data(), count, cga::ExponentialRule::Exact, batch.data(), ok.get());
  for (int i = 0; i < count; ++i)
  {
    cga::Vec3 pointwise;
    if (!ok[i] ||
      !cga::sandwichPoint(cga::exponential(exponents[i], cga::ExponentialRule::Exact), points[i], pointwise))
    {
      std::printf("unmapped\n");
      continue;
    }
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", batch[i].x, batch[i].y, batch[i].z,
      pointwise.x, pointwise.y, pointwise.z);
  }
  return 0;
}
} // namespace

namespace
{
constexpr int kBivectorGenerator = 5;

// One generator line: its FieldGenerator, and its row when it has a kind. False on bad input.
bool readGenerator(cga::FieldGenerator& field, cga::GeneratorParameters& row, bool& hasRow)
{
  int kind;
  cga::Vec3 x;
  if (std::scanf("%d %lf %lf %lf", &kind, &x.x, &x.y, &x.z) != 4)
  {
    return false;
  }
  if (kind == kBivectorGenerator)
  {
    cga::Bivector b;
    for (double& c : b.c)
    {
      if (std::scanf("%lf", &c) != 1)
      {
        return false;
      }
    }
    double weight;
    if (std::scanf("%lf", &weight) != 1)
    {
      return false;
    }
    field = cga::FieldGenerator{ x, b, weight };
    hasRow = false;
    return true;
  }
  row.kind = static_cast<cga::GeneratorKind>(kind);
  row.location = x;
  if (!cga::isGeneratorKind(kind) ||
    std::scanf("%lf %lf %lf %lf %lf", &row.direction.x, &row.direction.y, &row.direction.z,
      &row.pitch, &row.weight) != 5)
  {
    return false;
  }
  field = cga::FieldGenerator::of(row.kind, x, row.direction, row.pitch, row.weight);
  hasRow = true;
  return true;
}
} // namespace

namespace
{
void printDerivatives(const cga::PointPairField& field, const std::vector<double>& points, double strength)
{
  constexpr int kBivector = cga::Bivector::Count;
  for (std::size_t i = 0; 3 * i < points.size(); ++i)
  {
    const cga::Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
    cga::Vec3 image, weighted;
    double byBivector[3 * kBivector];
    std::vector<double> byWeight(3 * field.size());
    if (!field.mapWithBivectorDerivative(p, strength, cga::ExponentialRule::Exact, image, byBivector) ||
      !field.mapWithWeightDerivatives(p, strength, cga::ExponentialRule::Exact, weighted, byWeight.data()))
    {
      std::printf("unmapped\n");
      continue;
    }
    for (const double c : field.generatorAt(p).c)
    {
      std::printf("%.17g ", c);
    }
    std::printf("%.17g %.17g %.17g", image.x, image.y, image.z);
    for (const double entry : byBivector)
    {
      std::printf(" %.17g", entry);
    }
    for (const double entry : byWeight)
    {
      std::printf(" %.17g", entry);
    }
    std::printf("\n");
  }
}
} // namespace

int main(int argc, char** argv)
{
  if (argc > 1 && std::strcmp(argv[1], "exponents") == 0)
  {
    return mapExponents();
  }
  const bool derivatives = argc > 1 && std::strcmp(argv[1], "derivatives") == 0;
  double falloff, epsilon, strength;
  int generatorCount, pointCount;
  while (std::scanf("%lf %lf %lf %d %d", &falloff, &epsilon, &strength, &generatorCount,
                    &pointCount) == 5)
  {
    std::vector<cga::FieldGenerator> generators(generatorCount);
    std::vector<cga::GeneratorParameters> rows(generatorCount);
    bool everyRow = true;
    for (int g = 0; g < generatorCount; ++g)
    {
      bool hasRow = false;
      if (!readGenerator(generators[g], rows[g], hasRow))
      {
        return 2;
      }
      everyRow = everyRow && hasRow;
    }
    std::vector<double> points(3 * pointCount), batch(3 * pointCount), rowsBatch(3 * pointCount);
    for (double& c : points)
    {
      if (std::scanf("%lf", &c) != 1)
      {
        return 2;
      }
    }
    const cga::PointPairField field(generators.data(), generators.size(), falloff, epsilon);
    if (derivatives)
    {
      printDerivatives(field, points, strength);
      continue;
    }
    const cga::PointPairField rowsField(everyRow ? rows.data() : nullptr,
      everyRow ? rows.size() : 0, falloff, epsilon);
    field.mapPoints(points.data(), batch.data(), pointCount, strength, cga::ExponentialRule::Exact);
    rowsField.mapPoints(
      points.data(), rowsBatch.data(), pointCount, strength, cga::ExponentialRule::Exact);
    for (int i = 0; i < pointCount; ++i)
    {
      const cga::Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      cga::Vec3 pointwise, withJacobian, rowsPointwise;
      double jacobian[9];
      if (!field.map(p, strength, cga::ExponentialRule::Exact, pointwise) ||
        (everyRow && !rowsField.map(p, strength, cga::ExponentialRule::Exact, rowsPointwise)))
      {
        std::printf("unmapped\n");
        continue;
      }
      if (!field.mapWithJacobian(p, strength, cga::ExponentialRule::Exact, withJacobian, jacobian))
      {
        // Refused (its tangents overflow beyond weights of about 1e90): NaN entries, a failure
        // where the test checks the Jacobian.
        std::fill(jacobian, jacobian + 9, std::numeric_limits<double>::quiet_NaN());
      }
      std::printf("%.17g %.17g %.17g %.17g %.17g %.17g", batch[3 * i], batch[3 * i + 1],
                  batch[3 * i + 2], pointwise.x, pointwise.y, pointwise.z);
      for (const double entry : jacobian)
      {
        std::printf(" %.17g", entry);
      }
      if (everyRow)
      {
        std::printf(" %.17g %.17g %.17g %.17g %.17g %.17g", rowsBatch[3 * i], rowsBatch[3 * i + 1],
          rowsBatch[3 * i + 2], rowsPointwise.x, rowsPointwise.y, rowsPointwise.z);
      }
      std::printf("\n");
    }
  }
  return 0;
}
