// A field of generators (docs/conventions.md section 3 (item 9), eq 23; also items 8 and 12): at a
// point p the generators sum, each weighted by its inverse squared distance, into
//   B(p) = sum_i w_i G_i / (k |p - x_i|^2 + eps),
// with G_i the null point pair tau(x_i, v_i), a generator of another kind (GeneratorKind:
// rotation, twist, dilation, translation; docs/conventions.md section 2 item 11) or any bivector,
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
#include <functional>
#include <memory>
#include <string>
#include <optional>
#include <vector>

namespace cga
{
namespace kernel
{
struct FieldArgs;
}
namespace detail
{
class GeneratorTree;
}

/// Which exponential turns B(p) into K (docs/conventions.md section 2).
enum class ExponentialRule
{
  Exact, ///< the true exponential: a conformal map, every image point null
  Paper  ///< eq 9-10 with s = <B B>_0, as the paper and its author's library compute it
};

/// exp(b) by the chosen rule (expExact or expPaper, overflow-safe scaling).
Even exponential(const Bivector& b, ExponentialRule rule);

/// The kinds of generator G (docs/conventions.md section 2 item 11). The values are the VTK
/// classes' constants and the ParaView enumeration's; PointPair is the default.
enum class GeneratorKind
{
  PointPair = 0,  ///< tau(x, v): a boost (a transversion about x)
  Rotation = 1,   ///< half the dual line through x along v: a rotation about that axis
  Twist = 2,      ///< a dual line with a pitch: a screw about the axis through x along v
  Dilation = 3,   ///< minus half the flat point at x: a uniform scaling about x
  Translation = 4 ///< half of v ni: a translation along v
};

/// True for the five kinds above (an integer cast to GeneratorKind may be none of them).
bool isGeneratorKind(int kind);

/// One generator of the field: a bivector G placed at a location x, with a weight w; it adds
/// w G / (k |p - x|^2 + eps) to B(p). With K = exp(-strength B(p)) and c = strength w |v| /
/// (k |p - x|^2 + eps) for a generator alone (|v| the direction's or axis's length, 1 for a
/// dilation), the map of p is, in closed form:
///   pointPair:   the transversion of weight -c v/|v| about x (docs/conventions.md section 2);
///   rotation:    the turn by the angle c (radians) about the axis through x along v, right-handed
///                (a positive angle turns counter-clockwise seen from the tip of v);
///   twist:       that turn and the advance pitch * c along v/|v| (they commute; pitch: a length per
///                radian, 2 pi pitch per full turn; pitch 0 is the rotation);
///   dilation:    the scaling about x by the factor exp(c) (a positive weight grows);
///   translation: the translation by c v/|v|; the location only places the falloff.
/// Directions and axes of any finite non-zero length; a zero or non-finite one gives a NaN weight,
/// which PointPairField skips (and counts), as it does any non-finite bivector.
/// G is given in space; the field moves it to its center c: the named constructors keep it about
/// the origin too (atOrigin), which the field moves by x - c (eps |x|, exact for a lone generator,
/// as rows given as PointPairGenerator or GeneratorParameters are built at x - c); a bivector given
/// without it is moved by -c (translatedBivector), which rounds like |G| |x|^2. The fields are
/// public: a caller may edit any of them, and the field then uses what was edited (atOrigin only
/// where, moved to the location, it is the bivector to rounding; otherwise it is ignored).
struct FieldGenerator
{
  Vec3 location;
  Bivector bivector;
  double weight = 1.0;
  /// The same generator built about the origin, when known (every named constructor and of()
  /// set it): the field then moves it by x - c, which is exact for a lone generator (x = c), so a
  /// point on it stays on it to the bit, as with rows. Without it, or when it is stale (moved to
  /// `location` it differs from `bivector` by more than 64 units of 2^-53 of |atOrigin|
  /// (1 + |location|)^2 in a component: `bivector`, `location` or it edited after construction),
  /// the field moves `bivector` by -c.
  std::optional<Bivector> atOrigin;

