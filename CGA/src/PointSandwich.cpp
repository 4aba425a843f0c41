#include "cga/PointSandwich.h"

#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "SparseProduct.h"

namespace cga
{
using detail::SparseProduct;

ConformalVector sandwichGrade1(const Even& k, const ConformalVector& x)
{
  // K X has grades 1, 3 and 5; of (K X) ~K only grade 1 is formed.
  static const SparseProduct evenTimesVector(
    detail::kEvenBlades, ConformalVector::kBlades, detail::kOddBlades);
  static const SparseProduct oddTimesEvenToVector(
    detail::kOddBlades, detail::kEvenBlades, ConformalVector::kBlades);
  const detail::EvenArray kk = detail::pack(k);
  const detail::EvenArray rev = detail::pack(reverse(k));
  std::array<double, detail::kOddBlades.size()> odd{};
  evenTimesVector.accumulate(kk.data(), x.c.data(), odd.data());
  ConformalVector r;
  oddTimesEvenToVector.accumulate(odd.data(), rev.data(), r.c.data());
  return r;
}

bool normalizePoint(const ConformalVector& p, Vec3& out)
{
  const double alpha = p.weight();
  if (alpha == 0.0 || !std::isfinite(alpha))
  {
    return false;
  }
  const Vec3 x = p.euclidean() / alpha;
  if (!isFinite(x))
  {
    return false;
  }
  out = x;
  return true;
}

bool sandwichPoint(const Even& k, Vec3 p, Vec3& out)
{
  return normalizePoint(sandwichGrade1(k, ConformalVector::point(p)), out);
}

PointMap::PointMap(const Even& k)
{
  for (int j = 0; j < ConformalVector::Count; ++j)
  {
    ConformalVector basis;
    basis[j] = 1.0;
    const ConformalVector image = sandwichGrade1(k, basis);
    for (int i = 0; i < ConformalVector::Count; ++i)
    {
      this->Matrix[i * ConformalVector::Count + j] = image[i];
    }
  }
}

ConformalVector PointMap::apply(const ConformalVector& x) const
{
  ConformalVector r;
  for (int i = 0; i < ConformalVector::Count; ++i)
  {
    double s = 0.0;
    for (int j = 0; j < ConformalVector::Count; ++j)
    {
      s += this->Matrix[i * ConformalVector::Count + j] * x[j];
    }
    r[i] = s;
  }
  return r;
}

bool PointMap::apply(Vec3 p, Vec3& out) const
{
  return normalizePoint(this->apply(ConformalVector::point(p)), out);
}
} // namespace cga
