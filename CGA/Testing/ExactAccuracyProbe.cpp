// Maps point sets through PointPairField's Exact rule for test_exact_accuracy.py, which compares
// them with a high-precision reference (Testing/Python/exact_reference.py). Reads from stdin, for
// each configuration:
//   falloff epsilon strength generators points
//   x y z dx dy dz weight        (one line per point-pair generator)
//   px py pz                     (one line per point)
// and prints per point the batch image (mapPoints), the pointwise image (map) and the Jacobian
// d image / d p (mapWithJacobian, row-major), 17 digits each, or "unmapped" for a point any of
// them leaves unchanged.
#include "cga/PointPairField.h"

#include <cstdio>
#include <vector>

int main()
{
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
