#include "GeneratorTree.h"

#include "PointPairKernelDispatch.h"
#include "TreeRemainder.h"

#include "cga/Compact.h"
#include "cga/PointPairs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace cga
{
namespace detail
{
namespace
{
constexpr int L = kernel::kLanes;
constexpr int kStride = kernel::kGeneratorStride;
constexpr int kComponents = Bivector::Count;

// The first-order motion bound of g in the frame of its node (GeneratorTree.h): with g's parts
// there, translation C (e_i^ni), rotation E (e_i^e_j), dilation d (no^ni) and transversion A
// (e_i^no), v_p(g) = 2 C' for C' the translation part of g moved to p, and with y = p - center
//   C' = C - E y - d y + (1/2)|y|^2 A - (A.y) y  (docs/conventions.md section 2 item 12, t = -y),
// |E y + d y| <= sqrt(|E|^2 + d^2) |y| (E y is orthogonal to y), |(1/2)|y|^2 A - (A.y) y| = |y|^2 |A|/2:
//   |v_p(g)| <= 2 |C| + 2 sqrt(|E|^2 + d^2) |y| + |A| |y|^2.
// The one layout of the three parts, for addMotion (the generators' absolute motions) and for the
// signed moments' norms (computeBudgets): the components in the parts' order, and per part its
// first component there, its size and its factor in the bound.
constexpr int kMotionComponents[kComponents] = { Bivector::E1NI, Bivector::E2NI, Bivector::E3NI, Bivector::E12,
                                                 Bivector::E13,  Bivector::E23,  Bivector::NONI, Bivector::E1NO,
                                                 Bivector::E2NO, Bivector::E3NO };
struct MotionPart
{
  int first, size;
  double scale;
};
constexpr MotionPart kMotionParts[3] = { { 0, 3, 2.0 }, { 3, 4, 2.0 }, { 7, 3, 1.0 } };

void addMotion(const Bivector& g, double* motion)
{
  for (int part = 0; part < 3; ++part)
  {
    const MotionPart& layout = kMotionParts[part];
    double squared = 0.0;
    for (int i = layout.first; i < layout.first + layout.size; ++i)
    {
      const double c = g.c[static_cast<std::size_t>(kMotionComponents[i])];
      squared += c * c;
    }
    motion[part] += layout.scale * std::sqrt(squared);
  }
}

double binomial(int n, int k)
{
  double r = 1.0;
  for (int i = 1; i <= k; ++i)
  {
    r = r * (n - k + i) / i;
  }
  return r;
}

double factorial(int n)
{
  double r = 1.0;
  for (int i = 2; i <= n; ++i)
  {
    r *= i;
  }
  return r;
}

constexpr int kMaxMoments = monomialCount(GeneratorTree::kMaxDegree);
static_assert(GeneratorTree::kMaxDegree + 1 <= kMaxSpreadPower, "treeSpreadMoment takes powers up to P + 1");

} // namespace

GeneratorTree::GeneratorTree(const double* generators,
                             std::size_t count,
                             double falloff,
                             double epsilon,
                             double tolerance)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  // The largest degree: each use of a node takes the least degree its budget allows (degreeFor),
  // but the nodes worth moments grow with it (DirectBelow), which pays only at tight budgets.
  this->Degree = tolerance < kHighDegreeBelow && count >= kHighDegreeFrom ? kMaxDegree : kDegree;
  this->QLimit = kLargestOpening;
  const int P = this->Degree;
  // Monomials in graded order, each one power above a lower one.
  this->MonomialIndex.assign(static_cast<std::size_t>((P + 1) * (P + 1) * (P + 1)), -1);
  auto at = [P](int a, int b, int c) { return (a * (P + 1) + b) * (P + 1) + c; };
  for (int n = 0; n <= P; ++n)
  {
    for (int a = n; a >= 0; --a)
    {
      for (int b = n - a; b >= 0; --b)
      {
        const int c = n - a - b;
        const int index = static_cast<int>(this->MonomialPowers.size());
        this->MonomialIndex[static_cast<std::size_t>(at(a, b, c))] = index;
        this->MonomialPowers.push_back({ a, b, c });
        this->MonomialDegree.push_back(n);
        const int axis = a > 0 ? 0 : (b > 0 ? 1 : 2);
        this->MonomialAxis.push_back(axis);
        this->MonomialParent.push_back(
          n == 0 ? -1
                 : this->MonomialIndex[static_cast<std::size_t>(
                     at(a - (axis == 0), b - (axis == 1), c - (axis == 2)))]);
      }
    }
  }
  this->MomentCount = static_cast<int>(this->MonomialPowers.size());
  // e_b(u) = sum over g with 2g <= b of coef(b - 2g, |g|) |g|!/g! u^(b - 2g), with
  // coef(a, l) = |a|!/a! C(|a| + l, l) 2^|a| (-1)^l (docs/conventions.md section 3 item 14); the
  // terms make b! e_b, since the moments are stored over b! (computeMoments).
  for (int moment = 0; moment < this->MomentCount; ++moment)
  {
    const auto& beta = this->MonomialPowers[static_cast<std::size_t>(moment)];
    const double betaFactorial = factorial(beta[0]) * factorial(beta[1]) * factorial(beta[2]);
    for (int g0 = 0; 2 * g0 <= beta[0]; ++g0)
    {
      for (int g1 = 0; 2 * g1 <= beta[1]; ++g1)
      {
        for (int g2 = 0; 2 * g2 <= beta[2]; ++g2)
        {
          const int a0 = beta[0] - 2 * g0, a1 = beta[1] - 2 * g1, a2 = beta[2] - 2 * g2;
          const int m = a0 + a1 + a2, l = g0 + g1 + g2;
          const double coefficient = factorial(m) /
              (factorial(a0) * factorial(a1) * factorial(a2)) * binomial(m + l, l) *
              std::ldexp(1.0, m) * (l % 2 ? -1.0 : 1.0) * factorial(l) /
              (factorial(g0) * factorial(g1) * factorial(g2)) * betaFactorial;
          this->Terms.push_back(
            { moment, this->MonomialIndex[static_cast<std::size_t>(at(a0, a1, a2))], coefficient });
        }
      }
    }
  }
  // A node is summed directly below (terms + 11 moments)/40 generators (123 at degree 10): with the
  // target cells the fastest of 33, 65, 100, 123, 129, 180 and 247 on the bench's field at
  // M = 100,000 (Tolerance 1e-3; 1e-6 is about as fast at 123 as at 247).
  this->DirectBelow =
    static_cast<std::size_t>((this->Terms.size() + 11 * this->MomentCount) / 40);

  // The multipole-to-local terms (GeneratorTreeCells.cpp): for each alpha, the index of
  // gamma = alpha + beta for every beta with |alpha| + |beta| <= P, beta in graded order (so that
  // those of |beta| <= n are the first monomialCount(n)).
  this->ShiftRuns.push_back(0);
  for (int alpha = 0; alpha < this->MomentCount; ++alpha)
  {
    const auto& a = this->MonomialPowers[static_cast<std::size_t>(alpha)];
    const int alphaDegree = this->MonomialDegree[static_cast<std::size_t>(alpha)];
    for (int beta = 0; beta < monomialCount(P - alphaDegree); ++beta)
    {
      const auto& b = this->MonomialPowers[static_cast<std::size_t>(beta)];
      this->ShiftGamma.push_back(
        this->MonomialIndex[static_cast<std::size_t>(at(a[0] + b[0], a[1] + b[1], a[2] + b[2]))]);
    }
    this->ShiftRuns.push_back(this->ShiftGamma.size());
  }

  // The local-to-local shift one axis at a time (a polynomial's shift by delta is its shifts by
  // delta_x e_x, delta_y e_y and delta_z e_z in turn): every alpha and power k with |alpha| + k <= P.
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int alpha = 0; alpha < this->MomentCount; ++alpha)
    {
      const auto& a = this->MonomialPowers[static_cast<std::size_t>(alpha)];
      for (int k = 0; k <= P - this->MonomialDegree[static_cast<std::size_t>(alpha)]; ++k)
      {
        const int source = this->MonomialIndex[static_cast<std::size_t>(
          at(a[0] + (axis == 0) * k, a[1] + (axis == 1) * k, a[2] + (axis == 2) * k))];
        this->AxisShiftTerms[axis].push_back({ alpha, source, k, binomial(a[axis] + k, k) });
      }
    }
  }

  // The moments' shift to a parent one axis at a time (computeMoments): every b and k <= b_axis.
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int b = 0; b < this->MomentCount; ++b)
    {
      const auto& powers = this->MonomialPowers[static_cast<std::size_t>(b)];
      for (int k = 0; k <= powers[axis]; ++k)
      {
        const int source = this->MonomialIndex[static_cast<std::size_t>(
          at(powers[0] - (axis == 0) * k, powers[1] - (axis == 1) * k, powers[2] - (axis == 2) * k))];
        this->MomentShiftTerms[axis].push_back({ b, source, k, binomial(powers[axis], k) });
      }
    }
  }

  for (const auto& powers : this->MonomialPowers)
  {
    this->InverseFactorial.push_back(1.0 / (factorial(powers[0]) * factorial(powers[1]) * factorial(powers[2])));
  }
  this->TermsOfDegree.assign(static_cast<std::size_t>(P + 1), 0);
  for (std::size_t t = 0; t < this->Terms.size(); ++t)
  {
    const int degree = this->MonomialDegree[static_cast<std::size_t>(this->Terms[t].moment)];
    for (int p = degree; p <= P; ++p)
    {
      this->TermsOfDegree[static_cast<std::size_t>(p)] = t + 1;
    }
  }

  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  this->Generators.assign(generators, generators + count * kStride);
  if (count > 0)
  {
    this->build(0, count, order, 0);
  }
  std::vector<double> permuted(count * kStride);
  for (std::size_t i = 0; i < count; ++i)
  {
    std::copy_n(generators + order[i] * kStride, kStride, permuted.data() + i * kStride);
  }
  this->Generators.swap(permuted);
  if (count > 0)
  {
    this->computeMoments(0);
  }
  for (std::vector<AxisShiftTerm>& terms : this->MomentShiftTerms)
  {
    std::vector<AxisShiftTerm>().swap(terms); // needed while building only
  }
  // Stored over beta! (every node's, once all shifts are done): the multipole-to-local sum then
  // reads them as they are (addSourceToLocal), and the expansions' terms make beta! e_beta.
  const auto nodeMoments = static_cast<std::size_t>(this->MomentCount * kComponents);
  for (std::size_t offset = 0; offset < this->Moments.size(); offset += nodeMoments)
  {
    for (std::size_t m = 0; m < static_cast<std::size_t>(this->MomentCount); ++m)
    {
      for (std::size_t c = 0; c < kComponents; ++c)
      {
        this->Moments[offset + m * kComponents + c] *= this->InverseFactorial[m];
      }
    }
  }
  this->computeBudgets(tolerance);
  this->chooseCells();
}

