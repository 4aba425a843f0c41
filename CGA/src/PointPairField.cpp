#include "cga/PointPairField.h"

#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "CompactLayout.h"
#include "PointPairKernelDispatch.h"
#include "SparseProduct.h"

#include <algorithm>

namespace cga
{
Even exponential(const Bivector& b, ExponentialRule rule)
{
  return rule == ExponentialRule::Exact ? expExact(b) : expPaper(b);
}

PointPairField::PointPairField(const PointPairGenerator* generators,
                               std::size_t count,
                               double falloff,
                               double epsilon)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  static_assert(kernel::kGeneratorStride == 3 + Bivector::Count, "location, then the pair");
  this->Locations.reserve(count);
  this->WeightedPairs.reserve(count);
  this->PackedGenerators.reserve(count * kernel::kGeneratorStride);
  for (std::size_t i = 0; i < count; ++i)
  {
    const PointPairGenerator& g = generators[i];
    if (!isFinite(g.location) || !isFinite(g.direction) || !std::isfinite(g.weight) ||
      norm2(g.direction) == 0.0)
    {
      ++this->Skipped;
      continue;
    }
    this->Locations.push_back(g.location);
    this->WeightedPairs.push_back(g.weight * nullPointPairCompact(g.location, g.direction));
    const Bivector& pair = this->WeightedPairs.back();
    this->PackedGenerators.insert(
      this->PackedGenerators.end(), { g.location.x, g.location.y, g.location.z });
    this->PackedGenerators.insert(this->PackedGenerators.end(), pair.c.begin(), pair.c.end());
  }
}

Bivector PointPairField::generatorAt(Vec3 p) const
{
  Bivector b;
  for (std::size_t i = 0; i < this->Locations.size(); ++i)
  {
    const double d2 = norm2(p - this->Locations[i]);
    b += this->WeightedPairs[i] * (1.0 / (this->Falloff * d2 + this->Epsilon));
  }
  return b;
}

Even PointPairField::boostAt(Vec3 p, double strength, ExponentialRule rule) const
{
  return exponential(this->generatorAt(p) * (-strength), rule);
}

bool PointPairField::map(Vec3 p, double strength, ExponentialRule rule, Vec3& out) const
{
  if (!isFinite(p))
  {
    return false;
  }
  if (this->Locations.empty() || strength == 0.0)
  {
    out = p;
    return true;
  }
  return sandwichPoint(this->boostAt(p, strength, rule), p, out);
}

namespace
{
// The terms of a sparse product (SparseProduct.h), as plain data for the block kernel, grouped
// by result slot (a stable sort: each slot still sums its terms in SparseProduct's order, so the
// kernel's sums round exactly as accumulate()'s).
class TermTable
{
public:
  explicit TermTable(const detail::SparseProduct& product)
  {
    for (int t = 0; t < product.size(); ++t)
    {
      const detail::ProductTerm& term = product.term(t);
      this->Terms[t] = { term.a, term.b, term.r, term.coefficient };
    }
    this->Size = product.size();
    std::stable_sort(this->Terms.begin(),
                     this->Terms.begin() + this->Size,
                     [](const kernel::KernelTerm& x, const kernel::KernelTerm& y) { return x.r < y.r; });
  }

