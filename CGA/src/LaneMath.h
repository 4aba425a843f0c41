// Internal: what the templates of ExponentialScalars.h and PointMapCore.h need of their number type
// T beyond + - * /: the lanes as an array (LaneArray), per-lane masks and selection, the fused
// multiply-add and the elementary functions sqrt, exp, cosh, sinh, tanh and sincos.
//
// T is double (one lane: PointPairField::map, expExact, ...), the block kernel's vector of lanes,
// whose overloads PointPairKernelLanes.h defines in its instruction set's namespace (found by
// argument-dependent lookup), or LaneClones.h's Eight (the curvature patch's eight samples and
// their jets: its masks only, below). The first two call the same elementary functions: with SLEEF
// (BOOSTED_HAVE_SLEEF) its deterministic 1-ulp functions (Sleef_cinz_*_u10: no fused multiply-add,
// the same bits on every instruction set and in the scalar build, "purec"), else libm per lane.
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "ForceInline.h"
#include "LaneClones.h"

#include <math.h>
#include <type_traits>

#ifdef BOOSTED_HAVE_SLEEF
#include <sleef.h>
#endif

namespace cga
{
namespace core
{
namespace
{
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

/// One flag per lane: bool for double, the lane vector's own mask type (T::Mask) otherwise. The
/// comparisons, selection and mask logic below have overloads for the lane vector
/// (PointPairKernelLanes.h) that compile to vector compares and blends.
template <typename T>
struct MaskOf
{
  using type = typename T::Mask;
};
template <>
struct MaskOf<double>
{
  using type = bool;
};
template <typename T>
using Mask = typename MaskOf<T>::type;

inline bool lessThan(double a, double b)
{
  return a < b;
}
inline bool lessEqual(double a, double b)
{
  return a <= b;
}
inline bool equalTo(double a, double b)
{
  return a == b;
}
inline bool maskAnd(bool a, bool b)
{
  return a && b;
}
inline bool maskOr(bool a, bool b)
{
  return a || b;
}
inline bool maskNot(bool a)
{
  return !a;
}
inline bool anyLane(bool a)
{
  return a;
}
inline bool allLanes(bool a)
{
  return a;
}
/// a where the mask is set, b elsewhere.
inline double select(bool mask, double a, double b)
{
  return mask ? a : b;
}
// LaneClones.h's Eight: eight lanes, the mask of its comparisons, and the mask logic the curvature
// patch's jets use. Eight is a builtin vector type (no namespace for argument-dependent lookup), so
// its overloads are declared here, before DualNumber.h's templates that call them; templates, so
// that only the files that use them (built with -Wno-psabi, see LaneClones.h) declare functions
// passing 64-byte vectors.
template <>
constexpr int kLanesOf<detail::Eight> = 8;
template <>
struct MaskOf<detail::Eight>
{
  using type = detail::EightMask;
};
template <typename V>
using IfEight = std::enable_if_t<std::is_same<V, detail::Eight>::value, int>;
template <typename M>
using IfEightMask = std::enable_if_t<std::is_same<M, detail::EightMask>::value, int>;
template <typename V, IfEight<V> = 0>
BOOSTED_LANE_INLINE detail::EightMask equalTo(V a, V b)
{
  return a == b;
}
template <typename M, IfEightMask<M> = 0>
BOOSTED_LANE_INLINE M maskAnd(M a, M b)
{
  return a & b;
}
template <typename V, IfEight<V> = 0>
BOOSTED_LANE_INLINE V select(detail::EightMask mask, V a, V b)
{
  return mask ? a : b;
}

/// |x| (the sign bit cleared, as the lane vector's).
inline double magnitude(double x)
{
  return __builtin_fabs(x);
}

/// The value of a number (a Dual's without its tangents: DualNumber.h; the lane vector's is itself).
inline double valueOf(double x)
{
  return x;
}

/// The power of two 2^e with 2^e <= x < 2^(e+1) for a normal x > 0 (its exponent bits alone),
/// 2^-1022 for a subnormal x. (Infinite and NaN x give infinity: callers select them away.)
inline double binaryFloor(double x)
{
  unsigned long long bits;
  __builtin_memcpy(&bits, &x, sizeof bits);
  bits &= 0x7ff0000000000000ULL;
  bits = bits == 0 ? 0x0010000000000000ULL : bits;
  double r;
  __builtin_memcpy(&r, &bits, sizeof r);
  return r;
}

/// The exponent field of x less its bias, as a number: e with 2^e <= |x| < 2^(e+1) for a normal x,
/// -1023 for a subnormal x or 0.
inline double binaryExponentOf(double x)
{
  unsigned long long bits;
  __builtin_memcpy(&bits, &x, sizeof bits);
  return static_cast<double>(static_cast<int>((bits >> 52) & 0x7ff) - 1023);
}

/// 2^k for an integral k with |k| <= 1022, exactly.
inline double powerOfTwoOf(double k)
{
  const unsigned long long bits = static_cast<unsigned long long>(static_cast<int>(k) + 1023) << 52;
  double r;
  __builtin_memcpy(&r, &bits, sizeof r);
  return r;
}

/// The unit in the last place of 1 of a number type's values (double's, the lanes' and a Dual's:
/// 2^-52), against which PointMapCore.h tells rounding from a value; DoubleDouble.h has its own.
template <typename T>
struct RoundingUnit
{
  static constexpr double value = 0x1p-52;
};

/// A number type's value c on every lane.
template <typename T>
inline T splat(double c)
{
  return T{} + c;
}

/// a b + c rounded once (fused multiply-add): correctly rounded, so every instruction set gives the
/// same bits, as the lane vector's (PointPairKernelLanes.h). Where the compiler may not assume the
/// instruction (the baseline build) this is a call to libm's fma, which glibc resolves to the
/// instruction on a CPU that has it and to an exact software fma otherwise (about 1.5 ns a call:
/// hence PointPairField::map takes its B(p) from the kernel, kernel::activeFieldBivector).
inline double fusedMultiplyAdd(double a, double b, double c)
{
  return __builtin_fma(a, b, c);
}

/// sin and cos of r + quadrant pi/2 (quadrant 0 to 3) from sin r and cos r: the last step of a
/// reduction by pi/2 (DoubleDouble.h's laneSinCos, ReducedSinCos.h's long double one).
template <typename T>
inline void sinCosOfQuadrant(int quadrant, const T& sr, const T& cr, T& s, T& c)
{
  s = quadrant == 0 ? sr : quadrant == 1 ? cr : quadrant == 2 ? -sr : -cr;
  c = quadrant == 0 ? cr : quadrant == 1 ? -sr : quadrant == 2 ? -cr : sr;
}

// The elementary functions for one lane: the same as every lane of the block kernel computes.
inline double laneSqrt(double x)
{
  return __builtin_sqrt(x); // correctly rounded, as the vector instructions
}

#ifdef BOOSTED_HAVE_SLEEF
inline double laneExp(double x)
{
  return Sleef_cinz_expd1_u10purec(x);
}
inline double laneCosh(double x)
{
  return Sleef_cinz_coshd1_u10purec(x);
}
inline double laneSinh(double x)
{
  return Sleef_cinz_sinhd1_u10purec(x);
}
inline double laneTanh(double x)
{
  return Sleef_cinz_tanhd1_u10purec(x);
}
inline void laneSinCos(double x, double& s, double& c)
{
  const auto r = Sleef_cinz_sincosd1_u10purec(x);
  s = r.x;
  c = r.y;
}
#else
inline double laneExp(double x)
{
  return exp(x);
}
inline double laneCosh(double x)
{
  return cosh(x);
}
inline double laneSinh(double x)
{
  return sinh(x);
}
inline double laneTanh(double x)
{
  return tanh(x);
}
inline void laneSinCos(double x, double& s, double& c)
{
  s = sin(x);
  c = cos(x);
}
#endif
} // namespace
} // namespace core
} // namespace cga
