// Internal: the image of a point under a loxodromic conformal map (exp of a bivector with a strong
// hyperbolic plane beside an elliptic one and a transversion part) written relative to its two
// fixed points, in Euclidean 3-vectors only (docs/conventions.md section 2 item 12, *A strong plane
// beside point pairs*). Templates over the number type T of PointMapCore.h, which calls them.
//
// The map M fixes the attractor a and the repeller r. In the frame psi(p) = inv(p - r) - inv(a - r)
// (inv(z) = z/|z|^2: r goes to infinity, a to 0) it is linear, y -> S L S y, with L = DM(a) =
// e^{-2 alpha} Q the map's derivative at a (Q a rotation) and S the reflection in the plane
// orthogonal to a - r (the derivative of inv at a - r, up to scale). Back: p' = a + inv(w + y) -
// inv(w), w = inv(a - r) (= r + inv(w + y)). Every difference of two inverses is formed without
// cancelling large terms (inverseDifference), so each step is accurate relative to the point's
// distance from the fixed point it approaches, and the factor e^{-2 alpha} multiplies only such
// a relative quantity: nothing the factor scales carries the rounding of a split of B.
//
// Everything has internal linkage (an unnamed namespace), as in PointMapCore.h.
#pragma once

#include "DualNumber.h"
#include "ExponentialScalars.h"
#include "LaneMath.h"

