#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "BoostProducts.h"
#include "PointMapCore.h"

namespace cga
{
using detail::EvenArray;
using detail::SparseProduct;

Even reverse(const Even& k)
{
  Even r = k;
  r.bivector = -k.bivector;
  return r;
}

Even operator*(const Even& a, const Even& b)
{
  static const SparseProduct table(detail::kEvenBlades, detail::kEvenBlades, detail::kEvenBlades);
  const EvenArray pa = detail::pack(a);
  const EvenArray pb = detail::pack(b);
  EvenArray r{};
  table.apply(pa.data(), pb.data(), r.data());
  return detail::unpack(r);
}

Even operator*(const Bivector& a, const Bivector& b)
{
  static const SparseProduct table(Bivector::kBlades, Bivector::kBlades, detail::kEvenBlades);
  EvenArray r{};
  table.apply(a.c.data(), b.c.data(), r.data());
  return detail::unpack(r);
}

double scalarSquare(const Bivector& b)
{
  return core::scalarSquare(b.c.data());
}

double scalarSquare(const Quadvector& q)
{
  double r = 0.0;
  detail::kQuadvectorSquare.apply(q.c.data(), q.c.data(), &r);
  return r;
}

Quadvector wedge(const Bivector& a, const Bivector& b)
{
  Quadvector r;
  detail::kWedge.apply(a.c.data(), b.c.data(), r.c.data());
  return r;
}

Bivector rightContraction(const Quadvector& q, const Bivector& b)
{
  Bivector r;
  detail::kRightContraction.apply(q.c.data(), b.c.data(), r.c.data());
  return r;
}

double dot(const ConformalVector& p, const ConformalVector& q)
{
  using V = ConformalVector;
  return p[V::E1] * q[V::E1] + p[V::E2] * q[V::E2] + p[V::E3] * q[V::E3] - p[V::NO] * q[V::NI] -
    p[V::NI] * q[V::NO];
}
} // namespace cga
