#include "cga/PointPairField.h"

#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

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
  this->Locations.reserve(count);
  this->WeightedPairs.reserve(count);
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
template <typename In, typename Out>
std::size_t mapPointsScalar(const PointPairField& field,
                            const In* in,
                            Out* out,
                            std::size_t count,
                            double strength,
                            ExponentialRule rule)
{
  std::size_t unchanged = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 p{ static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
      static_cast<double>(in[3 * i + 2]) };
    Vec3 image = p;
    if (!field.map(p, strength, rule, image) || !isFinite(image))
    {
      image = p;
      ++unchanged;
    }
    out[3 * i] = static_cast<Out>(image.x);
    out[3 * i + 1] = static_cast<Out>(image.y);
    out[3 * i + 2] = static_cast<Out>(image.z);
  }
  return unchanged;
}
} // namespace

std::size_t PointPairField::mapPoints(
  const double* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsScalar(*this, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsScalar(*this, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsScalar(*this, in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const double* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return mapPointsScalar(*this, in, out, count, strength, rule);
}
} // namespace cga
