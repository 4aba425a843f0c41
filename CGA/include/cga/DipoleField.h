// The dipole displacement field of section 7 (docs/conventions.md section 3 item 12, eq 27-28, Fig 13-14):
// at a point p the displacement v = p' - p of the boost built from point-pair generators, computed
// two ways that agree for one generator and differ for several:
//   (a) summed generators:    p' = fn(K up(p) ~K),  K = exp(-s sum_i w_i tau_i / d_i^2)  (the paper's)
//   (b) summed displacements: v = sum_i (fn(K_i up(p) ~K_i) - p),  K_i = exp(-s w_i tau_i / d_i^2)
// with tau_i = tau(x_i, v_i), d_i^2 = k |p - x_i|^2 + eps, and s a weight scale (1 normally; the
// VTK source's time steps run it from 0 to 1).
//
// Method (a) is PointPairField's map; method (b) is a sum of one-generator fields: a point pair
// alone is a 2-blade whose exponential is 1 + tau, a transversion with a closed form, which
// method (b) evaluates directly (docs/conventions.md section 3 item 12); the other kinds, and a
// point where that form would lose digits, go through one-generator PointPairFields. With a
// single generator method (b) is method (a)'s computation, to the bit. The contour scalar is the
// superposed dipole potential (see potential()).
#pragma once

#include "cga/PointPairField.h"
#include "cga/Vec3.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace cga
{
/// The values of the field at one point.
struct DipoleSample
{
  Vec3 summedGenerators;    ///< displacement by method (a)
  Vec3 summedDisplacements; ///< displacement by method (b)
  double potential = 0.0;   ///< the contour scalar, potential()
};

class DipoleField
{
public:
  /// Generators of any kind as PointPairField takes them (falloff k >= 0, epsilon > 0 enforced
  /// by callers; generators with a zero or non-finite direction, location, pitch or weight are
  /// skipped). `rule` is the exponential of both methods; method (b) exponentiates one generator
  /// at a time, for which both rules are exact except for a Twist of non-zero pitch (not a blade).
  /// Only the point pairs have a dipole potential (see potential()).
  DipoleField(const GeneratorParameters* generators,
              std::size_t count,
              double falloff,
              double epsilon,
              ExponentialRule rule = ExponentialRule::Exact);
  /// The same for point pairs.
  DipoleField(const PointPairGenerator* generators,
              std::size_t count,
              double falloff,
              double epsilon,
              ExponentialRule rule = ExponentialRule::Exact);
  explicit DipoleField(const std::vector<PointPairGenerator>& generators,
                       double falloff = 1.0,
                       double epsilon = 1e-2,
                       ExponentialRule rule = ExponentialRule::Exact)
    : DipoleField(generators.data(), generators.size(), falloff, epsilon, rule)
  {
  }

  std::size_t size() const { return this->Singles.size(); }

  /// Method (a)'s far-field approximation (PointPairField::setTolerance: 0, the default, is the
  /// direct sum; false for NaN or negative). Method (b) maps each generator alone, a sum of
  /// displacements rather than of generators, and stays exact.
  bool setTolerance(double tolerance) { return this->Summed.setTolerance(tolerance); }
  /// Method (a)'s tree cells fitted to the points about to be sampled
  /// (PointPairField::planTreeCells, the points computed by pointsOf).
  int planTreeCells(std::size_t count,
    const std::function<void(std::size_t first, std::size_t n, double* xyz)>& pointsOf)
  {
    return this->Summed.planTreeCells(count, pointsOf);
  }
  std::size_t skippedGenerators() const { return this->Summed.skippedGenerators(); }

  /// Method (a). Returns false (out = zero vector) where p is not finite or its image is at
  /// infinity or not finite.
  bool displacementSummedGenerators(Vec3 p, double weightScale, Vec3& out) const;

  /// Method (b). Returns false where p is not finite or one generator's image of it is at
  /// infinity; that generator then contributes nothing (the others still do).
  bool displacementSummedDisplacements(Vec3 p, double weightScale, Vec3& out) const;

  /// The superposed dipole potential  phi(p) = s sum_i w_i (v_i . r_i) / (|r_i|^2 + eps),
  /// r_i = p - x_i. For one generator and eps -> 0 the first-order displacement of both methods
  /// is -s w |r|^4 / (k |r|^2 + eps) grad((v . r) / |r|^2): antiparallel to grad phi, so the
  /// level sets of phi cross the field at right angles (the equipotential lines of Fig 14).
  /// For several generators it is the sum of their potentials. The other kinds have none (their
  /// first-order fields are not gradients: a rotation's circulates) and add nothing to it, so it
  /// is zero without point pairs. Zero for a non-finite p; it
  /// saturates at +-DBL_MAX where huge weights would overflow it.
  double potential(Vec3 p, double weightScale) const;

  /// Both methods and the potential at p. Returns false if either method failed (see above).
  bool sample(Vec3 p, double weightScale, DipoleSample& out) const;

  /// The batch form for the VTK source: `count` points, xyz interleaved; writes the two
  /// displacements (xyz interleaved) and the potential for every point, equal to sample()'s.
  /// Returns the number of failed maps (a point counts once per method (a) failure and once per
  /// generator of method (b) that failed on it); failed contributions are zero. `scratch` must hold
  /// 3 * count doubles. No other allocation.
  std::size_t sampleMany(const double* points,
                         std::size_t count,
                         double weightScale,
                         double* summedGenerators,
                         double* summedDisplacements,
                         double* potentials,
                         double* scratch) const;

private:
  /// One generator's displacement of p (method (b)'s term): the point pair's closed form, else
  /// its one-generator field. False where the image is at infinity or not finite (out = 0).
  bool singleDisplacement(std::size_t single, Vec3 p, double weightScale, Vec3& out) const;

  PointPairField Summed;              // all generators: method (a)
  std::vector<PointPairField> Singles; // one field per generator: method (b)
  // For each single: its index in PointPairs (evaluated in closed form), or -1 (another kind).
  std::vector<long> PointPairOf;
  std::vector<PointPairGenerator> PointPairs; // the kept point pairs, for the potential
  double LargestPointPairWeight = 0.0;        // of |w| over PointPairs, for the potential
  double Falloff;
  double Epsilon;
  ExponentialRule Rule;
};

/// The displacement of p by one point pair alone, in closed form (docs/conventions.md section 3
/// item 12): K = exp(-c tau(x, v)) = 1 + tau(x, u), u = -c v, c = s w / (k |r|^2 + eps),
/// r = p - x, moves p to x + SCT_u(r). Returns false, writing nothing, where that form is not
/// accurate to a few units in the last place of the displacement (near the point the boost sends
/// to infinity, or where a term overflows): the caller then maps p through the kernel.
bool pointPairDisplacement(const PointPairGenerator& generator, double falloff, double epsilon,
                           double weightScale, Vec3 p, Vec3& out);
} // namespace cga
