// Internal: the numerical core of the point map, written once as templates over the number type T.
//
// T is double (PointPairField::map, expPaper, expExact, sandwichGrade1) or the block kernel's
// vector of lanes (PointPairKernelLanes.h, one point per lane): the pointwise map and the batch
// kernel are two instantiations of these functions, so they agree bit for bit by construction
// (the whole library is compiled with -ffp-contract=off: no multiply-add the compiler fuses may
// round one instantiation differently from the other; the explicit fusedMultiplyAdd of LaneMath.h
// is correctly rounded, the same in both).
//
// T needs +, -, * and / (also with a double on either side), unary -, T{} == 0, and what
// LaneMath.h lists (lanes, masks, selection, the elementary functions), found by
// argument-dependent lookup for the lane vector. Arithmetic over components is written on T; what
// differs per lane (the choice of formula, of frame, of branch) is a per-lane selection, and a
// branch runs only when some lane of the block takes it.
//
// Everything here has internal linkage (an unnamed namespace) and calls only builtins, libm and
// SLEEF's functions for the translation unit's instruction set:
// the kernel instantiates these templates in translation units compiled for AVX2 and AVX-512, and
// a template instance or inline function with vague linkage emitted there could be the copy the
// linker keeps for the baseline code too, which would then fault on an older CPU.
#pragma once

#include "AccurateImage.h"
#include "ForceInline.h"
#include "DualNumber.h"
#include "ExponentialScalars.h"
#include "FixedPointImage.h"
#include "LaneMath.h"
#include "BoostProducts.h"
#include "PointPairKernel.h"
#include "SandwichScaling.h"

#include "cga/Compact.h" // for the component enumerators only: nothing of it is called here

#include <type_traits>
#include <utility>


namespace cga
{
namespace core
{
namespace
{
constexpr int E12 = Bivector::E12, E13 = Bivector::E13, E23 = Bivector::E23;
constexpr int E1NO = Bivector::E1NO, E2NO = Bivector::E2NO, E3NO = Bivector::E3NO;
constexpr int E1NI = Bivector::E1NI, E2NI = Bivector::E2NI, E3NI = Bivector::E3NI;
constexpr int NONI = Bivector::NONI, kBivector = Bivector::Count;
constexpr int NO = ConformalVector::NO, E1 = ConformalVector::E1, E2 = ConformalVector::E2;
constexpr int E3 = ConformalVector::E3, NI = ConformalVector::NI;
constexpr int kVector = ConformalVector::Count;
constexpr int kQuadvector = Quadvector::Count;
constexpr int kEven = Even::kCount; // scalar, bivector, quadvector (detail::pack order)
constexpr int kOdd = 16;

/// <B B>_0: e_ij^2 = -1; (e_i no)(e_i ni) and (e_i ni)(e_i no) have scalar part 1; (no^ni)^2 = 1.
template <typename T>
BOOSTED_FORCE_INLINE T scalarSquare(const T* b)
{
  return -(b[E12] * b[E12] + b[E13] * b[E13] + b[E23] * b[E23]) +
    2.0 * (b[E1NO] * b[E1NI] + b[E2NO] * b[E2NI] + b[E3NO] * b[E3NI]) + b[NONI] * b[NONI];
}

/// Per lane, whether x is finite (|x| < inf: NaN is not).
template <typename V>
BOOSTED_FORCE_INLINE Mask<V> finiteLanes(const V& x)
{
  return lessThan(magnitude(x), splat<V>(__builtin_inf()));
}

/// The per-lane flags of a mask as bools.
template <typename V>
BOOSTED_FORCE_INLINE void toFlags(const Mask<V>& mask, bool* flags)
{
  const LaneArray<V> lanes(select(mask, splat<V>(1.0), V{}));
  for (int l = 0; l < kLanesOf<V>; ++l)
  {
    flags[l] = lanes.v[l] != 0.0;
  }
}

/// Largest absolute component, NaN when one is NaN (Coefficients::maxAbs), in vector compares and
/// blends: the maximum and a NaN flag apart (a NaN component never wins a comparison). The
/// maximum pairwise, four compares deep instead of a chain of ten (every block waits for it: the
/// chain was about a tenth of an Exact update at M = 1); the maximum of magnitudes is the same
/// number in any order.
template <typename T>
BOOSTED_FORCE_INLINE ValueOf<T> maxAbs(const T* b)
{
  using V = ValueOf<T>;
  V a[kBivector];
  Mask<V> nan = lessThan(V{}, V{}); // no lane
  for (int c = 0; c < kBivector; ++c)
  {
    a[c] = magnitude(valueOf(b[c]));
    nan = maskOr(nan, maskNot(equalTo(a[c], a[c])));
  }
  for (int n = kBivector; n > 1; n = (n + 1) / 2)
  {
    for (int c = 0; c + 1 < n; c += 2)
    {
      a[c / 2] = select(lessThan(a[c], a[c + 1]), a[c + 1], a[c]);
    }
    if (n % 2 != 0)
    {
      a[n / 2] = a[n - 1];
    }
  }
  return select(nan, splat<V>(__builtin_nan("")), a[0]);
}

/// b = scale B(p), B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps) (PointPairField::generatorAt
/// without the factor). The squared distance, the denominator and the sums are explicit fused
/// multiply-adds (rounded once, so still the same bits on every instruction set): on the FMA pipes
/// they leave the add pipes, which bound the loop otherwise, only the three subtractions.
template <typename T>
BOOSTED_FORCE_INLINE void fieldBivector(const kernel::FieldArgs& args, const T* p, double scale, T* b)
{
  T sum[kBivector];
  for (int c = 0; c < kBivector; ++c)
  {
    sum[c] = T{};
  }
  const double falloff = args.falloff;
  const T epsilon = splat<T>(args.epsilon);
  for (std::size_t i = 0; i < args.generatorCount; ++i)
  {
    const double* g = args.generators + i * kernel::kGeneratorStride;
    const T dx = p[0] - g[0];
    const T dy = p[1] - g[1];
    const T dz = p[2] - g[2];
    const T distance2 = fusedMultiplyAdd(dz, dz, fusedMultiplyAdd(dy, dy, dx * dx));
    const T factor = 1.0 / fusedMultiplyAdd(distance2, falloff, epsilon);
    for (int c = 0; c < kBivector; ++c)
    {
      sum[c] = fusedMultiplyAdd(factor, g[3 + c], sum[c]);
    }
  }
  for (int c = 0; c < kBivector; ++c)
  {
    b[c] = sum[c] * scale;
  }
}

/// The scale m of B: the power of two 2^e with 2^e <= |B|_max < 2^(e+1), and per lane whether
/// |B|_max is finite, zero, or both finite and non-zero (usable: m is a scale).
template <typename T>
struct Scale
{
  ValueOf<T> m;
  Mask<T> finite, zero, usable;

