// Picks the block kernel for the running CPU: the widest instruction set it supports among those
// compiled (PointPairKernel.h), unless BOOSTEDSURFACES_KERNEL_ISA names another available one.
#include "PointPairKernelDispatch.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace cga
{
namespace kernel
{
namespace
{
struct Candidate
{
  const char* name;
  MapBlock block;
  MapBlockBy blockBy;
  MapBlockJacobian blockJacobian;
  MapBlockJets blockJets; // null: none (mapJetsByExponential's lane-by-lane loop)
  MapBlockDirectional blockDirectional;
  AddFieldBlock addField;
  AddFieldJacobianBlock addFieldJacobian;
  MapBlockJacobianBy blockJacobianBy;
  SinCosBlock sinCos;
  MapDisplacedBlock displacedBlock;
  MapDisplacedWideBlock displacedWideBlock; // null: none
  bool (*supported)();
};

bool always()
{
  return true;
}

#ifdef BOOSTED_KERNEL_X86_DISPATCH
bool hasAvx2()
{
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

bool hasAvx512()
{
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
    __builtin_cpu_supports("avx512vl");
}
#endif

// Narrowest first.
const Candidate kCandidates[] = {
  { "baseline", &baseline::mapBlock, &baseline::mapBlockBy, &baseline::mapBlockJacobian, nullptr,
    &baseline::mapBlockDirectional, &baseline::addFieldBlock,
    &baseline::addFieldJacobianBlock, &baseline::mapBlockJacobianBy, &baseline::sinCosBlock,
    &baseline::mapDisplacedBlock, nullptr, &always },
#ifdef BOOSTED_KERNEL_X86_DISPATCH
  { "avx2", &avx2::mapBlock, &avx2::mapBlockBy, &avx2::mapBlockJacobian, nullptr,
    &avx2::mapBlockDirectional, &avx2::addFieldBlock,
    &avx2::addFieldJacobianBlock, &avx2::mapBlockJacobianBy, &avx2::sinCosBlock,
    &avx2::mapDisplacedBlock, nullptr, &hasAvx2 },
  { "avx512", &avx512::mapBlock, &avx512::mapBlockBy, &avx512::mapBlockJacobian,
    &avx512::mapBlockJets, &avx512::mapBlockDirectional, &avx512::addFieldBlock,
    &avx512::addFieldJacobianBlock, &avx512::mapBlockJacobianBy,
    &avx512::sinCosBlock, &avx512::mapDisplacedBlock, &avx512wide::mapDisplacedBlock,
    &hasAvx512 },
#endif
};
constexpr int kCandidateCount = sizeof(kCandidates) / sizeof(kCandidates[0]);

int findAvailable(const char* name)
{
  for (int i = 0; i < kCandidateCount; ++i)
  {
    if (std::strcmp(kCandidates[i].name, name) == 0 && kCandidates[i].supported())
    {
      return i;
    }
  }
  return -1;
}

int defaultChoice()
{
  if (const char* requested = std::getenv("BOOSTEDSURFACES_KERNEL_ISA"))
  {
    const int i = findAvailable(requested);
    if (i >= 0)
    {
      return i;
    }
  }
  int best = 0;
  for (int i = 0; i < kCandidateCount; ++i)
  {
    if (kCandidates[i].supported())
    {
      best = i;
    }
  }
  return best;
}

std::atomic<int>& choice()
{
  static std::atomic<int> chosen{ defaultChoice() };
  return chosen;
}
} // namespace

MapBlock activeMapBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].block;
}

AddFieldJacobianBlock activeAddFieldJacobianBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].addFieldJacobian;
}

MapBlockJacobianBy activeMapBlockJacobianBy()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].blockJacobianBy;
}

MapBlockBy activeMapBlockBy()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].blockBy;
}

MapBlockJacobian activeMapBlockJacobian()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].blockJacobian;
}

MapBlockJets activeMapBlockJets()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].blockJets;
}

MapBlockDirectional activeMapBlockDirectional()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].blockDirectional;
}

MapDisplacedBlock activeMapDisplacedBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].displacedBlock;
}

MapDisplacedWideBlock activeMapDisplacedWideBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].displacedWideBlock;
}
AddFieldBlock activeAddFieldBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].addField;
}

SinCosBlock activeSinCosBlock()
{
  return kCandidates[choice().load(std::memory_order_relaxed)].sinCos;
}

void activeFieldBivector(const FieldArgs& args, const double* p, double scale, double* b)
{
  // Every lane holds p; the sums start at +0, so adding them to 0 changes no bit.
  double xyz[3 * kLanes], sums[kBivectorComponents * kLanes] = {};
  for (int k = 0; k < 3; ++k)
  {
    for (int l = 0; l < kLanes; ++l)
    {
      xyz[k * kLanes + l] = p[k];
    }
  }
  activeAddFieldBlock()(args, xyz, sums);
  for (int c = 0; c < kBivectorComponents; ++c)
  {
    b[c] = sums[c * kLanes] * scale;
  }
}

std::vector<std::string> availableInstructionSets()
{
  std::vector<std::string> names;
  for (const Candidate& candidate : kCandidates)
  {
    if (candidate.supported())
    {
      names.emplace_back(candidate.name);
    }
  }
  return names;
}

std::string activeInstructionSet()
{
  return kCandidates[choice().load()].name;
}

bool useInstructionSet(const std::string& name)
{
  const int i = findAvailable(name.c_str());
  if (i < 0)
  {
    return false;
  }
  choice().store(i);
  return true;
}
} // namespace kernel
} // namespace cga
