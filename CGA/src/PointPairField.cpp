#include "cga/PointPairField.h"

#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include "GeneratorTree.h"
#include "PointBlocks.h"
#include "PointPairKernelDispatch.h"
#include "PointMapCore.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

namespace cga
{
Even exponential(const Bivector& b, ExponentialRule rule)
{
  return rule == ExponentialRule::Exact ? expExact(b) : expPaper(b);
}

bool isGeneratorKind(int kind)
{
  return kind >= static_cast<int>(GeneratorKind::PointPair) &&
    kind <= static_cast<int>(GeneratorKind::Translation);
}

namespace
{
// 1/2 T(x) (a I3) ~T(x) = 1/2 (A - (x _| A) ni) with A = a I3 = a.z e12 - a.y e13 + a.x e23.
Bivector halfDualLine(Vec3 x, Vec3 a)
{
  using B = Bivector;
  Bivector b;
  b[B::E12] = 0.5 * a.z;
  b[B::E13] = -0.5 * a.y;
  b[B::E23] = 0.5 * a.x;
  // x _| (e_i ^ e_j) = x_i e_j - x_j e_i.
  const Vec3 contraction{ -x.y * b[B::E12] - x.z * b[B::E13],
                          x.x * b[B::E12] - x.z * b[B::E23],
                          x.x * b[B::E13] + x.y * b[B::E23] };
  b[B::E1NI] = -contraction.x;
  b[B::E2NI] = -contraction.y;
  b[B::E3NI] = -contraction.z;
  return b;
}

// The field's frame per coordinate: the mean m of the kept locations x_i where every x_i lies in
// [0.6, 1.6] m, else 0. In the first case x_i - m is exact (Sterbenz: y/2 <= x <= 2y makes x - y
// exact) and so is p - m for a point within 0.1 |m| of some x_i, so p - x_i formed from the two is
// the given doubles' difference to one rounding; a point farther from x_i loses at most
// 7 2^-53 |p - x_i| there (|p - m| < 7 |p - x_i|). The mean alone, inexact for three locations,
// changed |p - x_i|^2 by up to 2^-53 |p - m| / |p - x_i| of itself (1e-11 at 1e-5 from x_i).
// Otherwise the locations span at least 0.4 |m|, so with 0 (every difference exact) they are at
// most 3.5 times that span.
double frameCoordinate(double mean, const FieldGenerator* generators,
                       const std::vector<std::size_t>& kept, double Vec3::*axis)
{
  for (const std::size_t i : kept)
  {
    const double ratio = generators[i].location.*axis / mean; // NaN where mean = 0: 0 returned
    if (!(ratio >= 0.6 && ratio <= 1.6))
    {
      return 0.0;
    }
  }
  return mean;
}

// b += 1/2 d ni.
void addHalfTranslation(Bivector& b, Vec3 d)
{
  b[Bivector::E1NI] += 0.5 * d.x;
  b[Bivector::E2NI] += 0.5 * d.y;
  b[Bivector::E3NI] += 0.5 * d.z;
}
} // namespace

FieldGenerator FieldGenerator::pointPair(Vec3 location, Vec3 direction, double weight)
{
  return { location, nullPointPairCompact(location, direction), weight,
           nullPointPairCompact(Vec3{ 0.0, 0.0, 0.0 }, direction) };
}

FieldGenerator FieldGenerator::rotation(Vec3 location, Vec3 axis, double weight)
{
  return { location, halfDualLine(location, axis), weight, halfDualLine(Vec3{ 0.0, 0.0, 0.0 }, axis) };
}

FieldGenerator FieldGenerator::twist(Vec3 location, Vec3 axis, double pitch, double weight)
{
  FieldGenerator g = rotation(location, axis, weight);
  addHalfTranslation(g.bivector, pitch * axis);
  addHalfTranslation(*g.atOrigin, pitch * axis); // a translation is the same about every point
  return g;
}

FieldGenerator FieldGenerator::dilation(Vec3 location, double weight)
{
  FieldGenerator g{ location, Bivector{}, weight };
  g.bivector[Bivector::NONI] = -0.5;
  g.atOrigin = g.bivector;
  addHalfTranslation(g.bivector, -1.0 * location); // -1/2 x ^ ni
  return g;
}

FieldGenerator FieldGenerator::translation(Vec3 location, Vec3 direction, double weight)
{
  FieldGenerator g{ location, Bivector{}, weight };
  addHalfTranslation(g.bivector, direction);
  g.atOrigin = g.bivector;
  return g;
}

FieldGenerator FieldGenerator::of(
  GeneratorKind kind, Vec3 location, Vec3 direction, double pitch, double weight)
{
  const double length = norm(direction);
  const bool usable = isGeneratorKind(static_cast<int>(kind)) && isFinite(direction) &&
    length != 0.0 && std::isfinite(length) && (kind != GeneratorKind::Twist || std::isfinite(pitch));
  if (!usable)
  {
    return { location, Bivector{}, std::nan("") };
  }
  switch (kind)
  {
    case GeneratorKind::Rotation:
      return rotation(location, direction, weight);
    case GeneratorKind::Twist:
      return twist(location, direction, pitch, weight);
    case GeneratorKind::Dilation:
    {
      // The length multiplies the bivector, as the direction's does for the other kinds.
      FieldGenerator g = dilation(location, weight);
      g.bivector *= length;
      *g.atOrigin *= length;
      return g;
    }
    case GeneratorKind::Translation:
      return translation(location, direction, weight);
    case GeneratorKind::PointPair:
    default:
      return pointPair(location, direction, weight);
  }
}

namespace
{
// The rows as field generators in space (FieldGenerator::of: a zero or non-finite direction gives
// a NaN weight, which the field skips).
std::vector<FieldGenerator> fieldsOf(const GeneratorParameters* rows, std::size_t count)
{
  std::vector<FieldGenerator> fields;
  fields.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    fields.push_back(rows[i].field());
  }
  return fields;
}
} // namespace

