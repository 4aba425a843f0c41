// PointPairField's derivatives: core::mapPoint and core::mapPointBy (PointMapCore.h) run on dual
// numbers (DualNumber.h), pointwise for double and eight points at a time in the block kernel.
#include "cga/PointPairField.h"

#include "DualNumber.h"
#include "PointMapCore.h"
#include "PointPairKernel.h"
#include "PointPairKernelDispatch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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
    std::fill(jacobian, jacobian + 9, 0.0);
    jacobian[0] = jacobian[4] = jacobian[8] = 1.0;
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

std::size_t PointPairField::mapPointsWithJacobians(const double* in, double* out, double* jacobians,
  std::size_t count, double strength, ExponentialRule rule) const
{
  constexpr int L = kernel::kLanes;
  const auto identity = [](double* j) {
    std::fill(j, j + 9, 0.0);
    j[0] = j[4] = j[8] = 1.0;
  };
  if (this->Count == 0 || strength == 0.0)
  {
    std::size_t unchanged = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
      const double* p = in + 3 * i;
      unchanged += std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) ? 0 : 1;
      std::copy(p, p + 3, out + 3 * i);
      identity(jacobians + 9 * i);
    }
    return unchanged;
  }
  const kernel::FieldArgs args = this->args(strength, rule);
  const kernel::MapBlockJacobian mapBlock = kernel::activeMapBlockJacobian();
  const Vec3 c = this->Center;
  std::size_t unchanged = 0;
  alignas(64) double xyz[3 * L], image[3 * L], jacobian[9 * L];
  std::uint8_t mapped[L];
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    for (int l = 0; l < L; ++l)
    {
      // The last block repeats its last point in the unused lanes (as mapPoints).
      const double* p = in + 3 * (first + std::min(l, n - 1));
      xyz[l] = p[0] - c.x;
      xyz[L + l] = p[1] - c.y;
      xyz[2 * L + l] = p[2] - c.z;
    }
    mapBlock(args, xyz, image, jacobian, mapped);
    for (int l = 0; l < n; ++l)
    {
      const double* p = in + 3 * (first + l);
      double* o = out + 3 * (first + l);
      double* j = jacobians + 9 * (first + l);
      bool finite = mapped[l] != 0;
      for (int e = 0; e < 9 && finite; ++e)
      {
        finite = std::isfinite(jacobian[e * L + l]);
      }
      if (!finite)
      {
        // (in may be out: copy through temporaries)
        const double x = p[0], y = p[1], z = p[2];
        o[0] = x;
        o[1] = y;
        o[2] = z;
        identity(j);
        ++unchanged;
        continue;
      }
      const double x = p[0], y = p[1], z = p[2];
      o[0] = x + (image[l] - xyz[l]);
      o[1] = y + (image[L + l] - xyz[L + l]);
      o[2] = z + (image[2 * L + l] - xyz[2 * L + l]);
      for (int e = 0; e < 9; ++e)
      {
        j[e] = jacobian[e * L + l];
      }
    }
  }
  return unchanged;
}

bool PointPairField::mapWithBivectorDerivative(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* byBivector) const
{
  if (!isFinite(p))
  {
    return false;
  }
  using Tangent = core::Dual<double, kBivector>;
  const Vec3 c = this->Center;
  const double relative[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  const kernel::FieldArgs args = this->args(strength, rule);
  // The value: b = -strength B(p) about the center, as map() computes it.
  double b[kBivector];
  core::fieldBivector(args, relative, -strength, b);
  // The tangents: B in space as the seeds, moved to the center (translateBivector, linear in B:
  // the seeds' values do not matter) and scaled by -strength; the value stays map()'s b.
  Tangent seeds[kBivector], moved[kBivector], exponent[kBivector];
  for (int k = 0; k < kBivector; ++k)
  {
    seeds[k] = core::variable<double, kBivector>(0.0, k);
  }
  const Tangent shift[3] = { core::constant<double, kBivector>(-c.x),
    core::constant<double, kBivector>(-c.y), core::constant<double, kBivector>(-c.z) };
  core::translateBivector(seeds, shift, moved);
  for (int k = 0; k < kBivector; ++k)
  {
    exponent[k] = -strength * moved[k];
    exponent[k].v = b[k];
  }
  Tangent xyz[3], image[3];
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
  out = imageOf(p, relative, image);
  for (int j = 0; j < 3; ++j)
  {
    for (int k = 0; k < kBivector; ++k)
    {
      byBivector[kBivector * j + k] = image[j].d[k];
    }
  }
  return true;
}

bool PointPairField::mapWithWeightDerivatives(
  Vec3 p, double strength, ExponentialRule rule, Vec3& out, double* derivatives) const
{
  if (!isFinite(p))
  {
    return false;
  }
  using Tangent = core::Dual<double, kBivector>;
  const Vec3 c = this->Center;
  const double relative[3] = { p.x - c.x, p.y - c.y, p.z - c.z };
  const kernel::FieldArgs args = this->args(strength, rule);
  // d out / d b for the exponent b = -strength B(p) about the center, then
  // d b / d w_i = -strength G_i / (k |p - x_i|^2 + eps) (G_i about the center too).
  double b[kBivector];
  core::fieldBivector(args, relative, -strength, b);
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
  out = imageOf(p, relative, image);
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
        sum += image[j].d[k] * unit[k];
      }
      derivatives[3 * i + j] = sum * factor;
    }
  }
  return true;
}
} // namespace cga
