// GeneratorTree::evaluatePoints: the target side of the far-field approximation (docs/conventions.md
// section 3 item 14). The points of a call are sorted into the cubes of a fixed lattice (anchored
// at the field's center, leaves LeafSide wide, Levels levels up to the top cells); each occupied
// cell gets a local expansion of degree P, the Taylor polynomial in p - c_cell of the generator
// nodes usable for the whole cell (multipole-to-local), plus its parent's (local-to-local, an
// exact shift of the polynomial); in a leaf each point adds the polynomial's value and the nodes
// left over (the near field, per point as in evaluate()). Cells are cubes of the lattice, not
// boxes around the call's points, so B(p) depends on p alone.
#include "GeneratorTree.h"

#include "cga/Compact.h"

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
constexpr int kComponents = Bivector::Count;
// Points whose leaf index would exceed this are evaluated one by one (evaluate()).
constexpr double kLargestIndex = 0x1p50;

// A point's place in the lattice: its top cell and the Morton code of its leaf within it (the
// coarsest level in the highest bits, so that every cell's points are consecutive once sorted).
struct CellKey
{
  long long top[3];
  std::uint64_t morton;
  std::size_t index;
  bool operator<(const CellKey& other) const
  {
    for (int k = 0; k < 3; ++k)
    {
      if (this->top[k] != other.top[k])
      {
        return this->top[k] < other.top[k];
      }
    }
    if (this->morton != other.morton)
    {
      return this->morton < other.morton;
    }
    return this->index < other.index;
  }
};

std::uint64_t spreadBits(std::uint64_t v)
{
  std::uint64_t r = 0;
  for (int b = 0; b < 21; ++b)
  {
    r |= ((v >> b) & 1u) << (3 * b);
  }
  return r;
}

long long floorDivide(long long a, int shift)
{
  // Arithmetic shift rounds toward minus infinity for negative a on every supported compiler;
  // spelled out to not depend on it.
  const long long divisor = 1LL << shift;
  long long q = a / divisor;
  if (a % divisor != 0 && a < 0)
  {
    --q;
  }
  return q;
}

// The key of point p (finite) in the lattice of leaves 1/inverseSide wide and `levels` levels;
// false where its leaf index would exceed kLargestIndex (then it is evaluated on its own).
bool cellKey(const double* p, double inverseSide, int levels, std::size_t index, CellKey& key)
{
  double scaled[3];
  for (int k = 0; k < 3; ++k)
  {
    scaled[k] = std::floor(p[k] * inverseSide);
    if (!(std::fabs(scaled[k]) < kLargestIndex))
    {
      return false;
    }
  }
  key.morton = 0;
  key.index = index;
  for (int k = 0; k < 3; ++k)
  {
    const auto leaf = static_cast<long long>(scaled[k]);
    key.top[k] = floorDivide(leaf, levels);
    const auto within = static_cast<std::uint64_t>(leaf - key.top[k] * (1LL << levels));
    key.morton |= spreadBits(within) << k;
  }
  return true;
}
} // namespace

namespace
{
// The ten components of a bivector in registers: eight in one vector, two in another (the
// compiler does not vectorize the loop of ten over arrays that may alias).
struct Components
{
  Eight low = {};
  Two high = {};
  void add(double factor, const double* from)
  {
    Eight l;
    Two h;
    std::memcpy(&l, from, sizeof l);
    std::memcpy(&h, from + 8, sizeof h);
    this->low += factor * l;
    this->high += factor * h;
  }
  static Components load(const double* from)
  {
    Components c;
    std::memcpy(&c.low, from, sizeof c.low);
    std::memcpy(&c.high, from + 8, sizeof c.high);
    return c;
  }
  // factor * other, added
  void add(double factor, const Components& other)
  {
    this->low += factor * other.low;
    this->high += factor * other.high;
  }
  void store(double factor, double* to) const
  {
    const Eight l = factor * this->low;
    const Two h = factor * this->high;
    std::memcpy(to, &l, sizeof l);
    std::memcpy(to + 8, &h, sizeof h);
  }
  void addTo(double factor, double* to) const
  {
    Eight l;
    Two h;
    std::memcpy(&l, to, sizeof l);
    std::memcpy(&h, to + 8, sizeof h);
    l += factor * this->low;
    h += factor * this->high;
    std::memcpy(to, &l, sizeof l);
    std::memcpy(to + 8, &h, sizeof h);
  }
};
static_assert(kComponents == 10, "Components holds ten");
} // namespace

