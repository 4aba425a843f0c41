// Internal: the numerical core of the point map, written once as templates over the number type T.
//
// T is double (PointPairField::map, expPaper, expExact, sandwichGrade1) or the block kernel's
// vector of lanes (PointPairKernelLanes.h, one point per lane): the pointwise map and the batch
// kernel are two instantiations of these functions, so they agree bit for bit by construction
// (the whole library is compiled with -ffp-contract=off: no fused multiply-add may round one
// instantiation differently from the other).
//
// T needs +, -, * and / (also with a double on either side), unary -, T{} == 0, kLanesOf<T> lanes
// and, found by argument-dependent lookup, toLanes(const T&, double*) and fromLanes(const double*,
// T&). Arithmetic over components is written on T; what branches per lane (the choice of formula,
// the scalar functions of ExponentialScalars.h) is written on the lanes copied to small arrays.
//
// Everything here has internal linkage (an unnamed namespace) and calls only builtins and libm:
// the kernel instantiates these templates in translation units compiled for AVX2 and AVX-512, and
// a template instance or inline function with vague linkage emitted there could be the copy the
// linker keeps for the baseline code too, which would then fault on an older CPU.
#pragma once

#include "ExponentialScalars.h"
#include "PointPairKernel.h"
#include "ProductTerms.h"

#include "cga/Compact.h" // for the component enumerators only: nothing of it is called here

// The small pieces the kernel's hot path calls are inlined whatever the compiler's size budget
// (a call passes the lane vectors through memory).
#if defined(__GNUC__) || defined(__clang__)
#define BOOSTED_CORE_INLINE inline __attribute__((always_inline))
#else
#define BOOSTED_CORE_INLINE inline
#endif

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

// The number type double: one lane.
template <typename T>
constexpr int kLanesOf = T::kLanes;
template <>
constexpr int kLanesOf<double> = 1;

inline void toLanes(double x, double* lanes)
{
  lanes[0] = x;
}
inline void fromLanes(const double* lanes, double& x)
{
  x = lanes[0];
}

// The lanes of one T as an array, for the per-lane parts.
template <typename T>
struct LaneArray
{
  alignas(64) double v[kLanesOf<T>];

  LaneArray() = default;
  explicit LaneArray(const T& x) { toLanes(x, v); }
  T value() const
  {
    T x;
    fromLanes(v, x);
    return x;
  }
};

/// <B B>_0: e_ij^2 = -1; (e_i no)(e_i ni) and (e_i ni)(e_i no) have scalar part 1; (no^ni)^2 = 1.
template <typename T>
BOOSTED_CORE_INLINE T scalarSquare(const T* b)
{
  return -(b[E12] * b[E12] + b[E13] * b[E13] + b[E23] * b[E23]) +
    2.0 * (b[E1NO] * b[E1NI] + b[E2NO] * b[E2NI] + b[E3NO] * b[E3NI]) + b[NONI] * b[NONI];
}

/// Largest absolute component, NaN when one is NaN (Coefficients::maxAbs).
template <typename T>
BOOSTED_CORE_INLINE LaneArray<T> maxAbs(const T* b)
{
  constexpr int L = kLanesOf<T>;
  alignas(64) double lanes[kBivector][L];
  for (int c = 0; c < kBivector; ++c)
  {
    toLanes(b[c], lanes[c]);
  }
  // The running maximum and a NaN flag, kept apart so that the loop vectorizes.
  LaneArray<T> m;
  bool nan[L];
  for (int l = 0; l < L; ++l)
  {
    m.v[l] = 0.0;
    nan[l] = false;
  }
  for (int c = 0; c < kBivector; ++c)
  {
    for (int l = 0; l < L; ++l)
    {
      const double a = __builtin_fabs(lanes[c][l]);
      m.v[l] = a > m.v[l] ? a : m.v[l];
      nan[l] = nan[l] | (a != a);
    }
  }
  for (int l = 0; l < L; ++l)
  {
    m.v[l] = nan[l] ? __builtin_nan("") : m.v[l];
  }
  return m;
}

