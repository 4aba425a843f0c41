#include "cga/DipoleField.h"

#include "ForceInline.h"
#include "LaneClones.h"

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
  , Falloff(falloff)
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
      this->PointPairOf.push_back(-1);
      if (g.kind == GeneratorKind::PointPair)
      {
        this->PointPairOf.back() = static_cast<long>(this->PointPairs.size());
        this->PointPairs.push_back({ g.location, g.direction, g.weight });
        this->LargestPointPairWeight = std::max(this->LargestPointPairWeight, std::fabs(g.weight));
      }
    }
  }
}

namespace
{
// pointPairDisplacement's arithmetic, written once for the scalar function and the lane loop of
// addPointPairDisplacements (the same operations in the same order: the same bits).
//   SCT_u(r) - r = (|r|^2 u - (2 u.r + |u|^2 |r|^2) r) / D, D = 1 + 2 u.r + |u|^2 |r|^2:
// the displacement without the cancellation of r - r. With a = |u| |r|, D = |r/|r| + |r| u|^2 and
// the numerator's length is a |r| sqrt(D), while D's terms are at most (1 + a)^2 and the
// numerator's a |r| (3 + a) in size: where D >= (1 + a^2) / 8 >= (1 + a)^2 / 16, both lose at
// most a factor 16 to cancellation, a few units in the last place of the result. Elsewhere
// (next to the point sent to infinity, D = 0) and where a value is not finite: not accepted.
BOOSTED_FORCE_INLINE bool closedForm(const PointPairGenerator& g, double falloff, double epsilon,
  double weightScale, double px, double py, double pz, double& outX, double& outY, double& outZ)
{
  const double rx = px - g.location.x, ry = py - g.location.y, rz = pz - g.location.z;
  const double r2 = rx * rx + ry * ry + rz * rz;
  const double c = -weightScale * g.weight / (falloff * r2 + epsilon);
  const double ux = c * g.direction.x, uy = c * g.direction.y, uz = c * g.direction.z;
  const double ur = ux * rx + uy * ry + uz * rz;
  const double a2 = (ux * ux + uy * uy + uz * uz) * r2;
  const double d = 1.0 + 2.0 * ur + a2;
  const double t = 2.0 * ur + a2;
  const double inverse = 1.0 / d;
  outX = (r2 * ux - t * rx) * inverse;
  outY = (r2 * uy - t * ry) * inverse;
  outZ = (r2 * uz - t * rz) * inverse;
  const double largest = std::numeric_limits<double>::max();
  // Comparisons only, no branch (the lane loop stays vectorized): NaN fails every one.
  return (std::fabs(r2) <= largest) & (std::fabs(a2) <= largest) & (std::fabs(d) <= largest) &
    (d >= 0.125 * (1.0 + a2)) & (std::fabs(outX) <= largest) & (std::fabs(outY) <= largest) &
    (std::fabs(outZ) <= largest);
}

// closedForm for `count` points given as coordinate arrays: adds each accepted displacement to
// (dx, dy, dz) and sets accepted[i] (0: the caller maps that point another way).
BOOSTED_LANE_CLONES
void addPointPairDisplacements(const PointPairGenerator& g, double falloff, double epsilon,
  double weightScale, const double* x, const double* y, const double* z, std::size_t count,
  double* dx, double* dy, double* dz, unsigned char* accepted)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    double vx, vy, vz;
    const bool ok = closedForm(g, falloff, epsilon, weightScale, x[i], y[i], z[i], vx, vy, vz);
    dx[i] += ok ? vx : 0.0;
    dy[i] += ok ? vy : 0.0;
    dz[i] += ok ? vz : 0.0;
    accepted[i] = ok;
  }
}

// The sum of potential()'s terms for `count` points given as coordinate arrays (the same
// operations in the same order as potential()), added to phi.
BOOSTED_LANE_CLONES
void addPotentialTerms(const PointPairGenerator& g, double relativeWeight, double epsilon,
  const double* x, const double* y, const double* z, std::size_t count, double* phi)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    const double rx = x[i] - g.location.x, ry = y[i] - g.location.y, rz = z[i] - g.location.z;
    const double denominator = (rx * rx + ry * ry + rz * rz) + epsilon;
    phi[i] += relativeWeight *
      (g.direction.x * (rx / denominator) + g.direction.y * (ry / denominator) +
        g.direction.z * (rz / denominator));
  }
}

// The potential's last step (see potential()): phi scaled back, NaN as 0, saturated.
double saturatedPotential(double weightScale, double largestWeight, double phi)
{
  const double value = (weightScale * largestWeight) * phi;
  if (std::isnan(value))
  {
    return 0.0; // opposite terms of directions near 1e308 overflowed: no usable value
  }
  return std::max(-std::numeric_limits<double>::max(), std::min(std::numeric_limits<double>::max(), value));
}
} // namespace

bool pointPairDisplacement(const PointPairGenerator& generator, double falloff, double epsilon,
                           double weightScale, Vec3 p, Vec3& out)
{
  Vec3 displacement;
  if (!closedForm(generator, falloff, epsilon, weightScale, p.x, p.y, p.z, displacement.x,
                  displacement.y, displacement.z))
  {
    return false;
  }
  out = displacement;
  return true;
}