// The scratch of one evaluatePoints call: sorted keys, the points, one local expansion and two
// node lists per level.
struct GeneratorTree::CellWork
{
  double leafSide; // the lattice of this call (evaluatePoints' coarser)
  int levels;
  const double* xyz;
  double* bivectors;
  double* gradients; // null: B alone
  std::vector<CellKey> keys;
  std::vector<double> locals;           // per level: MomentCount x kComponents
  std::vector<std::vector<int>> lists;  // per level: the nodes left for the cells below
  std::vector<std::vector<int>> stacks; // per level: the nodes to classify
};

std::size_t GeneratorTree::countCells(const double* xyz, std::size_t count,
                                      std::size_t* cells) const
{
  std::vector<CellKey> keys;
  keys.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const double* p = xyz + 3 * i;
    CellKey key;
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
        cellKey(p, 1.0 / this->LeafSide, this->Levels, i, key))
    {
      keys.push_back(key);
    }
  }
  std::sort(keys.begin(), keys.end());
  // The lattice c levels coarser has the same top cells, and a leaf there is a Morton prefix.
  for (int c = 0; c <= this->Levels; ++c)
  {
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < keys.size(); ++i)
    {
      distinct += i == 0 || !std::equal(keys[i].top, keys[i].top + 3, keys[i - 1].top) ||
        (keys[i].morton >> (3 * c)) != (keys[i - 1].morton >> (3 * c));
    }
    cells[c] += distinct;
  }
  return keys.size();
}

void GeneratorTree::evaluatePoints(const double* xyz, std::size_t count, double* bivectors,
                                   double* gradients, int coarser) const
{
  std::fill_n(bivectors, count * kComponents, 0.0);
  if (gradients)
  {
    std::fill_n(gradients, 3 * count * kComponents, 0.0);
  }
  if (this->Nodes.empty())
  {
    return;
  }
  CellWork work;
  // The same top cells, 2^coarser times as wide leaves (exact: powers of two).
  coarser = std::max(0, std::min(coarser, this->Levels));
  work.leafSide = std::ldexp(this->LeafSide, coarser);
  work.levels = this->Levels - coarser;
  work.xyz = xyz;
  work.bivectors = bivectors;
  work.gradients = gradients;
  work.keys.reserve(count);
  const double inverseSide = 1.0 / work.leafSide;
  const int levels = work.levels;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double* p = xyz + 3 * i;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      continue;
    }
    CellKey key;
    if (!cellKey(p, inverseSide, levels, i, key))
    {
      // Far beyond the generators: one point at a time, every lane the same point.
      alignas(64) double lanes[3 * L], sums[kComponents * L], sumGradients[3 * kComponents * L];
      for (int k = 0; k < 3; ++k)
      {
        std::fill_n(lanes + k * L, L, p[k]);
      }
      this->evaluate(lanes, sums, gradients ? sumGradients : nullptr);
      for (int c = 0; c < kComponents; ++c)
      {
        bivectors[i * kComponents + c] = sums[c * L];
        for (int k = 0; gradients && k < 3; ++k)
        {
          gradients[(i * kComponents + c) * 3 + k] = sumGradients[(3 * c + k) * L];
        }
      }
      continue;
    }
    work.keys.push_back(key);
  }
  std::sort(work.keys.begin(), work.keys.end());
  const std::size_t localSize = static_cast<std::size_t>(this->MomentCount * kComponents);
  work.locals.resize(static_cast<std::size_t>(levels + 1) * localSize);
  work.lists.resize(static_cast<std::size_t>(levels + 2));
  work.stacks.resize(static_cast<std::size_t>(levels + 1));
  work.lists[0].assign(1, 0); // the root for every top cell
  for (std::size_t first = 0; first < work.keys.size();)
  {
    std::size_t last = first + 1;
    const long long* top = work.keys[first].top;
    while (last < work.keys.size() && std::equal(top, top + 3, work.keys[last].top))
    {
      ++last;
    }
    this->evaluateCell(work, 0, first, last, top, nullptr, nullptr);
    first = last;
  }
}

