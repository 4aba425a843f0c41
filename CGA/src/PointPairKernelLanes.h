// Internal: the block kernel of PointPairKernel.h, included once per instruction set by
// PointPairKernel<Isa>.cpp with BOOSTED_KERNEL_ISA set to that file's namespace.
//
// It is core::mapPoint (PointMapCore.h), the source of PointPairField::map(), instantiated for a
// vector of kLanes doubles (kWideLanes for the wide block): one point per lane.
//
// Everything here has internal linkage or lives in the ISA's own namespace and calls only
// builtins and libm: see PointPairKernel.h and PointMapCore.h.
#ifndef BOOSTED_KERNEL_ISA
#error "define BOOSTED_KERNEL_ISA before including PointPairKernelLanes.h"
#endif

#include "ForceInline.h"
#include "LaneMath.h"
#include "PointPairKernel.h"

namespace cga
{
namespace kernel
{
namespace BOOSTED_KERNEL_ISA
{
namespace
{
// Lanes per block: kLanes, or kWideLanes where the including file asks for the wide block
// (BOOSTED_KERNEL_WIDE: only mapDisplacedBlock, on two registers per value).
#ifdef BOOSTED_KERNEL_WIDE
constexpr int L = kWideLanes;
#else
constexpr int L = kLanes;
#endif

// kLanes doubles as one value, made of registers of the target's width (the including file sets
// BOOSTED_KERNEL_VECTOR_BYTES: 64 for AVX-512, 32 for AVX2, 16 otherwise). GCC/Clang vector
// extensions; wider vector types than the target has are lowered badly, hence the parts. The
// generator loop keeps its ten sums in registers, which plain arrays did not get from GCC.
#ifndef BOOSTED_KERNEL_VECTOR_BYTES
#define BOOSTED_KERNEL_VECTOR_BYTES 16
#endif
typedef double NativeVector __attribute__((vector_size(BOOSTED_KERNEL_VECTOR_BYTES)));
constexpr int kParts = L * static_cast<int>(sizeof(double)) / BOOSTED_KERNEL_VECTOR_BYTES;
static_assert(kParts >= 1 && kParts * BOOSTED_KERNEL_VECTOR_BYTES == L * sizeof(double),
              "lanes must fill whole registers");


typedef long long NativeMask __attribute__((vector_size(BOOSTED_KERNEL_VECTOR_BYTES)));

// Per-lane flags as the vector compares give them: all bits set or clear.
struct LaneMask
{
  NativeMask part[kParts];
};

struct LaneVector
{
  static constexpr int kLanes = L;
  using Mask = LaneMask;
  NativeVector part[kParts];
};

#define BOOSTED_LANE_OPERATOR(op)                                                                \
  BOOSTED_FORCE_INLINE LaneVector operator op(LaneVector a, const LaneVector& b)                  \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      a.part[i] = a.part[i] op b.part[i];                                                        \
    }                                                                                            \
    return a;                                                                                    \
  }                                                                                              \
  BOOSTED_FORCE_INLINE LaneVector operator op(LaneVector a, double b)                             \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      a.part[i] = a.part[i] op b;                                                                \
    }                                                                                            \
    return a;                                                                                    \
  }                                                                                              \
  BOOSTED_FORCE_INLINE LaneVector operator op(double a, LaneVector b)                             \
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

BOOSTED_FORCE_INLINE LaneVector operator-(LaneVector a)
{
  for (int i = 0; i < kParts; ++i)
  {
    a.part[i] = -a.part[i];
  }
  return a;
}

// LaneMath.h's fusedMultiplyAdd on every lane: a b + c rounded once, the bits of the scalar fma.
// The including file names its instruction (BOOSTED_KERNEL_FMA) where the instruction set has one;
// elsewhere (the baseline: SSE2 has none) each lane calls libm's fma, correct and much slower.
BOOSTED_FORCE_INLINE NativeVector fusedMultiplyAddPart(NativeVector a, NativeVector b, NativeVector c)
{
#ifdef BOOSTED_KERNEL_FMA
  return BOOSTED_KERNEL_FMA(a, b, c);
#else
  for (int l = 0; l < static_cast<int>(sizeof(NativeVector) / sizeof(double)); ++l)
  {
    c[l] = __builtin_fma(a[l], b[l], c[l]);
  }
  return c;
#endif
}