  /// m where it is usable, 1 elsewhere.
  ValueOf<T> usableOrOne() const { return select(usable, m, splat<ValueOf<T>>(1.0)); }
};

/// NaN where B is not finite, value elsewhere: a selection on T itself, so that a Dual
/// (DualNumber.h) keeps the tangents of the value it selects. Where B = 0 the computed value is
/// the identity's, with B's tangents: the closed forms and series run there with m = 1 (u = B).
template <typename T>
BOOSTED_FORCE_INLINE T nanWhereNotFinite(const Scale<T>& scale, const T& value)
{
  return select(scale.finite, value, splat<T>(__builtin_nan("")));
}

/// The scale m of B, and u = B / m where m is non-zero and finite (B where it is not): m a power
/// of two, so that u is B exactly (1/m is exact: one division, not one per component), its
/// components below 2 in size.
template <typename T>
BOOSTED_FORCE_INLINE void unitScaled(const T* b, Scale<T>& scale, T* u)
{
  using V = ValueOf<T>;
  const V largest = maxAbs(b);
  scale.finite = finiteLanes(largest);
  scale.zero = equalTo(largest, V{});
  scale.usable = maskAnd(scale.finite, maskNot(scale.zero));
  scale.m = binaryFloor(largest);
  const T inverse = asNumber<T>(1.0 / scale.usableOrOne());
  for (int c = 0; c < kBivector; ++c)
  {
    u[c] = b[c] * inverse;
  }
}

/// Scale m of B above which the sandwich of K = exp(B) may overflow: where B is (nearly) nilpotent
/// (a point pair of weight beyond about 1e154) K = 1 + B has components of size m, and <K X ~K>_1
/// terms of size m^2.
constexpr double kHugeExponent = 256.0;
constexpr double kHugeExponentScale = 0x1p256;

/// The power of two 2^-h, per lane of `huge` (1 elsewhere), that brings a K whose largest
/// component is `largest` near 2^kHugeExponent: h = e - 256 (e the binary exponent of `largest`),
/// so that the sandwich's terms |K|^2 |X| stay in range for any moderate X, at most
/// kLargestSandwichDownscale (537): from e = 793 the largest is 2^(e - 537) <= 2^487.
/// (A NaN lane gets 1; an infinite one may be scaled: its image is not finite either way.)
template <typename V>
BOOSTED_FORCE_INLINE V hugeSandwichFactor(const Mask<V>& huge, const V& largest)
{
  V h = binaryExponentOf(largest) - splat<V>(kHugeExponent);
  const V largestH = splat<V>(static_cast<double>(kLargestSandwichDownscale));
  h = select(lessThan(largestH, h), largestH, h);
  h = select(maskAnd(huge, lessThan(V{}, h)), h, V{});
  return powerOfTwoOf(-h);
}

/// K = c + B' for the unit-scaled u = B/m (scale from unitScaled) with <u u>_0 = s: exp(B) where B
/// is a 2-blade (B^2 = m^2 s), the Paper rule otherwise; on return u holds B' = sHat u. NaN where
/// B is not finite, c = 1 and B' = 0 where B = 0. With keepInRange (for a sandwich, not for K
/// itself) K is divided by hugeSandwichFactor where m is above kHugeExponentScale: its image is
/// the same, and a (nearly) nilpotent B's K = 1 + B, of size m, does not overflow the sandwich's
/// terms (docs/conventions.md section 2 item 7); two products, on such lanes only.
template <typename T>
BOOSTED_FORCE_INLINE void bladeExponential(
  const Scale<T>& scale, const T& s, bool divideByCosh, T* u, T& c, bool keepInRange = false)
{
  using V = ValueOf<T>;
  const detail::PlaneFunctions<T> f =
    detail::planeFunctions(asNumber<T>(scale.usableOrOne()), s, divideByCosh);
  c = nanWhereNotFinite(scale, f.c);
  T factor = nanWhereNotFinite(scale, f.sHat);
  if (keepInRange)
  {
    const Mask<V> huge = maskAnd(scale.usable, lessThan(splat<V>(kHugeExponentScale), scale.m));
    if (anyLane(huge))
    {
      // K's largest component within a factor 2 of max(|c|, |sHat|) (u's largest is in [1, 2))
      const V a = magnitude(valueOf(c)), b = magnitude(valueOf(factor));
      const T down = asNumber<T>(hugeSandwichFactor(huge, select(lessThan(a, b), b, a)));
      c = down * c;
      factor = down * factor;
    }
  }
  for (int i = 0; i < kBivector; ++i)
  {
    u[i] = factor * u[i];
  }
}

/// The Paper rule (expPaper): K = c + B' with on return b holding B' = sHat B/m; NaN where B is not
/// finite, c = 1 and B' = 0 where B = 0; keepInRange: bladeExponential's, for a sandwich.
template <typename T>
void paperExponential(T* b, T& c, bool divideByCosh, bool keepInRange = false)
{
  Scale<T> scale;
  unitScaled(b, scale, b);
  bladeExponential(scale, scalarSquare(b), divideByCosh, b, c, keepInRange);
}

/// Relative size, against the sum of the magnitudes of its terms, below which an invariant of the
/// unit-scaled u = B/m is rounding: B's components carry a few units in the last place of their
/// sums, the quadratic forms add their own (docs/conventions.md section 2 item 12).
/// (in units of the number type's RoundingUnit: 2^-52 for double).
constexpr double kInvariantNoise = 32.0;

/// q where |q| exceeds kInvariantNoise RoundingUnit<T> times `terms` (the sum of its terms' magnitudes), else 0
/// (its value: a Dual keeps its tangents, which need not vanish where the invariant does).
template <typename T>
BOOSTED_FORCE_INLINE T dropRounding(const T& q, const T& terms)
{
  return zeroValue(lessEqual(magnitude(q), (kInvariantNoise * RoundingUnit<T>::value) * terms), q);
}

/// The invariants of u = B/m: W = u ^ u, w2 = W W, s = <u u>_0, each 0 where it is below the
/// rounding of its terms. For a nilpotent B (a lone point pair) they are all rounding: dropping
/// them keeps exp(B) = 1 + B, instead of a closed form in the square roots of noise times m^2.
template <typename T>
BOOSTED_FORCE_INLINE void unitInvariants(const T* u, T* w, T& w2, T& s, bool dropNoise)
{
  if (!dropNoise)
  {
    detail::applyProduct<detail::kWedge>(u, u, w);
    detail::applyProduct<detail::kQuadvectorSquare>(w, w, &w2);
    s = scalarSquare(u);
    return;
  }
  T absU[kBivector], wTerms[kQuadvector], absW[kQuadvector], w2Terms;
  for (int c = 0; c < kBivector; ++c)
  {
    absU[c] = magnitude(u[c]);
  }
  detail::applyProduct<detail::kWedge>(u, u, w);
  detail::applyProductMagnitudes<detail::kWedge>(absU, absU, wTerms);
  for (int c = 0; c < kQuadvector; ++c)
  {
    w[c] = dropRounding(w[c], wTerms[c]);
    absW[c] = magnitude(w[c]);
  }
  detail::applyProduct<detail::kQuadvectorSquare>(w, w, &w2);
  detail::applyProductMagnitudes<detail::kQuadvectorSquare>(absW, absW, &w2Terms);
  w2 = dropRounding(w2, w2Terms);
  const T sTerms = absU[E12] * absU[E12] + absU[E13] * absU[E13] + absU[E23] * absU[E23] +
    2.0 * (absU[E1NO] * absU[E1NI] + absU[E2NO] * absU[E2NI] + absU[E3NO] * absU[E3NI]) +
    absU[NONI] * absU[NONI];
  s = dropRounding(scalarSquare(u), sTerms);
}

/// B scaled to u = B/m and the invariants of u (unitInvariants).
template <typename T>
struct UnitBivector
{
  Scale<T> scale;
  T u[kBivector], w[kQuadvector], w2, s;
};

/// dropNoise: unitInvariants drops the invariants that are rounding (needed where B may be
/// nilpotent; the map's field frame, taken only where B is far from nilpotent, skips it).
template <typename T>
BOOSTED_FORCE_INLINE void unitBivector(const T* b, UnitBivector<T>& v, bool dropNoise = true)
{
  unitScaled(b, v.scale, v.u);
  unitInvariants(v.u, v.w, v.w2, v.s, dropNoise);
}

/// exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 from the power series in B^2 = s + W
/// (detail::seriesCoefficients), into k (detail::pack order), from the invariants of u = B/m
/// (B^2 = m^2 (s_u + W_u)) and wu = <W_u u>_2. Only where m^2 |l| <= 1, so that the products by
/// powers of m stay bounded.
template <typename T>
void seriesExponential(const T* b, const T& m, const T& su, const T* wUnit, const T& w2Unit,
                       const T* wu, T* k)
{
  // Products by powers of m one factor at a time: m^2 alone may overflow where the products
  // do not (a zero invariant times a huge m).
  const T s = (su * m) * m, w2 = (((w2Unit * m) * m) * m) * m;
  // A nilpotent B (a lone point pair: s = W W = 0 on every lane) has the constant coefficients
  // the loop would sum: 1, 1/2, 1, 1/6.
  // (Not for a Dual: its tangents of s and W W need not vanish.)
  const detail::SeriesCoefficients<T> c =
    !kHasTangents<T> && allLanes(maskAnd(equalTo(s, T{}), equalTo(w2, T{})))
    ? detail::SeriesCoefficients<T>{ splat<T>(1.0), splat<T>(0.5), splat<T>(1.0), splat<T>(0.5 / 3.0) }
    : detail::seriesCoefficients(s, w2);
  k[0] = c.a0;
  for (int i = 0; i < kBivector; ++i)
  {
    k[1 + i] = c.b0 * b[i] + c.b4 * (((wu[i] * m) * m) * m);
  }
  for (int i = 0; i < kQuadvector; ++i)
  {
    k[1 + kBivector + i] = c.a4 * ((wUnit[i] * m) * m);
  }
}

/// The Exact rule (expExact) into k (detail::pack order): the power series where both squares of B
/// are at most 1 in size, else the closed form in u = B/m; NaN where B is not finite.
/// (With the plane squares l1, l2 of u and wu = <W u>_2 given.)
template <typename T>
void exactExponential(const T* b, const UnitBivector<T>& unit, const T& l1Value, const T& l2Value,
                      const T* wu, bool divideByCosh, T* k)
{
  using V = ValueOf<T>;
  const Scale<T>& scale = unit.scale;
  const T* u = unit.u;
  const T* w = unit.w;
  const T& w2 = unit.w2;
  const T& su = unit.s;
  const V m = scale.usableOrOne();
  // B = 0 takes the series with m = 1: exp(0) = 1, and a Dual gets the tangents of exp at 0.
  const Mask<V> useSeries = maskOr(
    maskAnd(scale.usable, detail::exactUsesSeries(m, valueOf(l1Value), valueOf(l2Value))),
    maskAnd(scale.finite, scale.zero));
  const Mask<V> closed = maskAnd(scale.usable, maskNot(useSeries));
  const bool anySeries = anyLane(useSeries), anyClosed = anyLane(closed);
  const bool allSeries = allLanes(useSeries), allClosed = allLanes(closed);
  const T mValue = asNumber<T>(m);
  T fromSeries[kEven] = {};
  if (anySeries)
  {
    seriesExponential(b, mValue, su, w, w2, wu, allSeries ? k : fromSeries);
    if (allSeries)
    {
      return;
    }
  }
  T fromClosed[kEven] = {};
  if (anyClosed)
  {
    const detail::ExactCoefficients<T> c =
      detail::exactCoefficients(mValue, l1Value, l2Value, divideByCosh);
    fromClosed[0] = c.scalar;
    for (int i = 0; i < kBivector; ++i)
    {
      fromClosed[1 + i] = c.bivector * u[i] + c.bivectorW * wu[i];
    }
    for (int i = 0; i < kQuadvector; ++i)
    {
      fromClosed[1 + kBivector + i] = c.quadvector * w[i];
    }
  }
  if (allClosed)
  {
    for (int i = 0; i < kEven; ++i)
    {
      k[i] = fromClosed[i];
    }
    return;
  }
  // Each lane takes one of the two, or NaN (selections on T: see nanWhereNotFinite).
  for (int i = 0; i < kEven; ++i)
  {
    k[i] = nanWhereNotFinite(scale, select(useSeries, fromSeries[i], fromClosed[i]));
  }
}

template <typename T>
void exactExponential(const T* b, const UnitBivector<T>& unit, bool divideByCosh, T* k)
{
  T wu[kBivector], l1, l2;
  detail::applyProduct<detail::kRightContraction>(unit.w, unit.u, wu);
  detail::planeSquares(unit.s, unit.w2, l1, l2);
  exactExponential(b, unit, l1, l2, wu, divideByCosh, k);
}

template <typename T>
void exactExponential(const T* b, bool divideByCosh, T* k, bool dropNoise = true)
{
  UnitBivector<T> unit;
  unitBivector(b, unit, dropNoise);
  exactExponential(b, unit, divideByCosh, k);
}

/// up(p) = no + p + |p|^2/2 ni (ConformalVector::point).
template <typename T>
BOOSTED_FORCE_INLINE void upPoint(const T* p, T* x)
{
  x[NO] = T{} + 1.0;
  x[E1] = p[0];
  x[E2] = p[1];
  x[E3] = p[2];
  x[NI] = 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}

/// y = v _| B for a conformal vector v and a bivector B: with v = a no + u + b ni and
/// B = E + A_i e_i^no + C_i e_i^ni + d no^ni (no.ni = -1),
/// y = (u.A + d a) no + (u _| E + b A + a C) + (u.C - d b) ni.
template <typename T>
BOOSTED_FORCE_INLINE void contract(const T* v, const T* b, T* y)
{
  const T a = v[NO], u1 = v[E1], u2 = v[E2], u3 = v[E3], bb = v[NI];
  const T d = b[NONI];
  y[NO] = u1 * b[E1NO] + u2 * b[E2NO] + u3 * b[E3NO] + d * a;
  y[E1] = -b[E12] * u2 - b[E13] * u3 + bb * b[E1NO] + a * b[E1NI];
  y[E2] = b[E12] * u1 - b[E23] * u3 + bb * b[E2NO] + a * b[E2NI];
  y[E3] = b[E13] * u1 + b[E23] * u2 + bb * b[E3NO] + a * b[E3NI];
  y[NI] = u1 * b[E1NI] + u2 * b[E2NI] + u3 * b[E3NI] - d * bb;
}

/// <K X ~K>_1 for K = c + B (no 4-vector part, the Paper rule), ~K = c - B. With y = X _| B,
/// <B X B>_1 = <B B>_0 X - 2 y _| B and B X - X B = -2 y, so
/// <K X ~K>_1 = (c^2 - <B B>_0) X - 2 c y + 2 y _| B.
template <typename T>
BOOSTED_FORCE_INLINE void sandwichScalarBivector(const T& c, const T* b, const T* x, T* r)
{
  T y[kVector], z[kVector];
  contract(x, b, y);
  contract(y, b, z);
  const T a = c * c - scalarSquare(b);
  const T twoC = 2.0 * c;
  for (int i = 0; i < kVector; ++i)
  {
    r[i] = a * x[i] - twoC * y[i] + 2.0 * z[i];
  }
}

/// Divides the `count` components of a full even K by hugeSandwichFactor on the lanes whose scale
/// m of B is above kHugeExponentScale: fn(<K X ~K>_1) is unchanged (a power of two scales both its
/// parts exactly, but for terms that underflow beside ones 2^500 times larger), but its terms of
/// size |K|^2 stay in range, so that a huge point pair moves a point next to its location (the
/// limit) instead of overflowing (docs/conventions.md section 2 item 7). Elsewhere K is untouched
/// (one comparison per block). (K = c + B' is scaled by bladeExponential itself.)
template <typename T>
BOOSTED_FORCE_INLINE void keepSandwichInRange(const ValueOf<T>& m, T* k, int count)
{
  using V = ValueOf<T>;
  const Mask<V> huge = lessThan(splat<V>(kHugeExponentScale), m);
  if (!anyLane(huge))
  {
    return;
  }
  V largest = V{};
  for (int i = 0; i < count; ++i)
  {
    const V a = magnitude(valueOf(k[i]));
    largest = select(lessThan(largest, a), a, largest);
  }
  const T factor = asNumber<T>(hugeSandwichFactor(huge, largest));
  for (int i = 0; i < count; ++i)
  {
    k[i] = factor * k[i];
  }
}

/// ~K for a full even K (detail::pack order): its bivector part negated.
template <typename T>
BOOSTED_FORCE_INLINE void reverseEven(const T* k, T* reversed)
{
  for (int s = 0; s < kEven; ++s)
  {
    reversed[s] = (s >= 1 && s <= kBivector) ? -1.0 * k[s] : k[s];
  }
}

/// <K X ~K>_1 for a full even K (detail::pack order) as two sparse products: the odd element
/// K X, then only the grade-1 part of (K X) ~K. Always inlined: for callers compiled for several
/// instruction sets (BOOSTED_LANE_CLONES), where an out-of-line copy would run the baseline's.
template <typename T>
BOOSTED_FORCE_INLINE void sandwichEvenInlined(const T* k, const T* x, T* r)
{
  T reversed[kEven], odd[kOdd];
  reverseEven(k, reversed);
  detail::applyProduct<detail::kEvenTimesVector>(k, x, odd);
  detail::applyProduct<detail::kOddTimesEvenToVector>(odd, reversed, r);
}

/// sandwichEvenInlined, where the compiler chooses whether to inline.
template <typename T>
void sandwichEven(const T* k, const T* x, T* r)
{
  sandwichEvenInlined(k, x, r);
}

/// <K e_J ~K>_1 for a full even K and its reverse: sandwichEven of basis vector J
/// (ConformalVector order) with only the terms of K X that e_J contributes
/// (detail::kEvenTimesBasis). Where K is finite these are sandwichEven's bits: each sum of K X
/// starts at +0, which the left-out terms (zeros) leave as it is; where K holds an infinity or
/// NaN, sandwichEven's terms 0 * inf give NaN that these do not.
template <int J, typename T>
BOOSTED_FORCE_INLINE void sandwichBasisInlined(const T* k, const T* reversed, T* r)
{
  T odd[kOdd];
  const T one[1] = { splat<T>(1.0) };
  detail::applyProduct<detail::kEvenTimesBasis<J>>(k, one, odd);
  detail::applyProduct<detail::kOddTimesEvenToVector>(odd, reversed, r);
}

/// <K no ~K>_1 for a full even K (sandwichBasisInlined of the origin).
template <typename T>
void sandwichOrigin(const T* k, T* r)
{
  T reversed[kEven];
  reverseEven(k, reversed);
  sandwichBasisInlined<NO>(k, reversed, r);
}

/// m sqrt(l1) (a, the hyperbolic angle of B's hyperbolic plane) above which the field's frame maps
/// by sandwichWithStrongLanes: there the closed form's sandwich cancels terms of size e^{2a} (or
/// forms 1 - tanh^2 a) to the point's weight, losing about e^{2a} units of 2^-53 (e^2 = 7 at the
/// threshold: 1e-15).
constexpr double kStrongHyperbolic = 1.0;

/// a above which a strong lane whose split is not exact (a transversion part beside the planes)
/// maps through its fixed points (strongImageByFixedPoints): below, the closed form's loss, measured
/// 1 ... 40 e^{2a} units of 2^-53 of the scale, stays below 2.4e-13, a quarter of the tested bound,
/// and the fixed points' path (taken by a whole block with the closed form for its other lanes) is
/// not paid where it gains nothing measurable: the bench's field has 2.7 % of its points at a in
/// (1, 1.5] at M = 16 and none above; at M = 64 31 % above 1, 0.06 % above 2.
constexpr double kStrongGeneral = 2.0;

/// a above which the field's frame keeps the closed form scaled by 1/cosh (item 7): e^a overflows
/// from 709.78, and where the image is in range there it is the attracting fixed point, which the
/// scaled closed form gives (a dilation's image x + e^{2a}(p - x) leaves the doubles' range unless
/// |p - x| < 1e-300).
constexpr double kStrongHyperbolicLimit = 700.0;

/// 2a up to which the strong sandwich keeps the tangents of its exactly-zero parts along seeds that
/// move B's e_i^no parts (exactZeroStaysZero): their rounding, times e^{2a} <= 2^10, stays within
/// 2^-43 of the derivative, as the closed form's (which such lanes took before they were strong).
constexpr double kKeptLeavingTangents = 10.0 * 0.6931471805599453;

/// Per lane, whether the e_i^no components that component(c) reads (c = E1NO, E2NO, E3NO) are all 0:
/// for B's values, B is a similarity's bivector (similarityLanes); for its tangents along a seed,
/// B stays one along that seed (exactZeroStaysZero).
template <typename Component>
BOOSTED_FORCE_INLINE auto noTransversionPart(const Component& component)
{
  using N = decltype(component(E1NO));
  return maskAnd(maskAnd(equalTo(component(E1NO), N{}), equalTo(component(E2NO), N{})),
    equalTo(component(E3NO), N{}));
}

/// q (a Dual: DualNumber.h) with its tangents dropped where its value is exactly 0, along the seeds
/// that keep u a similarity's bivector (no e_i^no tangent), and along every seed where `dropAll`.
/// Used for the parts of the strong sandwich that a factor e^{2a} multiplies: where B is a
/// similarity's bivector (similarityLanes: a dilation with translations, rotations, twists), its
/// growing null direction is ni exactly and those parts' no and Euclidean components are 0 at every
/// B of the similarities, their values to the bit, while their tangents would carry the rounding of
/// N1's normalization times e^{2a}. Along a seed that moves B's e_i^no parts (d p' / d B) B leaves
/// the similarities and those tangents are the derivative's own: kept where e^{2a} is small
/// (kKeptLeavingTangents), dropped beyond (dropAll). Either way they are not that derivative's
/// final value there: PointPairField's derivative by B takes the closed form of
/// StrongSimilarityDerivative.h on such lanes (docs/conventions.md section 3 item 15).
template <typename V, int N>
BOOSTED_FORCE_INLINE Dual<V, N> exactZeroStaysZero(Dual<V, N> q, const Dual<V, N>* u, const Mask<ValueOf<V>>& dropAll)
{
  if constexpr (kHasTangents<V>) // a jet: the value's own tangents alike
  {
    V values[kBivector];
    for (const int c : { E1NO, E2NO, E3NO })
    {
      values[c] = u[c].v;
    }
    q.v = exactZeroStaysZero(q.v, values, dropAll);
  }
  const Mask<ValueOf<V>> zero = equalTo(valueOf(q.v), ValueOf<V>{});
  for (int k = 0; k < N; ++k)
  {
    const auto staysSimilar = noTransversionPart([&](int c) { return u[c].d[k]; });
    q.d[k] = select(maskAnd(zero, maskOr(dropAll, staysSimilar)), V{}, q.d[k]);
  }
  return q;
}

/// The binary exponent of the largest of a vector's no and Euclidean components (those the image
/// reads), -1e4 where they are all 0 (so that such a part never sets the scale).
template <typename T>
BOOSTED_FORCE_INLINE ValueOf<T> imagePartExponent(const T* v)
{
  using V = ValueOf<T>;
  V largest = magnitude(valueOf(v[NO]));
  for (const int i : { E1, E2, E3 })
  {
    const V a = magnitude(valueOf(v[i]));
    largest = select(lessThan(largest, a), a, largest);
  }
  return select(equalTo(largest, V{}), splat<V>(-1e4), binaryExponentOf(largest));
}

/// Per lane, whether B = m u is a similarity's bivector: no e_i^no part (every generator a
/// dilation, rotation, twist or translation), so that ni is fixed. Its two planes are then
/// B1 = d (no^ni + x^ni) (the dilation about the fixed point x, d = u's no^ni component) and
/// B2 = E + C2^ni (the rotation about an axis through x, E = u's e_ij part): l1 = d^2 and
/// l2 = -|E|^2 exactly, and B2's E and no^ni components are u's E and 0 exactly.
template <typename T>
BOOSTED_FORCE_INLINE Mask<ValueOf<T>> similarityLanes(const T* u)
{
  return noTransversionPart([&](int c) { return valueOf(u[c]); });
}

/// Per lane, whether strongHyperbolicSandwich's parts that its factor e^{2a} multiplies come out
/// exact where they vanish (docs/conventions.md section 2 item 12): B a similarity's bivector
/// (similarityLanes: its growing null direction is ni, its split exact in the components that
/// matter). Elsewhere neither fixed point is ni, the part X- that e^{2a} multiplies is of order
/// |p - r|^2 next to the repeller r with an error of 2^-53 |X| (a 2-blade's too: a boost between two
/// points lost e^{4a} 2^-53 of its image there), and strongImageByFixedPoints maps instead.
template <typename T>
BOOSTED_FORCE_INLINE Mask<ValueOf<T>> strongSandwichIsExact(const UnitBivector<T>& unit)
{
  return similarityLanes(unit.u);
}

/// The elliptic part B2 = (wu/2 - l2 u)/(l1 - l2) of u = B1 + B2 (from <W u>_2 = 2 (l1 B2 + l2 B1),
/// l1 > 0 the square of u's hyperbolic plane, l2 the other's, wu = <W u>_2) into b2, and returns
/// sqrt(l1). Lanes where l1 is not positive (not strong: the caller selects them away) take l1 = 1,
/// so that nothing divides by 0.
template <typename T>
BOOSTED_FORCE_INLINE T ellipticPart(const T* u, const T& l1, const T& l2, const T* wu, T* b2)
{
  using V = ValueOf<T>;
  const Mask<V> positive = lessThan(V{}, valueOf(l1));
  const T l1Safe = select(positive, l1, splat<T>(1.0));
  const T inverseGap = 1.0 / (l1Safe - l2);
  for (int c = 0; c < kBivector; ++c)
  {
    b2[c] = (0.5 * wu[c] - l2 * u[c]) * inverseGap;
  }
  return laneSqrt(l1Safe);
}

/// <K X ~K>_1 (up to a positive factor) for K = exp(B), B = m u with a strong hyperbolic plane
/// (l1 > 0 the square of u's hyperbolic plane, l2 <= 0 the other's, wu = <W u>_2), without the
/// cancellation of 1 - tanh^2 (docs/conventions.md section 2 item 7 and 12). B splits into the
/// commuting B1 + B2, B2 = (wu/2 - l2 u)/(l1 - l2) (from <W B>_2 = 2 (l1 B2 + l2 B1)), B1 = u - B2,
/// and exp(B) = exp(B1) exp(B2). The elliptic exp(B2) = cos + sin N2 turns X by the closed form of
/// sandwichScalarBivector (its terms are bounded: cos^2 + sin^2, no cancellation) to Y. The
/// hyperbolic exp(a N1), N1 = B1/sqrt(l1) (N1^2 = 1), a = m sqrt(l1), fixes the part of Y
/// orthogonal to its plane and scales the plane's two null directions: with z = Y _| N1 and
/// P = z _| N1 (Y's projection on the plane), Y- = (P - z)/2 and Y+ = (P + z)/2 go to e^{2a} Y- and
/// e^{-2a} Y+, so
///   K Y ~K = e^{2a} Y- + (Y - P) + e^{-2a} Y+,
/// each part multiplied by its exact factor. Since the image is homogeneous, the three are scaled by
/// a power of two 2^-k that brings the largest of their no and Euclidean parts near 1, and e^{2a} is
/// applied as e^a, 2^-k, e^a in turn, so that nothing overflows while the image is in range
/// (a up to kStrongHyperbolicLimit). The caller takes it where strongSandwichIsExact: B a
/// similarity's bivector (a 2-blade among them: B2 = 0, Y = X), whose split takes its exact values (similarityLanes:
/// l1 = d^2, l2 = -|E|^2, B2's E = u's and no^ni = 0), so that N1 = B1/|d| has no e_ij part and
/// the no^ni component +-1 to the bit, and the parts that e^{2a} multiplies keep their exact zeros.
template <typename T>
void strongHyperbolicSandwich(const UnitBivector<T>& unit, const T& l1Split, const T& l2Split, const T* wu,
                              const T* x, T* r)
{
  using V = ValueOf<T>;
  const T* u = unit.u;
  const T m = asNumber<T>(unit.scale.usableOrOne());
  // A similarity's planes take their exact values (a Dual keeps the general formula's tangents:
  // B may leave the similarities along a tangent, e.g. d p' / d B).
  const Mask<V> similarity = similarityLanes(u);
  const bool anySimilarity = anyLane(similarity);
  T l1 = l1Split, l2 = l2Split;
  if (anySimilarity)
  {
    l1 = withValueOf(similarity, u[NONI] * u[NONI], l1);
    l2 = withValueOf(similarity, -(u[E12] * u[E12] + u[E13] * u[E13] + u[E23] * u[E23]), l2);
  }
  T n1[kBivector], b2[kBivector];
  const T root1 = ellipticPart(u, l1, l2, wu, b2);
  if (anySimilarity)
  {
    for (const int c : { E12, E13, E23 })
    {
      b2[c] = withValueOf(similarity, u[c], b2[c]);
    }
    b2[NONI] = zeroValue(similarity, b2[NONI]);
  }
  for (int c = 0; c < kBivector; ++c)
  {
    // A division, not a product by 1/root1: for a dilation N's no^ni component is then u/|u| = +-1
    // to the bit (sqrt(fl(u^2)) = |u|), which keeps X-'s and X_perp's no parts exactly 0.
    n1[c] = (u[c] - b2[c]) / root1;
  }
  // The elliptic factor (l2 <= 0; a rounding l2 > 0 is a tiny boost, as accurate).
  const detail::PlaneFunctions<T> f2 = detail::planeFunctions(m, l2, false);
  for (int c = 0; c < kBivector; ++c)
  {
    b2[c] = f2.sHat * b2[c];
  }
  T y[kVector];
  sandwichScalarBivector(f2.c, b2, x, y);
  T z[kVector], projection[kVector], minus[kVector], orthogonal[kVector], plus[kVector];
  contract(y, n1, z);
  contract(z, n1, projection);
  for (int i = 0; i < kVector; ++i)
  {
    minus[i] = 0.5 * (projection[i] - z[i]);
    orthogonal[i] = y[i] - projection[i];
    plus[i] = 0.5 * (projection[i] + z[i]);
  }
  const T a = m * root1;
  if constexpr (kHasTangents<T>)
  {
    const Mask<V> dropAll = lessThan(splat<V>(kKeptLeavingTangents), 2.0 * valueOf(a));
    for (const int i : { NO, E1, E2, E3 })
    {
      minus[i] = exactZeroStaysZero(minus[i], u, dropAll);
    }
    orthogonal[NO] = exactZeroStaysZero(orthogonal[NO], u, dropAll);
  }
  const T grow = laneExp(a), shrink = 1.0 / grow;
  // k: the largest binary exponent of the three scaled parts (2a/ln2 the exponent of e^{2a}).
  const V twoA = 2.0 * valueOf(a) * 1.4426950408889634;
  const V kMinus = twoA + imagePartExponent(minus);
  const V kOrthogonal = imagePartExponent(orthogonal);
  const V kPlus = imagePartExponent(plus) - twoA;
  V k = select(lessThan(kMinus, kOrthogonal), kOrthogonal, kMinus);
  k = select(lessThan(k, kPlus), kPlus, k);
  const V rounding = splat<V>(0x1.8p52);
  k = (k + rounding) - rounding;
  k = select(lessThan(k, splat<V>(-1022.0)), splat<V>(-1022.0), k);
  k = select(lessThan(splat<V>(1022.0), k), splat<V>(1022.0), k);
  k = select(equalTo(k, k), k, V{}); // a NaN lane (its image is NaN anyway)
  const T scale = asNumber<T>(powerOfTwoOf(-k));
  // Each part times its factors one at a time: a factor alone (e^{2a} 2^-k) may overflow where the
  // part is 0 or tiny (p on a dilation's location: only X+ is non-zero), the products do not.
  for (int i = 0; i < kVector; ++i)
  {
    r[i] = ((minus[i] * grow) * scale) * grow + scale * orthogonal[i] + ((plus[i] * shrink) * scale) * shrink;
  }
}

/// Newton steps from the split's guess of a fixed point to the zero of B's field: each about squares
/// the guess's relative error, which the split's rounding makes a few units of 2^-53 times its
/// conditioning, so three leave only the field's own rounding; cheap, on the strong general lanes
/// only.
constexpr int kFixedPointNewtonSteps = 3;

/// The fixed point of exp(B) (B = E + A_i e_i^no + C_i e_i^ni + d no^ni, ten components u) on the
/// null direction f of its hyperbolic plane: f's Euclidean point, refined by Newton steps on the
/// zeros of B's Euclidean field (fixedPointNewtonStep), so that its error is that of the field's
/// rounding at the point (a few units of 2^-53 of its terms over its derivative: the one-ulp
/// sensitivity of the fixed point), not that of f. A point beyond the unit sphere (2|f_ni| > |f_no|)
/// is found inverted, as the zero of the field of sigma(B) (the inversion no -> ni/2, ni -> 2 no:
/// A and C swap with the factors 2 and 1/2, d changes sign; exact) near f_E / (2 f_ni), so that a
/// far fixed point is as accurate relative to its size.
template <typename T>
BOOSTED_FORCE_INLINE void fixedPointAlong(const T* u, const T* f, T* point)
{
  using V = ValueOf<T>;
  const Mask<V> inverse = lessThan(magnitude(valueOf(f[NO])), 2.0 * magnitude(valueOf(f[NI])));
  T p[3], e[3], a[3], c[3];
  for (int i = 0; i < 3; ++i)
  {
    p[i] = select(inverse, f[E1 + i] / (2.0 * f[NI]), f[E1 + i] / f[NO]);
    e[i] = u[E12 + i];
    a[i] = select(inverse, 2.0 * u[E1NI + i], u[E1NO + i]);
    c[i] = select(inverse, 0.5 * u[E1NO + i], u[E1NI + i]);
  }
  const T d = select(inverse, -u[NONI], u[NONI]);
  for (int step = 0; step < kFixedPointNewtonSteps; ++step)
  {
    fixedPointNewtonStep(e, a, c, d, p);
  }
  T outside[3];
  inverted(p, outside);
  for (int i = 0; i < 3; ++i)
  {
    point[i] = select(inverse, outside[i], p[i]);
  }
}

/// The two finite fixed points of exp(B), B = m u with a strong hyperbolic plane (l1 > 0, the square
/// of u's hyperbolic plane, l2 <= 0 the other's, wu = <W u>_2) beside an e_i^no part: the split's
/// null directions, projected from no + ni (whose product with every null vector is non-zero), as
/// first guesses, refined on B's own field (fixedPointAlong). Returns u's dilation rate d' = d + A.a
/// at the attractor a (negative: the fixed point where it is the smaller); r is the repeller.
template <typename T>
BOOSTED_FORCE_INLINE T attractorAndRepeller(const UnitBivector<T>& unit, const T& l1, const T& l2, const T* wu,
                                            T* attractor, T* repeller)
{
  using V = ValueOf<T>;
  const T* u = unit.u;
  T n1[kBivector];
  const T root1 = ellipticPart(u, l1, l2, wu, n1);
  for (int c = 0; c < kBivector; ++c)
  {
    n1[c] = (u[c] - n1[c]) / root1;
  }
  // (P - z)/2 grows by e^{2a}, (P + z)/2 shrinks.
  T probe[kVector] = {};
  probe[NO] = splat<T>(1.0);
  probe[NI] = splat<T>(1.0);
  T z[kVector], projection[kVector], grows[kVector], shrinks[kVector];
  contract(probe, n1, z);
  contract(z, n1, projection);
  for (int i = 0; i < kVector; ++i)
  {
    grows[i] = 0.5 * (projection[i] - z[i]);
    shrinks[i] = 0.5 * (projection[i] + z[i]);
  }
  T first[3], second[3];
  fixedPointAlong(u, grows, first);
  fixedPointAlong(u, shrinks, second);
  const T a[3] = { u[E1NO], u[E2NO], u[E3NO] };
  const T rateFirst = dot3(first, a) + u[NONI], rateSecond = dot3(second, a) + u[NONI];
  const Mask<V> swap = lessThan(valueOf(rateSecond), valueOf(rateFirst));
  for (int i = 0; i < 3; ++i)
  {
    attractor[i] = select(swap, second[i], first[i]);
    repeller[i] = select(swap, first[i], second[i]);
  }
  return select(swap, rateSecond, rateFirst);
}

/// The rate d' and the turn omega = -2 m n' of B = m u moved to x (rateAndNormalAt): exp(B) has the
/// derivative e^{2 m d'} exp([omega]_x) at a fixed point x. Returns d'.
template <typename T>
BOOSTED_FORCE_INLINE T turnAt(const T* nE, const T* a, const T& d, const T& m, const T* x, T* omega)
{
  T n[3];
  const T rate = rateAndNormalAt(nE, a, d, x, n);
  for (int i = 0; i < 3; ++i)
  {
    omega[i] = (-2.0 * m) * n[i];
  }
  return rate;
}

/// The image of x = up(p) under exp(B), B = m u with a strong hyperbolic plane (l1 > 0, the square of
/// u's hyperbolic plane, l2 <= 0 the other's, wu = <W u>_2) beside an e_i^no part, where neither
/// fixed point is ni and the split of strongHyperbolicSandwich is not exact: through the map's two
/// fixed points (FixedPointImage.h; docs/conventions.md section 2 item 12, *A strong plane beside
/// point pairs*). The split B1 = u - B2 gives the plane's null directions only as first guesses;
/// the fixed points come from B's own field (fixedPointAlong), the rate and turn at the attractor
/// a from B moved there (d' = d + A.a, n' = n_E + a x A: exp(B) has the derivative
/// e^{2 m d'} exp(-2 m [n']_x) at a), and the image is a + inv(w + y) - inv(w) with
/// y = e^{2 m d'} S Q S psi(p): the factor e^{2 m d'} <= 1 (formed as e^{m d'} twice) multiplies
/// only psi(p), which is accurate relative to itself. r = (1, p', |p'|^2/2) (no = 1: the image
/// is normalized). p on the repeller (p - r = 0, or psi(p) beyond the doubles) stays there.
template <typename T>
void strongImageByFixedPoints(const UnitBivector<T>& unit, const T& l1, const T& l2, const T* wu,
                              const T* x, T* r)
{
  using V = ValueOf<T>;
  const T* u = unit.u;
  const T m = asNumber<T>(unit.scale.usableOrOne());
  T attractor[3], repeller[3];
  const T rate = attractorAndRepeller(unit, l1, l2, wu, attractor, repeller);
  const T a[3] = { u[E1NO], u[E2NO], u[E3NO] };
  // The turn at the attractor: omega = -2 m n', n' = n_E + attractor x A.
  const T nE[3] = { u[E23], -u[E13], u[E12] };
  T omega[3];
  turnAt(nE, a, u[NONI], m, attractor, omega);
  // psi(p) = inv(p - r) - inv(a - r), then y = e^{2 m d'} S Q S psi(p).
  const T p[3] = { x[E1], x[E2], x[E3] };
  T across[3], fromAttractor[3], fromRepeller[3];
  for (int i = 0; i < 3; ++i)
  {
    across[i] = attractor[i] - repeller[i];
    fromAttractor[i] = p[i] - attractor[i];
    fromRepeller[i] = p[i] - repeller[i];
  }
  T psi[3];
  differenceOfInverses(across, fromAttractor, fromRepeller, psi);
  const T down = asNumber<T>(1.0 / vectorScale(across));
  T normal[3];
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = across[i] * down;
  }
  const T length = laneSqrt(dot3(normal, normal));
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = normal[i] / length;
  }
  T reflectedPsi[3], turned[3], y[3];
  reflected(normal, psi, reflectedPsi);
  rotatedBy(omega, reflectedPsi, turned);
  reflected(normal, turned, y);
  const T factor = laneExp(m * rate);
  for (int i = 0; i < 3; ++i)
  {
    y[i] = (y[i] * factor) * factor;
  }
  // Back: p' = a + (inv(w + y) - inv(w)) near the attractor, r + inv(w + y) elsewhere.
  T w[3], sum[3], offset[3], far[3];
  inverted(across, w);
  for (int i = 0; i < 3; ++i)
  {
    sum[i] = w[i] + y[i];
  }
  inverseDifference(w, y, sum, offset);
  inverted(sum, far);
  const Mask<V> nearAttractor = withinHalf(w, y);
  Mask<V> onRepeller = maskAnd(maskAnd(equalTo(valueOf(fromRepeller[0]), V{}),
    equalTo(valueOf(fromRepeller[1]), V{})), equalTo(valueOf(fromRepeller[2]), V{}));
  for (int i = 0; i < 3; ++i)
  {
    onRepeller = maskOr(onRepeller, maskNot(finiteLanes(valueOf(y[i]))));
  }
  T stays[3] = { repeller[0], repeller[1], repeller[2] };
  if constexpr (kHasTangents<T>)
  {
    // p on r stays r, but its tangents are not r's alone: r moves by dr, and p, left at dp - dr
    // from it, is carried by exp(B)'s derivative there, e^{2 m d'} Q (d' and n' of B moved to r):
    // r's value with the tangents of r + e^{2 m d'} Q (p - r).
    T omegaAtRepeller[3], turnedOffset[3];
    const T rateAtRepeller = turnAt(nE, a, u[NONI], m, repeller, omegaAtRepeller);
    rotatedBy(omegaAtRepeller, fromRepeller, turnedOffset);
    const T growth = laneExp(m * rateAtRepeller);
    for (int i = 0; i < 3; ++i)
    {
      stays[i] = withValueOf(onRepeller, repeller[i], repeller[i] + (turnedOffset[i] * growth) * growth);
    }
  }
  T image[3];
  for (int i = 0; i < 3; ++i)
  {
    image[i] = select(onRepeller, stays[i],
      select(nearAttractor, attractor[i] + offset[i], repeller[i] + far[i]));
  }
  r[NO] = splat<T>(1.0);
  for (int i = 0; i < 3; ++i)
  {
    r[E1 + i] = image[i];
  }
  r[NI] = 0.5 * dot3(image, image);
}

/// fn(r): the Euclidean point r_e / r_no, and per lane whether it is mapped (normalizePoint: the
/// weight is non-zero, the point and p are finite).
template <typename T>
BOOSTED_FORCE_INLINE Mask<T> normalizeLanes(const T* p, const T* r, T* image)
{
  using V = ValueOf<T>;
  const T alpha = r[NO];
  for (int i = 0; i < 3; ++i)
  {
    image[i] = r[E1 + i] / alpha;
  }
  const V a = valueOf(alpha);
  Mask<V> mapped = maskAnd(maskNot(equalTo(a, V{})), finiteLanes(a));
  for (int i = 0; i < 3; ++i)
  {
    mapped = maskAnd(mapped, maskAnd(finiteLanes(valueOf(image[i])), finiteLanes(valueOf(p[i]))));
  }
  return mapped;
}

/// normalizeLanes with the flags as bools.
template <typename T>
BOOSTED_FORCE_INLINE void normalize(const T* p, const T* r, T* image, bool* mapped)
{
  toFlags<ValueOf<T>>(normalizeLanes(p, r, image), mapped);
}

/// T(t) B ~T(t) for the translator T(t) = 1 - t ni/2: with B = E + A_i e_i^no + C_i e_i^ni + d no^ni
/// the vectors move as no -> up(t), e_i -> e_i + t_i ni, ni -> ni, so
/// E'_ij = E_ij + A_i t_j - A_j t_i, A' = A, C'_k = C_k + E_kj t_j + (|t|^2/2) A_k - (A.t) t_k + d t_k,
/// d' = d - A.t.
template <typename T>
BOOSTED_FORCE_INLINE void translateBivector(const T* b, const T* t, T* out)
{
  const T a1 = b[E1NO], a2 = b[E2NO], a3 = b[E3NO], d = b[NONI];
  const T e12 = b[E12], e13 = b[E13], e23 = b[E23];
  const T at = a1 * t[0] + a2 * t[1] + a3 * t[2];
  out[E12] = e12 + (a1 * t[1] - a2 * t[0]);
  out[E13] = e13 + (a1 * t[2] - a3 * t[0]);
  out[E23] = e23 + (a2 * t[2] - a3 * t[1]);
  out[E1NO] = a1;
  out[E2NO] = a2;
  out[E3NO] = a3;
  // |t|^2/2 A_k - (A.t) t_k = sum_j t_j (t_j A_k / 2 - A_j t_k), the products of A and t first:
  // for a tiny t (a patch of size 1e-160 under curvatures 1e160) |t|^2 would be subnormal.
  const T a[3] = { a1, a2, a3 };
  T quadratic[3];
  for (int k = 0; k < 3; ++k)
  {
    quadratic[k] = t[0] * (0.5 * (t[0] * a[k]) - a[0] * t[k]) + t[1] * (0.5 * (t[1] * a[k]) - a[1] * t[k]) +
      t[2] * (0.5 * (t[2] * a[k]) - a[2] * t[k]);
  }
  out[E1NI] = b[E1NI] + (e12 * t[1] + e13 * t[2]) + quadratic[0] + d * t[0];
  out[E2NI] = b[E2NI] + (e23 * t[2] - e12 * t[0]) + quadratic[1] + d * t[1];
  out[E3NI] = b[E3NI] - (e13 * t[0] + e23 * t[1]) + quadratic[2] + d * t[2];
  out[NONI] = d - at;
}

/// Balances B about the origin by the dilation x -> 2^k x, which scales the e_i^no components by
/// 2^-k and the e_i^ni ones by 2^k (exactly: powers of two), with k making both about the same
/// size. Returns 2^-k per lane: exp of the balanced B maps 2^k x to 2^k x', so x' = 2^-k times
/// its image. Where one of the two parts is zero or B is not finite, k = 0.
template <typename T>
BOOSTED_FORCE_INLINE ValueOf<T> balanceByDilation(T* b)
{
  using V = ValueOf<T>;
  const auto largest = [](const V& x, const V& y, const V& z) {
    const V ax = magnitude(x), ay = magnitude(y), az = magnitude(z);
    const V ayz = select(lessThan(ay, az), az, ay);
    return select(lessThan(ax, ayz), ayz, ax);
  };
  // (a NaN part gives NaN or a smaller value: either way the lane is NaN and k does not matter)
  const V a = largest(valueOf(b[E1NO]), valueOf(b[E2NO]), valueOf(b[E3NO]));
  const V c = largest(valueOf(b[E1NI]), valueOf(b[E2NI]), valueOf(b[E3NI]));
  const Mask<V> usable = maskAnd(maskAnd(lessThan(V{}, a), lessThan(V{}, c)),
    maskAnd(finiteLanes(a), finiteLanes(c)));
  // k = half the difference of the exponents, rounded to the nearest integer (adding and taking
  // away 1.5 2^52 rounds a number below 2^51 in size to an integer), within +-1022.
  const V difference = binaryExponentOf(a) - binaryExponentOf(c);
  const V rounding = splat<V>(0x1.8p52);
  V k = select(usable, (0.5 * difference + rounding) - rounding, V{});
  k = select(lessThan(k, splat<V>(-1022.0)), splat<V>(-1022.0), k);
  k = select(lessThan(splat<V>(1022.0), k), splat<V>(1022.0), k);
  const V up = powerOfTwoOf(k), down = powerOfTwoOf(-k);
  const T upValue = asNumber<T>(up), downValue = asNumber<T>(down);
  for (const int i : { E1NO, E2NO, E3NO })
  {
    b[i] = downValue * b[i];
  }
  for (const int i : { E1NI, E2NI, E3NI })
  {
    b[i] = upValue * b[i];
  }
  return down;
}

/// max |l| of the plane squares of u = B/m below which B counts as nearly nilpotent: a huge
/// nilpotent part (a generator next to p with a small epsilon) plus a small rest.
constexpr double kNearlyNilpotent = 1e-4;

/// Scale of the balanced, translated B (the largest component m' of B about p, balanced) above
/// which a nearly nilpotent B's image is computed in double-double: its terms of size m'^2 cancel
/// to the image, so double loses about m'^2 units of 2^-53 of the scale: beyond m' ~ 800 more than
/// the tested bound (docs/conventions.md section 2 item 12), at 64 about 150 times less.
constexpr double kExtendedPrecisionScale = 64.0;

/// Per lane, whether the image of a nearly nilpotent B, balanced about p and unit-scaled (unit),
/// needs more than double precision: its scale m' above kExtendedPrecisionScale.
template <typename T>
BOOSTED_FORCE_INLINE Mask<T> needsExtendedPrecision(const UnitBivector<T>& unit)
{
  using V = ValueOf<T>;
  return maskAnd(unit.scale.usable, lessThan(splat<V>(kExtendedPrecisionScale), unit.scale.m));
}

/// The image (and whether mapped) of the lanes of `lanes` replaced by accurateImageAroundPoint's
/// (AccurateImage.h): their values, with a Dual's tangents of the double computation.
template <typename T>
Mask<T> imageInExtendedPrecision(const Mask<T>& lanes, const T* p, const T* b, T* image, const Mask<T>& mapped)
{
  using V = ValueOf<T>;
  constexpr int L = kLanesOf<V>;
  const LaneArray<V> which(select(lanes, splat<V>(1.0), V{}));
  LaneArray<V> flags(select(mapped, splat<V>(1.0), V{}));
  LaneArray<V> bLanes[kBivector], pLanes[3], out[3];
  for (int c = 0; c < kBivector; ++c)
  {
    bLanes[c] = LaneArray<V>(valueOf(b[c]));
  }
  for (int i = 0; i < 3; ++i)
  {
    pLanes[i] = LaneArray<V>(valueOf(p[i]));
    out[i] = LaneArray<V>(valueOf(image[i]));
  }
  for (int l = 0; l < L; ++l)
  {
    if (which.v[l] == 0.0)
    {
      continue;
    }
    double bl[kBivector], pl[3], il[3];
    for (int c = 0; c < kBivector; ++c)
    {
      bl[c] = bLanes[c].v[l];
    }
    for (int i = 0; i < 3; ++i)
    {
      pl[i] = pLanes[i].v[l];
    }
    const bool ok = accurateImageAroundPoint(bl, pl, il);
    for (int i = 0; i < 3; ++i)
    {
      out[i].v[l] = il[i];
    }
    flags.v[l] = ok ? 1.0 : 0.0;
  }
  for (int i = 0; i < 3; ++i)
  {
    image[i] = withValueOf(lanes, asNumber<T>(out[i].value()), image[i]);
  }
  return lessThan(V{}, flags.value());
}

/// The Exact image of p computed relative to p (up(p) becomes no) and balanced by a dilation about
/// p, for a nearly nilpotent B: there the closed form of exp(B) in the field's frame would cancel
/// terms of size |B|^2 / sqrt|l| (docs/conventions.md section 2 item 12).
template <typename T>
Mask<T> exactImageAroundPoint(const T* p, const T* b, T* image)
{
  const T t[3] = { -p[0], -p[1], -p[2] };
  T moved[kBivector];
  translateBivector(b, t, moved);
  const ValueOf<T> down = balanceByDilation(moved);
  UnitBivector<T> unit;
  unitBivector(moved, unit);
  // Where B is a 2-blade (W = 0: a lone point pair, generators at one place) exp(B) = c + sHat B
  // and its sandwich has a closed form; elsewhere the full even K. A block computes the one its
  // lanes need, both only where they differ, and each lane takes its own (the bits of map()).
  Mask<T> blade = equalTo(unit.w[0], T{});
  for (int i = 1; i < kQuadvector; ++i)
  {
    blade = maskAnd(blade, equalTo(unit.w[i], T{}));
  }
  const bool anyBlade = anyLane(blade), allBlade = allLanes(blade);
  T origin[kVector] = {}; // up(0) = no
  origin[NO] = splat<T>(1.0);
  T r[kVector], fromBlade[kVector];
  if (anyBlade)
  {
    T c, bp[kBivector];
    for (int i = 0; i < kBivector; ++i)
    {
      bp[i] = unit.u[i];
    }
    bladeExponential(unit.scale, unit.s, true, bp, c, true);
    sandwichScalarBivector(c, bp, origin, fromBlade);
  }
  // A Dual always takes the full K for its tangents (W may vanish at this B, its tangents need
  // not), the blade's values where it applies.
  const bool full = !allBlade || kHasTangents<T>;
  if (full)
  {
    T k[kEven];
    exactExponential(moved, unit, true, k);
    keepSandwichInRange(unit.scale.usableOrOne(), k, kEven);
    sandwichOrigin(k, r);
  }
  for (int i = 0; i < kVector; ++i)
  {
    r[i] = !full ? fromBlade[i] : (anyBlade ? withValueOf(blade, fromBlade[i], r[i]) : r[i]);
  }
  const T zero[3] = {};
  T offset[3];
  Mask<T> mapped = normalizeLanes(zero, r, offset);
  const T scale = asNumber<T>(down);
  for (int i = 0; i < 3; ++i)
  {
    image[i] = p[i] + scale * offset[i];
    mapped = maskAnd(mapped, finiteLanes(valueOf(p[i])));
  }
  if constexpr (RoundingUnit<T>::value == RoundingUnit<double>::value)
  {
    const Mask<T> accurate = needsExtendedPrecision(unit);
    if (anyLane(accurate))
    {
      mapped = imageInExtendedPrecision(accurate, p, b, image, mapped);
    }
  }
  return mapped;
}

/// The Exact image of p in the field's frame: fn(<K up(p) ~K>_1) with K = exp(b) in closed form
/// (invariants kept), for b far from nilpotent.
template <typename T>
Mask<T> exactImageInFieldFrame(const T* b, const T* p, T* image)
{
  T x[kVector], r[kVector], k[kEven];
  upPoint(p, x);
  exactExponential(b, true, k, false);
  sandwichEven(k, x, r);
  return normalizeLanes(p, r, image);
}

/// Whether T is a Dual of double (or of the lanes) with at most kExtendedTangentCount tangents:
/// the derivatives whose field-frame tangents may be taken in double-double.
template <typename T>
constexpr bool kExtendedTangents = false;
template <typename V, int N>
constexpr bool kExtendedTangents<Dual<V, N>> = N <= kExtendedTangentCount && !kHasTangents<V> &&
  RoundingUnit<V>::value == RoundingUnit<double>::value;

/// Margin of tangentsNeedExtendedPrecision, in units of 2^-53 of max(1, |J|).
constexpr double kExtendedTangentMargin = 1024.0;

/// Per lane, whether the field frame's tangents in double may miss the derivative's bound
/// max(1, |J|) (1e-12 + 8 2^-52 max(1, |b|)) (|b| = bMax, the largest component) (docs/conventions.md section 3 item 15): they carry
/// the image's rounding (about 2^-53 max(1, |p'|)) times the exponent's tangents (up to
/// G = max |d b / d seed|), measured at 1 ... 3 units of 2^-53 G max(1, |p'|); double-double
/// where G max(1, |p'|) > max(1, |J|) (1024 + 2 max(1, |b|)), within a third of the bound below.
template <typename V, int N>
BOOSTED_FORCE_INLINE Mask<V> tangentsNeedExtendedPrecision(const Dual<V, N>* b, const V& bMax, const Dual<V, N>* image)
{
  const auto larger = [](const V& x, const V& y) { return select(lessThan(x, y), y, x); };
  const V one = splat<V>(1.0);
  V tangents = V{}, size = one, jacobian = one;
  for (int c = 0; c < kBivector; ++c)
  {
    for (int k = 0; k < N; ++k)
    {
      tangents = larger(tangents, magnitude(b[c].d[k]));
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    size = larger(size, magnitude(image[i].v));
    for (int k = 0; k < N; ++k)
    {
      jacobian = larger(jacobian, magnitude(image[i].d[k]));
    }
  }
  const V exponent = larger(one, bMax);
  return lessThan(jacobian * (kExtendedTangentMargin + 2.0 * exponent), tangents * size);
}

/// The tangents of the image of the lanes of `lanes` replaced by accurateTangentsInFieldFrame's
/// (AccurateImage.h), where it maps them; the values stay the double computation's (map()'s bits).
template <typename V, int N>
void tangentsInExtendedPrecision(const Mask<V>& lanes, const Dual<V, N>* b, const Dual<V, N>* p, Dual<V, N>* image)
{
  constexpr int L = kLanesOf<V>;
  const LaneArray<V> which(select(lanes, splat<V>(1.0), V{}));
  LaneArray<V> bValues[kBivector], bTangents[kBivector][N], pValues[3], pTangents[3][N], out[3][N];
  for (int c = 0; c < kBivector; ++c)
  {
    bValues[c] = LaneArray<V>(b[c].v);
    for (int k = 0; k < N; ++k)
    {
      bTangents[c][k] = LaneArray<V>(b[c].d[k]);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    pValues[i] = LaneArray<V>(p[i].v);
    for (int k = 0; k < N; ++k)
    {
      pTangents[i][k] = LaneArray<V>(p[i].d[k]);
      out[i][k] = LaneArray<V>(image[i].d[k]);
    }
  }
  for (int l = 0; l < L; ++l)
  {
    if (which.v[l] == 0.0)
    {
      continue;
    }
    double bl[kBivector], dbl[kBivector * N], pl[3], dpl[3 * N], dil[3 * N];
    for (int c = 0; c < kBivector; ++c)
    {
      bl[c] = bValues[c].v[l];
      for (int k = 0; k < N; ++k)
      {
        dbl[N * c + k] = bTangents[c][k].v[l];
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      pl[i] = pValues[i].v[l];
      for (int k = 0; k < N; ++k)
      {
        dpl[N * i + k] = pTangents[i][k].v[l];
      }
    }
    if (!accurateTangentsInFieldFrame(N, bl, dbl, pl, dpl, dil))
    {
      continue; // the double tangents stay
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < N; ++k)
      {
        out[i][k].v[l] = dil[N * i + k];
      }
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < N; ++k)
    {
      image[i].d[k] = out[i][k].value();
    }
  }
}

/// Per lane, whether the field's frame maps by sandwichWithStrongLanes: among `candidates` (usable
/// lanes not mapped around p), a = m sqrt(l1) in (kStrongHyperbolic, kStrongHyperbolicLimit], and
/// above kStrongGeneral where the split is not exact (strongSandwichIsExact: those take
/// strongImageByFixedPoints). The angle first: the rest is tested only in blocks where some lane
/// passes it.
template <typename T>
BOOSTED_FORCE_INLINE Mask<ValueOf<T>> strongLanes(const UnitBivector<T>& unit, const T& l1, const Mask<T>& candidates)
{
  using V = ValueOf<T>;
  const V mUnit = unit.scale.usableOrOne();
  const V angleSquare = (valueOf(l1) * mUnit) * mUnit;
  Mask<V> strong = maskAnd(maskAnd(unit.scale.usable, candidates),
    maskAnd(lessThan(splat<V>(kStrongHyperbolic * kStrongHyperbolic), angleSquare),
      lessEqual(angleSquare, splat<V>(kStrongHyperbolicLimit * kStrongHyperbolicLimit))));
  if (!anyLane(strong))
  {
    return strong;
  }
  const Mask<V> strongGeneral = lessThan(splat<V>(kStrongGeneral * kStrongGeneral), angleSquare);
  return maskAnd(strong, maskOr(strongGeneral, strongSandwichIsExact(unit)));
}

/// The field frame's sandwich r = <K X ~K>_1 of a block with `strong` lanes: theirs by
/// strongHyperbolicSandwich where its split is exact (strongSandwichIsExact), by
/// strongImageByFixedPoints elsewhere (r then the normalized image), the others' by the closed form
/// of exp(B) (as mapPointBy's common path).
/// Out of line and cold, called only for such blocks: inlined into mapPointBy, or called from its
/// common path, its code changed how GCC kept the common path's values (registers, stack) and cost
/// a block without a strong lane about 4 ns per point on AVX-512 (issue #11).
template <typename T>
BOOSTED_COLD void sandwichWithStrongLanes(const T* b, const UnitBivector<T>& unit, const T& l1, const T& l2,
  const T* wu, const Mask<ValueOf<T>>& strong, const T* x, T* r)
{
  const bool allStrong = allLanes(strong);
  if (!allStrong)
  {
    T k[kEven];
    exactExponential(b, unit, l1, l2, wu, true, k);
    sandwichEven(k, x, r);
  }
  T fromStrong[kVector];
  const Mask<ValueOf<T>> exactSplit = strongSandwichIsExact(unit);
  const Mask<ValueOf<T>> general = maskAnd(strong, maskNot(exactSplit));
  const bool allGeneral = allLanes(general);
  if (!allGeneral)
  {
    strongHyperbolicSandwich(unit, l1, l2, wu, x, fromStrong);
  }
  if (anyLane(general))
  {
    T byFixedPoints[kVector];
    strongImageByFixedPoints(unit, l1, l2, wu, x, byFixedPoints);
    for (int i = 0; i < kVector; ++i)
    {
      fromStrong[i] = allGeneral ? byFixedPoints[i] : select(general, byFixedPoints[i], fromStrong[i]);
    }
  }
  for (int i = 0; i < kVector; ++i)
  {
    r[i] = allStrong ? fromStrong[i] : select(strong, fromStrong[i], r[i]);
  }
}

/// Per lane, whether the Exact rule maps b around p: mapPointBy's test (B nearly nilpotent: both
/// plane squares of B below kNearlyNilpotent m^2, m = maxAbs(b)) for strongExponentLane.
/// mapPointBy keeps its own copy of these lines: called there, the helper changed the kernel's
/// AVX-512, AVX2 and baseline code (registers, stack) for the same arithmetic; the two must stay
/// the same test (NearlyNilpotent.*, CGA/Testing/TestNearlyNilpotent.cpp, fails where they part).
template <typename T>
BOOSTED_FORCE_INLINE Mask<T> nearlyNilpotentLanes(const T* b, const T& m)
{
  const T threshold = (kNearlyNilpotent * m) * m;
  const T s = scalarSquare(b);
  Mask<T> aroundPoint = lessThan(0.5 * magnitude(s), threshold);
  if (anyLane(aroundPoint))
  {
    T w[kQuadvector], w2, l1, l2;
    detail::applyProduct<detail::kWedge>(b, b, w);
    detail::applyProduct<detail::kQuadvectorSquare>(w, w, &w2);
    detail::planeSquares(s, w2, l1, l2);
    const T largest = select(lessThan(magnitude(l1), magnitude(l2)), magnitude(l2), magnitude(l1));
    aroundPoint = lessThan(largest, threshold);
  }
  return aroundPoint;
}

/// The map p -> fn(<K up(p) ~K>_1), K = exp(b) by the rule of args, on every lane, for a given
/// bivector b (overwritten): mapPoint after its B(p), for callers with their own exponent per point
/// (kernel::MapBlockBy; the curvature patch, the generator tree's B(p)). Returns the lanes mapped
/// (mapPointBy below: as bools).
template <typename T>
Mask<T> mapPointByLanes(const kernel::FieldArgs& args, T* b, const T* p, T* image)
{
  T x[kVector], r[kVector];
  upPoint(p, x);
  if (!args.exactRule)
  {
    T c;
    paperExponential(b, c, true, true);
    sandwichScalarBivector(c, b, x, r);
    return normalizeLanes(p, r, image);
  }
  // Exact: in the field's frame, or around p where B is nearly nilpotent (each lane its own; a
  // block computes both only where its lanes differ). A NaN lane takes the field's frame.
  // The plane squares of B itself against kNearlyNilpotent m^2 (no division by m: a rough test).
  // The larger one in size is at least |s|/2 (s = l1 + l2; planeSquares keeps that after
  // rounding), so where every lane has |s|/2 above the threshold W need not be formed.
  const T m = asNumber<T>(maxAbs(b));
  const T threshold = (kNearlyNilpotent * m) * m;
  const T s = scalarSquare(b);
  Mask<T> aroundPoint = lessThan(0.5 * magnitude(s), threshold);
  if (anyLane(aroundPoint))
  {
    T w[kQuadvector], w2, l1, l2;
    detail::applyProduct<detail::kWedge>(b, b, w);
    detail::applyProduct<detail::kQuadvectorSquare>(w, w, &w2);
    detail::planeSquares(s, w2, l1, l2);
    const T largest = select(lessThan(magnitude(l1), magnitude(l2)), magnitude(l2), magnitude(l1));
    aroundPoint = lessThan(largest, threshold);
  }
  const bool anyAround = anyLane(aroundPoint), allAround = allLanes(aroundPoint);
  T around[3];
  Mask<T> aroundMapped = aroundPoint;
  if (anyAround)
  {
    aroundMapped = exactImageAroundPoint(p, b, around);
  }
  if (allAround)
  {
    for (int i = 0; i < 3; ++i)
    {
      image[i] = around[i];
    }
    return aroundMapped;
  }
  // The field's frame: the closed form of exp(B) and its sandwich, or where B's hyperbolic plane
  // is strong (m^2 l1 above kStrongHyperbolic^2) sandwichWithStrongLanes.
  using V = ValueOf<T>;
  UnitBivector<T> unit;
  unitBivector(b, unit, false);
  T wu[kBivector], l1, l2;
  detail::applyProduct<detail::kRightContraction>(unit.w, unit.u, wu);
  detail::planeSquares(unit.s, unit.w2, l1, l2);
  const Mask<V> strong = strongLanes(unit, l1, maskNot(aroundPoint));
  if (anyLane(strong))
  {
    sandwichWithStrongLanes(b, unit, l1, l2, wu, strong, x, r);
  }
  else
  {
    T k[kEven];
    exactExponential(b, unit, l1, l2, wu, true, k);
    sandwichEven(k, x, r);
  }
  Mask<T> fieldMapped = normalizeLanes(p, r, image);
  if constexpr (kExtendedTangents<T>)
  {
    // Not the strong lanes: their tangents come exact from strongHyperbolicSandwich or
    // strongImageByFixedPoints, while the double-double path recomputes the cancelling closed form.
    const Mask<T> wide = maskAnd(maskAnd(maskNot(aroundPoint), maskNot(strong)),
      tangentsNeedExtendedPrecision(b, valueOf(m), image));
    if (anyLane(wide))
    {
      tangentsInExtendedPrecision(wide, b, p, image);
    }
  }
  if (anyAround)
  {
    for (int i = 0; i < 3; ++i)
    {
      image[i] = select(aroundPoint, around[i], image[i]);
    }
    fieldMapped = maskOr(maskAnd(aroundPoint, aroundMapped), maskAnd(maskNot(aroundPoint), fieldMapped));
  }
  return fieldMapped;
}

/// mapPointByLanes with the lanes mapped as bools.
template <typename T>
void mapPointBy(const kernel::FieldArgs& args, T* b, const T* p, T* image, bool* mapped)
{
  toFlags<ValueOf<T>>(mapPointByLanes(args, b, p, image), mapped);
}

/// Whether mapPointBy's Exact rule maps the one exponent b (double) by its strong lanes
/// (strongHyperbolicSandwich or strongImageByFixedPoints; its lanes' decisions, for double), and
/// then in `similarity` whether b is a similarity's bivector: the lanes whose d out / d b
/// StrongSimilarityDerivative.h computes in closed form (a similarity's, or conjugated to one by
/// the inversion about the repeller).
inline bool strongExponentLane(const double* b, bool& similarity)
{
  similarity = false;
  if (nearlyNilpotentLanes(b, maxAbs(b)))
  {
    return false;
  }
  UnitBivector<double> unit;
  unitBivector(b, unit, false);
  double wu[kBivector], l1, l2;
  detail::applyProduct<detail::kRightContraction>(unit.w, unit.u, wu);
  detail::planeSquares(unit.s, unit.w2, l1, l2);
  if (!strongLanes(unit, l1, true))
  {
    return false;
  }
  similarity = similarityLanes(unit.u);
  return true;
}

/// The map p -> fn(<K up(p) ~K>_1), K = exp(-strength B(p)) by the rule of args, on every lane.
/// Returns the lanes mapped (mapPoint below: as bools).
template <typename T>
Mask<T> mapPointLanes(const kernel::FieldArgs& args, const T* p, T* image)
{
  T b[kBivector];
  fieldBivector(args, p, -args.strength, b);
  return mapPointByLanes(args, b, p, image);
}

/// mapPointLanes with the lanes mapped as bools.
template <typename T>
void mapPoint(const kernel::FieldArgs& args, const T* p, T* image, bool* mapped)
{
  toFlags<ValueOf<T>>(mapPointLanes(args, p, image), mapped);
}
} // namespace
} // namespace core
} // namespace cga
