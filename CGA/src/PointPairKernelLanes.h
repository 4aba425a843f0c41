// Internal: the block kernel of PointPairKernel.h, included once per instruction set by
// PointPairKernel<Isa>.cpp with BOOSTED_KERNEL_ISA set to that file's namespace.
//
// It repeats, lane by lane and operation by operation, what PointPairField::map() computes through
// generatorAt(), expPaper()/expExact() (their scalar arithmetic is shared: ExponentialScalars.h)
// and sandwichPoint(), so that B(p) and K round the same way (the kernel files are compiled with
// -ffp-contract=off: no fused multiply-add may change a rounding, which a large rotation angle
// would amplify). Only the sandwich differs: for the Paper rule it is the closed form below
// instead of the sparse product, equal up to rounding.
//
// Everything here has internal linkage and calls only builtins and libm: see PointPairKernel.h.
#ifndef BOOSTED_KERNEL_ISA
#error "define BOOSTED_KERNEL_ISA before including PointPairKernelLanes.h"
#endif

#include "ExponentialScalars.h"
#include "PointPairKernel.h"

#include "cga/Compact.h" // for the component enumerators only: nothing of it is called here

namespace cga
{
namespace kernel
{
namespace BOOSTED_KERNEL_ISA
{
namespace
{
constexpr int L = kLanes;

// Component numbers of Compact.h.
constexpr int E12 = Bivector::E12, E13 = Bivector::E13, E23 = Bivector::E23;
constexpr int E1NO = Bivector::E1NO, E2NO = Bivector::E2NO, E3NO = Bivector::E3NO;
constexpr int E1NI = Bivector::E1NI, E2NI = Bivector::E2NI, E3NI = Bivector::E3NI;
constexpr int NONI = Bivector::NONI, BivectorCount = Bivector::Count;
constexpr int NO = ConformalVector::NO, E1 = ConformalVector::E1, E2 = ConformalVector::E2;
constexpr int E3 = ConformalVector::E3, NI = ConformalVector::NI;
constexpr int VectorCount = ConformalVector::Count;
constexpr int QuadvectorCount = Quadvector::Count;
constexpr int EvenCount = Even::kCount; // scalar, bivector, quadvector (detail::pack order)

using Lanes = double[L];

// kLanes doubles as one value, made of registers of the target's width (the including file sets
// BOOSTED_KERNEL_VECTOR_BYTES: 64 for AVX-512, 32 for AVX2, 16 otherwise). GCC/Clang vector
// extensions; wider vector types than the target has are lowered badly, hence the parts. The
// generator loop below keeps its ten sums in registers, which plain arrays did not get from GCC.
#ifndef BOOSTED_KERNEL_VECTOR_BYTES
#define BOOSTED_KERNEL_VECTOR_BYTES 16
#endif
typedef double NativeVector __attribute__((vector_size(BOOSTED_KERNEL_VECTOR_BYTES)));
constexpr int kParts = L * static_cast<int>(sizeof(double)) / BOOSTED_KERNEL_VECTOR_BYTES;
static_assert(kParts >= 1 && kParts * BOOSTED_KERNEL_VECTOR_BYTES == L * sizeof(double),
              "lanes must fill whole registers");

struct LaneVector
{
  NativeVector part[kParts];
};

#define BOOSTED_LANE_OPERATOR(op)                                                                \
  inline LaneVector operator op(LaneVector a, const LaneVector& b)                               \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      a.part[i] = a.part[i] op b.part[i];                                                        \
    }                                                                                            \
    return a;                                                                                    \
  }                                                                                              \
  inline LaneVector operator op(LaneVector a, double b)                                          \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      a.part[i] = a.part[i] op b;                                                                \
    }                                                                                            \
    return a;                                                                                    \
  }                                                                                              \
  inline LaneVector operator op(double a, LaneVector b)                                          \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      b.part[i] = a op b.part[i];                                                                \
    }                                                                                            \
    return b;                                                                                    \
  }
BOOSTED_LANE_OPERATOR(+)
BOOSTED_LANE_OPERATOR(-)
BOOSTED_LANE_OPERATOR(*)
BOOSTED_LANE_OPERATOR(/)
#undef BOOSTED_LANE_OPERATOR

inline LaneVector operator-(LaneVector a)
{
  for (int i = 0; i < kParts; ++i)
  {
    a.part[i] = -a.part[i];
  }
  return a;
}

inline LaneVector& operator+=(LaneVector& a, const LaneVector& b)
{
  return a = a + b;
}

