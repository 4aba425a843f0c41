// Maps point sets through PointPairField's Exact rule for test_exact_accuracy.py, which compares
// them with a high-precision reference (Testing/Python/exact_reference.py). Reads from stdin, for
// each configuration:
//   falloff epsilon strength generators points
//   x y z dx dy dz weight        (one line per point-pair generator)
//   px py pz                     (one line per point)
// and prints per point the batch image (mapPoints), the pointwise image (map) and the Jacobian
// d image / d p (mapWithJacobian, row-major), 17 digits each, or "unmapped" for a point any of
// them leaves unchanged.
//
// With the argument "exponents" it maps given exponents instead (mapPointsByExponentials, the
// curvature patch's map), reading "count" and then per point the ten Bivector components of b and
// p, and prints per point the batch image (mapPointsByExponentials) and the pointwise one
// (sandwichPoint(exponential(b, Exact), p)), or "unmapped".
#include "cga/ExponentialMap.h"
#include "cga/PointPairField.h"
#include "cga/PointSandwich.h"

#include <cstdio>
#include <cstring>
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

int main(int argc, char** argv)
{
  if (argc > 1 && std::strcmp(argv[1], "exponents") == 0)
  {
    return mapExponents();
  }
  double falloff, epsilon, strength;
  int generatorCount, pointCount;
  while (std::scanf("%lf %lf %lf %d %d", &falloff, &epsilon, &strength, &generatorCount,
                    &pointCount) == 5)
  {
    std::vector<cga::PointPairGenerator> generators(generatorCount);
    for (cga::PointPairGenerator& g : generators)
    {
      if (std::scanf("%lf %lf %lf %lf %lf %lf %lf", &g.location.x, &g.location.y, &g.location.z,
                     &g.direction.x, &g.direction.y, &g.direction.z, &g.weight) != 7)
      {
        return 2;
      }
    }
    std::vector<double> points(3 * pointCount), batch(3 * pointCount);
    for (double& c : points)
    {
      if (std::scanf("%lf", &c) != 1)
      {
        return 2;
      }
    }
    const cga::PointPairField field(generators, falloff, epsilon);
    field.mapPoints(points.data(), batch.data(), pointCount, strength, cga::ExponentialRule::Exact);
    for (int i = 0; i < pointCount; ++i)
    {
      const cga::Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
      cga::Vec3 pointwise, withJacobian;
      double jacobian[9];
      if (!field.map(p, strength, cga::ExponentialRule::Exact, pointwise) ||
        !field.mapWithJacobian(p, strength, cga::ExponentialRule::Exact, withJacobian, jacobian))
      {
        std::printf("unmapped\n");
        continue;
      }
      std::printf("%.17g %.17g %.17g %.17g %.17g %.17g", batch[3 * i], batch[3 * i + 1],
                  batch[3 * i + 2], pointwise.x, pointwise.y, pointwise.z);
      for (const double entry : jacobian)
      {
        std::printf(" %.17g", entry);
      }
      std::printf("\n");
    }
  }
  return 0;
}
