// Compact named types for the hot loops: only the grades a boost needs, stored in the null basis
// (NullBasis.h) in the component order of docs/conventions.md section 5 and of the test vectors' *_null keys.
//
// Each type lists, in kBlades, the null blade index of every component; conversions to and from
// the full Multivector live in CompactConversion.h, products in CompactAlgebra.h.
#pragma once

#include "cga/NullBasis.h"
#include "cga/Vec3.h"

#include <array>
#include <cmath>

namespace cga
{
namespace detail
{
// Component-wise arithmetic shared by the coefficient arrays below.
template <typename Derived, int N>
struct Coefficients
{
  std::array<double, N> c{};

  double& operator[](int i) { return c[i]; }
  double operator[](int i) const { return c[i]; }

  Derived& operator+=(const Derived& o)
  {
    for (int i = 0; i < N; ++i)
    {
      c[i] += o.c[i];
    }
    return static_cast<Derived&>(*this);
  }
  Derived& operator-=(const Derived& o)
  {
    for (int i = 0; i < N; ++i)
    {
      c[i] -= o.c[i];
    }
    return static_cast<Derived&>(*this);
  }
  Derived& operator*=(double s)
  {
    for (double& x : c)
    {
      x *= s;
    }
    return static_cast<Derived&>(*this);
  }

  friend Derived operator+(Derived a, const Derived& b) { return a += b; }
  friend Derived operator-(Derived a, const Derived& b) { return a -= b; }
  friend Derived operator-(Derived a) { return a *= -1.0; }
  friend Derived operator*(Derived a, double s) { return a *= s; }
  friend Derived operator*(double s, Derived a) { return a *= s; }
  friend Derived operator/(Derived a, double s)
  {
    for (double& x : a.c)
    {
      x /= s;
    }
    return a;
  }

  /// Largest absolute coefficient (NaN when a coefficient is NaN).
  double maxAbs() const
  {
    double m = 0.0;
    for (double x : c)
    {
      const double ax = std::fabs(x);
      m = (ax > m || std::isnan(ax)) ? ax : m;
    }
    return m;
  }

  bool isFinite() const
  {
    for (double x : c)
    {
      if (!std::isfinite(x))
      {
        return false;
      }
    }
    return true;
  }
};
} // namespace detail

/// A conformal vector P = a no + x + b ni (the test vectors' Q_null order: no, e1, e2, e3, ni).
struct ConformalVector : detail::Coefficients<ConformalVector, 5>
{
  enum Component
  {
    NO,
    E1,
    E2,
    E3,
    NI,
    Count
  };
  static constexpr std::array<unsigned, Count> kBlades = {
    nullblade::no, nullblade::e1, nullblade::e2, nullblade::e3, nullblade::ni
  };

  /// up(x) = no + x + |x|^2/2 ni.
  static ConformalVector point(Vec3 x)
  {
    ConformalVector p;
    p.c = { 1.0, x.x, x.y, x.z, 0.5 * norm2(x) };
    return p;
  }

  Vec3 euclidean() const { return { c[E1], c[E2], c[E3] }; }

  /// -ni.P, the weight by which fn divides (eq 19-20).
  double weight() const { return c[NO]; }
};

/// A bivector B = sum c_ij e_i^e_j + a_i e_i^no + b_i e_i^ni + d no^ni.
struct Bivector : detail::Coefficients<Bivector, 10>
{
  enum Component
  {
    E12,
    E13,
    E23,
    E1NO,
    E2NO,
    E3NO,
    E1NI,
    E2NI,
    E3NI,
    NONI,
    Count
  };
  static constexpr std::array<unsigned, Count> kBlades = { 3u,  5u,  6u,  9u,  10u,
                                                           12u, 17u, 18u, 20u, nullblade::E };
};

/// A 4-vector, in the order e1^e2^e3^no, e1^e2^e3^ni, e1^e2^no^ni, e1^e3^no^ni, e2^e3^no^ni.
struct Quadvector : detail::Coefficients<Quadvector, 5>
{
  enum Component
  {
    E123NO,
    E123NI,
    E12NONI,
    E13NONI,
    E23NONI,
    Count
  };
  static constexpr std::array<unsigned, Count> kBlades = { 15u, 23u, 27u, 29u, 30u };
};

/// An even element scalar + bivector + 4-vector: rotors, translators, motors, boosts and the
/// paper's (non-versor) exponentials of sums of point pairs.
struct Even
{
  double scalar = 0.0;
  Bivector bivector;
  Quadvector quadvector;

  static constexpr int kCount = 1 + Bivector::Count + Quadvector::Count;

  static Even identity()
  {
    Even k;
    k.scalar = 1.0;
    return k;
  }

  static Even fromBivector(const Bivector& b)
  {
    Even k;
    k.bivector = b;
    return k;
  }

  Even& operator+=(const Even& o)
  {
    scalar += o.scalar;
    bivector += o.bivector;
    quadvector += o.quadvector;
    return *this;
  }
  Even& operator-=(const Even& o)
  {
    scalar -= o.scalar;
    bivector -= o.bivector;
    quadvector -= o.quadvector;
    return *this;
  }
  Even& operator*=(double s)
  {
    scalar *= s;
    bivector *= s;
    quadvector *= s;
    return *this;
  }

  friend Even operator+(Even a, const Even& b) { return a += b; }
  friend Even operator-(Even a, const Even& b) { return a -= b; }
  friend Even operator-(Even a) { return a *= -1.0; }
  friend Even operator*(Even a, double s) { return a *= s; }
  friend Even operator*(double s, Even a) { return a *= s; }
  friend Even operator/(Even a, double s)
  {
    a.scalar /= s;
    a.bivector = a.bivector / s;
    a.quadvector = a.quadvector / s;
    return a;
  }

  double maxAbs() const
  {
    const double a = std::fabs(scalar);
    const double b = bivector.maxAbs();
    const double q = quadvector.maxAbs();
    if (std::isnan(a) || std::isnan(b) || std::isnan(q))
    {
      return a + b + q;
    }
    return std::fmax(a, std::fmax(b, q));
  }

  bool isFinite() const
  {
    return std::isfinite(scalar) && bivector.isFinite() && quadvector.isFinite();
  }
};
} // namespace cga