bool DipoleField::singleDisplacement(std::size_t single, Vec3 p, double weightScale, Vec3& out) const
{
  // One generator: method (a)'s computation (its own field is Summed's, to the bit).
  const long pointPair = this->Singles.size() > 1 ? this->PointPairOf[single] : -1;
  if (pointPair >= 0 &&
      pointPairDisplacement(this->PointPairs[static_cast<std::size_t>(pointPair)], this->Falloff,
                            this->Epsilon, weightScale, p, out))
  {
    return true;
  }
  Vec3 image;
  // Method (a)'s rule makes the two methods the same computation for one generator (for a
  // point pair, tau^2 = 0, both rules are exact).
  if (this->Singles[single].map(p, weightScale, this->Rule, image) && isFinite(image))
  {
    out = image - p;
    return true;
  }
  out = Vec3{};
  return false;
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
  for (std::size_t i = 0; i < this->Singles.size(); ++i)
  {
    Vec3 displacement;
    allMapped = this->singleDisplacement(i, p, weightScale, displacement) && allMapped;
    out = out + displacement;
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
  const double largestWeight = this->LargestPointPairWeight;
  if (largestWeight == 0.0 || weightScale == 0.0)
  {
    return 0.0;
  }
  double phi = 0.0;
  for (const PointPairGenerator& g : this->PointPairs)
  {
    addPotentialTerms(g, g.weight / largestWeight, this->Epsilon, &p.x, &p.y, &p.z, 1, &phi);
  }
  return saturatedPotential(weightScale, largestWeight, phi);
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
  }
  if (this->Singles.size() == 1)
  {
    // One generator: method (b) is method (a)'s computation (singleDisplacement), to the bit.
    std::copy_n(summedGenerators, 3 * count, summedDisplacements);
    failures *= 2;
  }
  // Chunks of points as coordinate arrays for the lane loops; per point the generators in their
  // order, as the pointwise methods add them.
  constexpr std::size_t kChunk = 256;
  double x[kChunk], y[kChunk], z[kChunk], dx[kChunk], dy[kChunk], dz[kChunk], phi[kChunk];
  unsigned char accepted[kChunk];
  const double largestWeight = this->LargestPointPairWeight;
  for (std::size_t first = 0; first < count; first += kChunk)
  {
    const std::size_t n = std::min(kChunk, count - first);
    const double* chunk = points + 3 * first;
    for (std::size_t i = 0; i < n; ++i)
    {
      x[i] = chunk[3 * i];
      y[i] = chunk[3 * i + 1];
      z[i] = chunk[3 * i + 2];
      dx[i] = dy[i] = dz[i] = phi[i] = 0.0;
    }
    for (std::size_t s = 0; this->Singles.size() > 1 && s < this->Singles.size(); ++s)
    {
      if (this->PointPairOf[s] < 0)
      {
        double* images = scratch + 3 * first;
        failures += this->Singles[s].mapPoints(chunk, images, n, weightScale, this->Rule);
        for (std::size_t i = 0; i < n; ++i)
        {
          dx[i] += images[3 * i] - chunk[3 * i];
          dy[i] += images[3 * i + 1] - chunk[3 * i + 1];
          dz[i] += images[3 * i + 2] - chunk[3 * i + 2];
        }
        continue;
      }
      const PointPairGenerator& pair =
        this->PointPairs[static_cast<std::size_t>(this->PointPairOf[s])];
      addPointPairDisplacements(pair, this->Falloff, this->Epsilon, weightScale, x, y, z, n, dx,
                                dy, dz, accepted);
      for (std::size_t i = 0; i < n; ++i)
      {
        if (!accepted[i]) // the kernel where the closed form would lose digits
        {
          Vec3 v;
          failures += !this->singleDisplacement(s, Vec3{ x[i], y[i], z[i] }, weightScale, v);
          dx[i] += v.x;
          dy[i] += v.y;
          dz[i] += v.z;
        }
      }
    }
    for (std::size_t k = 0; largestWeight != 0.0 && weightScale != 0.0 && k < this->PointPairs.size(); ++k)
    {
      const PointPairGenerator& g = this->PointPairs[k];
      addPotentialTerms(g, g.weight / largestWeight, this->Epsilon, x, y, z, n, phi);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t at = first + i;
      if (this->Singles.size() != 1)
      {
        summedDisplacements[3 * at] = dx[i];
        summedDisplacements[3 * at + 1] = dy[i];
        summedDisplacements[3 * at + 2] = dz[i];
      }
      const bool finite = isFinite(Vec3{ x[i], y[i], z[i] });
      potentials[at] = finite && largestWeight != 0.0 && weightScale != 0.0
        ? saturatedPotential(weightScale, largestWeight, phi[i])
        : 0.0;
      if (!finite) // NaN - NaN: make the documented zero
      {
        for (int c = 0; c < 3; ++c)
        {
          summedGenerators[3 * at + c] = 0.0;
          summedDisplacements[3 * at + c] = 0.0;
        }
      }
    }
  }
  return failures;
}
} // namespace cga