/// b = -strength B(p), B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps) (PointPairField::generatorAt
/// without the factor).
template <typename T>
BOOSTED_CORE_INLINE void fieldBivector(const kernel::FieldArgs& args, const T* p, double scale, T* b)
{
  T sum[kBivector];
  for (int c = 0; c < kBivector; ++c)
  {
    sum[c] = T{};
  }
  const double falloff = args.falloff, epsilon = args.epsilon;
  for (std::size_t i = 0; i < args.generatorCount; ++i)
  {
    const double* g = args.generators + i * kernel::kGeneratorStride;
    const T dx = p[0] - g[0];
    const T dy = p[1] - g[1];
    const T dz = p[2] - g[2];
    const T factor = 1.0 / (falloff * (dx * dx + dy * dy + dz * dz) + epsilon);
    for (int c = 0; c < kBivector; ++c)
    {
      sum[c] = sum[c] + g[3 + c] * factor;
    }
  }
  for (int c = 0; c < kBivector; ++c)
  {
    b[c] = sum[c] * scale;
  }
}

/// Per lane, whether the largest component m of B is finite, and whether it is zero.
template <typename T>
struct Scale
{
  LaneArray<T> m;
  bool finite[kLanesOf<T>], zero[kLanesOf<T>];

  bool usable(int l) const { return finite[l] && !zero[l]; }

  /// NaN where B is not finite, the identity's value where B = 0, else the computed value.
  double guard(int l, double identity, double value) const
  {
    return !finite[l] ? __builtin_nan("") : (zero[l] ? identity : value);
  }
};

/// The scale m of B, and u = B / m where m is non-zero and finite (B where it is not).
template <typename T>
BOOSTED_CORE_INLINE void unitScaled(const T* b, Scale<T>& scale, T* u)
{
  scale.m = maxAbs(b);
  LaneArray<T> divisor;
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    scale.finite[l] = __builtin_isfinite(scale.m.v[l]);
    scale.zero[l] = scale.m.v[l] == 0.0;
    divisor.v[l] = scale.usable(l) ? scale.m.v[l] : 1.0;
  }
  const T d = divisor.value();
  for (int c = 0; c < kBivector; ++c)
  {
    u[c] = b[c] / d;
  }
}

/// The Paper rule (expPaper): K = c + B' with on return b holding B' = sHat B/m; NaN where B is not
/// finite, c = 1 and B' = 0 where B = 0.
template <typename T>
void paperExponential(T* b, T& c, bool divideByCosh)
{
  constexpr int L = kLanesOf<T>;
  Scale<T> scale;
  unitScaled(b, scale, b);
  const LaneArray<T>& m = scale.m;
  const LaneArray<T> lh(scalarSquare(b));
  LaneArray<T> r, x, cosine, sHat;
  for (int l = 0; l < L; ++l)
  {
    r.v[l] = __builtin_sqrt(__builtin_fabs(lh.v[l]));
    x.v[l] = m.v[l] * r.v[l];
  }
  for (int l = 0; l < L; ++l)
  {
    // The power series of planeFunctions for every lane, in a loop of its own so that it
    // vectorizes (sqrt's errno branch above would keep it scalar), then the transcendental form
    // where it applies.
    detail::planeSeries(m.v[l], lh.v[l], x.v[l], cosine.v[l], sHat.v[l]);
  }
  for (int l = 0; l < L; ++l)
  {
    if (!(x.v[l] < detail::kPlaneSeriesLimit) && scale.usable(l))
    {
      detail::planeTranscendental(lh.v[l], r.v[l], x.v[l], divideByCosh, cosine.v[l], sHat.v[l]);
    }
  }
  for (int l = 0; l < L; ++l)
  {
    cosine.v[l] = scale.guard(l, 1.0, cosine.v[l]);
    sHat.v[l] = scale.guard(l, 0.0, sHat.v[l]);
  }
  c = cosine.value();
  const T factor = sHat.value();
  for (int i = 0; i < kBivector; ++i)
  {
    b[i] = factor * b[i];
  }
}

