// Basis blades of the conformal algebra R^{4,1}, generated at compile time.
//
// A basis blade is a bitmask over the orthonormal basis vectors
//   bit 0: e1, bit 1: e2, bit 2: e3   (square +1)
//   bit 3: e+ (ep)                    (square +1)
//   bit 4: e- (em)                    (square -1)
// so a multivector stores its 32 coefficients indexed by that mask. The null vectors
// no = (em + ep)/2 and ni = em - ep are built on top of this basis (Conformal.h).
#pragma once

#include <array>
#include <cstdint>

namespace cga
{
constexpr int kDimension = 5;
constexpr int kBladeCount = 1 << kDimension;

namespace blade
{
constexpr unsigned e1 = 1u, e2 = 2u, e3 = 4u, ep = 8u, em = 16u;
constexpr unsigned pseudoscalar = 31u;
}

constexpr int bladeGrade(unsigned mask)
{
  int g = 0;
  for (; mask; mask &= mask - 1)
  {
    ++g;
  }
  return g;
}

// Sign of the product of two basis blades: the reordering sign (number of transpositions
// needed to bring the factors into canonical order) times the metric of the shared factors.
constexpr int bladeProductSign(unsigned a, unsigned b)
{
  int swaps = 0;
  for (unsigned shifted = a >> 1; shifted; shifted >>= 1)
  {
    swaps += bladeGrade(shifted & b);
  }
  int sign = (swaps & 1) ? -1 : 1;
  if ((a & b) & blade::em)
  {
    sign = -sign; // e- squares to -1
  }
  return sign;
}

struct ProductTable
{
  std::array<std::array<std::int8_t, kBladeCount>, kBladeCount> sign{};
};

constexpr ProductTable makeGeometricTable()
{
  ProductTable t{};
  for (unsigned a = 0; a < kBladeCount; ++a)
  {
    for (unsigned b = 0; b < kBladeCount; ++b)
    {
      t.sign[a][b] = static_cast<std::int8_t>(bladeProductSign(a, b));
    }
  }
  return t;
}

// The geometric product of blades a and b is sign[a][b] * blade(a ^ b).
inline constexpr ProductTable kGeometric = makeGeometricTable();

// Sign of the reverse of a grade-k blade: (-1)^{k(k-1)/2}.
constexpr int reverseSign(int grade)
{
  return ((grade * (grade - 1) / 2) & 1) ? -1 : 1;
}

// Sign of the grade involution of a grade-k blade: (-1)^k.
constexpr int involutionSign(int grade)
{
  return (grade & 1) ? -1 : 1;
}
} // namespace cga
