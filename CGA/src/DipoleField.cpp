#include "cga/DipoleField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cga
{
DipoleField::DipoleField(const GeneratorParameters* generators,
                         std::size_t count,
                         double falloff,
                         double epsilon,
                         ExponentialRule rule)
  : Summed(generators, count, falloff, epsilon)
  , Epsilon(epsilon)
  , Rule(rule)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    const GeneratorParameters& g = generators[i];
    PointPairField single(&g, 1, falloff, epsilon);
    if (single.size() == 1) // kept by the same rule as in Summed
    {
      this->Singles.push_back(std::move(single));
      if (g.kind == GeneratorKind::PointPair)
      {
        this->PointPairs.push_back({ g.location, g.direction, g.weight });
      }
    }
  }
}

namespace
{
std::vector<GeneratorParameters> pointPairParameters(const PointPairGenerator* generators,
                                                     std::size_t count)
{
  std::vector<GeneratorParameters> parameters;
  parameters.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    parameters.push_back({ GeneratorKind::PointPair, generators[i].location,
                           generators[i].direction, 0.0, generators[i].weight });
  }
  return parameters;
}
} // namespace

DipoleField::DipoleField(const PointPairGenerator* generators,
                         std::size_t count,
                         double falloff,
                         double epsilon,
                         ExponentialRule rule)
  : DipoleField(pointPairParameters(generators, count).data(), count, falloff, epsilon, rule)
{
}

bool DipoleField::displacementSummedGenerators(Vec3 p, double weightScale, Vec3& out) const
{
  Vec3 image;
  if (!this->Summed.map(p, weightScale, this->Rule, image) || !isFinite(image))
  {
    out = Vec3{};
    return false;
  }
  out = image - p;
  return true;
}

bool DipoleField::displacementSummedDisplacements(Vec3 p, double weightScale, Vec3& out) const
{
  out = Vec3{};
  if (!isFinite(p))
  {
    return false;
  }
  bool allMapped = true;
  for (const PointPairField& single : this->Singles)
  {
    Vec3 image;
    // Method (a)'s rule makes the two methods the same computation for one generator (for a
    // point pair, tau^2 = 0, both rules are exact).
    if (single.map(p, weightScale, this->Rule, image) && isFinite(image))
    {
      out = out + (image - p);
    }
    else
    {
      allMapped = false;
    }
  }
  return allMapped;
}

double DipoleField::potential(Vec3 p, double weightScale) const
{
  if (!isFinite(p))
  {
    return 0.0;
  }
  // Weights relative to the largest, and r/(|r|^2 + eps), at most 1/(2 sqrt(eps)) long: huge
  // weights (up to 1e308), directions or distances cannot overflow a term (w v.r did: inf, or
  // inf - inf = NaN with opposite weights). The result saturates at +-DBL_MAX.
  double largestWeight = 0.0;
  for (const PointPairGenerator& g : this->PointPairs)
  {
    largestWeight = std::max(largestWeight, std::fabs(g.weight));
  }
  if (largestWeight == 0.0 || weightScale == 0.0)
  {
    return 0.0;
  }
  double phi = 0.0;
  for (const PointPairGenerator& g : this->PointPairs)
  {
    const Vec3 r = p - g.location;
    phi += (g.weight / largestWeight) * dot(g.direction, r / (norm2(r) + this->Epsilon));
  }
  const double value = (weightScale * largestWeight) * phi;
  if (std::isnan(value))
  {
    return 0.0; // opposite terms of directions near 1e308 overflowed: no usable value
  }
  return std::max(-std::numeric_limits<double>::max(), std::min(std::numeric_limits<double>::max(), value));
}

bool DipoleField::sample(Vec3 p, double weightScale, DipoleSample& out) const
{
  const bool a = this->displacementSummedGenerators(p, weightScale, out.summedGenerators);
  const bool b = this->displacementSummedDisplacements(p, weightScale, out.summedDisplacements);
  out.potential = this->potential(p, weightScale);
  return a && b;
}

std::size_t DipoleField::sampleMany(const double* points,
                                    std::size_t count,
                                    double weightScale,
                                    double* summedGenerators,
                                    double* summedDisplacements,
                                    double* potentials,
                                    double* scratch) const
{
  // mapPoints copies a point it cannot map, so a failed map adds a zero displacement, as in the
  // pointwise methods.
  std::size_t failures = this->Summed.mapPoints(points, scratch, count, weightScale, this->Rule);
  for (std::size_t i = 0; i < 3 * count; ++i)
  {
    summedGenerators[i] = scratch[i] - points[i];
    summedDisplacements[i] = 0.0;
  }
  for (const PointPairField& single : this->Singles)
  {
    failures += single.mapPoints(points, scratch, count, weightScale, this->Rule);
    for (std::size_t i = 0; i < 3 * count; ++i)
    {
      summedDisplacements[i] += scratch[i] - points[i];
    }
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
    potentials[i] = this->potential(p, weightScale);
    if (!isFinite(p)) // NaN - NaN: make the documented zero
    {
      for (int c = 0; c < 3; ++c)
      {
        summedGenerators[3 * i + c] = 0.0;
        summedDisplacements[3 * i + c] = 0.0;
      }
    }
  }
  return failures;
}
} // namespace cga