  kernel::KernelTerms view() const { return { this->Terms.data(), this->Size }; }

private:
  std::array<kernel::KernelTerm, 512> Terms{};
  int Size = 0;
};

// The products of expExact and sandwichGrade1, with the same blade lists as there.
struct ExactRuleTables
{
  TermTable wedge{ detail::SparseProduct(
    Bivector::kBlades, Bivector::kBlades, Quadvector::kBlades) };
  TermTable quadvectorSquare{ detail::SparseProduct(
    Quadvector::kBlades, Quadvector::kBlades, detail::kScalarBlade) };
  TermTable rightContraction{ detail::SparseProduct(
    Quadvector::kBlades, Bivector::kBlades, Bivector::kBlades) };
  TermTable evenTimesVector{ detail::SparseProduct(
    detail::kEvenBlades, ConformalVector::kBlades, detail::kOddBlades) };
  TermTable oddTimesEvenToVector{ detail::SparseProduct(
    detail::kOddBlades, detail::kEvenBlades, ConformalVector::kBlades) };
};

const ExactRuleTables& exactRuleTables()
{
  static const ExactRuleTables tables;
  return tables;
}

template <typename In, typename Out>
void copyPoint(const In* in, Out* out)
{
  out[0] = static_cast<Out>(in[0]);
  out[1] = static_cast<Out>(in[1]);
  out[2] = static_cast<Out>(in[2]);
}

bool finitePoint(double x, double y, double z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

// Without generators or at strength 0 every finite point stays where it is.
template <typename In, typename Out>
std::size_t copyPoints(const In* in, Out* out, std::size_t count)
{
  std::size_t unchanged = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!finitePoint(in[3 * i], in[3 * i + 1], in[3 * i + 2]))
    {
      ++unchanged;
    }
    copyPoint(in + 3 * i, out + 3 * i);
  }
  return unchanged;
}

template <typename In, typename Out>
std::size_t mapPointsInBlocks(const kernel::KernelArgs& args,
                              const In* in,
                              Out* out,
                              std::size_t count)
{
  constexpr int L = kernel::kLanes;
  const kernel::MapBlock mapBlock = kernel::activeMapBlock();
  std::size_t unchanged = 0;
  alignas(64) double xyz[3 * L];
  alignas(64) double image[3 * L];
  std::uint8_t mapped[L];
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    for (int l = 0; l < L; ++l)
    {
      // The last block repeats its last point in the unused lanes.
      const In* p = in + 3 * (first + std::min(l, n - 1));
      xyz[l] = static_cast<double>(p[0]);
      xyz[L + l] = static_cast<double>(p[1]);
      xyz[2 * L + l] = static_cast<double>(p[2]);
    }
    mapBlock(args, xyz, image, mapped);
    for (int l = 0; l < n; ++l)
    {
      Out* o = out + 3 * (first + l);
      if (mapped[l])
      {
        o[0] = static_cast<Out>(image[l]);
        o[1] = static_cast<Out>(image[L + l]);
        o[2] = static_cast<Out>(image[2 * L + l]);
      }
      else
      {
        o[0] = static_cast<Out>(xyz[l]);
        o[1] = static_cast<Out>(xyz[L + l]);
        o[2] = static_cast<Out>(xyz[2 * L + l]);
        ++unchanged;
      }
    }
  }
  return unchanged;
}

template <typename In, typename Out>
std::size_t mapPointsWith(const PointPairField& field,
                          const std::vector<double>& packedGenerators,
                          const In* in,
                          Out* out,
                          std::size_t count,
                          double strength,
                          ExponentialRule rule)
{
  if (field.size() == 0 || strength == 0.0)
  {
    return copyPoints(in, out, count);
  }
  kernel::KernelArgs args;
  args.generators = packedGenerators.data();
  args.generatorCount = field.size();
  args.falloff = field.falloff();
  args.epsilon = field.epsilon();
  args.strength = strength;
  args.exactRule = rule == ExponentialRule::Exact;
  if (args.exactRule)
  {
    const ExactRuleTables& tables = exactRuleTables();
    args.wedge = tables.wedge.view();
    args.quadvectorSquare = tables.quadvectorSquare.view();
    args.rightContraction = tables.rightContraction.view();
    args.evenTimesVector = tables.evenTimesVector.view();
    args.oddTimesEvenToVector = tables.oddTimesEvenToVector.view();
  }
  return mapPointsInBlocks(args, in, out, count);
}
} // namespace

std::size_t PointPairField::mapPoints(
  const double* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsWith(*this, this->PackedGenerators, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsWith(*this, this->PackedGenerators, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsWith(*this, this->PackedGenerators, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const double* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsWith(*this, this->PackedGenerators, in, out, count, strength, rule);
}

std::vector<std::string> mapPointsInstructionSets()
{
  return kernel::availableInstructionSets();
}

std::string mapPointsInstructionSet()
{
  return kernel::activeInstructionSet();
}

bool useMapPointsInstructionSet(const std::string& name)
{
  return kernel::useInstructionSet(name);
}
} // namespace cga
