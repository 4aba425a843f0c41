// Internal: the far-field approximation of the generator sum B(p) = sum_i g_i / (k |p - x_i|^2 + eps)
// (g_i = w_i G_i) behind PointPairField::setTolerance (docs/conventions.md section 3 item 14).
//
// A binary tree over the generators (split at the median of the widest extent, leaves of at most
// kLeafSize); each node holds the Cartesian moments mu_b = sum_i g_i yhat_i^b, |b| <= P (10, 16), of
// its generators about its center c (yhat = (x - c)/s, s its radius rho, so no moment overflows),
// stored over b! (the multipole-to-local sum reads them as they are).
// For a point p, d = p - c, D = k |d|^2 + eps, kappa = k/D, u = sqrt(kappa) d, q = rho sqrt(kappa):
//   1/(k |d - y|^2 + eps) = (1/D) sum_j D_j,  |D_j| <= (j + 1) q^j (Chebyshev U_j with |arg| <= 1),
// so the degree-p truncation errs by at most (1/D) R_p(q), R_p(q) = q^(p+1) ((p+2) - (p+1) q)/(1-q)^2,
// per generator, and also by (1/D) S q^(p+1)/(1-q), S = sqrt(D/eps) >= 1/sqrt(1 - |u|^2) >= |U_j|:
// the remainder bound is the smaller of the two. The budget is the image's: to first order a
// change dB of B(p) moves the image by s v_p(dB), v_p(h) = 2 x (the translation part of h moved to
// p), and |v_p(g_i)| <= m0 + m1 |p - x_i| + m2 |p - x_i|^2 with g_i's parts about x_i (addMotion),
// <= A0 + A1 l + A2 l^2 about the node's center (|p - x_i| <= l + r_i). Generator i, at r_i from
// the center, errs by at most (r_i/rho)^(p+1) times the node's R_p(q) (Salmon and Warren's
// absolute moments: each node keeps sum_i A_k,i (r_i/rho)^j, j <= P + 1, its spread). The budget
// t V (V the field's displacement scale per unit strength) is shared at each point by the
// generators' weights z_i(p) = (a_i + b_i r^2)/(k r^2 + eps), r = |p - x_i| (a_i + b_i r^2 >=
// g_i's own motion bound: z_i is a bound of |v_p(g_i)|/D_i): a node used for every point of a
// cube may err by t V X/Phi, X <= sum over its generators of z_i at every point of the cube,
// Phi >= sum over all generators of z_i there (weightSum); the nodes used at a point are
// disjoint, so their errors add up to at most t V. A node is used at the least degree p with
// R_p(q)/D sum_i (A0 + A1 l + A2 l^2)_i (r_i/rho)^(p+1) <= t V X/Phi (l the farthest |p - c|).
// Nodes that fail are opened; leaves are summed directly. The points' side (GeneratorTreeCells.cpp)
// uses the same test with the radius r of a cube of points added to rho and r_i (the weights
// ((r_i + r)/(rho + r))^(p+1)): the cube's local expansion.
#pragma once

#include "LaneClones.h"
#include "PointPairKernel.h"

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include <array>
#include <cstddef>
#include <cstring>
#include <vector>

// The loops over lanes and over the ten components are compiled for AVX-512, AVX2 and the
// baseline (BOOSTED_LANE_CLONES).

namespace cga
{
namespace detail
{
// Two doubles of GCC's vector extension, beside LaneClones.h's Eight.
typedef double Two __attribute__((vector_size(2 * sizeof(double))));

/// sums[c kLanes, (c + 1) kLanes) += out[c] for a bivector's ten components (a block's lanes per
/// component; sums need not be aligned).
__attribute__((always_inline)) inline void addLanes(double* sums, const Eight* out)
{
  static_assert(kernel::kLanes == 8, "one vector of Eight per block of lanes");
  for (int c = 0; c < kernel::kBivectorComponents; ++c)
  {
    Eight sum;
    std::memcpy(&sum, sums + c * kernel::kLanes, sizeof sum);
    sum += out[c];
    std::memcpy(sums + c * kernel::kLanes, &sum, sizeof sum);
  }
}

/// The monomials of degree at most `degree` in three variables.
constexpr int monomialCount(int degree)
{
  return (degree + 1) * (degree + 2) * (degree + 3) / 6;
}

/// One use of a node's expansion, recorded for the test that splits the bound's excess
/// (TestGeneratorTree.cpp, BoundSplit): the node, its degree, the cube of points it was used for
/// (center, radius; the leaf's for a per-point use) and the quantities its degree was chosen from
/// (q, D, the farthest distance reach, the share of t V).
struct TreeBoundRecord
{
  int node, degree;
  double center[3];
  double radius;
  double q, D, reach, share;
  bool perPoint;
};
/// When not null, evaluatePoints appends a TreeBoundRecord per use of an expansion on this thread
/// (tests only: one branch per node used, each use costing thousands of operations).
inline thread_local std::vector<TreeBoundRecord>* treeBoundRecords = nullptr;

class GeneratorTree
{
public:
  /// Generators in the field's layout (kernel::kGeneratorStride doubles each, relative to the
  /// field's center, all finite); 0 < tolerance (the caller caps it).
  GeneratorTree(const double* generators,
                std::size_t count,
                double falloff,
                double epsilon,
                double tolerance);

