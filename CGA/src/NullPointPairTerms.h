// Internal: the closed form of the null point pair tau(x, v) written into an accumulator, as a
// template over the number types of the accumulator, the weight and x: double for
// nullPointPairCompact and the sums of PointPairs.cpp, dual numbers for the derivatives of the
// curvature operators (src/surfaces/CurvatureOperatorTerms.h), so that both run the same formula.
#pragma once

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include "ForceInline.h"

namespace cga
{
namespace detail
{
/// b[0..9] += w tau(x, v) in Bivector's component order (b a Bivector or an array of ten
/// numbers); x[0..2] the location, v a constant direction (its length multiplies the weight).
/// Polynomial of degree 2 in x.
template <typename Accumulator, typename W, typename X>
BOOSTED_FORCE_INLINE void addNullPointPair(Accumulator& b, const W& w, const X* x, Vec3 v)
{
  using B = Bivector;
  const X vx = v.x * x[0] + v.y * x[1] + v.z * x[2];
  const X half = 0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  b[B::E12] = b[B::E12] + w * (x[0] * v.y - x[1] * v.x);
  b[B::E13] = b[B::E13] + w * (x[0] * v.z - x[2] * v.x);
  b[B::E23] = b[B::E23] + w * (x[1] * v.z - x[2] * v.y);
  b[B::E1NO] = b[B::E1NO] - w * v.x;
  b[B::E2NO] = b[B::E2NO] - w * v.y;
  b[B::E3NO] = b[B::E3NO] - w * v.z;
  b[B::E1NI] = b[B::E1NI] + w * (vx * x[0] - half * v.x);
  b[B::E2NI] = b[B::E2NI] + w * (vx * x[1] - half * v.y);
  b[B::E3NI] = b[B::E3NI] + w * (vx * x[2] - half * v.z);
  b[B::NONI] = b[B::NONI] + w * vx;
}
} // namespace detail
} // namespace cga
