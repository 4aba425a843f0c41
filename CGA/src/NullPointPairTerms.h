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
/// tau(x, v)'s pieces that do not depend on the weight, in the number type X of x: the three
/// e_ij parts, x.v and the three e_i ni parts (the e_i no parts are -v). A sum whose locations
/// and directions are fixed (the curvature patch's corners) computes them once.
template <typename X>
struct NullPointPairTerms
{
  X e12, e13, e23, vx, e1ni, e2ni, e3ni;
  Vec3 v;
};

template <typename X>
BOOSTED_FORCE_INLINE NullPointPairTerms<X> nullPointPairTerms(const X* x, Vec3 v)
{
  const X vx = v.x * x[0] + v.y * x[1] + v.z * x[2];
  const X half = 0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  return { x[0] * v.y - x[1] * v.x, x[0] * v.z - x[2] * v.x, x[1] * v.z - x[2] * v.y, vx,
    vx * x[0] - half * v.x, vx * x[1] - half * v.y, vx * x[2] - half * v.z, v };
}

/// b[0..9] += w tau(x, v) from its pieces (nullPointPairTerms), in Bivector's component order.
template <typename Accumulator, typename W, typename X>
BOOSTED_FORCE_INLINE void addNullPointPairTerms(
  Accumulator& b, const W& w, const NullPointPairTerms<X>& t)
{
  using B = Bivector;
  b[B::E12] = b[B::E12] + w * t.e12;
  b[B::E13] = b[B::E13] + w * t.e13;
  b[B::E23] = b[B::E23] + w * t.e23;
  b[B::E1NO] = b[B::E1NO] - w * t.v.x;
  b[B::E2NO] = b[B::E2NO] - w * t.v.y;
  b[B::E3NO] = b[B::E3NO] - w * t.v.z;
  b[B::E1NI] = b[B::E1NI] + w * t.e1ni;
  b[B::E2NI] = b[B::E2NI] + w * t.e2ni;
  b[B::E3NI] = b[B::E3NI] + w * t.e3ni;
  b[B::NONI] = b[B::NONI] + w * t.vx;
}

/// b[0..9] += w tau(x, v) in Bivector's component order (b a Bivector or an array of ten
/// numbers); x[0..2] the location, v a constant direction (its length multiplies the weight).
/// Polynomial of degree 2 in x.
template <typename Accumulator, typename W, typename X>
BOOSTED_FORCE_INLINE void addNullPointPair(Accumulator& b, const W& w, const X* x, Vec3 v)
{
  addNullPointPairTerms(b, w, nullPointPairTerms(x, v));
}
} // namespace detail
} // namespace cga