// Each node's weights (GeneratorTree.h; a parent's are its children's), its absolute moments,
// and the displacement scale V.
void GeneratorTree::computeBudgets(double tolerance)
{
  if (this->Nodes.empty())
  {
    return;
  }
  // z_i = (a_i + b_i r^2)/(k r^2 + eps) with a_i + b_i r^2 >= m0 + m1 r + m2 r^2, g_i's own motion
  // bound about x_i (m1 r <= m1 (l/2 + r^2/(2 l)) for any l > 0; l = sqrt(eps/k), the falloff's
  // length, where it is finite and positive).
  const double length = std::sqrt(this->Epsilon / this->Falloff);
  const double l = std::isfinite(length) && length > 0.0 ? length : 1.0;
  std::vector<double> ownMotions(3 * this->Nodes[0].count); // per generator, about its location
  for (std::size_t index = this->Nodes.size(); index-- > 0;) // children (later in preorder) first
  {
    Node& node = this->Nodes[index];
    if (node.children[0] < 0)
    {
      for (std::size_t i = node.first; i < node.first + node.count; ++i)
      {
        const double* g = this->Generators.data() + i * kStride;
        Bivector b;
        std::copy_n(g + 3, kComponents, b.c.data());
        double* own = ownMotions.data() + 3 * i;
        addMotion(translatedBivector(b, { -g[0], -g[1], -g[2] }), own);
        const double a = own[0] + 0.5 * own[1] * l;
        const double bb = this->Falloff > 0.0 ? own[2] + 0.5 * own[1] / l : 0.0;
        const bool increasing = bb * this->Epsilon > a * this->Falloff;
        node.weights[increasing ? 0 : 2] += a;
        node.weights[increasing ? 1 : 3] += bb;
      }
      continue;
    }
    for (int child : node.children)
    {
      const Node& c = this->Nodes[static_cast<std::size_t>(child)];
      for (int w = 0; w < 4; ++w)
      {
        node.weights[w] += c.weights[w];
      }
    }
  }
  // The absolute moments of the nodes with moments: each generator's motion bound about the node's
  // center, weighted by powers of its distance r from it over the radius. With |p - x_i| <= l + r
  // for |p - center| <= l, its own bound about x_i gives
  //   m0 + m1 (l + r) + m2 (l + r)^2 = (m0 + m1 r + m2 r^2) + (m1 + 2 m2 r) l + m2 l^2,
  // exact for the transversion of a point pair about its location (the parts moved to the center
  // bound it alike), and no more than the triangle inequality's loss for the other parts.
  for (Node& node : this->Nodes)
  {
    if (node.moments < 0)
    {
      continue;
    }
    node.spread = static_cast<long>(this->Spread.size());
    this->Spread.resize(this->Spread.size() + 3 * kSpreadPowers, 0.0);
    double* spread = this->Spread.data() + node.spread;
    for (std::size_t i = node.first; i < node.first + node.count; ++i)
    {
      const double* g = this->Generators.data() + i * kStride;
      const double dx = g[0] - node.center[0], dy = g[1] - node.center[1], dz = g[2] - node.center[2];
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double* own = ownMotions.data() + 3 * i;
      const double motion[3] = { own[0] + (own[1] + own[2] * r) * r, own[1] + 2.0 * own[2] * r, own[2] };
      // s <= 1: the radius is the largest of these distances, computed alike (build).
      const double s = node.radius > 0.0 ? r / node.radius : 0.0;
      double power = 1.0;
      for (int j = 0; j < kSpreadPowers; ++j)
      {
        for (int part = 0; part < 3; ++part)
        {
          spread[part * kSpreadPowers + j] += motion[part] * power;
        }
        power *= s;
      }
    }
  }
  // The signed moments' norms: each node's moments as bivectors about its center, split into the
  // motion bound's three parts, and the norm of each part's trace-free tensor of every degree.
  const int P = this->Degree;
  std::vector<double> parts(static_cast<std::size_t>(this->MomentCount) * 10);
  for (Node& node : this->Nodes)
  {
    if (node.moments < 0)
    {
      continue;
    }
    node.harmonic = static_cast<long>(this->Harmonic.size());
    this->Harmonic.resize(this->Harmonic.size() + 3 * kHarmonicDegrees, 0.0);
    // The move to the center is linear: its matrix from the ten unit bivectors, in the parts' order.
    double move[kComponents][10];
    for (std::size_t c = 0; c < kComponents; ++c)
    {
      Bivector unit;
      unit.c[c] = 1.0;
      const Bivector moved = translatedBivector(unit, { -node.center[0], -node.center[1], -node.center[2] });
      for (int k = 0; k < 10; ++k)
      {
        move[c][k] = moved.c[static_cast<std::size_t>(kMotionComponents[k])];
      }
    }
    for (std::size_t m = 0; m < static_cast<std::size_t>(this->MomentCount); ++m)
    {
      const double* mu = this->Moments.data() + static_cast<std::size_t>(node.moments) + m * kComponents;
      double* part = parts.data() + m * 10;
      std::fill_n(part, 10, 0.0);
      for (std::size_t c = 0; c < kComponents; ++c)
      {
        const double value = mu[c] / this->InverseFactorial[m];
        for (int k = 0; k < 10; ++k)
        {
          part[k] += value * move[c][k];
        }
      }
    }
    for (int part = 0; part < 3; ++part)
    {
      auto moment = [&](int a, int b, int c) {
        return parts.data() + static_cast<std::size_t>(this->MonomialIndex[static_cast<std::size_t>((a * (P + 1) + b) * (P + 1) + c)]) * 10 +
          kMotionParts[part].first;
      };
      for (int k = 0; k <= P; ++k)
      {
        this->Harmonic[static_cast<std::size_t>(node.harmonic + part * kHarmonicDegrees + k)] =
          kMotionParts[part].scale * treeTraceFreeNorm(k, kMotionParts[part].size, moment);
      }
    }
  }
  // V: the direct sum's first-order displacement at the sample points.
  const std::size_t sampleFrom = std::max<std::size_t>(1, this->Nodes[0].count / kSampleShare);
  std::vector<const Node*> samples;
  for (const Node& node : this->Nodes)
  {
    if (node.count >= sampleFrom)
    {
      samples.push_back(&node);
    }
  }
  double scale = 0.0;
  constexpr std::size_t kBlock = L; // sample points per call of the block kernel
  alignas(64) double centers[3 * kBlock], sums[kComponents * kBlock];
  for (std::size_t first = 0; first < samples.size(); first += kBlock)
  {
    const std::size_t n = std::min(kBlock, samples.size() - first);
    for (std::size_t l = 0; l < kBlock; ++l)
    {
      const double* center = samples[first + std::min(l, n - 1)]->center; // repeats the last
      for (std::size_t k = 0; k < 3; ++k)
      {
        centers[k * kBlock + l] = center[k];
      }
    }
    std::fill_n(sums, kComponents * kBlock, 0.0);
    this->addDirect(0, this->Nodes[0].count, centers, sums, nullptr);
    for (std::size_t l = 0; l < n; ++l)
    {
      Bivector b;
      for (std::size_t c = 0; c < kComponents; ++c)
      {
        b.c[c] = sums[c * kBlock + l];
      }
      const double* center = samples[first + l]->center;
      scale = std::max(scale, norm(firstOrderMotion(b, { center[0], center[1], center[2] })));
    }
  }
  this->DisplacementScale = scale;
  // Overflow (huge weights) or no displacement at the samples: nodes are used only where exact.
  const double budget = tolerance * scale;
  this->Budget = std::isfinite(budget) && budget > 0.0 ? budget : 0.0;
}

