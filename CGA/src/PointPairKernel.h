// Internal: the lane kernel behind PointPairField::mapPoints.
//
// kLanes points at a time, in structure-of-arrays form, go through B(p), K = exp(-strength B) and
// the sandwich: the templates of PointMapCore.h instantiated for a vector of kLanes doubles, the
// same source PointPairField::map() instantiates for double. It (PointPairKernelLanes.h) is
// compiled once per instruction set (PointPairKernel<Isa>.cpp, each
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
/// Points per wide block (MapDisplacedWideBlock): two AVX-512 registers per value, two blocks'
/// chains of dependent steps side by side.
constexpr int kWideLanes = 2 * kLanes;

/// Components of a bivector (Compact.h order): of B(p) and of each weighted generator w G.
constexpr int kBivectorComponents = 10;

/// Doubles per generator in FieldArgs::generators, the field's one layout: location x, y, z,
/// then the ten Bivector components (Compact.h order) of the weighted generator w G.
constexpr int kGeneratorStride = 3 + kBivectorComponents;

/// B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps) and what K = exp(-strength B(p)) needs: everything
/// one evaluation of the map, pointwise (PointPairField::map) or per block, reads.
struct FieldArgs
{
  const double* generators = nullptr; // kGeneratorStride doubles per generator
  std::size_t generatorCount = 0;
  double falloff = 1.0;
  double epsilon = 1e-2;
  double strength = 1.0;
  bool exactRule = false;
};

/// Maps kLanes points: xyz holds x[kLanes], y[kLanes], z[kLanes]; image receives the images in
/// the same layout and mapped[l] whether lane l has a finite image (p finite, weight non-zero).
using MapBlock = void (*)(const FieldArgs& args,
                          const double* xyz,
                          double* image,
                          std::uint8_t* mapped);

/// The same for a given exponent per point: K = exp(b) by args' rule (its field and strength are
/// not read), b holding the ten Bivector components of each lane's exponent, component-major
/// (b[c * kLanes + l]); b is overwritten.
using MapBlockBy = void (*)(const FieldArgs& args,
                            double* bivectors,
                            const double* xyz,
                            double* image,
                            std::uint8_t* mapped);

/// mapBlock and its derivative: jacobian receives, component-major, d image_i / d p_j of each
/// lane at jacobian[(3 i + j) * kLanes + l] (forward-mode differentiation of the same source,
/// DualNumber.h: the images are mapBlock's).
using MapBlockJacobian = void (*)(const FieldArgs& args,
                                  const double* xyz,
                                  double* image,
                                  double* jacobian,
                                  std::uint8_t* mapped);

/// Parts per value of MapBlockJets: the value and its first and second derivatives in two
/// parameters (a, b), in SurfaceJet's order (value, d/da, d/db, d2/da2, d2/dadb, d2/db2).
constexpr int kJetParts = 6;

/// mapBlockBy with the first and second derivatives in two parameters (a, b): forward mode on
/// second-order dual numbers (DualNumber.h), the images mapBlockBy's. bivectorJets holds part j of
/// component c of lane l's exponent at bivectorJets[(kJetParts c + j) kLanes + l], pointJets part j
/// of coordinate i at pointJets[(kJetParts i + j) kLanes + l]; imageJets receives the image's in
/// pointJets' layout. AVX-512 only (null elsewhere: mapJetsByExponential maps one lane at a time).
using MapBlockJets = void (*)(const FieldArgs& args,
                              const double* bivectorJets,
                              const double* pointJets,
                              double* imageJets,
                              std::uint8_t* mapped);

/// Adds B(p) of args' generators (falloff and epsilon; strength and rule are not read) to
/// bivectors, component-major (bivectors[c * kLanes + l]): the kernel's generator loop for the
/// generator tree's near field (GeneratorTree.cpp), which sums parts of the generators.
using AddFieldBlock = void (*)(const FieldArgs& args, const double* xyz, double* bivectors);
/// AddFieldBlock with B's derivatives: gradients[(3 c + k) * kLanes + l] += d B_c / d p_k of lane l
/// (forward mode, DualNumber.h: the sums added to bivectors are AddFieldBlock's, to the bit). The
/// generator tree's near field for PointPairField's derivatives.
using AddFieldJacobianBlock = void (*)(const FieldArgs& args,
                                       const double* xyz,
                                       double* bivectors,
                                       double* gradients);
/// MapBlockJacobian for a given exponent b per point and its derivatives d b / d p: bivectors as
/// MapBlockBy's (not overwritten), gradients[(3 c + k) * kLanes + l] = d b_c / d p_k; the images
/// are MapBlockBy's to the bit, the Jacobian MapBlockJacobian's layout. The generator tree's
/// derivatives (the exponent -strength B(p) and its derivatives from the tree).
using MapBlockJacobianBy = void (*)(const FieldArgs& args,
                                    const double* bivectors,
                                    const double* gradients,
                                    const double* xyz,
                                    double* image,
                                    double* jacobian,
                                    std::uint8_t* mapped);
