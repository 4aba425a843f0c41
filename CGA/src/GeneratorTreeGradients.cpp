// GeneratorTree's per-point expansions with B's derivatives d B / d p (evaluatePoints and evaluate
// with gradients): the local polynomial of GeneratorTreeCells.cpp and a node's multipole series of
// GeneratorTree.cpp, the same operations in the same order on the dual numbers of DualNumber.h
// (three tangents: along x, y and z), so that their values are addLocal's and addMultipole's to
// the bit and their tangents the derivatives of the same truncated expansions.
#include "GeneratorTree.h"

#include "DualNumber.h"

#include "cga/Compact.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

// As CurvaturePatchJet.cpp: compiled per instruction set, but not where BOOSTED_FORCE_INLINE is a
// plain inline (AddressSanitizer, coverage): there DualNumber.h's operators on Eight may be called
// out of line, and a 64-byte vector must not cross a call between a clone and the default target.
#ifdef BOOSTED_PLAIN_INLINE
#define BOOSTED_GRADIENT_CLONES
#else
#define BOOSTED_GRADIENT_CLONES BOOSTED_LANE_CLONES
#endif

namespace cga
{
namespace detail
{
namespace
{
constexpr int L = kernel::kLanes;
constexpr int kComponents = Bivector::Count;
using Gradient = core::Dual<Eight, 3>;

/// sums[c L + l] += out[c]'s value (addLanes' sums) and gradients[(3 c + k) L + l] += its
/// tangent k.
BOOSTED_FORCE_INLINE void addGradientLanes(double* sums, double* gradients, const Gradient* out)
{
  for (int c = 0; c < kComponents; ++c)
  {
    Eight sum;
    std::memcpy(&sum, sums + c * L, sizeof sum);
    sum += out[c].v;
    std::memcpy(sums + c * L, &sum, sizeof sum);
    for (int k = 0; k < 3; ++k)
    {
      std::memcpy(&sum, gradients + (3 * c + k) * L, sizeof sum);
      sum += out[c].d[k];
      std::memcpy(gradients + (3 * c + k) * L, &sum, sizeof sum);
    }
  }
}
// Each thread's scratch for the expansions' monomials (up to 2 x 969 dual numbers of 256 bytes:
// too large for a worker thread's stack), on a 64-byte boundary by hand: this function is
// compiled for the default target, where GCC aligns 64-byte vectors to 16 bytes only, and the
// AVX-512 clones store whole vectors there.
thread_local std::vector<double> scratchOfThread;

Gradient* scratch(std::size_t count)
{
  constexpr std::size_t kDoubles = sizeof(Gradient) / sizeof(double), kAlign = 64 / sizeof(double);
  if (scratchOfThread.size() < count * kDoubles + kAlign)
  {
    scratchOfThread.resize(count * kDoubles + kAlign);
  }
  const auto address = reinterpret_cast<std::uintptr_t>(scratchOfThread.data());
  return reinterpret_cast<Gradient*>((address + 63) & ~std::uintptr_t{ 63 });
}
} // namespace

// addLocal on the lanes' points as variables.
BOOSTED_GRADIENT_CLONES
void GeneratorTree::addLocalGradient(const double* local, const double* center, double radius,
                                     const double* p, double* sums, double* gradients) const
{
  const int M = this->MomentCount;
  const double inverse = 1.0 / radius;
  Gradient y[3];
  for (int k = 0; k < 3; ++k)
  {
    Eight coordinate;
    std::memcpy(&coordinate, p + k * L, sizeof coordinate);
    y[k] = core::constant<Eight, 3>((coordinate - center[k]) * inverse);
    y[k].d[k] = Eight{} + inverse;
  }
  Gradient* power = scratch(static_cast<std::size_t>(M));
  this->monomialPowers(y, M, power);
  Gradient out[kComponents];
  this->sumLocal(local, power, out);
  addGradientLanes(sums, gradients, out);
}

// addMultipole on the lanes' points as variables: d = p - c, D, sqrt(k/D), q, u and 1/D per lane
// on Dual<double, 3>, then the series on the lanes.
BOOSTED_GRADIENT_CLONES
void GeneratorTree::addMultipoleGradient(const Node& node, const double* moments, int degree,
                                         const double* p, double* sums, double* gradients) const
{
  using Scalar = core::Dual<double, 3>;
  const int M = monomialCount(degree);
  Gradient u[3], q, scale;
  for (int k = 0; k < 3; ++k)
  {
    u[k] = core::constant<Eight, 3>(Eight{});
  }
  q = scale = core::constant<Eight, 3>(Eight{});
  for (int l = 0; l < L; ++l)
  {
    Scalar d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = core::variable<double, 3>(p[k * L + l] - node.center[k], k);
    }
    const Scalar D = this->Falloff * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + this->Epsilon;
    const Scalar rootKappa = core::laneSqrt(this->Falloff / D);
    const Scalar lanes[5] = { node.radius * rootKappa, rootKappa * d[0], rootKappa * d[1],
                              rootKappa * d[2], 1.0 / D };
    Gradient* targets[5] = { &q, &u[0], &u[1], &u[2], &scale };
    for (int t = 0; t < 5; ++t)
    {
      targets[t]->v[l] = lanes[t].v;
      for (int k = 0; k < 3; ++k)
      {
        targets[t]->d[k][l] = lanes[t].d[k];
      }
    }
  }
  Gradient* power = scratch(2 * static_cast<std::size_t>(M));
  Gradient* e = power + M;
  this->monomialPowers(u, M, power);
  Gradient out[kComponents];
  this->sumSeries(moments, degree, power, q, scale, e, out);
  addGradientLanes(sums, gradients, out);
}
} // namespace detail
} // namespace cga