BOOSTED_FORCE_INLINE LaneVector fusedMultiplyAdd(const LaneVector& a, const LaneVector& b, LaneVector c)
{
  for (int i = 0; i < kParts; ++i)
  {
    c.part[i] = fusedMultiplyAddPart(a.part[i], b.part[i], c.part[i]);
  }
  return c;
}

BOOSTED_FORCE_INLINE LaneVector fusedMultiplyAdd(const LaneVector& a, double b, LaneVector c)
{
  // b in every lane as b - 0, which is b for every b (-0 included), so the compiler drops the
  // subtraction and broadcasts b from memory; 0 + b is not b for b = -0 and would cost one add
  // per call on the add pipes, copies into the lanes became a load and permutations.
  const NativeVector factor = b - NativeVector{};
  for (int i = 0; i < kParts; ++i)
  {
    c.part[i] = fusedMultiplyAddPart(a.part[i], factor, c.part[i]);
  }
  return c;
}

// The comparisons, mask logic and selection of LaneMath.h, lane by lane in vector instructions.
#define BOOSTED_LANE_COMPARISON(name, op)                                                        \
  BOOSTED_FORCE_INLINE LaneMask name(const LaneVector& a, const LaneVector& b)                    \
  {                                                                                              \
    LaneMask m;                                                                                  \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      m.part[i] = a.part[i] op b.part[i];                                                        \
    }                                                                                            \
    return m;                                                                                    \
  }
BOOSTED_LANE_COMPARISON(lessThan, <)
BOOSTED_LANE_COMPARISON(lessEqual, <=)
BOOSTED_LANE_COMPARISON(equalTo, ==)
#undef BOOSTED_LANE_COMPARISON

BOOSTED_FORCE_INLINE LaneMask maskAnd(LaneMask a, const LaneMask& b)
{
  for (int i = 0; i < kParts; ++i)
  {
    a.part[i] &= b.part[i];
  }
  return a;
}

BOOSTED_FORCE_INLINE LaneMask maskOr(LaneMask a, const LaneMask& b)
{
  for (int i = 0; i < kParts; ++i)
  {
    a.part[i] |= b.part[i];
  }
  return a;
}

BOOSTED_FORCE_INLINE LaneMask maskNot(LaneMask a)
{
  for (int i = 0; i < kParts; ++i)
  {
    a.part[i] = ~a.part[i];
  }
  return a;
}

BOOSTED_FORCE_INLINE bool anyLane(const LaneMask& m)
{
  NativeMask acc = m.part[0];
  for (int i = 1; i < kParts; ++i)
  {
    acc |= m.part[i];
  }
  long long lanes = 0;
  for (int l = 0; l < static_cast<int>(sizeof(NativeMask) / sizeof(long long)); ++l)
  {
    lanes |= acc[l];
  }
  return lanes != 0;
}

BOOSTED_FORCE_INLINE bool allLanes(const LaneMask& m)
{
  return !anyLane(maskNot(m));
}

BOOSTED_FORCE_INLINE LaneVector select(const LaneMask& m, const LaneVector& a, const LaneVector& b)
{
  LaneVector r;
  for (int i = 0; i < kParts; ++i)
  {
    r.part[i] = m.part[i] ? a.part[i] : b.part[i];
  }
  return r;
}

BOOSTED_FORCE_INLINE LaneVector magnitude(LaneVector x)
{
  const NativeMask noSign = NativeMask{} + 0x7fffffffffffffffLL;
  for (int i = 0; i < kParts; ++i)
  {
    x.part[i] = (NativeVector)((NativeMask)x.part[i] & noSign);
  }
  return x;
}