  /// B(p) for kernel::kLanes points: xyz holds x[kLanes], y[kLanes], z[kLanes] (relative to the
  /// field's center); bivectors receives Bivector::Count components per lane, component-major
  /// (bivectors[c * kLanes + l]). A lane whose point is not finite gets 0. The nodes are chosen
  /// for the block as a whole (its center and radius): used for points beyond the target cells'
  /// lattice (evaluatePoints), one point per call. With gradients, also d B_c / d p_k of lane l
  /// at gradients[(3 c + k) * kLanes + l] (kernel::AddFieldJacobianBlock's layout).
  void evaluate(const double* xyz, double* bivectors, double* gradients = nullptr) const;

  /// B(p) for `count` points, xyz interleaved (relative to the field's center), into
  /// bivectors[i * Bivector::Count + c]; a point that is not finite gets 0. The far field comes from
  /// local expansions about the cells of a fixed lattice of cubes (GeneratorTreeCells.cpp), so that
  /// each B(p) depends on p alone, not on the other points of the call: the same bits whatever
  /// the chunking, the threads, or map() of one point. Scratch memory O(count), allocated per call.
  /// With gradients, also the derivatives of the same approximation (its expansions and direct
  /// sums differentiated, GeneratorTreeGradients.cpp): d B_c / d p_k of point i at
  /// gradients[(i * Bivector::Count + c) * 3 + k], the values in bivectors the same bits as
  /// without. With `coarser` > 0 the leaves are 2^coarser times as wide (at most levels() times:
  /// then the top cells are the leaves), for sparse points (countCells); each B(p) then depends
  /// on p and `coarser`.
  void evaluatePoints(const double* xyz, std::size_t count, double* bivectors,
                      double* gradients = nullptr, int coarser = 0) const;

  /// For the points (relative to the field's center, interleaved) as one evaluatePoints call:
  /// cells[c] += the number of distinct leaves of the lattice c levels coarser that hold them,
  /// for c = 0 ... levels() (cells holds levels() + 1 counts), each leaf being one local
  /// expansion of that call. Returns the number of points counted (the finite ones within the
  /// lattice).
  std::size_t countCells(const double* xyz, std::size_t count, std::size_t* cells) const;

  /// The target cells: the side of the finest (leaf) cubes and the levels above them.
  double leafSide() const { return this->LeafSide; }
  int levels() const { return this->Levels; }

  /// The moments' degree P (each use takes the least degree its budget allows), and the largest
  /// q a node is used at.
  int degree() const { return this->Degree; }
  double openingLimit() const { return this->QLimit; }
  /// V: the field's displacement scale per unit strength, the largest first-order displacement
  /// |v_p(B(p))| of the direct sum at the sample points (the centers of the nodes of at least
  /// M/kSampleShare generators). The budget of every point is tolerance * V.
  double displacementScale() const { return this->DisplacementScale; }
  /// Bytes held (the permuted generators, the nodes, the moments): O(M).
  std::size_t bytes() const;

