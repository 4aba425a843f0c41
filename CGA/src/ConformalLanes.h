// Eight conformal vectors side by side (LaneClones.h's Eight): the 5x5 point-map product and
// normalizePoint, in the one-point code's operations and order, so that lane code gives the same
// bits as PointMap::apply (PointMaps::apply: eight maps of one point; the Hopf fibers' circleImages:
// one map of eight points).
#pragma once

#include "cga/Compact.h"

#include "ForceInline.h"
#include "LaneClones.h"

namespace cga
{
namespace detail
{
/// r = M x in applyMatrix's order (each row summed from 0 over j), with entry(i, j) M's entry
/// and x[j] the vector's component: either may be per lane (Eight) or shared (double).
template <class Entry, class Component>
BOOSTED_LANE_INLINE void conformalProduct(Entry entry, const Component* x, Eight* r)
{
  constexpr int C = ConformalVector::Count;
  for (int i = 0; i < C; ++i)
  {
    Eight s = Eight{};
    for (int j = 0; j < C; ++j)
    {
      s += entry(i, j) * x[j];
    }
    r[i] = s;
  }
}

/// normalizePoint on eight lanes: image[k] = r's e_k over its weight -ni.r = r's no component; all
/// ones in the lanes where normalizePoint maps (the weight nonzero and finite, the image finite).
template <class Lanes>
BOOSTED_LANE_INLINE auto normalizedLanes(const Lanes* r, Lanes* image)
{
  const Lanes alpha = r[ConformalVector::NO];
  for (int k = 0; k < 3; ++k)
  {
    image[k] = r[ConformalVector::E1 + k] / alpha;
  }
  return (alpha != 0.0) & finiteLanes(alpha) & finiteLanes(image[0]) & finiteLanes(image[1]) &
    finiteLanes(image[2]);
}
} // namespace detail
} // namespace cga
