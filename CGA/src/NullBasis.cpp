#include "cga/NullBasis.h"

#include "NullBladeProduct.h"

namespace cga
{
int nullBladeProduct(unsigned a, unsigned b, NullTerm out[2])
{
  return detail::nullBladeTerms(a, b, out);
}

Multivector nullBladeToMultivector(unsigned blade)
{
  double null[kBladeCount] = {};
  double orthonormal[kBladeCount];
  null[blade & 31u] = 1.0;
  nullToOrthonormal(null, orthonormal);
  Multivector m;
  for (int i = 0; i < kBladeCount; ++i)
  {
    m.c[i] = orthonormal[i];
  }
  return m;
}

void nullToOrthonormal(const double null[kBladeCount], double orthonormal[kBladeCount])
{
  for (unsigned a = 0; a < 8u; ++a)
  {
    const double withNo = null[a | nullblade::no];
    const double withNi = null[a | nullblade::ni];
    orthonormal[a] = null[a];
    orthonormal[a | blade::ep] = 0.5 * withNo - withNi;
    orthonormal[a | blade::em] = 0.5 * withNo + withNi;
    orthonormal[a | blade::ep | blade::em] = null[a | nullblade::E];
  }
}

void orthonormalToNull(const double orthonormal[kBladeCount], double null[kBladeCount])
{
  // A e+ = A no - A ni / 2 and A e- = A no + A ni / 2.
  for (unsigned a = 0; a < 8u; ++a)
  {
    const double withEp = orthonormal[a | blade::ep];
    const double withEm = orthonormal[a | blade::em];
    null[a] = orthonormal[a];
    null[a | nullblade::no] = withEp + withEm;
    null[a | nullblade::ni] = 0.5 * (withEm - withEp);
    null[a | nullblade::E] = orthonormal[a | blade::ep | blade::em];
  }
}
} // namespace cga
