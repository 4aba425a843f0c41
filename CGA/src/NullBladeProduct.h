// Internal: the geometric product of two null basis blades (cga::nullBladeProduct) as a constexpr
// function, so that the product tables of the block kernel (SparseProduct.h, BoostProducts.h) are
// built by the compiler and the same function serves the run-time tables.
#pragma once

#include "cga/Basis.h"
#include "cga/NullBasis.h"

namespace cga
{
namespace detail
{
// The Minkowski factor of a null blade: 0 = 1, 1 = no, 2 = ni, 3 = E = no ^ ni.
constexpr unsigned minkowskiPart(unsigned blade)
{
  return blade >> 3;
}

constexpr int minkowskiGrade(unsigned m)
{
  return m == 0u ? 0 : (m == 3u ? 2 : 1);
}

// Products in the algebra spanned by {1, no, ni, E}, from no.no = ni.ni = 0 and no.ni = -1:
//   no ni = -1 + E, ni no = -1 - E, no E = no, E no = -no, ni E = -ni, E ni = ni, E E = 1.
constexpr int minkowskiProduct(unsigned a, unsigned b, NullTerm out[2])
{
  if (a == 0u)
  {
    out[0] = { b, 1.0 };
    return 1;
  }
  if (b == 0u)
  {
    out[0] = { a, 1.0 };
    return 1;
  }
  switch (a * 4u + b)
  {
    case 1u * 4u + 2u: // no ni
      out[0] = { 0u, -1.0 };
      out[1] = { 3u, 1.0 };
      return 2;
    case 1u * 4u + 3u: // no E
      out[0] = { 1u, 1.0 };
      return 1;
    case 2u * 4u + 1u: // ni no
      out[0] = { 0u, -1.0 };
      out[1] = { 3u, -1.0 };
      return 2;
    case 2u * 4u + 3u: // ni E
      out[0] = { 2u, -1.0 };
      return 1;
    case 3u * 4u + 1u: // E no
      out[0] = { 1u, -1.0 };
      return 1;
    case 3u * 4u + 2u: // E ni
      out[0] = { 2u, 1.0 };
      return 1;
    case 3u * 4u + 3u: // E E
      out[0] = { 0u, 1.0 };
      return 1;
    default: // no no, ni ni
      return 0;
  }
}

/// cga::nullBladeProduct: writes the 0, 1 or 2 terms of a b to `out` and returns how many.
constexpr int nullBladeTerms(unsigned a, unsigned b, NullTerm out[2])
{
  const unsigned ea = a & nullblade::euclideanMask;
  const unsigned eb = b & nullblade::euclideanMask;
  const unsigned ma = minkowskiPart(a);
  // (A Ma)(B Mb) = (-1)^{grade(Ma) grade(B)} (A B)(Ma Mb): no and ni anticommute with Euclidean
  // vectors, E commutes with them.
  int sign = kGeometric.sign[ea][eb];
  if ((minkowskiGrade(ma) * bladeGrade(eb)) & 1)
  {
    sign = -sign;
  }
  NullTerm m[2] = {};
  const int count = minkowskiProduct(ma, minkowskiPart(b), m);
  for (int i = 0; i < count; ++i)
  {
    out[i] = { (ea ^ eb) | (m[i].blade << 3), sign * m[i].coefficient };
  }
  return count;
}
} // namespace detail
} // namespace cga
