// Internal: the step of cga::surfaceCurvature that lane code (BoostedCircleRow::curvatures) calls
// per sample as it is, so that it is written once.
#pragma once

#include "cga/Vec3.h"

namespace cga
{
/// The unit principal directions from the shape operator W = [[w11, w12], [w12, w22]] in the
/// orthonormal tangent frame (t1, t2) of the unit normal n, half = (w11 - w22) / 2 and radius
/// W's eigenvalues' half difference: direction1 (of the larger curvature) signed along the nearer
/// of t1 and t2, t1 at an umbilic; direction2 = n x direction1.
void principalDirections(Vec3 n, Vec3 t1, Vec3 t2, double w11, double w12, double w22,
  double half, double radius, Vec3& direction1, Vec3& direction2);
} // namespace cga