  /// The largest degree the tree chooses from.
  static constexpr int kMaxDegree = 16;
  /// The largest degree, kMaxDegree below kHighDegreeBelow with at least kHighDegreeFrom
  /// generators (tight budgets over many generators make larger nodes worth their costlier
  /// expansions). Measured on the bench's field in 65,536-point calls, degree 12 against 10 took
  /// at M = 100,000 0.71 times the CPU time at 1e-6, 0.75 at 1e-5, 0.84 at 1e-4, 1.04 at 1e-3 and
  /// 1.6 at 0.1; at M = 30,000 1.1 times at 1e-5, at M = 10,000 1.4 times at 1e-4. With the
  /// cheaper translations (addSourceToLocal, shiftLocal), at M = 100,000 against degree 12 (CPU
  /// time, one probe each, load 5-10): degree 14 0.94 times at 1e-6, 16 0.74-0.81, 18 0.89, 20
  /// 0.87; degree 16 0.91 times at 1e-5 and 1.07 at 1e-4.
  static constexpr int kDegree = 10;
  static constexpr double kHighDegreeBelow = 1e-3;
  static constexpr std::size_t kHighDegreeFrom = 100000;
  static constexpr int kMaxMomentsOfDegree = (kMaxDegree + 1) * (kMaxDegree + 2) * (kMaxDegree + 3) / 6;
  /// A node's weights are summed whole into Phi where their largest value is at most this times
  /// their least one, or the node has fewer than DirectBelow generators.
  static constexpr double kWeightSpread = 1.5;
  /// Generators per leaf at most.
  static constexpr std::size_t kLeafSize = 32;
  /// A leaf cell's width over that of the widest cell usable at any distance, at degree kDegree
  /// and at kMaxDegree. At kMaxDegree a multipole to local costs 9.3 times as much per cell (74,613
  /// terms against 8,008 at degree 10), so larger leaves, with more points to share it, pay:
  /// measured on the bench's field at M = 100,000 (262,000 mesh points in 65,536-point calls, CPU
  /// time, against 0.25): 0.96 times the time at Tolerance 1e-6 and 0.95 at 1e-4 with degree 16,
  /// but 1.13 times at 0.1 and 1.38 at 1e-3 with degree 10 (1.0: 2.1 times at 1e-6).
  static constexpr double kLeafShare = 0.25;
  static constexpr double kHighDegreeLeafShare = 0.5;
  /// The largest q a node is used at (the series converges for q < 1; its terms' bound grows
  /// like (j + 1) q^j).
  static constexpr double kLargestOpening = 0.5;
  /// The displacement scale's sample points: the centers of the nodes of at least M/kSampleShare
  /// generators (at most 2 kSampleShare of them).
  static constexpr std::size_t kSampleShare = 64;

  friend struct TreeBoundSplit; // the test's access to the nodes (TestGeneratorTree.cpp)

private:
  struct Node
  {
    double center[3];
    double radius = 0.0; // the largest |x_i - center|
    std::size_t first = 0, count = 0;
    int children[2] = { -1, -1 };
    long moments = -1; // offset in Moments, or -1: the node is summed directly
    // The generators' weights z_i = (a_i + b_i s)/(k s + eps), s = r^2, summed: {a, b} of those
    // increasing in s (b_i eps > a_i k), then {a, b} of the others (nodeWeights).
    double weights[4] = { 0.0, 0.0, 0.0, 0.0 };
    // Offset in Spread of the node's absolute moments (nodes with moments only, else -1):
    // Spread[spread + part * kSpreadPowers + j] = sum_i m_part,i (|x_i - center|/radius)^j, with
    // m_0,i + m_1,i l + m_2,i l^2 >= |v_p(g_i)| for |p - center| <= l (addMotion about the center).
    long spread = -1;
    // Offset in Harmonic of the norms of the trace-free parts (in R^4) of the node's signed moment
    // tensors of each degree k <= Degree, per part of the motion bound about the center
    // (treeTraceFreeNorm; nodes with moments only, else -1):
    // Harmonic[harmonic + part * kHarmonicDegrees + k], part 0: 2 |C|, 1: 2 sqrt(|E|^2 + d^2), 2: |A|.
    long harmonic = -1;
  };
  static constexpr int kHarmonicDegrees = kMaxDegree + 1;
  static constexpr int kSpreadPowers = kMaxDegree + 2;
  // One term of e_b(u) = sum coefficient u^a (Taylor coefficient of the kernel for moment b).
  struct Term
  {
    int moment, monomial;
    double coefficient;
  };
  // One term of the local-to-local shift along one axis (shiftLocal): local[target] +=
  // C(target_axis + power, power) delta_axis^power parent[source], source = target + power e_axis.
  struct AxisShiftTerm
  {
    int target, source, power;
    double binomial;
  };
  struct CellWork;
  void evaluateCell(CellWork& work, int level, std::size_t first, std::size_t last,
                    const long long* cell, const double* parentLocal, const double* parentCenter) const;
  void addSourceToLocal(const Node& node, const double* center, double radius, int degree, double* local) const;
  void shiftLocal(const double* parent, const double* parentCenter, const double* center,
                  double radius, double* local) const;
  void addLocal(const double* local, const double* center, double radius, const double* p,
                double* sums) const;
  // addLocal and addMultipole adding d B / d p too (GeneratorTreeGradients.cpp; gradients in
  // kernel::AddFieldJacobianBlock's layout).
  void addLocalGradient(const double* local, const double* center, double radius, const double* p,
                        double* sums, double* gradients) const;
  void addMultipoleGradient(const Node& node, const double* moments, int degree, const double* p,
                            double* sums, double* gradients) const;
  // gradients: null, or d B / d p added too.
  void addNear(const int* starts, std::size_t count, const double* center, double radius,
               double weightSum, const double* p, double* sums, double* gradients) const;
  void chooseCells();
  int build(std::size_t first, std::size_t count, std::vector<std::size_t>& order, int depth);
  bool computeMoments(int node);
  void addGeneratorMoments(const Node& node, double scale, double* mu) const;
  void addDirect(std::size_t first, std::size_t count, const double* p, double* sums,
                 double* gradients) const;
  void addMultipole(const Node& node, const double* moments, int degree, const double* p, double* b) const;
  // power[m], m < count, of the coordinates y in the graded order, each its parent's times one
  // coordinate; T is double or Eight (a block's lanes), inlined into each lane clone.
  template <typename T>
  __attribute__((always_inline)) void monomialPowers(const T* y, int count, T* power) const
  {
    power[0] = T{} + 1.0;
    for (int m = 1; m < count; ++m)
    {
      power[m] = power[this->MonomialParent[static_cast<std::size_t>(m)]] *
        y[this->MonomialAxis[static_cast<std::size_t>(m)]];
    }
  }

