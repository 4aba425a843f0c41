// The full multivector of R^{4,1}: 32 coefficients, every product computed blade by blade.
//
// This is the reference implementation every fast path is tested against. It favours being
// obviously right over being fast: products loop over all non-zero coefficient pairs.
#pragma once

#include "cga/Basis.h"

#include <array>
#include <cmath>
#include <initializer_list>

namespace cga
{
class Multivector
{
public:
  constexpr Multivector() = default;

  static Multivector scalar(double s)
  {
    Multivector m;
    m.c[0] = s;
    return m;
  }

  static Multivector basisBlade(unsigned mask, double coefficient = 1.0)
  {
    Multivector m;
    m.c[mask] = coefficient;
    return m;
  }

  double& operator[](unsigned mask) { return c[mask]; }
  double operator[](unsigned mask) const { return c[mask]; }

  double scalarPart() const { return c[0]; }

  Multivector& operator+=(const Multivector& o)
  {
    for (int i = 0; i < kBladeCount; ++i)
    {
      c[i] += o.c[i];
    }
    return *this;
  }
  Multivector& operator-=(const Multivector& o)
  {
    for (int i = 0; i < kBladeCount; ++i)
    {
      c[i] -= o.c[i];
    }
    return *this;
  }
  Multivector& operator*=(double s)
  {
    for (double& x : c)
    {
      x *= s;
    }
    return *this;
  }

  friend Multivector operator+(Multivector a, const Multivector& b) { return a += b; }
  friend Multivector operator-(Multivector a, const Multivector& b) { return a -= b; }
  friend Multivector operator-(Multivector a) { return a *= -1.0; }
  friend Multivector operator*(Multivector a, double s) { return a *= s; }
  friend Multivector operator*(double s, Multivector a) { return a *= s; }
  friend Multivector operator/(Multivector a, double s) { return a *= 1.0 / s; }

  /// Geometric product.
  friend Multivector operator*(const Multivector& a, const Multivector& b)
  {
    return product(a, b, [](unsigned, unsigned) { return true; });
  }

  /// Outer (wedge) product: blades that share no factor.
  friend Multivector operator^(const Multivector& a, const Multivector& b)
  {
    return product(a, b, [](unsigned x, unsigned y) { return (x & y) == 0; });
  }

  /// Left contraction a ⌋ b: blade x contracts onto y when x's factors are all in y.
  friend Multivector leftContraction(const Multivector& a, const Multivector& b)
  {
    return product(a, b, [](unsigned x, unsigned y) { return (x & ~y) == 0; });
  }

  /// Scalar product <a b>_0.
  friend double scalarProduct(const Multivector& a, const Multivector& b)
  {
    double s = 0.0;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      s += kGeometric.sign[i][i] * a.c[i] * b.c[i];
    }
    return s;
  }

  Multivector reverse() const
  {
    Multivector r;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      r.c[i] = reverseSign(bladeGrade(i)) * c[i];
    }
    return r;
  }

  Multivector involution() const
  {
    Multivector r;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      r.c[i] = involutionSign(bladeGrade(i)) * c[i];
    }
    return r;
  }

  Multivector grade(int k) const
  {
    Multivector r;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      if (bladeGrade(i) == k)
      {
        r.c[i] = c[i];
      }
    }
    return r;
  }

  /// Dual A* = A I^{-1} with I = e1 e2 e3 e+ e- (I^2 = -1, so I^{-1} = -I).
  Multivector dual() const { return *this * basisBlade(blade::pseudoscalar, -1.0); }

  /// Inverse of the dual: A = A* I.
  Multivector undual() const { return *this * basisBlade(blade::pseudoscalar, 1.0); }

  /// Euclidean norm of the coefficient array (metric-free; for tolerances and tests).
  double coefficientNorm() const
  {
    double s = 0.0;
    for (double x : c)
    {
      s += x * x;
    }
    return std::sqrt(s);
  }

  /// Largest absolute coefficient of a grade (or of all grades for k < 0).
  double maxAbs(int k = -1) const
  {
    double m = 0.0;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      if (k < 0 || bladeGrade(i) == k)
      {
        m = std::fmax(m, std::fabs(c[i]));
      }
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

  std::array<double, kBladeCount> c{};

private:
  template <typename Keep>
  static Multivector product(const Multivector& a, const Multivector& b, Keep keep)
  {
    Multivector r;
    for (unsigned i = 0; i < kBladeCount; ++i)
    {
      if (a.c[i] == 0.0)
      {
        continue;
      }
      for (unsigned j = 0; j < kBladeCount; ++j)
      {
        if (b.c[j] != 0.0 && keep(i, j))
        {
          r.c[i ^ j] += kGeometric.sign[i][j] * a.c[i] * b.c[j];
        }
      }
    }
    return r;
  }
};

/// Inner product of two vectors (grade 1 each): the scalar of their geometric product.
inline double dot(const Multivector& a, const Multivector& b)
{
  return scalarProduct(a.grade(1), b.grade(1));
}
} // namespace cga
