// Internal: the block kernel of PointPairKernel.h, included once per instruction set by
// PointPairKernel<Isa>.cpp with BOOSTED_KERNEL_ISA set to that file's namespace.
//
// It repeats, lane by lane and operation by operation, what PointPairField::map() computes through
// generatorAt(), expPaper()/expExact() and sandwichPoint(), so that B(p) and K come out bit for bit
// the same (the kernel files are compiled with -ffp-contract=off: no fused multiply-add may change a
// rounding, which a large rotation angle would amplify). Only the sandwich differs: for the Paper
// rule it is the closed form below instead of the sparse product, equal up to rounding.
//
// Everything here has internal linkage and calls only builtins and libm: see PointPairKernel.h.
#ifndef BOOSTED_KERNEL_ISA
#error "define BOOSTED_KERNEL_ISA before including PointPairKernelLanes.h"
#endif

#include "PointPairKernel.h"

#include <math.h>

namespace cga
{
namespace kernel
{
namespace BOOSTED_KERNEL_ISA
{
namespace
{
constexpr int L = kLanes;

// Bivector components (Compact.h): e12 e13 e23, e_i^no, e_i^ni, no^ni.
enum
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
  BivectorCount
};

// Conformal vector components (Compact.h): no, e1, e2, e3, ni.
enum
{
  NO,
  E1,
  E2,
  E3,
  NI,
  VectorCount
};

using Lanes = double[L];

// b[c][l] = -strength B(p_l) = -strength sum_i w_i tau_i / (k |p_l - x_i|^2 + eps).
void accumulateGenerator(const KernelArgs& args, const double* xyz, double (*b)[L])
{
  for (int c = 0; c < BivectorCount; ++c)
  {
    for (int l = 0; l < L; ++l)
    {
      b[c][l] = 0.0;
    }
  }
  const double* px = xyz;
  const double* py = xyz + L;
  const double* pz = xyz + 2 * L;
  for (std::size_t i = 0; i < args.generatorCount; ++i)
  {
    const double* g = args.generators + i * kGeneratorStride;
    alignas(64) Lanes factor;
    for (int l = 0; l < L; ++l)
    {
      const double dx = px[l] - g[0];
      const double dy = py[l] - g[1];
      const double dz = pz[l] - g[2];
      const double d2 = dx * dx + dy * dy + dz * dz;
      factor[l] = 1.0 / (args.falloff * d2 + args.epsilon);
    }
    for (int c = 0; c < BivectorCount; ++c)
    {
      const double pair = g[3 + c];
      for (int l = 0; l < L; ++l)
      {
        b[c][l] += pair * factor[l];
      }
    }
  }
  const double scale = -args.strength;
  for (int c = 0; c < BivectorCount; ++c)
  {
    for (int l = 0; l < L; ++l)
    {
      b[c][l] *= scale;
    }
  }
}

// Largest absolute component, NaN when one is NaN (Coefficients::maxAbs).
void maxAbs(const double (*b)[L], double* m)
{
  for (int l = 0; l < L; ++l)
  {
    m[l] = 0.0;
  }
  for (int c = 0; c < BivectorCount; ++c)
  {
    for (int l = 0; l < L; ++l)
    {
      const double a = __builtin_fabs(b[c][l]);
      m[l] = (a > m[l] || __builtin_isnan(a)) ? a : m[l];
    }
  }
}

// <B B>_0 (scalarSquare in CompactAlgebra.cpp, same order of operations).
inline double scalarSquare(const double (*b)[L], int l)
{
  return -(b[E12][l] * b[E12][l] + b[E13][l] * b[E13][l] + b[E23][l] * b[E23][l]) +
    2.0 * (b[E1NO][l] * b[E1NI][l] + b[E2NO][l] * b[E2NI][l] + b[E3NO][l] * b[E3NI][l]) +
    b[NONI][l] * b[NONI][l];
}

// planeFunctions() of Exponential.cpp outside its power-series range (x >= 1e-2), one lane.
void planeTranscendental(double r, double x, double lh, double& c, double& sHat)
{
  if (lh > 0.0)
  {
    if (x > 20.0) // kExpScalingThreshold: divided by cosh
    {
      c = 1.0;
      sHat = tanh(x) / r;
    }
    else
    {
      c = cosh(x);
      sHat = sinh(x) / r;
    }
  }
  else
  {
    c = cos(x);
    sHat = sin(x) / r;
  }
}

// y = v _| B for conformal vectors v (five lanes arrays) and a bivector B:
// v = a no + u + b ni gives y = (u.A + d a) no + (u _| E + b A + a C) + (u.C - d b) ni with
// B = E + A_i e_i^no + C_i e_i^ni + d no^ni (no.ni = -1).
void contract(const double (*v)[L], const double (*b)[L], double (*y)[L])
{
  for (int l = 0; l < L; ++l)
  {
    const double a = v[NO][l], u1 = v[E1][l], u2 = v[E2][l], u3 = v[E3][l], bb = v[NI][l];
    const double d = b[NONI][l];
    y[NO][l] = u1 * b[E1NO][l] + u2 * b[E2NO][l] + u3 * b[E3NO][l] + d * a;
    y[E1][l] = -b[E12][l] * u2 - b[E13][l] * u3 + bb * b[E1NO][l] + a * b[E1NI][l];
    y[E2][l] = b[E12][l] * u1 - b[E23][l] * u3 + bb * b[E2NO][l] + a * b[E2NI][l];
    y[E3][l] = b[E13][l] * u1 + b[E23][l] * u2 + bb * b[E3NO][l] + a * b[E3NI][l];
    y[NI][l] = u1 * b[E1NI][l] + u2 * b[E2NI][l] + u3 * b[E3NI][l] - d * bb;
  }
}

// up(p) = no + p + |p|^2/2 ni.
void upPoints(const double* xyz, double (*x)[L])
{
  for (int l = 0; l < L; ++l)
  {
    const double px = xyz[l], py = xyz[L + l], pz = xyz[2 * L + l];
    x[NO][l] = 1.0;
    x[E1][l] = px;
    x[E2][l] = py;
    x[E3][l] = pz;
    x[NI][l] = 0.5 * (px * px + py * py + pz * pz);
  }
}

// K = c + B (the Paper rule: no 4-vector part), ~K = c - B. With y = X _| B,
// <B X B>_1 = <B B>_0 X - 2 y _| B, and B X - X B = -2 y, so
// <K X ~K>_1 = (c^2 - <B B>_0) X - 2 c y + 2 y _| B.
void sandwichScalarBivector(const double* c,
                            const double (*b)[L],
                            const double (*x)[L],
                            double (*r)[L])
{
  alignas(64) double y[VectorCount][L];
  alignas(64) double z[VectorCount][L];
  contract(x, b, y);
  contract(y, b, z);
  for (int l = 0; l < L; ++l)
  {
    const double a = c[l] * c[l] - scalarSquare(b, l);
    const double twoC = 2.0 * c[l];
    for (int i = 0; i < VectorCount; ++i)
    {
      r[i][l] = a * x[i][l] - twoC * y[i][l] + 2.0 * z[i][l];
    }
  }
}

// <K X ~K>_1 for a full even K (scalar, bivector, 4-vector slots as detail::pack) through the
// sparse product terms of sandwichGrade1, in the same order.
void sandwichEven(const KernelArgs& args,
                  const double (*k)[L],
                  const double (*x)[L],
                  double (*r)[L])
{
  constexpr int EvenCount = 16;
  alignas(64) double reversed[EvenCount][L];
  for (int s = 0; s < EvenCount; ++s)
  {
    const double sign = (s >= 1 && s <= BivectorCount) ? -1.0 : 1.0;
    for (int l = 0; l < L; ++l)
    {
      reversed[s][l] = sign * k[s][l];
    }
  }
  alignas(64) double odd[16][L] = {};
  for (int t = 0; t < args.evenTimesVectorSize; ++t)
  {
    const KernelTerm term = args.evenTimesVector[t];
    for (int l = 0; l < L; ++l)
    {
      odd[term.r][l] += term.coefficient * k[term.a][l] * x[term.b][l];
    }
  }
  for (int i = 0; i < VectorCount; ++i)
  {
    for (int l = 0; l < L; ++l)
    {
      r[i][l] = 0.0;
    }
  }
  for (int t = 0; t < args.oddTimesEvenToVectorSize; ++t)
  {
    const KernelTerm term = args.oddTimesEvenToVector[t];
    for (int l = 0; l < L; ++l)
    {
      r[term.r][l] += term.coefficient * odd[term.a][l] * reversed[term.b][l];
    }
  }
}

// K of the Paper rule (expPaper), c + B, for every lane; a lane whose B is not finite gets NaN.
void paperExponential(double (*b)[L], double* c)
{
  alignas(64) Lanes m;
  maxAbs(b, m);
  alignas(64) Lanes lh, r, x;
  for (int l = 0; l < L; ++l)
  {
    // A zero or non-finite lane divides by 1 here and is fixed below.
    const double scale = (m[l] != 0.0 && __builtin_isfinite(m[l])) ? m[l] : 1.0;
    for (int i = 0; i < BivectorCount; ++i)
    {
      b[i][l] = b[i][l] / scale;
    }
  }
  for (int l = 0; l < L; ++l)
  {
    lh[l] = scalarSquare(b, l);
    r[l] = __builtin_sqrt(__builtin_fabs(lh[l]));
    x[l] = m[l] * r[l];
  }
  alignas(64) Lanes sHat;
  for (int l = 0; l < L; ++l)
  {
    // The power series in l of both functions (x < 1e-2), computed for every lane.
    const double q = lh[l] >= 0.0 ? x[l] * x[l] : -x[l] * x[l];
    c[l] = 1.0 + q / 2.0 * (1.0 + q / 12.0 * (1.0 + q / 30.0 * (1.0 + q / 56.0)));
    sHat[l] = m[l] * (1.0 + q / 6.0 * (1.0 + q / 20.0 * (1.0 + q / 42.0 * (1.0 + q / 72.0))));
  }
  for (int l = 0; l < L; ++l)
  {
    if (!(x[l] < 1e-2) && m[l] != 0.0 && __builtin_isfinite(m[l]))
    {
      planeTranscendental(r[l], x[l], lh[l], c[l], sHat[l]);
    }
  }
  const double nan = __builtin_nan("");
  for (int l = 0; l < L; ++l)
  {
    const bool finite = __builtin_isfinite(m[l]);
    const bool zero = m[l] == 0.0;
    c[l] = !finite ? nan : (zero ? 1.0 : c[l]);
    const double factor = !finite ? nan : (zero ? 0.0 : sHat[l]);
    for (int i = 0; i < BivectorCount; ++i)
    {
      b[i][l] = factor * b[i][l];
    }
  }
}

// fn(r): the Euclidean point r_e / r_no, or not mapped (normalizePoint).
void normalize(const double* xyz, const double (*r)[L], double* image, std::uint8_t* mapped)
{
  for (int l = 0; l < L; ++l)
  {
    const double alpha = r[NO][l];
    const double ix = r[E1][l] / alpha, iy = r[E2][l] / alpha, iz = r[E3][l] / alpha;
    const bool ok = alpha != 0.0 && __builtin_isfinite(alpha) && __builtin_isfinite(ix) &&
      __builtin_isfinite(iy) && __builtin_isfinite(iz) && __builtin_isfinite(xyz[l]) &&
      __builtin_isfinite(xyz[L + l]) && __builtin_isfinite(xyz[2 * L + l]);
    image[l] = ix;
    image[L + l] = iy;
    image[2 * L + l] = iz;
    mapped[l] = ok ? 1 : 0;
  }
}
} // namespace

void mapBlock(const KernelArgs& args, const double* xyz, double* image, std::uint8_t* mapped)
{
  alignas(64) double b[BivectorCount][L];
  accumulateGenerator(args, xyz, b);
  alignas(64) double x[VectorCount][L];
  upPoints(xyz, x);
  alignas(64) double r[VectorCount][L];
  if (!args.exactRule)
  {
    alignas(64) Lanes c;
    paperExponential(b, c);
    sandwichScalarBivector(c, b, x, r);
  }
  else
  {
    alignas(64) double k[16][L];
    for (int l = 0; l < L; ++l)
    {
      double lane[BivectorCount];
      double even[16];
      for (int i = 0; i < BivectorCount; ++i)
      {
        lane[i] = b[i][l];
      }
      args.exactExponential(lane, even);
      for (int s = 0; s < 16; ++s)
      {
        k[s][l] = even[s];
      }
    }
    sandwichEven(args, k, x, r);
  }
  normalize(xyz, r, image, mapped);
}
} // namespace BOOSTED_KERNEL_ISA
} // namespace kernel
} // namespace cga