// The cell `cell` (integer coordinates at `level`) holding the sorted keys [first, last).
void GeneratorTree::evaluateCell(CellWork& work, int level, std::size_t first, std::size_t last,
                                 const long long* cell, const double* parentLocal,
                                 const double* parentCenter) const
{
  const double side = std::ldexp(work.leafSide, work.levels - level);
  const double radius = 0.5 * std::sqrt(3.0) * side;
  const double center[3] = { (static_cast<double>(cell[0]) + 0.5) * side,
                             (static_cast<double>(cell[1]) + 0.5) * side,
                             (static_cast<double>(cell[2]) + 0.5) * side };
  const std::size_t localSize = static_cast<std::size_t>(this->MomentCount * kComponents);
  double* local = work.locals.data() + static_cast<std::size_t>(level) * localSize;
  bool hasLocal = parentLocal != nullptr;
  const double weightSum = this->weightSum(center, radius);
  if (hasLocal)
  {
    this->shiftLocal(parentLocal, parentCenter, center, radius, local);
  }
  else
  {
    std::fill_n(local, localSize, 0.0);
  }
  const bool leaf = level == work.levels;
  const std::vector<int>& candidates = work.lists[static_cast<std::size_t>(level)];
  std::vector<int>& left = work.lists[static_cast<std::size_t>(level + 1)];
  std::vector<int>& stack = work.stacks[static_cast<std::size_t>(level)];
  left.clear();
  stack.assign(candidates.rbegin(), candidates.rend());
  while (!stack.empty())
  {
    const int index = stack.back();
    stack.pop_back();
    const Node& node = this->Nodes[static_cast<std::size_t>(index)];
    const double dx = center[0] - node.center[0], dy = center[1] - node.center[1],
                 dz = center[2] - node.center[2];
    const double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    // A point of the cell is at most distance + radius from the node's center.
    const double reach = distance + radius;
    if (node.moments >= 0)
    {
      const double D = this->Falloff * distance * distance + this->Epsilon;
      const double share = this->shareOf(node, distance, radius, weightSum);
      const int degree =
        this->degreeFor(node, (node.radius + radius) * std::sqrt(this->Falloff / D), D, reach, share, radius);
      if (degree >= 0)
      {
        if (treeBoundRecords)
        {
          treeBoundRecords->push_back({ index, degree, { center[0], center[1], center[2] }, radius,
                                        (node.radius + radius) * std::sqrt(this->Falloff / D), D, reach, share, false });
        }
        this->addSourceToLocal(node, center, radius, degree, local);
        hasLocal = true;
        continue;
      }
    }
    // Left whole for the cells below (or the leaf's points one by one) while the cell is the
    // larger of the two, or the node may be usable at the cell's nearest point; else opened.
    const double nearest = std::max(0.0, distance - radius);
    const double nearestD = this->Falloff * nearest * nearest + this->Epsilon;
    const bool usableBelow = node.moments >= 0 &&
      this->degreeFor(node, node.radius * std::sqrt(this->Falloff / nearestD), nearestD, reach,
                      this->shareOf(node, distance, radius, weightSum), 0.0) >= 0;
    if (leaf || node.children[0] < 0 || node.moments < 0 || usableBelow || node.radius <= radius)
    {
      left.push_back(index);
      continue;
    }
    stack.push_back(node.children[1]);
    stack.push_back(node.children[0]);
  }
  if (!leaf)
  {
    const int shift = work.levels - level - 1;
    for (std::size_t begin = first; begin < last;)
    {
      const unsigned octant = static_cast<unsigned>((work.keys[begin].morton >> (3 * shift)) & 7u);
      std::size_t end = begin + 1;
      while (end < last && ((work.keys[end].morton >> (3 * shift)) & 7u) == octant)
      {
        ++end;
      }
      const long long child[3] = { 2 * cell[0] + (octant & 1u), 2 * cell[1] + ((octant >> 1) & 1u),
                                   2 * cell[2] + ((octant >> 2) & 1u) };
      this->evaluateCell(work, level + 1, begin, end, child, hasLocal ? local : nullptr, center);
      begin = end;
    }
    return;
  }
  // The leaf's points, kLanes at a time (the last block repeats its last point).
  for (std::size_t begin = first; begin < last; begin += L)
  {
    const std::size_t n = std::min<std::size_t>(L, last - begin);
    alignas(64) double p[3 * L], sums[kComponents * L], sumGradients[3 * kComponents * L];
    for (int l = 0; l < L; ++l)
    {
      const double* point = work.xyz + 3 * work.keys[begin + std::min<std::size_t>(l, n - 1)].index;
      for (int k = 0; k < 3; ++k)
      {
        p[k * L + l] = point[k];
      }
    }
    std::fill_n(sums, kComponents * L, 0.0);
    double* gradients = work.gradients ? sumGradients : nullptr;
    if (gradients)
    {
      std::fill_n(gradients, 3 * kComponents * L, 0.0);
    }
    if (hasLocal && gradients)
    {
      this->addLocalGradient(local, center, radius, p, sums, gradients);
    }
    else if (hasLocal)
    {
      this->addLocal(local, center, radius, p, sums);
    }
    this->addNear(left.data(), left.size(), center, radius, weightSum, p, sums, gradients);
    for (std::size_t l = 0; l < n; ++l)
    {
      const std::size_t index = work.keys[begin + l].index;
      double* out = work.bivectors + index * kComponents;
      for (int c = 0; c < kComponents; ++c)
      {
        out[c] = sums[c * L + static_cast<int>(l)];
        for (int k = 0; gradients && k < 3; ++k)
        {
          work.gradients[(index * kComponents + c) * 3 + k] =
            gradients[(3 * c + k) * L + static_cast<int>(l)];
        }
      }
    }
  }
}

