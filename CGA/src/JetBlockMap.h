// Internal: mapPointBy (PointMapCore.h) on a block's second-order jets in (a, b), the layout of
// kernel::MapBlockJets (part j of value v of lane l at [(kJetParts v + j) kLanes + l]). One
// template for both callers: the kernel's mapBlockJets on its lane vector (all lanes at once) and
// mapJetsByExponential's fallback on double (one lane at a time), so the two agree bit for bit.
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "ForceInline.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "SurfaceJetDual.h"

namespace cga
{
namespace core
{
namespace
{
/// The block's jets of exponents and points mapped by mapPointBy on SecondOrderDual<T>: T the
/// lane vector reads all kLanes lanes (lane 0), T double reads only lane `lane`. mapped receives
/// mapPointBy's flags (kLanesOf<T> of them).
template <typename T>
BOOSTED_FORCE_INLINE void mapJetBlockBy(const kernel::FieldArgs& args, const double* bivectorJets,
  const double* pointJets, double* imageJets, bool* mapped, int lane = 0)
{
  constexpr int L = kernel::kLanes;
  constexpr int P = kJetParts;
  static_assert(P == kernel::kJetParts, "the kernel's jets are SurfaceJetDual.h's");
  const auto secondOrderAt = [lane](const double* parts) {
    T values[P];
    for (int j = 0; j < P; ++j)
    {
      fromLanes(parts + j * L + lane, values[j]);
    }
    return secondOrderOf(values);
  };
  SecondOrderDual<T> b[kBivector], p[3], out[3];
  for (int c = 0; c < kBivector; ++c)
  {
    b[c] = secondOrderAt(bivectorJets + P * c * L);
  }
  for (int i = 0; i < 3; ++i)
  {
    p[i] = secondOrderAt(pointJets + P * i * L);
  }
  mapPointBy(args, b, p, out, mapped);
  for (int i = 0; i < 3; ++i)
  {
    T parts[P];
    partsOf(out[i], parts);
    for (int j = 0; j < P; ++j)
    {
      toLanes(parts[j], imageJets + (P * i + j) * L + lane);
    }
  }
}
} // namespace
} // namespace core
} // namespace cga
