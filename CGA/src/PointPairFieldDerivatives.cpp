// PointPairField's derivatives: core::mapPoint and core::mapPointBy (PointMapCore.h) run on dual
// numbers (DualNumber.h), pointwise for double and eight points at a time in the block kernel.
#include "cga/PointPairField.h"

#include "DualNumber.h"
#include "GeneratorTree.h"
#include "PointBlocks.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"
#include "StrongSimilarityDerivative.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace cga
{
namespace
{
constexpr int kBivector = Bivector::Count;

template <int N>
bool finiteTangents(const core::Dual<double, N>* x, int count)
{
  for (int i = 0; i < count; ++i)
  {
    for (int k = 0; k < N; ++k)
    {
      if (!std::isfinite(x[i].d[k]))
      {
        return false;
      }
    }
  }
  return true;
}

/// The identity 3x3 (row-major): the derivative of a point the map leaves in place.
void writeIdentity(double* jacobian)
{
  std::fill(jacobian, jacobian + 9, 0.0);
  jacobian[0] = jacobian[4] = jacobian[8] = 1.0;
}

/// The image of p relative to the field's center (as map()): p plus the relative displacement.
template <int N>
Vec3 imageOf(Vec3 p, const double* relative, const core::Dual<double, N>* image)
{
  return { p.x + (image[0].v - relative[0]), p.y + (image[1].v - relative[1]),
    p.z + (image[2].v - relative[2]) };
}
} // namespace

bool PointPairField::mapWithJacobian(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* jacobian) const
{
  if (!isFinite(p))
  {
    return false;
  }
  if (this->Count == 0 || strength == 0.0)
  {
    out = p;
    writeIdentity(jacobian);
    return true;
  }
  if (this->Tree)
  {
    // The tree's B and its derivatives (as map() takes the tree's B): the batch form.
    const double in[3] = { p.x, p.y, p.z };
    double image[3], j[9];
    if (this->mapPointsWithJacobians(in, image, j, 1, strength, rule) != 0)
    {
      return false;
    }
    out = { image[0], image[1], image[2] };
    std::copy(j, j + 9, jacobian);
    return true;
  }
  using Tangent = core::Dual<double, 3>;
  const Vec3 c = this->Center;
  const double relative[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  Tangent xyz[3], image[3];
  for (int i = 0; i < 3; ++i)
  {
    xyz[i] = core::variable<double, 3>(relative[i], i);
  }
  bool mapped = false;
  core::mapPoint(this->args(strength, rule), xyz, image, &mapped);
  if (!mapped || !finiteTangents(image, 3))
  {
    return false;
  }
  out = imageOf(p, relative, image);
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      jacobian[3 * i + j] = image[i].d[j];
    }
  }
  return true;
}

namespace
{
/// Whether the n doubles of lane l of a component-major block are finite.
bool finiteLane(const double* block, int n, int l)
{
  for (int e = 0; e < n; ++e)
  {
    if (!std::isfinite(block[e * kernel::kLanes + l]))
    {
      return false;
    }
  }
  return true;
}

/// mapPointsInBlocks with a generator tree's B(p) and its derivatives d B / d p (one
/// evaluatePoints for the whole call, whose cells' expansions its points share), each block mapped
/// by kernel::MapBlockJacobianBy: the images are mapPoints' with the same tree, to the bit, and
/// onPointWritten(index, jacobian) receives J (row-major, 9 doubles), or null where the point is
/// not mapped or its J is not finite. Returns the count of points not mapped.
template <typename OnPointWritten>
std::size_t mapPointsWithTreeJacobians(const detail::GeneratorTree& tree, int coarser,
  const kernel::FieldArgs& args, Vec3 c, const double* in, double* out, std::size_t count,
  OnPointWritten&& onPointWritten)
{
  constexpr int L = kernel::kLanes;
  std::vector<double> b(kBivector * count), gradients(3 * kBivector * count);
  detail::evaluatePointsAbout(tree, coarser, c, in, count, b.data(), gradients.data());
  const kernel::MapBlockJacobianBy mapBlock = kernel::activeMapBlockJacobianBy();
  alignas(64) double exponents[kBivector * L], exponentGradients[3 * kBivector * L],
    jacobian[9 * L];
  const auto mapLanes = [&](std::size_t first, int n, const double* xyz, double* image,
                          std::uint8_t* mapped) {
    // as mapPoints' exponent; the gradients' rows (3 e + k) in MapBlockJacobianBy's order
    gatherLanes(b.data(), kBivector, first, n, -args.strength, exponents);
    gatherLanes(gradients.data(), 3 * kBivector, first, n, -args.strength, exponentGradients);
    mapBlock(args, exponents, exponentGradients, xyz, image, jacobian, mapped);
    for (int l = 0; l < L; ++l)
    {
      mapped[l] = mapped[l] && finiteLane(jacobian, 9, l);
    }
  };
  const auto written = [&](std::size_t i, int l, bool mapped) {
    double j[9];
    for (int e = 0; e < 9; ++e)
    {
      j[e] = jacobian[e * L + l];
    }
    onPointWritten(i, mapped ? j : nullptr);
  };
  return mapPointsInBlocks(c, in, out, count, mapLanes, written);
}
} // namespace

