// Internal: what the templates of ExponentialScalars.h and PointMapCore.h need of their number type
// T beyond + - * /: the lanes as an array (LaneArray), per-lane masks and selection, and the
// elementary functions sqrt, cosh, sinh, tanh and sincos.
//
// T is double (one lane: PointPairField::map, expExact, ...) or the block kernel's vector of lanes,
// whose overloads PointPairKernelLanes.h defines in its instruction set's namespace (found by
// argument-dependent lookup). Both call the same functions: with SLEEF (BOOSTED_HAVE_SLEEF) its
// deterministic 1-ulp functions (Sleef_cinz_*_u10: no fused multiply-add, the same bits on every
// instruction set and in the scalar build, "purec"), else libm per lane.
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include <math.h>

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

/// One flag per lane.
template <typename T>
struct Mask
{
  bool v[kLanesOf<T>];

  bool any() const
  {
    bool r = false;
    for (int l = 0; l < kLanesOf<T>; ++l)
    {
      r = r || v[l];
    }
    return r;
  }
  bool all() const
  {
    bool r = true;
    for (int l = 0; l < kLanesOf<T>; ++l)
    {
      r = r && v[l];
    }
    return r;
  }
};

/// The lanes where predicate(x) holds.
template <typename T, typename Predicate>
inline Mask<T> lanesWhere(const T& x, Predicate predicate)
{
  const LaneArray<T> a(x);
  Mask<T> m;
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    m.v[l] = predicate(a.v[l]);
  }
  return m;
}

template <typename T>
inline Mask<T> operator&&(const Mask<T>& a, const Mask<T>& b)
{
  Mask<T> m;
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    m.v[l] = a.v[l] && b.v[l];
  }
  return m;
}

template <typename T>
inline Mask<T> operator!(const Mask<T>& a)
{
  Mask<T> m;
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    m.v[l] = !a.v[l];
  }
  return m;
}

/// a where the mask is set, b elsewhere.
template <typename T>
inline T select(const Mask<T>& mask, const T& a, const T& b)
{
  const LaneArray<T> x(a), y(b);
  LaneArray<T> r;
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    r.v[l] = mask.v[l] ? x.v[l] : y.v[l];
  }
  return r.value();
}

/// |x| on every lane.
template <typename T>
inline T magnitude(const T& x)
{
  LaneArray<T> a(x);
  for (int l = 0; l < kLanesOf<T>; ++l)
  {
    a.v[l] = __builtin_fabs(a.v[l]);
  }
  return a.value();
}

// The elementary functions for one lane: the same as every lane of the block kernel computes.
inline double laneSqrt(double x)
{
  return __builtin_sqrt(x); // correctly rounded, as the vector instructions
}

#ifdef BOOSTED_HAVE_SLEEF
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