double GeneratorTree::nodeWeights(const Node& node, double nearest, double farthest, bool lower) const
{
  // Each z_i is monotone in s = r^2: the increasing ones are least at the nearest distance, the
  // others at the farthest.
  const double sNear = nearest * nearest, sFar = farthest * farthest;
  const double dNear = this->Falloff * sNear + this->Epsilon, dFar = this->Falloff * sFar + this->Epsilon;
  const double sUp = lower ? sNear : sFar, dUp = lower ? dNear : dFar;
  const double sDown = lower ? sFar : sNear, dDown = lower ? dFar : dNear;
  return (node.weights[0] + node.weights[1] * sUp) / dUp + (node.weights[2] + node.weights[3] * sDown) / dDown;
}

double GeneratorTree::weightSum(const double* center, double radius) const
{
  double sum = 0.0;
  int stack[256];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[static_cast<std::size_t>(stack[--top])];
    const double dx = center[0] - node.center[0], dy = center[1] - node.center[1],
                 dz = center[2] - node.center[2];
    const double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double nearest = std::max(0.0, distance - radius - node.radius);
    const double farthest = distance + radius + node.radius;
    const double largest = this->nodeWeights(node, nearest, farthest, false);
    if (node.children[0] >= 0 && node.count >= this->DirectBelow && top < 254 &&
        largest > kWeightSpread * this->nodeWeights(node, nearest, farthest, true))
    {
      stack[top++] = node.children[1];
      stack[top++] = node.children[0];
      continue;
    }
    sum += largest;
  }
  return sum;
}