std::size_t PointPairField::mapPointsWithJacobians(const double* in, double* out, double* jacobians,
  std::size_t count, double strength, ExponentialRule rule) const
{
  constexpr int L = kernel::kLanes;
  if (this->Count == 0 || strength == 0.0)
  {
    return copyPoints(in, out, count,
      [jacobians](std::size_t i, bool) { writeIdentity(jacobians + 9 * i); });
  }
  const kernel::FieldArgs args = this->args(strength, rule);
  if (this->Tree)
  {
    return mapPointsWithTreeJacobians(*this->Tree, this->TreeCellsCoarser, args, this->Center, in,
      out, count,
      [jacobians](std::size_t i, const double* j) {
        if (j)
        {
          std::copy(j, j + 9, jacobians + 9 * i);
        }
        else
        {
          writeIdentity(jacobians + 9 * i);
        }
      });
  }
  const kernel::MapBlockJacobian mapBlock = kernel::activeMapBlockJacobian();
  alignas(64) double jacobian[9 * L];
  const auto mapLanes = [&](std::size_t, int, const double* xyz, double* image,
                          std::uint8_t* mapped) {
    mapBlock(args, xyz, image, jacobian, mapped);
    for (int l = 0; l < L; ++l)
    {
      mapped[l] = mapped[l] && finiteLane(jacobian, 9, l);
    }
  };
  const auto writeJacobian = [&](std::size_t i, int l, bool mapped) {
    double* j = jacobians + 9 * i;
    if (!mapped)
    {
      writeIdentity(j);
      return;
    }
    for (int e = 0; e < 9; ++e)
    {
      j[e] = jacobian[e * L + l];
    }
  };
  return mapPointsInBlocks(this->Center, in, out, count, mapLanes, writeJacobian);
}

std::size_t PointPairField::mapPointsWithDirectionalDerivatives(const double* in,
  const double* directions, double* out, double* derivatives, std::size_t count, double strength,
  ExponentialRule rule) const
{
  constexpr int L = kernel::kLanes, N = kernel::kDirections;
  // Per point N directions of 3 components: t_k's component i at directions[3 N point + 3 k + i].
  constexpr int kPerPoint = 3 * N;
  const auto copyDirections = [directions, derivatives](std::size_t i) {
    std::copy(directions + kPerPoint * i, directions + kPerPoint * (i + 1),
      derivatives + kPerPoint * i);
  };
  if (this->Count == 0 || strength == 0.0)
  {
    return copyPoints(in, out, count, [&](std::size_t i, bool) { copyDirections(i); });
  }
  const kernel::FieldArgs args = this->args(strength, rule);
  if (this->Tree)
  {
    // The tree's whole J, then J t_k.
    return mapPointsWithTreeJacobians(*this->Tree, this->TreeCellsCoarser, args, this->Center, in,
      out, count,
      [&](std::size_t i, const double* j) {
        if (!j)
        {
          copyDirections(i);
          return;
        }
        const double* t = directions + kPerPoint * i;
        double* d = derivatives + kPerPoint * i;
        for (int k = 0; k < N; ++k)
        {
          for (int r = 0; r < 3; ++r)
          {
            d[3 * k + r] =
              j[3 * r] * t[3 * k] + j[3 * r + 1] * t[3 * k + 1] + j[3 * r + 2] * t[3 * k + 2];
          }
        }
      });
  }
  const kernel::MapBlockDirectional mapBlock = kernel::activeMapBlockDirectional();
  alignas(64) double seeds[kPerPoint * L], along[kPerPoint * L];
  const auto mapLanes = [&](std::size_t first, int n, const double* xyz, double* image,
                          std::uint8_t* mapped) {
    for (int l = 0; l < L; ++l)
    {
      const double* t = directions + kPerPoint * (first + std::min(l, n - 1));
      for (int k = 0; k < N; ++k)
      {
        for (int i = 0; i < 3; ++i)
        {
          seeds[(N * i + k) * L + l] = t[3 * k + i]; // the kernel's layout
        }
      }
    }
    mapBlock(args, xyz, seeds, image, along, mapped);
    for (int l = 0; l < L; ++l)
    {
      mapped[l] = mapped[l] && finiteLane(along, kPerPoint, l);
    }
  };
  const auto writeDerivatives = [&](std::size_t i, int l, bool mapped) {
    if (!mapped)
    {
      copyDirections(i);
      return;
    }
    double* d = derivatives + kPerPoint * i;
    for (int k = 0; k < N; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        d[3 * k + c] = along[(N * c + k) * L + l];
      }
    }
  };
  return mapPointsInBlocks(this->Center, in, out, count, mapLanes, writeDerivatives);
}

