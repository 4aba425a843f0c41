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

/// x = M^-1 v for M = d I + K, K u = w x u (solveByFieldDerivative with rate -d).
void solveFixedPoint(double d, const double* w, const double* v, double* x)
{
  solveByFieldDerivative(-d, w, v, x);
}
} // namespace

bool strongSimilarityExponentDerivative(const double* b, const double* p, double* byExponent, double* image)
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
  if (image != nullptr)
  {
    for (int j = 0; j < 3; ++j)
    {
      const Complex moved = u[j][0] * (expMu[0] * qe[0]) + u[j][1] * (expMu[1] * qe[1]) +
        u[j][2] * (expMu[2] * qe[2]);
      image[j] = (xHigh[j] + xLow[j]) + scale * moved.real();
    }
  }
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

namespace
{
/// The Euclidean field of b at x (euclideanField): its zeros are the fixed points of exp(b), and it
/// is linear in b.
void fieldAt(const double* b, const double* x, double* v)
{
  const double nE[3] = { b[E23], -b[E13], b[E12] }, a[3] = { b[E1NO], b[E2NO], b[E3NO] };
  double n[3];
  euclideanField(nE, a, b + E1NI, rateAndNormalAt(nE, a, b[NONI], x, n), x, v);
}

/// d out / d b at p on the repeller r (its image): r moves with b by dr = -Dv(r)^-1 v_e(r) along a
/// seed e, and p, left behind at -dr from it, is carried by exp(b)'s derivative there,
/// e^{2 d'} Q (d' = d + A.r, Q = exp(-2 [n']_x), n' = n_E + r x A): d out = (I - e^{2 d'} Q) dr.
bool repellerDerivative(const double* b, const double* r, double* byExponent)
{
  const double a[3] = { b[E1NO], b[E2NO], b[E3NO] }, nE[3] = { b[E23], -b[E13], b[E12] };
  double n[3], omega[3];
  const double rate = rateAndNormalAt(nE, a, b[NONI], r, n);
  for (int i = 0; i < 3; ++i)
  {
    omega[i] = -2.0 * n[i];
  }
  const double growth = std::exp(rate); // e^{d'}, applied twice
  for (int k = 0; k < kBivector; ++k)
  {
    double unit[kBivector] = {}, v[3], dr[3], turned[3];
    unit[k] = 1.0;
    fieldAt(unit, r, v);
    solveByFieldDerivative(rate, n, v, dr);
    for (int i = 0; i < 3; ++i)
    {
      dr[i] = -dr[i];
    }
    rotatedBy(omega, dr, turned);
    for (int j = 0; j < 3; ++j)
    {
      const double value = dr[j] - (turned[j] * growth) * growth;
      if (!std::isfinite(value))
      {
        return false;
      }
      byExponent[kBivector * j + k] = value;
    }
  }
  return true;
}

/// sigma(T(-x) c ~T(-x)): the bivector c moved by -x, then inverted in the unit sphere (sigma:
/// no -> ni/2, ni -> 2 no, e_i fixed; exact): E fixed, A and C swap with the factors 2 and 1/2, d
/// changes sign.
void movedAndInverted(const double* c, const double* x, double* out)
{
  const double t[3] = { -x[0], -x[1], -x[2] };
  double moved[kBivector];
  translateBivector(c, t, moved);
  for (const int e : { E12, E13, E23 })
  {
    out[e] = moved[e];
  }
  for (int i = 0; i < 3; ++i)
  {
    out[E1NO + i] = 2.0 * moved[E1NI + i];
    out[E1NI + i] = 0.5 * moved[E1NO + i];
  }
  out[NONI] = -moved[NONI];
}
} // namespace

bool strongBoostExponentDerivative(const double* b, const double* p, double* byExponent)
{
  UnitBivector<double> unit;
  unitBivector(b, unit, false);
  double wu[kBivector], l1, l2, attractor[3], repeller[3];
  detail::applyProduct<detail::kRightContraction>(unit.w, unit.u, wu);
  detail::planeSquares(unit.s, unit.w2, l1, l2);
  if (!(l1 > 0.0))
  {
    return false;
  }
  attractorAndRepeller(unit, l1, l2, wu, attractor, repeller);
  if (p[0] == repeller[0] && p[1] == repeller[1] && p[2] == repeller[2])
  {
    return repellerDerivative(b, repeller, byExponent);
  }
  // About the repeller r, inverted: sigma(T(-r) b ~T(-r)) fixes infinity (r's image), a
  // similarity's bivector whose e_i^no part, twice the field of b at r, is the rounding of r (a
  // perturbation of b within its one-ulp sensitivity): set to 0. Its derivative maps p'' = inv(p - r)
  // to out'' (out = r + inv(out'')), and the seeds move with it, e_i^no parts kept.
  double similar[kBivector], field[3];
  movedAndInverted(b, repeller, similar);
  fieldAt(b, repeller, field);
  double terms = std::fabs(b[NONI]) + std::fabs(b[E12]) + std::fabs(b[E13]) + std::fabs(b[E23]);
  for (int i = 0; i < 3; ++i)
  {
    terms += std::fabs(b[E1NI + i]) + std::fabs(b[E1NO + i]) * (1.0 + std::fabs(repeller[i]));
  }
  const double size = terms * (1.0 + std::sqrt(dot3(repeller, repeller)));
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::fabs(field[i]) <= 0x1p-40 * size)) // not a fixed point (or not finite)
    {
      return false;
    }
    similar[E1NO + i] = 0.0;
  }
  const double offset[3] = { p[0] - repeller[0], p[1] - repeller[1], p[2] - repeller[2] };
  double pInverted[3], byInverted[3 * kBivector], imageInverted[3];
  inverted(offset, pInverted);
  if (!strongSimilarityExponentDerivative(similar, pInverted, byInverted, imageInverted))
  {
    return false;
  }
  // d inv(y) = (I - 2 y y^T / |y|^2) / |y|^2 at y = out'', with y scaled by a power of two.
  const double down = 1.0 / vectorScale(imageInverted);
  const double y[3] = { imageInverted[0] * down, imageInverted[1] * down, imageInverted[2] * down };
  const double ySquare = dot3(y, y);
  for (int k = 0; k < kBivector; ++k)
  {
    double unitSeed[kBivector] = {}, seed[kBivector], column[3];
    unitSeed[k] = 1.0;
    movedAndInverted(unitSeed, repeller, seed);
    for (int i = 0; i < 3; ++i)
    {
      column[i] = 0.0;
      for (int c = 0; c < kBivector; ++c)
      {
        column[i] += byInverted[kBivector * i + c] * seed[c];
      }
    }
    const double along = 2.0 * dot3(y, column) / ySquare;
    for (int j = 0; j < 3; ++j)
    {
      const double value = ((column[j] - along * y[j]) / ySquare * down) * down;
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