inline LaneVector loadLanes(const double* p)
{
  LaneVector v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

inline void storeLanes(double* p, const LaneVector& v)
{
  __builtin_memcpy(p, &v, sizeof v);
}

// b[c][l] = -strength B(p_l) = -strength sum_i w_i tau_i / (k |p_l - x_i|^2 + eps).
void accumulateGenerator(const KernelArgs& args, const double* xyz, double (*b)[L])
{
  const LaneVector px = loadLanes(xyz);
  const LaneVector py = loadLanes(xyz + L);
  const LaneVector pz = loadLanes(xyz + 2 * L);
  LaneVector sum[BivectorCount];
  for (int c = 0; c < BivectorCount; ++c)
  {
    sum[c] = LaneVector{};
  }
  const double falloff = args.falloff, epsilon = args.epsilon;
  for (std::size_t i = 0; i < args.generatorCount; ++i)
  {
    const double* g = args.generators + i * kGeneratorStride;
    const LaneVector dx = px - g[0];
    const LaneVector dy = py - g[1];
    const LaneVector dz = pz - g[2];
    const LaneVector d2 = dx * dx + dy * dy + dz * dz;
    const LaneVector factor = 1.0 / (falloff * d2 + epsilon);
    for (int c = 0; c < BivectorCount; ++c)
    {
      sum[c] += g[3 + c] * factor;
    }
  }
  const double scale = -args.strength;
  for (int c = 0; c < BivectorCount; ++c)
  {
    storeLanes(b[c], sum[c] * scale);
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

// y = v _| B for conformal vectors v (five lanes arrays) and a bivector B:
// v = a no + u + b ni gives y = (u.A + d a) no + (u _| E + b A + a C) + (u.C - d b) ni with
// B = E + A_i e_i^no + C_i e_i^ni + d no^ni (no.ni = -1).
inline void contract(const LaneVector* v, const LaneVector* b, LaneVector* y)
{
  const LaneVector a = v[NO], u1 = v[E1], u2 = v[E2], u3 = v[E3], bb = v[NI];
  const LaneVector d = b[NONI];
  y[NO] = u1 * b[E1NO] + u2 * b[E2NO] + u3 * b[E3NO] + d * a;
  y[E1] = -b[E12] * u2 - b[E13] * u3 + bb * b[E1NO] + a * b[E1NI];
  y[E2] = b[E12] * u1 - b[E23] * u3 + bb * b[E2NO] + a * b[E2NI];
  y[E3] = b[E13] * u1 + b[E23] * u2 + bb * b[E3NO] + a * b[E3NI];
  y[NI] = u1 * b[E1NI] + u2 * b[E2NI] + u3 * b[E3NI] - d * bb;
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
  LaneVector bv[BivectorCount], xv[VectorCount], y[VectorCount], z[VectorCount];
  for (int i = 0; i < BivectorCount; ++i)
  {
    bv[i] = loadLanes(b[i]);
  }
  for (int i = 0; i < VectorCount; ++i)
  {
    xv[i] = loadLanes(x[i]);
  }
  contract(xv, bv, y);
  contract(y, bv, z);
  const LaneVector cv = loadLanes(c);
  const LaneVector square = -(bv[E12] * bv[E12] + bv[E13] * bv[E13] + bv[E23] * bv[E23]) +
    2.0 * (bv[E1NO] * bv[E1NI] + bv[E2NO] * bv[E2NI] + bv[E3NO] * bv[E3NI]) +
    bv[NONI] * bv[NONI];
  const LaneVector a = cv * cv - square;
  const LaneVector twoC = 2.0 * cv;
  for (int i = 0; i < VectorCount; ++i)
  {
    storeLanes(r[i], a * xv[i] - twoC * y[i] + 2.0 * z[i]);
  }
}

// r = sum of the terms' coefficient a[a] b[b], each slot's sum in the table's order like
// SparseProduct::accumulate, but in a register rather than through memory.
template <int NR>
void applyTerms(const KernelTerms& table, const double (*a)[L], const double (*b)[L], double (*r)[L])
{
  int t = 0;
  for (int i = 0; i < NR; ++i)
  {
    alignas(64) Lanes sum = {};
    for (; t < table.size && table.terms[t].r == i; ++t)
    {
      const KernelTerm term = table.terms[t];
      for (int l = 0; l < L; ++l)
      {
        sum[l] += term.coefficient * a[term.a][l] * b[term.b][l];
      }
    }
    for (int l = 0; l < L; ++l)
    {
      r[i][l] = sum[l];
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
  alignas(64) double odd[16][L];
  applyTerms<16>(args.evenTimesVector, k, x, odd);
  applyTerms<VectorCount>(args.oddTimesEvenToVector, odd, reversed, r);
}

// seriesExp() of Exponential.cpp on every lane of b, into k (detail::pack order).
void seriesExponential(const KernelArgs& args, const double (*b)[L], double (*k)[L])
{
  alignas(64) double w[QuadvectorCount][L];
  applyTerms<QuadvectorCount>(args.wedge, b, b, w);
  alignas(64) double w2[1][L];
  applyTerms<1>(args.quadvectorSquare, w, w, w2);
  alignas(64) double wb[BivectorCount][L];
  applyTerms<BivectorCount>(args.rightContraction, w, b, wb);
  alignas(64) Lanes s, a0, a4, b0, b4;
  for (int l = 0; l < L; ++l)
  {
    s[l] = scalarSquare(b, l);
  }
  const detail::SeriesCoefficients<LaneVector> c =
    detail::seriesCoefficients(loadLanes(s), loadLanes(w2[0]));
  storeLanes(a0, c.a0);
  storeLanes(a4, c.a4);
  storeLanes(b0, c.b0);
  storeLanes(b4, c.b4);
  for (int l = 0; l < L; ++l)
  {
    k[0][l] = a0[l];
    for (int i = 0; i < BivectorCount; ++i)
    {
      k[1 + i][l] = b0[l] * b[i][l] + b4[l] * wb[i][l];
    }
    for (int i = 0; i < QuadvectorCount; ++i)
    {
      k[1 + BivectorCount + i][l] = a4[l] * w[i][l];
    }
  }
}

// K of the Exact rule (expExact) for every lane, in detail::pack order; NaN where B is not finite.
void exactExponential(const KernelArgs& args, const double (*b)[L], double (*k)[L])
{
  alignas(64) Lanes m;
  maxAbs(b, m);
  alignas(64) double u[BivectorCount][L];
  for (int l = 0; l < L; ++l)
  {
    const double scale = (m[l] != 0.0 && __builtin_isfinite(m[l])) ? m[l] : 1.0;
    for (int i = 0; i < BivectorCount; ++i)
    {
      u[i][l] = b[i][l] / scale;
    }
  }
  alignas(64) double w[QuadvectorCount][L];
  applyTerms<QuadvectorCount>(args.wedge, u, u, w);
  alignas(64) double w2[1][L];
  applyTerms<1>(args.quadvectorSquare, w, w, w2);
  // Which lanes take the power series (seriesExp of B itself) and which the closed form.
  alignas(64) Lanes l1, l2;
  bool series[L], closed[L];
  bool anySeries = false, anyClosed = false;
  for (int l = 0; l < L; ++l)
  {
    detail::planeSquares(scalarSquare(u, l), w2[0][l], l1[l], l2[l]);
    const bool usable = m[l] != 0.0 && __builtin_isfinite(m[l]);
    series[l] = usable && detail::exactUsesSeries(m[l], l1[l], l2[l]);
    closed[l] = usable && !series[l];
    anySeries = anySeries || series[l];
    anyClosed = anyClosed || closed[l];
  }
  alignas(64) double fromSeries[EvenCount][L] = {};
  if (anySeries)
  {
    seriesExponential(args, b, fromSeries);
  }
  alignas(64) double wu[BivectorCount][L] = {};
  alignas(64) double coefficients[4][L] = {};
  if (anyClosed)
  {
    applyTerms<BivectorCount>(args.rightContraction, w, u, wu);
    for (int l = 0; l < L; ++l)
    {
      if (closed[l])
      {
        const detail::ExactCoefficients c = detail::exactCoefficients(m[l], l1[l], l2[l], true);
        coefficients[0][l] = c.scalar;
        coefficients[1][l] = c.quadvector;
        coefficients[2][l] = c.bivector;
        coefficients[3][l] = c.bivectorW;
      }
    }
  }
  const double nan = __builtin_nan("");
  for (int l = 0; l < L; ++l)
  {
    const bool finite = __builtin_isfinite(m[l]);
    const bool zero = m[l] == 0.0;
    for (int i = 0; i < EvenCount; ++i)
    {
      double closedValue;
      if (i == 0)
      {
        closedValue = coefficients[0][l];
      }
      else if (i <= BivectorCount)
      {
        closedValue = coefficients[2][l] * u[i - 1][l] + coefficients[3][l] * wu[i - 1][l];
      }
      else
      {
        closedValue = coefficients[1][l] * w[i - 1 - BivectorCount][l];
      }
      const double identity = i == 0 ? 1.0 : 0.0;
      k[i][l] = !finite ? nan : (zero ? identity : (series[l] ? fromSeries[i][l] : closedValue));
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
    // The power series of planeFunctions, computed for every lane (it vectorizes).
    detail::planeSeries(m[l], lh[l], x[l], c[l], sHat[l]);
  }
  for (int l = 0; l < L; ++l)
  {
    if (!(x[l] < detail::kPlaneSeriesLimit) && m[l] != 0.0 && __builtin_isfinite(m[l]))
    {
      detail::planeTranscendental(lh[l], r[l], x[l], true, c[l], sHat[l]);
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
    alignas(64) double k[EvenCount][L];
    exactExponential(args, b, k);
    sandwichEven(args, k, x, r);
  }
  normalize(xyz, r, image, mapped);
}
} // namespace BOOSTED_KERNEL_ISA
} // namespace kernel
} // namespace cga
