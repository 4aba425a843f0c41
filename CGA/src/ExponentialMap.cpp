#include "cga/ExponentialMap.h"

#include "DualNumber.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"
#include "ProductTerms.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace cga
{
std::size_t mapPointsByExponentials(const Bivector* b,
                                    const Vec3* p,
                                    std::size_t count,
                                    ExponentialRule rule,
                                    Vec3* out,
                                    bool* mapped)
{
  constexpr int L = kernel::kLanes;
  constexpr int kBivector = Bivector::Count;
  const kernel::MapBlockBy mapBlockBy = kernel::activeMapBlockBy();
  kernel::FieldArgs args; // no field: only the rule and its tables are read
  args.exactRule = rule == ExponentialRule::Exact;
  args.tables = &detail::boostTables();
  std::size_t unmapped = 0;
  alignas(64) double bivectors[kBivector * L];
  alignas(64) double xyz[3 * L];
  alignas(64) double image[3 * L];
  std::uint8_t ok[L];
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    for (int l = 0; l < L; ++l)
    {
      // The last block repeats its last point in the unused lanes.
      const std::size_t i = first + static_cast<std::size_t>(std::min(l, n - 1));
      for (int c = 0; c < kBivector; ++c)
      {
        bivectors[c * L + l] = b[i].c[c];
      }
      xyz[l] = p[i].x;
      xyz[L + l] = p[i].y;
      xyz[2 * L + l] = p[i].z;
    }
    mapBlockBy(args, bivectors, xyz, image, ok);
    for (int l = 0; l < n; ++l)
    {
      mapped[first + l] = ok[l] != 0;
      if (ok[l])
      {
        out[first + l] = { image[l], image[L + l], image[2 * L + l] };
      }
      else
      {
        ++unmapped;
      }
    }
  }
  return unmapped;
}

namespace
{
// Second order in (a, b): the tangents of the tangents.
using First = core::Dual<double, 2>;
using Second = core::Dual<First, 2>;

Second secondOf(const SurfaceJet& j)
{
  Second x;
  x.v = First{ j.value, { j.da, j.db } };
  x.d[0] = First{ j.da, { j.daa, j.dab } };
  x.d[1] = First{ j.db, { j.dab, j.dbb } };
  return x;
}

bool jetOf(const Second& x, SurfaceJet& j)
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

bool mapJetByExponential(
  const SurfaceJet* bivector, const SurfaceJet* point, ExponentialRule rule, SurfaceJet* image)
{
  kernel::FieldArgs args; // no field: only the rule and its tables are read
  args.exactRule = rule == ExponentialRule::Exact;
  args.tables = &detail::boostTables();
  Second b[Bivector::Count], p[3], out[3];
  for (int c = 0; c < Bivector::Count; ++c)
  {
    b[c] = secondOf(bivector[c]);
  }
  for (int i = 0; i < 3; ++i)
  {
    p[i] = secondOf(point[i]);
  }
  bool mapped = false;
  core::mapPointBy(args, b, p, out, &mapped);
  SurfaceJet result[3];
  if (!mapped || !jetOf(out[0], result[0]) || !jetOf(out[1], result[1]) || !jetOf(out[2], result[2]))
  {
    return false;
  }
  std::copy(result, result + 3, image);
  return true;
}
} // namespace cga