BOOSTED_FORCE_INLINE LaneVector valueOf(const LaneVector& x)
{
  return x;
}

// LaneMath.h's binaryFloor on every lane.
BOOSTED_FORCE_INLINE LaneVector binaryFloor(LaneVector x)
{
  const NativeMask exponent = NativeMask{} + 0x7ff0000000000000LL;
  const NativeMask smallest = NativeMask{} + 0x0010000000000000LL;
  for (int i = 0; i < kParts; ++i)
  {
    const NativeMask bits = (NativeMask)x.part[i] & exponent;
    x.part[i] = (NativeVector)(bits == 0 ? smallest : bits);
  }
  return x;
}

// LaneMath.h's binaryExponentOf and powerOfTwoOf on every lane, without integer conversions: an
// integer n in [0, 2^52) is the double 2^52 + n less 2^52, whose low bits hold n.
// (Shifts on unsigned lanes: no sign bit to shift into.)
typedef unsigned long long NativeBits __attribute__((vector_size(BOOSTED_KERNEL_VECTOR_BYTES)));

BOOSTED_FORCE_INLINE LaneVector binaryExponentOf(LaneVector x)
{
  const NativeBits field = NativeBits{} + 0x7ffULL;
  const NativeBits twoTo52 = NativeBits{} + 0x4330000000000000ULL;
  for (int i = 0; i < kParts; ++i)
  {
    const NativeBits e = ((NativeBits)x.part[i] >> 52) & field;
    x.part[i] = (NativeVector)(e | twoTo52) - (0x1p52 + 1023.0);
  }
  return x;
}

BOOSTED_FORCE_INLINE LaneVector powerOfTwoOf(LaneVector k)
{
  for (int i = 0; i < kParts; ++i)
  {
    const NativeVector biased = k.part[i] + (0x1p52 + 1023.0); // 2^52 + k + 1023, exactly
    k.part[i] = (NativeVector)((NativeBits)biased << 52);
  }
  return k;
}

// The lane access PointMapCore.h finds by argument-dependent lookup.
BOOSTED_FORCE_INLINE void toLanes(const LaneVector& v, double* lanes)
{
  __builtin_memcpy(lanes, &v, sizeof v);
}

BOOSTED_FORCE_INLINE void fromLanes(const double* lanes, LaneVector& v)
{
  __builtin_memcpy(&v, lanes, sizeof v);
}

// The elementary functions of LaneMath.h on every lane, found by argument-dependent lookup: with
// SLEEF on x86-64 its deterministic vector functions of this instruction set
// (BOOSTED_KERNEL_SLEEF(name), set by the including file), which give the bits of the scalar
// Sleef_cinz_*d1_u10purec that map() calls; otherwise the scalar function per lane.
#if defined(BOOSTED_HAVE_SLEEF) && defined(BOOSTED_KERNEL_SLEEF)
#define BOOSTED_LANE_FUNCTION(name, sleefName)                                                   \
  BOOSTED_FORCE_INLINE LaneVector name(LaneVector x)                                              \
  {                                                                                              \
    for (int i = 0; i < kParts; ++i)                                                             \
    {                                                                                            \
      x.part[i] = BOOSTED_KERNEL_SLEEF(sleefName)(x.part[i]);                                    \
    }                                                                                            \
    return x;                                                                                    \
  }
BOOSTED_LANE_FUNCTION(laneExp, exp)
BOOSTED_LANE_FUNCTION(laneCosh, cosh)
BOOSTED_LANE_FUNCTION(laneSinh, sinh)
BOOSTED_LANE_FUNCTION(laneTanh, tanh)
#undef BOOSTED_LANE_FUNCTION

