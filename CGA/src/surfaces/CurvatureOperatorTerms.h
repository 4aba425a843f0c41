// Internal: the curvature operators of CurvatureOperators.h (eq 15-18, 21-22, 24-26) and the
// curvature patch's choice among them, written once as templates over the number type T of the
// patch coordinates (a, b): double for the values (CurvatureOperators.cpp, CurvaturePatch.cpp),
// LaneClones.h's Eight for eight samples at once (CurvaturePatch.cpp's control point sums), and
// Eight's second-order dual numbers (SurfaceJetDual.h) for their derivatives in (a, b)
// (CurvaturePatchJet.cpp), and double's for one sample (the tests' reference of the lanes). Every
// operator is a sum of w_i(a, b) tau(x_i(a, b), d_i), the null point pair's closed form from
// NullPointPairTerms.h. The operations keep one order for every T (the core has no fused
// multiply-add), so a jet's value is the double result bit for bit.
#pragma once

#include "cga/surfaces/CurvaturePatch.h"

#include "../DualNumber.h"
#include "../ForceInline.h"
#include "../LaneClones.h"
#include "../NullPointPairTerms.h"

#include <array>
#include <optional>
#include <type_traits>

namespace cga
{
namespace detail
{
namespace // internal linkage: no calls through the shared library's symbol table (PLT)
{
/// A point whose coordinates are numbers of type T.
template <typename T>
using PointOf = std::array<T, 3>;

/// An exponent and a curvature generator on T: Bivector and CurvatureGenerator for double.
template <typename T>
struct CurvatureNumbers
{
  using Exponent = std::array<T, Bivector::Count>;
  struct Generator
  {
    Exponent exponent{};
    T weight{};
  };
};
template <>
struct CurvatureNumbers<double>
{
  using Exponent = Bivector;
  using Generator = CurvatureGenerator;
};
template <typename T>
using ExponentOf = typename CurvatureNumbers<T>::Exponent;
template <typename T>
using GeneratorOf = typename CurvatureNumbers<T>::Generator;

/// The number x as a T without tangents (a dual number has its value in v, its tangents in d).
template <typename T>
struct Constant
{
  static T of(double x)
  {
    T r{};
    r.v = Constant<decltype(r.v)>::of(x);
    return r;
  }
};
template <>
struct Constant<double>
{
  static double of(double x) { return x; }
};
template <>
struct Constant<Eight>
{
  // A template: compiled only where used (files built with -Wno-psabi; see LaneClones.h).
  template <typename D>
  static BOOSTED_LANE_INLINE Eight of(D x)
  {
    return Eight{} + x;
  }
};

/// Whether T holds eight samples, one per lane: Eight or a dual number over it.
template <typename T>
struct OnLanes : std::false_type
{
};
template <>
struct OnLanes<Eight> : std::true_type
{
};
template <typename T, int N>
struct OnLanes<core::Dual<T, N>> : OnLanes<T>
{
};

/// PatchFrame::at(a, b) = origin + a u + b v, on the number types of a and b.
template <typename A, typename B>
BOOSTED_FORCE_INLINE auto patchPoint(const PatchFrame& frame, const A& a, const B& b)
{
  using T = decltype(frame.origin.x + a * frame.u.x + b * frame.v.x);
  return PointOf<T>{ frame.origin.x + a * frame.u.x + b * frame.v.x,
    frame.origin.y + a * frame.u.y + b * frame.v.y, frame.origin.z + a * frame.u.z + b * frame.v.z };
}

template <typename T>
BOOSTED_FORCE_INLINE PointOf<T> pointOf(Vec3 p)
{
  return { p.x, p.y, p.z };
}

template <typename T>
BOOSTED_FORCE_INLINE PointOf<T> difference(const PointOf<T>& p, Vec3 x)
{
  return { p[0] - x.x, p[1] - x.y, p[2] - x.z };
}

/// dot(q, v) and norm2(q) of Vec3.h, in their order of operations.
template <typename T>
BOOSTED_FORCE_INLINE T dotProduct(const PointOf<T>& q, Vec3 v)
{
  return q[0] * v.x + q[1] * v.y + q[2] * v.z;
}
template <typename T>
BOOSTED_FORCE_INLINE T squaredLength(const PointOf<T>& q)
{
  return q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
}

/// The exponent e times s (Bivector's e * s).
template <typename T, typename S>
BOOSTED_FORCE_INLINE auto scaled(const ExponentOf<T>& e, const S& s)
{
  ExponentOf<decltype(e[0] * s)> r{};
  for (int c = 0; c < Bivector::Count; ++c)
  {
    r[c] = e[c] * s;
  }
  return r;
}

/// tau(x, v) with its location on T (nullPointPairCompact).
template <typename T>
BOOSTED_FORCE_INLINE ExponentOf<T> nullPointPair(const PointOf<T>& x, Vec3 v)
{
  ExponentOf<T> tau{};
  addNullPointPair(tau, 1.0, x.data(), v);
  return tau;
}

/// The exponent -w pair of a generator of weight w, exactly zero where w is zero: tau of a
/// far-away location may not be finite (0 * inf).
BOOSTED_FORCE_INLINE Bivector exponentOfWeight(const Bivector& pair, double w)
{
  Bivector term{};
  if (w != 0.0)
  {
    term = scaled<double>(pair, -w);
  }
  return term;
}

/// Per lane, where x and all its tangents are zero (x of Eight, double or their jets).
template <typename T>
BOOSTED_LANE_INLINE auto zeroWithTangents(const T& x)
{
  return core::equalTo(x, T{});
}
template <typename T, int N>
BOOSTED_LANE_INLINE auto zeroWithTangents(const core::Dual<T, N>& x)
{
  auto zero = zeroWithTangents(x.v);
  for (const T& d : x.d)
  {
    zero = core::maskAnd(zero, zeroWithTangents(d));
  }
  return zero;
}

/// exponentOfWeight for eight samples at once (Eight: CurvaturePatch.cpp's
/// controlPointGenerators; its jets: CurvaturePatchJet.cpp's generatorJets) and for the jets of
/// one sample (the tests' scalar reference of generatorJets), each lane as for one sample: zero
/// where w and its tangents are. Where only w's value is zero (two terms that cancel at p but not
/// nearby), the value is +0 as for double and the tangents are -w pair's.
template <typename T, std::enable_if_t<OnLanes<T>::value || core::kHasTangents<T>, int> = 0>
BOOSTED_LANE_INLINE ExponentOf<T> exponentOfWeight(const Bivector& pair, const T& w)
{
  const auto zero = zeroWithTangents(w);
  const auto zeroValue = core::equalTo(w, T{}); // a dual number compares its value
  ExponentOf<T> term = scaled<double>(pair, -w);
  for (int c = 0; c < Bivector::Count; ++c)
  {
    term[c] = core::zeroValue(zeroValue, core::select(zero, T{}, term[c]));
  }
  return term;
}

/// osculatingTerm's kappa / (sphere^2 + plane^2 + epsilon) of q = p - x, given |q|^2, q.n and the
/// normal of the osculating circle's plane (along x n); zero for a flat direction.
template <typename T>
BOOSTED_FORCE_INLINE T osculatingWeight(
  const PointOf<T>& q, const T& q2, const T& qn, Vec3 planeNormal, double kappa, double epsilon)
{
  if (kappa == 0.0)
  {
    return T{};
  }
  // Written in q, where the r^2 of |p - center|^2 - r^2 cancels exactly: for |kappa| below ~1e-154
  // r^2 overflows and the direct form gives inf - inf = NaN instead of a weight near 0.
  const T sphere = 0.5 * q2 + qn / kappa;
  const T plane = dotProduct(q, planeNormal) / kappa;
  return kappa / (sphere * sphere + plane * plane + epsilon);
}

/// Eq 15 (bentLine).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> bentLineOf(const PatchFrame& frame, double kappa, const T& b)
{
  const double weight = 0.5 * kappa;
  GeneratorOf<T> g;
  g.weight = Constant<T>::of(weight);
  g.exponent = scaled<T>(nullPointPair(patchPoint(frame, 0.0, b), frame.normal), -weight);
  return g;
}

/// Eq 16 (translatedTangents).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> translatedTangentsOf(
  const PatchFrame& frame, double kappaU, double kappaV, const T& a, const T& b)
{
  GeneratorOf<T> g;
  addNullPointPair(g.exponent, -0.5 * kappaU, patchPoint(frame, 0.0, b).data(), frame.normal);
  addNullPointPair(g.exponent, -0.5 * kappaV, patchPoint(frame, a, 0.0).data(), frame.normal);
  g.weight = Constant<T>::of(0.5 * (kappaU + kappaV));
  return g;
}

/// Eq 17-18 (osculatingCircles).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> osculatingCirclesOf(const CurvatureControlPoint& c, const PointOf<T>& p, double epsilon)
{
  const PointOf<T> q = difference(p, c.location);
  const T q2 = squaredLength(q), qn = dotProduct(q, c.normal);
  GeneratorOf<T> g;
  g.weight = osculatingWeight(q, q2, qn, cross(c.uDirection, c.normal), c.kappaU, epsilon) +
    osculatingWeight(q, q2, qn, cross(cross(c.normal, c.uDirection), c.normal), c.kappaV, epsilon);
  g.exponent = exponentOfWeight(nullPointPair(pointOf<double>(c.location), c.normal), g.weight);
  return g;
}

/// Eq 21-22 (ControlPointSum::at): osculatingCirclesOf's terms with the prepared pieces, each
/// divided by k |p - x_i|^2 + eps. PointPairField does not fit here: its generator weights are
/// fixed, while W_i depends on p through the osculating circle distances as well as through
/// |p - x_i|.
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> controlPointSumOf(const ControlPointSum& sum, const PointOf<T>& p)
{
  GeneratorOf<T> g;
  for (const ControlPointSum::Prepared& prepared : sum.prepared())
  {
    const CurvatureControlPoint& c = prepared.point;
    const PointOf<T> q = difference(p, c.location);
    const T q2 = squaredLength(q), qn = dotProduct(q, c.normal);
    const T weight = osculatingWeight(q, q2, qn, prepared.planeNormalU, c.kappaU, sum.epsilon()) +
      osculatingWeight(q, q2, qn, prepared.planeNormalV, c.kappaV, sum.epsilon());
    const ExponentOf<T> exponent = exponentOfWeight(prepared.pair, weight);
    // eq 22: d_p^2 = -2 up(p).up(x) = |p - x|^2
    const T scale = 1.0 / (sum.falloff() * q2 + sum.epsilon());
    g.weight = g.weight + weight * scale;
    for (int k = 0; k < Bivector::Count; ++k)
    {
      g.exponent[k] = g.exponent[k] + exponent[k] * scale;
    }
  }
  return g;
}

/// Eq 24 (linearInterpolation).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> linearInterpolationOf(const PointOf<T>& x1, const CornerGenerator& g1,
  const PointOf<T>& x2, const CornerGenerator& g2, const T& t)
{
  GeneratorOf<T> g;
  addNullPointPair(g.exponent, -0.5 * (1.0 - t) * g1.weight, x1.data(), g1.direction);
  addNullPointPair(g.exponent, -0.5 * t * g2.weight, x2.data(), g2.direction);
  g.weight =
    0.5 * ((1.0 - t) * g1.weight * norm(g1.direction) + t * g2.weight * norm(g2.direction));
  return g;
}

/// Eq 25-26's pieces that do not depend on (s, t): each corner's tau terms and direction length,
/// computed once for a whole grid (CurvaturePatch::mapRow) instead of at every sample.
struct BilinearCorners
{
  NullPointPairTerms<double> terms[4];
  double weights[4], lengths[4];

