// A field of generators (docs/conventions.md section 3 (item 9), eq 23; also items 8 and 12): at a
// point p the generators sum, each weighted by its inverse squared distance, into
//   B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps),
// with G_i the null point pair tau(x_i, v_i) (or any bivector: FieldGenerator),
// and p moves to fn(K up(p) ~K) with K = exp(-strength B(p)).
//
// This is the one implementation the deformation filter, the dipole field and the curvature
// patches share; its results are tested against the full multivector product.
//
// Far from the origin: the field computes relative to its center c (the mean of its generators'
// locations): the generators and each point are moved by -c and mapped, and the relative
// displacement is added to the point (so a point the map fixes comes back to the bit).
// The map is exactly translation covariant in the algebra, so this changes no result beyond
// rounding, but the rounding is then eps |c| instead of eps |c|^2 (up(p) holds |p|^2): moving a
// whole configuration by t moves its images by t to a few eps |t|.
#pragma once

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cga
{
namespace kernel
{
struct FieldArgs;
}

/// Which exponential turns B(p) into K (docs/conventions.md section 2).
enum class ExponentialRule
{
  Exact, ///< the true exponential: a conformal map, every image point null
  Paper  ///< eq 9-10 with s = <B B>_0, as the paper and its author's library compute it
};

/// exp(b) by the chosen rule (expExact or expPaper, overflow-safe scaling).
Even exponential(const Bivector& b, ExponentialRule rule);

/// One generator of the field: a bivector G placed at a location x, with a weight w; it adds
/// w G / (k |p - x|^2 + eps) to B(p). A point pair is one kind of G (pointPair()); a dual line
/// (rotation, twist), a flat point (dilation) or a translation bivector is another term of the
/// same sum. G is given in space; the field moves it to its center c (translatedBivector), which
/// rounds like |G| |x|^2, so far from the origin build G at x - c instead (point pairs given as
/// PointPairGenerator are: eps |x|).
struct FieldGenerator
{
  Vec3 location;
  Bivector bivector;
  double weight = 1.0;

  /// The null point pair tau(location, direction) (nullPointPairCompact); the direction's length
  /// multiplies the weight.
  static FieldGenerator pointPair(Vec3 location, Vec3 direction, double weight = 1.0);
};

/// A point-pair generator as the filter and the sources describe one (FieldGenerator::pointPair).
struct PointPairGenerator
{
  Vec3 location;
  Vec3 direction;
  double weight = 1.0;
};

class PointPairField
{
public:
  /// falloff k >= 0 and epsilon > 0 (enforced by the callers; epsilon keeps B finite on a
  /// generator's location). Generators with a zero or non-finite direction, location or weight,
  /// or whose pair tau overflows (a location beyond about 1e154), are skipped;
  /// skippedGenerators() counts them.
  PointPairField(const PointPairGenerator* generators,
                 std::size_t count,
                 double falloff,
                 double epsilon);
  explicit PointPairField(const std::vector<PointPairGenerator>& generators,
                          double falloff = 1.0,
                          double epsilon = 1e-2)
    : PointPairField(generators.data(), generators.size(), falloff, epsilon)
  {
  }
  /// The same for generators of any bivector: those with a non-finite location, weight or
  /// bivector, or a zero bivector, are skipped.
  PointPairField(const FieldGenerator* generators,
                 std::size_t count,
                 double falloff,
                 double epsilon);

  std::size_t size() const { return this->Count; }
  std::size_t skippedGenerators() const { return this->Skipped; }
  double falloff() const { return this->Falloff; }
  double epsilon() const { return this->Epsilon; }
  /// The center c the field computes relative to: the mean location of the kept generators.
  Vec3 center() const { return this->Center; }

  /// B(p).
  Bivector generatorAt(Vec3 p) const;

  /// K = exp(-strength B(p)).
  Even boostAt(Vec3 p, double strength, ExponentialRule rule) const;

  /// out = fn(K up(p) ~K). Returns false (out unchanged) when the image is at infinity or not
  /// finite, or p is not finite. With no generators, or strength 0, out = p.
  bool map(Vec3 p, double strength, ExponentialRule rule, Vec3& out) const;

  /// The batch form of map() that the VTK filters call on each chunk of points: `count` points,
  /// xyz interleaved, from `in` to `out` (which may be the same array when the types match).
  /// A point that is not finite, or whose image is not finite, is copied unchanged; the return
  /// value counts them. `out` is written for every point. No heap allocation.
  /// The points go through a vectorized block kernel, the same source as map() instantiated for
  /// a vector of points (every image bit for bit as map() gives it), compiled for several
  /// instruction sets and chosen for the running CPU: see mapPointsInstructionSets().
  std::size_t mapPoints(
    const double* in, double* out, std::size_t count, double strength, ExponentialRule rule) const;
  std::size_t mapPoints(
    const float* in, float* out, std::size_t count, double strength, ExponentialRule rule) const;
  std::size_t mapPoints(
    const float* in, double* out, std::size_t count, double strength, ExponentialRule rule) const;
  std::size_t mapPoints(
    const double* in, float* out, std::size_t count, double strength, ExponentialRule rule) const;

private:
  void add(const FieldGenerator* generators, const PointPairGenerator* pairs, std::size_t count);
  kernel::FieldArgs args(double strength, ExponentialRule rule) const;
  template <typename In, typename Out>
  std::size_t mapPointsOf(
    const In* in, Out* out, std::size_t count, double strength, ExponentialRule rule) const;

  // The one layout of the generators, read by map() and the block kernel alike: per generator 13
  // doubles, the location x_i - c, then the ten components of w_i G_i moved by -c.
  std::vector<double> Generators;
  Vec3 Center;
  std::size_t Count = 0;
  double Falloff = 1.0;
  double Epsilon = 1e-2;
  std::size_t Skipped = 0;
};

/// The instruction sets of mapPoints()' block kernel that this build holds and this CPU runs,
/// narrowest first: "baseline" (the build's default target), and on x86-64 "avx2", "avx512".
std::vector<std::string> mapPointsInstructionSets();

/// The one mapPoints() uses: the widest available, or the one the environment variable
/// BOOSTEDSURFACES_KERNEL_ISA names when it is available.
std::string mapPointsInstructionSet();

/// Makes mapPoints() use the named instruction set (for tests and benchmarks, process-wide).
/// Returns false, changing nothing, when it is not available.
bool useMapPointsInstructionSet(const std::string& name);
} // namespace cga