PointPairField::PointPairField(const PointPairGenerator* generators,
                               std::size_t count,
                               double falloff,
                               double epsilon)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  std::vector<GeneratorParameters> rows(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    rows[i].location = generators[i].location;
    rows[i].direction = generators[i].direction;
    rows[i].weight = generators[i].weight;
  }
  this->add(fieldsOf(rows.data(), count).data(), rows.data(), count);
}

PointPairField::PointPairField(const GeneratorParameters* generators,
                               std::size_t count,
                               double falloff,
                               double epsilon)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  this->add(fieldsOf(generators, count).data(), generators, count);
}

PointPairField::PointPairField(const FieldGenerator* generators,
                               std::size_t count,
                               double falloff,
                               double epsilon)
  : Falloff(falloff)
  , Epsilon(epsilon)
{
  this->add(generators, nullptr, count);
}

namespace
{
// True when atOrigin moved to `location` is `bivector` to rounding: each component within 64 units
// of 2^-53 of |atOrigin|max (1 + |location|)^2, the size of the translation's terms (a named
// constructor's pair differs by a few units). A caller who edited `bivector`, `location` or
// `atOrigin` after construction fails it by far.
bool atOriginIsBivector(const FieldGenerator& g)
{
  const Bivector moved = translatedBivector(*g.atOrigin, g.location);
  const double reach = 1.0 + norm(g.location);
  const double tolerance = 64.0 * 0x1p-53 * g.atOrigin->maxAbs() * reach * reach;
  for (int k = 0; k < Bivector::Count; ++k)
  {
    if (!(std::abs(moved[k] - g.bivector[k]) <= tolerance))
    {
      return false;
    }
  }
  return true;
}
} // namespace

