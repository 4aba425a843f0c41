// The independent reference of the exponential tests: the 5x5 matrix of the map a bivector
// induces on the vectors of R^{4,1}, and Eigen's matrix exponential of it (in long double).
#pragma once

#include "cga/Conformal.h"
#include "cga/Multivector.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

namespace cgatest
{
using Matrix5 = Eigen::Matrix<double, 5, 5>;

using cga::Multivector;

constexpr unsigned kVectorMasks[5] = { cga::blade::e1, cga::blade::e2, cga::blade::e3,
                                      cga::blade::ep, cga::blade::em };

// The vector map y -> B y - y B in the basis e1, e2, e3, e+, e-: d/dt of exp(tB) y exp(-tB).
inline Matrix5 generator(const Multivector& b)
{
  Matrix5 a;
  for (int j = 0; j < 5; ++j)
  {
    const Multivector ej = Multivector::basisBlade(kVectorMasks[j]);
    const Multivector image = b * ej - ej * b;
    for (int i = 0; i < 5; ++i)
    {
      a(i, j) = image[kVectorMasks[i]];
    }
  }
  return a;
}

// Columns K e_j ~K of the versor K acting on vectors.
inline Matrix5 vectorAction(const Multivector& k)
{
  Matrix5 m;
  for (int j = 0; j < 5; ++j)
  {
    const Multivector image = cga::sandwich(k, Multivector::basisBlade(kVectorMasks[j])).grade(1);
    for (int i = 0; i < 5; ++i)
    {
      m(i, j) = image[kVectorMasks[i]];
    }
  }
  return m;
}

// exp(A) by Eigen's matrix exponential, evaluated in long double: in double, its Pade approximant
// is off by up to ~1e-11 of the result for the non-normal generators of conjugated rotations.
inline Matrix5 matrixExponential(const Matrix5& a)
{
  using MatrixL = Eigen::Matrix<long double, 5, 5>;
  const MatrixL e = a.cast<long double>().exp();
  return e.cast<double>();
}
} // namespace cgatest
