#include "cga/ExponentialMap.h"

#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"
#include "ProductTerms.h"

#include <algorithm>
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
} // namespace cga