  /// The null point pair tau(location, direction) (nullPointPairCompact).
  static FieldGenerator pointPair(Vec3 location, Vec3 direction, double weight = 1.0);
  /// 1/2 T(x) (axis I3) ~T(x), I3 = e1 e2 e3 (axis e3 gives e1^e2, which turns e1 toward e2).
  static FieldGenerator rotation(Vec3 location, Vec3 axis, double weight = 1.0);
  /// rotation(location, axis) + 1/2 pitch axis ni.
  static FieldGenerator twist(Vec3 location, Vec3 axis, double pitch, double weight = 1.0);
  /// -1/2 T(x) (no ^ ni) ~T(x) = -1/2 up(x) ^ ni.
  static FieldGenerator dilation(Vec3 location, double weight = 1.0);
  /// 1/2 direction ni, placed at location (where its falloff distance is measured from).
  static FieldGenerator translation(Vec3 location, Vec3 direction, double weight = 1.0);
  /// The generator of the given kind, as the VTK classes' rows describe one: the direction is
  /// the point pair's, the axis of a rotation or twist, the translation's direction; for a
  /// dilation only its length counts (it multiplies the weight, as for every kind). The pitch is
  /// read by Twist only. An unknown kind, like a zero or non-finite direction or a non-finite
  /// pitch, gives a NaN weight (skipped by the field).
  static FieldGenerator of(
    GeneratorKind kind, Vec3 location, Vec3 direction, double pitch, double weight = 1.0);
};

/// A point-pair generator as the filter and the sources describe one (FieldGenerator::pointPair).
struct PointPairGenerator
{
  Vec3 location;
  Vec3 direction;
  double weight = 1.0;
};

/// A generator of any kind as the filter and the sources describe one (FieldGenerator::of).
struct GeneratorParameters
{
  GeneratorKind kind = GeneratorKind::PointPair;
  Vec3 location;
  Vec3 direction;
  double pitch = 0.0;
  double weight = 1.0;

  FieldGenerator field() const
  {
    return FieldGenerator::of(this->kind, this->location, this->direction, this->pitch, this->weight);
  }
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
  /// The same for generators of any kind (GeneratorParameters::field()).
  PointPairField(const GeneratorParameters* generators,
                 std::size_t count,
                 double falloff,
                 double epsilon);
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
  /// The center c the field computes relative to: per coordinate, the mean of the kept generators'
  /// locations where every one lies within [0.6, 1.6] times it, else 0, so that p - x_i formed from
  /// p - c and x_i - c is the difference of the given doubles (docs/conventions.md section 2 item 12).
  Vec3 center() const { return this->Center; }