  BilinearCorners(const Vec3 x[4], const CornerGenerator g[4])
  {
    for (int i = 0; i < 4; ++i)
    {
      const double location[3] = { x[i].x, x[i].y, x[i].z };
      terms[i] = nullPointPairTerms(location, g[i].direction);
      weights[i] = g[i].weight;
      lengths[i] = norm(g[i].direction);
    }
  }
};

/// Eq 25-26 (bilinearInterpolation).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> bilinearInterpolationOf(
  const BilinearCorners& corners, const T& s, const T& t)
{
  const T factors[4] = { (1.0 - s) * (1.0 - t), (1.0 - s) * t, s * (1.0 - t), s * t };
  GeneratorOf<T> result;
  for (int i = 0; i < 4; ++i)
  {
    result.weight = result.weight + 0.5 * factors[i] * corners.weights[i] * corners.lengths[i];
  }
  for (int i = 0; i < 4; ++i)
  {
    addNullPointPairTerms(result.exponent, -0.5 * factors[i] * corners.weights[i], corners.terms[i]);
  }
  return result;
}

/// The moved patch's corner locations (cornerLocations() of the patch moved by -shift).
inline BilinearCorners bilinearCornersOf(const CurvaturePatch& patch, Vec3 shift)
{
  PatchFrame moved = patch.frame;
  moved.origin = patch.frame.origin - shift;
  const double hu = 0.5 * patch.sizeU, hv = 0.5 * patch.sizeV;
  const Vec3 x[4] = { moved.at(-hu, -hv), moved.at(hu, -hv), moved.at(-hu, hv), moved.at(hu, hv) };
  return BilinearCorners(x, patch.corners.data());
}