  // The local polynomial at the lanes' points, out[c] = sum_m local[m][c] power[m]; and a node's
  // series, out[c] = sum_b e_b(u) q^|b| / D mu_b[c] (e = the kernel's Taylor coefficients from the
  // monomials of u, scale = 1 / D). Lane is Eight (values: addLocal, addMultipole) or a dual number
  // on Eight (values and d / d p: GeneratorTreeGradients.cpp), so both run the same operations in
  // the same order and their values are the same bits.
  template <typename Lane>
  __attribute__((always_inline)) void sumLocal(const double* local, const Lane* power,
                                               Lane* out) const
  {
    for (int c = 0; c < Bivector::Count; ++c)
    {
      out[c] = Lane{};
    }
    for (int m = 0; m < this->MomentCount; ++m)
    {
      const double* coefficients = local + m * Bivector::Count;
      for (int c = 0; c < Bivector::Count; ++c)
      {
        out[c] = out[c] + coefficients[c] * power[m];
      }
    }
  }
  template <typename Lane>
  __attribute__((always_inline)) void sumSeries(const double* moments, int degree,
                                                const Lane* power, const Lane& q, Lane scale,
                                                Lane* e, Lane* out) const
  {
    const int count = monomialCount(degree);
    const std::size_t termCount = this->TermsOfDegree[static_cast<std::size_t>(degree)];
    for (std::size_t t = 0; t < termCount;)
    {
      const int moment = this->Terms[t].moment; // its terms are consecutive
      Lane sum{};
      for (; t < termCount && this->Terms[t].moment == moment; ++t)
      {
        sum = sum + this->Terms[t].coefficient * power[this->Terms[t].monomial];
      }
      e[moment] = sum;
    }
    // Each moment's coefficient (b! e_b, the moments being mu_b / b!) times q^|b| / D.
    int n = 0;
    for (int c = 0; c < Bivector::Count; ++c)
    {
      out[c] = Lane{};
    }
    for (int m = 0; m < count; ++m)
    {
      if (this->MonomialDegree[static_cast<std::size_t>(m)] != n)
      {
        n = this->MonomialDegree[static_cast<std::size_t>(m)];
        scale = scale * q;
      }
      const double* mu = moments + m * Bivector::Count;
      const Lane term = e[m] * scale; // once per monomial: (e scale) mu, left to right
      for (int c = 0; c < Bivector::Count; ++c)
      {
        out[c] = out[c] + term * mu[c];
      }
    }
  }