// `rows`, when given, are the rows `generators` were made of: their relative generators are built
// at x_i - c rather than moved there (eps |x_i| instead of eps |x_i|^2). A FieldGenerator's
// atOrigin is used only where it is its bivector to rounding (atOriginIsBivector): otherwise the
// bivector, which the caller may have edited, is moved as given.
void PointPairField::add(
  const FieldGenerator* generators, const GeneratorParameters* rows, std::size_t count)
{
  static_assert(kernel::kGeneratorStride == 3 + Bivector::Count, "location, then the bivector");
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < count; ++i)
  {
    const FieldGenerator& g = generators[i];
    if (!isFinite(g.location) || !g.bivector.isFinite() || !std::isfinite(g.weight) ||
      g.bivector.maxAbs() == 0.0)
    {
      ++this->Skipped;
      continue;
    }
    kept.push_back(i);
  }
  // The mean as a sum of x_i / n: no overflow; a lone generator's location exactly, so a point on
  // it maps to itself exactly.
  Vec3 mean;
  const double share = kept.empty() ? 0.0 : 1.0 / static_cast<double>(kept.size());
  for (const std::size_t i : kept)
  {
    mean = mean + share * generators[i].location;
  }
  this->Center = { frameCoordinate(mean.x, generators, kept, &Vec3::x),
                   frameCoordinate(mean.y, generators, kept, &Vec3::y),
                   frameCoordinate(mean.z, generators, kept, &Vec3::z) };
  this->Generators.reserve(kept.size() * kernel::kGeneratorStride);
  for (const std::size_t i : kept)
  {
    const FieldGenerator& g = generators[i];
    const Vec3 location = g.location - this->Center;
    Bivector relative;
    if (rows)
    {
      GeneratorParameters row = rows[i];
      row.location = location;
      relative = row.field().bivector;
    }
    else if (g.atOrigin && atOriginIsBivector(g))
    {
      relative = translatedBivector(*g.atOrigin, location);
    }
    else
    {
      relative = translatedBivector(g.bivector, -this->Center);
    }
    const Bivector weighted = g.weight * relative;
    this->Generators.insert(this->Generators.end(), { location.x, location.y, location.z });
    this->Generators.insert(this->Generators.end(), weighted.c.begin(), weighted.c.end());
    this->Unweighted.insert(this->Unweighted.end(), relative.c.begin(), relative.c.end());
    ++this->Count;
  }
}

kernel::FieldArgs PointPairField::args(double strength, ExponentialRule rule) const
{
  kernel::FieldArgs args;
  args.generators = this->Generators.data();
  args.generatorCount = this->Count;
  args.falloff = this->Falloff;
  args.epsilon = this->Epsilon;
  args.strength = strength;
  args.exactRule = rule == ExponentialRule::Exact;
  return args;
}

bool PointPairField::setTolerance(double tolerance, std::size_t minimumGenerators, double minimumTolerance)
{
  if (!(tolerance >= 0.0))
  {
    return false;
  }
  this->Tolerance = std::min(tolerance, maximumTolerance());
  this->Tree.reset();
  this->TreeCellsCoarser = 0;
  if (usesTree(this->Tolerance, this->Count, minimumGenerators, minimumTolerance))
  {
    this->Tree = std::make_shared<const detail::GeneratorTree>(
      this->Generators.data(), this->Count, this->Falloff, this->Epsilon, this->Tolerance);
  }
  return true;
}

bool PointPairField::usesTree(double tolerance, std::size_t generators,
  std::size_t minimumGenerators, double minimumTolerance)
{
  if (minimumTolerance < 0.0)
  {
    minimumTolerance = treeMinimumTolerance(generators);
  }
  tolerance = std::min(tolerance, maximumTolerance()); // NaN stays NaN: no tree
  return tolerance > 0.0 && tolerance >= minimumTolerance &&
    generators >= std::max<std::size_t>(1, minimumGenerators);
}

bool PointPairField::shareTree(const PointPairField& previous, double tolerance,
  std::size_t minimumGenerators, double minimumTolerance)
{
  if (!(tolerance >= 0.0) || !previous.Tree)
  {
    return false;
  }
  // The tree is a function of these alone (GeneratorTree's constructor), compared bit for bit:
  // the generators as kept (relative to the center), their count, falloff, epsilon, tolerance.
  const auto sameBits = [](const double* a, const double* b, std::size_t count) {
    return std::memcmp(a, b, count * sizeof(double)) == 0;
  };
  const double used = std::min(tolerance, maximumTolerance());
  if (!usesTree(used, this->Count, minimumGenerators, minimumTolerance) ||
      previous.Count != this->Count || previous.Generators.size() != this->Generators.size() ||
      !sameBits(&previous.Tolerance, &used, 1) || !sameBits(&previous.Falloff, &this->Falloff, 1) ||
      !sameBits(&previous.Epsilon, &this->Epsilon, 1) ||
      !sameBits(previous.Generators.data(), this->Generators.data(), this->Generators.size()))
  {
    return false;
  }
  this->Tolerance = used;
  this->Tree = previous.Tree;
  this->TreeCellsCoarser = 0;
  return true;
}

