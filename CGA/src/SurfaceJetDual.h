// Internal: the public SurfaceJet (value and first and second derivatives in two parameters,
// ExponentialMap.h) as the second-order dual number Dual<Dual<double, 2>, 2> of DualNumber.h and
// back: mapJetByExponential's input and output, and the curvature patch's jets of its operators
// (src/surfaces/CurvaturePatchJet.cpp).
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "cga/ExponentialMap.h"

#include "DualNumber.h"

#include <cmath>

namespace cga
{
namespace core
{
namespace
{
// Second order in (a, b): the tangents of the tangents.
using SurfaceJetDual = Dual<Dual<double, 2>, 2>;

inline SurfaceJetDual secondOf(const SurfaceJet& j)
{
  using First = Dual<double, 2>;
  SurfaceJetDual x;
  x.v = First{ j.value, { j.da, j.db } };
  x.d[0] = First{ j.da, { j.daa, j.dab } };
  x.d[1] = First{ j.db, { j.dab, j.dbb } };
  return x;
}

/// False when a value or derivative is not finite (j is filled anyway).
inline bool jetOf(const SurfaceJetDual& x, SurfaceJet& j)
{
  // x.v.d and x.d[.].v are both the first derivatives; x.d[0].d[1] and x.d[1].d[0] both d2/dadb.
  j.value = x.v.v;
  j.da = x.d[0].v;
  j.db = x.d[1].v;
  j.daa = x.d[0].d[0];
  j.dab = x.d[0].d[1];
  j.dbb = x.d[1].d[1];
  return std::isfinite(j.value) && std::isfinite(j.da) && std::isfinite(j.db) &&
    std::isfinite(j.daa) && std::isfinite(j.dab) && std::isfinite(j.dbb);
}
} // namespace
} // namespace core
} // namespace cga