// local += the degree-p Taylor polynomial in yhat = (p - center)/radius of the node's sum
// (GeneratorTree.h): with d = center - c_node, D = k|d|^2 + eps, u = sqrt(k/D) d,
// a = sqrt(k/D) radius and b = sqrt(k/D) rho_node,
//   L_alpha += (-a)^|alpha| sum_beta C(alpha + beta, alpha) b^|beta| e_(alpha+beta)(u)/D mu_beta.
BOOSTED_LANE_CLONES
void GeneratorTree::addSourceToLocal(const Node& node, const double* center, double radius, int degree,
                                     double* local) const
{
  const int M = (degree + 1) * (degree + 2) * (degree + 3) / 6;
  const double d[3] = { center[0] - node.center[0], center[1] - node.center[1], center[2] - node.center[2] };
  const double D = this->Falloff * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + this->Epsilon;
  const double rootKappa = std::sqrt(this->Falloff / D);
  const double u[3] = { rootKappa * d[0], rootKappa * d[1], rootKappa * d[2] };
  const double a = rootKappa * radius;
  const double b = rootKappa * (node.radius > 0.0 ? node.radius : 1.0);
  double power[kMaxMomentsOfDegree], e[kMaxMomentsOfDegree];
  this->monomialPowers(u, M, power);
  // gamma! e_gamma (the terms' coefficients carry gamma!).
  std::fill_n(e, M, 0.0);
  const std::size_t termCount = this->TermsOfDegree[static_cast<std::size_t>(degree)];
  for (std::size_t t = 0; t < termCount; ++t)
  {
    const Term& term = this->Terms[t];
    e[term.moment] += term.coefficient * power[term.monomial];
  }
  // With C(alpha + beta, alpha) = gamma!/(alpha! beta!) and b^|beta| = b^|gamma| / b^|alpha|:
  //   L_alpha += (-a/b)^|alpha|/alpha! sum_beta (gamma! e_gamma b^|gamma| / D) (mu_beta / beta!),
  // the stored moments as they are (mu_beta / beta!), one product per term. Where a/b = r/rho_node
  // is so large that its powers could overflow (a node far smaller than the cube), the powers of
  // b go to a copy of the moments instead: L_alpha += (-a)^|alpha|/alpha! sum_beta
  // (gamma! e_gamma / D) (b^|beta| mu_beta / beta!).
  const double* moments = this->Moments.data() + node.moments;
  const double ratio = a / b;
  const bool scaleMoments = !(ratio <= 0x1p32);
  double alphaFactor[kMaxDegree + 1], gammaFactor[kMaxDegree + 1];
  alphaFactor[0] = 1.0;
  gammaFactor[0] = 1.0 / D;
  for (int n = 1; n <= degree; ++n)
  {
    alphaFactor[n] = -(scaleMoments ? a : ratio) * alphaFactor[n - 1];
    gammaFactor[n] = (scaleMoments ? 1.0 : b) * gammaFactor[n - 1];
  }
  for (int m = 0; m < M; ++m)
  {
    e[m] *= gammaFactor[this->MonomialDegree[static_cast<std::size_t>(m)]];
  }
  alignas(64) double scaled[kMaxMomentsOfDegree * kComponents];
  if (scaleMoments)
  {
    double bPower = 1.0;
    for (int m = 0; m < M; ++m)
    {
      const auto index = static_cast<std::size_t>(m);
      if (m > 0 && this->MonomialDegree[index] != this->MonomialDegree[index - 1])
      {
        bPower *= b;
      }
      for (int c = 0; c < kComponents; ++c)
      {
        scaled[m * kComponents + c] = bPower * moments[m * kComponents + c];
      }
    }
    moments = scaled;
  }
  // The monomials are in graded order: alpha's betas of |alpha| + |beta| <= degree come first, the
  // same betas for every alpha of one degree. Four alphas at a time share each moment's loads
  // (the moments, 77 KB at degree 16, stream from the cache once per four alphas instead of once
  // per alpha), each alpha's sum in the same order as one at a time.
  for (int n = 0; n <= degree; ++n)
  {
    const int first = n == 0 ? 0 : n * (n + 1) * (n + 2) / 6;
    const int last = (n + 1) * (n + 2) * (n + 3) / 6;
    const int betaCount = (degree - n + 1) * (degree - n + 2) * (degree - n + 3) / 6;
    const double factor = alphaFactor[n];
    int alpha = first;
    for (; alpha + 4 <= last; alpha += 4)
    {
      const int* gamma[4];
      for (int k = 0; k < 4; ++k)
      {
        gamma[k] = this->ShiftGamma.data() + this->ShiftRuns[static_cast<std::size_t>(alpha + k)];
      }
      Components sum[4] = {};
      for (int beta = 0; beta < betaCount; ++beta)
      {
        const Components moment = Components::load(moments + beta * kComponents);
        for (int k = 0; k < 4; ++k)
        {
          sum[k].add(e[gamma[k][beta]], moment);
        }
      }
      for (int k = 0; k < 4; ++k)
      {
        sum[k].addTo(factor * this->InverseFactorial[static_cast<std::size_t>(alpha + k)],
                     local + (alpha + k) * kComponents);
      }
    }
    for (; alpha < last; ++alpha)
    {
      const int* gamma = this->ShiftGamma.data() + this->ShiftRuns[static_cast<std::size_t>(alpha)];
      Components sum = {};
      for (int beta = 0; beta < betaCount; ++beta)
      {
        sum.add(e[gamma[beta]], moments + beta * kComponents);
      }
      sum.addTo(factor * this->InverseFactorial[static_cast<std::size_t>(alpha)], local + alpha * kComponents);
    }
  }
}

