#include "cga/PointPairs.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Conformal.h"

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

Bivector translatedBivector(const Bivector& b, Vec3 d)
{
  const Even t = toEven(translator(d));
  return (t * Even::fromBivector(b) * reverse(t)).bivector;
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
