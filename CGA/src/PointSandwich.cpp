#include "cga/PointSandwich.h"

#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "PointMapCore.h"

namespace cga
{
ConformalVector sandwichGrade1(const Even& k, const ConformalVector& x)
{
  const detail::EvenArray kk = detail::pack(k);
  ConformalVector r;
  core::sandwichEven(detail::boostTables(), kk.data(), x.c.data(), r.c.data());
  return r;
}

bool normalizePoint(const ConformalVector& p, Vec3& out)
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  double image[3];
  bool mapped = false;
  core::normalize(origin, p.c.data(), image, &mapped);
  if (mapped)
  {
    out = { image[0], image[1], image[2] };
  }
  return mapped;
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