int PointPairField::planTreeCells(std::size_t count,
  const std::function<void(std::size_t first, std::size_t n, double* xyz)>& pointsOf)
{
  this->TreeCellsCoarser = 0;
  if (!this->Tree || count == 0)
  {
    return 0;
  }
  const detail::GeneratorTree& tree = *this->Tree;
  std::vector<std::size_t> cells(static_cast<std::size_t>(tree.levels()) + 1, 0);
  std::vector<double> xyz;
  std::size_t counted = 0;
  const std::size_t chunks = (count + treePlanChunk() - 1) / treePlanChunk();
  const std::size_t used = std::min(chunks, treePlanChunks());
  for (std::size_t j = 0; j < used; ++j)
  {
    // Chunks spread evenly from the first to the last, moved to the center as the tree takes them.
    const std::size_t chunk = used > 1 ? j * (chunks - 1) / (used - 1) : 0;
    const std::size_t first = chunk * treePlanChunk();
    const std::size_t n = std::min(treePlanChunk(), count - first);
    xyz.resize(3 * n);
    pointsOf(first, n, xyz.data());
    for (std::size_t i = 0; i < n; ++i)
    {
      xyz[3 * i] -= this->Center.x;
      xyz[3 * i + 1] -= this->Center.y;
      xyz[3 * i + 2] -= this->Center.z;
    }
    counted += tree.countCells(xyz.data(), n, cells.data());
  }
  int coarser = 0;
  while (coarser < tree.levels() &&
         counted < treeCellPoints() * cells[static_cast<std::size_t>(coarser)])
  {
    ++coarser;
  }
  this->TreeCellsCoarser = coarser;
  return coarser;
}

int PointPairField::planTreeCells(const double* points, std::size_t count)
{
  return this->planTreeCells(count, [points](std::size_t first, std::size_t n, double* xyz) {
    std::copy_n(points + 3 * first, 3 * n, xyz);
  });
}

int PointPairField::planTreeCells(const float* points, std::size_t count)
{
  return this->planTreeCells(count, [points](std::size_t first, std::size_t n, double* xyz) {
    std::copy_n(points + 3 * first, 3 * n, xyz);
  });
}

bool PointPairField::sharesTreeWith(const PointPairField& other) const
{
  return this->Tree && this->Tree == other.Tree;
}

double PointPairField::treeMinimumTolerance(std::size_t generators)
{
  const double count = static_cast<double>(std::max<std::size_t>(generators, 1));
  return std::min(maximumTolerance(), 1e-4 * std::pow(10000.0 / count, 3.0));
}

std::size_t PointPairField::treeBytes() const
{
  return this->Tree ? this->Tree->bytes() : 0;
}

int PointPairField::treeDegree() const
{
  return this->Tree ? this->Tree->degree() : 0;
}

double PointPairField::treeDisplacementScale() const
{
  return this->Tree ? this->Tree->displacementScale() : 0.0;
}