// local = the parent's polynomial in the child's variable: yhat_parent = lambda yhat + delta,
// lambda = radius / parentRadius = 1/2, delta = (center - parentCenter)/parentRadius:
//   L_alpha = lambda^|alpha| sum_beta C(alpha + beta, alpha) delta^beta L_parent,(alpha+beta),
// the shift by delta done as the shifts by delta_x e_x, delta_y e_y, delta_z e_z in turn (each
// exact for a polynomial of degree P: sum_k C(alpha_axis + k, k) delta_axis^k L_(alpha + k e_axis)),
// 3 C(P + 4, 4) terms instead of C(P + 6, 6) (14,535 against 74,613 at P = 16).
BOOSTED_LANE_CLONES
void GeneratorTree::shiftLocal(const double* parent, const double* parentCenter, const double* center,
                               double radius, double* local) const
{
  const int P = this->Degree;
  const double parentRadius = 2.0 * radius;
  alignas(64) double scratch[kMaxMomentsOfDegree * kComponents];
  // parent -> local (x) -> scratch (y) -> local (z, with lambda^|alpha|).
  double lambdaPower[kMaxDegree + 1];
  lambdaPower[0] = 1.0;
  for (int n = 1; n <= P; ++n)
  {
    lambdaPower[n] = 0.5 * lambdaPower[n - 1];
  }
  const double* from[3] = { parent, local, scratch };
  double* to[3] = { local, scratch, local };
  for (int axis = 0; axis < 3; ++axis)
  {
    const double delta = (center[axis] - parentCenter[axis]) / parentRadius;
    double deltaPower[kMaxDegree + 1];
    deltaPower[0] = 1.0;
    for (int n = 1; n <= P; ++n)
    {
      deltaPower[n] = delta * deltaPower[n - 1];
    }
    const std::vector<AxisShiftTerm>& terms = this->AxisShiftTerms[axis];
    for (std::size_t t = 0; t < terms.size();)
    {
      const int target = terms[t].target;
      Components sum = {};
      for (; t < terms.size() && terms[t].target == target; ++t)
      {
        sum.add(terms[t].binomial * deltaPower[terms[t].power], from[axis] + terms[t].source * kComponents);
      }
      sum.store(axis == 2 ? lambdaPower[this->MonomialDegree[static_cast<std::size_t>(target)]] : 1.0,
                to[axis] + target * kComponents);
    }
  }
}

// sums[c * L + l] += the local polynomial at lane l's point. The lanes in one vector (Eight): the
// compiler's own vectorization of the loops over lanes shuffled the ten components instead
// (16 % of the mapping's samples at Tolerance 0.1, M = 100,000).
BOOSTED_LANE_CLONES
void GeneratorTree::addLocal(const double* local, const double* center, double radius, const double* p,
                             double* sums) const
{
  static_assert(L == 8, "one vector of Eight per block of lanes");
  const int M = this->MomentCount;
  const double inverse = 1.0 / radius;
  Eight y[3];
  for (int k = 0; k < 3; ++k)
  {
    Eight coordinate;
    std::memcpy(&coordinate, p + k * L, sizeof coordinate);
    y[k] = (coordinate - center[k]) * inverse;
  }
  Eight power[kMaxMomentsOfDegree];
  this->monomialPowers(y, M, power);
  Eight out[kComponents];
  this->sumLocal(local, power, out);
  addLanes(sums, out);
}
} // namespace detail
} // namespace cga