double GeneratorTree::shareOf(const Node& node, double distance, double radius, double weightSum) const
{
  const double least =
    this->nodeWeights(node, std::max(0.0, distance - radius - node.radius), distance + radius + node.radius, true);
  const double share = this->Budget * (least / weightSum);
  return std::isfinite(share) ? share : 0.0;
}

int GeneratorTree::degreeFor(const Node& node, double q, double D, double reach, double share,
                             double targetRadius) const
{
  if (!(q <= this->QLimit))
  {
    return -1;
  }
  // The generators' motions at l = reach, weighted by their distances' powers (TreeRemainder.h:
  // a generator at |x_i - c| errs by ((|x_i - c| + r)/(rho + r))^(p+1) times the node's bound).
  const double* spread = this->Spread.data() + node.spread;
  double motions[kSpreadPowers];
  for (int j = 0; j < kSpreadPowers; ++j)
  {
    motions[j] = spread[j] + (spread[kSpreadPowers + j] + spread[2 * kSpreadPowers + j] * reach) * reach;
  }
  const double extent = node.radius + targetRadius;
  const double a = extent > 0.0 ? node.radius / extent : 1.0;
  const double b = extent > 0.0 ? targetRadius / extent : 0.0;
  const int P = this->Degree;
  const TreeSpreadWeights weights(a, b, P + 1);
  // The degree-p truncation errs by at most (1/D) [sum_{p < j <= P} q^j t_j + R_P(q, S) spread_(P+1)]
  // (docs/conventions.md section 3 item 14), t_j the smaller of the absolute bound of the degree-j
  // term, min(j + 1, S) spread_j, and the signed one, sqrt((j + 1) 2^j) times the binomial sum of
  // the trace-free moments' norms (the generators' cancellation); S = sqrt(D/eps) = 1/sqrt(1 - |u|^2).
  // A node whose tail beyond P alone exceeds its share (most of those tested) costs O(P); one used
  // at degree p costs O(P^2 - p^2) here (the binomial sums of the degrees above p), less than the
  // expansion it is used by.
  const double allowed = share * D;
  const double S = this->Epsilon > 0.0 ? std::sqrt(D / this->Epsilon) : HUGE_VAL;
  double bound = treeRemainderBound(P, q, S) * weights.moment(motions, P + 1);
  if (!(bound <= allowed))
  {
    return -1;
  }
  // The signed moments' norms at l = reach.
  const double* harmonic = this->Harmonic.data() + node.harmonic;
  double signedMotions[kHarmonicDegrees];
  for (int k = 0; k <= P; ++k)
  {
    signedMotions[k] =
      harmonic[k] + (harmonic[kHarmonicDegrees + k] + harmonic[2 * kHarmonicDegrees + k] * reach) * reach;
  }
  double qPowers[kMaxDegree + 1];
  qPowers[0] = 1.0;
  for (int j = 1; j <= P; ++j)
  {
    qPowers[j] = qPowers[j - 1] * q;
  }
  int degree = -1;
  for (int p = P; p >= 0 && bound <= allowed; --p)
  {
    degree = p;
    if (p > 0)
    {
      const double absolute = std::min(p + 1.0, S) * weights.moment(motions, p);
      const double cancelling = treeHarmonicTermNorm(p) * weights.moment(signedMotions, p);
      bound += qPowers[p] * std::min(absolute, cancelling);
    }
  }
  return degree;
}

