#include "cga/PointPairs.h"

#include "NullPointPairTerms.h"

namespace cga
{
namespace
{
// b += w tau(x, v), the closed form of nullPointPairCompact written into an accumulator.
void addNullPointPair(Bivector& b, double w, Vec3 x, Vec3 v)
{
  const double location[3] = { x.x, x.y, x.z };
  detail::addNullPointPair(b, w, location, v);
}
} // namespace

Bivector nullPointPairCompact(Vec3 location, Vec3 direction)
{
  Bivector b;
  addNullPointPair(b, 1.0, location, direction);
  return b;
}

// T(d) moves each vector of a blade: e_i -> e_i + d_i ni, no -> up(d) = no + d + |d|^2/2 ni,
// ni -> ni, and a bivector as the wedge of its moved vectors (the versor is an outermorphism):
// e_i^e_j gains d_j e_i^ni - d_i e_j^ni; e_i^no gains e_i^d + |d|^2/2 e_i^ni - d_i no^ni
// - d_i d^ni; no^ni gains d^ni; e_i^ni stays. About 50 operations instead of two products of
// even elements (TestFastPaths checks it against the full algebra's T b ~T).
Bivector translatedBivector(const Bivector& b, Vec3 d)
{
  using B = Bivector;
  const double n1 = b[B::E1NO], n2 = b[B::E2NO], n3 = b[B::E3NO];
  const double dn = d.x * n1 + d.y * n2 + d.z * n3; // d . (the e_i^no part)
  const double half = 0.5 * (d.x * d.x + d.y * d.y + d.z * d.z);
  const double along = b[B::NONI] - dn; // the d_j e_j^ni terms' factor
  Bivector r = b;
  r[B::E12] += n1 * d.y - n2 * d.x;
  r[B::E13] += n1 * d.z - n3 * d.x;
  r[B::E23] += n2 * d.z - n3 * d.y;
  r[B::NONI] = along;
  r[B::E1NI] += (d.y * b[B::E12] + d.z * b[B::E13]) + half * n1 + along * d.x;
  r[B::E2NI] += (d.z * b[B::E23] - d.x * b[B::E12]) + half * n2 + along * d.y;
  r[B::E3NI] += -(d.x * b[B::E13] + d.y * b[B::E23]) + half * n3 + along * d.z;
  return r;
}

Vec3 firstOrderMotion(const Bivector& b, Vec3 p)
{
  const Bivector at = translatedBivector(b, -1.0 * p);
  return { 2.0 * at[Bivector::E1NI], 2.0 * at[Bivector::E2NI], 2.0 * at[Bivector::E3NI] };
}

Bivector weightedSum(const Bivector* bivectors, const double* weights, std::size_t count)
{
  Bivector sum;
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int j = 0; j < Bivector::Count; ++j)
    {
      sum[j] += weights[i] * bivectors[i][j];
    }
  }
  return sum;
}

Bivector weightedNullPointPairSum(const Vec3* locations,
                                  const Vec3* directions,
                                  const double* weights,
                                  std::size_t count)
{
  Bivector sum;
  for (std::size_t i = 0; i < count; ++i)
  {
    addNullPointPair(sum, weights[i], locations[i], directions[i]);
  }
  return sum;
}
} // namespace cga