/// The Bilinear method's (s, t) of the patch point (a, b).
template <typename T>
BOOSTED_FORCE_INLINE T bilinearS(const CurvaturePatch& patch, const T& b)
{
  return patch.sizeV > 0.0 ? 0.5 + b / patch.sizeV : T{};
}
template <typename T>
BOOSTED_FORCE_INLINE T bilinearT(const CurvaturePatch& patch, const T& a)
{
  return 0.5 + a / patch.sizeU;
}

/// The pieces of the patch's E(a, b) that do not depend on (a, b), of the patch moved by -shift:
/// the moved frame, the control points' prepared terms (ControlPoints) and the corners' tau terms
/// (Bilinear), computed once for many samples (CurvaturePatch::mapRow, derivativesRow) instead of
/// at every sample.
struct PatchPieces
{
  PatchFrame moved;
  std::optional<ControlPointSum> controlPointSum;
  std::optional<BilinearCorners> corners;

  PatchPieces(const CurvaturePatch& patch, Vec3 shift)
    : moved(patch.frame)
  {
    moved.origin = patch.frame.origin - shift;
    if (patch.method == CurvatureMethod::ControlPoints)
    {
      controlPointSum.emplace(patch.controlPoints.data(), patch.controlPoints.size(),
        patch.falloff, patch.epsilon, shift);
    }
    if (patch.method == CurvatureMethod::Bilinear)
    {
      corners.emplace(bilinearCornersOf(patch, shift));
    }
  }
};