// The target cells' lattice: leaves about kLeafShare (kHighDegreeLeafShare at kMaxDegree) of the
// widest cell usable at any distance (q <= QLimit at |d| = 0: radius QLimit sqrt(eps/k)), a power
// of two wide, between 2^-12 and 2 times the generators' radius; the top cells span the
// generators' diameter.
void GeneratorTree::chooseCells()
{
  const double extent = this->Nodes.empty() ? 0.0 : this->Nodes[0].radius;
  const double share = this->Degree == kMaxDegree ? kHighDegreeLeafShare : kLeafShare;
  const double floorWidth = this->Falloff > 0.0
    ? share * this->QLimit * std::sqrt(this->Epsilon / this->Falloff) * 2.0 / std::sqrt(3.0)
    : HUGE_VAL;
  double side = std::min(floorWidth, 2.0 * extent);
  side = std::max(side, std::ldexp(extent, -12));
  if (!(side > 0.0) || !std::isfinite(side))
  {
    side = std::isfinite(floorWidth) && floorWidth > 0.0 ? floorWidth : 1.0;
  }
  this->LeafSide = std::exp2(std::floor(std::log2(side)));
  // At most 20 levels, clamped as a double: generators near the largest doubles make the ratio
  // (or the extent itself) infinite, which converted to int is undefined (found by the fuzz).
  const double levels = extent > 0.0 ? std::ceil(std::log2(2.0 * extent / this->LeafSide)) : 0.0;
  this->Levels = levels >= 20.0 ? 20 : levels > 0.0 ? static_cast<int>(levels) : 0;
}

