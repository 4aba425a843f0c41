#include "cga/ExponentialMap.h"

#include "JetBlockMap.h"
#include "PointBlocks.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"

#include <algorithm>
#include <cstdint>

namespace cga
{
namespace
{
/// The kernel's arguments for given exponents: no field, only the rule is read.
kernel::FieldArgs argsOf(ExponentialRule rule)
{
  kernel::FieldArgs args;
  args.exactRule = rule == ExponentialRule::Exact;
  return args;
}
} // namespace

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
  const kernel::FieldArgs args = argsOf(rule);
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

namespace
{
/// kernel::MapBlockJets one lane at a time on double (the kernel's template: the same bits), for
/// the instruction sets without a MapBlockJets.
void mapBlockJetsByLane(const kernel::FieldArgs& args, const double* bivectorJets,
  const double* pointJets, double* imageJets, std::uint8_t* mapped)
{
  for (int l = 0; l < kernel::kLanes; ++l)
  {
    bool ok = false;
    core::mapJetBlockBy<double>(args, bivectorJets, pointJets, imageJets, &ok, l);
    mapped[l] = ok ? 1 : 0;
  }
}
} // namespace

std::size_t mapJetsByExponential(const SurfaceJet* bivectors,
                                 const SurfaceJet* points,
                                 std::size_t count,
                                 ExponentialRule rule,
                                 SurfaceJet* images,
                                 bool* mapped)
{
  constexpr int L = kernel::kLanes;
  constexpr int P = kernel::kJetParts;
  constexpr int kBivector = Bivector::Count;
  const kernel::MapBlockJets active = kernel::activeMapBlockJets();
  const kernel::MapBlockJets mapBlockJets = active ? active : &mapBlockJetsByLane;
  const kernel::FieldArgs args = argsOf(rule);
  alignas(64) double bivectorJets[kBivector * P * L];
  alignas(64) double pointJets[3 * P * L];
  alignas(64) double imageJets[3 * P * L];
  std::uint8_t ok[L];
  // Part j of value v of lane l at [(P v + j) L + l], in SurfaceJet's order.
  const auto fill = [](const SurfaceJet& x, double* lanes, int l) {
    double parts[P];
    core::partsOf(x, parts);
    for (int j = 0; j < P; ++j)
    {
      lanes[j * L + l] = parts[j];
    }
  };
  return forEachBlock(
    count,
    [&](int l, std::size_t i) {
      for (int c = 0; c < kBivector; ++c)
      {
        fill(bivectors[kBivector * i + c], bivectorJets + P * c * L, l);
      }
      for (int k = 0; k < 3; ++k)
      {
        fill(points[3 * i + k], pointJets + P * k * L, l);
      }
    },
    [&](std::size_t, int) { mapBlockJets(args, bivectorJets, pointJets, imageJets, ok); },
    [&](std::size_t i, int l) {
      SurfaceJet image[3];
      bool finite = ok[l] != 0;
      for (int k = 0; k < 3; ++k)
      {
        double parts[P];
        for (int j = 0; j < P; ++j)
        {
          parts[j] = imageJets[(P * k + j) * L + l];
        }
        finite = core::jetOf(parts, image[k]) && finite;
      }
      mapped[i] = finite;
      if (finite)
      {
        std::copy(image, image + 3, images + 3 * i);
      }
      return finite;
    });
}

bool mapJetByExponential(
  const SurfaceJet* bivector, const SurfaceJet* point, ExponentialRule rule, SurfaceJet* image)
{
  bool mapped = false;
  mapJetsByExponential(bivector, point, 1, rule, image, &mapped);
  return mapped;
}
} // namespace cga