/// The patch's E(a, b) and local weight by its method, of the patch moved by -shift, given that
/// shift's pieces.
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> patchGeneratorOf(
  const CurvaturePatch& patch, const PatchPieces& pieces, const T& a, const T& b)
{
  const PatchFrame& moved = pieces.moved;
  switch (patch.method)
  {
    case CurvatureMethod::BentLine:
      return bentLineOf(moved, patch.kappaU, b);
    case CurvatureMethod::TranslatedTangents:
      return translatedTangentsOf(moved, patch.kappaU, patch.kappaV, a, b);
    case CurvatureMethod::OsculatingCircles:
    {
      const CurvatureControlPoint c{ moved.origin, moved.normal, moved.u, patch.kappaU,
        patch.kappaV };
      return osculatingCirclesOf(c, patchPoint(moved, a, b), patch.epsilon);
    }
    case CurvatureMethod::ControlPoints:
      return controlPointSumOf(*pieces.controlPointSum, patchPoint(moved, a, b));
    case CurvatureMethod::Linear:
    {
      // each row carries the two generators along (x_i + b v): every row is the same curve
      const double hu = 0.5 * patch.sizeU;
      const T t = 0.5 + a / patch.sizeU;
      return linearInterpolationOf(patchPoint(moved, -hu, b), patch.corners[0],
        patchPoint(moved, hu, b), patch.corners[1], t);
    }
    case CurvatureMethod::Bilinear:
      return bilinearInterpolationOf(*pieces.corners, bilinearS(patch, b), bilinearT(patch, a));
  }
  return {};
}

/// The patch's E(a, b) and local weight by its method, of the patch moved by -shift
/// (CurvaturePatch::generatorAt for shift 0).
template <typename T>
BOOSTED_FORCE_INLINE GeneratorOf<T> patchGeneratorOf(const CurvaturePatch& patch, const T& a, const T& b, Vec3 shift)
{
  return patchGeneratorOf(patch, PatchPieces(patch, shift), a, b);
}
} // namespace
} // namespace detail
} // namespace cga