  /// The far-field approximation of B(p) (docs/conventions.md section 3 item 14): with a
  /// tolerance t > 0, B(p) is summed by a tree over the generators whose error is bounded at
  /// every point in the image's terms: to first order in the error dB of B(p), the image under
  /// strength s moves by s firstOrderMotion(dB, p) (PointPairs.h), and the tree keeps
  ///   |firstOrderMotion(B_tree(p) - B(p), p)| <= t V,
  /// V = treeDisplacementScale(), the field's displacement scale per unit strength (the largest
  /// first-order displacement |firstOrderMotion(B(x), x)| of the direct sum over sample points x
  /// spread over the generators): the image errs by at most t times the displacement scale s V,
  /// to first order, whatever s. generatorAt, map and mapPoints use it; local expansions about
  /// cubes of a fixed lattice holding the points of a mapPoints call make B(p) depend on p alone,
  /// not on the call (map() of one point gives mapPoints' bits, but pays for a whole column of
  /// cubes, and mapPoints should get many points at once). 0 (the default) is the
  /// direct sum. A tolerance above maximumTolerance() is used as maximumTolerance(). Returns false,
  /// changing nothing, for a NaN or negative tolerance. Fields of fewer than `minimumGenerators`
  /// generators (default treeMinimumGenerators()), and tolerances below `minimumTolerance`
  /// (default, or negative: treeMinimumTolerance() of the field's generator count), always sum
  /// directly: the measured crossovers below which the direct sum is faster (tests and the bench
  /// pass smaller values). The tree takes O(M) memory (treeBytes()).
  bool setTolerance(double tolerance,
                    std::size_t minimumGenerators = treeMinimumGenerators(),
                    double minimumTolerance = -1.0);
  /// setTolerance with `previous`'s tree, shared (a tree is read-only), where it is the tree that
  /// setTolerance(tolerance, minimumGenerators, minimumTolerance) would build: `previous` holds a
  /// tree for the same tolerance (as used) and was made from the same kept generators, falloff
  /// and epsilon, bit for bit. Then the tolerance is set, no tree is built, every result is the
  /// same bits as after that setTolerance, and it returns true. Otherwise nothing changes and it
  /// returns false: call setTolerance. For callers that update often with the same generators
  /// (the deformation filter keeps its last field, so that a new Strength or time step does not
  /// build the tree again).
  bool shareTree(const PointPairField& previous, double tolerance,
                 std::size_t minimumGenerators = treeMinimumGenerators(),
                 double minimumTolerance = -1.0);
  /// Whether this field and `other` use one tree (shareTree).
  bool sharesTreeWith(const PointPairField& other) const;
  /// Whether setTolerance(tolerance, minimumGenerators, minimumTolerance) builds a tree for a
  /// field of `generators` kept generators (size()).
  static bool usesTree(double tolerance, std::size_t generators,
                       std::size_t minimumGenerators = treeMinimumGenerators(),
                       double minimumTolerance = -1.0);
  double tolerance() const { return this->Tolerance; }
  static constexpr double maximumTolerance() { return 1.0; }
  static constexpr std::size_t treeMinimumGenerators() { return 10000; }
  /// The least tolerance at which M generators are summed by the tree by default,
  /// 1e-4 (10,000/M)^3 (at most 1): the tree's cost grows with the digits asked for and the
  /// direct sum's with M; measured on the bench's field in calls of 65,536 points, where the tree
  /// was 0.99, 1.04 and 1.35 times as fast as the direct sum at this tolerance for M = 10,000,
  /// 30,000 and 100,000 (1e-4, 3.7e-6, 1e-7) (README, Performance, Many generators).
  static double treeMinimumTolerance(std::size_t generators);
  /// Fits the tree's target cells to the points about to be mapped (`count` points, xyz
  /// interleaved: all of them, before they are split into calls or threads). The tree expands
  /// its far field about every cube of a lattice that holds points of a mapPoints call. Its
  /// leaves are sized for the field (35 points each on the bench's 10^6-point sheet); on a
  /// sparse mesh they hold one point or none, and each expansion costs far more than its point
  /// gains (10,000 points with 100,000 generators mapped 4 times slower than the direct sum).
  /// So the leaves are made 2^k times as wide, k >= 0 the least at which they hold at least
  /// treeCellPoints() points on average: counted in the leaves that each call of
  /// treePlanChunk() consecutive points would expand, on at most treePlanChunks() such chunks
  /// spread over the points. Returns k. k is 0 without a tree, and after setTolerance or
  /// shareTree until planned again. The bound holds at every cell size. Every later call uses
  /// these cells, so B(p) depends on p and this plan: the same bits whatever the chunking or the
  /// threads.
  int planTreeCells(const double* points, std::size_t count);
  int planTreeCells(const float* points, std::size_t count);
  /// planTreeCells for `count` points computed rather than stored (a grid's):
  /// pointsOf(first, n, xyz) writes points first ... first + n - 1 to xyz, interleaved.
  int planTreeCells(std::size_t count,
    const std::function<void(std::size_t first, std::size_t n, double* xyz)>& pointsOf);
  int treeCellsCoarser() const { return this->TreeCellsCoarser; }
  static constexpr std::size_t treeCellPoints() { return 16; }
  static constexpr std::size_t treePlanChunk() { return 65536; }
  static constexpr std::size_t treePlanChunks() { return 8; }
  /// Bytes the tree holds (0 without one), its expansion degree (0 without one), and V, the
  /// displacement scale per unit strength its budget is relative to (0 without one).
  std::size_t treeBytes() const;
  int treeDegree() const;
  double treeDisplacementScale() const;

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
  /// value counts them. A float out holds an image beyond the largest float (3.4e38) as inf, as
  /// the conversion rounds it: the VTK classes turn that into an error. `out` is written for every point. No heap allocation
  /// without a tree (setTolerance); with one, O(count) scratch, about 150 bytes per point.
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

  /// What mapPointsWithDisplacements found among its points.
  struct DisplacementCounts
  {
    std::size_t unchanged = 0;  ///< points copied unchanged: mapPoints' return value
    std::size_t notFinite = 0;  ///< of those, the points that are NaN or infinite
    std::size_t beyondRange = 0; ///< finite points whose image or displacement is not finite in Out
  };

  /// mapPoints, and in the same pass over the points each displacement out - in, computed in
  /// double from the written image and rounded to Out (0 for a point that is not finite): the
  /// deformation filter's Displacement array without a second pass over memory, while each
  /// block of points is still in cache. `out` and `displacements` must not overlap `in`.
  DisplacementCounts mapPointsWithDisplacements(const double* in, double* out,
    double* displacements, std::size_t count, double strength, ExponentialRule rule) const;
  DisplacementCounts mapPointsWithDisplacements(const float* in, float* out,
    float* displacements, std::size_t count, double strength, ExponentialRule rule) const;
  DisplacementCounts mapPointsWithDisplacements(const float* in, double* out,
    double* displacements, std::size_t count, double strength, ExponentialRule rule) const;
  DisplacementCounts mapPointsWithDisplacements(const double* in, float* out,
    float* displacements, std::size_t count, double strength, ExponentialRule rule) const;

  // The derivatives of the map (docs/conventions.md section 3 item 15): forward-mode automatic
  // differentiation of the same computation as map() (every branch and frame the value takes),
  // exact to rounding. Each returns false, writing nothing, where map() does or a derivative is
  // not finite. With a tolerance (setTolerance), mapWithJacobian, mapPointsWithJacobians and
  // mapPointsWithDirectionalDerivatives differentiate the tree's approximation of B (its local
  // polynomials, series and direct sums), so their images are map()'s to the bit and J is the
  // tree's: its error against the direct sum's J is measured, not bounded (README, Many
  // generators); mapWithBivectorDerivative and mapWithWeightDerivatives sum directly (their
  // image: the direct sum's, within the tolerance of map()'s). Without one every image is map()'s.

