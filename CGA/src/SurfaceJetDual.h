// Internal: a value with its first and second derivatives in two parameters (a, b) (the public
// SurfaceJet of ExponentialMap.h, six parts) as the second-order dual number
// Dual<Dual<T, 2>, 2> of DualNumber.h and back, for T LaneClones.h's Eight (the curvature patch's
// jets of its operators, src/surfaces/CurvaturePatchJet.cpp), the block kernel's lane vector and
// double (JetBlockMap.h: mapJetsByExponential's input and output; the tests' reference).
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

/// A jet's parts in SurfaceJet's order.
inline void partsOf(const SurfaceJet& j, double (&parts)[kJetParts])
{
  parts[0] = j.value;
  parts[1] = j.da;
  parts[2] = j.db;
  parts[3] = j.daa;
  parts[4] = j.dab;
  parts[5] = j.dbb;
}

/// The jet of parts in SurfaceJet's order; false when one is not finite (j is filled anyway).
inline bool jetOf(const double (&parts)[kJetParts], SurfaceJet& j)
{
  j = SurfaceJet{ parts[0], parts[1], parts[2], parts[3], parts[4], parts[5] };
  bool finite = true;
  for (double part : parts)
  {
    finite = finite && std::isfinite(part);
  }
  return finite;
}

inline SurfaceJetDual secondOf(const SurfaceJet& j)
{
  double parts[kJetParts];
  partsOf(j, parts);
  return secondOrderOf(parts);
}

/// False when a value or derivative is not finite (j is filled anyway).
inline bool jetOf(const SurfaceJetDual& x, SurfaceJet& j)
{
  double parts[kJetParts];
  partsOf(x, parts);
  return jetOf(parts, j);
}
} // namespace
} // namespace core
} // namespace cga
