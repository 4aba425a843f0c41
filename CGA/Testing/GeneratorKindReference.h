// The generator kinds built on the full Multivector from their definitions (docs/conventions.md
// section 2 item 11): the independent reference of the kernel's and the VTK classes' tests.
#pragma once

#include "cga/Conformal.h"
#include "cga/Multivector.h"
#include "cga/PointPairField.h"

#include <vector>

namespace cgatest
{
constexpr cga::GeneratorKind kAllKinds[] = { cga::GeneratorKind::PointPair,
                                             cga::GeneratorKind::Rotation,
                                             cga::GeneratorKind::Twist,
                                             cga::GeneratorKind::Dilation,
                                             cga::GeneratorKind::Translation };

inline cga::Multivector referenceBivector(const cga::GeneratorParameters& g)
{
  using namespace cga;
  const Multivector t = translator(g.location);
  const Multivector axisPlane = vector(g.direction) * euclideanPseudoscalar();
  switch (g.kind)
  {
    case GeneratorKind::PointPair:
      return nullPointPair(g.location, g.direction);
    case GeneratorKind::Rotation:
      return 0.5 * sandwich(t, axisPlane);
    case GeneratorKind::Twist:
      return 0.5 * sandwich(t, axisPlane) + (0.5 * g.pitch) * (vector(g.direction) * ni());
    case GeneratorKind::Dilation:
      return (-0.5 * norm(g.direction)) * sandwich(t, minkowskiPlane());
    case GeneratorKind::Translation:
      return 0.5 * (vector(g.direction) * ni());
  }
  return Multivector();
}

/// B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps) on the full Multivector.
inline cga::Multivector referenceField(const std::vector<cga::GeneratorParameters>& generators,
                                       cga::Vec3 p,
                                       double k,
                                       double eps)
{
  cga::Multivector b;
  for (const cga::GeneratorParameters& g : generators)
  {
    b += referenceBivector(g) * (g.weight / (k * cga::norm2(p - g.location) + eps));
  }
  return b;
}
} // namespace cgatest