namespace cga
{
namespace core
{
namespace
{
template <typename T>
BOOSTED_FORCE_INLINE T dot3(const T* x, const T* y)
{
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

template <typename T>
BOOSTED_FORCE_INLINE void cross3(const T* x, const T* y, T* out)
{
  const T c0 = x[1] * y[2] - x[2] * y[1], c1 = x[2] * y[0] - x[0] * y[2], c2 = x[0] * y[1] - x[1] * y[0];
  out[0] = c0;
  out[1] = c1;
  out[2] = c2;
}

/// The power of two s with s <= max |x_i| < 2s where that is a normal positive number, 1 elsewhere
/// (a zero or non-finite x: the caller selects such lanes away).
template <typename T>
BOOSTED_FORCE_INLINE ValueOf<T> vectorScale(const T* x)
{
  using V = ValueOf<T>;
  V largest = magnitude(valueOf(x[0]));
  for (int i = 1; i < 3; ++i)
  {
    const V c = magnitude(valueOf(x[i]));
    largest = select(lessThan(largest, c), c, largest);
  }
  const Mask<V> usable = maskAnd(lessThan(V{}, largest), lessThan(largest, splat<V>(__builtin_inf())));
  return select(usable, binaryFloor(largest), splat<V>(1.0));
}

/// inv(z) = z/|z|^2 (the inversion in the unit sphere), formed from z scaled by a power of two so
/// that |z|^2 neither overflows nor underflows.
template <typename T>
BOOSTED_FORCE_INLINE void inverted(const T* z, T* out)
{
  using V = ValueOf<T>;
  const V s = vectorScale(z);
  const T down = asNumber<T>(1.0 / s), scale = asNumber<T>(s);
  const T scaled[3] = { z[0] * down, z[1] * down, z[2] * down };
  const T denominator = dot3(scaled, scaled) * scale;
  for (int i = 0; i < 3; ++i)
  {
    out[i] = scaled[i] / denominator;
  }
}

/// inv(w + y) - inv(w) for |y| <= |w|/2 (sum = w + y given), as
/// (y |w|^2 - w (y . (sum + w))) / (|sum|^2 |w|^2): every term is proportional to y, and their sum
/// is at least a seventh of the largest (|sum| >= |w|/2), so the difference is accurate relative to
/// itself where the two inverses nearly cancel. Scaled by the power of two of w.
template <typename T>
BOOSTED_FORCE_INLINE void inverseDifference(const T* w, const T* y, const T* sum, T* out)
{
  using V = ValueOf<T>;
  const V s = vectorScale(w);
  const T down = asNumber<T>(1.0 / s);
  T ws[3], ys[3], sums[3], both[3];
  for (int i = 0; i < 3; ++i)
  {
    ws[i] = w[i] * down;
    ys[i] = y[i] * down;
    sums[i] = sum[i] * down;
    both[i] = sums[i] + ws[i];
  }
  const T w2 = dot3(ws, ws);
  const T projection = dot3(ys, both);
  const T denominator = (dot3(sums, sums) * w2) * asNumber<T>(s);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = (ys[i] * w2 - ws[i] * projection) / denominator;
  }
}

/// Whether |y| <= |w|/2 per lane (inverseDifference's range).
template <typename T>
BOOSTED_FORCE_INLINE Mask<ValueOf<T>> withinHalf(const T* w, const T* y)
{
  using V = ValueOf<T>;
  const V s = vectorScale(w);
  const V down = 1.0 / s;
  V ws[3], ys[3];
  for (int i = 0; i < 3; ++i)
  {
    ws[i] = valueOf(w[i]) * down;
    ys[i] = valueOf(y[i]) * down;
  }
  return lessEqual(4.0 * dot3(ys, ys), dot3(ws, ws));
}

/// inv(w + y) - inv(w) (sum = w + y given): inverseDifference where |y| <= |w|/2, the two inverses
/// apart elsewhere (there their difference is at least a fifth of the larger).
template <typename T>
BOOSTED_FORCE_INLINE void differenceOfInverses(const T* w, const T* y, const T* sum, T* out)
{
  T near[3], first[3], second[3];
  inverseDifference(w, y, sum, near);
  inverted(sum, first);
  inverted(w, second);
  const auto close = withinHalf(w, y);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = select(close, near[i], first[i] - second[i]);
  }
}

/// B = E + A_i e_i^no + C_i e_i^ni + d no^ni moved to x: its rate d' = x.A + d and the normal of its
/// turn, n = n_E + x x A (n_E = (E23, -E13, E12)). The derivative of B's Euclidean field at x is
/// -d' I + [n]_x, and at a fixed point x exp(B) has the derivative e^{2 d'} exp(-2 [n]_x).
template <typename T>
BOOSTED_FORCE_INLINE T rateAndNormalAt(const T* nE, const T* a, const T& d, const T* x, T* n)
{
  T xa[3];
  cross3(x, a, xa);
  for (int i = 0; i < 3; ++i)
  {
    n[i] = nE[i] + xa[i];
  }
  return dot3(x, a) + d;
}

/// The Euclidean field v(x) = y_E - y_no x of y = up(x) _| B: v(x) = n_E x x + |x|^2/2 A + C - d' x
/// with d' = x.A + d (rateAndNormalAt). Its zeros are the fixed points of exp(B); it is linear in B.
template <typename T>
BOOSTED_FORCE_INLINE void euclideanField(const T* nE, const T* a, const T* c, const T& rate, const T* x, T* v)
{
  T turn[3];
  cross3(nE, x, turn);
  const T half = 0.5 * dot3(x, x);
  for (int i = 0; i < 3; ++i)
  {
    v[i] = turn[i] + half * a[i] + c[i] - rate * x[i];
  }
}

/// M^-1 z for M = -rate I + [n]_x (the field's derivative, rateAndNormalAt):
/// (rate^2 z + n (n.z) + rate n x z) / (-rate (rate^2 + |n|^2)).
template <typename T>
BOOSTED_FORCE_INLINE void solveByFieldDerivative(const T& rate, const T* n, const T* z, T* out)
{
  T nz[3];
  cross3(n, z, nz);
  const T rate2 = rate * rate;
  const T nDotZ = dot3(n, z);
  const T denominator = -rate * (rate2 + dot3(n, n));
  for (int i = 0; i < 3; ++i)
  {
    out[i] = (rate2 * z[i] + n[i] * nDotZ + rate * nz[i]) / denominator;
  }
}

/// One Newton step on the zeros of B's Euclidean field: p -= Dv(p)^-1 v(p).
template <typename T>
BOOSTED_FORCE_INLINE void fixedPointNewtonStep(const T* e, const T* a, const T* c, const T& d, T* p)
{
  const T nE[3] = { e[2], -e[1], e[0] };
  T n[3], v[3], step[3];
  const T rate = rateAndNormalAt(nE, a, d, p, n);
  euclideanField(nE, a, c, rate, p, v);
  solveByFieldDerivative(rate, n, v, step);
  for (int i = 0; i < 3; ++i)
  {
    p[i] = p[i] - step[i];
  }
}

/// x rotated by exp([omega]_x) (Rodrigues: x + sinc(t) omega x x + sinc(t/2)^2/2 omega x (omega x x),
/// t = |omega|; no cancellation for small t).
template <typename T>
BOOSTED_FORCE_INLINE void rotatedBy(const T* omega, const T* x, T* out)
{
  const T t = laneSqrt(dot3(omega, omega));
  const T halfSinc = detail::sinc(0.5 * t);
  const T first = detail::sinc(t), second = 0.5 * halfSinc * halfSinc;
  T ox[3], oox[3];
  cross3(omega, x, ox);
  cross3(omega, ox, oox);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = x[i] + first * ox[i] + second * oox[i];
  }
}

/// x reflected in the plane orthogonal to the unit vector n.
template <typename T>
BOOSTED_FORCE_INLINE void reflected(const T* n, const T* x, T* out)
{
  const T twice = 2.0 * dot3(n, x);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = x[i] - twice * n[i];
  }
}
} // namespace
} // namespace core
} // namespace cga
