// Internal: forward-mode automatic differentiation for the templates of PointMapCore.h.
//
// Dual<T, N> is a value of the number type T with N tangents (its derivatives with respect to N
// seeds), and is itself a number type of PointMapCore.h: the map's own source, run on Dual
// values, computes the map's derivative exactly (to rounding), with every branch, frame and
// selection the value takes. T is double (the pointwise derivatives), the block kernel's lane
// vector (the batch derivatives) or a Dual itself (second derivatives: the tangents of the
// tangents).
//
// What the value decides (comparisons, masks, the lanes of LaneArray) reads the value only;
// LaneArray(x).value() is a constant (no tangents). PointMapCore.h takes such constants only for
// scale factors the result does not depend on (the unit scale m of B = m u, powers of two of the
// balancing dilation), so the derivative stays exact.
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "ForceInline.h"
#include "LaneMath.h"

#include <type_traits>
#include <utility>


namespace cga
{
namespace core
{
namespace
{
template <typename T, int N>
struct Dual
{
  static constexpr int kLanes = kLanesOf<T>;
  using Mask = core::Mask<T>;
  static constexpr int kTangents = N;

  T v;    // the value
  T d[N]; // d v / d seed_k
};

/// Dual<Dual<T, 2>, 2> (second order in two seeds) holds each first derivative twice (x.v.d[k] and
/// x.d[k].v) and the mixed one twice (x.d[0].d[1] and x.d[1].d[0]). Every operation below ends by
/// copying the first of each pair over the second, so the compiler drops the second's arithmetic
/// (17 multiplications per product instead of 25). The parts kept are computed as before, to the
/// bit: the two copies of a first derivative were the same expression of equal inputs, and
/// d[0].d[1] never reads d[1].d[0].
template <typename D>
BOOSTED_FORCE_INLINE void mirrorTangents(D&)
{
}
template <typename T>
BOOSTED_FORCE_INLINE void mirrorTangents(Dual<Dual<T, 2>, 2>& x)
{
  x.d[0].v = x.v.d[0];
  x.d[1].v = x.v.d[1];
  x.d[1].d[0] = x.d[0].d[1];
}

// The lanes of a Dual are its value's (a constant comes back: no tangents).
template <typename T, int N>
BOOSTED_FORCE_INLINE void toLanes(const Dual<T, N>& x, double* lanes)
{
  toLanes(x.v, lanes);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE void fromLanes(const double* lanes, Dual<T, N>& x)
{
  fromLanes(lanes, x.v);
  for (int k = 0; k < N; ++k)
  {
    x.d[k] = T{};
  }
}

template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator+(Dual<T, N> a, const Dual<T, N>& b)
{
  a.v = a.v + b.v;
  for (int k = 0; k < N; ++k)
  {
    a.d[k] = a.d[k] + b.d[k];
  }
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator-(Dual<T, N> a, const Dual<T, N>& b)
{
  a.v = a.v - b.v;
  for (int k = 0; k < N; ++k)
  {
    a.d[k] = a.d[k] - b.d[k];
  }
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator-(Dual<T, N> a)
{
  a.v = -a.v;
  for (int k = 0; k < N; ++k)
  {
    a.d[k] = -a.d[k];
  }
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b)
{
  Dual<T, N> r;
  r.v = a.v * b.v;
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  }
  mirrorTangents(r);
  return r;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b)
{
  Dual<T, N> r;
  r.v = a.v / b.v;
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
  }
  mirrorTangents(r);
  return r;
}

// With a double on either side.
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator+(Dual<T, N> a, double b)
{
  a.v = a.v + b;
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator+(double a, Dual<T, N> b)
{
  b.v = a + b.v;
  mirrorTangents(b);
  return b;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator-(Dual<T, N> a, double b)
{
  a.v = a.v - b;
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator-(double a, const Dual<T, N>& b)
{
  Dual<T, N> r = -b;
  r.v = a - b.v;
  mirrorTangents(r);
  return r;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator*(Dual<T, N> a, double b)
{
  a.v = a.v * b;
  for (int k = 0; k < N; ++k)
  {
    a.d[k] = a.d[k] * b;
  }
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator*(double a, Dual<T, N> b)
{
  b.v = a * b.v;
  for (int k = 0; k < N; ++k)
  {
    b.d[k] = a * b.d[k];
  }
  mirrorTangents(b);
  return b;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator/(Dual<T, N> a, double b)
{
  a.v = a.v / b;
  for (int k = 0; k < N; ++k)
  {
    a.d[k] = a.d[k] / b;
  }
  mirrorTangents(a);
  return a;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> operator/(double a, const Dual<T, N>& b)
{
  Dual<T, N> r;
  r.v = a / b.v;
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = -(r.v * b.d[k]) / b.v;
  }
  mirrorTangents(r);
  return r;
}

/// a b + c with the value rounded once (LaneMath.h's fusedMultiplyAdd) and the tangents
/// a' b + a b' + c' as fused multiply-adds too; the second factor a constant or a Dual.
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> fusedMultiplyAdd(const Dual<T, N>& a, double b, Dual<T, N> c)
{
  c.v = fusedMultiplyAdd(a.v, b, c.v);
  for (int k = 0; k < N; ++k)
  {
    c.d[k] = fusedMultiplyAdd(a.d[k], b, c.d[k]);
  }
  mirrorTangents(c);
  return c;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> fusedMultiplyAdd(const Dual<T, N>& a, const Dual<T, N>& b, Dual<T, N> c)
{
  c.v = fusedMultiplyAdd(a.v, b.v, c.v);
  for (int k = 0; k < N; ++k)
  {
    c.d[k] = fusedMultiplyAdd(a.d[k], b.v, fusedMultiplyAdd(a.v, b.d[k], c.d[k]));
  }
  mirrorTangents(c);
  return c;
}

// Comparisons and masks: the value's.
template <typename T, int N>
BOOSTED_FORCE_INLINE Mask<T> lessThan(const Dual<T, N>& a, const Dual<T, N>& b)
{
  return lessThan(a.v, b.v);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Mask<T> lessEqual(const Dual<T, N>& a, const Dual<T, N>& b)
{
  return lessEqual(a.v, b.v);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Mask<T> equalTo(const Dual<T, N>& a, const Dual<T, N>& b)
{
  return equalTo(a.v, b.v);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> select(const Mask<T>& mask, const Dual<T, N>& a, const Dual<T, N>& b)
{
  Dual<T, N> r;
  r.v = select(mask, a.v, b.v);
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = select(mask, a.d[k], b.d[k]);
  }
  mirrorTangents(r);
  return r;
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> magnitude(const Dual<T, N>& x)
{
  return select(lessThan(x.v, T{}), -x, x);
}

/// f(x) with f(x.v) = value and f'(x.v) = slope.
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> chain(const Dual<T, N>& x, const T& value, const T& slope)
{
  Dual<T, N> r;
  r.v = value;
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = slope * x.d[k];
  }
  mirrorTangents(r);
  return r;
}

/// sqrt, with the derivative 0 where the value is 0 (an infinite slope there): PointMapCore.h
/// takes square roots of the plane squares, which are exactly 0 only where they are 0 in a whole
/// neighbourhood (a 2-blade's second plane, a nilpotent B's invariants), so their tangents are 0.
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> laneSqrt(const Dual<T, N>& x)
{
  const T r = laneSqrt(x.v);
  const Mask<T> zero = equalTo(r, T{});
  const T half = 0.5 / select(zero, splat<T>(1.0), r);
  return chain(x, r, select(zero, T{}, half));
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> laneExp(const Dual<T, N>& x)
{
  const T e = laneExp(x.v);
  return chain(x, e, e);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> laneCosh(const Dual<T, N>& x)
{
  return chain(x, laneCosh(x.v), laneSinh(x.v));
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> laneSinh(const Dual<T, N>& x)
{
  return chain(x, laneSinh(x.v), laneCosh(x.v));
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> laneTanh(const Dual<T, N>& x)
{
  const T t = laneTanh(x.v);
  return chain(x, t, 1.0 - t * t);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE void laneSinCos(const Dual<T, N>& x, Dual<T, N>& sine, Dual<T, N>& cosine)
{
  T s, c;
  laneSinCos(x.v, s, c);
  sine = chain(x, s, c);
  cosine = chain(x, c, -s);
}

/// The value without its tangents (LaneMath.h's valueOf; of a nested Dual, the innermost value).
template <typename T, int N>
inline auto valueOf(const Dual<T, N>& x)
{
  return valueOf(x.v);
}

/// A Dual rounds as its value's type (double-double's own unit for Dual<DoubleDouble, N>).
template <typename T, int N>
struct RoundingUnit<Dual<T, N>>
{
  static constexpr double value = RoundingUnit<T>::value;
};

/// Whether a number type carries tangents.
template <typename T>
constexpr bool kHasTangents = false;
template <typename T, int N>
constexpr bool kHasTangents<Dual<T, N>> = true;

/// q with its value set to 0 where the mask is set: for a value that is rounding noise (its true
/// value 0) whose tangents are not (an invariant of B that vanishes at this B but not nearby).
template <typename T>
BOOSTED_FORCE_INLINE T zeroValue(const Mask<T>& mask, const T& q)
{
  return select(mask, T{}, q);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> zeroValue(const Mask<T>& mask, Dual<T, N> q)
{
  q.v = zeroValue(mask, q.v);
  return q;
}

/// The value of `value` where the mask is set (of `tangents` elsewhere), the tangents of
/// `tangents`: for two formulas of one function where only the second differentiates everywhere.
template <typename T>
BOOSTED_FORCE_INLINE T withValueOf(const Mask<T>& mask, const T& value, const T& tangents)
{
  return select(mask, value, tangents);
}
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> withValueOf(const Mask<T>& mask, const Dual<T, N>& value, Dual<T, N> tangents)
{
  tangents.v = withValueOf(mask, value.v, tangents.v);
  return tangents;
}

/// A constant (no tangents).
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> constant(const T& value)
{
  Dual<T, N> r;
  r.v = value;
  for (int k = 0; k < N; ++k)
  {
    r.d[k] = T{};
  }
  return r;
}

/// The variable of seed k: value, tangent 1 for seed k, 0 for the others.
template <typename T, int N>
BOOSTED_FORCE_INLINE Dual<T, N> variable(const T& value, int k)
{
  Dual<T, N> r = constant<T, N>(value);
  r.d[k] = splat<T>(1.0);
  return r;
}

/// The value type of T: T itself, or a Dual's value without its tangents (DualNumber.h), on which
/// the per-lane decisions (scales, branches, flags) are made.
template <typename T>
using ValueOf = decltype(valueOf(std::declval<const T&>()));

/// A value as a T (for a Dual: a constant).
template <typename T, typename V>
BOOSTED_FORCE_INLINE T asNumber(const V& v)
{
  if constexpr (std::is_same<T, V>::value)
  {
    return v;
  }
  else
  {
    const LaneArray<V> lanes(v);
    T x;
    fromLanes(lanes.v, x);
    return x;
  }
}
} // namespace
} // namespace core
} // namespace cga