/// map() of p with d out / d b (byExponent[10 j + k] = d out_j / d b_k) for the exponent
/// b = -strength B(p) about the field's center, as map() computes it: the one differentiation
/// behind mapWithBivectorDerivative and mapWithWeightDerivatives.
bool PointPairField::mapWithExponentDerivative(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* byExponent) const
{
  if (!isFinite(p))
  {
    return false;
  }
  using Tangent = core::Dual<double, kBivector>;
  const Vec3 c = this->Center;
  const double relative[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  const kernel::FieldArgs args = this->args(strength, rule);
  double b[kBivector];
  kernel::activeFieldBivector(args, relative, -strength, b);
  Tangent exponent[kBivector], xyz[3], image[3];
  for (int k = 0; k < kBivector; ++k)
  {
    exponent[k] = core::variable<double, kBivector>(b[k], k);
  }
  for (int i = 0; i < 3; ++i)
  {
    xyz[i] = core::constant<double, kBivector>(relative[i]);
  }
  bool mapped = false;
  core::mapPointBy(args, exponent, xyz, image, &mapped);
  if (!mapped || !finiteTangents(image, 3))
  {
    return false;
  }
  // On the strong lanes the tangents miss the derivative: where the map took the strong sandwich
  // of a similarity's bivector, along seeds that leave the similarities (B's e_i^no parts) they are
  // the derivative of parts that are exactly 0 at b; where it took the two fixed points (B with
  // e_i^no parts), p on the repeller stays it and takes its tangents alone, without the factor
  // e^{2a} that carries p's offset from the moved repeller. The closed form instead
  // (docs/conventions.md section 3 item 15).
  bool similarity = false;
  if (rule == ExponentialRule::Exact && core::strongExponentLane(b, similarity))
  {
    const bool computed = similarity ? core::strongSimilarityExponentDerivative(b, relative, byExponent)
                                     : core::strongBoostExponentDerivative(b, relative, byExponent);
    if (!computed)
    {
      return false; // out unwritten (byExponent is the callers' scratch)
    }
    out = imageOf(p, relative, image);
    return true;
  }
  out = imageOf(p, relative, image);
  for (int j = 0; j < 3; ++j)
  {
    for (int k = 0; k < kBivector; ++k)
    {
      byExponent[kBivector * j + k] = image[j].d[k];
    }
  }
  return true;
}

bool PointPairField::mapWithBivectorDerivative(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* byBivector) const
{
  double byExponent[3 * kBivector];
  if (!this->mapWithExponentDerivative(p, strength, rule, out, byExponent))
  {
    return false;
  }
  // b = -strength (B in space moved to the center): translateBivector is linear in B, so
  // d b / d B_k = -strength times the unit bivector e_k moved by -c.
  const double shift[3] = { -this->Center.x, -this->Center.y, -this->Center.z };
  for (int k = 0; k < kBivector; ++k)
  {
    double unit[kBivector] = {}, moved[kBivector];
    unit[k] = 1.0;
    core::translateBivector(unit, shift, moved);
    for (int j = 0; j < 3; ++j)
    {
      double sum = 0.0;
      for (int c = 0; c < kBivector; ++c)
      {
        sum += byExponent[kBivector * j + c] * moved[c];
      }
      byBivector[kBivector * j + k] = -strength * sum;
    }
  }
  return true;
}

bool PointPairField::mapWithWeightDerivatives(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* derivatives) const
{
  // d out / d b, then d b / d w_i = -strength G_i / (k |p - x_i|^2 + eps) (G_i about the center).
  double byExponent[3 * kBivector];
  if (!this->mapWithExponentDerivative(p, strength, rule, out, byExponent))
  {
    return false;
  }
  const Vec3 c = this->Center;
  const double relative[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    const double* g = this->Generators.data() + i * kernel::kGeneratorStride;
    const double* unit = this->Unweighted.data() + i * kBivector;
    const double dx = relative[0] - g[0], dy = relative[1] - g[1], dz = relative[2] - g[2];
    const double factor = -strength / (this->Falloff * (dx * dx + dy * dy + dz * dz) + this->Epsilon);
    for (int j = 0; j < 3; ++j)
    {
      double sum = 0.0;
      for (int k = 0; k < kBivector; ++k)
      {
        sum += byExponent[kBivector * j + k] * unit[k];
      }
      derivatives[3 * i + j] = sum * factor;
    }
  }
  return true;
}
} // namespace cga
