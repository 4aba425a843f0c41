#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "SparseProduct.h"

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
  table.accumulate(pa.data(), pb.data(), r.data());
  return detail::unpack(r);
}

Even operator*(const Bivector& a, const Bivector& b)
{
  static const SparseProduct table(Bivector::kBlades, Bivector::kBlades, detail::kEvenBlades);
  EvenArray r{};
  table.accumulate(a.c.data(), b.c.data(), r.data());
  return detail::unpack(r);
}

double scalarSquare(const Bivector& b)
{
  using B = Bivector;
  // e_ij^2 = -1; (e_i no)(e_i ni) and (e_i ni)(e_i no) have scalar part 1; (no^ni)^2 = 1.
  return -(b[B::E12] * b[B::E12] + b[B::E13] * b[B::E13] + b[B::E23] * b[B::E23]) +
    2.0 * (b[B::E1NO] * b[B::E1NI] + b[B::E2NO] * b[B::E2NI] + b[B::E3NO] * b[B::E3NI]) +
    b[B::NONI] * b[B::NONI];
}

double scalarSquare(const Quadvector& q)
{
  static const SparseProduct table(Quadvector::kBlades, Quadvector::kBlades, detail::kScalarBlade);
  double r = 0.0;
  table.accumulate(q.c.data(), q.c.data(), &r);
  return r;
}

Quadvector wedge(const Bivector& a, const Bivector& b)
{
  static const SparseProduct table(Bivector::kBlades, Bivector::kBlades, Quadvector::kBlades);
  Quadvector r;
  table.accumulate(a.c.data(), b.c.data(), r.c.data());
  return r;
}

Bivector rightContraction(const Quadvector& q, const Bivector& b)
{
  static const SparseProduct table(Quadvector::kBlades, Bivector::kBlades, Bivector::kBlades);
  Bivector r;
  table.accumulate(q.c.data(), b.c.data(), r.c.data());
  return r;
}

double dot(const ConformalVector& p, const ConformalVector& q)
{
  using V = ConformalVector;
  return p[V::E1] * q[V::E1] + p[V::E2] * q[V::E2] + p[V::E3] * q[V::E3] - p[V::NO] * q[V::NI] -
    p[V::NI] * q[V::NO];
}
} // namespace cga