BOOSTED_FORCE_INLINE void laneSinCos(const LaneVector& x, LaneVector& sine, LaneVector& cosine)
{
  for (int i = 0; i < kParts; ++i)
  {
    const auto r = BOOSTED_KERNEL_SLEEF(sincos)(x.part[i]);
    sine.part[i] = r.x;
    cosine.part[i] = r.y;
  }
}
#else
#define BOOSTED_LANE_FUNCTION(name)                                                              \
  BOOSTED_FORCE_INLINE LaneVector name(const LaneVector& x)                                       \
  {                                                                                              \
    alignas(64) double lanes[L];                                                                 \
    toLanes(x, lanes);                                                                           \
    for (int l = 0; l < L; ++l)                                                                  \
    {                                                                                            \
      lanes[l] = core::name(lanes[l]);                                                           \
    }                                                                                            \
    LaneVector r;                                                                                \
    fromLanes(lanes, r);                                                                         \
    return r;                                                                                    \
  }
BOOSTED_LANE_FUNCTION(laneExp)
BOOSTED_LANE_FUNCTION(laneCosh)
BOOSTED_LANE_FUNCTION(laneSinh)
BOOSTED_LANE_FUNCTION(laneTanh)
#undef BOOSTED_LANE_FUNCTION

BOOSTED_FORCE_INLINE void laneSinCos(const LaneVector& x, LaneVector& sine, LaneVector& cosine)
{
  alignas(64) double lanes[L], s[L], c[L];
  toLanes(x, lanes);
  for (int l = 0; l < L; ++l)
  {
    core::laneSinCos(lanes[l], s[l], c[l]);
  }
  fromLanes(s, sine);
  fromLanes(c, cosine);
}
#endif

// Correctly rounded, as the scalar sqrt: the instruction set's own (BOOSTED_KERNEL_SQRT) where the
// including file names it.
BOOSTED_FORCE_INLINE LaneVector laneSqrt(LaneVector x)
{
#ifdef BOOSTED_KERNEL_SQRT
  for (int i = 0; i < kParts; ++i)
  {
    x.part[i] = BOOSTED_KERNEL_SQRT(x.part[i]);
  }
  return x;
#else
  alignas(64) double lanes[L];
  toLanes(x, lanes);
  for (int l = 0; l < L; ++l)
  {
    lanes[l] = __builtin_sqrt(lanes[l]);
  }
  fromLanes(lanes, x);
  return x;
#endif
}
} // namespace

} // namespace BOOSTED_KERNEL_ISA
} // namespace kernel
} // namespace cga

#include "PointMapCore.h"
#include "DualNumber.h"
#include "JetBlockMap.h"