  std::vector<double> Generators; // permuted, kGeneratorStride doubles each
  std::vector<Node> Nodes;
  std::vector<double> Moments; // per node: MomentCount x Bivector::Count, mu_b / b!
  std::vector<double> Spread;  // per node with moments: 3 x kSpreadPowers absolute moments
  std::vector<double> Harmonic; // per node with moments: 3 x kHarmonicDegrees signed moments' norms
  double Falloff, Epsilon;
  int Degree = 0;
  double QLimit = 0.0;
  double DisplacementScale = 0.0;
  double Budget = 0.0; // t V; 0 where it is not finite: nodes are used only where exact (q = 0)
  // The degree a node is used at, -1 where it is not usable: the least p <= Degree with
  // R_p(q, S) sum_i |v_p(g_i)| ((|x_i - c| + r)/(rho + r))^(p+1) <= share D, the motions bounded
  // at l = reach (nodes at q <= QLimit only; S = sqrt(D/eps); r = targetRadius, the cube's for a
  // local expansion, 0 for points). A NaN share (overflow far away or with huge weights) opens
  // the node.
  int degreeFor(const Node& node, double q, double D, double reach, double share,
                double targetRadius) const;
  // The node's weight sum for generator distances r in [nearest, farthest]: its least value
  // (lower = true, X) or its largest (Phi's term).
  double nodeWeights(const Node& node, double nearest, double farthest, bool lower) const;
  // Phi for the points within `radius` of `center`: an upper bound of sum_i z_i(p) there, from
  // the nodes' largest weights, opened while the largest is above kWeightSpread times the least.
  double weightSum(const double* center, double radius) const;
  // The share of the budget of a node whose center is `distance` from `center`, used for the
  // points within `radius` of it: t V X/Phi (0 where not finite).
  double shareOf(const Node& node, double distance, double radius, double weightSum) const;
  void computeBudgets(double tolerance);
  std::vector<double> InverseFactorial; // 1/beta!, beta! = beta_0! beta_1! beta_2! per monomial
  // The multipole-to-local sum's indices: ShiftGamma[ShiftRuns[alpha] + beta] = index of alpha + beta.
  std::vector<std::size_t> ShiftRuns;
  std::vector<int> ShiftGamma;
  std::vector<std::size_t> TermsOfDegree; // Terms[0, TermsOfDegree[p]) make e_beta for |beta| <= p
  int MomentCount = 0;
  std::vector<int> MonomialIndex;       // (a, b, c) -> graded index, (Degree+1)^3 entries
  std::vector<int> MonomialParent;      // index of the monomial with one power less
  std::vector<int> MonomialAxis;        // which power (0, 1, 2)
  std::vector<int> MonomialDegree;      // |a|
  std::vector<std::array<int, 3>> MonomialPowers;
  std::vector<Term> Terms;
  std::size_t DirectBelow = 0; // nodes with fewer generators are summed directly even when usable
  std::vector<AxisShiftTerm> AxisShiftTerms[3]; // per axis, grouped by target in graded order
  // The moments' shift to a parent per axis: moment[target] += C(target_axis, power)
  // delta_axis^power child[source], source = target - power e_axis (computeMoments; freed once
  // the moments are built).
  std::vector<AxisShiftTerm> MomentShiftTerms[3];
  double LeafSide = 1.0; // a power of two
  int Levels = 0;        // the top cells are LeafSide * 2^Levels wide
};

/// tree.evaluatePoints of `count` points given in space (xyz interleaved, float or double),
/// moved to the field's center c first, as the tree takes them, on the lattice `coarser` levels
/// coarser: mapPoints' and mapPointsWithJacobians' B(p) of a whole call.
template <typename In>
void evaluatePointsAbout(const GeneratorTree& tree, int coarser, Vec3 c, const In* in,
                         std::size_t count, double* bivectors, double* gradients = nullptr)
{
  std::vector<double> relative(3 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    relative[3 * i] = static_cast<double>(in[3 * i]) - c.x;
    relative[3 * i + 1] = static_cast<double>(in[3 * i + 1]) - c.y;
    relative[3 * i + 2] = static_cast<double>(in[3 * i + 2]) - c.z;
  }
  tree.evaluatePoints(relative.data(), count, bivectors, gradients, coarser);
}
} // namespace detail
} // namespace cga
