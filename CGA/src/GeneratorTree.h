// Internal: the far-field approximation of the generator sum B(p) = sum_i g_i / (k |p - x_i|^2 + eps)
// (g_i = w_i G_i) behind PointPairField::setTolerance (docs/conventions.md section 3 item 14).
//
// A binary tree over the generators (split at the median of the widest extent, leaves of at most
// kLeafSize); each node holds the Cartesian moments mu_b = sum_i g_i yhat_i^b, |b| <= P, of its
// generators about its center c (yhat = (x - c)/s, s its radius rho, so no moment overflows).
// For a point p, d = p - c, D = k |d|^2 + eps, kappa = k/D, u = sqrt(kappa) d, q = rho sqrt(kappa):
//   1/(k |d - y|^2 + eps) = (1/D) sum_j D_j,  |D_j| <= (j + 1) q^j (Chebyshev U_j with |arg| <= 1),
// so the degree-P truncation errs by at most (1/D) R_P(q), R_P(q) = q^(P+1) ((P+2) - (P+1) q)/(1-q)^2,
// per generator. A node is used for a block of points when R_P(q)(1+q)^2 <= tolerance for every
// point of the block (q at the block's nearest possible distance): its error is then at most
// tolerance times its own share of A(p) = sum_i |g_i|_max / (k |p - x_i|^2 + eps), and the total
// at most tolerance A(p). Nodes that fail are opened; leaves are summed directly.
#pragma once

#include "PointPairKernel.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cga
{
namespace detail
{
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
  /// (bivectors[c * kLanes + l]). A lane whose point is not finite gets 0.
  void evaluate(const double* xyz, double* bivectors) const;

  /// The expansion degree P chosen for the tolerance, and the largest q a node is used at.
  int degree() const { return this->Degree; }
  double openingLimit() const { return this->QLimit; }
  /// Bytes held (the permuted generators, the nodes, the moments): O(M).
  std::size_t bytes() const;

  /// The largest degree the tree chooses from.
  static constexpr int kMaxDegree = 10;
  /// Generators per leaf at most.
  static constexpr std::size_t kLeafSize = 32;

private:
  struct Node
  {
    double center[3];
    double radius = 0.0; // the largest |x_i - center|
    std::size_t first = 0, count = 0;
    int children[2] = { -1, -1 };
    long moments = -1; // offset in Moments, or -1: the node is summed directly
  };
  // One term of e_b(u) = sum coefficient u^a (Taylor coefficient of the kernel for moment b).
  struct Term
  {
    int moment, monomial;
    double coefficient;
  };
  int build(std::size_t first, std::size_t count, std::vector<std::size_t>& order, int depth);
  bool computeMoments(int node);
  void addDirect(const Node& node, const double* p, double* sums) const;
  void addMultipole(const Node& node, const double* moments, const double* p, double* b) const;

  std::vector<double> Generators; // permuted, kGeneratorStride doubles each
  std::vector<Node> Nodes;
  std::vector<double> Moments; // per node: MomentCount x Bivector::Count
  double Falloff, Epsilon;
  int Degree = 0;
  double QLimit = 0.0;
  int MomentCount = 0;
  std::vector<int> MonomialIndex;       // (a, b, c) -> graded index, (Degree+1)^3 entries
  std::vector<int> MonomialParent;      // index of the monomial with one power less
  std::vector<int> MonomialAxis;        // which power (0, 1, 2)
  std::vector<int> MonomialDegree;      // |a|
  std::vector<std::array<int, 3>> MonomialPowers;
  std::vector<Term> Terms;
  std::size_t DirectBelow = 0; // nodes with fewer generators are summed directly even when usable
};
} // namespace detail
} // namespace cga