Bivector PointPairField::generatorAt(Vec3 p) const
{
  const Vec3 relative = p - this->Center;
  Bivector b;
  if (this->Tree)
  {
    const double xyz[3] = { relative.x, relative.y, relative.z };
    this->Tree->evaluatePoints(xyz, 1, b.c.data(), nullptr, this->TreeCellsCoarser);
  }
  else
  {
    const double xyz[3] = { relative.x, relative.y, relative.z };
    kernel::activeFieldBivector(this->args(1.0, ExponentialRule::Exact), xyz, 1.0, b.c.data());
  }
  return translatedBivector(b, this->Center); // back in space
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
  if (this->Count == 0 || strength == 0.0)
  {
    out = p;
    return true;
  }
  if (this->Tree)
  {
    const double in[3] = { p.x, p.y, p.z };
    double image[3];
    if (this->mapPointsOf(in, image, 1, strength, rule) != 0)
    {
      return false;
    }
    out = { image[0], image[1], image[2] };
    return true;
  }
  // core::mapPoint for one point (the block kernel instantiates the same template for its lanes),
  // its B(p) by the kernel's generator loop (activeFieldBivector: the same bits, on the FMA
  // instruction). Relative to the center, as the block kernel's lanes (PointBlocks.h); the image
  // is p plus the relative displacement, so that a point the map leaves in place comes back to
  // the bit.
  const Vec3 c = this->Center;
  const double xyz[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  const kernel::FieldArgs args = this->args(strength, rule);
  double b[kernel::kBivectorComponents], image[3];
  kernel::activeFieldBivector(args, xyz, -strength, b);
  bool mapped = false;
  core::mapPointBy(args, b, xyz, image, &mapped);
  if (!mapped)
  {
    return false;
  }
  out = { p.x + (image[0] - xyz[0]), p.y + (image[1] - xyz[1]), p.z + (image[2] - xyz[2]) };
  return true;
}

namespace
{
// mapPoints' blocks (PointBlocks.h): runBlocks(mapLanes) runs one of its block loops with the
// kernel's mapLanes. With a tree, B(p) of each block comes from it and the kernel maps with the
// given B.
template <typename In, typename RunBlocks>
auto mapPointsByKernel(const kernel::FieldArgs& args,
                       const detail::GeneratorTree* tree,
                       int coarser,
                       Vec3 c,
                       const In* in,
                       std::size_t count,
                       RunBlocks&& runBlocks)
{
  constexpr int L = kernel::kLanes;
  const kernel::MapBlock mapBlock = kernel::activeMapBlock();
  const kernel::MapBlockBy mapBlockBy = kernel::activeMapBlockBy();
  alignas(64) double bivectors[Bivector::Count * L];
  // With a tree, B of every point of the call first (the tree's target cells span the call).
  std::vector<double> treeBivectors;
  if (tree)
  {
    treeBivectors.resize(Bivector::Count * count);
    detail::evaluatePointsAbout(*tree, coarser, c, in, count, treeBivectors.data());
  }
  const auto mapLanes = [&](std::size_t first, int n, const double* xyz, double* image,
                          std::uint8_t* mapped) {
    if (!tree)
    {
      mapBlock(args, xyz, image, mapped);
      return;
    }
    // the exponent, as mapBlock's
    gatherLanes(treeBivectors.data(), Bivector::Count, first, n, -args.strength, bivectors);
    mapBlockBy(args, bivectors, xyz, image, mapped);
  };
  return runBlocks(mapLanes);
}

bool finite3(double x, double y, double z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

// mapPointsWithDisplacements' and mapPoints' whole blocks of double points, each in one call of
// the kernel (kernel::MapDisplacedBlock: the images and displacements in its registers instead of
// a pass of scalar code per point; displacements null: the images only), two blocks a call where
// the instruction set has a wide block (kernel::MapDisplacedWideBlock). Returns the points done:
// count less its last partial block.
std::size_t mapWholeBlocks(const kernel::FieldArgs& args, Vec3 c,
  const double* in, double* out, double* displacements, std::size_t count,
  BlockDisplacementCounts& counts)
{
  constexpr std::size_t L = kernel::kLanes, W = kernel::kWideLanes;
  const kernel::MapDisplacedBlock mapBlock = kernel::activeMapDisplacedBlock();
  const kernel::MapDisplacedWideBlock mapWideBlock = kernel::activeMapDisplacedWideBlock();
  const double center[3] = { c.x, c.y, c.z };
  std::uint8_t mapped[W];
  const std::size_t whole = count - count % L;
  auto mapFrom = [&](std::size_t first, kernel::MapDisplacedBlock map, std::size_t lanes) {
    double* o = out + 3 * first;
    counts.beyondRange += static_cast<std::size_t>(
      map(args, center, in + 3 * first, o, displacements ? displacements + 3 * first : nullptr,
        mapped));
    for (std::size_t l = 0; l < lanes; ++l)
    {
      // A point left in place: not finite, or its image is not (then a finite point).
      if (!mapped[l])
      {
        ++counts.unchanged;
        counts.notFinite += finite3(o[3 * l], o[3 * l + 1], o[3 * l + 2]) ? 0 : 1;
      }
    }
  };
  std::size_t first = 0;
  if (mapWideBlock)
  {
    for (; first + W <= whole; first += W)
    {
      mapFrom(first, mapWideBlock, W);
    }
  }
  for (; first < whole; first += L)
  {
    mapFrom(first, mapBlock, L);
  }
  return whole;
}

} // namespace

template <typename In, typename Out>
std::size_t PointPairField::mapPointsOf(
  const In* in, Out* out, std::size_t count, double strength, ExponentialRule rule) const
{
  if (this->Count == 0 || strength == 0.0)
  {
    return copyPoints(in, out, count, [](std::size_t, bool) {});
  }
  const Vec3 c = this->Center;
  const kernel::FieldArgs args = this->args(strength, rule);
  std::size_t done = 0, unmapped = 0;
  if constexpr (std::is_same<In, double>::value && std::is_same<Out, double>::value)
  {
    if (!this->Tree)
    {
      BlockDisplacementCounts found;
      done = mapWholeBlocks(args, c, in, out, nullptr, count, found);
      unmapped = found.unchanged;
    }
  }
  // The rest (the last partial block; float points; the tree) block by block in lanes.
  const In* restIn = in + 3 * done;
  return unmapped +
    mapPointsByKernel(args, this->Tree.get(), this->TreeCellsCoarser, c, restIn, count - done,
      [&](const auto& mapLanes) {
      return mapPointsInBlocks(c, restIn, out + 3 * done, count - done, mapLanes,
        [](std::size_t, int, bool) {});
    });
}

template <typename In, typename Out>
PointPairField::DisplacementCounts PointPairField::mapPointsWithDisplacementsOf(const In* in,
  Out* out, Out* displacements, std::size_t count, double strength, ExponentialRule rule) const
{
  DisplacementCounts counts;
  if (this->Count > 0 && strength != 0.0)
  {
    const Vec3 c = this->Center;
    const kernel::FieldArgs args = this->args(strength, rule);
    BlockDisplacementCounts found;
    std::size_t done = 0;
    if constexpr (std::is_same<In, double>::value && std::is_same<Out, double>::value)
    {
      if (!this->Tree)
      {
        done = mapWholeBlocks(args, c, in, out, displacements, count, found);
      }
    }
    // The rest (the last partial block; float points; the tree) block by block in lanes.
    const In* restIn = in + 3 * done;
    const BlockDisplacementCounts rest = mapPointsByKernel(args, this->Tree.get(),
      this->TreeCellsCoarser, c, restIn,
      count - done, [&](const auto& mapLanes) {
        return mapPointsAndDisplacementsInBlocks(
          c, restIn, out + 3 * done, displacements + 3 * done, count - done, mapLanes);
      });
    counts.unchanged = found.unchanged + rest.unchanged;
    counts.notFinite = found.notFinite + rest.notFinite;
    counts.beyondRange = found.beyondRange + rest.beyondRange;
    return counts;
  }
  // The points copied: each point's displacement right after it.
  std::size_t beyondRange = 0;
  const auto onPointWritten = [&](std::size_t index, bool mapped) {
    const In* p = in + 3 * index;
    const Out* o = out + 3 * index;
    Out* d = displacements + 3 * index;
    const double x = p[0], y = p[1], z = p[2];
    if (!mapped && !finite3(x, y, z))
    {
      ++counts.notFinite;
      d[0] = d[1] = d[2] = Out(0);
      return;
    }
    d[0] = static_cast<Out>(o[0] - x);
    d[1] = static_cast<Out>(o[1] - y);
    d[2] = static_cast<Out>(o[2] - z);
    beyondRange += finiteImageAndDisplacement(o, d) ? 0 : 1;
  };
  counts.unchanged = copyPoints(in, out, count, onPointWritten);
  counts.beyondRange = beyondRange;
  return counts;
}

std::size_t PointPairField::mapPoints(
  const double* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsOf(in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsOf(in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const float* in, double* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsOf(in, out, count, strength, rule);
}

std::size_t PointPairField::mapPoints(
  const double* in, float* out, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsOf(in, out, count, strength, rule);
}

PointPairField::DisplacementCounts PointPairField::mapPointsWithDisplacements(const double* in,
  double* out, double* displacements, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsWithDisplacementsOf(in, out, displacements, count, strength, rule);
}

PointPairField::DisplacementCounts PointPairField::mapPointsWithDisplacements(const float* in,
  float* out, float* displacements, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsWithDisplacementsOf(in, out, displacements, count, strength, rule);
}

PointPairField::DisplacementCounts PointPairField::mapPointsWithDisplacements(const float* in,
  double* out, double* displacements, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsWithDisplacementsOf(in, out, displacements, count, strength, rule);
}

PointPairField::DisplacementCounts PointPairField::mapPointsWithDisplacements(const double* in,
  float* out, float* displacements, std::size_t count, double strength, ExponentialRule rule) const
{
  return this->mapPointsWithDisplacementsOf(in, out, displacements, count, strength, rule);
}

std::vector<std::string> mapPointsInstructionSets()
{
  return kernel::availableInstructionSets();
}

std::string mapPointsInstructionSet()
{
  return kernel::activeInstructionSet();
}

bool useMapPointsInstructionSet(const std::string& name)
{
  return kernel::useInstructionSet(name);
}
} // namespace cga
