// d out / d b for a similarity's bivector with a strong hyperbolic plane (docs/conventions.md
// section 3 item 15, "The derivative by B next to a strong dilation").
//
// About its fixed point x, b = E + C^ni + d no^ni is E + d no^ni: its action A (X -> b X - X b) on
// the basis no, e1, e2, e3, ni is diag(-2d, 2K, 2d) with K u = w x u (w = (-e23, e13, -e12)), whose
// eigenvectors are no (-2d), ni (2d), the axis w/|w| (0) and (f1 -+ i f2)/sqrt2 (+-2i|w|) for f1, f2
// orthonormal across the axis. There the Frechet derivative of exp(A) along E is
// V (F o (V^-1 E V)) V^-1, F_ij = (e^mu_i - e^mu_j)/(mu_i - mu_j), and the image relative to x is
// Y_e / Y_no with Y = exp(A) up(p - x): its derivative (d Y_e - (x' - x) d Y_no) / Y_no, in which
// every e^{+-2d} is combined with 1/Y_no = e^{+-2d} before it is formed (no cancellation, no
// overflow while the image and its derivative are in range).
#include "StrongSimilarityDerivative.h"

#include "DoubleDouble.h"
#include "PointMapCore.h"

#include <cmath>
#include <complex>

namespace cga
{
namespace core
{
namespace
{
using Complex = std::complex<double>;

/// (e^z - 1)/z without cancellation: its Taylor series for |z| < 1/2, else expm1 and the half-angle
/// form of cos - 1.
Complex expm1OverZ(Complex z)
{
  if (std::abs(z) < 0.5)
  {
    Complex sum = 0.0, term = 1.0;
    for (int n = 1; n <= 22; ++n)
    {
      sum += term / static_cast<double>(n); // z^(n-1)/n!
      term *= z / static_cast<double>(n);
    }
    return sum;
  }
  const double x = z.real(), y = z.imag(), s = std::sin(0.5 * y);
  const Complex e(std::expm1(x) * std::cos(y) - 2.0 * s * s, std::exp(x) * std::sin(y));
  return e / z;
}

/// The action X -> b X - X b = -2 X _| b of a bivector on the basis no, e1, e2, e3, ni:
/// a[row][column].
void actionMatrix(const double* b, double a[5][5])
{
  for (int j = 0; j < kVector; ++j)
  {
    double basis[kVector] = {}, y[kVector];
    basis[j] = 1.0;
    contract(basis, b, y);
    for (int i = 0; i < kVector; ++i)
    {
      a[i][j] = -2.0 * y[i];
    }
  }
}

/// x = M^-1 v for M = d I + K, K u = w x u: (d^2 v - d w x v + (w.v) w) / (d (d^2 + |w|^2)).
void solveFixedPoint(double d, const double* w, const double* v, double* x)
{
  const double wv = w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
  const double cross[3] = { w[1] * v[2] - w[2] * v[1], w[2] * v[0] - w[0] * v[2],
    w[0] * v[1] - w[1] * v[0] };
  const double denominator = d * (d * d + (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
  for (int i = 0; i < 3; ++i)
  {
    x[i] = (d * d * v[i] - d * cross[i] + wv * w[i]) / denominator;
  }
}
} // namespace

bool strongSimilarityExponentDerivative(const double* b, const double* p, double* byExponent)
{
  const double d = b[NONI];
  if (b[E1NO] != 0.0 || b[E2NO] != 0.0 || b[E3NO] != 0.0 || !(d != 0.0))
  {
    return false;
  }
  // The fixed point x: M x = C, M = d I + K (translateBivector of E + d no^ni by x), to double-double
  // through one residual: near x the image and its derivative depend on p - x, which a rounded x
  // would move by 2^-53 |x|.
  const double w[3] = { -b[E23], b[E13], -b[E12] };
  const double c[3] = { b[E1NI], b[E2NI], b[E3NI] };
  double xHigh[3], residual[3], xLow[3];
  solveFixedPoint(d, w, c, xHigh);
  const DD mx[3] = { DD(d) * xHigh[0] + DD(b[E12]) * xHigh[1] + DD(b[E13]) * xHigh[2],
    DD(-b[E12]) * xHigh[0] + DD(d) * xHigh[1] + DD(b[E23]) * xHigh[2],
    DD(-b[E13]) * xHigh[0] - DD(b[E23]) * xHigh[1] + DD(d) * xHigh[2] };
  for (int i = 0; i < 3; ++i)
  {
    residual[i] = (DD(c[i]) - mx[i]).hi;
  }
  solveFixedPoint(d, w, residual, xLow);
  double r[3];
  for (int i = 0; i < 3; ++i)
  {
    r[i] = ((DD(p[i]) - xHigh[i]) - xLow[i]).hi;
  }
  // The eigenbasis of the Euclidean block 2K: columns u[m][0] = the axis (0), u[m][1] = w+ (2i theta),
  // u[m][2] = w- (-2i theta).
  const double theta = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  double axis[3] = { 0.0, 0.0, 1.0 };
  if (theta > 0.0)
  {
    for (int i = 0; i < 3; ++i)
    {
      axis[i] = w[i] / theta;
    }
  }
  // f1: the axis crossed with the coordinate axis least along it, normalized; f2 = axis x f1.
  int least = 0;
  for (int i = 1; i < 3; ++i)
  {
    least = std::fabs(axis[i]) < std::fabs(axis[least]) ? i : least;
  }
  double f1[3] = { 0.0, 0.0, 0.0 };
  f1[(least + 1) % 3] = axis[(least + 2) % 3];
  f1[(least + 2) % 3] = -axis[(least + 1) % 3];
  const double f1Length = std::sqrt(f1[0] * f1[0] + f1[1] * f1[1] + f1[2] * f1[2]);
  for (double& f : f1)
  {
    f /= f1Length;
  }
  const double f2[3] = { axis[1] * f1[2] - axis[2] * f1[1], axis[2] * f1[0] - axis[0] * f1[2],
    axis[0] * f1[1] - axis[1] * f1[0] };
  const double half = std::sqrt(0.5);
  Complex u[3][3];
  for (int m = 0; m < 3; ++m)
  {
    u[m][0] = axis[m];
    u[m][1] = Complex(half * f1[m], -half * f2[m]);
    u[m][2] = Complex(half * f1[m], half * f2[m]);
  }
  const Complex mu[3] = { 0.0, Complex(0.0, 2.0 * theta), Complex(0.0, -2.0 * theta) };
  Complex expMu[3];
  for (int i = 0; i < 3; ++i)
  {
    expMu[i] = std::exp(mu[i]);
  }
  // The point's eigen-coordinates (no: 1, ni: |r|^2/2), those of the Euclidean part scaled by
  // e^{2d} where d > 0 (rho = e^{2d} r: the image relative to x before the rotation).
  const bool growing = d > 0.0;
  const double s = 2.0 * std::fabs(d);
  const double grow = std::exp(std::fabs(d)), shrink = std::exp(-s); // e^{|d|}, e^{-2|d|}
  double q[3];
  for (int i = 0; i < 3; ++i)
  {
    q[i] = growing ? (r[i] * grow) * grow : r[i];
  }
  const double halfSquare = 0.5 * (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  Complex qe[3];
  for (int i = 0; i < 3; ++i)
  {
    qe[i] = std::conj(u[0][i]) * q[0] + std::conj(u[1][i]) * q[1] + std::conj(u[2][i]) * q[2];
  }
  // The divided differences, each with its factor of 1/Y_no and of q (see the file's comment):
  // the no column's (p), the Euclidean block's (f), the ni column's (n) and the no row's (o).
  Complex pFactor[3], fFactor[3][3], nFactor[3], oFactor[3];
  for (int i = 0; i < 3; ++i)
  {
    if (growing)
    {
      pFactor[i] = ((grow * expMu[i]) * expm1OverZ(-s - mu[i])) * grow; // e^s one half at a time
      nFactor[i] = expm1OverZ(mu[i] - s);
      oFactor[i] = expMu[i] * expm1OverZ(-s - mu[i]);
    }
    else
    {
      pFactor[i] = expm1OverZ(mu[i] - s);
      nFactor[i] = shrink * expMu[i] * expm1OverZ(-s - mu[i]);
      oFactor[i] = expm1OverZ(mu[i] - s);
    }
    for (int j = 0; j < 3; ++j)
    {
      fFactor[i][j] = (growing ? 1.0 : shrink) * expMu[j] * expm1OverZ(mu[i] - mu[j]);
    }
  }
  const double scale = growing ? 1.0 : shrink; // (x' - x) = scale U (e^mu qe)
  const double shift[3] = { -xHigh[0], -xHigh[1], -xHigh[2] };
  for (int k = 0; k < kBivector; ++k)
  {
    // The seed e_k about x (translateBivector by -x: x's low part moves it by 2^-53 |x| relative).
    double unit[kBivector] = {}, moved[kBivector], a[5][5];
    unit[k] = 1.0;
    translateBivector(unit, shift, moved);
    actionMatrix(moved, a);
    // V^-1 A V in the eigen-coordinates: no, the Euclidean eigenvectors, ni.
    Complex column[3], row[3], block[3][3], niColumn[3];
    for (int i = 0; i < 3; ++i)
    {
      column[i] = row[i] = niColumn[i] = 0.0;
      for (int m = 0; m < 3; ++m)
      {
        column[i] += std::conj(u[m][i]) * a[E1 + m][NO];
        niColumn[i] += std::conj(u[m][i]) * a[E1 + m][NI];
        row[i] += a[NO][E1 + m] * u[m][i];
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        block[i][j] = 0.0;
        for (int m = 0; m < 3; ++m)
        {
          for (int n = 0; n < 3; ++n)
          {
            block[i][j] += std::conj(u[m][i]) * a[E1 + m][E1 + n] * u[n][j];
          }
        }
      }
    }
    Complex weight = a[NO][NO];
    for (int j = 0; j < 3; ++j)
    {
      weight += oFactor[j] * row[j] * qe[j];
    }
    Complex derivative[3];
    for (int i = 0; i < 3; ++i)
    {
      Complex sum = pFactor[i] * column[i] + nFactor[i] * niColumn[i] * halfSquare;
      for (int j = 0; j < 3; ++j)
      {
        sum += fFactor[i][j] * block[i][j] * qe[j];
      }
      derivative[i] = sum - scale * expMu[i] * qe[i] * weight;
    }
    for (int j = 0; j < 3; ++j)
    {
      const double value =
        (u[j][0] * derivative[0] + u[j][1] * derivative[1] + u[j][2] * derivative[2]).real();
      if (!std::isfinite(value))
      {
        return false;
      }
      byExponent[kBivector * j + k] = value;
    }
  }
  return true;
}
} // namespace core
} // namespace cga