namespace cga
{
namespace kernel
{
namespace BOOSTED_KERNEL_ISA
{
#ifndef BOOSTED_KERNEL_WIDE
void mapBlock(const FieldArgs& args, const double* xyz, double* image, std::uint8_t* mapped)
{
  LaneVector p[3], out[3];
  for (int i = 0; i < 3; ++i)
  {
    fromLanes(xyz + i * L, p[i]);
  }
  bool ok[L];
  core::mapPoint(args, p, out, ok);
  for (int i = 0; i < 3; ++i)
  {
    toLanes(out[i], image + i * L);
  }
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = ok[l] ? 1 : 0;
  }
}
#endif

int mapDisplacedBlock(const FieldArgs& args, const double* center, const double* points,
  double* out, double* displacements, std::uint8_t* mapped)
{
  // The transposes as plain loops over the lanes, which the compiler turns into permutes.
  alignas(64) double lanes[3 * L];
  for (int l = 0; l < L; ++l)
  {
    for (int i = 0; i < 3; ++i)
    {
      lanes[i * L + l] = points[3 * l + i];
    }
  }
  LaneVector p[3], relative[3], image[3];
  for (int i = 0; i < 3; ++i)
  {
    fromLanes(lanes + i * L, p[i]);
    relative[i] = p[i] - center[i];
  }
  // The lanes mapped as a mask, not bools: bools turned back into a vector cost a stalled load
  // (eight narrow stores read as one wide load), about a fifth of this function's time.
  const LaneMask isMapped = core::mapPointLanes(args, relative, image);
  const LaneVector zero = core::splat<LaneVector>(0.0);
  // As mapPointsInBlocks writes an image, p + (image - (p - c)), and its displacement; a lane
  // not mapped keeps its point, displacement 0.
  alignas(64) double moved[3 * L], shift[3 * L];
  LaneVector finiteness = zero;
  for (int i = 0; i < 3; ++i)
  {
    const LaneVector o = p[i] + (image[i] - relative[i]);
    const LaneVector d = o - p[i];
    // v - v is 0 for a finite v and NaN otherwise.
    finiteness = finiteness + ((o - o) + (d - d));
    toLanes(select(isMapped, o, p[i]), moved + i * L);
    toLanes(select(isMapped, d, zero), shift + i * L);
  }
  alignas(64) double flags[L], finite[L];
  toLanes(select(isMapped, core::splat<LaneVector>(1.0), zero), flags);
  toLanes(finiteness, finite);
  int beyondRange = 0;
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = flags[l] != 0.0 ? 1 : 0;
    beyondRange += mapped[l] && finite[l] != 0.0 ? 1 : 0;
  }
  for (int l = 0; l < L; ++l)
  {
    for (int i = 0; i < 3; ++i)
    {
      out[3 * l + i] = moved[i * L + l];
    }
  }
  if (displacements)
  {
    for (int l = 0; l < L; ++l)
    {
      for (int i = 0; i < 3; ++i)
      {
        displacements[3 * l + i] = shift[i * L + l];
      }
    }
  }
  return beyondRange;
}

#ifndef BOOSTED_KERNEL_WIDE
void addFieldBlock(const FieldArgs& args, const double* xyz, double* bivectors)
{
  LaneVector p[3], b[core::kBivector];
  for (int i = 0; i < 3; ++i)
  {
    fromLanes(xyz + i * L, p[i]);
  }
  core::fieldBivector(args, p, 1.0, b);
  for (int c = 0; c < core::kBivector; ++c)
  {
    LaneVector sum;
    fromLanes(bivectors + c * L, sum);
    toLanes(sum + b[c], bivectors + c * L);
  }
}
void addFieldJacobianBlock(const FieldArgs& args, const double* xyz, double* bivectors,
  double* gradients)
{
  using Tangent = core::Dual<LaneVector, 3>;
  Tangent p[3], b[core::kBivector];
  for (int i = 0; i < 3; ++i)
  {
    LaneVector value;
    fromLanes(xyz + i * L, value);
    p[i] = core::variable<LaneVector, 3>(value, i);
  }
  core::fieldBivector(args, p, 1.0, b);
  for (int c = 0; c < core::kBivector; ++c)
  {
    LaneVector sum;
    fromLanes(bivectors + c * L, sum);
    toLanes(sum + b[c].v, bivectors + c * L);
    for (int k = 0; k < 3; ++k)
    {
      fromLanes(gradients + (3 * c + k) * L, sum);
      toLanes(sum + b[c].d[k], gradients + (3 * c + k) * L);
    }
  }
}

void mapBlockJacobianBy(const FieldArgs& args, const double* bivectors, const double* gradients,
  const double* xyz, double* image, double* jacobian, std::uint8_t* mapped)
{
  using Tangent = core::Dual<LaneVector, 3>;
  Tangent b[core::kBivector], p[3], out[3];
  for (int c = 0; c < core::kBivector; ++c)
  {
    fromLanes(bivectors + c * L, b[c].v);
    for (int k = 0; k < 3; ++k)
    {
      fromLanes(gradients + (3 * c + k) * L, b[c].d[k]);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    LaneVector value;
    fromLanes(xyz + i * L, value);
    p[i] = core::variable<LaneVector, 3>(value, i);
  }
  bool ok[L];
  core::mapPointBy(args, b, p, out, ok);
  for (int i = 0; i < 3; ++i)
  {
    toLanes(out[i].v, image + i * L);
    for (int k = 0; k < 3; ++k)
    {
      toLanes(out[i].d[k], jacobian + (3 * i + k) * L);
    }
  }
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = ok[l] ? 1 : 0;
  }
}

void sinCosBlock(bool hyperbolic, const double* angles, double* cosines, double* sines)
{
  LaneVector x, c, s;
  fromLanes(angles, x);
  if (hyperbolic)
  {
    c = laneCosh(x);
    s = laneSinh(x);
  }
  else
  {
    laneSinCos(x, s, c);
  }
  toLanes(c, cosines);
  toLanes(s, sines);
}

void mapBlockBy(const FieldArgs& args, double* bivectors, const double* xyz, double* image,
  std::uint8_t* mapped)
{
  LaneVector b[core::kBivector], p[3], out[3];
  for (int c = 0; c < core::kBivector; ++c)
  {
    fromLanes(bivectors + c * L, b[c]);
  }
  for (int i = 0; i < 3; ++i)
  {
    fromLanes(xyz + i * L, p[i]);
  }
  bool ok[L];
  core::mapPointBy(args, b, p, out, ok);
  for (int i = 0; i < 3; ++i)
  {
    toLanes(out[i], image + i * L);
  }
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = ok[l] ? 1 : 0;
  }
}
namespace
{
/// core::mapPoint on N tangents per lane: seeds[(N i + k) * L + l] is component i of tangent k of
/// lane l (the unit vectors e_k when seeds is null: then tangent k is d / d p_k), and
/// derivatives[(N i + k) * L + l] receives d image_i along tangent k (for the unit tangents
/// d image_i / d p_k: J row-major).
template <int N>
void mapBlockTangents(const FieldArgs& args, const double* xyz, const double* seeds, double* image,
  double* derivatives, std::uint8_t* mapped)
{
  using Tangent = core::Dual<LaneVector, N>;
  Tangent p[3], out[3];
  for (int i = 0; i < 3; ++i)
  {
    LaneVector value;
    fromLanes(xyz + i * L, value);
    p[i] = core::constant<LaneVector, N>(value);
    for (int k = 0; k < N; ++k)
    {
      if (seeds)
      {
        fromLanes(seeds + (N * i + k) * L, p[i].d[k]);
      }
      else if (k == i)
      {
        p[i].d[k] = core::splat<LaneVector>(1.0);
      }
    }
  }
  bool ok[L];
  core::mapPoint(args, p, out, ok);
  for (int i = 0; i < 3; ++i)
  {
    toLanes(out[i].v, image + i * L);
    for (int k = 0; k < N; ++k)
    {
      toLanes(out[i].d[k], derivatives + (N * i + k) * L);
    }
  }
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = ok[l] ? 1 : 0;
  }
}
} // namespace

void mapBlockJacobian(const FieldArgs& args, const double* xyz, double* image, double* jacobian,
  std::uint8_t* mapped)
{
  mapBlockTangents<3>(args, xyz, nullptr, image, jacobian, mapped);
}

void mapBlockDirectional(const FieldArgs& args, const double* xyz, const double* directions,
  double* image, double* derivatives, std::uint8_t* mapped)
{
  mapBlockTangents<kDirections>(args, xyz, directions, image, derivatives, mapped);
}

#ifdef BOOSTED_KERNEL_JETS
void mapBlockJets(const FieldArgs& args, const double* bivectorJets, const double* pointJets,
  double* imageJets, std::uint8_t* mapped)
{
  bool ok[L];
  core::mapJetBlockBy<LaneVector>(args, bivectorJets, pointJets, imageJets, ok);
  for (int l = 0; l < L; ++l)
  {
    mapped[l] = ok[l] ? 1 : 0;
  }
}
#endif // BOOSTED_KERNEL_JETS
#endif // BOOSTED_KERNEL_WIDE
} // namespace BOOSTED_KERNEL_ISA
} // namespace kernel
} // namespace cga
