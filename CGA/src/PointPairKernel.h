// Internal: the lane kernel behind PointPairField::mapPoints.
//
// kLanes points at a time, in structure-of-arrays form, go through B(p), K = exp(-strength B) and
// the sandwich with plain loops over the lanes that the compiler vectorizes. The same source
// (PointPairKernelLanes.h) is compiled once per instruction set (PointPairKernel<Isa>.cpp, each
// with its own compile options and namespace) and PointPairKernelDispatch.cpp picks the best one
// the running CPU supports, so the default build runs everywhere without -march=native.
//
// Only plain data crosses this interface: a translation unit compiled for AVX-512 must not emit
// an inline function of a shared header, which the linker could then hand to baseline code.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cga
{
namespace kernel
{
/// Points per block. Eight doubles fill one AVX-512 register, two AVX2 or four SSE2 registers.
constexpr int kLanes = 8;

/// Doubles per generator in KernelField::generators: location x, y, z, then the ten Bivector
/// components (Compact.h order) of w tau(x, v).
constexpr int kGeneratorStride = 13;

/// One term r[r] += coefficient a[a] b[b] of a sparse product (SparseProduct.h), as plain data.
struct KernelTerm
{
  std::uint8_t a, b, r;
  double coefficient;
};

/// The terms of one sparse product, sorted by result slot, each slot's in SparseProduct's order.
struct KernelTerms
{
  const KernelTerm* terms = nullptr;
  int size = 0;
};

/// Everything one call of a block kernel needs.
struct KernelArgs
{
  const double* generators = nullptr; // kGeneratorStride doubles per generator
  std::size_t generatorCount = 0;
  double falloff = 1.0;
  double epsilon = 1e-2;
  double strength = 1.0;
  bool exactRule = false;
  // The products expExact and sandwichGrade1 use (CompactAlgebra.cpp, PointSandwich.cpp), for
  // the Exact rule: B ^ B, Q Q, Q _| B; K X (even times vector into odd) and <(K X) ~K>_1.
  KernelTerms wedge, quadvectorSquare, rightContraction;
  KernelTerms evenTimesVector, oddTimesEvenToVector;
};

/// Maps kLanes points: xyz holds x[kLanes], y[kLanes], z[kLanes]; image receives the images in
/// the same layout and mapped[l] whether lane l has a finite image (p finite, weight non-zero).
using MapBlock = void (*)(const KernelArgs& args,
                          const double* xyz,
                          double* image,
                          std::uint8_t* mapped);

namespace baseline
{
void mapBlock(const KernelArgs&, const double*, double*, std::uint8_t*);
}
#ifdef BOOSTED_KERNEL_X86_DISPATCH
namespace avx2
{
void mapBlock(const KernelArgs&, const double*, double*, std::uint8_t*);
}
namespace avx512
{
void mapBlock(const KernelArgs&, const double*, double*, std::uint8_t*);
}
#endif
} // namespace kernel
} // namespace cga
