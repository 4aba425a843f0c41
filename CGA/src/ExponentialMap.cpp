#include "cga/ExponentialMap.h"

#include "DualNumber.h"
#include "PointBlocks.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"
#include "SurfaceJetDual.h"

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
  kernel::FieldArgs args; // no field: only the rule is read
  args.exactRule = rule == ExponentialRule::Exact;
  alignas(64) double bivectors[kBivector * L];
  alignas(64) double xyz[3 * L];
  alignas(64) double image[3 * L];
  std::uint8_t ok[L];
  return forEachBlock(
    count,
    [&](int l, std::size_t i) {
      for (int c = 0; c < kBivector; ++c)
      {
        bivectors[c * L + l] = b[i].c[c];
      }
      xyz[l] = p[i].x;
      xyz[L + l] = p[i].y;
      xyz[2 * L + l] = p[i].z;
    },
    [&](std::size_t, int) { mapBlockBy(args, bivectors, xyz, image, ok); },
    [&](std::size_t i, int l) {
      mapped[i] = ok[l] != 0;
      if (ok[l])
      {
        out[i] = { image[l], image[L + l], image[2 * L + l] };
      }
      return mapped[i];
    });
}

using Second = core::SurfaceJetDual;
using core::jetOf;
using core::secondOf;

bool mapJetByExponential(
  const SurfaceJet* bivector, const SurfaceJet* point, ExponentialRule rule, SurfaceJet* image)
{
  kernel::FieldArgs args; // no field: only the rule is read
  args.exactRule = rule == ExponentialRule::Exact;
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
