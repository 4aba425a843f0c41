#include "cga/CompactConversion.h"

#include "CompactLayout.h"

namespace cga
{
namespace
{
template <std::size_t N>
Multivector fromSlots(const std::array<unsigned, N>& blades, const double* values)
{
  double null[kBladeCount] = {};
  for (std::size_t i = 0; i < N; ++i)
  {
    null[blades[i]] = values[i];
  }
  Multivector m;
  nullToOrthonormal(null, m.c.data());
  return m;
}

template <std::size_t N>
void toSlots(const Multivector& m, const std::array<unsigned, N>& blades, double* values)
{
  double null[kBladeCount];
  orthonormalToNull(m.c.data(), null);
  for (std::size_t i = 0; i < N; ++i)
  {
    values[i] = null[blades[i]];
  }
}
} // namespace

Multivector toMultivector(const ConformalVector& v)
{
  return fromSlots(ConformalVector::kBlades, v.c.data());
}

Multivector toMultivector(const Bivector& b)
{
  return fromSlots(Bivector::kBlades, b.c.data());
}

Multivector toMultivector(const Quadvector& q)
{
  return fromSlots(Quadvector::kBlades, q.c.data());
}

Multivector toMultivector(const Even& k)
{
  const detail::EvenArray a = detail::pack(k);
  return fromSlots(detail::kEvenBlades, a.data());
}

ConformalVector toConformalVector(const Multivector& m)
{
  ConformalVector v;
  toSlots(m, ConformalVector::kBlades, v.c.data());
  return v;
}

Bivector toBivector(const Multivector& m)
{
  Bivector b;
  toSlots(m, Bivector::kBlades, b.c.data());
  return b;
}

Quadvector toQuadvector(const Multivector& m)
{
  Quadvector q;
  toSlots(m, Quadvector::kBlades, q.c.data());
  return q;
}

Even toEven(const Multivector& m)
{
  detail::EvenArray a{};
  toSlots(m, detail::kEvenBlades, a.data());
  return detail::unpack(a);
}
} // namespace cga
