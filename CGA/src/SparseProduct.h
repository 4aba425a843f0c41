// Internal: a bilinear product of two compact types, reduced once to its non-zero terms.
//
// The operands and the result are given as lists of null blades (the kBlades of Compact.h).
// Products that land on a blade missing from the result list are dropped: that is how grade
// projections such as <K X ~K>_1 are computed without forming the other grades.
#pragma once

#include "cga/NullBasis.h"

#include <array>
#include <cstdint>

namespace cga
{
namespace detail
{
struct ProductTerm
{
  std::uint8_t a = 0, b = 0, r = 0;
  double coefficient = 0.0;
};

class SparseProduct
{
public:
  template <std::size_t NA, std::size_t NB, std::size_t NR>
  SparseProduct(const std::array<unsigned, NA>& slotsA,
                const std::array<unsigned, NB>& slotsB,
                const std::array<unsigned, NR>& slotsR)
  {
    static_assert(NA * NB * 2 <= 512, "operands too large for the term capacity");
    std::array<int, kBladeCount> resultSlot;
    resultSlot.fill(-1);
    for (std::size_t r = 0; r < NR; ++r)
    {
      resultSlot[slotsR[r]] = static_cast<int>(r);
    }
    for (std::size_t i = 0; i < NA; ++i)
    {
      for (std::size_t j = 0; j < NB; ++j)
      {
        NullTerm terms[2];
        const int count = nullBladeProduct(slotsA[i], slotsB[j], terms);
        for (int t = 0; t < count; ++t)
        {
          const int r = resultSlot[terms[t].blade];
          if (r >= 0)
          {
            Terms[Size++] = { static_cast<std::uint8_t>(i),
                              static_cast<std::uint8_t>(j),
                              static_cast<std::uint8_t>(r),
                              terms[t].coefficient };
          }
        }
      }
    }
  }

  /// r += a * b (only the kept terms). r must hold as many values as the result list.
  void accumulate(const double* a, const double* b, double* r) const
  {
    for (int t = 0; t < Size; ++t)
    {
      const ProductTerm& term = Terms[t];
      r[term.r] += term.coefficient * a[term.a] * b[term.b];
    }
  }

  int size() const { return Size; }
  const ProductTerm& term(int i) const { return Terms[i]; }

private:
  // 16 x 16 slot pairs with at most two terms each.
  std::array<ProductTerm, 512> Terms{};
  int Size = 0;
};
} // namespace detail
} // namespace cga
