// Internal: a value with its first and second derivatives in two parameters (a, b) (the public
// SurfaceJet of ExponentialMap.h, six parts) as the second-order dual number
// Dual<Dual<T, 2>, 2> of DualNumber.h and back, for T double (the curvature patch's jets of its
// operators, src/surfaces/CurvaturePatchJet.cpp) or the block kernel's lane vector (the kernel's
// mapBlockJets, mapJetsByExponential's input and output).
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
template <typename T>
using SecondOrderDual = Dual<Dual<T, 2>, 2>;
using SurfaceJetDual = SecondOrderDual<double>;

/// The parts of a jet, in SurfaceJet's order: value, da, db, daa, dab, dbb.
constexpr int kJetParts = 6;

template <typename T>
BOOSTED_FORCE_INLINE SecondOrderDual<T> secondOrderOf(const T (&parts)[kJetParts])
{
  SecondOrderDual<T> x;
  x.v = Dual<T, 2>{ parts[0], { parts[1], parts[2] } };
  x.d[0] = Dual<T, 2>{ parts[1], { parts[3], parts[4] } };
  x.d[1] = Dual<T, 2>{ parts[2], { parts[4], parts[5] } };
  return x;
}

/// x.v.d and x.d[.].v are both the first derivatives; x.d[0].d[1] and x.d[1].d[0] both d2/dadb.
template <typename T>
BOOSTED_FORCE_INLINE void partsOf(const SecondOrderDual<T>& x, T (&parts)[kJetParts])
{
  parts[0] = x.v.v;
  parts[1] = x.d[0].v;
  parts[2] = x.d[1].v;
  parts[3] = x.d[0].d[0];
  parts[4] = x.d[0].d[1];
  parts[5] = x.d[1].d[1];
}

inline SurfaceJetDual secondOf(const SurfaceJet& j)
{
  const double parts[kJetParts] = { j.value, j.da, j.db, j.daa, j.dab, j.dbb };
  return secondOrderOf(parts);
}

/// False when a value or derivative is not finite (j is filled anyway).
inline bool jetOf(const SurfaceJetDual& x, SurfaceJet& j)
{
  double parts[kJetParts];
  partsOf(x, parts);
  j = SurfaceJet{ parts[0], parts[1], parts[2], parts[3], parts[4], parts[5] };
  return std::isfinite(j.value) && std::isfinite(j.da) && std::isfinite(j.db) &&
    std::isfinite(j.daa) && std::isfinite(j.dab) && std::isfinite(j.dbb);
}
} // namespace
} // namespace core
} // namespace cga