/// exp(B) = a0 + a4 W + b0 B + b4 <W B>_2 from the power series in B^2 = s + W
/// (detail::seriesCoefficients), into k (detail::pack order).
template <typename T>
void seriesExponential(const detail::BoostTables& tables, const T* b, T* k)
{
  T w[kQuadvector], w2, wb[kBivector];
  detail::applyTerms(tables.wedge, kQuadvector, b, b, w);
  detail::applyTerms(tables.quadvectorSquare, 1, w, w, &w2);
  detail::applyTerms(tables.rightContraction, kBivector, w, b, wb);
  const detail::SeriesCoefficients<T> c = detail::seriesCoefficients(scalarSquare(b), w2);
  k[0] = c.a0;
  for (int i = 0; i < kBivector; ++i)
  {
    k[1 + i] = c.b0 * b[i] + c.b4 * wb[i];
  }
  for (int i = 0; i < kQuadvector; ++i)
  {
    k[1 + kBivector + i] = c.a4 * w[i];
  }
}

/// The Exact rule (expExact) into k (detail::pack order): the power series where both squares of B
/// are at most 1 in size, else the closed form in u = B/m; NaN where B is not finite.
template <typename T>
void exactExponential(const detail::BoostTables& tables, const T* b, bool divideByCosh, T* k)
{
  constexpr int L = kLanesOf<T>;
  Scale<T> scale;
  T u[kBivector];
  unitScaled(b, scale, u);
  const LaneArray<T>& m = scale.m;
  T w[kQuadvector], w2;
  detail::applyTerms(tables.wedge, kQuadvector, u, u, w);
  detail::applyTerms(tables.quadvectorSquare, 1, w, w, &w2);
  const LaneArray<T> s(scalarSquare(u)), w2Lanes(w2);
  LaneArray<T> l1, l2;
  bool useSeries[L], closed[L];
  bool anySeries = false, anyClosed = false, allSeries = true, allClosed = true;
  for (int l = 0; l < L; ++l)
  {
    detail::planeSquares(s.v[l], w2Lanes.v[l], l1.v[l], l2.v[l]);
    useSeries[l] = scale.usable(l) && detail::exactUsesSeries(m.v[l], l1.v[l], l2.v[l]);
    closed[l] = scale.usable(l) && !useSeries[l];
    anySeries = anySeries || useSeries[l];
    anyClosed = anyClosed || closed[l];
    allSeries = allSeries && useSeries[l];
    allClosed = allClosed && closed[l];
  }
  if (allSeries)
  {
    seriesExponential(tables, b, k);
    return;
  }
  T fromSeries[kEven] = {};
  if (anySeries)
  {
    seriesExponential(tables, b, fromSeries);
  }
  T fromClosed[kEven] = {};
  if (anyClosed)
  {
    LaneArray<T> scalar, quadvector, bivector, bivectorW;
    for (int l = 0; l < L; ++l)
    {
      const detail::ExactCoefficients c = closed[l]
        ? detail::exactCoefficients(m.v[l], l1.v[l], l2.v[l], divideByCosh)
        : detail::ExactCoefficients{ 0.0, 0.0, 0.0, 0.0 };
      scalar.v[l] = c.scalar;
      quadvector.v[l] = c.quadvector;
      bivector.v[l] = c.bivector;
      bivectorW.v[l] = c.bivectorW;
    }
    T wu[kBivector];
    detail::applyTerms(tables.rightContraction, kBivector, w, u, wu);
    fromClosed[0] = scalar.value();
    const T cb = bivector.value(), cw = bivectorW.value(), cq = quadvector.value();
    for (int i = 0; i < kBivector; ++i)
    {
      fromClosed[1 + i] = cb * u[i] + cw * wu[i];
    }
    for (int i = 0; i < kQuadvector; ++i)
    {
      fromClosed[1 + kBivector + i] = cq * w[i];
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
  // Each lane takes one of the two, or NaN, or the identity (lane by lane, as the old kernel's
  // loop that the compiler turns into blends).
  alignas(64) double series[kEven][L], closedForm[kEven][L], out[kEven][L];
  for (int i = 0; i < kEven; ++i)
  {
    toLanes(fromSeries[i], series[i]);
    toLanes(fromClosed[i], closedForm[i]);
  }
  const double nan = __builtin_nan("");
  for (int l = 0; l < L; ++l)
  {
    const bool finite = scale.finite[l], zero = scale.zero[l], fromSeriesLane = useSeries[l];
    for (int i = 0; i < kEven; ++i)
    {
      const double identity = i == 0 ? 1.0 : 0.0;
      out[i][l] = !finite ? nan : (zero ? identity : (fromSeriesLane ? series[i][l] : closedForm[i][l]));
    }
  }
  for (int i = 0; i < kEven; ++i)
  {
    fromLanes(out[i], k[i]);
  }
}

/// up(p) = no + p + |p|^2/2 ni (ConformalVector::point).
template <typename T>
BOOSTED_CORE_INLINE void upPoint(const T* p, T* x)
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
BOOSTED_CORE_INLINE void contract(const T* v, const T* b, T* y)
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
BOOSTED_CORE_INLINE void sandwichScalarBivector(const T& c, const T* b, const T* x, T* r)
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

/// <K X ~K>_1 for a full even K (detail::pack order) as two sparse products: the odd element
/// K X, then only the grade-1 part of (K X) ~K.
template <typename T>
void sandwichEven(const detail::BoostTables& tables, const T* k, const T* x, T* r)
{
  T reversed[kEven], odd[kOdd];
  for (int s = 0; s < kEven; ++s)
  {
    reversed[s] = (s >= 1 && s <= kBivector) ? -1.0 * k[s] : k[s];
  }
  detail::applyTerms(tables.evenTimesVector, kOdd, k, x, odd);
  detail::applyTerms(tables.oddTimesEvenToVector, kVector, odd, reversed, r);
}

/// fn(r): the Euclidean point r_e / r_no, and whether it is mapped (normalizePoint: the weight is
/// non-zero, the point and p are finite).
template <typename T>
BOOSTED_CORE_INLINE void normalize(const T* p, const T* r, T* image, bool* mapped)
{
  const T alpha = r[NO];
  for (int i = 0; i < 3; ++i)
  {
    image[i] = r[E1 + i] / alpha;
  }
  const LaneArray<T> a(alpha), x(image[0]), y(image[1]), z(image[2]);
  const LaneArray<T> px(p[0]), py(p[1]), pz(p[2]);
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    mapped[l] = a.v[l] != 0.0 && __builtin_isfinite(a.v[l]) && __builtin_isfinite(x.v[l]) &&
      __builtin_isfinite(y.v[l]) && __builtin_isfinite(z.v[l]) && __builtin_isfinite(px.v[l]) &&
      __builtin_isfinite(py.v[l]) && __builtin_isfinite(pz.v[l]);
  }
}

/// The map p -> fn(<K up(p) ~K>_1), K = exp(b) by the rule of args, on every lane, for a given
/// bivector b (overwritten): mapPoint after its B(p), for callers with their own exponent per point
/// (kernel::MapBlockBy; the curvature patch, the generator tree's B(p)).
template <typename T>
void mapPointBy(const kernel::FieldArgs& args, T* b, const T* p, T* image, bool* mapped)
{
  T x[kVector], r[kVector];
  upPoint(p, x);
  if (!args.exactRule)
  {
    T c;
    paperExponential(b, c, true);
    sandwichScalarBivector(c, b, x, r);
  }
  else
  {
    T k[kEven];
    exactExponential(*args.tables, b, true, k);
    sandwichEven(*args.tables, k, x, r);
  }
  normalize(p, r, image, mapped);
}

/// The map p -> fn(<K up(p) ~K>_1), K = exp(-strength B(p)) by the rule of args, on every lane.
template <typename T>
void mapPoint(const kernel::FieldArgs& args, const T* p, T* image, bool* mapped)
{
  T b[kBivector];
  fieldBivector(args, p, -args.strength, b);
  mapPointBy(args, b, p, image, mapped);
}
} // namespace
} // namespace core
} // namespace cga
