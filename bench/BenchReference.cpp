// The full-multivector reference path, the way the tests compute it: B(p) summed as Multivectors,
// eq 9 on the Multivector, the full sandwich K up(p) ~K and fn. 20,000 of the mesh's points per
// iteration; the rate is per point like the others: Reference/Paper/M:<generators>.
#include "BenchSupport.h"

#include "cga/Conformal.h"

#include <cmath>

namespace
{
using namespace boostedbench;

constexpr std::size_t kReferencePoints = 20000;

cga::Multivector paperExponential(const cga::Multivector& b)
{
  const double s = (b * b).c[0];
  if (s > 0.0)
  {
    const double r = std::sqrt(s);
    return cga::Multivector::scalar(std::cosh(r)) + b * (std::sinh(r) / r);
  }
  if (s < 0.0)
  {
    const double r = std::sqrt(-s);
    return cga::Multivector::scalar(std::cos(r)) + b * (std::sin(r) / r);
  }
  return cga::Multivector::scalar(1.0) + b;
}

void Reference(benchmark::State& state)
{
  const auto generators = benchmarkGenerators(static_cast<int>(state.range(0)));
  std::vector<cga::Multivector> pairs;
  for (const cga::PointPairGenerator& g : generators)
  {
    pairs.push_back(cga::nullPointPair(g.location, g.direction) * g.weight);
  }
  const double* in = benchmarkPoints();
  // Every 50th point, so that the sample covers the whole sheet.
  constexpr std::size_t stride = kMeshPoints / kReferencePoints;
  for (auto _ : state)
  {
    for (std::size_t i = 0; i < kReferencePoints; ++i)
    {
      const double* q = in + 3 * i * stride;
      const cga::Vec3 p{ q[0], q[1], q[2] };
      cga::Multivector b;
      for (std::size_t g = 0; g < pairs.size(); ++g)
      {
        b += pairs[g] * (1.0 / (kFalloff * cga::norm2(p - generators[g].location) + kEpsilon));
      }
      cga::Vec3 image;
      cga::normalizePoint(
        cga::sandwich(paperExponential(b * -kStrength), cga::up(p)).grade(1), image);
      benchmark::DoNotOptimize(image);
    }
  }
  reportPoints(state, kReferencePoints);
}

BENCHMARK(Reference)
  ->Name("Reference/Paper")
  ->ArgsProduct({ generatorCounts() })
  ->ArgNames({ "M" })
  ->Apply(timedPerPoint);
} // namespace