// Nodes [first, first + count) of `order`, split at the median of the widest extent.
int GeneratorTree::build(std::size_t first, std::size_t count, std::vector<std::size_t>& order, int depth)
{
  const int index = static_cast<int>(this->Nodes.size());
  this->Nodes.emplace_back();
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, high[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  const double* g = this->Generators.data();
  for (std::size_t i = first; i < first + count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      low[k] = std::min(low[k], g[order[i] * kStride + k]);
      high[k] = std::max(high[k], g[order[i] * kStride + k]);
    }
  }
  Node node;
  node.first = first;
  node.count = count;
  int axis = 0;
  for (int k = 0; k < 3; ++k)
  {
    node.center[k] = 0.5 * low[k] + 0.5 * high[k];
    if (high[k] - low[k] > high[axis] - low[axis])
    {
      axis = k;
    }
  }
  for (std::size_t i = first; i < first + count; ++i)
  {
    const double* x = g + order[i] * kStride;
    const double dx = x[0] - node.center[0], dy = x[1] - node.center[1], dz = x[2] - node.center[2];
    node.radius = std::max(node.radius, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  // Coincident generators stay in one leaf (radius 0: its expansion is exact).
  if (count > kLeafSize && high[axis] > low[axis] && depth < 100)
  {
    const std::size_t half = count / 2;
    std::nth_element(order.begin() + static_cast<long>(first),
                     order.begin() + static_cast<long>(first + half),
                     order.begin() + static_cast<long>(first + count),
                     [g, axis](std::size_t a, std::size_t b) {
                       return g[a * kStride + axis] < g[b * kStride + axis];
                     });
    node.children[0] = this->build(first, half, order, depth + 1);
    node.children[1] = this->build(first + half, count - half, order, depth + 1);
  }
  this->Nodes[static_cast<std::size_t>(index)] = node;
  return index;
}

// The moments of nodes of at least DirectBelow generators: from the children's (exact shift of
// the polynomials) when both have them, else from the generators.
bool GeneratorTree::computeMoments(int index)
{
  Node node = this->Nodes[static_cast<std::size_t>(index)];
  bool childrenHaveMoments = node.children[0] >= 0;
  for (int child : node.children)
  {
    if (child >= 0)
    {
      childrenHaveMoments = this->computeMoments(child) && childrenHaveMoments;
    }
  }
  if (node.count < this->DirectBelow)
  {
    return false;
  }
  const int M = this->MomentCount;
  const std::size_t offset = this->Moments.size();
  this->Moments.resize(offset + static_cast<std::size_t>(M * kComponents), 0.0);
  this->Nodes[static_cast<std::size_t>(index)].moments = static_cast<long>(offset);
  const double scale = node.radius > 0.0 ? node.radius : 1.0;
  if (!childrenHaveMoments)
  {
    this->addGeneratorMoments(node, scale, this->Moments.data() + offset);
    return true;
  }
  // yhat_parent = lambda yhat_child + delta: mu_b += sum_{g <= b} C(b, g) lambda^|g| delta^(b-g) mu_g,
  // the child's moments scaled by lambda^|g| and then shifted one axis at a time (the binomial
  // of (lambda y + delta)^b is the product of the axes' binomials):
  //   mu'_b = sum_{k <= b_axis} C(b_axis, k) delta_axis^k mu_(b - k e_axis),
  // 3 C(P + 4, 4) terms instead of C(P + 6, 6).
  const int P = this->Degree;
  const auto size = static_cast<std::size_t>(M * kComponents);
  std::vector<double> from(size), to(size);
  for (int child : node.children)
  {
    const Node& c = this->Nodes[static_cast<std::size_t>(child)];
    const double childScale = c.radius > 0.0 ? c.radius : 1.0;
    const double lambda = childScale / scale;
    const double delta[3] = { (c.center[0] - node.center[0]) / scale,
                              (c.center[1] - node.center[1]) / scale,
                              (c.center[2] - node.center[2]) / scale };
    double lambdaPower[kMaxDegree + 1];
    lambdaPower[0] = 1.0;
    for (int n = 1; n <= P; ++n)
    {
      lambdaPower[n] = lambdaPower[n - 1] * lambda;
    }
    const double* childMoments = this->Moments.data() + c.moments;
    for (std::size_t m = 0; m < static_cast<std::size_t>(M); ++m)
    {
      for (std::size_t k = 0; k < kComponents; ++k)
      {
        from[m * kComponents + k] = lambdaPower[this->MonomialDegree[m]] * childMoments[m * kComponents + k];
      }
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      double deltaPower[kMaxDegree + 1];
      deltaPower[0] = 1.0;
      for (int n = 1; n <= P; ++n)
      {
        deltaPower[n] = deltaPower[n - 1] * delta[axis];
      }
      std::fill(to.begin(), to.end(), 0.0);
      for (const AxisShiftTerm& term : this->MomentShiftTerms[axis])
      {
        const double factor = term.binomial * deltaPower[term.power];
        for (std::size_t k = 0; k < kComponents; ++k)
        {
          to[static_cast<std::size_t>(term.target) * kComponents + k] +=
            factor * from[static_cast<std::size_t>(term.source) * kComponents + k];
        }
      }
      from.swap(to);
    }
    double* mu = this->Moments.data() + offset;
    for (std::size_t i = 0; i < size; ++i)
    {
      mu[i] += from[i];
    }
  }
  return true;
}

// mu_b[c] += yhat^b g[c] over the node's generators, added to each moment in their order (the same
// bits on every instruction set), four at a time: their monomials computed together (one vector
// of four per monomial), and each moment loaded and stored once per four generators instead of
// once per generator (the loop was bound by those stores and by the monomials' chain).
BOOSTED_LANE_CLONES
void GeneratorTree::addGeneratorMoments(const Node& node, double scale, double* __restrict mu) const
{
  typedef double Four __attribute__((vector_size(4 * sizeof(double))));
  constexpr int kGroup = 4;
  const int M = this->MomentCount;
  // On a 32-byte boundary by hand: with a std::vector<Four> the AVX-512 clone's aligned stores
  // crashed.
  std::vector<double> storage(static_cast<std::size_t>(kGroup * (M + 1)));
  const auto address = reinterpret_cast<std::uintptr_t>(storage.data());
  Four* powers = reinterpret_cast<Four*>((address + 31) & ~std::uintptr_t{ 31 });
  double components[kGroup][kComponents];
  const std::size_t end = node.first + node.count;
  for (std::size_t i = node.first; i < end; i += kGroup)
  {
    const int n = static_cast<int>(std::min<std::size_t>(kGroup, end - i));
    Four y[3] = {};
    for (int k = 0; k < n; ++k)
    {
      const double* g = this->Generators.data() + (i + static_cast<std::size_t>(k)) * kStride;
      for (int axis = 0; axis < 3; ++axis)
      {
        y[axis][k] = (g[axis] - node.center[axis]) / scale;
      }
      std::copy(g + 3, g + 3 + kComponents, components[k]);
    }
    this->monomialPowers(y, M, powers);
    for (int m = 0; m < M; ++m)
    {
      double* out = mu + m * kComponents;
      const Four power = powers[static_cast<std::size_t>(m)];
      if (n == kGroup)
      {
        for (int c = 0; c < kComponents; ++c)
        {
          out[c] = (((out[c] + power[0] * components[0][c]) + power[1] * components[1][c]) +
                    power[2] * components[2][c]) +
            power[3] * components[3][c];
        }
        continue;
      }
      for (int k = 0; k < n; ++k)
      {
        for (int c = 0; c < kComponents; ++c)
        {
          out[c] += power[k] * components[k][c];
        }
      }
    }
  }
}

// sums[c * L + l] += the node's expansion at lane l's point (p: x[L], y[L], z[L]). The lanes are
// the inner loops, so that they vectorize (compiled for the CPU's widest vectors: BOOSTED_LANE_CLONES).
// Adds the nodes `starts` and their subtrees to sums for the lanes' points p, each node by its
// expansion when usable for every point within `radius` of `center` (q at the nearest possible
// distance), else opened; leaves and nodes without moments directly. Nodes visited one after the
// other often hold consecutive generators (siblings: the tree's order), so each such run is summed
// in one call of the block kernel instead of one per node (its sums loaded and stored once).
void GeneratorTree::addNear(const int* starts, std::size_t count, const double* center,
                            double radius, double weightSum, const double* p, double* sums,
                            double* gradients) const
{
  std::size_t runFirst = 0, runEnd = 0; // the generators [runFirst, runEnd) not summed yet
  auto direct = [&](const Node& node) {
    if (node.first != runEnd)
    {
      this->addDirect(runFirst, runEnd - runFirst, p, sums, gradients);
      runFirst = node.first;
    }
    runEnd = node.first + node.count;
  };
  int stack[256];
  for (std::size_t s = 0; s < count; ++s)
  {
    int top = 0;
    stack[top++] = starts[s];
    while (top > 0)
    {
      const Node& node = this->Nodes[static_cast<std::size_t>(stack[--top])];
      if (node.moments < 0)
      {
        direct(node);
        continue;
      }
      const double dx = center[0] - node.center[0], dy = center[1] - node.center[1],
                   dz = center[2] - node.center[2];
      const double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double nearest = std::max(0.0, distance - radius);
      const double q = node.radius > 0.0
        ? node.radius * std::sqrt(this->Falloff / (this->Falloff * nearest * nearest + this->Epsilon))
        : 0.0;
      // Every point is within `radius` of `center`: at least `nearest` and at most
      // distance + radius from the node's center.
      const int degree = this->degreeFor(node, q, this->Falloff * nearest * nearest + this->Epsilon, distance + radius,
                                         this->shareOf(node, distance, radius, weightSum), 0.0);
      if (degree >= 0)
      {
        if (treeBoundRecords)
        {
          treeBoundRecords->push_back({ static_cast<int>(&node - this->Nodes.data()), degree,
                                        { center[0], center[1], center[2] }, radius, q,
                                        this->Falloff * nearest * nearest + this->Epsilon, distance + radius,
                                        this->shareOf(node, distance, radius, weightSum), true });
        }
        if (gradients)
        {
          this->addMultipoleGradient(node, this->Moments.data() + node.moments, degree, p, sums,
                                     gradients);
        }
        else
        {
          this->addMultipole(node, this->Moments.data() + node.moments, degree, p, sums);
        }
      }
      else if (node.children[0] < 0)
      {
        direct(node);
      }
      else
      {
        stack[top++] = node.children[1];
        stack[top++] = node.children[0];
      }
    }
  }
  this->addDirect(runFirst, runEnd - runFirst, p, sums, gradients);
}

// The lanes in one vector (Eight), each moment's terms summed in a register (they are consecutive),
// in the same order and with the same bits as the loops over lanes through arrays before.
BOOSTED_LANE_CLONES
void GeneratorTree::addMultipole(const Node& node, const double* moments, int degree, const double* p,
                                 double* sums) const
{
  static_assert(L == 8, "one vector of Eight per block of lanes");
  const int M = monomialCount(degree);
  alignas(64) double uLanes[3][L], qLanes[L], scaleLanes[L];
  for (int l = 0; l < L; ++l)
  {
    const double d0 = p[l] - node.center[0], d1 = p[L + l] - node.center[1],
                 d2 = p[2 * L + l] - node.center[2];
    const double D = this->Falloff * (d0 * d0 + d1 * d1 + d2 * d2) + this->Epsilon;
    const double rootKappa = std::sqrt(this->Falloff / D);
    qLanes[l] = node.radius * rootKappa; // 0 for a node of coincident generators (only mu_0 != 0)
    uLanes[0][l] = rootKappa * d0;
    uLanes[1][l] = rootKappa * d1;
    uLanes[2][l] = rootKappa * d2;
    scaleLanes[l] = 1.0 / D;
  }
  Eight u[3], q, scale;
  std::memcpy(u, uLanes, sizeof u);
  std::memcpy(&q, qLanes, sizeof q);
  std::memcpy(&scale, scaleLanes, sizeof scale);
  Eight power[kMaxMoments], e[kMaxMoments], out[kComponents];
  this->monomialPowers(u, M, power);
  this->sumSeries(moments, degree, power, q, scale, e, out);
  addLanes(sums, out);
}

// The generators [first, first + count) summed directly for the lanes' points: the block kernel's
// generator loop (kernel::AddFieldBlock, compiled per instruction set with its sums in registers).
void GeneratorTree::addDirect(std::size_t first, std::size_t count, const double* p, double* sums,
                              double* gradients) const
{
  if (count == 0)
  {
    return;
  }
  kernel::FieldArgs args;
  args.generators = this->Generators.data() + first * kStride;
  args.generatorCount = count;
  args.falloff = this->Falloff;
  args.epsilon = this->Epsilon;
  if (gradients)
  {
    kernel::activeAddFieldJacobianBlock()(args, p, sums, gradients);
  }
  else
  {
    kernel::activeAddFieldBlock()(args, p, sums);
  }
}

void GeneratorTree::evaluate(const double* xyz, double* bivectors, double* gradients) const
{
  bool finite[L];
  double center[3] = { 0.0, 0.0, 0.0 };
  int finiteCount = 0;
  for (int l = 0; l < L; ++l)
  {
    finite[l] = std::isfinite(xyz[l]) && std::isfinite(xyz[L + l]) && std::isfinite(xyz[2 * L + l]);
    if (finite[l])
    {
      ++finiteCount;
      for (int k = 0; k < 3; ++k)
      {
        center[k] += xyz[k * L + l];
      }
    }
  }
  std::fill_n(bivectors, kComponents * L, 0.0);
  if (gradients)
  {
    std::fill_n(gradients, 3 * kComponents * L, 0.0);
  }
  if (finiteCount == 0 || this->Nodes.empty())
  {
    return;
  }
  for (double& c : center)
  {
    c /= finiteCount;
  }
  // The lanes' points, a non-finite one replaced by the block's center (its result is dropped).
  double p[3 * L];
  double blockRadius = 0.0;
  for (int l = 0; l < L; ++l)
  {
    double distance2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      p[k * L + l] = finite[l] ? xyz[k * L + l] : center[k];
      const double d = p[k * L + l] - center[k];
      distance2 += d * d;
    }
    blockRadius = std::max(blockRadius, std::sqrt(distance2));
  }
  const int root = 0;
  this->addNear(&root, 1, center, blockRadius, this->weightSum(center, blockRadius), p, bivectors,
                gradients);
  for (int l = 0; l < L; ++l)
  {
    if (!finite[l])
    {
      for (int c = 0; c < kComponents; ++c)
      {
        bivectors[c * L + l] = 0.0;
        for (int k = 0; gradients && k < 3; ++k)
        {
          gradients[(3 * c + k) * L + l] = 0.0;
        }
      }
    }
  }
}

std::size_t GeneratorTree::bytes() const
{
  return this->Generators.capacity() * sizeof(double) + this->Nodes.capacity() * sizeof(Node) +
    this->Moments.capacity() * sizeof(double) + this->Spread.capacity() * sizeof(double) +
    this->Harmonic.capacity() * sizeof(double) +
    this->Terms.capacity() * sizeof(Term) +
    this->MonomialPowers.capacity() * sizeof(std::array<int, 3>) +
    4 * this->MonomialIndex.capacity() * sizeof(int) + this->ShiftGamma.capacity() * sizeof(int) +
    (this->AxisShiftTerms[0].capacity() + this->AxisShiftTerms[1].capacity() + this->AxisShiftTerms[2].capacity() +
     this->MomentShiftTerms[0].capacity() + this->MomentShiftTerms[1].capacity() +
     this->MomentShiftTerms[2].capacity()) *
      sizeof(AxisShiftTerm);
}
} // namespace detail
} // namespace cga