/// cos and sin of kLanes angles (hyperbolic: cosh and sinh), the elementary functions that
/// map() calls (LaneMath.h) on every lane: cosines[l] and sines[l] of angles[l]. The conformal
/// orbit's closed form at eight times at once (Orbit::versors).
using SinCosBlock = void (*)(bool hyperbolic, const double* angles, double* cosines, double* sines);
/// Directions per lane of MapBlockDirectional.
constexpr int kDirections = 2;

/// mapBlock and the derivatives along kDirections given directions per lane (forward mode with
/// kDirections tangents instead of 3: what the transformed normal needs, cof(J) n = J t1 x J t2
/// for t1 x t2 = n). directions holds component i of direction k of lane l at
/// directions[(kDirections i + k) * kLanes + l]; derivatives receives J t_k in the same layout.
using MapBlockDirectional = void (*)(const FieldArgs& args,
                                     const double* xyz,
                                     const double* directions,
                                     double* image,
                                     double* derivatives,
                                     std::uint8_t* mapped);

/// mapBlock on kLanes whole points read from `points` (x, y, z interleaved, in space) relative to
/// center[3], written back in space: out receives p + (image - (p - c)) and displacements
/// out - p, x, y, z interleaved; a lane whose mapped[l] is 0 (as mapBlock's) keeps p,
/// displacement 0 (`points` may be `out`; `displacements` may be null: the images only). Returns
/// the count of mapped lanes whose image or displacement is not finite.
/// The filter's pass (PointPairField::mapPointsWithDisplacements) and mapPoints' whole blocks of
/// double points in the kernel's registers.
using MapDisplacedBlock = int (*)(const FieldArgs& args,
                                  const double* center,
                                  const double* points,
                                  double* out,
                                  double* displacements,
                                  std::uint8_t* mapped);

/// MapDisplacedBlock on kWideLanes points (the same source, the same bits per point), on AVX-512:
/// one block's steps depend on each other (B, its scale, the division, the exponential, the
/// sandwich, the normalization), and two blocks side by side keep the core busier. Measured on
/// the reference machine (AMD EPYC Zen 5), 10^6 points, against two calls of MapDisplacedBlock
/// (a throwaway probe, best of 15): Paper 1.10 to 1.27 times the rate at M = 1 to 64, Exact 1.02
/// to 1.14 (docs/performance.md, *Two blocks side by side*).
using MapDisplacedWideBlock = MapDisplacedBlock;

namespace baseline
{
void mapBlock(const FieldArgs&, const double*, double*, std::uint8_t*);
void mapBlockBy(const FieldArgs&, double*, const double*, double*, std::uint8_t*);
void mapBlockJacobian(const FieldArgs&, const double*, double*, double*, std::uint8_t*);
void mapBlockDirectional(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
void addFieldBlock(const FieldArgs&, const double*, double*);
void addFieldJacobianBlock(const FieldArgs&, const double*, double*, double*);
void mapBlockJacobianBy(
  const FieldArgs&, const double*, const double*, const double*, double*, double*, std::uint8_t*);
void sinCosBlock(bool, const double*, double*, double*);
int mapDisplacedBlock(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
}
#ifdef BOOSTED_KERNEL_X86_DISPATCH
namespace avx2
{
void mapBlock(const FieldArgs&, const double*, double*, std::uint8_t*);
void mapBlockBy(const FieldArgs&, double*, const double*, double*, std::uint8_t*);
void mapBlockJacobian(const FieldArgs&, const double*, double*, double*, std::uint8_t*);
void mapBlockDirectional(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
void addFieldBlock(const FieldArgs&, const double*, double*);
void addFieldJacobianBlock(const FieldArgs&, const double*, double*, double*);
void mapBlockJacobianBy(
  const FieldArgs&, const double*, const double*, const double*, double*, double*, std::uint8_t*);
void sinCosBlock(bool, const double*, double*, double*);
int mapDisplacedBlock(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
}
namespace avx512wide
{
int mapDisplacedBlock(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
}
namespace avx512
{
void mapBlock(const FieldArgs&, const double*, double*, std::uint8_t*);
void mapBlockBy(const FieldArgs&, double*, const double*, double*, std::uint8_t*);
void mapBlockJacobian(const FieldArgs&, const double*, double*, double*, std::uint8_t*);
void mapBlockJets(const FieldArgs&, const double*, const double*, double*, std::uint8_t*);
void mapBlockDirectional(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
void addFieldBlock(const FieldArgs&, const double*, double*);
void addFieldJacobianBlock(const FieldArgs&, const double*, double*, double*);
void mapBlockJacobianBy(
  const FieldArgs&, const double*, const double*, const double*, double*, double*, std::uint8_t*);
void sinCosBlock(bool, const double*, double*, double*);
int mapDisplacedBlock(
  const FieldArgs&, const double*, const double*, double*, double*, std::uint8_t*);
}
#endif
} // namespace kernel
} // namespace cga