  /// map() and its derivative J = d out / d p, row-major: jacobian[3 i + j] = d out_i / d p_j.
  /// J is a general 3x3 matrix for both rules: K(p) varies with p, so even the Exact rule's map,
  /// conformal for a constant K, is not conformal as a whole.
  bool mapWithJacobian(
    Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* jacobian) const;

  /// The batch form of mapWithJacobian through the block kernel: `count` points xyz interleaved,
  /// their images to `out` as mapPoints() writes them (the same bits), and 9 doubles per point to
  /// `jacobians` (row-major). A point that is not mapped, or whose derivative is not finite (an
  /// image whose derivative overflows: huge weights), is copied unchanged with the identity as its
  /// Jacobian, unlike mapPoints, which maps the latter: callers that need every image call
  /// mapPoints where the returned count is not 0. Returns how many points are such. No heap
  /// allocation without a tree; with one, O(count) scratch, about 400 bytes per point, and the
  /// tree's cells shared by the call's points as in mapPoints. Threads are the caller's.
  std::size_t mapPointsWithJacobians(const double* in, double* out, double* jacobians,
    std::size_t count, double strength, ExponentialRule rule) const;

  /// mapPointsWithJacobians along two given directions per point instead of the whole J: for
  /// each point, directions holds t1 then t2 (6 doubles: t1.x, t1.y, t1.z, t2.x, ...) and
  /// derivatives receives J t1 then J t2 in the same layout, forward mode with two tangents
  /// instead of three: what a normal needs, since cof(J) n = (J t1) x (J t2) for t1 x t2 = n
  /// (vtkPointPairDeformationFilter's normals). The images and unchanged points are
  /// mapPointsWithJacobians' (an unchanged point gets its directions back: J = I); with a tree,
  /// J t1 and J t2 from its whole J. No heap allocation without a tree; threads are the caller's.
  std::size_t mapPointsWithDirectionalDerivatives(const double* in, const double* directions,
    double* out, double* derivatives, std::size_t count, double strength,
    ExponentialRule rule) const;

  /// map() and d out / d B: how the image moves per unit change of each of the ten components
  /// (Compact.h order) of B(p) (generatorAt(p), in space, before the factor -strength):
  /// byBivector[10 j + c] = d out_j / d B_c. For a parameter theta of the generators,
  /// d out / d theta = sum_c byBivector[10 j + c] d B_c / d theta.
  /// Next to a strong dilation (a similarity's bivector with a strong hyperbolic plane) it is
  /// computed in closed form; next to a strong boost between two points (a hyperbolic 2-blade that
  /// is not a similarity's: no closed form yet) it returns false, as mapWithWeightDerivatives
  /// (docs/conventions.md section 3 item 15).
  bool mapWithBivectorDerivative(
    Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* byBivector) const;

  /// map() and d out / d w_i for each kept generator i < size(), in the order given (skipped
  /// ones left out): derivatives[3 i + j] = d out_j / d w_i.
  bool mapWithWeightDerivatives(
    Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* derivatives) const;

private:
  bool mapWithExponentDerivative(
    Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* byExponent) const;
  void add(const FieldGenerator* generators, const GeneratorParameters* rows, std::size_t count);
  kernel::FieldArgs args(double strength, ExponentialRule rule) const;
  template <typename In, typename Out>
  std::size_t mapPointsOf(
    const In* in, Out* out, std::size_t count, double strength, ExponentialRule rule) const;
  template <typename In, typename Out>
  DisplacementCounts mapPointsWithDisplacementsOf(const In* in, Out* out, Out* displacements,
    std::size_t count, double strength, ExponentialRule rule) const;

  // The one layout of the generators, read by map() and the block kernel alike: per generator 13
  // doubles, the location x_i - c, then the ten components of w_i G_i moved by -c.
  std::vector<double> Generators;
  // G_i of each kept generator moved by -c, without its weight (ten doubles each; the weight may
  // be 0): d B / d w_i for mapWithWeightDerivatives.
  std::vector<double> Unweighted;
  Vec3 Center;
  std::size_t Count = 0;
  double Falloff = 1.0;
  double Epsilon = 1e-2;
  std::size_t Skipped = 0;
  double Tolerance = 0.0;
  std::shared_ptr<const detail::GeneratorTree> Tree; // null: the direct sum
  int TreeCellsCoarser = 0;                          // planTreeCells
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
